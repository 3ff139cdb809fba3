// Least-squares fit of the paper's bending law, M = Σₖ cₖ Kᵏ (k = 1…n), to
// measured moment–curvature points: what `drape material fit` prints and the
// material dialog will show.
//
// The law is applied as an odd function, M(K) = sign(K) Σ cₖ |K|ᵏ (the
// fabric bends alike both ways; MakePolynomialLaw), so points of both signs
// are fitted together through |K| and sign(K) M.
#pragma once

#include <array>
#include <vector>

namespace drape {

struct PolynomialFit {
  std::vector<double> coefficients;   // c₁…cₙ, in the units of the points
  double rms_error = 0;               // √(mean of (M_fit − M)²), moment units
  std::array<double, 2> range{0, 0};  // smallest and largest K fitted
  double valid_to = 0;                // largest |K| fitted
};

// Throws std::invalid_argument for fewer points than coefficients, a degree
// outside 1…9, sizes that differ, or non-finite values.
PolynomialFit FitOddPolynomial(const std::vector<double>& curvature,
                               const std::vector<double>& moment,
                               int degree);

struct CurveFit {
  std::vector<std::array<double, 2>> points;  // [K, M] knots, K > 0 ascending (0 implied)
  double rms_error = 0;                       // of the monotone curve through them
  std::array<double, 2> range{0, 0};          // smallest and largest K fitted
  double valid_to = 0;                        // largest |K| fitted
};

// A monotone spline for the `curve` law that smooths measurement noise:
// `knots` evenly spaced curvatures K_j = j K_max/knots (j = 1 … knots), the
// moment at each from a local least-squares line through the points within
// one knot spacing (tent weights), and MakeCurveLaw's Fritsch–Carlson cubic
// through (0, 0) and them. Data of both signs are folded as for the
// polynomial. Throws std::invalid_argument for knots outside 2 … 50, a
// knot with fewer than 2 points near it, sizes that differ, or non-finite
// values.
CurveFit FitMonotoneCurve(const std::vector<double>& curvature,
                          const std::vector<double>& moment,
                          int knots);

}  // namespace drape
