// Load histories of walls in HDF5 (layout in load_history.hpp): one group per wall, one dataset
// per quantity (vectors N×3), units as attributes; written under a temporary name and renamed.
#include <paddy/io/h5_file.hpp>

#include <paddy/errors.hpp>
#include <paddy/geometry/load_history.hpp>
#include <paddy/io/atomic_file.hpp>

#include <filesystem>
#include <set>

namespace paddy::geometry {

namespace {

constexpr std::uint64_t kFormatVersion = 1;

struct Column {
  const char* name;
  const char* unit;
  const char* description;
};

void writeScalar(h5::File& f, const std::string& group, const Column& c, const std::vector<LoadSample>& samples,
                 double (*get)(const LoadSample&)) {
  std::vector<double> v;
  v.reserve(samples.size());
  for (const LoadSample& s : samples) v.push_back(get(s));
  const std::string path = group + "/" + c.name;
  f.write(path, v);
  f.writeAttr(path, "unit", std::string(c.unit));
  f.writeAttr(path, "description", std::string(c.description));
}

void writeVector(h5::File& f, const std::string& group, const Column& c, const std::vector<LoadSample>& samples,
                 const Vec3& (*get)(const LoadSample&)) {
  std::vector<double> v;
  v.reserve(3 * samples.size());
  for (const LoadSample& s : samples) {
    const Vec3& x = get(s);
    v.insert(v.end(), {x.x(), x.y(), x.z()});
  }
  const std::string path = group + "/" + c.name;
  f.write(path, v, 3);
  f.writeAttr(path, "unit", std::string(c.unit));
  f.writeAttr(path, "description", std::string(c.description));
  f.writeAttr(path, "columns", std::string("x,y,z"));
}

void writeWall(h5::File& f, const NamedLoadHistory& w) {
  const std::vector<LoadSample>& s = *w.samples;
  const std::string g = "/" + w.wall;
  writeScalar(f, g, {"t", "s", "simulated time of the sample"}, s, [](const LoadSample& x) { return x.t; });
  writeVector(f, g, {"force", "N", "force exerted by the particles on the wall"}, s,
              [](const LoadSample& x) -> const Vec3& { return x.force; });
  writeVector(f, g, {"torque", "N m", "torque about the torque origin (current point of the rotation axis)"}, s,
              [](const LoadSample& x) -> const Vec3& { return x.torque; });
  writeScalar(f, g, {"axial_torque", "N m", "torque component along the rotation axis"}, s,
              [](const LoadSample& x) { return x.axial_torque; });
  writeScalar(f, g, {"distance", "m", "distance travelled along the translation direction, summed over the changes of motion"}, s,
              [](const LoadSample& x) { return x.distance; });
  writeScalar(f, g, {"angle", "rad", "angle turned about the rotation axis, summed over the changes of motion"}, s,
              [](const LoadSample& x) { return x.angle; });
  f.writeAttr(g, "wall", w.wall);
  f.writeAttr(g, "samples", static_cast<std::uint64_t>(s.size()));
}

void checkNames(const std::string& path, const std::vector<NamedLoadHistory>& walls) {
  if (walls.empty()) throw InputError(path + ": no wall load history to write");
  std::set<std::string> seen;
  for (const auto& w : walls) {
    if (!w.samples) throw InputError(path + ": wall '" + w.wall + "' has no load history");
    if (w.wall.empty() || w.wall == "." || w.wall.find('/') != std::string::npos)
      throw InputError(path + ": wall name '" + w.wall +
                       "' cannot name an HDF5 group (it must be non-empty, not \".\", and without '/')");
    if (!seen.insert(w.wall).second)
      throw InputError(path + ": two walls are named '" + w.wall +
                       "'; each wall's group is named after it, so give the walls distinct names");
  }
}

}  // namespace

void writeLoadHistoryH5(const std::string& path, const std::vector<NamedLoadHistory>& walls) {
  checkNames(path, walls);
  // Errors name the temporary "<path>.tmp.<pid>" (removed again) or the target.
  io::produceFileAtomic(path, [&](const std::filesystem::path& tmp) {
    h5::File f = h5::File::create(tmp.string());
    f.writeAttr("/", "format", std::string("paddy wall loads"));
    f.writeAttr("/", "version", kFormatVersion);
    for (const auto& w : walls) writeWall(f, w);
    f.close();
  });
}

}  // namespace paddy::geometry
