// Fuzz target: restart from a checkpoint (engine/core/src/checkpoint_load.cpp, through sim:run's
// resume in engine/lua/src/lua_run.cpp). Two fixed scripts, chosen by the input's first byte: a
// small pile (two materials, a plane floor, Hertz-Mindlin contacts with history), and a pile of
// JKR spheres with rolling friction in a meshed cup with a meshed plate lid moving down on it
// (mesh walls with their pose, motion and wall-contact history; contacts in tension). Each
// writes a checkpoint at step 30 once; each input's remaining bytes are decoded
// into operations on that checkpoint held as data (checkpoint_model.hpp: remove or add datasets
// and attributes, change element types, shapes, row counts, values to NaN, infinities, negative,
// huge or off-by-one ones, declare huge sizes without data, compress), the result is written as
// a valid HDF5 file, and the same script restarts from it.
//
// Besides crashes, leaks, hangs and undefined behaviour, the rules checked:
//   * a refusal is an input error (exit code 2) whose message names the checkpoint file;
//   * a checkpoint the reader must refuse (a dataset or attribute missing, of another element
//     type or shape, a non-finite value, particle counts that disagree, another format version)
//     is refused;
//   * the unchanged checkpoint is accepted and the run resumes from step 30 (the steps before it
//     are not run again);
//   * an accepted checkpoint may still end in an instability (exit code 3) of its own physics
//     (e.g. a huge speed), never in another error.
#include "checkpoint_model.hpp"
#include "fuzz_script.hpp"

#include <cstdlib>
#include <cstring>
#include <dlfcn.h>

using namespace paddy::fuzz;

namespace {

// The parameters and the run both scenarios share: write the checkpoint at step 30, or resume from it.
const char* const kParameters = R"lua(
local P = paddy.parameters{
  checkpoint = {default = "", type = "string", description = "checkpoint file (absolute path)"},
  write = {default = 0, type = "integer", min = 0, max = 1, description = "1: only write the checkpoint at step 30"},
  expect_resumed = {default = 0, type = "integer", min = 0, max = 1, description = "1: the run must resume at step 30"},
}
)lua";
const char* const kRun = R"lua(
if P.write == 1 then
  sim:run{steps = 30, progress = false}
  sim:checkpoint(P.checkpoint)
else
  -- A callback every 10 steps: 3 calls when the run resumed at step 30, 6 when it started afresh.
  local calls = 0
  sim:run{steps = 60, progress = false, checkpoint = P.checkpoint, checkpoint_every = 20 * sim:timestep(),
          every_steps = 10, callback = function() calls = calls + 1 end}
  if P.expect_resumed == 1 and (calls ~= 3 or sim:steps() ~= 60) then
    error("the run did not resume at step 30: " .. calls .. " callbacks, at step " .. sim:steps())
  end
end
paddy.result{steps = sim:steps()}
)lua";

// The pile on a plane floor.
const char* const kPile = R"lua(
local sim = paddy.simulation{threads = 1}
local a = sim:material{name = "a", density = 2500, shear_modulus = 1e6, poisson = 0.3}
local b = sim:material{name = "b", density = 1500, shear_modulus = 2e6, poisson = 0.4}
local law = {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", restitution = 0.5, friction = 0.3}
sim:interaction(a, a, law)
sim:interaction(a, b, law)
sim:interaction(b, b, law)
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = a}
for i = 0, 2 do
  for j = 0, 2 do
    sim:add_particle{pos = {0.00198 * i, 0.00198 * j, 0.00099}, radius = 0.001, material = (i + j) % 2 == 0 and a or b}
  end
end
for i = 0, 1 do
  for j = 0, 1 do
    sim:add_particle{pos = {0.00099 + 0.00198 * i, 0.00099 + 0.00198 * j, 0.00239}, radius = 0.001, material = b}
  end
end
)lua";

// The mesh-wall scenario.
const char* const kCupAndLid = R"lua(
local sim = paddy.simulation{threads = 1}
local mud = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}
sim:interaction(mud, mud, {normal = "jkr", rolling = "constant_torque", restitution = 0.5, friction = 0.3,
                           rolling_friction = 0.1, surface_energy = 0.1})
