// Adaptive arc-length continuation (Schweizerhof & Wriggers 1986; the paper's
// constraint with ψ scaling). Each step moves a distance Δs along the
// equilibrium path in (u, λ) space,
//
//   ‖Δu‖² + ψ_e² Δλ² = Δs²,   ψ_e² = ψ² + ‖∂u_p/∂λ‖²,
//
// over the free nodes' translations, the prescribed motion's speed folded
// into ψ. Every iteration solves K twice (bordered update): Δu_H = −K⁻¹R and
// Δu_I = K⁻¹F₀ with F₀ = ∂F_ext/∂λ − ∂F_int/∂λ (for prescribed motion the
// paper's −∂P/∂λ, −K_fp ∂u_p/∂λ); δλ solves the constraint's quadratic and
// the root that keeps going forward is taken. Limit points (where λ turns
// back) and bifurcations pass; a step that would overshoot λ = 1 lands on it
// under load control.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/continuation/cancellation_token.h"
#include "core/continuation/convergence.h"
#include "core/continuation/equilibrium_system.h"
#include "core/continuation/newton_corrector.h"
#include "core/fe/stage_loading.h"

namespace drape {

// The last converged step's direction: to continue forward, not back.
struct PathDirection {
  Eigen::VectorXd translation;  // Δu over the free DOFs, rotations zeroed
  double lambda = 0;            // Δλ
};

struct ContinuationStep {
  NewtonOutcome::Status status = NewtonOutcome::Status::kDiverged;
  std::string reason;
  int iterations = 0;
  std::vector<double> residuals;
  Convergence convergence = Convergence::kNotYet;  // how the last iteration was judged
  int negative_pivots = 0;
  double lambda = 0;      // reached
  double arc_length = 0;  // Δs actually used
  bool landed = false;    // ended exactly on the target λ under load control
  PathDirection direction;
};

class ArcLengthStepper {
 public:
  ArcLengthStepper(EquilibriumSystem& system,
                   const StageLoading& loading,
                   const NewtonSettings& newton,
                   double psi);

  // What a step asks for.
  struct StepRequest {
    double lambda = 0;      // of the converged state the step starts from
    double arc_length = 0;  // Δs; ≤ 0: the length whose predictor's Δλ is `first_increment`
    double first_increment = 0;
    const PathDirection* previous = nullptr;  // the step that arrived there (null: none)
    double target = 1.0;                      // λ the step lands on when it would pass it
  };

  // One step from the converged (state, request.lambda). On failure the
  // caller restores the state.
  ContinuationStep Step(ShellState& state,
                        const StepRequest& request,
                        const CancellationToken* cancel);

  // On a positive definite tangent the predictor goes to larger λ (on by
  // default; see Step). Off once a branch switch has landed behind its
  // bifurcation and the way forward led back to it: that branch bends
  // back, and forward would only meet the same bifurcation again.
  void SetDefiniteGoesForward(bool on) { definite_goes_forward_ = on; }

  // Called at each predicted state (positions moved, λ placed), before the
  // corrector: forces that depend on the path's history (friction's lagged
  // normal force) take their values there. True when they changed so much
  // that the predictor itself, made with the old values, is wrong: it is
  // made again once from the step's start.
  using PredictionHook = std::function<bool(const ShellState& predicted)>;
  void SetPredictionHook(PredictionHook hook) { prediction_hook_ = std::move(hook); }

  // A load-controlled step to λ = target (tangent predictor, then Newton).
  ContinuationStep StepTo(ShellState& state,
                          double lambda,
                          double target,
                          const CancellationToken* cancel);

  // A step onto a secondary branch (Wagner & Wriggers 1988): predictor
  // along `mode` (over the free DOFs), λ unchanged; corrector on the
  // hyperplane n·Δq = amplitude, λ free, where n is the mode in the metric
  // that weighs a rotation θ as a translation θ·`rotation_length` (modes of
  // thin fabric can be nearly all rotation). The hyperplane excludes the
  // primary path, which runs orthogonal to the mode. `amplitude` [m] is the
  // step's length in that metric; residuals are judged against the force
  // level (the step adds no load).
  ContinuationStep StepAlong(ShellState& state,
                             double lambda,
                             const Eigen::VectorXd& mode,
                             double amplitude,
                             double rotation_length,
                             const CancellationToken* cancel);

