// Sphere–mesh contacts: closest point on a triangle, analytic plane and cylinder, one contact per
// flat region across edges and vertices (continuous overlap and normal), concave corners, sharp
// convex edges, candidate lists equal to a brute-force search.
#include <paddy/geometry/closest_point.hpp>
#include <paddy/geometry/mesh_check.hpp>
#include <paddy/geometry/mesh_wall.hpp>
#include <paddy/geometry/parts.hpp>

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <random>

using namespace paddy;
using namespace paddy::geometry;

namespace {
constexpr double kPi = 3.14159265358979323846;

std::vector<WallContact> contactsAt(const MeshWall& w, const Vec3& c, double r, double gap = 0.0) {
  std::vector<WallContact> out;
  w.contactsOfSphere(c, r, gap, 0, out);
  return out;
}
}  // namespace

TEST_CASE("geometry closest point on a triangle: regions and distance against dense sampling") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  CHECK(closestPointOnTriangle(Vec3(0.2, 0.2, 1), a, b, c).feature == TriFeature::Face);
  CHECK(closestPointOnTriangle(Vec3(0.5, -1, 0.3), a, b, c).feature == TriFeature::Edge0);
  CHECK(closestPointOnTriangle(Vec3(1, 1, 0.3), a, b, c).feature == TriFeature::Edge1);
  CHECK(closestPointOnTriangle(Vec3(-1, 0.5, 0), a, b, c).feature == TriFeature::Edge2);
  CHECK(closestPointOnTriangle(Vec3(-1, -1, 2), a, b, c).feature == TriFeature::Vertex0);
  CHECK(closestPointOnTriangle(Vec3(2, -0.1, 0), a, b, c).feature == TriFeature::Vertex1);
  CHECK(closestPointOnTriangle(Vec3(-0.1, 3, 0), a, b, c).feature == TriFeature::Vertex2);
  CHECK((closestPointOnTriangle(Vec3(0.2, 0.3, -2), a, b, c).point - Vec3(0.2, 0.3, 0)).norm() < 1e-15);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  const Vec3 ta(0.1, -0.2, 0.3), tb(0.9, 0.1, -0.2), tc(-0.3, 0.8, 0.1);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 p(u(rng), u(rng), u(rng));
    const auto cp = closestPointOnTriangle(p, ta, tb, tc);
    const double d = (cp.point - p).norm();
    double best = 1e300;
    const int n = 200;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const Vec3 q = ta + (tb - ta) * (double(i) / n) + (tc - ta) * (double(j) / n);
        best = std::min(best, (q - p).norm());
      }
    REQUIRE(d <= best + 1e-12);
    REQUIRE(d > best - 0.01);  // sampling resolution
  }
}

TEST_CASE("geometry sphere on a meshed plane: overlap and normal equal the analytic plane") {
  MeshWall plate("plate", 0, buildPlate());
  CHECK(plate.regionCount() == 1);
  const double r = 0.001;
  for (double h : {0.0009, 0.0005, 0.00099999, 0.0}) {
    const auto c = contactsAt(plate, Vec3(0.0123, -0.2, h), r);
    REQUIRE(c.size() == 1);
    CHECK(c[0].overlap == Approx(r - h).epsilon(1e-12));
    CHECK((c[0].normal - Vec3(0, 0, 1)).norm() < 1e-12);
    CHECK((c[0].point - Vec3(0.0123, -0.2, 0)).norm() < 1e-15);
  }
  // Two-sided: below the plate the normal points down.
  auto below = contactsAt(plate, Vec3(0.3, 0.3, -0.0004), r);
  REQUIRE(below.size() == 1);
  CHECK(below[0].normal.z() == Approx(-1.0));
  CHECK(below[0].overlap == Approx(0.0006));
  // Out of reach, and gap contacts within max_gap.
  CHECK(contactsAt(plate, Vec3(0, 0, 0.0011), r).empty());
  auto gap = contactsAt(plate, Vec3(0, 0, 0.0011), r, 0.0002);
  REQUIRE(gap.size() == 1);
  CHECK(gap[0].overlap == Approx(-0.0001));
  // Beyond the plate's edge the contact is with the edge (distance to the rim line).
  auto rim = contactsAt(plate, Vec3(0.5003, 0.1, 0.0004), r);
  REQUIRE(rim.size() == 1);
  CHECK(rim[0].overlap == Approx(r - 0.0005).epsilon(1e-9));
}

