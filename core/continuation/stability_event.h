// A change of the tangent's inertia along a path: limit points, bifurcations
// and the branch taken.
#pragma once

namespace drape {

// What the number of negative pivots changing between two converged steps
// means: a limit point (λ turns along the path: snap-through, snap-back) or a
// bifurcation (the count changes while λ keeps its direction). A snap is the
// jump a part makes at either when no stable path goes on from it (under
// solver.branching: stable): at the same λ, to the rest state the energy
// minimiser finds.
enum class StabilityKind { kLimit, kBifurcation, kSnap };
// Which way the path went on from a bifurcation.
enum class Branch {
  kFundamental,  // on along the primary path (solver.branching: fundamental)
  kStable,       // switched to a secondary branch with the pivots of before
  kNone,         // not a bifurcation (a limit point), or no branch was found
};
// What a part snapped at: a limit point, a bifurcation with no stable
// branch, or a stage's start where it cannot carry the first increment (a
// mechanism: a sheet held at two corners swings about the line through them).
// kSliding: a part held only by contact whose every node in contact slides
// (its stabilisation springs carry what friction cannot), or that would not
// settle at a stage's end. kRelease: a hold stage that releases grippers
// from a state the part cannot rest in without them. kStalled: a path whose
// steps cut back until they gave up, past its start (a fold of the path too
// sharp to step round, or one the stability test did not see).
enum class SnapTrigger { kLimit, kBifurcation, kStart, kSliding, kRelease, kStalled };
const char* ToString(StabilityKind kind);  // "limit", "bifurcation", "snap"
const char* ToString(Branch branch);       // "fundamental", "stable", "none"
// "limit", "bifurcation", "start", "sliding", "release", "stalled"
const char* ToString(SnapTrigger trigger);

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
  // Snaps: what the path met, the energy the jump released [J], its largest
  // nodal translation [m] (in mode_max_displacement), and what the minimiser
  // cost (in switch_iterations, switch_s).
  SnapTrigger trigger = SnapTrigger::kLimit;
  double energy_released = 0;
};

}  // namespace drape
