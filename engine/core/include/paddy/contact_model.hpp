// Contact sub-models: the pieces a pair's contact law is composed of.
//
// A material pair's law is a chain of sub-models run in a fixed order on each ContactBatch:
//   normal → normal-force extras → damping → tangential → rolling → twisting → other extras.
// "Normal-force extras" are the extras whose SubModelInfo declares Capability::NormalForce in
// `provides` (liquid bridge, lubrication, plastic adhesion): they add to fn, and may raise
// fn_friction or mark a contact active, before damping, the tangential spring and the rolling
// torque read them. Other extras (e.g. a pure torque) run last. Extras keep their given order
// within each group.
// Each sub-model is a small class with one `compute(batch)` that loops over the batch; the engine
// calls it once per batch (never once per contact). New physics is a new sub-model in a plugin
// (see docs/plugins.md); the engine's kernel is not edited.
#pragma once

#include <paddy/contact_batch.hpp>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace paddy {

enum class SubModelKind { Normal, Damping, Tangential, Rolling, Twisting, Extra };

const char* toString(SubModelKind kind);

// One numeric parameter a sub-model accepts; the engine validates values against [min, max]
// and reports the name, value and range on error.
struct ParamSpec {
  std::string name;
  double default_value = 0.0;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  std::string unit;
  std::string description;
  bool required = false;  // no default: the user must give it
  // Coarse-graining law of this parameter, declared beside the model that defines it: when the
  // particles are enlarged by α = d_cg / d_ref, the value becomes α^coarse_graining_exponent
  // times the reference value (paddy.coarse_grain reads it; docs/measurement.md). 0: unchanged.
  double coarse_graining_exponent = 0.0;
  std::string coarse_graining_reason;  // what the law holds invariant, and its source
};

// What a sub-model provides to, or needs from, the rest of its chain (bit flags). ContactLaw
// refuses at set-up a chain in which a sub-model needs something no other sub-model provides, or
// in which one sub-model provides what another refuses; the message names both sub-models.
enum Capability : unsigned {
  kNormalForce = 1u << 0,          // adds to fn (an extra with it runs right after the normal model)
  kContactState = 1u << 1,         // sets active, contact_radius and fn_friction
  kNormalStiffness = 1u << 2,      // sets stiffness_n (read by damping)
  kTangentialStiffness = 1u << 3,  // sets stiffness_t (read by tangential springs)
  kCohesiveNormalForce = 1u << 4,  // attracts (fn < 0 possible)
  kRangeBeyondContact = 1u << 5,   // acts across a gap (overlap < 0): maxSeparation(r_eff) > 0
  kViscousFluidForce = 1u << 6,    // models the interstitial fluid's viscous (lubrication) force
};
// "normal force, contact state, ..." for messages.
std::string capabilityNames(unsigned capabilities);

// Intrinsic properties of a material (reference Table 2).
struct Material {
  std::string name;
  double density = 0.0;        // ρ [kg/m³]
  double shear_modulus = 0.0;  // G [Pa]
  double poisson = 0.0;        // ν [-]
  double youngs() const { return 2.0 * shear_modulus * (1.0 + poisson); }
};

// Pair constants derived from two materials (Hertz/Mindlin effective moduli):
//   1/E* = (1−ν_i²)/E_i + (1−ν_j²)/E_j,   1/G* = (2−ν_i)/G_i + (2−ν_j)/G_j.
struct MaterialPair {
  Material a, b;
  double e_star = 0.0;
  double g_star = 0.0;
  static MaterialPair of(const Material& a, const Material& b);
};

using ParamValues = std::map<std::string, double>;

class SubModel {
 public:
  virtual ~SubModel() = default;
  // Doubles of per-contact history this sub-model keeps (0 if none).
  virtual std::size_t historySize() const { return 0; }
  // How far apart (as a positive gap, [m]) two bodies can be and still interact, for a contact
  // with effective radius r_eff (for a wall contact r_eff is the sphere's radius).
  // Contract the neighbour search relies on (engine/core/src/neighbour_list.cpp):
  //   * a sub-model that acts beyond contact (overlap < 0) MUST return its reach here: a pair is
  //     only ever handed to compute() while its gap is below the chain's maxSeparation (the
  //     largest over its sub-models), so a force beyond that reach is silently never applied;
  //   * the value must not decrease with r_eff: the list's cell size and the candidate test use
  //     maxSeparation(R_max / 2) (R_max the largest radius) and the wall search
  //     maxSeparation(R_max), as upper bounds for every pair; the skin is added on top;
  //   * it must be 0 when the sub-model does nothing beyond contact (e.g. its strength is 0), so
  //     that the neighbour list, and with it the order of the force sums, is exactly the same as
  //     without it.
  virtual double maxSeparation(double /*r_eff*/) const { return 0.0; }
  // Runs the law on the whole batch. `history_offset` locates this sub-model's history block.
  virtual void compute(ContactBatch& batch, std::size_t history_offset) const = 0;
};

// What a plugin registers for one sub-model.
struct SubModelInfo {
  std::string name;         // e.g. "hertz", "jkr", "mindlin", "constant_torque"
  SubModelKind kind = SubModelKind::Normal;
  std::string description;  // one line: formula and source
  std::vector<ParamSpec> params;
  // Builds the sub-model for one material pair from validated parameters (every declared
  // parameter is present, defaults filled in).
  std::function<std::unique_ptr<SubModel>(const ParamValues&, const MaterialPair&)> create;
  // Capability flags (see Capability): what it provides to the chain, what it needs from the
  // other sub-models, what it cannot be combined with. After `create` so that a registration
  // written as {name, kind, description, params, create} still compiles (all 0: no checks).
  unsigned provides = 0;
  unsigned needs = 0;
  unsigned refuses = 0;
};

}  // namespace paddy