TEST_CASE("geometry sphere sliding across edges and a 6-triangle vertex keeps one continuous contact") {
  PlateParams pp;
  pp.side = 0.02;
  pp.divisions = 4;  // vertex (0, 0) is shared by 6 triangles; squares of 5 mm
  MeshWall plate("plate", 0, buildPlate(pp));
  const double r = 0.001, h = 0.0007;
  // Paths through the 6-triangle vertex: generic direction, along the diagonals, along grid lines.
  const Vec3 dirs[] = {Vec3(1, 0.37, 0).normalized(), Vec3(1, 1, 0).normalized(), Vec3(1, -1, 0).normalized(),
                       Vec3(1, 0, 0), Vec3(0, 1, 0)};
  for (const Vec3& d : dirs) {
    INFO("direction " << d.transpose());
    double prev_overlap = r - h;
    for (int i = 0; i <= 4000; ++i) {
      const double s = -0.006 + 0.012 * i / 4000.0;
      const Vec3 centre = Vec3(0, 0, h) + s * d;
      const auto c = contactsAt(plate, centre, r, 0.0001);
      INFO("s = " << s);
      REQUIRE(c.size() == 1);
      REQUIRE(c[0].key == 0u);
      REQUIRE(std::abs(c[0].overlap - (r - h)) < 1e-15);
      REQUIRE((c[0].normal - Vec3(0, 0, 1)).norm() < 1e-14);
      REQUIRE((c[0].point - Vec3(centre.x(), centre.y(), 0)).norm() < 1e-15);
      REQUIRE(std::abs(c[0].overlap - prev_overlap) < 1e-15);
      prev_overlap = c[0].overlap;
    }
  }
  // A path exactly through the vertex at grazing height, and one through it when deep.
  for (double hz : {0.00099, 0.0001}) {
    const auto c = contactsAt(plate, Vec3(0, 0, hz), r);
    REQUIRE(c.size() == 1);
    CHECK(c[0].overlap == Approx(r - hz));
  }
}

TEST_CASE("geometry sphere inside the meshed cup: cylinder distance, one contact on the side, two in the corner") {
  const double R = 0.05;
  const int n = 96;
  MeshWall cup("cup", 0, buildCup());
  CHECK(cup.regionCount() == 2);  // bottom, side
  const double r = 0.001;
  // Around the cylinder at height 0.06, centre 0.4 mm from the wall: analytic cylinder overlap
  // r − (R − ρ), up to the facet chord error R (1 − cos(π/n)) (the facets lie inside the circle).
  const double rho = R - 0.0004;
  const double chord = R * (1.0 - std::cos(kPi / n));
  std::uint32_t key = 0;
  Vec3 prev_n = Vec3::Zero();
  for (int i = 0; i <= 3000; ++i) {
    const double phi = 2.0 * kPi * i / 3000.0 * 0.25;  // a quarter turn: 24 facets, edges and vertices
    const Vec3 centre(rho * std::cos(phi), rho * std::sin(phi), 0.06);
    const auto c = contactsAt(cup, centre, r);
    INFO("phi = " << phi);
    REQUIRE(c.size() == 1);
    if (i == 0) key = c[0].key;
    REQUIRE(c[0].key == key);  // history survives sliding around the faceted wall
    const double analytic = r - (R - rho);
    REQUIRE(c[0].overlap >= analytic - 1e-12);
    REQUIRE(c[0].overlap <= analytic + chord + 1e-12);
    const Vec3 inward(-std::cos(phi), -std::sin(phi), 0);
    REQUIRE(c[0].normal.dot(inward) > std::cos(kPi / n) - 1e-12);  // at most half a facet off
    if (i > 0) REQUIRE((c[0].normal - prev_n).norm() < 2.0 * std::sin(kPi / n) + 1e-9);  // no flip
    prev_n = c[0].normal;
  }
  // Concave corner: touching the bottom and the side gives two contacts.
  const auto corner = contactsAt(cup, Vec3(R - 0.0008, 0.0, 0.0006), r);
  REQUIRE(corner.size() == 2);
  CHECK(corner[0].key != corner[1].key);
  int up = 0, side = 0;
  for (const auto& c : corner) {
    if (c.normal.z() > 0.999) { ++up; CHECK(c.overlap == Approx(0.0004)); }
    if (c.normal.x() < -0.999) { ++side; CHECK(c.overlap == Approx(r - 0.0008 * std::cos(kPi / n)).epsilon(1e-9)); }
  }
  CHECK(up == 1);
  CHECK(side == 1);
  // On the bottom away from the wall: one contact, key = bottom region.
  const auto bottom = contactsAt(cup, Vec3(0.01, 0.02, 0.0009), r);
  REQUIRE(bottom.size() == 1);
  CHECK(bottom[0].key == cup.regionOf(0));
}

