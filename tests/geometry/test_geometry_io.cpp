// Mesh files: STL (binary/ASCII), OFF, OBJ round trips, units and placement, broken inputs
// refused with their message, shipped meshes equal to the builders.
#include "test_util.hpp"

#include <paddy/errors.hpp>
#include <paddy/geometry/cgal_ops.hpp>
#include <paddy/geometry/mesh_check.hpp>
#include <paddy/geometry/mesh_io.hpp>
#include <paddy/geometry/parts.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

using namespace paddy;
using namespace paddy::geometry;
using Catch::Matchers::Contains;

namespace {
constexpr double kPi = 3.14159265358979323846;

void sameShape(const TriangleMesh& a, const TriangleMesh& b, double tol) {
  REQUIRE(a.triangles.size() == b.triangles.size());
  const Bounds ba = bounds(a), bb = bounds(b);
  CHECK((ba.lo - bb.lo).norm() < tol);
  CHECK((ba.hi - bb.hi).norm() < tol);
  CHECK(surfaceArea(a) == Approx(surfaceArea(b)).epsilon(1e-6));
  // Triangle by triangle (order is kept): same centroid and same normal.
  for (std::size_t t = 0; t < a.triangles.size(); ++t) {
    Vec3 ca = Vec3::Zero(), cb = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      ca += a.vertices[a.triangles[t][k]] / 3.0;
      cb += b.vertices[b.triangles[t][k]] / 3.0;
    }
    INFO("triangle " << t);
    REQUIRE((ca - cb).norm() < tol);
    REQUIRE(triangleNormal(a, t).dot(triangleNormal(b, t)) > 1.0 - 1e-6);
  }
}

// Closed unit tetrahedron (outward) as text in each format.
const char* kTetraOff = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

std::string binaryStl(const std::vector<std::array<float, 9>>& tris) {
  std::string s(80, '\0');
  const auto n = static_cast<std::uint32_t>(tris.size());
  s.append(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : tris) {
    const float zero[3] = {0, 0, 0};
    s.append(reinterpret_cast<const char*>(zero), 12);
    s.append(reinterpret_cast<const char*>(t.data()), 36);
    s.append(2, '\0');
  }
  return s;
}
}  // namespace

