// What the outside world sees of a run: one StepState per converged step
// (Ceres' IterationSummary), handed to observers that may stop the run, and a
// cancellation token checked between Newton iterations.
#pragma once

#include <Eigen/Core>

#include <atomic>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/solve/shell_state.h"

namespace drape {

struct NamedVector {
  std::string name;
  Eigen::Vector3d value = Eigen::Vector3d::Zero();
};

struct StepState {
  int stage = -1;  // index in the scene's stages
  std::string stage_name;
  int step = 0;                   // 1-based over the whole run
  int stage_step = 0;             // 1-based within the stage
  double lambda = 0;              // the stage's load factor
  int iterations = 0;             // Newton iterations of this step
  std::vector<double> residuals;  // ‖R‖/‖R₀‖ after each assembly (R₀: the load the step added)
  double arc_length = 0;          // the step's length along the path
  int negative_pivots = 0;             // of the converged tangent
  std::vector<NamedVector> reactions;  // force each support and gripper exerts [N]
  std::vector<NamedVector> probes;     // probe positions [m]
  ShellState state;                    // the converged configuration
  double elapsed_s = 0;                // since the run started
};

enum class StepDecision { kContinue, kStop };

using StepObserver = std::function<StepDecision(const StepState&)>;

// Set from another thread (or a signal handler) to stop a run between Newton
// iterations; the run keeps every step converged so far.
class CancellationToken {
 public:
  void Cancel() { cancelled_.store(true, std::memory_order_relaxed); }
  bool IsCancelled() const { return cancelled_.load(std::memory_order_relaxed); }

 private:
  std::atomic<bool> cancelled_{false};
};

}  // namespace drape
