// Finite rotations of the shell directors (Simo & Fox 1989).
//
// Each node carries an orientation Λ ∈ SO(3) with director t = Λ E₃; the first
// two columns of Λ are the node's tangent basis (g₁, g₂). A rotation increment
// has two components (a, b) in that basis, w = a g₁ + b g₂ (no drilling), and
// is applied as Λ ← exp(ŵ) Λ, never by adding to t and renormalising.
#pragma once

#include <Eigen/Core>

namespace drape {

// ŵ: the skew matrix with ŵ v = w × v.
Eigen::Matrix3d Skew(const Eigen::Vector3d& w);

// exp(ŵ) by Rodrigues' formula, accurate for small and large |w|.
Eigen::Matrix3d ExpRotation(const Eigen::Vector3d& w);

// A rotation taking E₃ to t: for E₃·t ≥ 0 the one about the axis E₃ × t, the
// paper's Λ = (E·t) I + (E×t)^ + (E×t)⊗(E×t) / (1 + E·t); below the equator
// that rotation composed with a half turn about E₁, so it stays accurate down
// to t = −E₃ (a fold's turned-over end). Requires |t| = 1. The shell's
// strains depend on t alone, not on which such rotation it is.
Eigen::Matrix3d RotationFromDirector(const Eigen::Vector3d& t);

// Applies the increment (a, b): Λ ← exp(ŵ) Λ with w = a Λe₁ + b Λe₂.
void UpdateRotation(const Eigen::Vector2d& increment, Eigen::Matrix3d& rotation);

// ∂t/∂(a, b) at zero increment: the 3 × 2 matrix [−g₂, g₁], since
// w × t = a g₁ × g₃ + b g₂ × g₃ = −a g₂ + b g₁. The second derivatives are
// ∂²t/∂a² = ∂²t/∂b² = −t and ∂²t/∂a∂b = 0 (from ½ w × (w × t) = −½|w|² t).
Eigen::Matrix<double, 3, 2> DirectorTangent(const Eigen::Matrix3d& rotation);

}  // namespace drape
