// What the outside world sees of a run: one StepState per converged step
// (Ceres' IterationSummary), handed to observers that may stop the run, and a
// cancellation token checked between Newton iterations.
#pragma once

#include <Eigen/Core>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/solve/shell_state.h"

namespace drape {

struct NamedVector {
  std::string name;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
};

// What contact does in a state (scenes with obstacles).
struct ContactReport {
  int nodes = 0;                                    // nodes in contact
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  // obstacles on the fabric [N]
  double max_penetration = 0;                       // largest −g [m], ≥ 0
  // With the "auto" penalty: the penetration the augmented-Lagrangian passes
  // hold (0: no target, a penalty the user set), the passes this step took,
  // and why they stopped short of the target ("" when it was met).
  double penetration_target = 0;  // [m]
  int augmentation_passes = 0;
  std::string augmentation_shortfall;
  // The stabilisation springs of a scene held only by contact (zero when off).
  Eigen::Vector3d stabilization_force = Eigen::Vector3d::Zero();  // Σ [N]
  double max_stabilization_force = 0;                             // largest nodal [N]
  std::vector<double> pressure;  // per node: contact force / tributary area [Pa]
};

// How an iteration stands against the convergence test.
enum class Convergence {
  kNotYet,     // iterate on
  kTolerance,  // ‖R‖/‖R₀‖ ≤ tolerance
  kRoundOff,   // ‖R‖ at the round-off floor: as converged as the arithmetic allows
  kStalled,    // the corrections stopped with the residual above both: not converged
};

// "tolerance", "round_off", "stalled", "not_converged" (result.json's words).
const char* ToString(Convergence convergence);

// What the number of negative pivots changing between two converged steps
// means: a limit point (λ turns along the path: snap-through, snap-back) or a
// bifurcation (the count changes while λ keeps its direction).
enum class StabilityKind { kLimit, kBifurcation };
// Which way the path went on from a bifurcation.
enum class Branch {
  kFundamental,  // on along the primary path (solver.branching: fundamental)
  kStable,       // switched to a secondary branch with the pivots of before
  kNone,         // not a bifurcation (a limit point), or no branch was found
};
const char* ToString(StabilityKind kind);  // "limit", "bifurcation"
const char* ToString(Branch branch);       // "fundamental", "stable", "none"

// A change in the number of negative pivots between two converged steps: the
// path crossed a limit or bifurcation point.
struct StabilityEvent {
  int stage = -1;
  int step = 0;       // the first step after the change (on the branch taken)
  double lambda = 0;  // where it happened (a located bifurcation: its λ)
  int negative_pivots_before = 0;
  int negative_pivots_after = 0;  // on the path the step took (the branch when switched)
  StabilityKind kind = StabilityKind::kLimit;
  Branch branch = Branch::kNone;
  // Bifurcations: the pivots on the primary path just past the point, how
  // many critical modes, the largest nodal translation of the switch onto the
  // branch [m], and what locating and switching cost.
  int negative_pivots_fundamental = 0;
  int modes = 0;
  double mode_max_displacement = 0;
  int switch_iterations = 0;
  double switch_s = 0;
};

struct StepState {
  int stage = -1;  // index in the scene's stages
  std::string stage_name;
  int step = 0;                   // 1-based over the whole run
  int stage_step = 0;             // 1-based within the stage
  double lambda = 0;              // the stage's load factor
  int iterations = 0;             // Newton iterations of this step
  std::vector<double> residuals;  // ‖R‖/‖R₀‖ after each assembly (R₀: the load the step added)
  // How the step's last iteration met the test: the tolerance, or the
  // round-off floor (NewtonSettings::round_off_factor).
  Convergence convergence = Convergence::kTolerance;
  double arc_length = 0;                 // the step's length along the path
  int negative_pivots = 0;               // of the converged tangent
  double max_curvature = 0;              // largest principal |κ| at a Gauss point [1/m]
  double law_curvature = 0;              // largest argument of the bending laws [1/m]
  std::vector<NamedVector> reactions;    // force each support and gripper exerts [N]
  std::vector<NamedVector> probes;       // probe positions [m]
  std::optional<ContactReport> contact;  // present when the scene has obstacles
  // The smallest distance between the mid-surfaces of two parts of the
  // fabric more than SolveSummary::layer_exclusion apart at rest, when two
  // such parts come within twice the thickness of each other [m]: below the
  // thickness, layers pass into each other.
  std::optional<double> layer_distance;
  // With self-contact, the force the layers exert on each other then
  // (SelfContactEvaluation::force) [N].
  std::optional<double> layer_force;
  ShellState state;  // the converged configuration
  // Set on the step where the path crossed a limit or bifurcation point
  // (also in SolveSummary::stability_events).
  std::optional<StabilityEvent> stability_event;
  double elapsed_s = 0;  // since the run started
};

enum class StepDecision { kContinue, kStop };

using StepObserver = std::function<StepDecision(const StepState&)>;

// Set from another thread (or a signal handler) to stop a run between Newton
// iterations; the run keeps every step converged so far. A run can also be
// paused between Newton iterations (from another thread, not a signal
// handler): the solver then waits in WaitWhilePaused until resumed or
// cancelled.
class CancellationToken {
 public:
  // Only an atomic store, so a signal handler may call it; a paused solver
  // sees it within WaitWhilePaused's polling interval.
  void Cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  // Cancelled, or its parent is, or its deadline has passed.
  bool IsCancelled() const {
    return cancelled_.load(std::memory_order_relaxed) || (parent_ && parent_->IsCancelled()) ||
           DeadlinePassed();
  }

  // A token for one run: it also stops when `parent` (may be null) is
  // cancelled, waits while the parent is paused, and stops at `deadline`.
  // Set both before the run starts.
  void Follow(const CancellationToken* parent) { parent_ = parent; }
  void SetDeadline(std::chrono::steady_clock::time_point deadline) { deadline_ = deadline; }
  bool DeadlinePassed() const {
    return deadline_ && std::chrono::steady_clock::now() >= *deadline_;
  }

  void Pause() {
    std::lock_guard lock(mutex_);
    paused_ = true;
  }
  void Resume() {
    {
      std::lock_guard lock(mutex_);
      paused_ = false;
    }
    wake_.notify_all();
  }
  bool IsPaused() const {
    std::lock_guard lock(mutex_);
    return paused_;
  }
  // The solver's side: blocks while paused (returns at once otherwise),
  // until resumed or cancelled.
  void WaitWhilePaused() const {
    if (parent_) parent_->WaitWhilePaused();
    std::unique_lock lock(mutex_);
    while (paused_ && !IsCancelled()) wake_.wait_for(lock, std::chrono::milliseconds(20));
  }

 private:
  std::atomic<bool> cancelled_{false};
  const CancellationToken* parent_ = nullptr;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  mutable std::mutex mutex_;
  mutable std::condition_variable wake_;
  bool paused_ = false;
};

}  // namespace drape
