#include "ui/render/animation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/mechanics/director.h"
#include "ui/render/video_encoder.h"

namespace drape {

ShellState InterpolatedState(const std::vector<const ShellState*>& states, double s) {
  const size_t last = states.size() - 1;
  const size_t a = std::min(static_cast<size_t>(std::floor(std::max(s, 0.0))), last);
  const size_t b = std::min(a + 1, last);
  const double w = std::clamp(s - static_cast<double>(a), 0.0, 1.0);
  const ShellState& sa = *states[a];
  const ShellState& sb = *states[b];
  ShellState out;
  out.positions = (1 - w) * sa.positions + w * sb.positions;
  out.rotations.resize(sa.rotations.size());
  for (size_t n = 0; n < sa.rotations.size(); ++n) {
    Eigen::Vector3d t = (1 - w) * sa.rotations[n].col(2) + w * sb.rotations[n].col(2);
    if (t.norm() < 1e-12) t = sb.rotations[n].col(2);
    out.rotations[n] = RotationFromDirector(t.normalized());
  }
  out.obstacles = sa.obstacles;
  for (size_t o = 0; o < out.obstacles.size() && o < sb.obstacles.size(); ++o) {
    const Eigen::Quaterniond qa(sa.obstacles[o].rotation), qb(sb.obstacles[o].rotation);
    out.obstacles[o].rotation = qa.slerp(w, qb).toRotationMatrix();
    out.obstacles[o].translation =
        (1 - w) * sa.obstacles[o].translation + w * sb.obstacles[o].translation;
  }
  return out;
}

int WriteAnimation(const AnimationInput& input,
                   const AnimationOptions& options,
                   const std::filesystem::path& output,
                   const AnimationProgress& progress,
                   const std::atomic<bool>* cancel) {
  if (!(options.fps > 0 && options.fps <= 120))
    throw std::invalid_argument("--fps: must lie in (0, 120], got " + std::to_string(options.fps));
  if (options.duration < 0) throw std::invalid_argument("--duration: must be positive");
  if (input.states.size() < 2)
    throw std::invalid_argument("an animation needs a run: at least one converged step");
  if (options.view.field && FromContact(*options.view.field))
    throw std::invalid_argument(
        "--field pressure and slip: contact pressure and friction are stored for the last step "
        "only; render that step");
  const Scene& scene = *input.scene;
  const ShellModel& model = *input.model;
  std::optional<std::array<double, 2>> range;
  if (options.view.field) range = FieldRange(*options.view.field, model, input.states);
  FrameRenderer renderer(scene, model, options.view, RunBounds(scene, input.states), range);
  const size_t states = input.states.size();
  const int frames =
      options.duration > 0
          ? std::max(2, static_cast<int>(std::lround(options.duration * options.fps)))
          : static_cast<int>(states);
  auto sink = OpenFrameSink(output, options.view.width, options.view.height, options.fps);
  for (int done = 0; done < frames; ++done) {
    if (cancel && cancel->load()) {
      sink->Abort();
      return -1;
    }
    // Step time: frame `done` shows state s (interpolated with a duration).
    const double s = options.duration > 0 ? static_cast<double>(done) / (frames - 1) *
                                                static_cast<double>(states - 1)
                                          : static_cast<double>(done);
    const size_t near = std::min(static_cast<size_t>(std::lround(s)), states - 1);
    const ShellState state =
        options.duration > 0 ? InterpolatedState(input.states, s) : *input.states[near];
    Frame f;
    f.state = &state;
    f.step = static_cast<int>(near);
    f.stage_name = input.stage_names[near];
    if (near < input.stages.size()) f.stage = input.stages[near];
    f.lambda = input.lambdas[near];
    renderer.Show(f);
    sink->Add(renderer.CaptureRgb());
    if (progress) progress(done + 1, frames);
  }
  sink->Finish();
  return frames;
}

}  // namespace drape
