// Part builders: polygons written by hand in body coordinates, then triangulated, checked and
// (solids) oriented outwards by CGAL (cgal::finalizePart). See parts.hpp for the geometry.
#include <paddy/errors.hpp>
#include <paddy/geometry/cgal_ops.hpp>
#include <paddy/geometry/parts.hpp>

#include <cmath>

namespace paddy::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

using Poly = std::vector<std::uint32_t>;

std::uint32_t add(PolygonSoup& s, double x, double y, double z) {
  s.points.emplace_back(x, y, z);
  return static_cast<std::uint32_t>(s.points.size() - 1);
}

// Ring of n points of radius r at height z; angle of point i = 2π i / n.
std::vector<std::uint32_t> ring(PolygonSoup& s, double r, double z, int n) {
  std::vector<std::uint32_t> ids(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * kPi * i / n;
    ids[static_cast<std::size_t>(i)] = add(s, r * std::cos(a), r * std::sin(a), z);
  }
  return ids;
}

// Side band between two rings of equal size (lower b, upper t); outward = normals away from axis.
void band(PolygonSoup& s, const std::vector<std::uint32_t>& b, const std::vector<std::uint32_t>& t, bool outward) {
  const std::size_t n = b.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (outward) s.polygons.push_back({b[i], b[j], t[j], t[i]});
    else s.polygons.push_back({b[i], t[i], t[j], b[j]});
  }
}

// Disk as a fan around a centre point; up = normal +z.
void fan(PolygonSoup& s, const std::vector<std::uint32_t>& r, double z, bool up) {
  const std::uint32_t c = add(s, 0.0, 0.0, z);
  const std::size_t n = r.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (up) s.polygons.push_back({c, r[i], r[j]});
    else s.polygons.push_back({c, r[j], r[i]});
  }
}

// Annulus between rings inner (a) and outer (b) at the same height; up = normal +z.
void annulus(PolygonSoup& s, const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b, bool up) {
  const std::size_t n = a.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (up) s.polygons.push_back({a[i], b[i], b[j], a[j]});
    else s.polygons.push_back({a[i], a[j], b[j], b[i]});
  }
}

// Axis-aligned box [lo, hi] as six outward quads.
void box(PolygonSoup& s, const Vec3& lo, const Vec3& hi) {
  std::uint32_t v[8];
  for (int i = 0; i < 8; ++i)
    v[i] = add(s, (i & 1) ? hi.x() : lo.x(), (i & 2) ? hi.y() : lo.y(), (i & 4) ? hi.z() : lo.z());
  s.polygons.push_back({v[0], v[2], v[3], v[1]});  // -z
  s.polygons.push_back({v[4], v[5], v[7], v[6]});  // +z
  s.polygons.push_back({v[0], v[1], v[5], v[4]});  // -y
  s.polygons.push_back({v[2], v[6], v[7], v[3]});  // +y
  s.polygons.push_back({v[0], v[4], v[6], v[2]});  // -x
  s.polygons.push_back({v[1], v[3], v[7], v[5]});  // +x
}

int checkCount(const std::string& name, int n, int lo, int hi) {
  checkRange(name, n, lo, hi);
  return n;
}

}  // namespace

