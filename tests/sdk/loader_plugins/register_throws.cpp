// Registers a sub-model, then throws: nothing it registered may stay visible.
#include "loader_test_plugin.hpp"

#include <stdexcept>

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  registry->addSubModel(loader_test::normalModel("loader_test_register_throws", "must not be visible"));
  throw std::runtime_error("deliberate failure during registration");
}
