// PluginManager: dlopen()s libpaddy_*.so files and calls their single C entry point.
#include <paddy/errors.hpp>
#include <paddy/geometry.hpp>
#include <paddy/plugin_manager.hpp>

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

namespace paddy {
namespace fs = std::filesystem;

struct PluginManager::Impl {
  std::map<std::pair<SubModelKind, std::string>, SubModelInfo> sub_models;
  std::map<std::string, GeometryInfo> geometries;
  std::map<std::string, MeshReaderInfo> readers;  // by lower-case extension
  std::vector<void*> handles;
};

namespace {

// Collects what one plugin registers, so the manager can record what each library provides.
class RecordingRegistry final : public PluginRegistry {
 public:
  explicit RecordingRegistry(PluginManager& m) : manager_(m) {}
  void addSubModel(SubModelInfo info) override {
    provides.push_back(std::string(toString(info.kind)) + ":" + info.name);
    manager_.addSubModel(std::move(info));
  }
  void addGeometry(const GeometryInfo& info) override {
    provides.push_back("geometry:" + info.name);
    manager_.addGeometry(info);
  }
  void addMeshReader(const MeshReaderInfo& info) override {
    provides.push_back("mesh_reader:" + info.name);
    manager_.addMeshReader(info);
  }
  std::vector<std::string> provides;

 private:
  PluginManager& manager_;
};

std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string executableDir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.parent_path().string();
}

}  // namespace

PluginManager::PluginManager() : impl_(std::make_unique<Impl>()) {}

PluginManager::~PluginManager() {
  // Registered std::function objects point into the libraries: drop them before unloading.
  impl_->sub_models.clear();
  impl_->geometries.clear();
  impl_->readers.clear();
  for (void* h : impl_->handles) dlclose(h);
}

std::vector<std::string> PluginManager::defaultSearchPath() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("PADDY_PLUGIN_PATH")) {
    std::stringstream ss(env);
    std::string item;
    while (std::getline(ss, item, ':'))
      if (!item.empty()) dirs.push_back(item);
  }
  const std::string exe_dir = executableDir();
  if (!exe_dir.empty()) dirs.push_back((fs::path(exe_dir) / ".." / PADDY_PLUGIN_SUBDIR).lexically_normal().string());
  return dirs;
}

void PluginManager::loadDirectories(const std::vector<std::string>& dirs) {
  for (const auto& dir : dirs) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    std::vector<fs::path> libs;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("libpaddy_", 0) == 0 && entry.path().extension() == ".so") libs.push_back(entry.path());
    }
    std::sort(libs.begin(), libs.end());  // deterministic load order
    for (const auto& lib : libs) {
      const std::string canonical = fs::weakly_canonical(lib).string();
      bool seen = std::any_of(loaded_.begin(), loaded_.end(), [&](const LoadedPlugin& p) { return p.path == canonical; });
      // A library of the same file name found earlier on the path shadows later ones.
      bool shadowed = std::any_of(loaded_.begin(), loaded_.end(), [&](const LoadedPlugin& p) {
        return fs::path(p.path).filename() == lib.filename();
      });
      if (!seen && !shadowed) loadLibrary(canonical);
    }
  }
}

void PluginManager::loadLibrary(const std::string& path) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw InputError("cannot load plugin '" + path + "': " + dlerror());
  auto fn = reinterpret_cast<paddy_register_plugin_fn>(dlsym(handle, "paddy_register_plugin"));
  if (!fn) {
    dlclose(handle);
    throw InputError("plugin '" + path + "' does not export the entry point paddy_register_plugin");
  }
  RecordingRegistry registry(*this);
  const int abi = fn(&registry);
  if (abi != PADDY_PLUGIN_ABI_VERSION) {
    dlclose(handle);
    throw InputError("plugin '" + path + "' was built for plugin ABI " + std::to_string(abi) +
                     ", this Paddy has ABI " + std::to_string(PADDY_PLUGIN_ABI_VERSION) + "; rebuild it");
  }
  impl_->handles.push_back(handle);
  loaded_.push_back({path, registry.provides});
}

void PluginManager::addSubModel(SubModelInfo info) {
  if (info.name.empty() || !info.create) throw InputError("a plugin registered a sub-model without name or factory");
  auto key = std::make_pair(info.kind, info.name);
  impl_->sub_models[key] = std::move(info);  // later registrations replace earlier ones
}

const SubModelInfo& PluginManager::subModel(const std::string& name, SubModelKind kind) const {
  auto it = impl_->sub_models.find({kind, name});
  if (it != impl_->sub_models.end()) return it->second;
  std::ostringstream msg;
  msg << "unknown " << toString(kind) << " contact model '" << name << "'; available: ";
  bool first = true;
  for (const auto* info : subModels(kind)) {
    msg << (first ? "" : ", ") << info->name;
    first = false;
  }
  if (first) msg << "(none — is PADDY_PLUGIN_PATH set? searched: ";
  if (first) {
    for (const auto& d : defaultSearchPath()) msg << d << " ";
    msg << ")";
  }
  throw InputError(msg.str());
}

std::vector<const SubModelInfo*> PluginManager::subModels(SubModelKind kind) const {
  std::vector<const SubModelInfo*> out;
  for (const auto& [key, info] : impl_->sub_models)
    if (key.first == kind) out.push_back(&info);
  return out;
}

void PluginManager::addGeometry(const GeometryInfo& info) {
  if (info.name.empty() || !info.build) throw InputError("a plugin registered a geometry without name or builder");
  impl_->geometries[info.name] = info;
}

const GeometryInfo& PluginManager::geometry(const std::string& name) const {
  auto it = impl_->geometries.find(name);
  if (it != impl_->geometries.end()) return it->second;
  std::ostringstream msg;
  msg << "unknown geometry '" << name << "'; available: ";
  bool first = true;
  for (const auto& [n, info] : impl_->geometries) {
    msg << (first ? "" : ", ") << n;
    first = false;
  }
  if (first) msg << "(none)";
  throw InputError(msg.str());
}

std::vector<std::string> PluginManager::geometryNames() const {
  std::vector<std::string> out;
  for (const auto& [n, info] : impl_->geometries) out.push_back(n);
  return out;
}

void PluginManager::addMeshReader(const MeshReaderInfo& info) {
  if (info.name.empty() || !info.read || info.extensions.empty())
    throw InputError("a plugin registered a mesh reader without name, extensions or read function");
  for (const auto& ext : info.extensions) {
    std::string e = lowerCase(ext);
    if (e.empty() || e[0] != '.') e = "." + e;
    impl_->readers[e] = info;
  }
}

const MeshReaderInfo& PluginManager::meshReader(const std::string& extension) const {
  std::string e = lowerCase(extension);
  if (!e.empty() && e[0] != '.') e = "." + e;
  auto it = impl_->readers.find(e);
  if (it != impl_->readers.end()) return it->second;
  std::ostringstream msg;
  msg << "no mesh reader for files '" << (e.empty() ? std::string("(no extension)") : e) << "'; readable: ";
  bool first = true;
  for (const auto& [ext, info] : impl_->readers) {
    msg << (first ? "" : ", ") << ext;
    first = false;
  }
  if (first) msg << "(none — the geometry plugin provides .stl, .off, .obj; is PADDY_PLUGIN_PATH set?)";
  throw InputError(msg.str());
}

std::vector<std::string> PluginManager::meshExtensions() const {
  std::vector<std::string> out;
  for (const auto& [ext, info] : impl_->readers) out.push_back(ext);
  return out;
}

}  // namespace paddy
