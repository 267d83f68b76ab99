// PluginManager: dlopen()s libpaddy_*.so files, checks their ABI version, stages what their entry
// point registers and keeps it only when registration succeeds (the contract is in
// plugin_manager.hpp and docs/plugins.md, "Loading").
#include <paddy/errors.hpp>
#include <paddy/geometry.hpp>
#include <paddy/plugin_manager.hpp>

#include <dlfcn.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
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
  // which library registered each name ("normal:hertz", "geometry:box", "mesh_reader:.stl")
  std::map<std::string, std::string> provider;
  std::string current_library = "(registered directly)";
  std::vector<void*> handles;
};

namespace {

// Stages what one plugin registers; the manager keeps it only if registration succeeds.
class StagingRegistry final : public PluginRegistry {
 public:
  void addSubModel(SubModelInfo info) override { sub_models.push_back(std::move(info)); }
  void addGeometry(const GeometryInfo& info) override { geometries.push_back(info); }
  void addMeshReader(const MeshReaderInfo& info) override { readers.push_back(info); }
  std::vector<SubModelInfo> sub_models;
  std::vector<GeometryInfo> geometries;
  std::vector<MeshReaderInfo> readers;
};

std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string normalisedExtension(const std::string& ext) {
  std::string e = lowerCase(ext);
  if (e.empty() || e[0] != '.') e = "." + e;
  return e;
}

std::string executableDir() {
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.parent_path().string();
}

// dlsym, but only a symbol defined in the library itself: dlsym on a handle also searches the
// library's dependencies, which must not stand in for a symbol the plugin lacks.
void* ownSymbol(void* handle, const std::string& path, const char* name) {
  void* sym = dlsym(handle, name);
  if (!sym) return nullptr;
  Dl_info info{};
  if (!dladdr(sym, &info) || !info.dli_fname) return nullptr;
  std::error_code ec;
  return fs::equivalent(info.dli_fname, path, ec) ? sym : nullptr;
}

// Unloads a refused library on every exit path of loadLibrary unless released.
struct HandleGuard {
  void* handle;
  ~HandleGuard() {
    if (handle) dlclose(handle);
  }
};

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
      const auto sameFile = [&](const std::string& p) { return p == canonical; };
      const auto sameName = [&](const std::string& p) { return fs::path(p).filename() == lib.filename(); };
      // A library of the same file name found earlier on the path (loaded or refused) shadows later ones.
      const bool seen = std::any_of(loaded_.begin(), loaded_.end(), [&](const LoadedPlugin& p) { return sameFile(p.path); }) ||
                        std::any_of(failures_.begin(), failures_.end(), [&](const PluginLoadFailure& f) { return sameFile(f.path); });
      const bool shadowed = std::any_of(loaded_.begin(), loaded_.end(), [&](const LoadedPlugin& p) { return sameName(p.path); }) ||
                            std::any_of(failures_.begin(), failures_.end(), [&](const PluginLoadFailure& f) { return sameName(f.path); });
      if (seen || shadowed) continue;
      try {
        loadLibrary(canonical);
      } catch (const InputError& e) {
        failures_.push_back({canonical, e.what()});
        std::fprintf(stderr, "paddy: warning: skipped plugin: %s\n", e.what());
      }
    }
  }
}

