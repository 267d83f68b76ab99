// A library with the ABI symbol (from the header) but without paddy_register_plugin.
#include "loader_test_plugin.hpp"

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin_misspelt(paddy::PluginRegistry*) {
  return PADDY_PLUGIN_ABI_VERSION;
}
