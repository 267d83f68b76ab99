// sim:run{...}: the time loop. The engine steps in chunks; between chunks it calls the script's
// callback, writes snapshots and redraws the progress line.
//
//   sim:run{duration = 0.5 | steps = 10000, every = 0.01, callback = function(s) ... end,
//           snapshot_every = 0.05, record_loads_every = 0.01, record_loads = {w, ...},
//           progress = true}  → steps taken, stopped_early
//
// record_loads_every = T appends a load sample to every mesh wall (or to the walls listed in
// record_loads) without a callback, at the instants a callback with every = T would run:
// t0 + k·n·dt (n = round(T/dt) steps, k = 1, 2, ...) and at the end of the run (also when a
// callback stops it early), once per instant. Order at an instant: snapshot, loads, callback.
//
// checkpoint = "name.h5", checkpoint_every = T: saves the whole state (sim:checkpoint, written to a
// temporary file and renamed) every round(T/dt) steps of this run. If that file exists when the
// run starts, the run resumes from it: a script killed in the middle and started again with the
// same output directory, seed and thread count ends in the same state as an uninterrupted run.
// The steps done before the checkpoint are not repeated, nor their callbacks, snapshots and load
// samples (docs/reliability.md). A relative path is taken inside paddy.out_dir.
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"
#include "sim_handle.hpp"
#include "wall_args.hpp"

#include <paddy/errors.hpp>
#include <paddy/io/progress.hpp>
#include <paddy/simulation.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace paddy::lua {

std::filesystem::path writeSnapshot(lua_State* L, SimHandle& h);  // lua_output.cpp

namespace {

using Clock = std::chrono::steady_clock;

// Steps of length dt in `seconds` (rounded to the nearest step, at least 1).
std::uint64_t stepsFor(double seconds, double dt, const char* what) {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) {
    std::ostringstream m;
    m << "sim:run: " << what << " = " << seconds << " s must be a positive number of seconds (> 0, finite)";
    throw InputError(m.str());
  }
  return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(seconds / dt)));
}

// Next multiple of `every` after `done` (or `never` when every == 0).
std::uint64_t nextEvent(std::uint64_t done, std::uint64_t every, std::uint64_t never) {
  return every ? (done / every + 1) * every : never;
}

// Calls the callback (stack index `cb`) with the simulation (index 1); false stops the run.
bool callBack(lua_State* L, int cb) {
  lua_pushvalue(L, cb);
  lua_pushvalue(L, 1);
  protectedCall(L, 1, 1);
  const bool stop = lua_type(L, -1) == LUA_TBOOLEAN && !lua_toboolean(L, -1);
  lua_pop(L, 1);
  return !stop;
}

