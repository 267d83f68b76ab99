// Sub-commands of the `paddy` executable (each in its own file).
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace paddy::app {

// A sub-command registers its options and returns the action to run once parsing succeeded.
using Action = std::function<int()>;

Action addRunCommand(CLI::App& app);
Action addPluginsCommand(CLI::App& app);

}  // namespace paddy::app
