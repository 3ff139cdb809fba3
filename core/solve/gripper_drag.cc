#include "core/solve/gripper_drag.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <variant>

#include "core/continuation/energy_minimiser.h"
#include "core/fe/bending_slip.h"
#include "core/fe/element_orientation.h"
#include "core/fe/stage_loading.h"
#include "core/linalg/machine_resources.h"

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

// Jumps that find no rest state, in a row, after which a drag stops trying.
constexpr int kSnapsToTry = 2;

std::string DragStageName(const std::string& gripper) {
  return "drag " + gripper;
}

}  // namespace

GripperDrag::GripperDrag(DragBasis basis, const DragSettings& settings)
    : basis_(std::move(basis)), settings_(settings) {
  if (!basis_.model || !basis_.system)
    throw std::invalid_argument("a drag needs a run that completed every stage");
  if (basis_.gripper < 0 || basis_.gripper >= static_cast<int>(basis_.model->grippers.size()))
    throw std::invalid_argument("no such gripper to drag");
  const int node = basis_.model->grippers[basis_.gripper].nodes.front();
  if (!basis_.system->dofs().IsFixed(kDofsPerNode * node))
    throw std::invalid_argument("gripper '" + gripper() +
                                "' was released by the run's stages: only a held gripper can be "
                                "dragged");
}

const std::string& GripperDrag::gripper() const {
  return basis_.model->grippers[basis_.gripper].name;
}

Eigen::VectorXd GripperDrag::HandleRate(const Eigen::Vector3d& motion) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(basis_.model->DofCount());
  for (int node : basis_.model->grippers[basis_.gripper].nodes)
    v.segment<3>(kDofsPerNode * node) = motion;
  return v;
}

double GripperDrag::Predict(const Eigen::Vector3d& motion, DragFrame& frame) {
  EquilibriumSystem& system = *basis_.system;
  const Eigen::VectorXd rate = HandleRate(motion);
  system.Assemble(basis_.state, /*with_tangent=*/true, &rate);
  negative_pivots_ = system.Factorize().negative_pivots;
  ++frame.factorizations;
  Eigen::VectorXd increment =
      rate +
      system.dofs().Expand(system.Solve(-system.dofs().Restrict(system.InternalForceRate())));
  // The gripper goes no further than keeps the layers apart; the rest of
  // its motion waits for the next frame.
  const double t = std::min(1.0, system.StepBound(basis_.state, increment));
  ApplyIncrement(t * increment, basis_.state);
  return t;
}

Eigen::VectorXd GripperDrag::External(const ShellState& state) const {
  const Stage hold{.kind = StageKind::kHold};
  const StageLoading loading(*basis_.model, hold, {}, basis_.weight_factor, basis_.load_factor);
  return loading.External(1.0, state);
}

double GripperDrag::Residual(bool fresh, Eigen::VectorXd& residual, DragFrame& frame) {
  EquilibriumSystem& system = *basis_.system;
  system.Assemble(basis_.state, fresh);
  if (fresh) {
    system.Factorize();
    ++frame.factorizations;
  }
  const Eigen::VectorXd external = External(basis_.state);
  residual = system.Residual(external);
  return residual.norm() / std::max(system.ForceLevel(external), 1e-300);
}

double GripperDrag::Correct(DragFrame& frame) {
  EquilibriumSystem& system = *basis_.system;
  Eigen::VectorXd residual;
  double ratio = Residual(/*fresh=*/false, residual, frame);
  int corrections = 0;
  auto done = [&] {
    return !std::isfinite(ratio) || ratio <= settings_.tolerance ||
           corrections >= settings_.max_corrections ||
           residual.norm() <= settings_.round_off_factor * system.RoundOffLevel(basis_.state);
  };
  // The factorisation is of an earlier state: the predictor's start, or the
  // state before the last correction.
  bool stale = true;
  while (!done()) {
    Eigen::VectorXd correction = system.dofs().Expand(system.Solve(-residual));
    if (const double t = system.StepBound(basis_.state, correction); t < 1) correction *= t;
    const ShellState before = basis_.state;
    ApplyIncrement(correction, basis_.state);
    ++corrections;
    ++frame.corrections;
    const double last = ratio;
    ratio = Residual(/*fresh=*/false, residual, frame);
    if (stale && !(ratio < last)) {
      // A stale tangent made things worse (contact came or went since it
      // was factorised): undo, and correct again on the tangent here.
      basis_.state = before;
      ratio = Residual(/*fresh=*/true, residual, frame);
      stale = false;
      continue;
    }
    stale = true;
    // Slow: the tangent has gone stale. Assemble it here, factorise, go on.
    if (!done() && ratio > settings_.contraction * last) {
      ratio = Residual(/*fresh=*/true, residual, frame);
      stale = false;
    }
  }
  return ratio;
}

