// Snapshots written by paddy::io::SnapshotWriter are read back with the HDF5 C API.
#include <paddy/io/snapshot.hpp>
#include <paddy/plugin_manager.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>
#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace paddy;

namespace {

fs::path workDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("paddy_io_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Reads a whole dataset of doubles/u64 and its dimensions.
template <class T>
std::vector<T> readDataset(hid_t file, const char* path, hid_t type, std::vector<hsize_t>& dims) {
  const hid_t set = H5Dopen2(file, path, H5P_DEFAULT);
  REQUIRE(set >= 0);
  const hid_t space = H5Dget_space(set);
  dims.assign(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)), 0);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  hsize_t total = 1;
  for (hsize_t d : dims) total *= d;
  std::vector<T> values(total);
  if (total) REQUIRE(H5Dread(set, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0);
  H5Sclose(space);
  H5Dclose(set);
  return values;
}

double readAttribute(hid_t file, const char* name, hid_t type) {
  const hid_t attr = H5Aopen(file, name, H5P_DEFAULT);
  REQUIRE(attr >= 0);
  double d = 0;
  std::uint64_t u = 0;
  if (type == H5T_NATIVE_DOUBLE) H5Aread(attr, type, &d);
  else H5Aread(attr, type, &u);
  H5Aclose(attr);
  return type == H5T_NATIVE_DOUBLE ? d : double(u);
}

std::unique_ptr<Simulation> twoSpheres() {
  // Kept alive beyond the simulations: plugin code must outlive the sub-models it created.
  static const auto plugins = [] {
    auto p = std::make_shared<PluginManager>();
    p->loadDefault();
    return p;
  }();
  auto sim = std::make_unique<Simulation>(plugins);
  const int m = sim->addMaterial({"mud", 1680, 1e6, 0.5});
  InteractionSpec spec;
  spec.params = {{"restitution", 0.5}, {"friction", 0.3}};
  sim->setInteraction(m, m, spec);
  sim->setGravity(Vec3::Zero());
  sim->addParticle(Vec3(0, 0, 0), 0.001, m, Vec3(0.01, 0, 0));
  sim->addParticle(Vec3(0.0019, 0, 0), 0.001, m);
  sim->addParticle(Vec3(0.1, 0.2, 0.3), 0.0015, m, Vec3(0, 0, -1));
  sim->setTimeStepFraction(0.2);
  return sim;
}

}  // namespace

TEST_CASE("io: snapshot is readable back with the right particles and contacts", "[io]") {
  auto sim = twoSpheres();
  sim->step(3);
  const fs::path dir = workDir("snapshot");
  io::SnapshotWriter writer(dir / "snapshots");
  const fs::path file = writer.write(*sim);
  CHECK(file.filename() == "snap_000000.h5");
  REQUIRE(fs::exists(file));

  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  std::vector<hsize_t> dims;
  const auto pos = readDataset<double>(f, "/particles/position", H5T_NATIVE_DOUBLE, dims);
  REQUIRE(dims == std::vector<hsize_t>{3, 3});
  const auto& p = sim->particles();
  for (std::size_t i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) CHECK(pos[3 * i + k] == p.position[i][k]);
  const auto radius = readDataset<double>(f, "/particles/radius", H5T_NATIVE_DOUBLE, dims);
  CHECK(radius == p.radius);
  const auto ids = readDataset<std::uint64_t>(f, "/particles/id", H5T_NATIVE_UINT64, dims);
  CHECK(ids == p.id);
  const auto vel = readDataset<double>(f, "/particles/velocity", H5T_NATIVE_DOUBLE, dims);
  CHECK(vel[3 * 2 + 2] == p.velocity[2].z());
  for (const char* name : {"/particles/omega", "/particles/force", "/particles/material"})
    CHECK(H5Lexists(f, name, H5P_DEFAULT) > 0);
  // The XDMF connectivity: one vertex cell per particle, 0 .. N-1.
  const auto vertex = readDataset<std::int64_t>(f, "/particles/vertex", H5T_NATIVE_INT64, dims);
  REQUIRE(vertex.size() == sim->particles().size());
  for (std::size_t i = 0; i < vertex.size(); ++i) CHECK(vertex[i] == static_cast<std::int64_t>(i));
  CHECK(readAttribute(f, "time", H5T_NATIVE_DOUBLE) == sim->time());
  CHECK(readAttribute(f, "step", H5T_NATIVE_UINT64) == 3.0);

  const auto contacts = sim->contacts();
  const auto id_i = readDataset<std::uint64_t>(f, "/contacts/id_i", H5T_NATIVE_UINT64, dims);
  CHECK(id_i.size() == contacts.size());
  CHECK(contacts.size() >= 1);  // the two touching spheres
  const auto fn = readDataset<double>(f, "/contacts/fn", H5T_NATIVE_DOUBLE, dims);
  for (std::size_t k = 0; k < contacts.size(); ++k) CHECK(fn[k] == contacts[k].fn);
  const auto normal = readDataset<double>(f, "/contacts/normal", H5T_NATIVE_DOUBLE, dims);
  CHECK(dims == std::vector<hsize_t>{contacts.size(), 3});
  for (const char* name : {"/contacts/id_j", "/contacts/wall", "/contacts/overlap", "/contacts/ft"})
    CHECK(H5Lexists(f, name, H5P_DEFAULT) > 0);
  H5Fclose(f);
}

