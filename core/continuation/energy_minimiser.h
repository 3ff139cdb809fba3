// The jump of a part that snaps: from a state that is no longer a stable
// equilibrium at load level λ, the stable equilibrium it falls into, found by
// minimising the total potential energy at that λ.
//
// A proximal-point iteration (implicit gradient flow, or pseudo-transient
// continuation solved exactly per step): each step finds
//   q₊ = argmin Π(q) + ½ μ (x − xₙ)ᵀ D (x − xₙ),
// D = |diag K| (so μ is dimensionless; x − xₙ: the translations' difference
// and each node's rotation from Λₙ, on its tangent basis), by the Newton
// corrector that also serves the path (newton_corrector.h) on the residual
// R(q) + μD(x − xₙ) and the tangent K + μD. The term is a viscous drag on
// the nodes: it makes the tangent definite where K is not (past a limit
// point, on a saddle), and since each step is solved to equilibrium, not
// linearised, the part follows the curved valleys of large rotations that a
// linear step leaves. A step is accepted when its corrector converges to a
// definite K + μD with every element right side out (a local minimum of the
// step's problem, so Π fell); otherwise μ rises and the step is retried. μ
// falls while steps converge quickly, so that near the rest state the steps
// are Newton's. What it reaches has ‖R‖ within the tolerance and 0 negative
// pivots of K itself, or it says why not.
#pragma once

#include <string>

#include "core/continuation/newton_corrector.h"

namespace drape {

struct MinimiserSettings {
  // ‖R‖ against the force level (relative_to_force_level is set), the
  // round-off floor and the iteration limit (corrections of every step,
  // accepted or not) as the corrector judges them.
  NewtonSettings newton;
  double initial_drag = 1.0;    // μ of the first step
  double smallest_drag = 1e-9;  // below it the step is Newton's own (μ = 0)
  double largest_drag = 1e12;   // beyond it no step is found: the minimiser gives up
  // A saddle reached (‖R‖ converged, some pivots negative) is left along its
  // lowest mode this many times before the minimiser gives up, each push
  // twice the last (the first 1e-3 of the part's size).
  int max_restarts = 5;
  // A node this many times the part's size (its diagonal) from where it
  // started ends the search: nothing holds the part (a sheet sliding down a
  // table steeper than its friction allows). Left to go on, such a part
  // travels until its coordinates' round-off exceeds the tolerance and it
  // would pass for resting.
  double max_travel = 10.0;
};

struct MinimiserOutcome {
  // Converged: ‖R‖ met the tolerance (or the floor) at a state whose tangent
  // has 0 negative pivots. Iterations: every correction of every step.
  NewtonOutcome newton;
  int steps = 0;          // accepted proximal steps
  int refused_steps = 0;  // steps retried with more drag
  // Π at the end less Π at the start (EquilibriumSystem::PotentialEnergy)
  // [J]: what the jump released, negated.
  double energy_change = 0;
  // It ended because the part travelled beyond max_travel: nothing holds it.
  bool unheld = false;
};

// Minimises the total potential energy at a fixed load from `state` (updated
// in place): the loads `external`, the prescribed DOFs as the system's DOF map
// holds them.
MinimiserOutcome MinimiseEnergy(EquilibriumSystem& system,
                                const ExternalForce& external,
                                const MinimiserSettings& settings,
                                ShellState& state,
                                const CancellationToken* cancel);

}  // namespace drape