sim:interaction(mud, steel, {normal = "jkr", restitution = 0.3, friction = 0.6, surface_energy = 0.05})
sim:add_mesh_wall{name = "cup", material = steel, part = "cup", params = {diameter = 0.012, height = 0.01},
                  motion = {type = "fixed"}}
local lid = sim:add_mesh_wall{name = "lid", material = steel, part = "plate", params = {side = 0.01},
                              translate = {0, 0, 0.00398}, motion = {type = "translate", velocity = {0, 0, -0.02}}}
-- A ring of six touching its neighbours and a centre sphere on the cup's bottom, one on top under the lid.
for k = 0, 5 do
  local a = 2 * math.pi * k / 6
  sim:add_particle{pos = {0.002 * math.cos(a), 0.002 * math.sin(a), 0.00101}, radius = 0.001, material = mud}
end
sim:add_particle{pos = {0, 0, 0.00101}, radius = 0.001, material = mud}
sim:add_particle{pos = {0, 0, 0.00299}, radius = 0.001, material = mud}
)lua";

std::string scriptOf(unsigned scenario) { return std::string(kParameters) + (scenario == 0 ? kPile : kCupAndLid) + kRun; }

// The contact-model plugins stay loaded for the whole process: each run loads and unloads them,
// and libFuzzer keeps writing the coverage counters of every instrumented library it has seen,
// so an unloaded plugin would crash it. A second reference (RTLD_NODELETE) keeps each mapped.
void pinPlugins() {
  const char* env = std::getenv("PADDY_PLUGIN_PATH");
  std::string dirs = env && *env ? env : PADDY_FUZZ_PLUGIN_DIR;
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const auto end = std::min(dirs.find(':', start), dirs.size());
    const std::filesystem::path dir = dirs.substr(start, end - start);
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
      if (e.path().extension() == ".so") dlopen(e.path().c_str(), RTLD_NOW | RTLD_NODELETE);
    start = end + 1;
  }
}

Model writeBase(unsigned scenario) {
  const std::string base = (scratchDir() / ("base_checkpoint_" + std::to_string(scenario) + ".h5")).string();
  const auto r = runFixedScript("checkpoint", scriptOf(scenario), {{"checkpoint", base}, {"write", "1"}});
  if (r.code != paddy::lua::kExitOk) {
    std::fprintf(stderr, "writing the base checkpoint of scenario %u failed: %s\n", scenario, r.err.c_str());
    std::abort();
  }
  return readModel(base);
}

const Model& baseModel(unsigned scenario) {
  static const Model* models = [] {
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // HDF5's own error stacks would flood the log
    pinPlugins();
    static Model m[2] = {writeBase(0), writeBase(1)};
    return m;
  }();
  return models[scenario];
}

// The input, read as operations.
class Bytes {
 public:
  Bytes(const std::uint8_t* d, std::size_t n) : d_(d), n_(n) {}
  bool more() const { return k_ < n_; }
  unsigned byte() { return k_ < n_ ? d_[k_++] : 0u; }
  unsigned word() {
    const unsigned lo = byte();
    return lo | (byte() << 8);
  }
  std::uint64_t raw() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t(byte()) << (8 * i);
    return v;
  }
 private:
  const std::uint8_t* d_;
  std::size_t n_, k_ = 0;
};

