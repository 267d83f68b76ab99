// Plugin entry point: registers the parts of parts.hpp (slump_cone, plate, cup, vane).
#include <paddy/geometry.hpp>
#include <paddy/geometry/parts.hpp>
#include <paddy/plugin.hpp>

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  for (const auto& part : paddy::geometry::partCatalogue()) registry->addGeometry(part);
  return PADDY_PLUGIN_ABI_VERSION;
}