int run(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  Simulation& sim = *h.sim;
  OptionTable opt(L, 2, "sim:run");
  const double dt = ensureTimeStep(sim);
  const auto duration = opt.optNumber("duration");
  const long long steps_opt = opt.integer("steps", 0);
  if (duration && steps_opt) throw InputError("sim:run: give either duration or steps, not both");
  if (!duration && steps_opt <= 0) throw InputError("sim:run needs duration = (seconds) or steps = (count > 0)");
  const std::uint64_t total = duration ? stepsFor(*duration, dt, "duration") : static_cast<std::uint64_t>(steps_opt);

  const bool has_callback = opt.push("callback") == LUA_TFUNCTION;
  if (!has_callback && !lua_isnil(L, -1)) throw InputError("sim:run: callback must be a function");
  const int cb = lua_gettop(L);
  std::uint64_t every = 0, snap_every = 0;
  if (auto e = opt.optNumber("every")) every = stepsFor(*e, dt, "every");
  if (auto e = opt.integer("every_steps", 0)) every = static_cast<std::uint64_t>(std::max<long long>(e, 1));
  if (has_callback && !every) every = total;  // at the end only
  if (auto e = opt.optNumber("snapshot_every")) snap_every = stepsFor(*e, dt, "snapshot_every");
  std::uint64_t rec_every = 0;
  if (auto e = opt.optNumber("record_loads_every")) rec_every = stepsFor(*e, dt, "record_loads_every");
  std::vector<int> recorded;  // wall indices
  if (opt.push("record_loads") != LUA_TNIL) {
    if (!rec_every) throw InputError("sim:run: record_loads needs record_loads_every = (seconds > 0)");
    recorded = meshWallList(L, h, -1, "sim:run: record_loads");
  } else if (rec_every) {
    recorded = allMeshWalls(sim);
    if (recorded.empty())
      throw InputError("sim:run: record_loads_every: the simulation has no mesh walls to record (sim:add_mesh_wall)");
  }
  lua_pop(L, 1);
  std::uint64_t ck_every = 0;
  std::filesystem::path ck_path;
  if (auto e = opt.optNumber("checkpoint_every")) ck_every = stepsFor(*e, dt, "checkpoint_every");
  if (opt.push("checkpoint") != LUA_TNIL) {
    ck_path = toString(L, -1, "sim:run: checkpoint");
    if (ck_path.empty()) throw InputError("sim:run: checkpoint must name a file (e.g. \"settle.h5\")");
    if (ck_path.is_relative()) ck_path = runtimeState(L).out_dir / ck_path;
  }
  lua_pop(L, 1);
  if (ck_every && ck_path.empty()) throw InputError("sim:run: checkpoint_every needs checkpoint = (file name)");
  if (!ck_path.empty() && !ck_every) throw InputError("sim:run: checkpoint needs checkpoint_every = (seconds > 0)");
  const bool progress = opt.boolean("progress", true);
  opt.finish();
  auto recordLoads = [&] {
    for (int w : recorded) dynamic_cast<MeshWall&>(sim.wall(w)).recordLoads(sim.time());
  };

  RuntimeState& st = runtimeState(L);
  std::uint64_t done = 0, chunk = 16, recorded_at = 0;
  if (ck_every && std::filesystem::exists(ck_path)) {
    // Resume: the checkpoint was written by this run of the same script (same set-up before it).
    const std::uint64_t first = sim.stepCount();
    const double t_first = sim.time();
    sim.loadCheckpoint(ck_path.string());
    if (sim.stepCount() < first || sim.stepCount() - first > total)
      throw InputError("sim:run: checkpoint '" + ck_path.string() + "' is at step " + std::to_string(sim.stepCount()) +
                       ", outside this run (steps " + std::to_string(first) + " to " + std::to_string(first + total) +
                       "): it belongs to another run; remove it to start afresh");
    if (sim.time() < t_first) {
      std::ostringstream m;
      m.precision(17);
      m << "sim:run: checkpoint '" << ck_path.string() << "' is at t = " << sim.time() << " s, before this run's start (t = "
        << t_first << " s): it belongs to another run; remove it to start afresh";
      throw InputError(m.str());
    }
    done = sim.stepCount() - first;
  }
  if (ck_path.has_parent_path()) std::filesystem::create_directories(ck_path.parent_path());
  io::ProgressLine line(total, sim.time(), dt, progress);
  const auto start = Clock::now();
  bool stopped = false;
  if (snap_every && !h.snapshots) writeSnapshot(L, h);  // the initial state
  try {
    while (done < total && !stopped) {
      const std::uint64_t next_cb = has_callback ? std::min(total, nextEvent(done, every, total)) : total;
      const std::uint64_t next_snap = snap_every ? std::min(total, nextEvent(done, snap_every, total)) : total;
      const std::uint64_t next_rec = rec_every ? std::min(total, nextEvent(done, rec_every, total)) : total;
      const std::uint64_t next_ck = ck_every ? std::min(total, nextEvent(done, ck_every, total)) : total;
      const std::uint64_t target = std::min({next_cb, next_snap, next_rec, next_ck, done + chunk});
      const auto t0 = Clock::now();
      sim.step(target - done);
      const double spent = std::chrono::duration<double>(Clock::now() - t0).count();
      // Aim at chunks of ~0.1 s so the progress line and Ctrl-C stay responsive.
      const double per_step = spent / double(target - done);
      chunk = per_step > 0 ? std::clamp<std::uint64_t>(static_cast<std::uint64_t>(0.1 / per_step), 1, 100000)
                           : chunk * 2;
      st.stats.particle_steps += double(target - done) * double(sim.particles().size());
      st.stats.steps += target - done;
      done = target;
      line.update(done, sim.particles().size());
      if (snap_every && (done == next_snap)) writeSnapshot(L, h);
      if (rec_every && done == next_rec) {
        recordLoads();
        recorded_at = done;
      }
      if (ck_every && done == next_ck) sim.saveCheckpoint(ck_path.string());
      if (has_callback && done == next_cb && !callBack(L, cb)) stopped = true;
    }
    if (rec_every && recorded_at != done) recordLoads();  // stopped early by the callback
  } catch (...) {
    st.stats.run_wall_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    throw;
  }
  line.finish(done, sim.particles().size());
  st.stats.run_wall_seconds += std::chrono::duration<double>(Clock::now() - start).count();
  st.stats.particles = sim.particles().size();
  st.stats.simulated_time = sim.time();
  st.stats.state_hash = stateHash(sim.particles());
  lua_pushinteger(L, static_cast<lua_Integer>(done));
  lua_pushboolean(L, stopped);
  return 2;
}

const SimulationMethod reg_run{"run", &guarded<run>};

}  // namespace

}  // namespace paddy::lua
