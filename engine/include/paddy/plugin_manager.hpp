// PluginManager: finds plugin libraries on the search path, loads them through their one C entry
// point and keeps what they register (contact sub-models, geometry builders, mesh-file readers).
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

class PluginManager {
 public:
  PluginManager();
  ~PluginManager();
  PluginManager(const PluginManager&) = delete;
  PluginManager& operator=(const PluginManager&) = delete;

  // Directories searched by loadDefault(): $PADDY_PLUGIN_PATH entries, then the directory
  // lib/paddy/plugins beside the running executable's prefix.
  static std::vector<std::string> defaultSearchPath();
  // Loads every libpaddy_*.so in each directory (missing directories are skipped).
  void loadDirectories(const std::vector<std::string>& dirs);
  void loadDefault() { loadDirectories(defaultSearchPath()); }
  // Loads one library; throws InputError naming the file and the reason.
  void loadLibrary(const std::string& path);

  const std::vector<LoadedPlugin>& loaded() const { return loaded_; }

  // Registry contents.
  void addSubModel(SubModelInfo info);
  const SubModelInfo& subModel(const std::string& name, SubModelKind kind) const;  // throws, listing choices
  std::vector<const SubModelInfo*> subModels(SubModelKind kind) const;
  void addGeometry(const GeometryInfo& info);
  const GeometryInfo& geometry(const std::string& name) const;  // throws, listing choices
  std::vector<std::string> geometryNames() const;
  // Readers by extension (".stl"; compared in lower case). A later reader for an extension
  // replaces an earlier one. meshReader throws InputError listing the extensions available.
  void addMeshReader(const MeshReaderInfo& info);
  const MeshReaderInfo& meshReader(const std::string& extension) const;
  std::vector<std::string> meshExtensions() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<LoadedPlugin> loaded_;
};

}  // namespace paddy
