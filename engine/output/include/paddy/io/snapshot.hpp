// HDF5 snapshots of a simulation and the XDMF index that lets ParaView open them.
//
// Layout of one snapshot file (all SI units):
//   /particles/{id (u64, N), material (i32, N), radius (N), position, velocity, omega, force (N×3),
//               vertex (i64, N: 0 .. N-1, the connectivity of the XDMF Polyvertex topology)}
//   /contacts/{id_i, id_j (u64, M), wall (u8, M), overlap (M), normal (M×3), fn (M), ft (M×3)}
//   /walls/{vertices (V×3), triangles (i64, T×3: vertex rows), wall (i32, T: index into names)},
//          attribute names ("\n"-separated): the surfaces of the finite walls (triangle meshes:
//          cone, vane, cup...) at the snapshot's time, in world coordinates; only when there are
//          any (an infinite plane has no surface to draw)
//   root attributes: time (double), step (u64)
// A SnapshotWriter numbers its files snap_000000.h5, snap_000001.h5, ... in its directory and
// rewrites particles.xmf (a temporal collection of Polyvertex grids, one vertex cell per particle:
// ParaView draws them in its default view) after each one, and walls.xmf (a temporal collection of
// Triangle grids, one per snapshot with wall surfaces) when the snapshots hold walls.
#pragma once

#include <paddy/geometry.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace paddy {
class Simulation;
}

namespace paddy::io {

// A wall's surface at the time of a snapshot: world coordinates [m], triangles as in TriangleMesh.
struct WallSurface {
  std::string name;
  TriangleMesh mesh;
};

// Writes one snapshot file (atomically), with the given wall surfaces (none: no /walls group).
// Throws std::runtime_error naming the file on failure.
void writeSnapshot(const Simulation& sim, const std::filesystem::path& file,
                   const std::vector<WallSurface>& walls = {});

struct SnapshotEntry {
  std::string file;  // file name relative to the XDMF file's directory
  double time = 0.0;
  std::uint64_t particles = 0;
  std::uint64_t wall_vertices = 0, wall_triangles = 0;  // of /walls (0: none in this file)
};

// The XDMF text for a list of snapshots (exposed for tests): particles.xmf, and walls.xmf (the
// entries with wall triangles; empty text when there are none).
std::string xdmfText(const std::vector<SnapshotEntry>& entries);
std::string wallsXdmfText(const std::vector<SnapshotEntry>& entries);

class SnapshotWriter {
 public:
  explicit SnapshotWriter(std::filesystem::path dir) : dir_(std::move(dir)) {}
  // Writes the next snapshot and the updated XDMF; returns the snapshot's path. The first call
  // removes stale snap_*.h5 files, particles.xmf and walls.xmf left in the directory by an
  // earlier run.
  std::filesystem::path write(const Simulation& sim, const std::vector<WallSurface>& walls = {});
  const std::filesystem::path& directory() const { return dir_; }
  std::size_t count() const { return entries_.size(); }

 private:
  std::filesystem::path dir_;
  std::vector<SnapshotEntry> entries_;
};

}  // namespace paddy::io
