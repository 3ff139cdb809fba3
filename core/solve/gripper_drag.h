// A gripper dragged by hand after a run: the fabric re-equilibrates
// quasi-statically, frame by frame, from the run's last equilibrium — a
// preview of where the part goes, fast enough to follow a mouse.
//
// Each frame predicts the fabric's motion from the handle's: the linear
// response K_ff Δq_f = −K_fp Δu_p to the gripper's nodes moving by Δu_p, on
// the tangent at the frame's start (assembled and factorised once). Moving
// the held nodes alone would kink the elements next to them, a state Newton
// recovers from slowly if at all. Then a few Newton corrections on that kept
// factorisation (modified Newton); the tangent is assembled and factorised
// again only when a correction reduces the residual by less than
// `DragSettings::contraction`, and a correction on a stale factorisation
// that does not reduce it at all is undone and taken again on a fresh one
// (where a node has come into contact, the old tangent points elsewhere:
// kept, such steps left the strip fold's end stuck at 1.86 cm of a 2 cm
// lift). A frame whose corrections leave more than
// `worst_ratio` is undone and taken in smaller sub-steps; what a frame's
// sub-steps cannot take waits for the next: the gripper lags behind the
// handle and catches up.
//
// A frame is not a converged step: it reports its residual ratio, and a
// release solves the edited scene from the start (`DraggedScene`). Where the
// fabric cannot follow the handle (it has passed a limit: a compressive drag
// that wrinkles), the frame takes the jump to the next stable rest state
// (`DragSettings::snap_iterations`) and says so (`DragFrame::snapped`).
//
//   ShellSolver solver(scene, options);
//   solver.Solve({});
//   GripperDrag drag(solver.BasisForDrag("corner"), DragSettings{});
//   for (int f = 1; f <= 40; ++f) drag.MoveTo(f / 40.0 * by);
#pragma once

#include <Eigen/Core>

#include <string>

#include "core/contact/node_contact.h"
#include "core/continuation/equilibrium_system.h"
#include "core/continuation/newton_corrector.h"
#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/model/scene.h"

namespace drape {

// What a drag goes on from: the run's last equilibrium and the system that
// holds it (ShellSolver::DragBasis). The model, system and contact belong to
// the solver, which must outlive the drag.
struct DragBasis {
  const ShellModel* model = nullptr;
  EquilibriumSystem* system = nullptr;  // on the last stage's DOFs
  NodeContact* contact = nullptr;       // null without obstacles
  ShellState state;                     // the last converged state
  int gripper = -1;                     // in model->grippers
  double weight_factor = 0;             // reached by the run's stages
  double load_factor = 0;
};

struct DragSettings {
  // A frame stops correcting at ‖R‖ ≤ tolerance × the force level (loads
  // and reactions), or after `max_corrections` linear solves. A frame is a
  // picture: 1e-4 of the force level is far below what it shows, and the
  // release is solved to the scene's own tolerance. Measured at 20 × 20:
  // the scene's 1e-5 made the diagonal fold's frames 3.5 times as slow.
  double tolerance = 1e-4;
  int max_corrections = 8;
  // A correction that leaves more than this fraction of the residual makes
  // the next one use a freshly factorised tangent. Newton on a current
  // tangent contracts quadratically; a stale one linearly at best.
  double contraction = 0.25;
  // A sub-step ending above this residual ratio is undone and retried with
  // half the motion, down to 2^-max_halvings of it; a frame takes at most
  // `max_substeps` sub-steps (what is left waits for the next frame).
  double worst_ratio = 1e-2;
  int max_halvings = 4;
  int max_substeps = 8;
  // A frame that has moved takes no further sub-step once it has run this
  // long [s]: the rest of the motion waits for the next frame, and the view
  // keeps answering the hand. Measured on the diagonal fold: laying the
  // corner back onto the sheet took 0.77 s in one frame of eight sub-steps.
  double budget_seconds = 0.05;
  // Assembly threads for the frames (0: as the caller's thread has them).
  // Measured at 20 × 20: one thread is as fast as two, and far faster when
  // the other core is busy (a preview, a build), where two OpenMP threads
  // wait on each other.
  int threads = 0;
  // A residual this many times its round-off level cannot fall further: the
  // corrector's own floor (NewtonSettings::round_off_factor).
  double round_off_factor = NewtonSettings{}.round_off_factor;
  // Where the fabric cannot follow the handle quasi-statically (a sub-step
  // of the smallest share fails, or the tangent where the frame starts has
  // negative pivots: the part is past a limit), it snaps: the gripper goes
  // to the handle and the energy minimiser (energy_minimiser.h) takes the
  // fabric to a stable rest state, within this many Newton iterations
  // (0: never; the gripper then lags, as before). After two jumps in a row
  // that find none, the drag stops trying until the fabric follows again.
  int snap_iterations = 400;
};

struct DragFrame {
  int frame = 0;                                     // 1, 2, … since the drag began
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // of the gripper from the start [m]
  double seconds = 0;                                // the frame's own wall time
  double residual_ratio = 0;                         // ‖R‖ / force level at its end
  int corrections = 0;                               // linear solves
  int factorizations = 0;
  // The fabric snapped in this frame: it jumped to a stable rest state with
  // the gripper at the handle, releasing this much energy [J].
  bool snapped = false;
  double energy_released = 0;
  // Why the fabric could not follow the handle here, when a jump was tried
  // and found no rest state ("" otherwise): the gripper stays behind.
  std::string not_followed;
};

class GripperDrag {
 public:
  // Throws std::invalid_argument when the basis holds no system (the run
  // did not complete) or the gripper is not held.
  GripperDrag(DragBasis basis, const DragSettings& settings);

  // Moves the gripper to `offset` from where the run left it and brings the
  // fabric towards equilibrium there.
  DragFrame MoveTo(const Eigen::Vector3d& offset);

  const ShellState& state() const { return basis_.state; }
  const Eigen::Vector3d& offset() const { return offset_; }
  const std::string& gripper() const;

 private:
  // The prescribed DOFs' change for the gripper moving by `motion` (full).
  Eigen::VectorXd HandleRate(const Eigen::Vector3d& motion) const;
  // Moves the gripper and the fabric's linear response to it (factorising
  // the tangent at the state); returns the fraction of `motion` taken.
  double Predict(const Eigen::Vector3d& motion, DragFrame& frame);
  // Assembles at the state (with the tangent, factorised, when `fresh`) and
  // returns ‖R‖ / force level; `residual` gets R over the free DOFs.
  double Residual(bool fresh, Eigen::VectorXd& residual, DragFrame& frame);
  // Newton corrections on the kept factorisation; returns the last ratio.
  double Correct(DragFrame& frame);
  // The jump to a stable rest state with the gripper moved by `motion`;
  // false (the state kept) when the minimiser finds none.
  bool Snap(const Eigen::Vector3d& motion, DragFrame& frame);
  // F_ext: the weight and loads the run's stages reached.
  Eigen::VectorXd External(const ShellState& state) const;

  DragBasis basis_;
  DragSettings settings_;
  Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();
  int frames_ = 0;
  int negative_pivots_ = 0;  // of the tangent the last prediction factorised
  int failed_snaps_ = 0;     // jumps in a row that found no rest state
};

// The scene a drag leaves: `scene` with the gripper carried by `by` after
// its stages — the last stage's line extended when that stage is a drag of
// the same gripper ("drag <gripper>", one line move), else a new such stage.
// Solving it from the start is the release's full solve.
Scene DraggedScene(const Scene& scene, const std::string& gripper, const Eigen::Vector3d& by);

}  // namespace drape
