#include "core/solve/converged_step.h"

#include <cmath>
#include <string>

#include "core/fe/bending_slip.h"
#include "core/fe/element_fields.h"
#include "core/model/string_format.h"
#include "core/solve/contact_augmentation.h"

namespace drape {
namespace {

// A node's normal force this far (of the largest) from its lag leaves the
// step unsettled.
constexpr double kUnsettledLag = 1e-2;
// The share of the load the stabilisation springs of a sliding part carry.
constexpr double kSlidingSpringShare = 1e-3;

// The contact report of the state, with what augmentation did.
ContactReport ReportContact(const SolveRun& run, const Augmentation& augmentation) {
  ContactReport report = run.contact->Report(run.state);
  report.augmentation_passes = augmentation.passes;
  report.augmentation_shortfall = augmentation.shortfall;
  if (run.augment_contact)
    report.penetration_target = run.options.penetration_tolerance * run.model.thickness;
  return report;
}

// Where two layers of the fabric come within twice its thickness: their
// distance and the force self-contact carries between them.
void MeasureLayers(SolveRun& run, StepState& step) {
  const double d = run.layers->SmallestDistance(run.state.positions, 2 * run.model.thickness);
  if (!std::isfinite(d)) return;
  step.layer_distance = d;
  // Infinite only where held nodes alone put layers inside the offset.
  if (const double f =
          run.self_contact ? run.self_contact->Evaluate(run.state.positions, false).force : NAN;
      std::isfinite(f))
    step.layer_force = f;
}

// Whether nothing but the stabilisation springs holds the part at this
// state: every node in contact slides, and the springs carry a share of the
// load no settling part leaves them (a sheet on a table a little steeper
// than its friction: 2 % over μ leaves them 0.6 % of its weight). Nodes
// that slide while the part drapes over a curved form are not this: the
// form's normal forces hold it, and the springs carry almost nothing.
bool SlidesAsAWhole(const NodeContact& contact,
                    const ContactReport& report,
                    const Eigen::VectorXd& external) {
  if (contact.stabilization() <= 0 || report.sliding == 0 || report.sticking > 0) return false;
  Eigen::Vector3d load = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i + 2 < external.size(); i += kDofsPerNode)
    load += external.segment<3>(i);
  return report.stabilization_force.norm() > kSlidingSpringShare * load.norm();
}

}  // namespace

std::vector<NamedVector> Reactions(const ShellModel& model,
                                   const std::vector<bool>& released,
                                   const Eigen::VectorXd& unbalanced) {
  std::vector<NamedVector> reactions;
  auto reaction = [&](const HeldNodes& held, bool active) {
    NamedVector r{held.name, Eigen::Vector3d::Zero()};
    if (active)
      for (int node : held.nodes) r.value += unbalanced.segment<3>(kDofsPerNode * node);
    reactions.push_back(r);
  };
  for (const auto& s : model.supports) reaction(s, true);
  for (size_t g = 0; g < model.grippers.size(); ++g) reaction(model.grippers[g], !released[g]);
  return reactions;
}

bool PassContact(SolveRun& run,
                 double lambda,
                 const StageLoading& loading,
                 ContinuationStep& step,
                 Augmentation& passes) {
  if (!run.contact || !(run.augment_contact || run.contact->friction() > 0)) return true;
  NodeContact::Memory memory = run.contact->memory();
  passes = AugmentContact(run, lambda, loading, step);
  const double change = run.contact->FrictionLagChange(run.state);
  if (change <= kUnsettledLag) return true;
  run.contact->Restore(std::move(memory));
  step.status = NewtonOutcome::Status::kDiverged;
  step.reason = Format("friction's normal forces did not settle (still %.2g %% off: %s)",
                       100 * change,
                       passes.shortfall.c_str());
  return false;
}

StageOutcome RecordConvergedStep(SolveRun& run,
                                 const StepPlace& place,
                                 const StageLoading& loading,
                                 const ContinuationStep& converged,
                                 const StabilityEvent* classified,
                                 const Augmentation* passes) {
  ContinuationStep result = converged;
  Augmentation augmentation;
  if (passes)
    augmentation = *passes;
  else if (run.contact && (run.augment_contact || run.contact->friction() > 0))
    augmentation = AugmentContact(run, place.lambda, loading, result);
  const std::string& name = run.scene.stages[place.stage].name;
  // The steppers refuse non-finite trial states; this keeps the promise that
  // no observer and no file ever sees one, whatever a future path does.
  if (!IsFinite(run.state))
    return StageOutcome::Stop(Termination::kNumericalFailure,
                              "stage '" + name + "': a converged state at λ = " +
                                  std::to_string(place.lambda) + " is not finite; it was not kept");
  const ShellModel& model = run.model;
  StepState step;
  step.stage = place.stage;
  step.stage_name = name;
  step.stage_step = place.stage_step;
  step.lambda = place.lambda;
  step.iterations = result.iterations;
  step.residuals = result.residuals;
  step.convergence = result.convergence;
  step.arc_length = result.arc_length;
  step.negative_pivots = result.negative_pivots;
  step.max_curvature = MaxPrincipalCurvature(model, run.state);
  step.law_curvature =
      model.section.bending_law ? MaxLawCurvature(model, run.state) : step.max_curvature;
  const Eigen::VectorXd external = loading.External(place.lambda, run.state);
  step.reactions = Reactions(model, run.released, run.system->InternalForce() - external);
  for (const auto& probe : model.probes)
    step.probes.push_back({probe.name, ProbePosition(model, probe, run.state)});
  if (run.contact) {
    step.contact = ReportContact(run, augmentation);
    run.last_stabilization_force = step.contact->max_stabilization_force;
    run.slides_as_a_whole = SlidesAsAWhole(*run.contact, *step.contact, external);
    run.contact->Commit(run.state);
  }
  if (run.layers) MeasureLayers(run, step);
  // The yarns' friction keeps the slip it made: the next step starts from it.
  CommitBendingSlip(model, run.state);
  step.state = run.state;
  if (run.recorder->Record(step, classified) == StepDecision::kStop)
    return StageOutcome::Stop(
        Termination::kStoppedByObserver,
        "an observer stopped the run after step " + std::to_string(step.step));
  return StageOutcome::On();
}

}  // namespace drape
