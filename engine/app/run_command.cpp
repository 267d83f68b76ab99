// `paddy run SCRIPT.lua ...`: runs an experiment script (the work is in paddy::lua::runScript).
#include "commands.hpp"

#include <paddy/lua/runtime.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <unistd.h>

namespace paddy::app {

namespace {

namespace fs = std::filesystem;

// share/paddy/experiments beside the installed executable, else the source tree's experiments/.
std::string experimentsDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / PADDY_INSTALL_EXPERIMENTS_SUBDIR;
    if (fs::is_directory(installed, ec)) return installed.string();
  }
  return PADDY_SOURCE_EXPERIMENTS_DIR;
}

}  // namespace

Action addRunCommand(CLI::App& app) {
  auto opts = std::make_shared<lua::ScriptOptions>();
  auto sets = std::make_shared<std::vector<std::string>>();
  auto help = std::make_shared<bool>(false);
  CLI::App* run = app.add_subcommand("run", "Run an experiment script");
  run->set_help_flag();  // --help after the script lists the script's parameters instead
  run->add_flag("-h,--help", *help, "Without SCRIPT: this help; with SCRIPT: the script's parameters");
  run->add_option("script", opts->script, "Experiment script (.lua)");
  run->add_option("--set", *sets, "Override a script parameter: --set name=value (repeatable)")
      ->allow_extra_args(false);
  run->add_option("--out", opts->out_dir, "Output directory (default: out/<script name>)");
  run->add_option("--threads", opts->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  run->add_option("--seed", opts->seed, "Random seed, paddy.seed in the script")->capture_default_str();
  return [run, opts, sets, help]() {
    if (opts->script.empty()) {
      std::cout << run->help();
      return *help ? 0 : int(lua::kExitInput);
    }
    opts->help = *help;
    opts->experiments_dir = experimentsDir();
    for (const auto& s : *sets) opts->sets.push_back(lua::parseAssignment(s));
    return lua::runScript(*opts, std::cout, std::cerr);
  };
}

}  // namespace paddy::app
