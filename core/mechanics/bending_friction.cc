#include "core/mechanics/bending_friction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace drape {
namespace {

// The Jenkins element as a strip law of r = |κ − s|_A: M = min(k r, HB).
class StickSlipLaw final : public MomentCurvatureLaw {
 public:
  StickSlipLaw(double slip_moment, double stiffness)
      : hb_(slip_moment), k_(stiffness), r_(slip_moment / stiffness) {}
  double Energy(double r) const override {
    r = std::abs(r);
    return r <= r_ ? 0.5 * k_ * r * r : hb_ * r - 0.5 * hb_ * r_;
  }
  double Moment(double r) const override {
    return std::abs(r) <= r_ ? k_ * r : std::copysign(hb_, r);
  }
  double Stiffness(double r) const override { return std::abs(r) <= r_ ? k_ : 0.0; }
  double ValidTo() const override { return INFINITY; }

 private:
  double hb_, k_, r_;
};

}  // namespace

FrictionFamily MakeFrictionFamily(const Eigen::Matrix3d& metric, double width) {
  if (!(width > 0 && std::isfinite(width)))
    throw std::invalid_argument("bending hysteresis: 2HB must be positive and finite");
  return {metric, 0.5 * width, width / kHysteresisReversalCurvature};
}

void AddBendingFriction(const BendingFriction& friction,
                        const Eigen::Vector3d& curvature,
                        const ElementSlip& slip,
                        int gauss,
                        bool want_tangent,
                        PlateBendingResponse& response) {
  for (size_t f = 0; f < friction.families.size(); ++f) {
    const FrictionFamily& family = friction.families[f];
    const StickSlipLaw law(family.slip_moment, family.stick_stiffness);
    AddCurvatureNormLaw(law,
                        family.metric,
                        curvature - slip.col(2 * gauss + static_cast<int>(f)),
                        want_tangent,
                        response);
  }
}

void UpdateSlip(const BendingFriction& friction,
                const Eigen::Vector3d& curvature,
                int gauss,
                ElementSlip& slip) {
  for (size_t f = 0; f < friction.families.size(); ++f) {
    const FrictionFamily& family = friction.families[f];
    auto s = slip.col(2 * gauss + static_cast<int>(f));
    const Eigen::Vector3d d = curvature - s;
    const double r = std::sqrt(std::max(0.0, d.dot(family.metric * d)));
    const double stick = family.slip_moment / family.stick_stiffness;
    // The minimiser of ½k|κ − s|² + HB|s − sₙ| over s (soft thresholding).
    if (r > stick) s += (1 - stick / r) * d;
  }
}

}  // namespace drape
