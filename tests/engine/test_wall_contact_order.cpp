// The order of the particle–wall contacts: by (particle id, wall, key) whatever the particles'
// storage order. The wall contacts' history is matched to the stored one by a merge of two lists
// in that order (wall_forces.cpp), so a wrong order loses histories. The particles here are
// created against the spatial order, so the list build's re-sort stores them far from id order,
// and more than 256 of them touch the walls, so the sort key differs in more than one byte.
#include "test_models.hpp"

#include <paddy/plane_wall.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <memory>
#include <tuple>

using namespace paddy;

TEST_CASE("wall contacts come in (particle id, wall) order after the spatial re-sort", "[engine][walls]") {
  const double r = 1e-3;
  const int side = 24;  // 576 spheres on the floor, the last column also against a side wall
  Simulation sim(test::testPlugins());
  const auto [mud, steel] = test::mudAndSteelSprings(sim);
  const double x_max = (side - 1) * 2.5 * r;
  sim.addWall(std::make_unique<PlaneWall>("floor", steel, Vec3(0, 0, 0), Vec3::UnitZ()));
  sim.addWall(std::make_unique<PlaneWall>("side", steel, Vec3(x_max + r - 1e-5, 0, 0), -Vec3::UnitX()));
  // Created from the far corner back: ids rise against the cell order of the re-sort.
  for (int i = side - 1; i >= 0; --i)
    for (int j = side - 1; j >= 0; --j) sim.addParticle(Vec3(i * 2.5 * r, j * 2.5 * r, r - 1e-5), r, mud);
  sim.step(1);

  const auto& ids = sim.particles().id;
  bool stored_in_id_order = true;
  for (std::size_t k = 1; k < ids.size(); ++k) stored_in_id_order = stored_in_id_order && ids[k - 1] < ids[k];
  REQUIRE_FALSE(stored_in_id_order);  // the re-sort moved them: the order below is not the storage order

  std::size_t floor_contacts = 0, side_contacts = 0;
  std::tuple<std::uint64_t, std::uint64_t> last{0, 0};
  bool first = true;
  for (const auto& c : sim.contacts()) {
    if (!c.wall) continue;
    const std::tuple<std::uint64_t, std::uint64_t> key{c.id_i, c.id_j};
    if (!first) {
      INFO("contact of particle " << c.id_i << " with wall " << c.id_j);
      REQUIRE(std::get<0>(last) <= c.id_i);
      REQUIRE(last < key);
    }
    last = key;
    first = false;
    (c.id_j == 0 ? floor_contacts : side_contacts) += 1;
  }
  CHECK(floor_contacts == static_cast<std::size_t>(side * side));
  CHECK(side_contacts == static_cast<std::size_t>(side));
}
