// Wall load histories in HDF5 (writeLoadHistoryH5, MeshWall::writeLoadHistoryH5), read back with
// the HDF5 C API: values identical to the samples, units and names as attributes, one group per
// wall, atomic write, refused names.
#include "test_util.hpp"

#include <paddy/errors.hpp>
#include <paddy/geometry/load_history.hpp>
#include <paddy/geometry/mesh_wall.hpp>
#include <paddy/geometry/parts.hpp>

#include <catch2/catch.hpp>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <memory>

using namespace paddy;
using namespace paddy::geometry;
using Catch::Matchers::Contains;

namespace {

std::vector<double> readDoubles(hid_t file, const std::string& path, std::vector<hsize_t>& dims) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  REQUIRE(set >= 0);
  const hid_t space = H5Dget_space(set);
  dims.assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)), 0);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  std::vector<double> v(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  if (!v.empty()) REQUIRE(H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  H5Sclose(space);
  H5Dclose(set);
  return v;
}

std::string readString(hid_t file, const std::string& object, const char* name) {
  const hid_t attr = H5Aopen_by_name(file, object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(attr >= 0);
  const hid_t type = H5Aget_type(attr);
  CHECK(H5Tis_variable_str(type) > 0);
  const hid_t mem = H5Tcopy(H5T_C_S1);
  H5Tset_size(mem, H5T_VARIABLE);
  H5Tset_cset(mem, H5T_CSET_UTF8);
  char* text = nullptr;
  REQUIRE(H5Aread(attr, mem, &text) >= 0);
  std::string out(text);
  H5free_memory(text);
  H5Tclose(mem);
  H5Tclose(type);
  H5Aclose(attr);
  return out;
}

std::uint64_t readCount(hid_t file, const std::string& object, const char* name) {
  const hid_t attr = H5Aopen_by_name(file, object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(attr >= 0);
  std::uint64_t n = 0;
  REQUIRE(H5Aread(attr, H5T_NATIVE_UINT64, &n) >= 0);
  H5Aclose(attr);
  return n;
}

// Every value of the group equals the samples (bit for bit), and the units are recorded.
void checkGroup(hid_t f, const std::string& wall, const std::vector<LoadSample>& samples) {
  const std::string g = "/" + wall;
  const std::size_t n = samples.size();
  CHECK(readString(f, g, "wall") == wall);
  CHECK(readCount(f, g, "samples") == n);
  std::vector<hsize_t> dims;
  const auto t = readDoubles(f, g + "/t", dims);
  CHECK(dims == std::vector<hsize_t>{n});
  const auto force = readDoubles(f, g + "/force", dims);
  CHECK(dims == std::vector<hsize_t>{n, 3});
  const auto torque = readDoubles(f, g + "/torque", dims);
  CHECK(dims == std::vector<hsize_t>{n, 3});
  const auto axial = readDoubles(f, g + "/axial_torque", dims);
  const auto distance = readDoubles(f, g + "/distance", dims);
  const auto angle = readDoubles(f, g + "/angle", dims);
  CHECK(dims == std::vector<hsize_t>{n});
  for (std::size_t k = 0; k < n; ++k) {
    INFO(wall << " sample " << k);
    const LoadSample& s = samples[k];
    REQUIRE(t[k] == s.t);
    for (int c = 0; c < 3; ++c) {
      REQUIRE(force[3 * k + c] == s.force[c]);
      REQUIRE(torque[3 * k + c] == s.torque[c]);
    }
    REQUIRE(axial[k] == s.axial_torque);
    REQUIRE(distance[k] == s.distance);
    REQUIRE(angle[k] == s.angle);
  }
  CHECK(readString(f, g + "/t", "unit") == "s");
  CHECK(readString(f, g + "/force", "unit") == "N");
  CHECK(readString(f, g + "/force", "columns") == "x,y,z");
  CHECK(readString(f, g + "/torque", "unit") == "N m");
  CHECK(readString(f, g + "/axial_torque", "unit") == "N m");
  CHECK(readString(f, g + "/distance", "unit") == "m");
  CHECK(readString(f, g + "/angle", "unit") == "rad");
  CHECK_THAT(readString(f, g + "/torque", "description"), Contains("torque origin"));
}

// A vane turning at 0.7 rad/s and sinking at 1 mm/s, with pseudo-random loads at each sample.
std::unique_ptr<MeshWall> loadedVane(std::size_t samples) {
  Pose place;
  place.x = Vec3(0.01, -0.02, 0.03);
  Kinematics k = Kinematics::rotation(place.x, Vec3(0.1, 0, 1), SpeedSchedule::constant(0.7));
  k.direction = Vec3(0, 0, -1);
  k.speed = SpeedSchedule::constant(0.001);
  auto vane = std::make_unique<MeshWall>("vane", 0, buildVane(), place, k);
  for (std::size_t i = 1; i <= samples; ++i) {
    const double t = 0.0137 * static_cast<double>(i);
    vane->moveTo(t);
    vane->resetLoads();
    vane->addLoad(Vec3(std::sin(1.3 * t), std::cos(0.7 * t) / 3.0, -std::exp(-t)), vane->pose().apply(Vec3(0.02, 0, 0.01)));
    vane->addLoad(Vec3(1.0 / 7.0, -t * t, std::sqrt(t)), vane->pose().apply(Vec3(0, -0.025, 0.04)));
    vane->recordLoads(t);
  }
  return vane;
}

}  // namespace

TEST_CASE("geometry load history HDF5: one wall, read back identical to the samples") {
  test::TempDir dir;
  const auto owner = loadedVane(57);
  const MeshWall& vane = *owner;
  REQUIRE(vane.loadHistory().size() == 57);
  REQUIRE(vane.loadHistory().back().angle != 0.0);
  const std::string path = dir.file("vane_loads.h5");
  vane.writeLoadHistoryH5(path);
  // Atomic: the file and nothing else (no temporary left behind).
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path)) {
    ++files;
    CHECK(e.path().filename() == "vane_loads.h5");
  }
  CHECK(files == 1);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  CHECK(readString(f, "/", "format") == "paddy wall loads");
  CHECK(readCount(f, "/", "version") == 1);
  checkGroup(f, "vane", vane.loadHistory());
  H5Fclose(f);
  // Rewriting replaces the file.
  vane.writeLoadHistoryH5(path);
  CHECK(std::filesystem::exists(path));
}

