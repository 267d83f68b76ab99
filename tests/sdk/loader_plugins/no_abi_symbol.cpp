// A plugin built before the ABI symbol existed: it has the entry point but no
// paddy_plugin_abi_version().
#define PADDY_PLUGIN_NO_ABI_SYMBOL
#include "loader_test_plugin.hpp"

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  registry->addSubModel(loader_test::normalModel("loader_test_no_abi_symbol", "must not be visible"));
  return PADDY_PLUGIN_ABI_VERSION;
}