TriangleMesh buildSlumpCone(const SlumpConeParams& p) {
  checkRange("slump_cone.top_diameter", p.top_diameter, 1e-4, 10.0, "m");
  checkRange("slump_cone.bottom_diameter", p.bottom_diameter, 1e-4, 10.0, "m");
  checkRange("slump_cone.height", p.height, 1e-4, 10.0, "m");
  checkRange("slump_cone.thickness", p.thickness, 0.0, 0.5 * p.top_diameter, "m");
  const int n = checkCount("slump_cone.segments", p.segments, 8, 4096);
  const double rb = 0.5 * p.bottom_diameter, rt = 0.5 * p.top_diameter, h = p.height;
  PolygonSoup s;
  const auto b = ring(s, rb, 0.0, n);
  const auto t = ring(s, rt, h, n);
  TriangleMesh cone;
  if (p.thickness == 0.0) {
    band(s, b, t, /*outward=*/false);  // normals towards the axis: the side the mud is on
    cone = cgal::finalizePart(s, false, "slump_cone");
  } else {
    // Outer surface offset by the thickness along the normal: radii grow by t / cos β.
    const double cos_beta = h / std::hypot(h, rb - rt);
    const double dr = p.thickness / cos_beta;
    const auto bo = ring(s, rb + dr, 0.0, n);
    const auto to = ring(s, rt + dr, h, n);
    band(s, b, t, false);
    band(s, bo, to, true);
    annulus(s, b, bo, false);
    annulus(s, t, to, true);
    cone = cgal::finalizePart(s, true, "slump_cone");
  }
  if (p.handles) {
    // Two bars on ±x at 2/3 of the height, 40 mm long radially, 20 mm wide, 10 mm high.
    const double zh = 2.0 * h / 3.0;
    const double cos_beta = h / std::hypot(h, rb - rt);
    const double r_out = rb + (rt - rb) * zh / h + p.thickness / cos_beta;
    for (int side : {+1, -1}) {
      PolygonSoup hs;
      const double x0 = side > 0 ? r_out : -r_out - 0.040;
      box(hs, Vec3(x0, -0.010, zh - 0.005), Vec3(x0 + 0.040, 0.010, zh + 0.005));
      append(cone, cgal::finalizePart(hs, true, "slump_cone handle"));
    }
  }
  return cone;
}

TriangleMesh buildPlate(const PlateParams& p) {
  checkRange("plate.side", p.side, 1e-4, 1e3, "m");
  const int n = checkCount("plate.divisions", p.divisions, 1, 1000);
  PolygonSoup s;
  const double h = p.side / n, o = -0.5 * p.side;
  auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) add(s, o + i * h, o + j * h, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.polygons.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.polygons.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return cgal::finalizePart(s, false, "plate");
}

TriangleMesh buildCup(const CupParams& p) {
  checkRange("cup.diameter", p.diameter, 1e-4, 10.0, "m");
  checkRange("cup.height", p.height, 1e-4, 10.0, "m");
  checkRange("cup.thickness", p.thickness, 0.0, p.diameter, "m");
  const int n = checkCount("cup.segments", p.segments, 8, 4096);
  const double r = 0.5 * p.diameter, h = p.height, t = p.thickness;
  PolygonSoup s;
  const auto b = ring(s, r, 0.0, n);
  const auto top = ring(s, r, h, n);
  fan(s, b, 0.0, /*up=*/true);
  band(s, b, top, /*outward=*/false);
  if (t == 0.0) return cgal::finalizePart(s, false, "cup");
  const auto to = ring(s, r + t, h, n);
  const auto bo = ring(s, r + t, -t, n);
  annulus(s, top, to, true);
  band(s, bo, to, true);
  fan(s, bo, -t, false);
  return cgal::finalizePart(s, true, "cup");
}

