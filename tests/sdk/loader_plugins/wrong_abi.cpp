// Built for another plugin ABI: paddy_plugin_abi_version() reports PADDY_PLUGIN_ABI_VERSION + 1.
// Its register function must never be called; if it were, it would set an environment variable
// and register "loader_test_wrong_abi", both of which the tests look for.
#define PADDY_PLUGIN_NO_ABI_SYMBOL
#include "loader_test_plugin.hpp"

#include <cstdlib>

extern "C" PADDY_PLUGIN_EXPORT int paddy_plugin_abi_version() { return PADDY_PLUGIN_ABI_VERSION + 1; }

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  setenv("PADDY_LOADER_TEST_WRONG_ABI_REGISTERED", "1", 1);
  registry->addSubModel(loader_test::normalModel("loader_test_wrong_abi", "must not be visible"));
  return PADDY_PLUGIN_ABI_VERSION + 1;
}
