// Part builders: dimensions from vertex extents, closedness/orientation, volumes (CGAL PMP),
// catalogue and plugin registration.
#include <paddy/errors.hpp>
#include <paddy/geometry/cgal_ops.hpp>
#include <paddy/geometry/mesh_check.hpp>
#include <paddy/geometry/mesh_io.hpp>
#include <paddy/geometry/parts.hpp>
#include <paddy/plugin.hpp>
#include <paddy/plugin_manager.hpp>

#include <catch2/catch.hpp>
#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <cstdlib>
#include <map>

using namespace paddy;
using namespace paddy::geometry;
using Catch::Matchers::Contains;

namespace {
constexpr double kPi = 3.14159265358979323846;

// Largest distance from the z axis among vertices at height z (± tol).
double maxRadiusAt(const TriangleMesh& m, double z, double tol = 1e-12) {
  double r = -1.0;
  for (const Vec3& v : m.vertices)
    if (std::abs(v.z() - z) <= tol) r = std::max(r, std::hypot(v.x(), v.y()));
  return r;
}
double minRadiusAt(const TriangleMesh& m, double z, double tol = 1e-12) {
  double r = 1e300;
  for (const Vec3& v : m.vertices)
    if (std::abs(v.z() - z) <= tol) r = std::min(r, std::hypot(v.x(), v.y()));
  return r;
}
// Area of a regular n-gon of circumradius r.
double ngon(double r, int n) { return 0.5 * n * r * r * std::sin(2.0 * kPi / n); }
}  // namespace

TEST_CASE("geometry slump cone has the GB/T 50080 dimensions and is an open inward surface") {
  const TriangleMesh m = buildSlumpCone();
  const MeshReport rep = validateMesh(m, {"cone", Closure::Open, 1e-10});
  CHECK(rep.components == 1);
  CHECK(rep.closed_components == 0);
  CHECK(rep.boundary_edges == 2 * 96);  // open top and bottom
  CHECK(m.triangles.size() == 2 * 96);
  const Bounds b = bounds(m);
  CHECK(b.lo.z() == Approx(0.0).margin(1e-15));
  CHECK(b.hi.z() == Approx(0.300).epsilon(1e-12));
  CHECK(maxRadiusAt(m, 0.0) == Approx(0.100).epsilon(1e-12));
  CHECK(minRadiusAt(m, 0.0) == Approx(0.100).epsilon(1e-12));
  CHECK(maxRadiusAt(m, 0.3) == Approx(0.050).epsilon(1e-12));
  // Chord (facet) error at the bottom is far below a 1 mm particle.
  CHECK(0.1 * (1.0 - std::cos(kPi / 96)) < 0.06e-3);
  // Normals point towards the axis (the mud side).
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    Vec3 c = (m.vertices[m.triangles[t][0]] + m.vertices[m.triangles[t][1]] + m.vertices[m.triangles[t][2]]) / 3.0;
    c.z() = 0.0;
    REQUIRE(triangleNormal(m, t).dot(c) < 0.0);
  }
  CHECK_FALSE(cgal::isClosed(m));
}

TEST_CASE("geometry thick slump cone is a closed outward solid of the right volume") {
  SlumpConeParams p;
  p.thickness = 0.002;
  const TriangleMesh m = buildSlumpCone(p);
  CHECK(validateMesh(m, {"thick cone", Closure::Closed, 1e-10}).closed_components == 1);
  CHECK(cgal::isClosed(m));
  CHECK(cgal::isOutwardOriented(m));
  CHECK_FALSE(cgal::selfIntersects(m));
  // Frustum of regular 96-gons: V = h/3 (A1 + A2 + sqrt(A1 A2)), outer minus inner.
  const double h = 0.3, cb = h / std::hypot(h, 0.05), dr = 0.002 / cb;
  auto frustum = [&](double r1, double r2) {
    const double a1 = ngon(r1, 96), a2 = ngon(r2, 96);
    return h / 3.0 * (a1 + a2 + std::sqrt(a1 * a2));
  };
  const double expected = frustum(0.1 + dr, 0.05 + dr) - frustum(0.1, 0.05);
  CHECK(cgal::volume(m) == Approx(expected).epsilon(1e-9));
  CHECK(signedVolume(m) == Approx(expected).epsilon(1e-9));
  // Inner radii unchanged by the thickness.
  CHECK(minRadiusAt(m, 0.0) == Approx(0.1).epsilon(1e-12));
  CHECK(minRadiusAt(m, 0.3) == Approx(0.05).epsilon(1e-12));
  CHECK(maxRadiusAt(m, 0.0) == Approx(0.1 + dr).epsilon(1e-12));
}

TEST_CASE("geometry slump cone handles are two extra closed parts") {
  SlumpConeParams p;
  p.handles = true;
  const MeshReport rep = validateMesh(buildSlumpCone(p), {"cone+handles", Closure::Auto, 1e-10});
  CHECK(rep.components == 3);
  CHECK(rep.closed_components == 2);
}

