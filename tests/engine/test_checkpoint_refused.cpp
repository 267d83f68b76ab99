// A checkpoint that is not what paddy wrote (engine/core/src/checkpoint_load.cpp): each damaged
// copy is refused with an InputError naming the file, the dataset or attribute and the cause,
// and the simulation that refused it is left exactly as it was (it steps on like its twin).
// The fuzz target tests/fuzz/fuzz_checkpoint.cpp explores such files at large.
#include "test_models.hpp"

#include <paddy/errors.hpp>
#include <paddy/plane_wall.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

using namespace paddy;

namespace {
std::unique_ptr<Simulation> makePile() {
  auto sim = std::make_unique<Simulation>(test::testPlugins());
  const int mud = sim->addMaterial(test::mud());
  auto spec = test::linearSpring();
  spec.extras = {"contact_age"};
  spec.params["stiffness"] = 200.0;
  sim->setInteraction(mud, mud, spec);
  sim->addWall(std::make_unique<PlaneWall>("floor", mud, Vec3::Zero(), Vec3::UnitZ()));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) sim->addParticle(Vec3(i * 1.99e-3, j * 1.99e-3, 0.999e-3 + k * 1.99e-3), 1e-3, mud);
  return sim;
}

// Opens the file read-write, lets `change` damage it, closes it.
void damage(const std::string& path, const std::function<void(hid_t)>& change) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(f >= 0);
  change(f);
  REQUIRE(H5Fclose(f) >= 0);
}
void setAttribute(hid_t f, const char* name, double v) {
  const hid_t a = H5Aopen(f, name, H5P_DEFAULT);
  REQUIRE(a >= 0);
  REQUIRE(H5Awrite(a, H5T_NATIVE_DOUBLE, &v) >= 0);
  H5Aclose(a);
}
// The first value of a dataset of doubles replaced by change(value).
void changeFirst(hid_t f, const char* name, double (*change)(double)) {
  const hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
  REQUIRE(d >= 0);
  const hid_t space = H5Dget_space(d);
  std::vector<double> v(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  REQUIRE(H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  v[0] = change(v[0]);
  REQUIRE(H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  H5Sclose(space);
  H5Dclose(d);
}
}  // namespace

TEST_CASE("a damaged checkpoint is refused naming the file, the dataset and the cause, and changes nothing",
          "[engine][checkpoint]") {
  const auto dir = std::filesystem::temp_directory_path() / "paddy_test_checkpoint_refused";
  std::filesystem::create_directories(dir);
  const std::string good = (dir / "good.h5").string(), bad = (dir / "bad.h5").string();
  auto writer = makePile();
  writer->step(200);
  REQUIRE(writer->neighbourListBuilds() > 0);  // a neighbour list (the range2 case needs its slots)
  writer->saveCheckpoint(good);

  struct Case {
    const char* what;
    std::function<void(hid_t)> change;
    const char* named;  // the dataset or attribute the message must name
    const char* cause;  // and a part of the cause
  };
  const std::vector<Case> cases = {
      {"dt NaN", [](hid_t f) { setAttribute(f, "dt", std::nan("")); }, "attribute 'dt'", "not a finite number"},
      {"another version", [](hid_t f) { setAttribute(f, "version", 2); }, "attribute 'version'", "checkpoint version 3"},
      {"steps fractional", [](hid_t f) { setAttribute(f, "steps", 10.5); }, "attribute 'steps'", "not a whole number"},
      {"a mass that is not its sphere's", [](hid_t f) { changeFirst(f, "particles/mass", [](double m) { return 2 * m; }); }, "dataset 'particles/mass'",
       "the density of material"},
      {"a position infinite", [](hid_t f) { changeFirst(f, "particles/position", [](double) { return HUGE_VAL; }); }, "dataset 'particles/position'",
       "holds inf at row 0"},
      {"an interaction range changed", [](hid_t f) { changeFirst(f, "list/range2", [](double r2) { return 4 * r2; }); }, "dataset 'list/range2'",
       "radii and contact law give"},
      {"the partner list missing", [](hid_t f) { REQUIRE(H5Ldelete(f, "list/partner", H5P_DEFAULT) >= 0); },
       "no dataset 'list/partner'", ""},
  };
  for (const auto& c : cases) {
    DYNAMIC_SECTION(c.what) {
      std::filesystem::copy_file(good, bad, std::filesystem::copy_options::overwrite_existing);
      damage(bad, c.change);
      auto sim = makePile();
      auto twin = makePile();
      sim->step(50);
      twin->step(50);
      try {
        sim->loadCheckpoint(bad);
        FAIL("the damaged checkpoint was accepted");
      } catch (const InputError& e) {
        const std::string m = e.what();
        INFO(m);
        CHECK(m.find(bad) != std::string::npos);
        CHECK(m.find(c.named) != std::string::npos);
        CHECK(m.find(c.cause) != std::string::npos);
      }
      // Left as it was: the same state, and it steps on exactly like its twin.
      sim->step(100);
      twin->step(100);
      REQUIRE(sim->stepCount() == 150);
      const auto& p = sim->particles();
      const auto& q = twin->particles();
      REQUIRE(p.size() == q.size());
      for (std::size_t i = 0; i < p.size(); ++i) {
        REQUIRE(p.id[i] == q.id[i]);
        REQUIRE(p.position[i] == q.position[i]);
        REQUIRE(p.velocity[i] == q.velocity[i]);
      }
    }
  }
  // The undamaged file is accepted (the checks do not refuse what paddy writes).
  auto resumed = makePile();
  resumed->loadCheckpoint(good);
  REQUIRE(resumed->stepCount() == 200);
  std::filesystem::remove_all(dir);
}
