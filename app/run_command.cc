// `drape run SCENE -o DIR [--quiet] [--verbose]`: solve a scene and write
// DIR/result.json and DIR/states.bin. Exit codes: 0 converged, 1 invalid
// input, 2 solver failure (partial result written), 130 cancelled.
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/render_program.h"
#include "app/run_session.h"
#include "core/io/scene_reader.h"
#include "core/model/scene_error.h"
#include "core/model/solver_preset.h"
#include "core/model/unit_system.h"
#include "core/solve/shell_solver.h"

namespace drape::app {
namespace {

struct RunArgs {
  std::string scene;
  std::string output;
  bool quiet = false;
  bool verbose = false;
  int threads = 0;
  int render_every = 0;
  double time_limit_s = 0;      // 0: the scene's solver.max_wall_s
  bool error_estimate = false;  // or the scene's solver.error_estimate
  std::string preset;           // empty: the scene's solver settings
  std::string units;            // of the report; empty: the scene's own
};

int RunRun(const RunArgs& args) {
#ifndef DRAPE_WITH_RENDER
  if (args.render_every > 0) return RunInRenderProgram("run");
#endif
  CancellationToken cancel;
  InterruptGuard guard(cancel);
  Scene scene;
  std::unique_ptr<ShellSolver> solver;
  try {
    scene = ReadScene(args.scene);
    if (!args.preset.empty()) scene.solver = WithPreset(scene.solver, *PresetNamed(args.preset));
    SolverOptions options = SolverOptions::FromScene(scene.solver);
    options.threads = args.threads;
    if (args.time_limit_s > 0) options.max_wall_s = args.time_limit_s;
    solver = std::make_unique<ShellSolver>(scene, options);
  } catch (const SceneError& e) {
    std::cerr << "drape run: " << args.scene << ": " << e.what() << "\n";
    return 1;
  }
  SolveReport report;
  report.command = "drape run";
  report.quiet = args.quiet;
  report.verbose = args.verbose;
  report.render_every = args.render_every;
  report.error_estimate = args.error_estimate;
  report.units = args.units.empty() ? ScenesOwnUnits(args.scene) : *UnitSystemNamed(args.units);
  return SolveIntoFolder(scene, *solver, args.output, report, cancel);
}

}  // namespace

#ifndef DRAPE_WITH_RENDER
// Not called: RunRun hands a run that renders to drape-vtk.
StepObserver MakeRenderObserver(const Scene&,
                                const ShellModel&,
                                const std::filesystem::path&,
                                int) {
  throw std::runtime_error("this build of drape has no renderer (built without VTK)");
}
#endif

void AddRunCommand(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* cmd = app.add_subcommand("run", "Solve a scene and write its result folder");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
  cmd->add_option("-o,--output", args->output, "Result folder (created if missing)")->required();
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line and no report");
  cmd->add_flag("-v,--verbose", args->verbose, "Print the full solve report");
  cmd->add_option("--threads", args->threads, "Threads for assembly (0: all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--time-limit",
                  args->time_limit_s,
                  "Stop the run (failed, every converged step kept) after this many seconds; "
                  "overrides solver.max_wall_s")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--error-estimate",
                args->error_estimate,
                "Also solve on meshes 2 and 4 times coarser and estimate each probe's error "
                "(Richardson; solver.error_estimate)");
  std::vector<std::string> presets;
  for (const PresetDefinition& p : PresetDefinitions()) presets.push_back(p.name);
  cmd->add_option("--units",
                  args->units,
                  "Units of the report's quantities (contact depth, the last step's reactions "
                  "and probes): si, textile (cm, gf) or imperial (in, oz); default the units the "
                  "scene is written in")
      ->check(CLI::IsMember({"si", "textile", "imperial"}));
  cmd->add_option("--preset",
                  args->preset,
                  "Solve at this accuracy preset (solver.preset; overrides the scene's tolerance, "
                  "N_p and mesh scale): draft = half the mesh at 1e-4, balanced = the scene's "
                  "mesh at 1e-5, accurate = twice the mesh at 1e-7; N_p 6")
      ->check(CLI::IsMember(presets));
  cmd->add_option("--render-every",
                  args->render_every,
                  "Render every N-th converged step to DIR/frames/step_NNNN.png while solving")
      ->check(CLI::PositiveNumber);
  cmd->callback([args, &runner] { runner = [args] { return RunRun(*args); }; });
}

}  // namespace drape::app
