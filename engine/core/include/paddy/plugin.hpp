// Plugin interface. A plugin is a shared library (libpaddy_<name>.so) on the plugin search path
// that exports two C functions:
//
//   extern "C" int paddy_plugin_abi_version();   // defined by this header, see below
//   extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry);
//
// Loading (engine/core/src/plugin_manager.cpp) first reads paddy_plugin_abi_version() and
// refuses a library built against another PADDY_PLUGIN_ABI_VERSION without calling anything else
// in it. Only then is paddy_register_plugin called; it calls registry->addSubModel(...) /
// addGeometry(...) / addMeshReader(...) for everything it provides and returns
// PADDY_PLUGIN_ABI_VERSION. What it registers is staged and kept only if the call returns that
// version without throwing; otherwise the library is unloaded and none of it is visible.
//
// Every translation unit that includes this header defines paddy_plugin_abi_version() as a weak
// symbol returning the version of the header it was compiled with, so a plugin needs no code for
// it. Define PADDY_PLUGIN_NO_ABI_SYMBOL before including this header to leave it out (the
// engine's own sources do; the loader's tests use it to build a plugin with a wrong version).
//
// Search path: the directories in $PADDY_PLUGIN_PATH (':'-separated), then the plugin directory
// next to the paddy executable (<prefix>/lib/paddy/plugins).
#pragma once

#include <paddy/contact_model.hpp>

#include <string>
#include <vector>

// Version 2: ContactBatch gained resist_i / resist_j (torques opposing a body's own rotation).
// Version 3: the version is read from paddy_plugin_abi_version() before registration.
// Version 4: ParamSpec gained the coarse-graining law; SubModelInfo gained provides / needs /
//            refuses capability flags; extras providing a normal force run right after the
//            normal model.
// Version 5: ContactBatch holds a pointer to each contact's history block (history_at, read
//            through historyOf as before) instead of one array with a stride.
#define PADDY_PLUGIN_ABI_VERSION 5
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
// The entry point every plugin defines.
typedef int (*paddy_register_plugin_fn)(paddy::PluginRegistry* registry);
// The ABI version the plugin was compiled for (read before anything else is called).
typedef int (*paddy_plugin_abi_version_fn)();
}

#ifndef PADDY_PLUGIN_NO_ABI_SYMBOL
extern "C" __attribute__((weak, visibility("default"))) int paddy_plugin_abi_version() {
  return PADDY_PLUGIN_ABI_VERSION;
}
#endif
