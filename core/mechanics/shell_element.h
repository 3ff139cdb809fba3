// The geometrically exact stress-resultant shell element (Simo & Fox 1989) on a
// bilinear 4-node quadrilateral, with assumed natural transverse shear strains
// (MITC4, Dvorkin & Bathe 1984) against shear locking and 2 × 2 Gauss points.
//
// Strains, relative to the reference (flat or imperfect) surface, in the local
// Cartesian frame (e₁, e₂) of the reference surface at each Gauss point:
//   membrane  ε_ij = ½(φ,i·φ,j − φ⁰,i·φ⁰,j)
//   bending   κ_ij = ½(φ,i·t,j + φ,j·t,i) − (same at the reference)
//   shear     γ_i  = φ,i·t − φ⁰,i·t⁰, sampled at the MITC4 tying points
// with t the bilinear interpolation of the nodal directors. The element energy
// is Σ_gp dA [½ εᵀD_mε + ½ κᵀD_bκ + ½ γᵀD_sγ]; its gradient and Hessian are
// taken with respect to the element's 20 incremental DOFs — per node
// (Δu_x, Δu_y, Δu_z, a, b), the rotation increment (a, b) being in the node's
// tangent basis — at zero increment (see director.h).
#pragma once

#include <Eigen/Core>

#include <array>

#include "core/mechanics/shell_section.h"

namespace drape {

using ElementVector = Eigen::Matrix<double, 20, 1>;
using ElementMatrix = Eigen::Matrix<double, 20, 20>;
using NodeColumns = Eigen::Matrix<double, 3, 4>;  // one column per node

// What the element needs from its reference geometry, computed once.
struct ShellElementReference {
  struct GaussPoint {
    Eigen::Vector4d n;                   // N_I
    Eigen::Matrix<double, 4, 2> dn;      // ∂N_I/∂x_i in the local reference frame [1/m]
    Eigen::Matrix2d covariant_to_local;  // γ_i = Σ_α (J⁻¹)_iα γ_α
    double xi = 0, eta = 0;              // parametric position, for the MITC4 interpolation
    double area = 0;                     // dA × Gauss weight [m²]
    Eigen::Matrix2d metric0;             // φ⁰,i·φ⁰,j
    Eigen::Matrix2d curvature0;          // ½(φ⁰,i·t⁰,j + φ⁰,j·t⁰,i) [1/m]
    double orientation0 = 1;             // (φ⁰,₁ × φ⁰,₂)·t⁰ (local frame: ≈ 1)
  };
  struct TyingPoint {
    Eigen::Vector4d n;   // N_I at the tying point
    Eigen::Vector4d dn;  // ∂N_I/∂ξ^α for the component α it ties
    double shear0 = 0;   // φ⁰,α·t⁰ there
  };
  std::array<GaussPoint, 4> gauss;
  // γ_ξ at A (0, −1) and C (0, +1); γ_η at D (−1, 0) and B (+1, 0).
  std::array<TyingPoint, 4> tying;
};

// `positions` and `directors` of the reference state, nodes counter-clockwise.
// `material_x` is the in-plane direction of the local e₁ axis (the warp); it
// is projected on the tangent plane at each Gauss point.
ShellElementReference MakeShellElementReference(const NodeColumns& positions,
                                                const NodeColumns& directors,
                                                const Eigen::Vector3d& material_x);

// The current state of the element's nodes.
struct ShellElementState {
  NodeColumns positions;                                         // φ_I [m]
  NodeColumns directors;                                         // t_I, unit
  std::array<Eigen::Matrix<double, 3, 2>, 4> director_tangents;  // ∂t_I/∂(a, b)
};

struct ElementEnergy {
  double value = 0;                                // [J]
  ElementVector gradient = ElementVector::Zero();  // internal force [N, N·m]
  ElementMatrix hessian = ElementMatrix::Zero();   // tangent stiffness, symmetric
};

enum class ElementOutput { kEnergy, kGradient, kHessian };

// Energy and, as asked, gradient and Hessian at zero increment. With
// bending hysteresis (section.friction) `slip` is the element's slip
// curvature as of the last accepted step (null: none yet), and the energy
// holds the step's incremental potential of the frictional moment.
void EvaluateShellElement(const ShellElementReference& reference,
                          const ShellSection& section,
                          const ShellElementState& state,
                          ElementOutput output,
                          ElementEnergy& result,
                          const ElementSlip* slip = nullptr);

// The bending strains κ = (κ₁₁, κ₂₂, 2κ₁₂) at the four Gauss points, in the
// material frame [1/m]: what the section law is evaluated on.
std::array<Eigen::Vector3d, 4> BendingStrains(const ShellElementReference& reference,
                                              const NodeColumns& positions,
                                              const NodeColumns& directors);

// The membrane (Green–Lagrange) strains ε = (ε₁₁, ε₂₂, 2ε₁₂) at the four
// Gauss points, in the material frame.
std::array<Eigen::Vector3d, 4> MembraneStrains(const ShellElementReference& reference,
                                               const NodeColumns& positions);

// (φ,₁ × φ,₂)·t at the four Gauss points over its reference value: the
// oriented area the element has now per reference area, seen along its
// director. 1 undeformed; at or below 0 where the element has turned inside
// out, which the strains cannot tell: ½(φ,ᵢ·φ,ⱼ − G) is the same for a
// surface and its mirror image.
std::array<double, 4> OrientedAreaRatios(const ShellElementReference& reference,
                                         const NodeColumns& positions,
                                         const NodeColumns& directors);

}  // namespace drape