// A value of interest for an element: special floating-point values, bounds, raw bits.
double pickValue(Bytes& in) {
  static const double table[] = {std::nan(""), HUGE_VAL, -HUGE_VAL, -1.0, 0.0, 1.0, 0.5, 2.0, 3.0, 1e300, -1e300,
                                 9007199254740992.0, 1.8446744073709552e19, 4294967296.0, 5e-324, 1e-9, 1e3, 1e-3, 30.0,
                                 60.0, 61.0, -0.0};
  const unsigned c = in.byte();
  if (c < sizeof table / sizeof table[0]) return table[c];
  std::uint64_t bits = in.raw();
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

void setElement(Dataset& d, std::size_t k, double v, Bytes& in, bool raw) {
  if (d.kind == Kind::F64) {
    d.f[k] = v;
  } else if (raw) {
    d.u[k] = in.raw();
  } else {
    d.u[k] = d.kind == Kind::I64 ? static_cast<std::uint64_t>(toInt(v, -9.2e18, 9.2e18))
                                 : (v >= 1.8e19 ? ~std::uint64_t{0} : static_cast<std::uint64_t>(toInt(v, 0, 9.2e18)));
  }
}

void apply(Model& m, Bytes& in) {
  const unsigned op = in.byte() % 12;
  if (m.sets.empty() && op != 1 && op != 6) return;
  Dataset* d = m.sets.empty() ? nullptr : &m.sets[in.byte() % m.sets.size()];
  const std::size_t n = d ? d->size() : 0;
  switch (op) {
    case 0: m.sets.erase(m.sets.begin() + (d - m.sets.data())); break;
    case 1:
      if (!m.attrs.empty()) m.attrs.erase(m.attrs.begin() + in.byte() % m.attrs.size());
      break;
    case 2: {  // an extra dataset or attribute
      Dataset e;
      e.name = "extra/" + std::to_string(m.sets.size()) + "_" + std::to_string(in.byte());
      if (m.set(e.name)) break;
      e.f.assign(in.byte() % 8, 1.5);
      m.sets.push_back(e);
      m.attrs.push_back({"extra_" + std::to_string(m.attrs.size()), 1.0, Stored::F64});
      break;
    }
    case 3: d->stored = static_cast<Stored>(in.byte() % 7); break;
    case 4: {  // shape
      const unsigned how = in.byte() % 6;
      const std::size_t rows = d->columns ? n / d->columns : 0;
      if (how == 0 && rows > 0) {  // one row fewer
        d->f.resize(d->kind == Kind::F64 ? (rows - 1) * d->columns : 0);
        if (d->kind != Kind::F64) d->u.resize((rows - 1) * d->columns);
      } else if (how == 1) {  // k more rows, copies of the last (or zeros)
        const std::size_t add = (in.byte() % 4 + 1) * d->columns;
        for (std::size_t k = 0; k < add; ++k) {
          if (d->kind == Kind::F64) d->f.push_back(n >= d->columns ? d->f[n - d->columns + k % d->columns] : 0.0);
          else d->u.push_back(n >= d->columns ? d->u[n - d->columns + k % d->columns] : 0);
        }
      } else if (how == 2) {  // another column count (data cut to whole rows)
        d->columns = 1 + in.byte() % 4;
        d->rank = d->columns > 1 ? 2 : d->rank;
        const std::size_t keep = n / d->columns * d->columns;
        if (d->kind == Kind::F64) d->f.resize(keep);
        else d->u.resize(keep);
      } else if (how == 3) {
        d->rank = d->rank == 1 ? 2 : 1;  // N×1 as rank 2, or N×3 flattened to rank 1
      } else if (how == 4) {
        d->rank = 0;  // a scalar
      } else {
        d->f.clear(), d->u.clear();  // empty
      }
      break;
    }
    case 5:
    case 11: {  // one element (or every element) set to a value of interest
      if (n == 0) break;
      const bool every = in.byte() % 8 == 0;
      const std::size_t k = in.word() % n;
      const bool raw = op == 11;
      const double v = raw ? 0.0 : pickValue(in);
      if (every)
        for (std::size_t q = 0; q < n; ++q) setElement(*d, q, v, in, raw);
      else
        setElement(*d, k, v, in, raw);
      break;
    }
    case 6: {  // an attribute's value or form
      if (m.attrs.empty()) break;
      Attribute& a = m.attrs[in.byte() % m.attrs.size()];
      if (in.byte() % 4 == 0) a.stored = static_cast<Stored>(in.byte() % 7);
      else a.value = pickValue(in);
      break;
    }
    case 7: d->huge_rows = hsize_t{1} << (20 + in.byte() % 44); break;  // declared, never written
    case 8: d->compressed = !d->compressed; break;
    case 9:
    case 10: {  // two elements swapped, or one copied onto another (duplicates, disorder)
      if (n < 2) break;
      const std::size_t i = in.word() % n, j = in.word() % n;
      if (d->kind == Kind::F64) op == 9 ? std::swap(d->f[i], d->f[j]) : void(d->f[i] = d->f[j]);
      else op == 9 ? std::swap(d->u[i], d->u[j]) : void(d->u[i] = d->u[j]);
      break;
    }
  }
  // Off-by-one of an integer element rides along with every operation on integers.
  if (d && op >= 9 && d->kind != Kind::F64 && !d->u.empty() && in.more()) {
    auto& e = d->u[in.word() % d->u.size()];
    e += static_cast<std::uint64_t>(static_cast<std::int64_t>(static_cast<std::int8_t>(in.byte())));
  }
}

// What the reader must refuse whatever else the file holds (computed from the file as written).
std::string mustRefuse(Model& m) {
  auto* flag = m.attr("walls_refreshed");
  for (const auto& name : checkpointAttributes()) {
    if (name == "threads") continue;  // not read
    const Attribute* a = m.attr(name);
    if (!a) return "attribute '" + name + "' missing";
    if (a->stored == Stored::Text || a->stored == Stored::U8) return "attribute '" + name + "' not a single number";
    const double v = storedValue(a->value, a->stored);
    if (!std::isfinite(v)) return "attribute '" + name + "' not finite";
    if (name == "version" && v != 3.0) return "version " + std::to_string(v);
  }
  const bool refreshed = flag && storedValue(flag->value, flag->stored) == 1.0;
  const Dataset* id = m.set("particles/id");
  for (const auto& l : checkpointDatasets()) {
    const std::string name = l.name;
    if (name == "walls/x_at_refresh" && !refreshed) continue;
    Dataset* d = m.set(name);
    if (!d) return "dataset '" + name + "' missing";
    const bool native = d->stored == Stored::Native || (d->stored == Stored::F64 && d->kind == Kind::F64);
    if (!native) return "dataset '" + name + "' of another element type";
    if (d->huge_rows > 0) return "dataset '" + name + "' declared huge, never written";
    if (d->rank != (l.columns == 1 ? 1 : 2) || (d->rank == 2 && d->columns != l.columns))
      return "dataset '" + name + "' of another shape";
    if (d->kind == Kind::F64)
      for (double v : d->f)
        if (!std::isfinite(v)) return "dataset '" + name + "' holds " + std::to_string(v);
    const bool per_particle = name.rfind("particles/", 0) == 0 && name != "particles/id";
    if (per_particle && id && id->size() != d->size() / l.columns) return "dataset '" + name + "' rows differ from particles/id";
  }
  return "";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const unsigned scenario = in.byte() % 2;
  const Model& base = baseModel(scenario);
  Model m = base;
  for (int ops = 0; in.more() && ops < 16; ++ops) apply(m, in);
  const std::string path = (scratchDir() / "checkpoint.h5").string();
  std::filesystem::remove(path + ".tmp");
  writeModel(path, m);
  const bool unchanged = m == base;
  const std::string refuse = mustRefuse(m);
  std::vector<std::pair<std::string, std::string>> sets = {{"checkpoint", path}};
  if (unchanged) sets.emplace_back("expect_resumed", "1");
  const auto r = runFixedScript("checkpoint", scriptOf(scenario), sets, /*instability_allowed=*/true);
  if (r.code == paddy::lua::kExitInput) requireNamesFile(r.err, path);
  if (unchanged && r.code != paddy::lua::kExitOk) {
    std::fprintf(stderr, "the unchanged checkpoint was not accepted: %s\n", r.err.c_str());
    std::abort();
  }
  if (!refuse.empty() && r.code != paddy::lua::kExitInput) {
    std::fprintf(stderr, "a checkpoint with %s was not refused (exit %d): %s\n", refuse.c_str(), r.code, r.err.c_str());
    std::abort();
  }
  return 0;
}
