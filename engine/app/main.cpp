// paddy — command line of the Paddy DEM framework.
//   paddy run SCRIPT.lua [--set name=value ...] [--out DIR] [--threads N] [--seed S]
//   paddy run SCRIPT.lua --help      the script's parameters
//   paddy plugins                    plugins found, what they provide, the search path
//   paddy doe ...                    design of experiments (when built with paddy_doe)
// Exit codes: 0 ok, 1 other failure, 2 bad input, 3 numerical instability.
#include "commands.hpp"

#include <paddy/errors.hpp>
#include <paddy/lua/runtime.hpp>

#ifdef PADDY_HAVE_DOE
#include <paddy/doe/cli.hpp>
#include <paddy/lua/doe.hpp>
#endif

#include <csignal>
#include <cstring>
#include <iostream>

int main(int argc, char** argv) {
  // A file grown past `ulimit -f` must not kill paddy with SIGXFSZ (no message, no error.json):
  // ignored, the write fails with EFBIG and is reported like any other failed write, naming the
  // file. The jobs a campaign starts inherit this.
  std::signal(SIGXFSZ, SIG_IGN);
#ifdef PADDY_HAVE_DOE
  paddy::lua::addPreload("paddy.doe", &luaopen_paddy_doe);
  if (argc > 1 && std::strcmp(argv[1], "doe") == 0) return paddy::doe::runCli(argc - 1, argv + 1);
#endif
  CLI::App app{"Paddy: DEM for wet, viscous granular materials", "paddy"};
  app.set_version_flag("--version", std::string("paddy ") + paddy::lua::version());
  app.require_subcommand(1);
  const auto run = paddy::app::addRunCommand(app);
  const auto plugins = paddy::app::addPluginsCommand(app);
  auto* doe = app.add_subcommand("doe", "Design of experiments (screening, response surfaces, calibration)");
  doe->allow_extras();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : paddy::lua::kExitInput;
  }
  try {
    if (app.got_subcommand("run")) return run();
    if (app.got_subcommand("plugins")) return plugins();
    std::cerr << "paddy: error: this build has no design-of-experiments module (paddy_doe)\n";
    return paddy::lua::kExitInput;
  } catch (const paddy::InputError& e) {
    std::cerr << "paddy: error: " << e.what() << "\n";
    return paddy::lua::kExitInput;
  } catch (const paddy::InstabilityError& e) {
    std::cerr << "paddy: error: " << e.what() << "\n";
    return paddy::lua::kExitInstability;
  } catch (const std::exception& e) {
    std::cerr << "paddy: error: " << e.what() << "\n";
    return paddy::lua::kExitFailure;
  }
}