TEST_CASE("io: XDMF index lists every snapshot and refers to existing datasets", "[io]") {
  auto sim = twoSpheres();
  const fs::path dir = workDir("xdmf") / "snapshots";
  fs::create_directories(dir);
  std::ofstream(dir / "snap_000007.h5") << "stale";  // left over from an earlier run
  io::SnapshotWriter writer(dir);
  writer.write(*sim);
  sim->step(2);
  writer.write(*sim);
  CHECK_FALSE(fs::exists(dir / "snap_000007.h5"));
  CHECK(writer.count() == 2);

  std::ifstream in(dir / "particles.xmf");
  std::stringstream text;
  text << in.rdbuf();
  const std::string xmf = text.str();
  CHECK_THAT(xmf, Catch::Contains("CollectionType=\"Temporal\"") && Catch::Contains("Polyvertex"));
  const std::regex ref(R"(>([^<>:]+\.h5):(/[^<]+)</DataItem>)");
  std::size_t refs = 0;
  for (auto it = std::sregex_iterator(xmf.begin(), xmf.end(), ref); it != std::sregex_iterator(); ++it) {
    const fs::path file = dir / (*it)[1].str();
    REQUIRE(fs::exists(file));
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    REQUIRE(f >= 0);
    CHECK(H5Lexists(f, (*it)[2].str().c_str(), H5P_DEFAULT) > 0);
    H5Fclose(f);
    ++refs;
  }
  CHECK(refs == 2 * 8);  // vertex connectivity + position + 6 attributes per snapshot
  for (const auto& entry : fs::directory_iterator(dir))
    CHECK(entry.path().string().find(".tmp") == std::string::npos);  // no temporaries left
}

TEST_CASE("io: mesh walls are written beside the particles and indexed in walls.xmf", "[io]") {
  auto sim = twoSpheres();
  const fs::path dir = workDir("walls") / "snapshots";
  // Two surfaces: a tetrahedron and a single triangle, moved between the two snapshots.
  io::WallSurface tetra{"cone", {{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)},
                                 {{{0, 2, 1}}, {{0, 1, 3}}, {{0, 3, 2}}, {{1, 2, 3}}}}};
  io::WallSurface tri{"vane", {{Vec3(2, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0)}, {{{0, 1, 2}}}}};
  io::SnapshotWriter writer(dir);
  writer.write(*sim);  // no walls: no /walls group, no walls.xmf
  CHECK_FALSE(fs::exists(dir / "walls.xmf"));
  sim->step(2);
  for (Vec3& v : tetra.mesh.vertices) v.z() += 0.5;
  const fs::path file = writer.write(*sim, {tetra, tri});

  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  REQUIRE(f >= 0);
  std::vector<hsize_t> dims;
  const auto vertices = readDataset<double>(f, "/walls/vertices", H5T_NATIVE_DOUBLE, dims);
  CHECK(dims == std::vector<hsize_t>{7, 3});
  CHECK(vertices[3 * 3 + 2] == 1.5);  // the tetrahedron's apex, moved up
  CHECK(vertices[3 * 6 + 0] == 2.0);  // the triangle's last vertex
  const auto triangles = readDataset<std::int64_t>(f, "/walls/triangles", H5T_NATIVE_INT64, dims);
  CHECK(dims == std::vector<hsize_t>{5, 3});
  CHECK(std::vector<std::int64_t>(triangles.end() - 3, triangles.end()) == std::vector<std::int64_t>{4, 5, 6});
  const auto wall = readDataset<std::int32_t>(f, "/walls/wall", H5T_NATIVE_INT32, dims);
  CHECK(wall == std::vector<std::int32_t>{0, 0, 0, 0, 1});
  const hid_t group = H5Gopen2(f, "/walls", H5P_DEFAULT);
  const hid_t attr = H5Aopen(group, "names", H5P_DEFAULT);
  REQUIRE(attr >= 0);
  const hid_t type = H5Aget_type(attr);
  std::string names(H5Tget_size(type), '\0');
  CHECK(H5Aread(attr, type, names.data()) >= 0);
  CHECK(names.c_str() == std::string("cone\nvane"));
  H5Tclose(type);
  H5Aclose(attr);
  H5Gclose(group);
  H5Fclose(f);

  std::ifstream in(dir / "walls.xmf");
  std::stringstream text;
  text << in.rdbuf();
  const std::string xmf = text.str();
  CHECK_THAT(xmf, Catch::Contains("CollectionType=\"Temporal\"") && Catch::Contains("TopologyType=\"Triangle\"") &&
                      Catch::Contains("NumberOfElements=\"5\"") && Catch::Contains("snap_000001.h5:/walls/vertices"));
  CHECK(xmf.find("snap_000000.h5") == std::string::npos);  // the first snapshot had no walls
}
