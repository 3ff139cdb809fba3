#include "core/continuation/arc_length_stepper.h"

#include <cmath>
#include <optional>
#include <string>
#include <utility>

namespace drape {
namespace {

// The corrector's outcome in a step that already counted its predictor's
// solve.
void TakeOutcome(const NewtonOutcome& newton, ContinuationStep& out) {
  out.status = newton.status;
  out.reason = newton.reason;
  out.iterations += newton.iterations;
  out.residuals = newton.residuals;
  out.convergence = newton.convergence;
  out.negative_pivots = newton.negative_pivots;
}

// δλ from ‖a + t_h + δλ t_i‖² + ψ_e²(b + δλ)² = Δs²: the root whose new
// increment turns least from the current one (a, b); where there is no
// root, the δλ that comes as close to the sphere as possible.
double SphereRoot(const Eigen::VectorXd& a,
                  double b,
                  const Eigen::VectorXd& t_h,
                  const Eigen::VectorXd& t_i,
                  double psi2,
                  double ds) {
  const Eigen::VectorXd p = a + t_h;
  const double a1 = t_i.squaredNorm() + psi2;
  const double a2 = 2 * (t_i.dot(p) + psi2 * b);
  const double a3 = p.squaredNorm() + psi2 * b * b - ds * ds;
  const double disc = a2 * a2 - 4 * a1 * a3;
  if (disc < 0) return -a2 / (2 * a1);
  const double q = -0.5 * (a2 + std::copysign(std::sqrt(disc), a2));
  const double r1 = q / a1, r2 = q != 0 ? a3 / q : r1;
  auto forward = [&](double x) { return a.dot(p + x * t_i) + psi2 * b * (b + x); };
  return forward(r1) >= forward(r2) ? r1 : r2;
}

}  // namespace

ArcLengthStepper::ArcLengthStepper(EquilibriumSystem& system,
                                   const StageLoading& loading,
                                   const NewtonSettings& newton,
                                   double psi)
    : system_(system), loading_(loading), newton_(newton), psi_(psi) {
  // Moving grippers add no load: judge residuals against the forces present.
  newton_.relative_to_force_level = loading.MovesGrippers() || loading.MovesObstacles();
  const DofMap& dofs = system.dofs();
  translation_mask_.setZero(dofs.FreeCount());
  for (int d = 0; d < dofs.DofCount(); ++d)
    if (dofs.Free(d) >= 0 && d % kDofsPerNode < 3) translation_mask_(dofs.Free(d)) = 1;
}

Eigen::VectorXd ArcLengthStepper::Translations(const Eigen::VectorXd& free) const {
  return free.cwiseProduct(translation_mask_);
}

double ArcLengthStepper::Correct(Eigen::VectorXd& correction,
                                 double& delta,
                                 ShellState& state,
                                 double& lambda,
                                 Eigen::VectorXd& translations,
                                 double& lambda_increment) const {
  Eigen::VectorXd full = system_.dofs().Expand(correction);
  if (const double t = CollisionFreeFraction(state, full, lambda, delta); t < 1) {
    full *= t;
    correction *= t;
    delta *= t;
  }
  translations += Translations(correction);
  lambda_increment += delta;
  lambda += delta;
  ApplyIncrement(full, state);
  loading_.Place(lambda, state);
  return MaxTranslation(full);
}

double ArcLengthStepper::CollisionFreeFraction(const ShellState& state,
                                               const Eigen::VectorXd& full,
                                               double lambda,
                                               double delta) const {
  if (!system_.BoundsSteps()) return 1.0;
  ShellState moved = state;
  ApplyIncrement(full, moved);
  loading_.Place(lambda + delta, moved);
  return system_.StepBound(state, Positions(moved.positions - state.positions));
}

Eigen::VectorXd ArcLengthStepper::AssembleWithRate(const ShellState& state, double lambda) {
  const Eigen::VectorXd velocity = loading_.Velocity(lambda, state);
  system_.Assemble(state, /*with_tangent=*/true, loading_.MovesGrippers() ? &velocity : nullptr);
  Eigen::VectorXd f0 = system_.dofs().Restrict(loading_.ExternalRate(state));
  if (loading_.MovesGrippers()) f0 -= system_.dofs().Restrict(system_.InternalForceRate());
  if (loading_.MovesObstacles())
    f0 -=
        system_.dofs().Restrict(system_.ObstacleForceRate(state, loading_.ObstacleMotions(lambda)));
  return f0;
}

ContinuationStep ArcLengthStepper::StepTo(ShellState& state,
                                          double lambda,
                                          double target,
                                          const CancellationToken* cancel) {
  ContinuationStep out;
  const DofMap& dofs = system_.dofs();
  const ShellState start = prediction_hook_ ? state : ShellState{};
  // Tangent predictor: the linear response to the change of λ.
  Eigen::VectorXd f0, u_i;
  const double delta = target - lambda;
  for (bool again = false;; again = true) {
    f0 = AssembleWithRate(state, lambda);
    system_.Factorize();
    u_i = system_.Solve(f0);
    Eigen::VectorXd predictor = dofs.Expand(delta * u_i);
    if (const double t = system_.StepBound(state, predictor); t < 1) predictor *= t;
    ApplyIncrement(predictor, state);
    loading_.Place(target, state);
    if (!PredictAgain(state, again)) break;
    state = start;
  }
  NewtonSettings settings = newton_;
  settings.residual_reference = std::abs(delta) * f0.norm();
  NewtonOutcome newton = SolveEquilibrium(
      system_,
      [&](const ShellState& s) { return loading_.External(target, s); },
      settings,
      state,
      cancel);
  out.status = newton.status;
  out.reason = newton.reason;
  out.iterations = newton.iterations + 1;
  out.residuals = newton.residuals;
  out.convergence = newton.convergence;
  out.negative_pivots = newton.negative_pivots;
  out.lambda = target;
  out.landed = true;
  out.direction = {delta * Translations(u_i), delta};
  out.arc_length = std::abs(delta);
  return out;
}

std::optional<ContinuationStep> ArcLengthStepper::Predict(ShellState& state,
                                                          const StepRequest& request,
                                                          SphereStep& sphere,
                                                          const CancellationToken* cancel,
                                                          bool again) {
  const DofMap& dofs = system_.dofs();
  const ShellState start = prediction_hook_ ? state : ShellState{};
  double lambda = request.lambda;
  const PathDirection* previous = request.previous;
  const double speed = loading_.PrescribedSpeed(lambda, state);
  const double psi2 = psi_ * psi_ + speed * speed;

  // Predictor along the tangent: Δu = Δλ Δu_I with ‖Δu‖² + ψ_e²Δλ² = Δs².
  Eigen::VectorXd f0 = AssembleWithRate(state, lambda);
  const FactorizationInfo tangent = system_.Factorize();
  Eigen::VectorXd u_i = system_.Solve(f0);
  Eigen::VectorXd t_i = Translations(u_i);
  const double tangent_norm = std::sqrt(t_i.squaredNorm() + psi2);
  double ds = request.arc_length > 0 ? request.arc_length : request.first_increment * tangent_norm;
  double dl = ds / tangent_norm;
  // Forward: the side on which the tangent agrees with the last step. On a
  // positive definite tangent the path is a function of λ (implicit
  // function theorem) and, traversed from λ = 0, goes to larger λ (the sign
  // of Δλ turns with the sign of det K, at limit points): there a turn back
  // is the wrong side taken — after a step onto a stable branch that came
  // back a little (the diagonal fold as its corner lands), or where the
  // tangent swings by more than 90° between steps — and it would unfold the
  // part along a path it never takes.
  if (previous && previous->translation.dot(t_i) + psi2 * previous->lambda < 0) dl = -dl;
  if (definite_goes_forward_ && tangent.negative_pivots == 0) dl = std::abs(dl);
  if (dl > 0 && lambda + dl >= request.target - 1e-12) {
    ContinuationStep landing = StepTo(state, lambda, request.target, cancel);
    landing.arc_length = ds;
    return landing;
  }

  // A predictor that would pass through the fabric's own layers is
  // shortened, and the step with it.
  if (const double t = CollisionFreeFraction(state, dofs.Expand(dl * u_i), lambda, dl); t < 1) {
    ds *= t;
    dl *= t;
  }
  ApplyIncrement(dofs.Expand(dl * u_i), state);
  lambda += dl;
  loading_.Place(lambda, state);
  if (PredictAgain(state, again)) {
    state = start;
    return Predict(state, request, sphere, cancel, /*again=*/true);
  }
  sphere.lambda = lambda;
  sphere.target = request.target;
  sphere.ds = ds;
  sphere.psi2 = psi2;
  sphere.reference = std::abs(dl) * f0.norm();
  sphere.a = dl * t_i;
  sphere.b = dl;
  sphere.predicted = sphere.a;
  sphere.predicted_lambda = dl;
  sphere.f0 = std::move(f0);
  sphere.u_i = std::move(u_i);
  sphere.t_i = std::move(t_i);
  return std::nullopt;
}

NewtonOutcome ArcLengthStepper::CorrectOnSphere(ShellState& state,
                                                SphereStep& sphere,
                                                bool& overshot,
                                                const CancellationToken* cancel) {
  SphereStep& p = sphere;
  CorrectorRequest corrector;
  corrector.settings = newton_;
  corrector.assemble = [&](const ShellState& s, int) {
    p.f0 = AssembleWithRate(s, p.lambda);
    const Eigen::VectorXd f_ext = loading_.External(p.lambda, s);
    return CorrectorRequest::Residual{
        system_.Residual(f_ext),
        newton_.relative_to_force_level ? system_.ForceLevel(f_ext) : p.reference};
  };
  corrector.correct = [&](const Eigen::VectorXd& r, ShellState& s) {
    // Bordered update: two solves with one factorisation.
    const Eigen::VectorXd u_h = system_.Solve(-r);
    p.u_i = system_.Solve(p.f0);
    const Eigen::VectorXd t_h = Translations(u_h);
    p.t_i = Translations(p.u_i);
    double delta = SphereRoot(p.a, p.b, t_h, p.t_i, p.psi2, p.ds);
    Eigen::VectorXd correction = u_h + delta * p.u_i;
    return Correct(correction, delta, s, p.lambda, p.a, p.b);
  };
  overshot = false;
  corrector.refuse = [&](const ShellState&) -> std::string {
    if (p.lambda > p.target + 1e-12) {
      overshot = true;
      return "converged past the stage's end";
    }
    // Near a bifurcation the corrector can wander onto the part of the path
    // behind the step; that is not progress: cut the step instead.
    if (p.a.dot(p.predicted) + p.psi2 * p.b * p.predicted_lambda <= 0)
      return "the corrector converged back along the path";
    return "";
  };
  return RunCorrector(system_, state, corrector, cancel);
}

ContinuationStep ArcLengthStepper::Step(ShellState& state,
                                        const StepRequest& request,
                                        const CancellationToken* cancel) {
  const ShellState start = state;
  SphereStep sphere;
  if (std::optional<ContinuationStep> landing = Predict(state, request, sphere, cancel))
    return *landing;
  ContinuationStep out;
  out.arc_length = sphere.ds;
  out.iterations = 1;  // the predictor's solve, as the paper counts it
  bool overshot = false;
  const NewtonOutcome newton = CorrectOnSphere(state, sphere, overshot, cancel);
  if (overshot) {
    // Converged past the stage's end: redo the step landing on it.
    state = start;
    loading_.Place(request.lambda, state);
    ContinuationStep landing = StepTo(state, request.lambda, request.target, cancel);
    landing.arc_length = sphere.ds;
    return landing;
  }
  TakeOutcome(newton, out);
  if (newton.status == NewtonOutcome::Status::kConverged) {
    out.lambda = sphere.lambda;
    out.direction = {sphere.a, sphere.b};
  }
  return out;
}

double ArcLengthStepper::Length(const PathDirection& secant,
                                double lambda,
                                const ShellState& state) const {
  const double speed = loading_.PrescribedSpeed(lambda, state);
  return std::sqrt(secant.translation.squaredNorm() +
                   (psi_ * psi_ + speed * speed) * secant.lambda * secant.lambda);
}

int ArcLengthStepper::LambdaDirection(const ShellState& state,
                                      double lambda,
                                      const PathDirection& secant) {
  const double speed = loading_.PrescribedSpeed(lambda, state);
  const double psi2 = psi_ * psi_ + speed * speed;
  const Eigen::VectorXd f0 = AssembleWithRate(state, lambda);
  system_.Factorize();
  const Eigen::VectorXd t_i = Translations(system_.Solve(f0));
  return secant.translation.dot(t_i) + psi2 * secant.lambda >= 0 ? 1 : -1;
}

ContinuationStep ArcLengthStepper::StepAlong(ShellState& state,
                                             double lambda,
                                             const Eigen::VectorXd& mode,
                                             double amplitude,
                                             double rotation_length,
                                             const CancellationToken* cancel) {
  const DofMap& dofs = system_.dofs();
  ContinuationStep out;
  // The metric: 1 on translations, ℓ² on rotations.
  const Eigen::VectorXd metric =
      translation_mask_ + (rotation_length * rotation_length) *
                              (Eigen::VectorXd::Ones(mode.size()) - translation_mask_);
  const double mode_norm = std::sqrt(mode.cwiseAbs2().dot(metric));
  if (!(mode_norm > 0)) {
    out.reason = "the mode is zero";
    return out;
  }
  const Eigen::VectorXd n = metric.cwiseProduct(mode) / mode_norm;
  Eigen::VectorXd predictor = (amplitude / mode_norm) * mode;
  // Never into the fabric's layers or an obstacle's barrier.
  const double bound = system_.StepBound(state, dofs.Expand(predictor));
  predictor *= bound;
  amplitude *= bound;
  ApplyIncrement(dofs.Expand(predictor), state);
  Eigen::VectorXd q = predictor;        // accumulated free increments, all DOFs
  Eigen::VectorXd a = Translations(q);  // the same, translations only
  double b = 0;                         // accumulated Δλ
  out.iterations = 1;
  out.arc_length = std::abs(amplitude);
  CorrectorRequest request;
  request.settings = newton_;
  request.settings.relative_to_force_level = true;
  Eigen::VectorXd f0;
  request.assemble = [&](const ShellState& s, int) {
    f0 = AssembleWithRate(s, lambda);
    const Eigen::VectorXd f_ext = loading_.External(lambda, s);
    return CorrectorRequest::Residual{system_.Residual(f_ext), system_.ForceLevel(f_ext)};
  };
  request.correct = [&](const Eigen::VectorXd& r, ShellState& s) {
    const Eigen::VectorXd u_h = system_.Solve(-r);
    const Eigen::VectorXd u_i = system_.Solve(f0);
    // n·(q + u_h + δλ u_i) = amplitude. Where F₀ has no part along the mode
    // (n·u_i = 0) λ cannot hold the hyperplane: keep it and let Δu_H do.
    const double along = n.dot(u_i);
    const double miss = amplitude - n.dot(q + u_h);
    double delta = std::abs(along) > 1e-12 * n.norm() * u_i.norm() ? miss / along : 0.0;
    Eigen::VectorXd correction = u_h + delta * u_i;
    const double moved = Correct(correction, delta, s, lambda, a, b);
    q += correction;
    return moved;
  };
  request.refuse = [&](const ShellState&) -> std::string {
    if (std::abs(n.dot(q) - amplitude) > 0.5 * std::abs(amplitude))
      return "the corrector went back towards the primary path";
    return "";
  };
  const NewtonOutcome newton = RunCorrector(system_, state, request, cancel);
  TakeOutcome(newton, out);
  if (newton.status == NewtonOutcome::Status::kConverged) {
    out.lambda = lambda;
    out.direction = {a, b};
    out.arc_length = Length(out.direction, lambda, state);
  }
  return out;
}

}  // namespace drape
