// PluginManager: finds plugin libraries on the search path, loads them through their C entry
// points and keeps what they register (contact sub-models, geometry builders, mesh-file readers).
//
// Loading one library (loadLibrary): dlopen; read paddy_plugin_abi_version() and refuse another
// version before any plugin code runs; call paddy_register_plugin into a staging registry; keep
// what was staged only if the call returned the ABI version without throwing. A refused library
// is unloaded and nothing it registered is visible.
//
// Loading directories (loadDirectories, loadDefault): a library that cannot be loaded (not a
// shared object, missing entry point, unresolved dependency or symbol, wrong ABI, registration
// that throws) is skipped with a warning on stderr and recorded in failures(); the run goes on.
//
// One rule for names, the same as for files: the first wins. A library file found earlier on the
// search path shadows one of the same file name found later (directories in path order, files in
// a directory by name), and a sub-model (kind, name), geometry name or mesh-file extension
// registered first is kept; a later registration of the same name is ignored with a warning that
// names both libraries (recorded in warnings()).
#pragma once

#include <paddy/plugin.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace paddy {

struct LoadedPlugin {
  std::string path;
  std::vector<std::string> provides;  // "normal:hertz", "geometry:slump_cone", "mesh_reader:cgal", ...
};

// A library on the search path that was skipped, and why.
struct PluginLoadFailure {
  std::string path;
  std::string reason;
};

class PluginManager {
 public:
  PluginManager();
  ~PluginManager();
  PluginManager(const PluginManager&) = delete;
  PluginManager& operator=(const PluginManager&) = delete;

  // Directories searched by loadDefault(): $PADDY_PLUGIN_PATH entries, then the directory
  // lib/paddy/plugins beside the running executable's prefix.
  static std::vector<std::string> defaultSearchPath();
  // Loads every libpaddy_*.so in each directory (missing directories are skipped); a library
  // that fails is reported on stderr, recorded in failures() and skipped.
  void loadDirectories(const std::vector<std::string>& dirs);
  void loadDefault() { loadDirectories(defaultSearchPath()); }
  // Loads one library; throws InputError naming the file and the reason (nothing of it is kept).
  void loadLibrary(const std::string& path);

  const std::vector<LoadedPlugin>& loaded() const { return loaded_; }
  const std::vector<PluginLoadFailure>& failures() const { return failures_; }
  // Names registered twice (see the rule above), one message each naming both libraries.
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Registry contents. Direct calls (not through a plugin) follow the same first-wins rule and
  // are attributed to "(registered directly)".
  void addSubModel(SubModelInfo info);
  const SubModelInfo& subModel(const std::string& name, SubModelKind kind) const;  // throws, listing choices
  std::vector<const SubModelInfo*> subModels(SubModelKind kind) const;
  void addGeometry(const GeometryInfo& info);
  const GeometryInfo& geometry(const std::string& name) const;  // throws, listing choices
  std::vector<std::string> geometryNames() const;
  // Readers by extension (".stl"; compared in lower case). The first reader for an extension is
  // kept. meshReader throws InputError listing the extensions available.
  void addMeshReader(const MeshReaderInfo& info);
  const MeshReaderInfo& meshReader(const std::string& extension) const;
  std::vector<std::string> meshExtensions() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<LoadedPlugin> loaded_;
  std::vector<PluginLoadFailure> failures_;
  std::vector<std::string> warnings_;
};

}  // namespace paddy
