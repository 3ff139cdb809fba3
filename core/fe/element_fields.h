// Quantities of a state evaluated over the elements' Gauss points, for
// reports and colour fields (the solver itself does not need them).
#pragma once

#include <Eigen/Core>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"

namespace drape {

// The largest principal bending curvature |κ| over every Gauss point [1/m]:
// how far a fold has taken the material along its bending law.
double MaxPrincipalCurvature(const ShellModel& model, const ShellState& state);

// The largest curvature at which any Gauss point evaluates the bending laws
// (PlateBendingLaw::LawCurvature; with linear bending, the largest principal
// |κ|) [1/m]: what the laws' fitted range is checked against. For an
// isotropic law K = √(κᵀCκ) is 4.8 % above the principal curvature in
// cylindrical bending at ν = 0.3 and 69 % above it in equal two-way bending.
double MaxLawCurvature(const ShellModel& model, const ShellState& state);

// What a colour field shows.
enum class FieldKind {
  kDisplacement,     // |φ − φ₀| per node [m]
  kCurvature,        // largest principal |κ| per element [1/m]
  kBendingMoment,    // largest principal |m| per element [N·m/m]
  kMembraneStrain,   // largest principal |ε| per element (Green–Lagrange) [–]
  kElementEnergy,    // strain energy per reference area per element [J/m²]
  kContactPressure,  // normal contact force per node area [Pa]
  kFrictionState     // per node: 0 no friction, 1 sticking, 2 sliding
};

// Whether the field comes from the contact model (a step's ContactReport),
// not from the elements.
inline bool FromContact(FieldKind kind) {
  return kind == FieldKind::kContactPressure || kind == FieldKind::kFrictionState;
}

struct FieldInfo {
  FieldKind kind;
  const char* name;   // as on the command line: "curvature"
  const char* title;  // as on a colour bar: "curvature [1/m]"
  bool per_node;      // else per element
};

// Every field, in the order the help lists them.
const std::vector<FieldInfo>& Fields();
// The field named `name`, or nullopt.
std::optional<FieldInfo> FindField(std::string_view name);

// The values of a field other than contact pressure (which the contact
// model reports: ContactReport::pressure): one per node or per element.
Eigen::VectorXd EvaluateField(FieldKind kind, const ShellModel& model, const ShellState& state);

}  // namespace drape
