// The `drape` subcommands. Each registers itself on the CLI11 app and, when
// chosen, runs and returns the process exit code (docs/format.md: 0 success,
// 1 invalid input, 2 solver failure, 130 cancelled).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>

#include "core/solve/step_state.h"

namespace CLI {
class App;
}

namespace drape {
struct Scene;
struct ShellModel;
}  // namespace drape

namespace drape::app {

using CommandRunner = std::function<int()>;

// Adds `validate SCENE [--resolved]`; sets `runner` to run it when chosen.
void AddValidateCommand(CLI::App& app, CommandRunner& runner);
// Adds `run SCENE -o DIR [--quiet] [--verbose] [--threads N]`.
void AddRunCommand(CLI::App& app, CommandRunner& runner);
// Adds `drag SCENE --gripper NAME --by dx,dy,dz [--frames N] -o DIR`.
void AddDragCommand(CLI::App& app, CommandRunner& runner);
// Adds `measure RESULT --drape-coefficient [--support-radius R] [--step N] [--json]`.
void AddMeasureCommand(CLI::App& app, CommandRunner& runner);
// Adds `study STUDY -o DIR [--jobs N] [--emit slurm|parallel]` and `study DIR --collect`.
void AddStudyCommand(CLI::App& app, CommandRunner& runner);
// Adds `plan PLAN -o DIR [--jobs N] [--emit slurm|parallel]`.
void AddPlanCommand(CLI::App& app, CommandRunner& runner);
// Adds `material fit FILE …` and `material list`.
void AddMaterialCommand(CLI::App& app, CommandRunner& runner);
// Adds `pattern list FILE [--json]`: the pieces of a DXF-AAMA pattern file.
void AddPatternCommand(CLI::App& app, CommandRunner& runner);
// Adds `render INPUT -o PNG …` and `animate RESULT -o MOVIE …` (need VTK).
void AddRenderCommands(CLI::App& app, CommandRunner& runner);
// Adds `front DIR [-o PNG]`: a study's speed–accuracy front (needs VTK).
void AddFrontCommand(CLI::App& app, CommandRunner& runner);
// Adds `plan-chart DIR [-o PNG]`: a plan's search drawn (needs VTK).
void AddPlanChartCommand(CLI::App& app, CommandRunner& runner);
// Adds `export RESULT -o DIR --format …` (its surfaces need VTK, its DXF
// outline does not).
void AddExportCommand(CLI::App& app, CommandRunner& runner);

// For `run --render-every N`: an observer that renders every `every`-th
// converged step to `directory`/step_NNNN.png (1280 × 720, iso), the camera
// fitted to the part and its grippers' paths. Throws std::runtime_error when
// nothing can be rendered (no display, no renderer in this build).
StepObserver MakeRenderObserver(const Scene& scene,
                                const ShellModel& model,
                                const std::filesystem::path& directory,
                                int every);

}  // namespace drape::app