TriangleMesh buildVane(const VaneParams& p) {
  const int nb = checkCount("vane.blades", p.blades, 1, 32);
  checkRange("vane.diameter", p.diameter, 1e-4, 10.0, "m");
  checkRange("vane.height", p.height, 1e-4, 10.0, "m");
  checkRange("vane.shaft_diameter", p.shaft_diameter, 1e-5, 0.9 * p.diameter, "m");
  checkRange("vane.blade_thickness", p.blade_thickness, 1e-6, 0.9 * p.shaft_diameter, "m");
  checkRange("vane.shaft_length", p.shaft_length, 0.0, 100.0, "m");
  const int seg = checkCount("vane.segments", p.segments, 8, 4096);
  const double R = 0.5 * p.diameter, rs = 0.5 * p.shaft_diameter, ht = 0.5 * p.blade_thickness;
  const double alpha = std::asin(ht / rs);  // half-angle of the chord a blade covers on the shaft
  if (2.0 * alpha * nb >= 2.0 * kPi * 0.9)
    throw InputError("vane: " + std::to_string(nb) + " blades of thickness " + std::to_string(p.blade_thickness) +
                     " m do not fit around a shaft of diameter " + std::to_string(p.shaft_diameter) + " m");
  const double H = p.height, Htop = p.height + p.shaft_length;
  const int gap_arcs = std::max(2, seg / nb - 1);

  // Shaft ring angles: per blade its chord (φ−α, φ+α), then gap_arcs arcs to the next blade.
  std::vector<double> ang;
  std::vector<int> blade_at;  // index in ang of each blade's first chord vertex
  for (int k = 0; k < nb; ++k) {
    const double phi = 2.0 * kPi * k / nb, next = 2.0 * kPi * (k + 1) / nb;
    blade_at.push_back(static_cast<int>(ang.size()));
    ang.push_back(phi - alpha);
    ang.push_back(phi + alpha);
    for (int i = 1; i < gap_arcs; ++i)
      ang.push_back(phi + alpha + (next - alpha - (phi + alpha)) * i / gap_arcs);
  }
  const std::size_t m = ang.size();
  PolygonSoup s;
  auto mkRing = [&](double z) {
    std::vector<std::uint32_t> r(m);
    for (std::size_t i = 0; i < m; ++i) r[i] = add(s, rs * std::cos(ang[i]), rs * std::sin(ang[i]), z);
    return r;
  };
  const auto r0 = mkRing(0.0), rH = mkRing(H);
  std::vector<bool> chord(m, false);
  for (int j : blade_at) chord[static_cast<std::size_t>(j)] = true;
  fan(s, r0, 0.0, /*up=*/false);
  if (p.shaft_length > 0.0) {
    const auto rT = mkRing(Htop);
    band(s, rH, rT, true);
    fan(s, rT, Htop, true);
  } else {
    // Shaft ends at the blade top: the top disk, minus the blade chords, is the cap.
    fan(s, rH, H, true);
  }
  for (std::size_t i = 0; i < m; ++i) {
    if (chord[i]) continue;
    const std::size_t j = (i + 1) % m;
    s.polygons.push_back({r0[i], r0[j], rH[j], rH[i]});
  }
  const double xo = std::sqrt(R * R - ht * ht);  // outer corners on the circle of radius R
  for (int k = 0; k < nb; ++k) {
    const double phi = 2.0 * kPi * k / nb, c = std::cos(phi), sn = std::sin(phi);
    auto at = [&](double x, double y, double z) { return add(s, x * c - y * sn, x * sn + y * c, z); };
    const std::size_t j = static_cast<std::size_t>(blade_at[static_cast<std::size_t>(k)]), j1 = j + 1;
    const std::uint32_t o0m = at(xo, -ht, 0.0), o0p = at(xo, ht, 0.0), oHm = at(xo, -ht, H), oHp = at(xo, ht, H);
    s.polygons.push_back({r0[j], r0[j1], o0p, o0m});  // bottom
    s.polygons.push_back({oHm, oHp, rH[j1], rH[j]});  // top
    s.polygons.push_back({r0[j], o0m, oHm, rH[j]});   // side −y
    s.polygons.push_back({r0[j1], rH[j1], oHp, o0p}); // side +y
    s.polygons.push_back({o0m, o0p, oHp, oHm});       // tip
  }
  return cgal::finalizePart(s, true, "vane");
}

double vaneShearStress(double torque, double diameter, double height) {
  return torque / (kPi * diameter * diameter / 2.0 * (height + diameter / 3.0));
}

// ---- catalogue for the plugin ---------------------------------------------------------------
namespace {

int intParam(const ParamValues& v, const std::string& part, const std::string& name) {
  const double x = v.at(name);
  if (std::abs(x - std::round(x)) > 1e-9)
    throw InputError("parameter '" + part + "." + name + "' = " + std::to_string(x) + " must be an integer");
  return static_cast<int>(std::lround(x));
}

ParamSpec spec(std::string name, double def, double lo, double hi, std::string unit, std::string desc) {
  ParamSpec s;
  s.name = std::move(name);
  s.default_value = def;
  s.min = lo;
  s.max = hi;
  s.unit = std::move(unit);
  s.description = std::move(desc);
  return s;
}

}  // namespace