TEST_CASE("geometry sphere rolling over a sharp convex edge (vane blade tip) has one continuous contact") {
  MeshWall vane("vane", 0, buildVane());
  // Blade 0 lies along +x; its tip face is x = xo, top face z = 0.06. Move a sphere over the
  // top-tip edge on an arc around it at constant distance 0.0006 from the edge: overlap constant.
  const double ht = 0.001, xo = std::sqrt(0.025 * 0.025 - ht * ht), H = 0.06, r = 0.001, dist = 0.0006;
  Vec3 prev_n(0, 0, 1);
  for (int i = 0; i <= 2000; ++i) {
    const double a = -0.3 + (kPi / 2 + 0.6) * i / 2000.0;  // from above the top face to beside the tip face
    Vec3 centre;
    if (a < 0.0) centre = Vec3(xo + a * dist * 3, 0.0003, H + dist);          // over the top face
    else if (a > kPi / 2) centre = Vec3(xo + dist, 0.0003, H - (a - kPi / 2) * dist * 3);  // beside the tip
    else centre = Vec3(xo + dist * std::sin(a), 0.0003, H + dist * std::cos(a));  // around the edge
    const auto c = contactsAt(vane, centre, r);
    INFO("a = " << a << " centre " << centre.transpose());
    REQUIRE(c.size() == 1);
    REQUIRE(c[0].overlap == Approx(r - dist).epsilon(1e-9));
    REQUIRE((c[0].normal - prev_n).norm() < 0.01);
    prev_n = c[0].normal;
  }
  CHECK(prev_n.x() == Approx(1.0));
  // A sphere on the top face right next to the edge: one contact with normal +z.
  const auto near_edge = contactsAt(vane, Vec3(xo - 0.0002, 0.0, H + 0.0009), r);
  REQUIRE(near_edge.size() == 1);
  CHECK(near_edge[0].normal.z() == Approx(1.0));
}

TEST_CASE("geometry a sphere beside a thin closed blade within a contact range: the blade's far side is no penetration") {
  // The standard vane's blades are 2 mm thick. A sphere of radius 12.5 mm whose centre lies 16 mm
  // beside blade 0 (along +x, faces y = +-1 mm; 20 mm from the axis, out of reach of the shaft and the other blades) with a contact range of 6 mm (a liquid bridge's
  // rupture distance): the near face is 3.5 mm away (overlap -3.5 mm); the far face, 18 mm away,
  // is also within reach, but the centre is outside the blade, so it is no contact at all (taken
  // as a penetration it would be an overlap of r + 18 mm).
  MeshWall vane("vane", 0, buildVane());
  const double r = 0.0125, gap = 0.006;
  for (double y : {0.017, -0.017}) {
    const auto c = contactsAt(vane, Vec3(0.02, y, 0.03), r, gap);
    INFO("y = " << y);
    REQUIRE(c.size() == 1);
    CHECK(c[0].overlap == Approx(r - 0.016).epsilon(1e-9));
    CHECK(c[0].normal.y() == Approx(y > 0 ? 1.0 : -1.0));
  }
  // Past the blade tip, beside its corner: the closest feature is the tip edge; still one contact.
  const double xo = std::sqrt(0.025 * 0.025 - 0.001 * 0.001);
  const auto corner = contactsAt(vane, Vec3(xo + 0.003, 0.016, 0.03), r, gap);
  REQUIRE(corner.size() == 1);
  CHECK(corner[0].overlap == Approx(r - std::hypot(0.003, 0.015)).epsilon(1e-9));
  // A sphere that does penetrate the blade (centre inside it, 0.6 mm below the +y face) keeps its
  // contacts as penetrations: the +y face's with overlap r + 0.6 mm and none on the outside.
  const auto inside = contactsAt(vane, Vec3(0.02, 0.0004, 0.03), r, gap);
  REQUIRE_FALSE(inside.empty());
  bool near_face = false;
  for (const auto& x : inside) {
    CHECK(x.overlap > r);
    near_face = near_face || (std::abs(x.overlap - (r + 0.0006)) < 1e-9 && x.normal.y() == Approx(1.0));
  }
  CHECK(near_face);
}

