// ContactLaw: one material pair's chain of sub-models (normal → normal-force extras → damping →
// tangential → rolling → twisting → other extras; contact_model.hpp), built once at set-up from an InteractionSpec and run on whole batches.
#pragma once

#include <paddy/plugin_manager.hpp>
#include <paddy/simulation.hpp>

#include <memory>
#include <string>
#include <vector>

namespace paddy {

class ContactLaw {
 public:
  // Validates names and parameters; throws InputError naming the offending item.
  ContactLaw(const PluginManager& plugins, const InteractionSpec& spec, const MaterialPair& pair);

  std::size_t historySize() const { return history_size_; }
  double maxSeparation(double r_eff) const;
  // Runs every sub-model on the batch (batch.history must have stride >= historySize()).
  void compute(ContactBatch& batch) const {
    batch.resetOutputs();
    for (const auto& stage : stages_) stage.model->compute(batch, stage.history_offset);
  }
  const std::string& description() const { return description_; }
  const ParamValues& parameters() const { return values_; }

 private:
  // Throws InputError naming both sub-models when one refuses what another provides, or naming
  // the sub-model whose needs no other one provides (Capability, contact_model.hpp).
  static void checkCompatible(const std::vector<const SubModelInfo*>& infos);
  struct Stage {
    std::unique_ptr<SubModel> model;
    std::size_t history_offset = 0;
  };
  std::vector<Stage> stages_;
  std::size_t history_size_ = 0;
  ParamValues values_;
  std::string description_;
};

}  // namespace paddy
