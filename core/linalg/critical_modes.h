// The critical modes of a tangent at a bifurcation: the eigenvectors whose
// eigenvalues are nearest zero, by shift-invert (Spectra's Lanczos) on the
// factorisation the solver already holds, so no new factorisation is made.
//
// K mixes translations (N/m) and rotations (N·m): "nearest zero" is judged
// on the Jacobi-scaled S K S, S = diag(|K_ii|^-½), which has the inertia of
// K (Sylvester) and the same null vectors up to S.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace drape {

struct CriticalMode {
  double eigenvalue = 0;  // of S K S (dimensionless): negative past the critical point
  Eigen::VectorXd shape;  // over the free DOFs (S y for a unit eigenvector y of S K S)
};

// A factorised tangent K as the modes need it: its diagonal and x ↦ K⁻¹ x.
struct FactorizedTangent {
  Eigen::VectorXd diagonal;
  std::function<Eigen::VectorXd(const Eigen::VectorXd&)> solve;
};

// The negative modes of a factorised tangent nearest zero,
// at most `count`, nearest zero first: past a bifurcation crossed from a
// stable state they are the modes that crossed. Positive modes nearer zero
// (a free corner's director can be nearly free) are passed over. Throws std::runtime_error when
// Lanczos does not converge (the message says so).
std::vector<CriticalMode> CriticalModes(const FactorizedTangent& tangent, int count);

}  // namespace drape
