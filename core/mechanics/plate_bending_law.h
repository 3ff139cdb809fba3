// Bending of the shell section as an energy density of the curvature tensor,
// built on the one-dimensional moment–curvature laws a strip test measures
// (moment_curvature.h). One potential gives the moments and their tangent, so
// the tangent is symmetric; the potential depends on the curvature tensor and
// the material axes only, so the law is objective.
//
// Curvatures and moments are Voigt vectors in the material frame (e₁ = warp,
// e₂ = weft): κ = (κ₁₁, κ₂₂, 2κ₁₂) [1/m], m = ∂W/∂κ = (m₁₁, m₂₂, m₁₂)
// [N·m/m], per unit reference length.
#pragma once

#include <Eigen/Core>

#include <memory>

#include "core/mechanics/moment_curvature.h"

namespace drape {

struct PlateBendingResponse {
  double energy = 0;                                  // W [N/m]
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();   // ∂W/∂κ [N·m/m]
  Eigen::Matrix3d tangent = Eigen::Matrix3d::Zero();  // ∂²W/∂κ² [N·m]
};

class PlateBendingLaw {
 public:
  virtual ~PlateBendingLaw() = default;
  // W, m and, when `want_tangent`, ∂m/∂κ at the curvature κ.
  virtual void Evaluate(const Eigen::Vector3d& curvature,
                        bool want_tangent,
                        PlateBendingResponse& response) const = 0;
  // The tangent at κ = 0 (the linear law of small curvatures).
  Eigen::Matrix3d InitialTangent() const;
  // The largest curvature at which κ evaluates a one-dimensional law (K for
  // one law, the larger of K_warp and K_weft for two) [1/m]: what is held
  // against the laws' measured or fitted range.
  virtual double LawCurvature(const Eigen::Vector3d& curvature) const = 0;
};

// One law for every direction: W = W₁(K), K² = κᵀ C κ with the plane-stress
// matrix C = [[1, ν, 0], [ν, 1, 0], [0, 0, (1 − ν)/2]] / (1 − ν²). K is the
// curvature of a strip bent free of transverse moment (K² = κ₁₁² when
// m₂₂ = m₁₂ = 0, in any direction), so a narrow strip follows the measured
// M = W₁'(K) exactly, and K is invariant under in-plane rotation. With the
// linear law W₁ = ½BK² this is the linear plate m = B C κ.
std::unique_ptr<PlateBendingLaw> MakeIsotropicPlateLaw(
    std::shared_ptr<const MomentCurvatureLaw> law, double poisson_ratio);

// Warp and weft bend by their own laws, each on the curvature of its yarn
// family, K_α = |κ e_α| (the normal curvature κ_αα and the twist κ₁₂ of
// that yarn): W = W_warp(K₁) + W_weft(K₂), K₁² = κ₁₁² + κ₁₂²,
// K₂² = κ₂₂² + κ₁₂². There is no Poisson coupling between the yarn
// families (woven fabrics bend their yarns nearly independently); the twist
// rigidity follows from both laws, ∂m₁₂/∂(2κ₁₂) = (B_warp + B_weft)/4 at small
// curvature. With equal linear laws it is the isotropic law with ν = 0.
std::unique_ptr<PlateBendingLaw> MakeWarpWeftPlateLaw(
    std::shared_ptr<const MomentCurvatureLaw> warp, std::shared_ptr<const MomentCurvatureLaw> weft);

// The metrics A of the curvature norms K = √(κᵀAκ) the laws above apply
// their strip laws to: the isotropic law's plane-stress C (ν), and yarn
// family 0 (warp) or 1 (weft) of the warp–weft law.
Eigen::Matrix3d IsotropicCurvatureMetric(double poisson_ratio);
Eigen::Matrix3d YarnCurvatureMetric(int family);

// Adds W(K), K = √(κᵀAκ), of the strip law `law` to `response` with its
// derivatives in κ (the building block of both plate laws, and of the
// frictional moment of bending_friction.h):
//   ∂W/∂κ = (M/K) Aκ,   ∂²W/∂κ² = (M/K) A + (dM/dK − M/K)(Aκ)(Aκ)ᵀ/K².
void AddCurvatureNormLaw(const MomentCurvatureLaw& law,
                         const Eigen::Matrix3d& metric,
                         const Eigen::Vector3d& curvature,
                         bool want_tangent,
                         PlateBendingResponse& response);

}  // namespace drape
