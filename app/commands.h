// The `drape` subcommands. Each registers itself on the CLI11 app and, when
// chosen, runs and returns the process exit code (FORMAT.md: 0 success,
// 1 invalid input, 2 solver failure, 130 cancelled).
#pragma once

#include <functional>

namespace CLI {
class App;
}

namespace drape::app {

using CommandRunner = std::function<int()>;

// Adds `validate SCENE [--resolved]`; sets `runner` to run it when chosen.
void AddValidateCommand(CLI::App& app, CommandRunner& runner);
// Adds `run SCENE -o DIR [--quiet] [--verbose] [--threads N]`.
void AddRunCommand(CLI::App& app, CommandRunner& runner);
// Adds `material fit FILE [--degree N] [--branch B] [--json]`.
void AddMaterialCommand(CLI::App& app, CommandRunner& runner);

}  // namespace drape::app
