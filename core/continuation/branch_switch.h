// Passing a bifurcation on the branch a real part takes (Riks 1984; Wagner &
// Wriggers 1988). When the number of negative pivots rises between two
// converged steps while λ keeps its direction, the primary path beyond is
// unstable: the bifurcation is located by bisecting the step (the count
// changes inside the bracket), the critical mode(s) come from the tangent
// there (shift-invert on its factorisation), and a step along each mode and
// sign (StepAlong) looks for a secondary branch whose tangent has the pivots
// of before, and takes the first found. Where there is none (a subcritical
// bifurcation: every branch is unstable, the real part snaps dynamically)
// the switch fails and says so.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <string>

#include "core/continuation/arc_length_stepper.h"
#include "core/continuation/stability_event.h"

namespace drape {

// A converged point of the path and the step that reached it.
struct PathPoint {
  ShellState state;
  double lambda = 0;
  ContinuationStep step;
};

struct BifurcationSettings {
  // Bisection stops when the bracket is shorter than `locate_fraction` of
  // the stage's path up to it: `path_before` [m] (the stage's path to the
  // crossing step's start) plus the bracket's near end.
  double locate_fraction = 1e-3;
  double path_before = 0;
  int max_bisections = 30;
  // How far along the mode the switch goes [m], rotations weighed by
  // `rotation_length` (StepAlong).
  double amplitude = 0;
  double rotation_length = 0;
  // The scene's imperfection as free-DOF translations (empty: none): the
  // mode's sign that agrees with it is tried first; otherwise +, then −.
  Eigen::VectorXd imperfection;
};

// A crossing step bisected until the count of negative pivots changes within
// the settings' tolerance: `lo` has the count of before, `hi` more; their
// arc lengths from the start.
struct CrossingBracket {
  PathPoint lo, hi;
  double lo_s = 0, hi_s = 0;
  int iterations = 0;
  bool cancelled = false;
};

// `start`: the last accepted point (its count `pivots_before`); `crossing`:
// the converged step beyond it whose count rose; `previous`: the direction
// that arrived at `start` (null at a stage's start). A step of the bisection
// that does not converge ends it with the bracket it has.
CrossingBracket LocateCrossing(ArcLengthStepper& stepper,
                               const PathPoint& start,
                               const PathDirection* previous,
                               const PathPoint& crossing,
                               int pivots_before,
                               const BifurcationSettings& settings,
                               const CancellationToken* cancel);

struct BranchSwitch {
  bool switched = false;
  bool cancelled = false;
  std::string failure;  // why no branch was taken
  // The last point before the bifurcation on the primary path, when the
  // bisection found one beyond the step's start.
  std::optional<PathPoint> bifurcation;
  PathPoint branch;  // the first point on the branch taken
  Branch kind = Branch::kNone;
  double lambda = 0;                    // the located bifurcation (the bracket's middle)
  int negative_pivots_fundamental = 0;  // on the primary path just past it
  int modes = 0;
  // The first point past the bifurcation on the primary path, and the
  // critical mode nearest zero there (free DOFs; empty when none was found):
  // where a part with no stable branch snaps from.
  PathPoint past;
  Eigen::VectorXd mode;
  double max_displacement = 0;  // largest nodal translation from the bifurcation to the branch [m]
  int iterations = 0;           // of the bisection and the switch steps
  double seconds = 0;
};

// `start`: the last accepted point (its count `pivots_before`); `crossing`:
// the converged step beyond it whose count rose; `previous`: the direction
// that arrived at `start` (null at a stage's start).
BranchSwitch SwitchBranch(ArcLengthStepper& stepper,
                          EquilibriumSystem& system,
                          const PathPoint& start,
                          const PathDirection* previous,
                          const PathPoint& crossing,
                          int pivots_before,
                          const BifurcationSettings& settings,
                          const CancellationToken* cancel);

}  // namespace drape
