// Contact sub-models: the pieces a pair's contact law is composed of.
//
// A material pair's law is a chain of sub-models run in a fixed order on each ContactBatch:
//   normal → damping → tangential → rolling → twisting → extra effects (any number).
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
};

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
  // with effective radius r_eff. The neighbour search reaches at least this far.
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
};

}  // namespace paddy