TEST_CASE("geometry single-surface cone: contacts on both sides, key constant around the cone") {
  MeshWall cone("cone", 0, buildSlumpCone());
  CHECK(cone.regionCount() == 1);
  const double r = 0.001;
  // Inside, near the middle of a facet at mid-height (radius 0.075): pushed towards the axis.
  const double phi = kPi / 96, rho = 0.075 * std::cos(phi) - 0.0005;
  const auto in = contactsAt(cone, Vec3(rho * std::cos(phi), rho * std::sin(phi), 0.15), r);
  REQUIRE(in.size() == 1);
  CHECK(in[0].normal.x() < -0.98);
  CHECK(in[0].key == 0u);
  CHECK(in[0].normal.z() < 0.0);  // the wall leans inwards: its inner normal points down
  const double cos_beta = 0.3 / std::hypot(0.3, 0.05 * std::cos(phi));  // facet inclination
  CHECK(in[0].overlap == Approx(r - 0.0005 * cos_beta).epsilon(1e-9));
  // Outside: pushed away from the axis.
  const auto out = contactsAt(cone, Vec3(0.0755, 0.0, 0.15), r);
  REQUIRE(out.size() == 1);
  CHECK(out[0].normal.x() > 0.98);
}

TEST_CASE("geometry candidate lists give the same contacts as a full search, cost independent of mesh size") {
  double ratio[2] = {0, 0};
  int run = 0;
  // Same triangle size (12.5 mm squares), 64× more triangles in the second plate.
  for (auto [side, divisions] : {std::pair{0.2, 16}, std::pair{1.6, 128}}) {
    std::mt19937 rng(3);
    PlateParams pp;
    pp.side = side;
    pp.divisions = divisions;
    MeshWall plate("plate", 0, buildPlate(pp));
    std::vector<Vec3> pos;
    std::vector<double> rad;
    std::uniform_real_distribution<double> ux(-0.11, 0.11), uz(-0.003, 0.003), ur(0.0008, 0.0012);
    for (int i = 0; i < 20000; ++i) {
      pos.emplace_back(ux(rng), ux(rng), uz(rng));
      rad.push_back(ur(rng));
    }
    ParticleView view{pos.size(), pos.data(), rad.data()};
    const auto t0 = std::chrono::steady_clock::now();
    plate.buildCandidates(view, 0.0005);
    const auto t1 = std::chrono::steady_clock::now();
    plate.markListBuilt();
    std::vector<WallContact> fast;
    plate.findContacts(view, 0.0001, fast);
    const auto t2 = std::chrono::steady_clock::now();
    std::vector<WallContact> slow;
    for (std::size_t i = 0; i < pos.size(); ++i) plate.contactsOfSphere(pos[i], rad[i], 0.0001, static_cast<std::uint32_t>(i), slow);
    REQUIRE(fast.size() == slow.size());
    for (std::size_t k = 0; k < fast.size(); ++k) {
      REQUIRE(fast[k].particle == slow[k].particle);
      REQUIRE(fast[k].overlap == slow[k].overlap);
      REQUIRE(fast[k].key == slow[k].key);
    }
    // Every particle within reach of the plate has a contact.
    std::size_t expected = 0;
    for (std::size_t i = 0; i < pos.size(); ++i)
      if (std::abs(pos[i].z()) < rad[i] + 0.0001 && std::abs(pos[i].x()) <= 0.5 * side && std::abs(pos[i].y()) <= 0.5 * side) ++expected;
    CHECK(fast.size() >= expected);
    ratio[run++] = double(plate.candidatePairs()) / double(plate.candidateParticles());
    using ms = std::chrono::duration<double, std::milli>;
    const double build_ms = ms(t1 - t0).count(), find_ms = ms(t2 - t1).count();
    WARN("plate " << side << " m, " << 2 * divisions * divisions << " triangles: " << ratio[run - 1]
         << " triangles per candidate particle; buildCandidates " << build_ms << " ms, findContacts "
         << find_ms << " ms for 20000 particles");
  }
  CHECK(ratio[1] == Approx(ratio[0]).epsilon(0.1));
  CHECK(ratio[0] < 6.0);
}