void PluginManager::loadLibrary(const std::string& path) {
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) throw InputError("cannot load plugin '" + path + "': " + dlerror());
  HandleGuard guard{handle};
  // 1. The ABI version, before any other code of the plugin runs.
  auto abiFn = reinterpret_cast<paddy_plugin_abi_version_fn>(ownSymbol(handle, path, "paddy_plugin_abi_version"));
  if (!abiFn)
    throw InputError("plugin '" + path + "' does not export paddy_plugin_abi_version (built for plugin ABI 2 or "
                     "older? this Paddy has ABI " + std::to_string(PADDY_PLUGIN_ABI_VERSION) + "); rebuild it");
  const int abi = abiFn();
  if (abi != PADDY_PLUGIN_ABI_VERSION)
    throw InputError("plugin '" + path + "' was built for plugin ABI " + std::to_string(abi) +
                     ", this Paddy has ABI " + std::to_string(PADDY_PLUGIN_ABI_VERSION) + "; rebuild it");
  auto registerFn = reinterpret_cast<paddy_register_plugin_fn>(ownSymbol(handle, path, "paddy_register_plugin"));
  if (!registerFn) throw InputError("plugin '" + path + "' does not export the entry point paddy_register_plugin");
  // 2. Registration into a staging registry; kept only if it completes.
  std::string failure;
  int returned = 0;
  {
    StagingRegistry staged;
    try {
      returned = registerFn(&staged);
    } catch (const std::exception& e) {
      failure = std::string("its paddy_register_plugin threw: ") + e.what();
    } catch (...) {
      failure = "its paddy_register_plugin threw a non-standard exception";
    }
    if (failure.empty() && returned != PADDY_PLUGIN_ABI_VERSION)
      failure = "its paddy_register_plugin returned " + std::to_string(returned) + ", not the ABI version " +
                std::to_string(PADDY_PLUGIN_ABI_VERSION);
    if (failure.empty()) {
      // 3. Commit. Check every item first so that a bad item leaves nothing behind.
      for (const auto& info : staged.sub_models)
        if (info.name.empty() || !info.create) failure = "it registered a sub-model without name or factory";
      for (const auto& info : staged.geometries)
        if (info.name.empty() || !info.build) failure = "it registered a geometry without name or builder";
      for (const auto& info : staged.readers)
        if (info.name.empty() || !info.read || info.extensions.empty())
          failure = "it registered a mesh reader without name, extensions or read function";
    }
    if (failure.empty()) {
      LoadedPlugin lp{path, {}};
      impl_->current_library = path;
      for (auto& info : staged.sub_models) {
        lp.provides.push_back(std::string(toString(info.kind)) + ":" + info.name);
        addSubModel(std::move(info));
      }
      for (const auto& info : staged.geometries) {
        lp.provides.push_back("geometry:" + info.name);
        addGeometry(info);
      }
      for (const auto& info : staged.readers) {
        lp.provides.push_back("mesh_reader:" + info.name);
        addMeshReader(info);
      }
      impl_->current_library = "(registered directly)";
      impl_->handles.push_back(handle);
      guard.handle = nullptr;
      loaded_.push_back(std::move(lp));
      return;
    }
  }  // staged objects (whose code lives in the library) are destroyed before the library is unloaded
  throw InputError("plugin '" + path + "' refused: " + failure);
}

namespace {
// First-wins registration of one name; false (and a warning naming both libraries) for a repeat.
bool claimName(std::map<std::string, std::string>& provider, const std::string& key, const std::string& library,
               std::vector<std::string>& warnings) {
  const auto [it, inserted] = provider.emplace(key, library);
  if (inserted) return true;
  warnings.push_back(key + " is registered by both " + it->second + " and " + library + "; keeping the first (" +
                     it->second + ")");
  std::fprintf(stderr, "paddy: warning: %s\n", warnings.back().c_str());
  return false;
}
}  // namespace

void PluginManager::addSubModel(SubModelInfo info) {
  if (info.name.empty() || !info.create) throw InputError("a plugin registered a sub-model without name or factory");
  if (!claimName(impl_->provider, std::string(toString(info.kind)) + ":" + info.name, impl_->current_library, warnings_))
    return;
  auto key = std::make_pair(info.kind, info.name);
  impl_->sub_models.emplace(key, std::move(info));
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
  if (!claimName(impl_->provider, "geometry:" + info.name, impl_->current_library, warnings_)) return;
  impl_->geometries.emplace(info.name, info);
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
    const std::string e = normalisedExtension(ext);
    if (claimName(impl_->provider, "mesh_reader:" + e, impl_->current_library, warnings_)) impl_->readers.emplace(e, info);
  }
}

const MeshReaderInfo& PluginManager::meshReader(const std::string& extension) const {
  const std::string e = extension.empty() ? std::string() : normalisedExtension(extension);
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
