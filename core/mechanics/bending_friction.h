// Bending hysteresis: the frictional moment between yarns that opens the
// KES-FB2 moment–curvature loop (its width 2HB, Kawabata's "hysteresis of
// bending moment").
//
// Each yarn family with a hysteresis carries a Jenkins element beside the
// elastic law: a stick spring k in series with a Coulomb slider of strength
// HB = 2HB/2, on the same curvature norm K = √(κᵀAκ) as the family's elastic
// law (plate_bending_law.h). Its history is the slip curvature s, a Voigt
// vector per Gauss point: the part of κ the slider has let go. Bending
// further than s by r = |κ − s|_A gives the moment
//   m_f = k A(κ − s)                   while k r ≤ HB (stick),
//   m_f = HB A(κ − s)/r                beyond (slip),
// so that a strip loaded past the stick range carries M(K) ± HB and a reversal
// crosses from +HB to −HB over ΔK = 2HB/k: the loop is 2HB wide.
//
// Within a step s stays at its value at the start, and the moment is the
// gradient of the incremental potential (the Huber function of r, convex and
// C¹): ψ = ½ k r² while k r ≤ HB, else HB r − HB²/2k. Each step is still a
// minimisation with a symmetric tangent; an accepted step then commits the
// slip the slider made (UpdateSlip: s moves along κ − s until k r = HB).
#pragma once

#include <Eigen/Core>

#include <memory>
#include <vector>

#include "core/mechanics/moment_curvature.h"
#include "core/mechanics/plate_bending_law.h"

namespace drape {

// The curvature change over which a reversal takes the frictional moment from
// +HB to −HB: 0.1 1/cm, a twentieth of KES-FB2's ±2.5 1/cm sweep, so that its
// loop is fully open by |K| = 0.5 1/cm, where Kawabata's B and 2HB are read.
constexpr double kHysteresisReversalCurvature = 10.0;  // [1/m]

// The slip curvatures of one element: column 2p + f for Gauss point p and
// friction family f (at most two: warp and weft).
using ElementSlip = Eigen::Matrix<double, 3, 8>;
constexpr int kMaxFrictionFamilies = 2;

struct FrictionFamily {
  Eigen::Matrix3d metric;      // A of the family's curvature norm
  double slip_moment = 0;      // HB [N·m/m]
  double stick_stiffness = 0;  // k [N·m]
};

struct BendingFriction {
  std::vector<FrictionFamily> families;  // one (isotropic) or up to two (warp, weft)
};

// A family for a loop `width` 2HB [N·m/m] > 0 on the norm `metric`, its stick
// range kHysteresisReversalCurvature.
FrictionFamily MakeFrictionFamily(const Eigen::Matrix3d& metric, double width);

// Adds the frictional moment's incremental potential, moment and tangent at
// the curvature κ of Gauss point `gauss` with the slip of `slip` to
// `response`.
void AddBendingFriction(const BendingFriction& friction,
                        const Eigen::Vector3d& curvature,
                        const ElementSlip& slip,
                        int gauss,
                        bool want_tangent,
                        PlateBendingResponse& response);

// Moves the slip of Gauss point `gauss` to where the sliders leave it at κ.
void UpdateSlip(const BendingFriction& friction,
                const Eigen::Vector3d& curvature,
                int gauss,
                ElementSlip& slip);

}  // namespace drape