TEST_CASE("geometry candidate lists hold each triangle within reach exactly once, and give the full search's "
          "contacts (single-surface cone, closed cup)") {
  CupParams cp;
  cp.thickness = 0.005;  // a closed solid
  const std::pair<const char*, TriangleMesh> parts[] = {{"cone", buildSlumpCone()}, {"cup", buildCup(cp)}};
  for (const auto& [name, mesh] : parts) {
    MeshWall wall(name, 0, mesh);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> urho(0.0, 0.12), uphi(0.0, 2.0 * kPi), uz(-0.01, 0.32), ur(0.004, 0.006);
    std::vector<Vec3> pos;
    std::vector<double> rad;
    for (int i = 0; i < 20000; ++i) {
      const double rho = urho(rng), phi = uphi(rng);
      pos.emplace_back(rho * std::cos(phi), rho * std::sin(phi), uz(rng));
      rad.push_back(ur(rng));
    }
    const double range = 0.003, max_gap = 0.0005;
    ParticleView view{pos.size(), pos.data(), rad.data()};
    wall.buildCandidates(view, range);
    wall.markListBuilt();
    // Brute force over every triangle: the pairs within radius + range, the particles with one.
    std::size_t pairs = 0, particles = 0;
    const TriangleMesh& m = wall.bodyMesh();
    for (std::size_t i = 0; i < pos.size(); ++i) {
      const double reach = rad[i] + range;
      std::size_t own = 0;
      for (const auto& t : m.triangles) {
        const Vec3 q = closestPointOnTriangle(pos[i], m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]).point;
        if ((q - pos[i]).squaredNorm() <= reach * reach) ++own;
      }
      pairs += own;
      particles += own > 0 ? 1 : 0;
    }
    INFO(name);
    REQUIRE(particles > 1000);
    CHECK(wall.candidateParticles() == particles);
    CHECK(wall.candidatePairs() == pairs);
    // The contacts from the candidate lists are those of the search over the whole grid.
    std::vector<WallContact> fast, slow;
    wall.findContacts(view, max_gap, fast);
    for (std::size_t i = 0; i < pos.size(); ++i) wall.contactsOfSphere(pos[i], rad[i], max_gap, static_cast<std::uint32_t>(i), slow);
    REQUIRE(fast.size() > 100);
    REQUIRE(fast.size() == slow.size());
    for (std::size_t k = 0; k < fast.size(); ++k) {
      REQUIRE(fast[k].particle == slow[k].particle);
      REQUIRE(fast[k].key == slow[k].key);
      REQUIRE(fast[k].overlap == slow[k].overlap);
      REQUIRE(fast[k].normal == slow[k].normal);
    }
  }
}

TEST_CASE("geometry moved wall: contacts follow the pose (tilted, shifted plate)") {
  Pose place;
  place.R = Eigen::AngleAxisd(0.3, Vec3(1, 0, 0)).toRotationMatrix();
  place.x = Vec3(0.1, 0.2, 0.3);
  MeshWall plate("plate", 0, buildPlate(), place);
  const Vec3 n = place.R * Vec3(0, 0, 1);
  const Vec3 centre = place.x + 0.05 * (place.R * Vec3(1, 0, 0)) + 0.0007 * n;
  const auto c = contactsAt(plate, centre, 0.001);
  REQUIRE(c.size() == 1);
  CHECK(c[0].overlap == Approx(0.0003).epsilon(1e-9));
  CHECK((c[0].normal - n).norm() < 1e-12);
  CHECK((c[0].point - (centre - 0.0007 * n)).norm() < 1e-12);
}
