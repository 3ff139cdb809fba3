#include "core/fe/element_fields.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/mechanics/shell_element.h"

namespace drape {
namespace {

// Largest principal |value| of a symmetric 2 × 2 tensor in Voigt form
// (a₁₁, a₂₂, c·a₁₂), `shear_factor` = c (2 for engineering strains).
double LargestPrincipal(const Eigen::Vector3d& v, double shear_factor) {
  const double mean = 0.5 * (v(0) + v(1));
  const double radius = std::hypot(0.5 * (v(0) - v(1)), v(2) / shear_factor);
  return std::abs(mean) + radius;
}

struct ElementNodes {
  NodeColumns x, t;
};

ElementNodes NodesOf(const ShellModel& model, const ShellState& state, int e) {
  ElementNodes n;
  for (int k = 0; k < 4; ++k) {
    const int node = model.mesh.quads(e, k);
    n.x.col(k) = state.positions.row(node).transpose();
    n.t.col(k) = state.Director(node);
  }
  return n;
}

// Per element, the largest of `value` over its Gauss points.
template <typename PerGaussPoint>
Eigen::VectorXd ElementMaximum(const ShellModel& model,
                               const ShellState& state,
                               PerGaussPoint value) {
  Eigen::VectorXd out(model.mesh.ElementCount());
  for (int e = 0; e < model.mesh.ElementCount(); ++e) out(e) = value(e, NodesOf(model, state, e));
  return out;
}

// The slip of element e (zero when the state has no history: as if every
// Gauss point had been bent monotonically from flat).
const ElementSlip* SlipOf(const ShellState& state, int e) {
  return state.bending_slip.empty() ? nullptr : &state.bending_slip[e];
}

// The moment at Gauss point `gauss` of element e, the frictional one included.
Eigen::Vector3d Moment(const ShellSection& section,
                       const Eigen::Vector3d& curvature,
                       const ShellState& state,
                       int e,
                       int gauss) {
  PlateBendingResponse r;
  if (!section.bending_law)
    r.moment = section.bending * curvature;
  else
    section.bending_law->Evaluate(curvature, /*want_tangent=*/false, r);
  if (section.friction) {
    const ElementSlip* slip = SlipOf(state, e);
    AddBendingFriction(*section.friction,
                       curvature,
                       slip ? *slip : ElementSlip::Zero().eval(),
                       gauss,
                       /*want_tangent=*/false,
                       r);
  }
  return r.moment;
}

}  // namespace

double MaxPrincipalCurvature(const ShellModel& model, const ShellState& state) {
  const Eigen::VectorXd per_element = EvaluateField(FieldKind::kCurvature, model, state);
  return per_element.size() ? per_element.maxCoeff() : 0.0;
}

double MaxLawCurvature(const ShellModel& model, const ShellState& state) {
  const auto& law = model.section.bending_law;
  if (!law) return MaxPrincipalCurvature(model, state);
  double largest = 0;
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    const ElementNodes n = NodesOf(model, state, e);
    for (const auto& k : BendingStrains(model.elements[e], n.x, n.t))
      largest = std::max(largest, law->LawCurvature(k));
  }
  return largest;
}

const std::vector<FieldInfo>& Fields() {
  static const std::vector<FieldInfo> fields = {
      {FieldKind::kDisplacement, "displacement", "displacement [m]", true},
      {FieldKind::kCurvature, "curvature", "curvature [1/m]", false},
      {FieldKind::kBendingMoment, "moment", "bending moment [N m/m]", false},
      {FieldKind::kMembraneStrain, "strain", "membrane strain [-]", false},
      {FieldKind::kElementEnergy, "energy", "strain energy [J/m^2]", false},
      {FieldKind::kContactPressure, "pressure", "contact pressure [Pa]", true},
      {FieldKind::kFrictionState, "slip", "friction: 1 sticking, 2 sliding [-]", true},
  };
  return fields;
}

std::optional<FieldInfo> FindField(std::string_view name) {
  for (const auto& f : Fields())
    if (name == f.name) return f;
  return std::nullopt;
}

Eigen::VectorXd EvaluateField(FieldKind kind, const ShellModel& model, const ShellState& state) {
  switch (kind) {
    case FieldKind::kDisplacement:
      return (state.positions - model.reference.positions).rowwise().norm();
    case FieldKind::kCurvature:
      return ElementMaximum(model, state, [&](int e, const ElementNodes& n) {
        double m = 0;
        for (const auto& k : BendingStrains(model.elements[e], n.x, n.t))
          m = std::max(m, LargestPrincipal(k, 2));
        return m;
      });
    case FieldKind::kBendingMoment:
      return ElementMaximum(model, state, [&](int e, const ElementNodes& n) {
        double m = 0;
        const auto strains = BendingStrains(model.elements[e], n.x, n.t);
        for (int p = 0; p < 4; ++p)
          m = std::max(m, LargestPrincipal(Moment(model.section, strains[p], state, e, p), 1));
        return m;
      });
    case FieldKind::kMembraneStrain:
      return ElementMaximum(model, state, [&](int e, const ElementNodes& n) {
        double m = 0;
        for (const auto& eps : MembraneStrains(model.elements[e], n.x))
          m = std::max(m, LargestPrincipal(eps, 2));
        return m;
      });
    case FieldKind::kElementEnergy:
      return ElementMaximum(model, state, [&](int e, const ElementNodes&) {
        ShellElementState element;
        for (int k = 0; k < 4; ++k) {
          const int node = model.mesh.quads(e, k);
          element.positions.col(k) = state.positions.row(node).transpose();
          element.directors.col(k) = state.Director(node);
        }
        ElementEnergy energy;
        EvaluateShellElement(model.elements[e],
                             model.section,
                             element,
                             ElementOutput::kEnergy,
                             energy,
                             SlipOf(state, e));
        double area = 0;
        for (const auto& gp : model.elements[e].gauss) area += gp.area;
        return energy.value / area;
      });
    case FieldKind::kContactPressure:
    case FieldKind::kFrictionState:
      break;
  }
  throw std::invalid_argument(
      "contact pressure and friction come from the contact model, not the elements");
}

}  // namespace drape
