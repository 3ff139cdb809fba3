#include "core/continuation/energy_minimiser.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "core/linalg/critical_modes.h"

namespace drape {
namespace {

// A step whose corrector needs at most this many corrections lets μ fall,
// one that needs more than kSlowStep makes it rise.
constexpr int kQuickStep = 5;
constexpr int kSlowStep = 8;
constexpr int kStepIterations = 8;  // corrections a step may take
// After a refused step μ falls again only after this many quick steps in a
// row: halving straight back to where the step failed refuses every other.
constexpr int kQuickStepsToFall = 2;
constexpr double kDragFactor = 2;
// A step's corrector converges when its residual is this fraction of the
// true residual it started from: the next step goes on from there.
constexpr double kStepTolerance = 1e-3;

// D = |diag K| over the free DOFs, floored (per kind: translations and
// rotations) so that a DOF the tangent barely sees still feels the drag.
// On the rotations too: a state far from equilibrium can be unstable in its
// rotations alone, with every translation held.
Eigen::VectorXd DragScale(const EquilibriumSystem& system) {
  const DofMap& dofs = system.dofs();
  Eigen::VectorXd d = system.TangentDiagonal().cwiseAbs();
  double largest[2] = {0, 0};
  for (int dof = 0; dof < dofs.DofCount(); ++dof)
    if (const int f = dofs.Free(dof); f >= 0) {
      double& l = largest[dof % kDofsPerNode < 3 ? 0 : 1];
      l = std::max(l, d(f));
    }
  for (int dof = 0; dof < dofs.DofCount(); ++dof)
    if (const int f = dofs.Free(dof); f >= 0)
      d(f) = std::max(d(f), 1e-12 * std::max(largest[dof % kDofsPerNode < 3 ? 0 : 1], 1e-300));
  return d;
}

// Where `to` is from `from` over the free DOFs: the translations' difference,
// and each node's rotation from one to the other (the rotation vector of
// Λ_to Λ_fromᵀ) on `to`'s tangent basis.
Eigen::VectorXd Offset(const DofMap& dofs, const ShellState& from, const ShellState& to) {
  Eigen::VectorXd offset = Eigen::VectorXd::Zero(dofs.FreeCount());
  for (int node = 0; node < from.positions.rows(); ++node) {
    for (int a = 0; a < 3; ++a)
      if (const int f = dofs.Free(kDofsPerNode * node + a); f >= 0)
        offset(f) = to.positions(node, a) - from.positions(node, a);
    const Eigen::AngleAxisd turn(
        Eigen::Matrix3d(to.rotations[node] * from.rotations[node].transpose()));
    const Eigen::Vector3d w = turn.angle() * turn.axis();
    for (int a = 0; a < 2; ++a)
      if (const int f = dofs.Free(kDofsPerNode * node + 3 + a); f >= 0)
        offset(f) = w.dot(to.rotations[node].col(a));
  }
  return offset;
}

struct ProximalStepResult {
  bool accepted = false;
  NewtonOutcome newton;
};

// One step of the iteration from `state` (moved to q₊ when accepted) with
// drag `mu`: the corrector on R(q) + μD(x − xₙ) and K + μD.
ProximalStepResult ProximalStep(EquilibriumSystem& system,
                                const ExternalForce& external,
                                const NewtonSettings& newton,
                                const Eigen::VectorXd& drag_scale,
                                double mu,
                                ShellState& state,
                                const CancellationToken* cancel) {
  const ShellState start = state;
  ProximalStepResult out;
  double reference = 0;
  CorrectorRequest request;
  request.settings = newton;
  request.settings.tolerance = kStepTolerance;
  request.settings.relative_to_force_level = false;
  request.settings.max_iterations = kStepIterations;
  // Only the iteration limit ends a step early: with much drag its
  // corrections are small by design.
  request.settings.stall_correction = 0;
  request.assemble = [&](const ShellState& s, int iteration) {
    system.Assemble(s, /*with_tangent=*/true);
    Eigen::VectorXd r = system.Residual(external(s));
    if (iteration == 0) reference = r.norm();
    // The floor of K's own round-off, not of K + μD's, whose shift would
    // make any residual look like round-off.
    const double round_off = system.RoundOffLevel(s);
    if (mu > 0) {
      r += mu * drag_scale.cwiseProduct(Offset(system.dofs(), start, s));
      system.ShiftTangentDiagonal(mu * drag_scale);
    }
    return CorrectorRequest::Residual{std::move(r), reference, round_off};
  };
  request.correct = [&](const Eigen::VectorXd& r, ShellState& s) {
    return ApplyNewtonCorrection(system, r, s);
  };
  out.newton = RunCorrector(system, state, request, cancel);
  // A local minimum of the step's problem: converged where K + μD is definite.
  out.accepted =
      out.newton.status == NewtonOutcome::Status::kConverged && out.newton.negative_pivots == 0;
  if (!out.accepted) state = start;
  return out;
}

// Leaves a saddle along its lowest mode: a step of `length` [m] (largest
// translation) along it, from the tangent factorised at `state`.
bool LeaveSaddle(EquilibriumSystem& system, double length, ShellState& state) {
  std::vector<CriticalMode> modes;
  try {
    modes = CriticalModes(LastFactorizedTangent(system), 1);
  } catch (const std::exception&) {
    return false;
  }
  if (modes.empty()) return false;
  const Eigen::VectorXd increment = system.dofs().Expand(modes[0].shape);
  const double largest = MaxTranslation(increment);
  if (!(largest > 0)) return false;
  const Eigen::VectorXd step = increment * (length / largest);
  ApplyIncrement(step * system.StepBound(state, step), state);
  return true;
}

// Whether `state` is at rest: ‖R‖ within the tolerance (or the round-off
// floor), judged as the corrector judges a fixed-λ step. Leaves the system
// assembled there.
bool AtRest(EquilibriumSystem& system,
            const ExternalForce& external,
            const NewtonSettings& newton,
            const ShellState& state,
            MinimiserOutcome& out) {
  system.Assemble(state, /*with_tangent=*/true);
  const Eigen::VectorXd f = external(state);
  const double norm = system.Residual(f).norm();
  const double ratio = norm / std::max(system.ForceLevel(f), 1e-300);
  out.newton.residuals.push_back(ratio);
  if (ratio <= newton.tolerance) {
    out.newton.convergence = Convergence::kTolerance;
    return true;
  }
  if (norm <= newton.round_off_factor * system.RoundOffLevel(state)) {
    out.newton.convergence = Convergence::kRoundOff;
    return true;
  }
  return false;
}

}  // namespace

MinimiserOutcome MinimiseEnergy(EquilibriumSystem& system,
                                const ExternalForce& external,
                                const MinimiserSettings& settings,
                                ShellState& state,
                                const CancellationToken* cancel) {
  MinimiserOutcome out;
  NewtonOutcome& result = out.newton;
  const NewtonSettings& newton = settings.newton;
  double mu = settings.initial_drag;
  int quick_in_a_row = kQuickStepsToFall;
  std::string last_refusal;
  int restarts = 0;
  Eigen::VectorXd drag_scale;
  const double energy_before = system.PotentialEnergy(state, external(state));
  const Eigen::MatrixX3d start = state.positions;
  const double reach = settings.max_travel * system.model().characteristic_length;
  auto finish = [&](NewtonOutcome::Status status, std::string reason) {
    result.status = status;
    result.reason = std::move(reason);
    out.energy_change = system.PotentialEnergy(state, external(state)) - energy_before;
    return out;
  };
  for (;;) {
    if (const IterationVerdict v = CheckBeforeAssembly(state, cancel); v.done)
      return finish(v.status, v.reason);
    if (AtRest(system, external, newton, state, out)) {
      result.negative_pivots = system.Factorize().negative_pivots;
      if (result.negative_pivots == 0) return finish(NewtonOutcome::Status::kConverged, "");
      // An equilibrium, but a saddle: the energy falls along its unstable
      // modes. A push that falls back onto the same saddle is doubled.
      if (restarts >= settings.max_restarts ||
          !LeaveSaddle(system,
                       std::ldexp(1e-3, restarts++) * system.model().characteristic_length,
                       state))
        return finish(NewtonOutcome::Status::kDiverged,
                      "the minimiser ends at an unstable equilibrium (" +
                          std::to_string(result.negative_pivots) + " negative pivots)");
      continue;
    }
    if (drag_scale.size() == 0) drag_scale = DragScale(system);
    if (result.iterations >= newton.max_iterations)
      return finish(NewtonOutcome::Status::kIterationLimit,
                    "no rest state in " + std::to_string(result.iterations) + " iterations (" +
                        std::to_string(out.steps) +
                        " steps; ‖R‖/‖R₀‖ = " + Number(result.residuals.back()) + ")");
    if (mu > settings.largest_drag)
      return finish(NewtonOutcome::Status::kDiverged,
                    "no step converged however much drag held it (μ up to " +
                        Number(settings.largest_drag) + "; the last: " + last_refusal + ")");
    const ProximalStepResult step =
        ProximalStep(system, external, newton, drag_scale, mu, state, cancel);
    result.iterations += step.newton.iterations;
    if (step.newton.status == NewtonOutcome::Status::kCancelled)
      return finish(step.newton.status, step.newton.reason);
    if (!step.accepted) {
      ++out.refused_steps;
      last_refusal = step.newton.reason.empty() ? "negative pivots" : step.newton.reason;
      mu = kDragFactor * std::max(mu, settings.smallest_drag);
      quick_in_a_row = 0;
      continue;
    }
    ++out.steps;
    if (const double travel = (state.positions - start).rowwise().norm().maxCoeff();
        travel > reach) {
      out.unheld = true;
      return finish(NewtonOutcome::Status::kDiverged,
                    "nothing holds the part: it moves on without coming to rest (" +
                        Number(travel) + " m from where the jump began, " +
                        Number(travel / system.model().characteristic_length) + " times its size)");
    }
    if (step.newton.iterations > kSlowStep) {
      mu = kDragFactor * std::max(mu, settings.smallest_drag);
      quick_in_a_row = 0;
    } else if (step.newton.iterations <= kQuickStep && ++quick_in_a_row >= kQuickStepsToFall) {
      mu = mu / kDragFactor < settings.smallest_drag ? 0.0 : mu / kDragFactor;
    }
  }
}

}  // namespace drape