bool GripperDrag::Snap(const Eigen::Vector3d& motion, DragFrame& frame) {
  const ShellState kept = basis_.state;
  const double reached = Predict(motion, frame);
  const StabilizationOff springs(basis_.contact);
  MinimiserSettings settings;
  settings.newton.tolerance = settings_.tolerance;
  settings.newton.max_iterations = settings_.snap_iterations;
  const MinimiserOutcome out = MinimiseEnergy(
      *basis_.system,
      [&](const ShellState& s) { return External(s); },
      settings,
      basis_.state,
      nullptr);
  frame.corrections += out.newton.iterations;
  if (out.newton.status != NewtonOutcome::Status::kConverged) {
    basis_.state = kept;
    frame.not_followed = "the fabric cannot follow the handle and its jump found no rest state: " +
                         out.newton.reason;
    return false;
  }
  offset_ += reached * motion;
  // A prediction already at rest (a sub-step that failed only on its
  // corrections' budget) is no jump.
  frame.snapped = out.steps > 0;
  frame.energy_released = frame.snapped ? -out.energy_change : 0.0;
  frame.residual_ratio = out.newton.residuals.empty() ? 0.0 : out.newton.residuals.back();
  return true;
}

DragFrame GripperDrag::MoveTo(const Eigen::Vector3d& offset) {
  const auto start = Clock::now();
  UseAssemblyThreads(settings_.threads);
  DragFrame frame;
  frame.frame = ++frames_;
  const Eigen::Vector3d motion = offset - offset_;
  double taken = 0, share = 1;
  bool moved = false, stuck = false;
  // The motion in sub-steps: whole if it can, else halves, quarters, …
  // (growing back after a success), until it is all taken or the sub-steps
  // run out; then the gripper lags the handle and the next frame catches up.
  auto out_of_time = [&] {
    return moved &&
           std::chrono::duration<double>(Clock::now() - start).count() > settings_.budget_seconds;
  };
  for (int substep = 0; substep < settings_.max_substeps && taken < 1 && !out_of_time();
       ++substep) {
    const double part = std::min(share, 1 - taken);
    const ShellState kept = basis_.state;
    const double reached = Predict(part * motion, frame);
    if (negative_pivots_ > 0) {
      // Where the sub-step starts the fabric is past a limit (the last one
      // followed a symmetric path beyond it): it cannot rest there.
      basis_.state = kept;
      stuck = true;
      break;
    }
    const double ratio = Correct(frame);
    // A frame never shows a state no part can be in.
    if (IsFinite(basis_.state) && ratio <= settings_.worst_ratio &&
        !FindInvertedElement(*basis_.model, basis_.state)) {
      taken += reached * part;
      offset_ += reached * part * motion;
      frame.residual_ratio = ratio;
      moved = true;
      if (reached < 1) break;  // the layers are in the way
      share = std::min(1.0, 2 * share);
      continue;
    }
    basis_.state = kept;
    share = part / 2;  // of what failed: after a success `share` may exceed it
    // Unable to take even the smallest share, the fabric cannot follow.
    stuck = share < std::ldexp(1.0, -settings_.max_halvings);
    if (stuck) break;
  }
  // A jump that found no rest state is not tried again until the fabric has
  // followed the handle once more (each costs up to snap_iterations).
  if (moved && !stuck) failed_snaps_ = 0;
  if (stuck && settings_.snap_iterations > 0 && failed_snaps_ < kSnapsToTry) {
    if (Snap((1 - taken) * motion, frame)) {
      taken = 1;
      moved = true;
      failed_snaps_ = 0;
    } else {
      ++failed_snaps_;
    }
  }
  if (!moved) {
    Eigen::VectorXd residual;
    frame.residual_ratio = Residual(/*fresh=*/true, residual, frame);
  }
  if (basis_.contact) basis_.contact->Commit(basis_.state);
  CommitBendingSlip(*basis_.model, basis_.state);
  frame.offset = offset_;
  frame.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return frame;
}

Scene DraggedScene(const Scene& scene, const std::string& gripper, const Eigen::Vector3d& by) {
  Scene dragged = scene;
  const std::string name = DragStageName(gripper);
  if (!dragged.stages.empty()) {
    Stage& last = dragged.stages.back();
    if (last.name == name && last.kind == StageKind::kMove && last.release.empty() &&
        last.moves.size() == 1 && last.moves[0].gripper == gripper)
      if (auto* line = std::get_if<LinePath>(&last.moves[0].path)) {
        for (int k = 0; k < 3; ++k) line->by[k] += by[k];
        return dragged;
      }
  }
  Stage stage;
  stage.name = name;
  stage.kind = StageKind::kMove;
  Move move;
  move.gripper = gripper;
  move.path = LinePath{{by.x(), by.y(), by.z()}};
  stage.moves.push_back(move);
  dragged.stages.push_back(stage);
  return dragged;
}

}  // namespace drape
