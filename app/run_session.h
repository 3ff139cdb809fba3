// What `drape run` and `drape drag` share: Ctrl-C as a cancellation, the exit
// code of a termination, and a solve written to a result folder with its
// progress line and report.
#pragma once

#include <string>

#include "core/model/scene.h"
#include "core/model/unit_system.h"
#include "core/solve/shell_solver.h"
#include "core/solve/solve_summary.h"

namespace drape::app {

// Ctrl-C and SIGTERM set `token` for as long as the guard lives, so an
// interrupt while a model is built or a result written still ends cleanly.
class InterruptGuard {
 public:
  explicit InterruptGuard(CancellationToken& token);
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

// The units the scene file is written in (SI when it cannot be read).
UnitSystem ScenesOwnUnits(const std::string& file);

// docs/format.md's exit codes: 0 completed, 1 invalid input, 2 solver failure,
// 130 cancelled.
int ExitCode(Termination t);

struct SolveReport {
  std::string command;   // "drape run", for messages
  bool quiet = false;    // no progress line, no report
  bool verbose = false;  // the full report
  int render_every = 0;  // render every N-th step into DIR/frames
  bool error_estimate = false;
  // The units of the quantities printed (contact depth, the last step's
  // reactions and probes): --units, or the scene's own.
  UnitSystem units = UnitSystem::kSI;
};

// Solves `scene` with `solver` into `output` (result.json, states.bin),
// printing progress and the report on stderr; returns the exit code.
int SolveIntoFolder(const Scene& scene,
                    ShellSolver& solver,
                    const std::string& output,
                    const SolveReport& report,
                    CancellationToken& cancel);

}  // namespace drape::app