TEST_CASE("geometry load history HDF5: several walls in one file, a group each, and empty histories") {
  test::TempDir dir;
  const auto owner = loadedVane(9);
  const MeshWall& vane = *owner;
  const MeshWall cup("cup", 0, buildCup());  // never recorded: zero-length datasets
  const std::string path = dir.file("loads.h5");
  writeLoadHistoryH5(path, {{"vane", &vane.loadHistory()}, {"cup", &cup.loadHistory()}});
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  checkGroup(f, "vane", vane.loadHistory());
  checkGroup(f, "cup", cup.loadHistory());
  H5Fclose(f);
}

TEST_CASE("geometry load history HDF5: refuses names that cannot be groups, and duplicates") {
  test::TempDir dir;
  const std::vector<LoadSample> s(3);
  const std::string path = dir.file("bad.h5");
  CHECK_THROWS_WITH(writeLoadHistoryH5(path, {{"a", &s}, {"a", &s}}), Contains("two walls are named 'a'"));
  CHECK_THROWS_WITH(writeLoadHistoryH5(path, {{"a/b", &s}}), Contains("'a/b' cannot name an HDF5 group"));
  CHECK_THROWS_WITH(writeLoadHistoryH5(path, {{"", &s}}), Contains("cannot name an HDF5 group"));
  CHECK_THROWS_WITH(writeLoadHistoryH5(path, {}), Contains("no wall load history"));
  CHECK_FALSE(std::filesystem::exists(path));
  // An unwritable location (below a regular file) is an error naming the place.
  const std::string blocked = dir.write("file", "x") + "/sub/loads.h5";
  CHECK_THROWS_WITH(writeLoadHistoryH5(blocked, {{"a", &s}}), Contains("file/sub"));
}
