#include "app/run_session.h"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <vector>

#include "app/commands.h"
#include "core/io/result_writer.h"
#include "core/solve/error_estimate.h"

namespace drape::app {
namespace {

CancellationToken* g_cancel = nullptr;

// "end |F| 0.2843 gf, far_end |F| 0.1 gf" (forces) or "end (-5 cm, 0, 1 cm)"
// (positions), in `units`.
std::string Listed(const std::vector<NamedVector>& values, UnitSystem units, bool forces) {
  std::string text;
  for (const NamedVector& v : values) {
    if (!text.empty()) text += ", ";
    if (forces) {
      text += v.name + " |F| " + FormatQuantity(v.value.norm(), Measure::kForce, units);
    } else {
      text += v.name + " (";
      for (int k = 0; k < 3; ++k)
        text += (k ? ", " : "") + FormatQuantity(v.value[k], Measure::kLength, units);
      text += ")";
    }
  }
  return text;
}

extern "C" void OnInterrupt(int) {
  if (g_cancel) g_cancel->Cancel();
}

// One line, rewritten in place, on a terminal only.
class ProgressLine {
 public:
  ProgressLine(bool enabled, UnitSystem units) : enabled_(enabled), units_(units) {}
  ~ProgressLine() { Clear(); }

  void Show(const StepState& s, int stability_changes) {
    if (!enabled_) return;
    char contact[80] = "";
    if (s.contact)
      std::snprintf(
          contact,
          sizeof contact,
          "  contact %d nodes, %s deep",
          s.contact->nodes,
          FormatQuantity(s.contact->max_penetration, Measure::kThickness, units_, 3).c_str());
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
  UnitSystem units_;
  bool shown_ = false;
};

}  // namespace

InterruptGuard::InterruptGuard(CancellationToken& token) {
  g_cancel = &token;
  std::signal(SIGINT, OnInterrupt);
  std::signal(SIGTERM, OnInterrupt);
}

InterruptGuard::~InterruptGuard() {
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  g_cancel = nullptr;
}

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

UnitSystem ScenesOwnUnits(const std::string& file) {
  std::ifstream in(file);
  return GuessUnitSystem(std::string{std::istreambuf_iterator<char>(in), {}});
}

int SolveIntoFolder(const Scene& scene,
                    ShellSolver& solver,
                    const std::string& output,
                    const SolveReport& report,
                    CancellationToken& cancel) {
  std::unique_ptr<ResultWriter> writer;
  try {
    writer = std::make_unique<ResultWriter>(output, scene, solver.model());
  } catch (const std::exception& e) {
    std::cerr << report.command + ": " << e.what() << "\n";
    return 1;
  }

  ProgressLine progress(!report.quiet && isatty(STDERR_FILENO), report.units);
  int last_pivots = 0;
  std::vector<NamedVector> last_probes, last_reactions;
  StepObserver record = [&](const StepState& s) {
    writer->AddStep(s);
    last_probes = s.probes;
    last_reactions = s.reactions;
    progress.Show(s, s.negative_pivots != last_pivots);
    last_pivots = s.negative_pivots;
    return StepDecision::kContinue;
  };
  std::vector<StepObserver> observers = {record};
  if (report.render_every > 0) {
    try {
      observers.push_back(MakeRenderObserver(
          scene, solver.model(), writer->directory() / "frames", report.render_every));
    } catch (const std::exception& e) {
      std::cerr << report.command + ": --render-every: " << e.what() << "\n";
      return 1;
    }
  }
  SolveSummary summary = solver.Solve(observers, &cancel);
  progress.Clear();
  std::optional<ErrorEstimate> estimate;
  if ((report.error_estimate || scene.solver.error_estimate) && summary.IsComplete()) {
    if (!report.quiet) std::cerr << "  estimating the error on meshes 2 and 4 times coarser\n";
    estimate = EstimateError(scene, SolverOptions::FromScene(scene.solver), last_probes, &cancel);
    writer->SetErrorEstimate(*estimate);
  }
  try {
    writer->Finish(summary);
  } catch (const std::exception& e) {
    std::cerr << report.command + ": " << e.what() << "\n";
    return 2;
  }
  if (!report.quiet) {
    std::cerr << (report.verbose ? summary.FullReport() : summary.BriefReport() + "\n");
    if (!report.verbose) {
      for (const auto& e : summary.stability_events) std::cerr << "  " << Describe(e) << "\n";
      for (const auto& warning : summary.warnings) std::cerr << "  warning: " << warning << "\n";
      for (const auto& note : summary.notes) std::cerr << "  note: " << note << "\n";
    }
    if (!last_reactions.empty())
      std::cerr << "  reactions at the last step: " << Listed(last_reactions, report.units, true)
                << "\n";
    if (!last_probes.empty())
      std::cerr << "  probes at the last step: " << Listed(last_probes, report.units, false)
                << "\n";
    if (estimate) std::cerr << "  " << Describe(*estimate, ErrorUnit(report.units)) << "\n";
    std::cerr << "  results: " << (writer->directory() / kResultFileName).string() << "\n";
  }
  return ExitCode(summary.termination);
}

}  // namespace drape::app
