// `drape run SCENE -o DIR [--quiet] [--verbose]`: solve a scene and write
// DIR/result.json and DIR/states.bin. Exit codes: 0 converged, 1 invalid
// input, 2 solver failure (partial result written), 130 cancelled.
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.h"
#include "app/render_program.h"
#include "core/io/result_writer.h"
#include "core/io/scene_reader.h"
#include "core/model/scene_error.h"
#include "core/model/solver_preset.h"
#include "core/solve/error_estimate.h"
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
};

CancellationToken* g_cancel = nullptr;

extern "C" void OnInterrupt(int) {
  if (g_cancel) g_cancel->Cancel();
}

// One line, rewritten in place, on a terminal only.
class ProgressLine {
 public:
  explicit ProgressLine(bool enabled) : enabled_(enabled) {}
  ~ProgressLine() { Clear(); }

  void Show(const StepState& s, int stability_changes) {
    if (!enabled_) return;
    char contact[80] = "";
    if (s.contact)
      std::snprintf(contact,
                    sizeof contact,
                    "  contact %d nodes, %.3g mm deep",
                    s.contact->nodes,
                    1e3 * s.contact->max_penetration);
    char line[300];
    std::snprintf(line,
                  sizeof line,
                  "\r  stage %-8s step %5d  lambda %.6f  iterations %2d  pivots- %d%s%s  %7.1f s ",
                  s.stage_name.c_str(),
                  s.step,
                  s.lambda,
                  s.iterations,
                  s.negative_pivots,
                  stability_changes ? " (stability changed)" : "",
                  contact,
                  s.elapsed_s);
    std::fputs(line, stderr);
    shown_ = true;
  }
  void Clear() {
    if (enabled_ && shown_) std::fputs("\r\033[K", stderr);
    shown_ = false;
  }

 private:
  bool enabled_;
  bool shown_ = false;
};

int ExitCode(Termination t) {
  switch (t) {
    case Termination::kCompleted:
      return 0;
    case Termination::kCancelled:
    case Termination::kStoppedByObserver:
      return 130;
    case Termination::kInvalidInput:
      return 1;
    default:
      return 2;
  }
}

// Ctrl-C and SIGTERM set the token for the whole command, so an interrupt
// while the model is built or the result is written still ends cleanly.
struct InterruptGuard {
  explicit InterruptGuard(CancellationToken& token) {
    g_cancel = &token;
    std::signal(SIGINT, OnInterrupt);
    std::signal(SIGTERM, OnInterrupt);
  }
  ~InterruptGuard() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    g_cancel = nullptr;
  }
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
  std::unique_ptr<ResultWriter> writer;
  try {
    writer = std::make_unique<ResultWriter>(args.output, scene, solver->model());
  } catch (const std::exception& e) {
    std::cerr << "drape run: " << e.what() << "\n";
    return 1;
  }

  ProgressLine progress(!args.quiet && isatty(STDERR_FILENO));
  int last_pivots = 0;
  std::vector<NamedVector> last_probes;
  StepObserver record = [&](const StepState& s) {
    writer->AddStep(s);
    last_probes = s.probes;
    progress.Show(s, s.negative_pivots != last_pivots);
    last_pivots = s.negative_pivots;
    return StepDecision::kContinue;
  };
  std::vector<StepObserver> observers = {record};
  if (args.render_every > 0) {
    try {
      observers.push_back(MakeRenderObserver(
          scene, solver->model(), writer->directory() / "frames", args.render_every));
    } catch (const std::exception& e) {
      std::cerr << "drape run: --render-every: " << e.what() << "\n";
      return 1;
    }
  }
  SolveSummary summary = solver->Solve(observers, &cancel);
  progress.Clear();
  std::optional<ErrorEstimate> estimate;
  if ((args.error_estimate || scene.solver.error_estimate) && summary.IsComplete()) {
    if (!args.quiet) std::cerr << "  estimating the error on meshes 2 and 4 times coarser\n";
    estimate = EstimateError(scene, SolverOptions::FromScene(scene.solver), last_probes, &cancel);
    writer->SetErrorEstimate(*estimate);
  }
  try {
    writer->Finish(summary);
  } catch (const std::exception& e) {
    std::cerr << "drape run: " << e.what() << "\n";
    return 2;
  }
  if (!args.quiet) {
    std::cerr << (args.verbose ? summary.FullReport() : summary.BriefReport() + "\n");
    if (!args.verbose) {
      for (const auto& e : summary.stability_events) std::cerr << "  " << Describe(e) << "\n";
      for (const auto& warning : summary.warnings) std::cerr << "  warning: " << warning << "\n";
      for (const auto& note : summary.notes) std::cerr << "  note: " << note << "\n";
    }
    if (estimate) std::cerr << "  " << Describe(*estimate) << "\n";
    std::cerr << "  results: " << (writer->directory() / kResultFileName).string() << "\n";
  }
  return ExitCode(summary.termination);
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
