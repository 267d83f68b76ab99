// Linked against libpaddy_loader_test_dependency.so, which lies outside every search path and
// has no RPATH entry: dlopen fails with "cannot open shared object file".
#include "loader_test_plugin.hpp"

extern "C" double paddy_loader_test_dependency_value();

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  registry->addSubModel(loader_test::normalModel("loader_test_missing_dependency",
                                                 std::to_string(paddy_loader_test_dependency_value())));
  return PADDY_PLUGIN_ABI_VERSION;
}
