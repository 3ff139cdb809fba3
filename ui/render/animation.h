// A run's animation written frame by frame: one frame per state, or frames
// interpolated in time to a duration. The same code serves `drape animate`
// and the workbench's export, with progress reported and cancellation
// honoured between frames (a cancelled movie leaves no file).
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/model/scene.h"
#include "ui/render/frame_renderer.h"

namespace drape {

struct AnimationInput {
  const Scene* scene = nullptr;
  const ShellModel* model = nullptr;
  std::vector<const ShellState*> states;  // [0] the reference
  std::vector<std::string> stage_names;   // per state
  std::vector<double> lambdas;            // per state
  std::vector<int> stages;                // per state (−1: the reference); may be empty
};

struct AnimationOptions {
  RenderOptions view;
  double fps = 25;
  double duration = 0;  // [s]; 0: one frame per state
};

// Frames done and in all, after each frame.
using AnimationProgress = std::function<void(int done, int frames)>;

// Writes the animation to `output` (OpenFrameSink decides the kind by the
// name). Returns the frames written; on `cancel` it stops, removes a partial
// movie and returns −1. Throws std::invalid_argument for bad options or a
// field that cannot be animated (contact pressure), std::runtime_error when
// the output cannot be written.
int WriteAnimation(const AnimationInput& input,
                   const AnimationOptions& options,
                   const std::filesystem::path& output,
                   const AnimationProgress& progress = {},
                   const std::atomic<bool>* cancel = nullptr);

// The state at "step time" s ∈ [0, n − 1] between recorded states:
// positions and obstacle translations interpolated linearly, directors
// normalised, obstacle rotations by quaternion slerp.
ShellState InterpolatedState(const std::vector<const ShellState*>& states, double s);

}  // namespace drape
