// The C++ object behind a Lua `paddy.simulation` userdata (private to engine/lua/src).
#pragma once

#include <paddy/io/snapshot.hpp>
#include <paddy/simulation.hpp>

#include <lua.hpp>

#include <filesystem>
#include <memory>

namespace paddy::lua {

struct SimHandle {
  std::unique_ptr<Simulation> sim;
  std::filesystem::path snapshot_dir;           // DIR/snapshots (DIR/snapshots_<k> for later ones)
  std::unique_ptr<io::SnapshotWriter> snapshots; // created on the first snapshot
};

inline constexpr const char* kSimulationMeta = "paddy.Simulation";

// The simulation `self` at stack index `idx`; throws InputError if it is something else.
SimHandle& checkSim(lua_State* L, int idx);
// Material id from a Lua value: the id returned by sim:material or a material name.
int materialArg(lua_State* L, SimHandle& h, int idx, const std::string& what);
// Ensures a time step is set (default fraction of the Rayleigh time) and returns it.
double ensureTimeStep(Simulation& sim);
// Order-independent digest of positions and velocities, ordered by particle id (hex).
std::string stateHash(const ParticleArrays& p);

}  // namespace paddy::lua
