// Refers to a function no library defines: dlopen(RTLD_NOW) fails with "undefined symbol".
#include "loader_test_plugin.hpp"

extern "C" double paddy_loader_test_symbol_nobody_defines();

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  registry->addSubModel(loader_test::normalModel("loader_test_undefined_symbol",
                                                 std::to_string(paddy_loader_test_symbol_nobody_defines())));
  return PADDY_PLUGIN_ABI_VERSION;
}
