// A working plugin next to the broken ones: it must still be loaded.
#include "loader_test_plugin.hpp"

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  registry->addSubModel(loader_test::normalModel("loader_test_good", "a working plugin"));
  return PADDY_PLUGIN_ABI_VERSION;
}
