// Job specs and content keys: exact parameter text, SHA-256 (OpenSSL EVP), required-module
// scan, the canonical key text and the code version.
#include <paddy/campaign/job.hpp>

#include <openssl/evp.h>

#include <dlfcn.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#ifndef PADDY_VERSION
#define PADDY_VERSION "unknown"
#endif

namespace paddy::campaign {

namespace fs = std::filesystem;

std::string formatNumber(double value) {
  char buf[64];
  if (std::isfinite(value) && value == std::trunc(value) && std::fabs(value) < 1e15)
    std::snprintf(buf, sizeof buf, "%.0f", value);
  else
    std::snprintf(buf, sizeof buf, "%.17g", value);
  return buf;
}

JobSpec& JobSpec::set(const std::string& name, double value) {
  params[name] = formatNumber(value);
  return *this;
}
JobSpec& JobSpec::set(const std::string& name, long long value) {
  params[name] = std::to_string(value);
  return *this;
}
JobSpec& JobSpec::set(const std::string& name, bool value) {
  params[name] = value ? "true" : "false";
  return *this;
}
JobSpec& JobSpec::set(const std::string& name, const std::string& value) {
  params[name] = value;
  return *this;
}

namespace {

struct MdCtxFree {
  void operator()(EVP_MD_CTX* c) const { EVP_MD_CTX_free(c); }
};

class Sha256 {
 public:
  Sha256() : ctx_(EVP_MD_CTX_new()) {
    if (!ctx_ || EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr) != 1)
      throw std::runtime_error("SHA-256: cannot initialise the OpenSSL digest");
  }
  void update(const void* data, std::size_t n) {
    if (EVP_DigestUpdate(ctx_.get(), data, n) != 1) throw std::runtime_error("SHA-256: update failed");
  }
  std::string hex() {
    unsigned char md[EVP_MAX_MD_SIZE];
    unsigned int len = 0;
    if (EVP_DigestFinal_ex(ctx_.get(), md, &len) != 1) throw std::runtime_error("SHA-256: final failed");
    static const char* digits = "0123456789abcdef";
    std::string out;
    for (unsigned int i = 0; i < len; ++i) {
      out += digits[md[i] >> 4];
      out += digits[md[i] & 15];
    }
    return out;
  }

 private:
  std::unique_ptr<EVP_MD_CTX, MdCtxFree> ctx_;
};

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + path.string() + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::optional<fs::path> resolveModule(const std::string& name, const std::vector<fs::path>& dirs) {
  std::string rel = name;
  for (char& ch : rel)
    if (ch == '.') ch = '/';
  std::error_code ec;
  for (const auto& d : dirs) {
    for (const fs::path& candidate : {d / (rel + ".lua"), d / rel / "init.lua"})
      if (fs::is_regular_file(candidate, ec)) return fs::weakly_canonical(candidate, ec);
  }
  return std::nullopt;
}

}  // namespace

std::string sha256Hex(const std::string& data) {
  Sha256 h;
  h.update(data.data(), data.size());
  return h.hex();
}

std::string sha256File(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + path.string() + "'");
  Sha256 h;
  char buf[1 << 16];
  while (in) {
    in.read(buf, sizeof buf);
    if (in.gcount() > 0) h.update(buf, static_cast<std::size_t>(in.gcount()));
  }
  return h.hex();
}

std::map<std::string, fs::path> requiredModules(const fs::path& script, const std::vector<fs::path>& module_path) {
  static const std::regex require_re(R"re(\brequire\s*\(?\s*["']([A-Za-z0-9_.\-]+)["'])re");
  std::map<std::string, fs::path> found;
  std::vector<fs::path> todo{script};
  std::set<fs::path> seen;
  while (!todo.empty()) {
    const fs::path file = todo.back();
    todo.pop_back();
    if (!seen.insert(file).second) continue;
    std::vector<fs::path> dirs{fs::absolute(script).parent_path()};
    dirs.insert(dirs.end(), module_path.begin(), module_path.end());
    const std::string text = readFile(file);
    for (std::sregex_iterator it(text.begin(), text.end(), require_re), end; it != end; ++it) {
      const std::string name = (*it)[1];
      if (found.count(name)) continue;
      if (auto p = resolveModule(name, dirs)) {
        found[name] = *p;
        todo.push_back(*p);
      }
    }
  }
  return found;
}

std::string keyMaterial(const JobSpec& spec, const std::string& code_version, const std::vector<fs::path>& module_path) {
  std::ostringstream s;
  s << "paddy-campaign-job 1\n";
  s << "code " << code_version << "\n";
  if (!spec.script.empty()) {
    s << "script " << sha256File(spec.script) << "\n";
    for (const auto& [name, path] : requiredModules(spec.script, module_path))
      s << "module " << name << " " << sha256File(path) << "\n";
  }
  for (const auto& [name, value] : spec.params)  // std::map: sorted by name
    s << "param " << name << "=" << value << "\n";
  s << "seed " << spec.seed << "\n";
  if (!spec.command.empty()) {
    s << "command";
    for (const auto& arg : spec.command) s << " " << arg.size() << ":" << arg;
    s << "\n";
  }
  return s.str();
}

std::string jobKey(const JobSpec& spec, const std::string& code_version, const std::vector<fs::path>& module_path) {
  return sha256Hex(keyMaterial(spec, code_version, module_path));
}

std::string defaultCodeVersion(const fs::path& executable) {
  std::string v = std::string("paddy ") + PADDY_VERSION;
  std::error_code ec;
  if (!executable.empty() && fs::is_regular_file(executable, ec)) {
    try {
      v += " exe:" + sha256File(executable);
    } catch (const std::exception&) {
    }
  }
  // The engine library (this code) decides the physics as much as the executable does.
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&defaultCodeVersion), &info) && info.dli_fname) {
    try {
      v += " lib:" + sha256File(info.dli_fname);
    } catch (const std::exception&) {
    }
  }
  return v;
}

}  // namespace paddy::campaign