TEST_CASE("geometry STL (binary and ASCII), OFF and OBJ round trips keep the mesh") {
  test::TempDir dir;
  SECTION("closed vane") {
    const TriangleMesh vane = buildVane();
    for (const char* name : {"vane_bin.stl", "vane_ascii.stl", "vane.off"}) {
      const std::string f = name;
      const std::string path = dir.file(f);
      if (f == "vane.off") writeOff(path, vane);
      else writeStl(path, vane, f == "vane_bin.stl");
      INFO(path);
      const TriangleMesh back = readMesh(path, {});
      sameShape(vane, back, 1e-7);
      CHECK(back.vertices.size() == vane.vertices.size());  // STL corners merged back into vertices
      CHECK(cgal::volume(back) == Approx(cgal::volume(vane)).epsilon(1e-6));
      CHECK(cgal::isOutwardOriented(back));
    }
  }
  SECTION("open cone") {
    const TriangleMesh cone = buildSlumpCone();
    writeStl(dir.file("cone.stl"), cone, true);
    sameShape(cone, readMesh(dir.file("cone.stl")), 1e-7);
  }
  SECTION("OBJ with a quad face is triangulated") {
    const std::string obj = dir.write("box.obj",
        "# unit cube\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
        "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    const TriangleMesh box = readMesh(obj, {});
    CHECK(box.triangles.size() == 12);
    CHECK(cgal::volume(box) == Approx(1.0).epsilon(1e-12));
    CHECK(cgal::isOutwardOriented(box));
  }
  SECTION("inside-out closed part is re-oriented outwards") {
    const std::string off = dir.write("inv.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
    const TriangleMesh t = readMesh(off);
    CHECK(signedVolume(t) == Approx(1.0 / 6.0));
  }
}

TEST_CASE("geometry import applies units, rotation about an axis and translation") {
  test::TempDir dir;
  const std::string off = dir.write("tetra_mm.off", "OFF\n4 4 0\n0 0 0\n1000 0 0\n0 1000 0\n0 0 1000\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  ImportOptions o;
  o.scale = 0.001;
  o.rotation_axis = Vec3(1, 0, 0);
  o.rotation_angle = kPi / 2;  // y → z, z → −y
  o.translation = Vec3(0, 0, 0.5);
  const TriangleMesh m = readMesh(off, o);
  const Bounds b = bounds(m);
  CHECK((b.lo - Vec3(0, -1, 0.5)).norm() < 1e-12);
  CHECK((b.hi - Vec3(1, 0, 1.5)).norm() < 1e-12);
  CHECK(cgal::volume(m) == Approx(1.0 / 6.0).epsilon(1e-12));
}

TEST_CASE("geometry broken mesh files are refused naming the file and the fault") {
  test::TempDir dir;
  auto refuse = [&](const std::string& path, const std::vector<std::string>& parts, const ImportOptions& o = {}) {
    INFO(path);
    try {
      readMesh(path, o);
      FAIL("accepted a broken mesh");
    } catch (const InputError& e) {
      const std::string msg = e.what();
      INFO(msg);
      CHECK_THAT(msg, Contains(path));
      for (const auto& p : parts) CHECK_THAT(msg, Contains(p));
    }
  };
  SECTION("missing, empty, unknown format, truncated") {
    refuse(dir.file("nope.stl"), {"not found"});
    refuse(dir.write("empty.stl", ""), {"empty file"});
    refuse(dir.write("blank.off", "  \n\n"), {"empty file"});
    refuse(dir.write("mesh.ply2", "x"), {"unknown mesh format", ".obj"});
    std::string bin = binaryStl({{0, 0, 0, 1, 0, 0, 0, 1, 0}});
    bin.resize(bin.size() - 20);
    refuse(dir.write("cut.stl", bin), {"not a valid STL"});
    refuse(dir.write("noface.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"), {"no triangles"});
    refuse(dir.write("noface.obj", "v 0 0 0\nv 1 0 0\n"), {"OBJ"});
    refuse(dir.write("garbage.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"), {"not a valid OFF"});
  }
  SECTION("non-finite coordinates name the vertex") {
    refuse(dir.write("nan.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 nan 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"),
           {"line 5", "vertex 2", "non-finite"});
    refuse(dir.write("inf.obj", "v 0 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n"), {"line 2", "vertex 1", "non-finite"});
    refuse(dir.write("nan_ascii.stl",
                     "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 NaN\nendloop\nendfacet\nendsolid t\n"),
           {"line 6", "vertex 2", "non-finite"});
    const float nan = std::numeric_limits<float>::quiet_NaN();
    refuse(dir.write("nan_bin.stl", binaryStl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 1, 0, 0, 0, 0, nan}})),
           {"triangle 1, corner 2", "non-finite"});
  }
  SECTION("degenerate triangles name the triangle") {
    // Collinear corners.
    refuse(dir.write("flat.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n3 0 0\n3 0 1 2\n3 1 3 4\n"),
           {"triangle 1", "degenerate"});
    // Two corners at the same point (merged into one vertex).
    refuse(dir.write("pinched.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nf 1 2 3\nf 1 2 4\n"), {"triangle 1", "degenerate"});
    // Binary STL sliver of zero area.
    refuse(dir.write("sliver.stl", binaryStl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 1, 1, 1, 2, 2, 2}})),
           {"triangle 1", "degenerate"});
  }
  SECTION("duplicate triangles name both") {
    refuse(dir.write("dup.off", std::string(kTetraOff).replace(4, 5, "4 5 0") + "3 0 1 3\n"),
           {"triangles 1 and 4", "duplicates"});
  }
  SECTION("non-manifold edge in a closed part, boundary in a required-closed part") {
    // Two tetrahedra sharing the edge (0,1): four triangles on one edge, no boundary.
    refuse(dir.write("bowtie.off",
                     "OFF\n6 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 -1 0\n0 0 -1\n"
                     "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
                     "3 0 4 1\n3 0 1 5\n3 0 5 4\n3 1 4 5\n"),
           {"non-manifold edge (0, 1)", "shared by 4 triangles", "closed part"});
    ImportOptions closed;
    closed.closure = Closure::Closed;
    refuse(dir.write("open.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n"),
           {"must be closed", "boundary edge"}, closed);
  }
  SECTION("an open surface with a fin (3 triangles on an edge) is accepted") {
    const std::string fin = dir.write("fin.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
    CHECK(readMesh(fin).triangles.size() == 3);
  }
}

TEST_CASE("geometry shipped meshes/*.stl are what the builders produce") {
  const std::string dir = test::sourceDir() + "/meshes/";
  const std::pair<std::string, TriangleMesh> parts[] = {
      {"slump_cone", buildSlumpCone()}, {"plate", buildPlate()}, {"cup", buildCup()}, {"vane", buildVane()}};
  for (const auto& [name, mesh] : parts) {
    INFO(dir + name + ".stl (regenerate with: paddy_mesh_export meshes docs/images)");
    const TriangleMesh shipped = readMesh(dir + name + ".stl");
    sameShape(mesh, shipped, 2e-7);
  }
}
