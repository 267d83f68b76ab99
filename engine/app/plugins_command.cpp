// `paddy plugins`: the plugin search path, the plugins found and everything they provide, the
// libraries skipped (file and reason) and names registered by two libraries.
#include "commands.hpp"

#include <paddy/geometry.hpp>
#include <paddy/plugin_manager.hpp>

#include <cmath>
#include <iostream>
#include <sstream>

namespace paddy::app {

namespace {

std::string range(const ParamSpec& p) {
  std::ostringstream s;
  s << '[' << p.min << ", " << p.max << ']';
  return s.str();
}

void printParams(const std::vector<ParamSpec>& params) {
  for (const ParamSpec& p : params) {
    std::cout << "        " << p.name << " = ";
    if (p.required) std::cout << "(required)";
    else std::cout << p.default_value;
    if (!p.unit.empty()) std::cout << ' ' << p.unit;
    std::cout << "  " << range(p);
    if (!p.description.empty()) std::cout << "  " << p.description;
    std::cout << '\n';
  }
}

int listPlugins() {
  PluginManager plugins;
  plugins.loadDefault();
  std::cout << "Plugin search path ($PADDY_PLUGIN_PATH, then beside the executable):\n";
  for (const auto& dir : PluginManager::defaultSearchPath()) std::cout << "  " << dir << '\n';
  std::cout << "\nPlugins loaded:\n";
  if (plugins.loaded().empty()) std::cout << "  (none)\n";
  for (const auto& lp : plugins.loaded()) {
    std::cout << "  " << lp.path << '\n';
    for (const auto& p : lp.provides) std::cout << "    provides " << p << '\n';
  }
  if (!plugins.failures().empty()) {
    std::cout << "\nPlugins skipped (could not be loaded):\n";
    for (const auto& f : plugins.failures()) std::cout << "  " << f.path << "\n    reason: " << f.reason << '\n';
  }
  if (!plugins.warnings().empty()) {
    std::cout << "\nNames registered twice (the first is kept):\n";
    for (const auto& w : plugins.warnings()) std::cout << "  " << w << '\n';
  }
  std::cout << "\nContact sub-models:\n";
  for (auto kind : {SubModelKind::Normal, SubModelKind::Damping, SubModelKind::Tangential, SubModelKind::Rolling,
                    SubModelKind::Twisting, SubModelKind::Extra}) {
    const auto models = plugins.subModels(kind);
    std::cout << "  " << toString(kind) << ":" << (models.empty() ? " (none)" : "") << '\n';
    for (const SubModelInfo* m : models) {
      std::cout << "    " << m->name << (m->description.empty() ? "" : " — " + m->description) << '\n';
      printParams(m->params);
    }
  }
  std::cout << "\nGeometries:\n";
  const auto names = plugins.geometryNames();
  if (names.empty()) std::cout << "  (none)\n";
  for (const auto& name : names) {
    const GeometryInfo& g = plugins.geometry(name);
    std::cout << "    " << g.name << (g.description.empty() ? "" : " — " + g.description) << '\n';
    printParams(g.params);
  }
  return 0;
}

}  // namespace

Action addPluginsCommand(CLI::App& app) {
  app.add_subcommand("plugins", "List the plugins found, what they provide, and the search path");
  return listPlugins;
}

}  // namespace paddy::app
