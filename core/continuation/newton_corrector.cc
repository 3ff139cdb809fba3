#include "core/continuation/newton_corrector.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/fe/element_orientation.h"

namespace drape {
namespace {

// Why a converged iterate is still no equilibrium to accept ("": none): an
// element turned inside out, or what the caller refuses.
std::string Refusal(const EquilibriumSystem& system,
                    const ShellState& state,
                    const CorrectorRequest& request) {
  if (const auto inverted = FindInvertedElement(system.model(), state))
    return Describe(*inverted, system.model());
  return request.refuse ? request.refuse(state) : "";
}

}  // namespace

const char* ToString(Convergence c) {
  switch (c) {
    case Convergence::kNotYet:
      return "not_converged";
    case Convergence::kTolerance:
      return "tolerance";
    case Convergence::kRoundOff:
      return "round_off";
    case Convergence::kStalled:
      return "stalled";
  }
  return "?";
}

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string StallReason(double ratio, double tolerance) {
  return "Newton stalled at ‖R‖/‖R₀‖ = " + Number(ratio) + " (tolerance " + Number(tolerance) +
         "): the corrections stopped while the residual stays above the tolerance and the "
         "round-off floor";
}

IterationVerdict CheckBeforeAssembly(const ShellState& state, const CancellationToken* cancel) {
  IterationVerdict v;
  if (cancel) cancel->WaitWhilePaused();  // a pause holds the run here
  if (cancel && cancel->IsCancelled()) {
    v = {true, NewtonOutcome::Status::kCancelled, "cancelled"};
  } else if (!IsFinite(state)) {
    v = {true, NewtonOutcome::Status::kDiverged, "the state is not finite"};
  }
  return v;
}

IterationVerdict JudgeIteration(const NewtonSettings& settings,
                                double norm,
                                double reference,
                                double round_off,
                                double last_correction,
                                int corrections,
                                std::vector<double>& ratios,
                                Convergence& convergence) {
  const double ratio = reference > 0 ? norm / reference : norm;
  ratios.push_back(ratio);
  if (!std::isfinite(norm))
    return {true, NewtonOutcome::Status::kDiverged, "the residual is not finite"};
  convergence = settings.Judge(ratios, norm, round_off, last_correction);
  if (convergence == Convergence::kTolerance || convergence == Convergence::kRoundOff)
    return {true, NewtonOutcome::Status::kConverged, ""};
  if (convergence == Convergence::kStalled)
    return {true, NewtonOutcome::Status::kStalled, StallReason(ratio, settings.tolerance)};
  if (ratio > settings.divergence_ratio)
    return {
        true, NewtonOutcome::Status::kDiverged, "the residual grew by a factor " + Number(ratio)};
  if (corrections >= settings.max_iterations)
    return {true,
            NewtonOutcome::Status::kIterationLimit,
            "no convergence in " + std::to_string(corrections) +
                " iterations (‖R‖/‖R₀‖ = " + Number(ratio) + ")"};
  return {};
}

NewtonOutcome RunCorrector(EquilibriumSystem& system,
                           ShellState& state,
                           const CorrectorRequest& request,
                           const CancellationToken* cancel) {
  NewtonOutcome out;
  double last_correction = INFINITY;
  for (int it = 0;; ++it) {
    if (const IterationVerdict v = CheckBeforeAssembly(state, cancel); v.done) {
      out.status = v.status;
      out.reason = v.reason;
      return out;
    }
    const CorrectorRequest::Residual r = request.assemble(state, it);
    IterationVerdict v =
        JudgeIteration(request.settings,
                       r.free.norm(),
                       r.reference,
                       r.round_off >= 0 ? r.round_off : system.RoundOffLevel(state),
                       last_correction,
                       it,
                       out.residuals,
                       out.convergence);
    if (v.done && v.status == NewtonOutcome::Status::kConverged)
      if (std::string why = Refusal(system, state, request); !why.empty())
        v = {true, NewtonOutcome::Status::kDiverged, std::move(why)};
    if (v.done) {
      out.status = v.status;
      out.reason = v.reason;
      // The stability indicator belongs to the converged state, whose tangent
      // was just assembled.
      if (v.status == NewtonOutcome::Status::kConverged)
        out.negative_pivots = system.Factorize().negative_pivots;
      return out;
    }
    if (!request.correct_factorizes) system.Factorize();
    last_correction = request.correct(r.free, state);
    if (last_correction < 0) {
      out.status = NewtonOutcome::Status::kDiverged;
      out.reason = "no correction found";
      return out;
    }
    ++out.iterations;
  }
}

double ApplyNewtonCorrection(EquilibriumSystem& system,
                             const Eigen::VectorXd& residual,
                             ShellState& state) {
  Eigen::VectorXd correction = system.dofs().Expand(system.Solve(-residual));
  // Never through the fabric itself: the part of the step that keeps its
  // layers apart and the fabric out of the obstacles (self-contact, barrier
  // contact; the whole step otherwise).
  if (const double t = system.StepBound(state, correction); t < 1) correction *= t;
  ApplyIncrement(correction, state);
  return MaxTranslation(correction);
}

NewtonOutcome SolveEquilibrium(EquilibriumSystem& system,
                               const ExternalForce& external,
                               const NewtonSettings& settings,
                               ShellState& state,
                               const CancellationToken* cancel) {
  CorrectorRequest request;
  request.settings = settings;
  double r0 = 0;
  request.assemble = [&](const ShellState& s, int iteration) {
    system.Assemble(s, /*with_tangent=*/true);
    const Eigen::VectorXd f_ext = external(s);
    CorrectorRequest::Residual r{system.Residual(f_ext), 0.0};
    // A predictor may start far from or close to equilibrium; the test stays
    // relative to the load the step added, not to where the predictor landed.
    if (iteration == 0)
      r0 = settings.residual_reference > 0 ? settings.residual_reference : r.free.norm();
    r.reference = settings.relative_to_force_level ? system.ForceLevel(f_ext) : r0;
    return r;
  };
  request.correct = [&](const Eigen::VectorXd& residual, ShellState& s) {
    return ApplyNewtonCorrection(system, residual, s);
  };
  return RunCorrector(system, state, request, cancel);
}

}  // namespace drape