TEST_CASE("geometry plate is a square in z = 0 with normals +z and valence-6 interior vertices") {
  const TriangleMesh m = buildPlate();
  CHECK(m.triangles.size() == 2 * 8 * 8);
  const Bounds b = bounds(m);
  CHECK(b.lo.x() == Approx(-0.5));
  CHECK(b.hi.y() == Approx(0.5));
  CHECK(b.size().z() == 0.0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) REQUIRE(triangleNormal(m, t).z() == Approx(1.0));
  CHECK(surfaceArea(m) == Approx(1.0).epsilon(1e-12));
  // Vertex at the centre is shared by 6 triangles.
  std::map<std::uint32_t, int> valence;
  for (const auto& t : m.triangles)
    for (auto v : t) ++valence[v];
  int centre_valence = 0;
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    if (m.vertices[v].norm() < 1e-12) centre_valence = valence[static_cast<std::uint32_t>(v)];
  CHECK(centre_valence == 6);
}

TEST_CASE("geometry cup: open cup capacity and thick cup volume (CGAL PMP) match the formulas") {
  const TriangleMesh open = buildCup();
  CHECK(validateMesh(open, {"cup", Closure::Open, 1e-10}).boundary_edges == 96);
  CHECK(maxRadiusAt(open, 0.12) == Approx(0.05).epsilon(1e-12));
  CHECK(bounds(open).size().z() == Approx(0.12));
  // Capacity (volume under the rim plane) by tetrahedra from the rim centre; the normals point
  // into the cup, so the enclosed volume comes out negative.
  CHECK(-signedVolume(open, Vec3(0, 0, 0.12)) == Approx(ngon(0.05, 96) * 0.12).epsilon(1e-12));
  CHECK(ngon(0.05, 96) * 0.12 == Approx(kPi * 0.05 * 0.05 * 0.12).epsilon(1e-3));
  for (std::size_t t = 0; t < open.triangles.size(); ++t) {
    const Vec3 n = triangleNormal(open, t);
    Vec3 c = (open.vertices[open.triangles[t][0]] + open.vertices[open.triangles[t][1]] + open.vertices[open.triangles[t][2]]) / 3.0;
    if (std::abs(n.z()) > 0.5) REQUIRE(n.z() > 0.0);  // bottom: +z into the cup
    else { c.z() = 0; REQUIRE(n.dot(c) < 0.0); }       // side: towards the axis
  }

  CupParams p;
  p.thickness = 0.003;
  const TriangleMesh thick = buildCup(p);
  CHECK(cgal::isClosed(thick));
  CHECK(cgal::isOutwardOriented(thick));
  CHECK_FALSE(cgal::selfIntersects(thick));
  const double expected = ngon(0.053, 96) * (0.12 + 0.003) - ngon(0.05, 96) * 0.12;
  CHECK(cgal::volume(thick) == Approx(expected).epsilon(1e-9));
  CHECK(cgal::area(thick) == Approx(surfaceArea(thick)).epsilon(1e-12));
}

TEST_CASE("geometry vane is one closed outward solid with the requested dimensions and volume") {
  const VaneParams p;
  const TriangleMesh m = buildVane(p);
  const MeshReport rep = validateMesh(m, {"vane", Closure::Closed, 1e-10});
  CHECK(rep.components == 1);
  CHECK(rep.nonmanifold_edges == 0);
  CHECK(cgal::isOutwardOriented(m));
  CHECK_FALSE(cgal::selfIntersects(m));
  double rmax = 0.0;
  for (const Vec3& v : m.vertices) rmax = std::max(rmax, std::hypot(v.x(), v.y()));
  CHECK(rmax == Approx(0.025).epsilon(1e-12));  // swept diameter 0.05 m
  const Bounds b = bounds(m);
  CHECK(b.lo.z() == Approx(0.0).margin(1e-15));
  CHECK(b.hi.z() == Approx(0.12).epsilon(1e-12));
  CHECK(maxRadiusAt(m, 0.12) == Approx(0.004).epsilon(1e-12));  // shaft top
  // Volume: shaft polygon × total length + blades beyond the chord.
  const double rs = 0.004, ht = 0.001, alpha = std::asin(ht / rs);
  double ring_area = 0.0;
  {
    // Same angles as the builder: per blade the chord 2α, then 7 equal arcs to the next blade.
    const int gap = 32 / 4 - 1;
    const double arc = (kPi / 2 - 2 * alpha) / gap;
    ring_area = 4 * (0.5 * rs * rs * std::sin(2 * alpha) + gap * 0.5 * rs * rs * std::sin(arc));
  }
  const double xi = rs * std::cos(alpha), xo = std::sqrt(0.025 * 0.025 - ht * ht);
  const double expected = ring_area * 0.12 + 4 * (2 * ht) * (xo - xi) * 0.06;
  CHECK(cgal::volume(m) == Approx(expected).epsilon(1e-9));
  // Torque ↔ stress relation: T = τ π D²/2 (H + D/3).
  CHECK(vaneShearStress(1.0, 0.05, 0.06) == Approx(1.0 / (kPi * 0.05 * 0.05 / 2 * (0.06 + 0.05 / 3))));

  VaneParams six;
  six.blades = 6;
  six.shaft_length = 0.0;
  const TriangleMesh m6 = buildVane(six);
  CHECK(cgal::isClosed(m6));
  CHECK(cgal::isOutwardOriented(m6));
  CHECK(bounds(m6).size().z() == Approx(0.06));
}

