// Built twice (LOADER_TEST_COPY = "a", "b"): both register the normal sub-model
// "loader_test_duplicate", with descriptions "copy a" and "copy b".
#include "loader_test_plugin.hpp"

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  registry->addSubModel(loader_test::normalModel("loader_test_duplicate", "copy " LOADER_TEST_COPY));
  return PADDY_PLUGIN_ABI_VERSION;
}
