// HDF5 snapshot files, see paddy/io/snapshot.hpp.
#include <paddy/io/atomic_file.hpp>
#include <paddy/io/snapshot.hpp>
#include <paddy/simulation.hpp>

#include "hdf5_util.hpp"

#include <cstdio>
#include <system_error>

namespace paddy::io {

namespace fs = std::filesystem;

namespace {

// Copies a Vec3 field into a contiguous N×3 array (Eigen's Vector3d is 3 packed doubles, but
// copying keeps the file layout independent of the container).
template <class Range, class Get>
std::vector<double> flatten3(const Range& items, Get get) {
  std::vector<double> out;
  out.reserve(items.size() * 3);
  for (const auto& item : items) {
    const Vec3& v = get(item);
    out.insert(out.end(), {v.x(), v.y(), v.z()});
  }
  return out;
}

void writeParticles(hid_t file, const ParticleArrays& p) {
  using namespace h5;
  Handle group(H5Gcreate2(file, "particles", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
               "create group /particles");
  const std::size_t n = p.size();
  const auto identity = [](const Vec3& v) -> const Vec3& { return v; };
  writeDataset(group, "id", H5T_NATIVE_UINT64, n, 0, p.id.data());
  std::vector<std::int32_t> material(p.material.begin(), p.material.end());
  writeDataset(group, "material", H5T_NATIVE_INT32, n, 0, material.data());
  writeDataset(group, "radius", H5T_NATIVE_DOUBLE, n, 0, p.radius.data());
  writeDataset(group, "position", H5T_NATIVE_DOUBLE, n, 3, flatten3(p.position, identity).data());
  writeDataset(group, "velocity", H5T_NATIVE_DOUBLE, n, 3, flatten3(p.velocity, identity).data());
  writeDataset(group, "omega", H5T_NATIVE_DOUBLE, n, 3, flatten3(p.omega, identity).data());
  writeDataset(group, "force", H5T_NATIVE_DOUBLE, n, 3, flatten3(p.force, identity).data());
  // The vertex cells of the XDMF topology (0 .. N-1): without an explicit connectivity ParaView's
  // XDMF3 reader makes points but no cells, and its default Surface view shows nothing.
  std::vector<std::int64_t> vertex(n);
  for (std::size_t i = 0; i < n; ++i) vertex[i] = static_cast<std::int64_t>(i);
  writeDataset(group, "vertex", H5T_NATIVE_INT64, n, 0, vertex.data());
}

void writeContacts(hid_t file, const std::vector<ContactRecord>& c) {
  using namespace h5;
  Handle group(H5Gcreate2(file, "contacts", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
               "create group /contacts");
  const std::size_t m = c.size();
  std::vector<std::uint64_t> id_i(m), id_j(m);
  std::vector<std::uint8_t> wall(m);
  std::vector<double> overlap(m), fn(m);
  for (std::size_t k = 0; k < m; ++k) {
    id_i[k] = c[k].id_i;
    id_j[k] = c[k].id_j;
    wall[k] = c[k].wall ? 1 : 0;
    overlap[k] = c[k].overlap;
    fn[k] = c[k].fn;
  }
  writeDataset(group, "id_i", H5T_NATIVE_UINT64, m, 0, id_i.data());
  writeDataset(group, "id_j", H5T_NATIVE_UINT64, m, 0, id_j.data());
  writeDataset(group, "wall", H5T_NATIVE_UINT8, m, 0, wall.data());
  writeDataset(group, "overlap", H5T_NATIVE_DOUBLE, m, 0, overlap.data());
  writeDataset(group, "fn", H5T_NATIVE_DOUBLE, m, 0, fn.data());
  writeDataset(group, "normal", H5T_NATIVE_DOUBLE, m, 3,
               flatten3(c, [](const ContactRecord& r) -> const Vec3& { return r.normal; }).data());
  writeDataset(group, "ft", H5T_NATIVE_DOUBLE, m, 3,
               flatten3(c, [](const ContactRecord& r) -> const Vec3& { return r.ft; }).data());
}

void writeWalls(hid_t file, const std::vector<WallSurface>& walls) {
  using namespace h5;
  std::vector<double> vertices;
  std::vector<std::int64_t> triangles;
  std::vector<std::int32_t> wall;
  std::string names;
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const TriangleMesh& m = walls[k].mesh;
    const auto offset = static_cast<std::int64_t>(vertices.size() / 3);
    for (const Vec3& v : m.vertices) vertices.insert(vertices.end(), {v.x(), v.y(), v.z()});
    for (const auto& t : m.triangles) {
      for (std::uint32_t i : t) triangles.push_back(offset + static_cast<std::int64_t>(i));
      wall.push_back(static_cast<std::int32_t>(k));
    }
    names += (k ? "\n" : "") + walls[k].name;
  }
  Handle group(H5Gcreate2(file, "walls", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
               "create group /walls");
  writeAttribute(group, "names", names);
  writeDataset(group, "vertices", H5T_NATIVE_DOUBLE, vertices.size() / 3, 3, vertices.data());
  writeDataset(group, "triangles", H5T_NATIVE_INT64, wall.size(), 3, triangles.data());
  writeDataset(group, "wall", H5T_NATIVE_INT32, wall.size(), 0, wall.data());
}

}  // namespace

void writeSnapshot(const Simulation& sim, const fs::path& file, const std::vector<WallSurface>& walls) {
  const std::vector<ContactRecord> contacts = sim.contacts();
  produceFileAtomic(file, [&](const fs::path& tmp) {
    using namespace h5;
    try {
      Handle f(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
               "create file " + tmp.string());
      writeAttribute(f, "time", sim.time());
      writeAttribute(f, "step", static_cast<std::uint64_t>(sim.stepCount()));
      writeParticles(f, sim.particles());
      writeContacts(f, contacts);
      if (!walls.empty()) writeWalls(f, walls);
      f.close("write file " + tmp.string());
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(std::string(e.what()) + " (snapshot " + file.string() + ")");
    }
  });
}

fs::path SnapshotWriter::write(const Simulation& sim, const std::vector<WallSurface>& walls) {
  if (entries_.empty()) {
    // Stale files from an earlier run in the same directory would confuse readers.
    std::error_code ec;
    if (fs::is_directory(dir_, ec)) {
      for (const auto& entry : fs::directory_iterator(dir_, ec)) {
        const std::string name = entry.path().filename().string();
        // (also the temporaries of a run killed while writing: snap_NNNNNN.h5.tmp.PID)
        if ((name.rfind("snap_", 0) == 0 && (entry.path().extension() == ".h5" || name.find(".h5.tmp.") != std::string::npos)) ||
            name == "particles.xmf" || name == "walls.xmf")
          fs::remove(entry.path(), ec);
      }
    }
  }
  char name[32];
  std::snprintf(name, sizeof name, "snap_%06zu.h5", entries_.size());
  const fs::path file = dir_ / name;
  writeSnapshot(sim, file, walls);
  SnapshotEntry entry{name, sim.time(), sim.particles().size()};
  for (const WallSurface& w : walls) {
    entry.wall_vertices += w.mesh.vertices.size();
    entry.wall_triangles += w.mesh.triangles.size();
  }
  entries_.push_back(std::move(entry));
  writeFileAtomic(dir_ / "particles.xmf", xdmfText(entries_));
  const std::string walls_xmf = wallsXdmfText(entries_);
  if (!walls_xmf.empty()) writeFileAtomic(dir_ / "walls.xmf", walls_xmf);
  return file;
}

}  // namespace paddy::io