TEST_CASE("geometry builders refuse out-of-range parameters with the parameter's name") {
  SlumpConeParams c;
  c.segments = 3;
  CHECK_THROWS_WITH(buildSlumpCone(c), Contains("slump_cone.segments"));
  VaneParams v;
  v.blade_thickness = 0.01;  // thicker than the shaft
  CHECK_THROWS_WITH(buildVane(v), Contains("vane.blade_thickness"));
  v = VaneParams{};
  v.blades = 32;
  v.blade_thickness = 0.0035;
  CHECK_THROWS_AS(buildVane(v), InputError);
  CupParams cup;
  cup.diameter = -1;
  CHECK_THROWS_WITH(buildCup(cup), Contains("cup.diameter"));
}

namespace {
std::map<std::string, double> defaults(const GeometryInfo& g) {
  std::map<std::string, double> v;
  for (const auto& p : g.params) v[p.name] = p.default_value;
  return v;
}

struct Registry : PluginRegistry {
  std::vector<GeometryInfo> parts;
  std::vector<MeshReaderInfo> readers;
  void addSubModel(SubModelInfo) override {}
  void addGeometry(const GeometryInfo& g) override { parts.push_back(g); }
  void addMeshReader(const MeshReaderInfo& r) override { readers.push_back(r); }
};
}  // namespace

TEST_CASE("geometry catalogue builds every part from its parameter defaults") {
  const auto parts = partCatalogue();
  REQUIRE(parts.size() == 4);
  for (const auto& g : parts) {
    INFO(g.name);
    const TriangleMesh m = g.build(defaults(g));
    CHECK(m.triangles.size() > 0);
    CHECK_NOTHROW(validateMesh(m, {g.name, Closure::Auto, 1e-10}));
  }
  auto v = defaults(parts[0]);
  v["segments"] = 95.5;
  CHECK_THROWS_WITH(parts[0].build(v), Contains("must be an integer"));
}

TEST_CASE("geometry plugin registers slump_cone, plate, cup and vane") {
  const char* path_env = std::getenv("PADDY_PLUGIN_PATH");
  const std::string lib = std::string(path_env ? path_env : PADDY_TEST_PLUGIN_DIR) + "/libpaddy_geometry.so";
  void* h = dlopen(lib.c_str(), RTLD_NOW | RTLD_LOCAL);
  INFO(lib << ": " << (h ? "" : dlerror()));
  REQUIRE(h != nullptr);
  auto fn = reinterpret_cast<paddy_register_plugin_fn>(dlsym(h, "paddy_register_plugin"));
  REQUIRE(fn != nullptr);
  {
    Registry r;
    CHECK(fn(&r) == PADDY_PLUGIN_ABI_VERSION);
    std::vector<std::string> names;
    for (const auto& g : r.parts) names.push_back(g.name);
    CHECK(names == std::vector<std::string>{"slump_cone", "plate", "cup", "vane"});
    const TriangleMesh cone = r.parts[0].build(defaults(r.parts[0]));
    CHECK(cone.triangles.size() == 192);
  }
  dlclose(h);
}

TEST_CASE("geometry plugin registers the mesh reader; the plugin manager finds it by extension") {
  const char* path_env = std::getenv("PADDY_PLUGIN_PATH");
  const std::string dir = path_env ? path_env : PADDY_TEST_PLUGIN_DIR;
  const std::string stl = (std::filesystem::temp_directory_path() / "paddy_reader_test.stl").string();
  TriangleMesh plate = buildPlate({.side = 100.0, .divisions = 2});  // "millimetres"
  writeStl(stl, plate, /*binary=*/false);
  {
    PluginManager pm;
    pm.loadLibrary(dir + "/libpaddy_geometry.so");
    const auto& provides = pm.loaded().at(0).provides;
    CHECK(std::find(provides.begin(), provides.end(), "mesh_reader:cgal") != provides.end());
    CHECK(pm.meshExtensions() == std::vector<std::string>{".obj", ".off", ".stl"});
    const MeshReaderInfo& reader = pm.meshReader(".STL");  // case-insensitive
    CHECK(reader.name == "cgal");
    // The reader applies no scale or placement: the file's own coordinates come back.
    const TriangleMesh m = reader.read(stl);
    CHECK(m.triangles.size() == plate.triangles.size());
    const Bounds b = bounds(m);
    CHECK(b.hi.x() == Approx(50.0));
    CHECK(b.lo.x() == Approx(-50.0));
    CHECK_THROWS_WITH(pm.meshReader(".ply"), Contains("'.ply'") && Contains(".obj, .off, .stl"));
    CHECK_THROWS_WITH(reader.read(stl + ".missing.stl"), Contains("paddy_reader_test.stl.missing.stl") &&
                                                            Contains("mesh file not found"));
  }
  std::filesystem::remove(stl);
}