  // The length of a step's secant in the arc-length metric, √(‖Δu‖² +
  // ψ_e²Δλ²), ψ_e at the state it ended at.
  double Length(const PathDirection& secant, double lambda, const ShellState& state) const;

  // Which way λ goes along the path at a converged (state, λ), forward being
  // the side of `secant` (the step that arrived there): +1 rising, −1
  // falling. From the tangent (K⁻¹F₀, 1); a flip between two states means a
  // limit point lies between them. Reuses the state's factorisation.
  int LambdaDirection(const ShellState& state, double lambda, const PathDirection& secant);

 private:
  // A step on the sphere ‖Δu‖² + ψ_e²Δλ² = Δs² once its predictor is taken.
  struct SphereStep {
    double lambda = 0;             // reached so far
    double target = 1;             // the stage's end
    double ds = 0;                 // Δs
    double psi2 = 0;               // ψ_e²: ψ² plus the prescribed motion's speed²
    double reference = 0;          // ‖R₀‖: the load the predictor added
    Eigen::VectorXd f0, u_i, t_i;  // F₀, K⁻¹F₀ and its translations
    Eigen::VectorXd a;             // accumulated free translations of the step
    double b = 0;                  // accumulated Δλ
    Eigen::VectorXd predicted;     // the predictor's direction, to tell forward from back
    double predicted_lambda = 0;
  };
  // The tangent predictor of Step from (state, request.lambda), applied to
  // `state`, `sphere` filled; or, when the predictor reaches the target, the
  // step that lands on it.
  std::optional<ContinuationStep> Predict(ShellState& state,
                                          const StepRequest& request,
                                          SphereStep& sphere,
                                          const CancellationToken* cancel,
                                          bool again = false);
  // The prediction hook at `predicted`; true when the predictor must be
  // made again (and `again` is false).
  bool PredictAgain(const ShellState& predicted, bool again) const {
    return prediction_hook_ && prediction_hook_(predicted) && !again;
  }
  // The corrector on the sphere (bordered Newton, δλ from the sphere's
  // quadratic). `overshot`: it converged past the stage's end.
  NewtonOutcome CorrectOnSphere(ShellState& state,
                                SphereStep& sphere,
                                bool& overshot,
                                const CancellationToken* cancel);
  // Assembles at (state, λ); returns F₀ over the free DOFs.
  Eigen::VectorXd AssembleWithRate(const ShellState& state, double lambda);
  Eigen::VectorXd Translations(const Eigen::VectorXd& free) const;
  // The fraction of an update (`full`, 5 per node, with λ moving from
  // `lambda` by `delta`) that keeps the fabric's layers apart, the held
  // nodes' prescribed motion included (EquilibriumSystem::StepBound).
  double CollisionFreeFraction(const ShellState& state,
                               const Eigen::VectorXd& full,
                               double lambda,
                               double delta) const;
  // Applies a corrector's (Δq, δλ), both first cut to the part that keeps
  // the fabric's layers apart (CollisionFreeFraction): the state and its
  // prescribed motion move on, the step's accumulated translations and Δλ
  // grow. Returns max|Δu|.
  double Correct(Eigen::VectorXd& correction,
                 double& delta,
                 ShellState& state,
                 double& lambda,
                 Eigen::VectorXd& translations,
                 double& lambda_increment) const;

  EquilibriumSystem& system_;
  const StageLoading& loading_;
  NewtonSettings newton_;
  double psi_;
  PredictionHook prediction_hook_;
  bool definite_goes_forward_ = true;
  Eigen::VectorXd translation_mask_;  // 1 on free translation DOFs, 0 on rotations
};

}  // namespace drape
