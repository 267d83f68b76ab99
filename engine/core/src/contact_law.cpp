#include "contact_law.hpp"

#include <paddy/errors.hpp>

#include <algorithm>
#include <map>
#include <sstream>

namespace paddy {

namespace {
std::string label(const SubModelInfo& info) { return std::string(toString(info.kind)) + " '" + info.name + "'"; }
}  // namespace

void ContactLaw::checkCompatible(const std::vector<const SubModelInfo*>& infos) {
  for (std::size_t a = 0; a < infos.size(); ++a) {
    for (std::size_t b = 0; b < infos.size(); ++b) {
      if (a == b) continue;
      if (a < b && infos[a]->name == infos[b]->name && infos[a]->kind == infos[b]->kind)
        throw InputError("contact model " + label(*infos[a]) + " appears twice in one interaction");
      const unsigned clash = infos[a]->refuses & infos[b]->provides;
      if (clash)
        throw InputError("contact model " + label(*infos[a]) + " cannot be combined with " + label(*infos[b]) +
                         ": " + label(*infos[b]) + " provides " + capabilityNames(clash) + ", which " +
                         label(*infos[a]) + " refuses");
    }
    unsigned missing = infos[a]->needs;
    for (std::size_t b = 0; b < infos.size(); ++b)
      if (b != a) missing &= ~infos[b]->provides;
    if (missing) {
      std::ostringstream msg;
      msg << "contact model " << label(*infos[a]) << " needs " << capabilityNames(missing)
          << ", which no other sub-model of the interaction provides (";
      const char* sep = "";
      for (std::size_t b = 0; b < infos.size(); ++b) {
        if (b == a) continue;
        msg << sep << label(*infos[b]) << " provides "
            << (infos[b]->provides ? capabilityNames(infos[b]->provides) : std::string("nothing"));
        sep = "; ";
      }
      msg << ")";
      throw InputError(msg.str());
    }
  }
}

ContactLaw::ContactLaw(const PluginManager& plugins, const InteractionSpec& spec, const MaterialPair& pair) {
  struct Slot {
    SubModelKind kind;
    std::string name;
  };
  std::vector<Slot> slots;
  if (spec.normal.empty()) throw InputError("an interaction needs a normal contact model (e.g. normal = \"hertz\")");
  // Order (contact_model.hpp): normal → normal-force extras → damping → tangential → rolling →
  // twisting → other extras.
  slots.push_back({SubModelKind::Normal, spec.normal});
  for (const auto& e : spec.extras)
    if (plugins.subModel(e, SubModelKind::Extra).provides & kNormalForce) slots.push_back({SubModelKind::Extra, e});
  if (!spec.damping.empty()) slots.push_back({SubModelKind::Damping, spec.damping});
  if (!spec.tangential.empty()) slots.push_back({SubModelKind::Tangential, spec.tangential});
  if (!spec.rolling.empty()) slots.push_back({SubModelKind::Rolling, spec.rolling});
  if (!spec.twisting.empty()) slots.push_back({SubModelKind::Twisting, spec.twisting});
  for (const auto& e : spec.extras)
    if (!(plugins.subModel(e, SubModelKind::Extra).provides & kNormalForce)) slots.push_back({SubModelKind::Extra, e});

  // Gather every parameter the chosen sub-models declare (shared names are one parameter).
  std::vector<const SubModelInfo*> infos;
  std::map<std::string, ParamSpec> specs;
  for (const auto& s : slots) {
    const SubModelInfo& info = plugins.subModel(s.name, s.kind);
    infos.push_back(&info);
    for (const auto& p : info.params) specs.emplace(p.name, p);
  }
  checkCompatible(infos);
  for (const auto& [name, value] : spec.params) {
    auto it = specs.find(name);
    if (it == specs.end()) {
      std::ostringstream msg;
      msg << "parameter '" << name << "' is not used by the chosen contact models (";
      for (std::size_t k = 0; k < slots.size(); ++k) msg << (k ? ", " : "") << slots[k].name;
      msg << "); they accept: ";
      bool first = true;
      for (const auto& [n, p] : specs) {
        msg << (first ? "" : ", ") << n;
        first = false;
      }
      if (first) msg << "(no parameters)";
      throw InputError(msg.str());
    }
    checkRange(name, value, it->second.min, it->second.max, it->second.unit);
    values_[name] = value;
  }
  for (const auto& [name, p] : specs) {
    if (values_.count(name)) continue;
    if (p.required) {
      std::ostringstream msg;
      msg << "parameter '" << name << "' is required by the contact model (" << p.description
          << "), allowed range [" << p.min << ", " << p.max << "]" << (p.unit.empty() ? "" : " " + p.unit);
      throw InputError(msg.str());
    }
    values_[name] = p.default_value;
  }

  std::ostringstream desc;
  for (std::size_t k = 0; k < infos.size(); ++k) {
    Stage stage;
    stage.model = infos[k]->create(values_, pair);
    if (!stage.model) throw InputError("contact model '" + infos[k]->name + "' could not be created");
    stage.history_offset = history_size_;
    history_size_ += stage.model->historySize();
    stages_.push_back(std::move(stage));
    desc << (k ? " + " : "") << toString(infos[k]->kind) << ":" << infos[k]->name;
  }
  description_ = desc.str();
}

double ContactLaw::maxSeparation(double r_eff) const {
  double s = 0.0;
  for (const auto& stage : stages_) s = std::max(s, stage.model->maxSeparation(r_eff));
  return s;
}

}  // namespace paddy
