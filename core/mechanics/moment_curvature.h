// One-dimensional bending laws per unit width: moment M [N·m/m] against
// curvature K [1/m], the SI forms of scene.h's LinearBending,
// PolynomialBending and CurveBending.
//
// Each law is an energy density W(K) = ∫₀ᴷ M dK [N/m] with M = W' and
// dM/dK = W'', so that a plate law built on it later derives its moments and
// tangent from one potential (symmetric tangent, objective when fed
// objective curvatures). Every law here has W(0) = 0, M(0) = 0, M continuous
// and dM/dK continuous (W is C²), and energies are exact integrals of M (no
// quadrature).
#pragma once

#include <array>
#include <memory>
#include <vector>

namespace drape {

// M(K) per unit width; W(K) = ∫₀ᴷ M dK.
class MomentCurvatureLaw {
 public:
  virtual ~MomentCurvatureLaw() = default;
  virtual double Energy(double k) const = 0;     // W [N·m/m · 1/m = N/m]
  virtual double Moment(double k) const = 0;     // M = W' [N·m/m]
  virtual double Stiffness(double k) const = 0;  // dM/dK [N·m²/m]
  struct Point {
    double energy, moment, stiffness;
  };
  // The three at once, for the element's inner loop (one branch, one piece
  // lookup); the same values as the three calls.
  virtual Point At(double k) const { return {Energy(k), Moment(k), Stiffness(k)}; }
  // |K| up to which the law is data or fit (infinity for the linear law).
  // For a curve whose data span both signs: the larger of |K_first|, |K_last|.
  virtual double ValidTo() const = 0;
};

// M = B K, B = `rigidity` [N·m²/m] > 0.
std::unique_ptr<MomentCurvatureLaw> MakeLinearLaw(double rigidity);

// M = Σₖ cₖ Kᵏ for 0 ≤ K ≤ valid_to with coefficients = {c₁, c₂, …, cₙ} (as in
// PolynomialBending: no constant term, coefficients[0] multiplies K¹), SI.
// The law is an odd function of K, M(−K) = −M(K) (the fabric bends alike both
// ways; fits are made to K ≥ 0 data), i.e. M = Σₖ cₖ |K|ᵏ⁻¹ K. Beyond
// ±valid_to it is continued linearly with the end tangent (a 5th-order fit
// turns over outside its data). Throws std::invalid_argument for no or
// non-finite coefficients or a valid_to that is not finite and > 0.
std::unique_ptr<MomentCurvatureLaw> MakePolynomialLaw(std::vector<double> coefficients,
                                                      double valid_to);

// Monotone piecewise cubic Hermite (Fritsch–Carlson: three-point initial
// tangents, zero tangent at local extrema of the data, α² + β² ≤ 9 limiter)
// through [K, M] points, K strictly increasing. The flat state is moment
// free: a point at K = 0 must have M = 0, and (0, 0) is added when K = 0 is
// not among the points. If all K ≥ 0 (or all K ≤ 0) the law is extended as an
// odd function; otherwise the points are used as given. Beyond the data the
// law is linear with the end tangent. Throws std::invalid_argument for fewer
// than 2 points, non-finite values, K not strictly increasing, or M ≠ 0 at
// K = 0.
std::unique_ptr<MomentCurvatureLaw> MakeCurveLaw(std::vector<std::array<double, 2>> points);

// Where the law's tangent dM/dK is negative for |K| ≤ ValidTo() (a softening
// fit): the curvatures [K_start, K_end] of each such interval, ascending. The
// range [−ValidTo, ValidTo] is sampled at `samples` + 1 evenly spaced points
// and each sign change is refined by bisection to rounding, so an interval
// narrower than the sample spacing may be missed. An odd law reports its
// intervals in mirrored pairs. With an infinite ValidTo (the linear law) only
// K = 0 is tested, and the answer is {} or {[−∞, ∞]}. Throws
// std::invalid_argument for samples < 1.
std::vector<std::array<double, 2>> NegativeStiffnessIntervals(const MomentCurvatureLaw& law,
                                                              int samples = 1000);

}  // namespace drape
