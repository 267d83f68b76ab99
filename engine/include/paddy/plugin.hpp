// Plugin interface. A plugin is a shared library (libpaddy_<name>.so) on the plugin search path
// that exports one C entry point:
//
//   extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry);
//
// It calls registry->addSubModel(...) / addGeometry(...) / addMeshReader(...) for everything it
// provides and returns
// PADDY_PLUGIN_ABI_VERSION. The engine refuses a plugin built against another ABI version.
// Search path: the directories in $PADDY_PLUGIN_PATH (':'-separated), then the plugin directory
// next to the paddy executable (<prefix>/lib/paddy/plugins).
#pragma once

#include <paddy/contact_model.hpp>

#include <string>
#include <vector>

// Version 2: ContactBatch gained resist_i / resist_j (torques opposing a body's own rotation).
#define PADDY_PLUGIN_ABI_VERSION 2
#define PADDY_PLUGIN_EXPORT __attribute__((visibility("default")))

namespace paddy {

struct GeometryInfo;    // declared in paddy/geometry.hpp (wall builders)
struct MeshReaderInfo;  // declared in paddy/geometry.hpp (mesh-file readers)

class PluginRegistry {
 public:
  virtual ~PluginRegistry() = default;
  virtual void addSubModel(SubModelInfo info) = 0;
  virtual void addGeometry(const GeometryInfo& info) = 0;
  // Mesh-file readers by extension. Not pure, so registries that only care about sub-models and
  // parts (test doubles) need not implement it; the engine's registry records them.
  virtual void addMeshReader(const MeshReaderInfo& info) { (void)info; }
};

}  // namespace paddy

extern "C" {
// The one entry point every plugin defines.
typedef int (*paddy_register_plugin_fn)(paddy::PluginRegistry* registry);
}