std::vector<GeometryInfo> partCatalogue() {
  std::vector<GeometryInfo> parts;
  {
    const SlumpConeParams d;
    GeometryInfo g;
    g.name = "slump_cone";
    g.description = "Slump cone after GB/T 50080-2016 (frustum, inner diameters 0.1/0.2 m, height 0.3 m, open ends)";
    g.params = {spec("top_diameter", d.top_diameter, 1e-4, 10, "m", "inner diameter at the top"),
                spec("bottom_diameter", d.bottom_diameter, 1e-4, 10, "m", "inner diameter at the bottom"),
                spec("height", d.height, 1e-4, 10, "m", "height"),
                spec("segments", d.segments, 8, 4096, "", "facets around the circumference"),
                spec("thickness", d.thickness, 0, 1, "m", "wall thickness (0: single surface)"),
                spec("handles", 0, 0, 1, "", "1: add the two handle bars")};
    g.build = [](const ParamValues& v) {
      SlumpConeParams p;
      p.top_diameter = v.at("top_diameter");
      p.bottom_diameter = v.at("bottom_diameter");
      p.height = v.at("height");
      p.segments = intParam(v, "slump_cone", "segments");
      p.thickness = v.at("thickness");
      p.handles = intParam(v, "slump_cone", "handles") != 0;
      return buildSlumpCone(p);
    };
    parts.push_back(std::move(g));
  }
  {
    const PlateParams d;
    GeometryInfo g;
    g.name = "plate";
    g.description = "Square plate in z = 0, normal +z, centred at the origin";
    g.params = {spec("side", d.side, 1e-4, 1e3, "m", "side length"),
                spec("divisions", d.divisions, 1, 1000, "", "squares per side (two triangles each)")};
    g.build = [](const ParamValues& v) {
      PlateParams p;
      p.side = v.at("side");
      p.divisions = intParam(v, "plate", "divisions");
      return buildPlate(p);
    };
    parts.push_back(std::move(g));
  }
  {
    const CupParams d;
    GeometryInfo g;
    g.name = "cup";
    g.description = "Rheometer cup: cylinder with flat bottom at z = 0, open top";
    g.params = {spec("diameter", d.diameter, 1e-4, 10, "m", "inner diameter"),
                spec("height", d.height, 1e-4, 10, "m", "inner depth"),
                spec("segments", d.segments, 8, 4096, "", "facets around the circumference"),
                spec("thickness", d.thickness, 0, 1, "m", "wall and bottom thickness (0: single surface)")};
    g.build = [](const ParamValues& v) {
      CupParams p;
      p.diameter = v.at("diameter");
      p.height = v.at("height");
      p.segments = intParam(v, "cup", "segments");
      p.thickness = v.at("thickness");
      return buildCup(p);
    };
    parts.push_back(std::move(g));
  }
  {
    const VaneParams d;
    GeometryInfo g;
    g.name = "vane";
    g.description = "Vane rotor: flat blades on a shaft, axis +z, blades over z in [0, height]";
    g.params = {spec("blades", d.blades, 1, 32, "", "number of blades"),
                spec("diameter", d.diameter, 1e-4, 10, "m", "diameter swept by the blade tips"),
                spec("height", d.height, 1e-4, 10, "m", "blade height"),
                spec("blade_thickness", d.blade_thickness, 1e-6, 1, "m", "blade thickness"),
                spec("shaft_diameter", d.shaft_diameter, 1e-5, 10, "m", "shaft diameter"),
                spec("shaft_length", d.shaft_length, 0, 100, "m", "shaft length above the blades"),
                spec("segments", d.segments, 8, 4096, "", "shaft facets")};
    g.build = [](const ParamValues& v) {
      VaneParams p;
      p.blades = intParam(v, "vane", "blades");
      p.diameter = v.at("diameter");
      p.height = v.at("height");
      p.blade_thickness = v.at("blade_thickness");
      p.shaft_diameter = v.at("shaft_diameter");
      p.shaft_length = v.at("shaft_length");
      p.segments = intParam(v, "vane", "segments");
      return buildVane(p);
    };
    parts.push_back(std::move(g));
  }
  return parts;
}

}  // namespace paddy::geometry
