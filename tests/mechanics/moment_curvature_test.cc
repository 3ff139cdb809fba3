#include "core/mechanics/moment_curvature.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "core/io/scene_reader.h"
#include "core/model/scene.h"
#include "support/test_paths.h"

namespace drape {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Unit conversion of the paper's law. Moment per unit width has the dimension
// of a force: 1 gf·cm/cm = 1 gf = 9.80665e-3 N = 9.80665e-3 N·m/m (not
// 9.80665e-5, which is gf·cm → N·m without the per-width). With K[1/cm] =
// K[1/m] / 100, M = Σ cₖ (K[1/m]/100)ᵏ gf·cm/cm, so
//   cₖ[SI] = cₖ[paper] · 9.80665e-3 · 100⁻ᵏ   [N·m/m · mᵏ].
// c₁[SI] = 1.33387 × 9.80665e-5 = 1.30808e-4 N·m²/m is the initial rigidity.
constexpr double kGfCmPerCm = 9.80665e-3;  // N·m/m
constexpr double kPerCm = 100.0;           // 1/m
const std::vector<double> kCottonPaper = {1.33387, -2.23070, 2.36510, -1.08471, 0.17876};
constexpr double kCottonValidTo = 2.5 * kPerCm;  // 250 1/m

std::vector<double> CottonSI() {
  std::vector<double> c;
  for (std::size_t i = 0; i < kCottonPaper.size(); ++i) {
    c.push_back(kCottonPaper[i] * kGfCmPerCm * std::pow(kPerCm, -static_cast<double>(i + 1)));
  }
  return c;
}

// For RecordProperty: the measured errors in scientific notation.
std::string Sci(double v) {
  std::ostringstream os;
  os.precision(2);
  os << std::scientific << v;
  return os.str();
}

double PowerSum(const std::vector<double>& c, double k) {
  double m = 0;
  for (std::size_t i = 0; i < c.size(); ++i) m += c[i] * std::pow(k, static_cast<double>(i + 1));
  return m;
}

// ∫ₐᵇ f dK by 5-point Gauss–Legendre (exact for f of degree ≤ 9).
template <class F>
double GaussIntegral(const F& f, double a, double b) {
  static const double x[] = {
      0.0, 0.5384693101056831, -0.5384693101056831, 0.9061798459386640, -0.9061798459386640};
  static const double w[] = {0.5688888888888889,
                             0.4786286704993665,
                             0.4786286704993665,
                             0.2369268850561891,
                             0.2369268850561891};
  const double c = (a + b) / 2, r = (b - a) / 2;
  double s = 0;
  for (int i = 0; i < 5; ++i) s += w[i] * f(c + r * x[i]);
  return r * s;
}

// ∫₀ᴷ f dK by Gauss–Legendre on each interval between consecutive breaks
// (the points where the law changes piece), so the quadrature is exact.
template <class F>
double PiecewiseIntegral(const F& f, double k, std::vector<double> breaks) {
  breaks.push_back(0);
  breaks.push_back(k);
  const double lo = std::min(0.0, k), hi = std::max(0.0, k);
  std::vector<double> pts;
  for (double b : breaks) {
    if (b >= lo && b <= hi) pts.push_back(b);
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  double s = 0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) s += GaussIntegral(f, pts[i], pts[i + 1]);
  return k >= 0 ? s : -s;
}

// The finite-difference step at K: a fraction of max(|K|, 1e-3 scale), so the
// truncation error stays relative to M ≈ S K also near K = 0 while rounding
// (ε |W| / h |M| ≈ ε |K| / 2h) stays near 1e-11.
constexpr double kEnergyStep = 3e-6;  // for M against the FD of W
constexpr double kMomentStep = 1e-6;  // for S against the FD of M
double Step(double k, double scale, double fraction) {
  return fraction * std::max(std::abs(k), 1e-3 * scale);
}

struct DerivativeErrors {
  double moment = 0;              // max |M_fd − M| / max(|M|, m_floor)
  double stiffness = 0;           // same for S, stencils inside one piece
  double stiffness_straddle = 0;  // same for S, stencils across a break
};

// Central differences at each K of `ks`: M against (W(K+h) − W(K−h))/2h with
// h = Step(K, kEnergyStep); S against (M(K+h) − M(K−h))/2h with h = Step(K, kMomentStep).
// The floors (1e-6 of |M(scale)|; 1e-3 of the largest |S| on the points) keep
// the relative error meaningful where M or S pass through zero. `breaks` are
// where M'' jumps (knots, ±valid_to, 0): W is C² there, so the energy check
// stays second order, but the stiffness check across a break is first order
// (off by h [M'']/4), hence its own tolerance. The exact-integral checks below
// pin S there instead.
DerivativeErrors CheckDerivatives(const MomentCurvatureLaw& law,
                                  const std::vector<double>& ks,
                                  const std::vector<double>& breaks,
                                  double scale) {
  constexpr double kMomentTolerance = 1e-8;
  constexpr double kStiffnessTolerance = 1e-7;
  constexpr double kStraddleTolerance = 1e-3;
  const double m_floor = 1e-6 * std::abs(law.Moment(scale));
  double s_max = 0;
  for (double k : ks) s_max = std::max(s_max, std::abs(law.Stiffness(k)));
  const double s_floor = 1e-3 * s_max;
  DerivativeErrors e;
  for (double k : ks) {
    SCOPED_TRACE("K = " + std::to_string(k));
    const double hw = Step(k, scale, kEnergyStep), hm = Step(k, scale, kMomentStep);
    const double m = law.Moment(k), s = law.Stiffness(k);
    const double m_fd = (law.Energy(k + hw) - law.Energy(k - hw)) / (2 * hw);
    const double s_fd = (law.Moment(k + hm) - law.Moment(k - hm)) / (2 * hm);
    const double em = std::abs(m_fd - m) / std::max(std::abs(m), m_floor);
    const double es = std::abs(s_fd - s) / std::max(std::abs(s), s_floor);
    const bool straddles =
        std::any_of(breaks.begin(), breaks.end(), [&](double b) { return std::abs(k - b) < hm; });
    EXPECT_LE(em, kMomentTolerance) << "M = " << m << ", FD of W = " << m_fd;
    EXPECT_LE(es, straddles ? kStraddleTolerance : kStiffnessTolerance)
        << "S = " << s << ", FD of M = " << s_fd;
    e.moment = std::max(e.moment, em);
    (straddles ? e.stiffness_straddle : e.stiffness) =
        std::max(straddles ? e.stiffness_straddle : e.stiffness, es);
  }
  ::testing::Test::RecordProperty("max_rel_error_moment_fd", Sci(e.moment));
  ::testing::Test::RecordProperty("max_rel_error_stiffness_fd", Sci(e.stiffness));
  ::testing::Test::RecordProperty("max_rel_error_stiffness_fd_across_break",
                                  Sci(e.stiffness_straddle));
  return e;
}

// W(K) = ∫₀ᴷ M and M(K) = ∫₀ᴷ S, by Gauss–Legendre exact on each piece.
void ExpectExactIntegrals(const MomentCurvatureLaw& law,
                          const std::vector<double>& ks,
                          const std::vector<double>& breaks) {
  auto moment = [&](double k) { return law.Moment(k); };
  auto stiffness = [&](double k) { return law.Stiffness(k); };
  double worst_w = 0, worst_m = 0;
  for (double k : ks) {
    if (k == 0) continue;
    const double w = PiecewiseIntegral(moment, k, breaks);
    const double m = PiecewiseIntegral(stiffness, k, breaks);
    EXPECT_NEAR(law.Energy(k), w, 1e-13 * std::abs(w)) << "K = " << k;
    EXPECT_NEAR(law.Moment(k), m, 1e-12 * std::abs(m)) << "K = " << k;
    worst_w = std::max(worst_w, std::abs(law.Energy(k) - w) / std::abs(w));
    worst_m = std::max(worst_m, std::abs(law.Moment(k) - m) / std::abs(m));
  }
  ::testing::Test::RecordProperty("max_rel_error_energy_integral", Sci(worst_w));
  ::testing::Test::RecordProperty("max_rel_error_moment_integral", Sci(worst_m));
}

// Breaks at ±b for each b, and at 0.
std::vector<double> Mirrored(const std::vector<double>& breaks) {
  std::vector<double> all = {0.0};
  for (double b : breaks) {
    all.push_back(b);
    all.push_back(-b);
  }
  return all;
}

// K at and around each break (within the FD stencils), inside and beyond, at
// both signs.
std::vector<double> SamplePoints(const std::vector<double>& breaks, double scale) {
  std::vector<double> ks = {0.0,
                            1e-3 * scale,
                            0.013 * scale,
                            0.1 * scale,
                            0.37 * scale,
                            0.5 * scale,
                            0.77 * scale,
                            0.999 * scale,
                            1.2 * scale,
                            2.0 * scale,
                            5.0 * scale};
  for (double b : breaks) {
    const double hw = Step(b, scale, kEnergyStep), hm = Step(b, scale, kMomentStep);
    for (double d :
         {0.0, 0.3 * hw, -0.3 * hw, 0.7 * hw, -0.7 * hw, 3 * hw, -3 * hw, 0.5 * hm, -0.5 * hm}) {
      ks.push_back(b + d);
    }
  }
  const std::size_t n = ks.size();
  for (std::size_t i = 0; i < n; ++i) ks.push_back(-ks[i]);
  return ks;
}

void ExpectOdd(const MomentCurvatureLaw& law, const std::vector<double>& ks) {
  for (double k : ks) {
    EXPECT_EQ(law.Moment(-k), -law.Moment(k)) << "K = " << k;
    EXPECT_EQ(law.Energy(-k), law.Energy(k)) << "K = " << k;
    EXPECT_EQ(law.Stiffness(-k), law.Stiffness(k)) << "K = " << k;
  }
}

// M, S and W have no jump at k (one ulp either side).
void ExpectContinuousAt(const MomentCurvatureLaw& law, double k) {
  const double below = std::nextafter(k, -kInf), above = std::nextafter(k, kInf);
  const double m = std::abs(law.Moment(k)) + 1e-300, s = std::abs(law.Stiffness(k)) + 1e-300;
  const double w = std::abs(law.Energy(k)) + 1e-300;
  EXPECT_NEAR(law.Moment(below), law.Moment(above), 1e-12 * m) << "K = " << k;
  EXPECT_NEAR(law.Stiffness(below), law.Stiffness(above), 1e-10 * s) << "K = " << k;
  EXPECT_NEAR(law.Energy(below), law.Energy(above), 1e-12 * w) << "K = " << k;
}

// ---- linear ---------------------------------------------------------------------

TEST(MomentCurvatureLinear, IsRigidityTimesCurvatureExactly) {
  const double b = 1.30808e-4;
  auto law = MakeLinearLaw(b);
  EXPECT_EQ(law->ValidTo(), kInf);
  for (double k : {0.0, 1e-9, 0.5, -3.0, 250.0, -1e4, 7.3e6}) {
    EXPECT_EQ(law->Moment(k), b * k);
    EXPECT_EQ(law->Energy(k), 0.5 * b * k * k);
    EXPECT_EQ(law->Stiffness(k), b);
  }
  EXPECT_EQ(law->Energy(0), 0);
  const auto ks = SamplePoints({}, 100.0);
  ExpectOdd(*law, ks);
  CheckDerivatives(*law, ks, {}, 100.0);
  ExpectExactIntegrals(*law, ks, {});
  EXPECT_TRUE(NegativeStiffnessIntervals(*law).empty());
}

TEST(MomentCurvatureLinear, RejectsNonPositiveOrNonFiniteRigidity) {
  EXPECT_THROW(MakeLinearLaw(0), std::invalid_argument);
  EXPECT_THROW(MakeLinearLaw(-1e-4), std::invalid_argument);
  EXPECT_THROW(MakeLinearLaw(kNaN), std::invalid_argument);
  EXPECT_THROW(MakeLinearLaw(kInf), std::invalid_argument);
}

// ---- polynomial -----------------------------------------------------------------

TEST(MomentCurvaturePolynomial, CottonSIConversionMatchesTheSceneReader) {
  const auto c = CottonSI();
  EXPECT_NEAR(c[0], 1.30808e-4, 1e-9);  // N·m²/m
  // The paper's law in its units at K = 1.7 1/cm.
  auto law = MakePolynomialLaw(c, kCottonValidTo);
  double m_paper = 0;
  for (std::size_t i = 0; i < kCottonPaper.size(); ++i) {
    m_paper += kCottonPaper[i] * std::pow(1.7, static_cast<double>(i + 1));
  }
  EXPECT_NEAR(law->Moment(1.7 * kPerCm) / kGfCmPerCm, m_paper, 1e-13 * m_paper);
  // Independent derivation: resources/scenes/diagonal-fold.json, read with its units.
  const Scene scene = ReadScene(test::ScenesDir() / "diagonal-fold.json");
  const auto& poly = std::get<PolynomialBending>(scene.material.bending.warp);
  ASSERT_EQ(poly.coefficients.size(), c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    EXPECT_NEAR(poly.coefficients[i], c[i], 1e-12 * std::abs(c[i])) << "c" << i + 1;
  }
  EXPECT_DOUBLE_EQ(poly.valid_to, kCottonValidTo);
}

TEST(MomentCurvaturePolynomial, CottonEqualsThePolynomialInsideAndItsEndTangentBeyond) {
  const auto c = CottonSI();
  const double v = kCottonValidTo;
  auto law = MakePolynomialLaw(c, v);
  EXPECT_EQ(law->ValidTo(), v);
  EXPECT_EQ(law->Energy(0), 0);
  EXPECT_EQ(law->Moment(0), 0);
  EXPECT_DOUBLE_EQ(law->Stiffness(0), c[0]);
  for (int i = 0; i <= 100; ++i) {
    const double k = v * i / 100;
    const double m = PowerSum(c, k);
    double w = 0, s = 0;
    for (std::size_t j = 0; j < c.size(); ++j) {
      w += c[j] * std::pow(k, static_cast<double>(j + 2)) / static_cast<double>(j + 2);
      s += static_cast<double>(j + 1) * c[j] * std::pow(k, static_cast<double>(j));
    }
    EXPECT_NEAR(law->Moment(k), m, 1e-13 * std::abs(m) + 1e-300) << "K = " << k;
    EXPECT_NEAR(law->Energy(k), w, 1e-13 * std::abs(w) + 1e-300) << "K = " << k;
    EXPECT_NEAR(law->Stiffness(k), s, 1e-13 * std::abs(s)) << "K = " << k;
  }
  const double mv = law->Moment(v), sv = law->Stiffness(v), wv = law->Energy(v);
  for (double d : {1e-9, 0.1, 10.0, 250.0, 1e4}) {
    const double k = v + d;
    EXPECT_EQ(law->Stiffness(k), sv) << "K = " << k;
    EXPECT_NEAR(law->Moment(k), mv + sv * d, 1e-14 * (mv + sv * d)) << "K = " << k;
    const double w = wv + mv * d + 0.5 * sv * d * d;
    EXPECT_NEAR(law->Energy(k), w, 1e-14 * w) << "K = " << k;
  }
  ExpectContinuousAt(*law, v);
  ExpectContinuousAt(*law, -v);
  ExpectContinuousAt(*law, 0);
}

TEST(MomentCurvaturePolynomial, CottonEnergyIsTheIntegralOfTheMoment) {
  auto law = MakePolynomialLaw(CottonSI(), kCottonValidTo);
  const double v = kCottonValidTo;
  ExpectExactIntegrals(*law, SamplePoints({v}, v), Mirrored({v}));
}

TEST(MomentCurvaturePolynomial, CottonDerivativesMatchFiniteDifferences) {
  auto law = MakePolynomialLaw(CottonSI(), kCottonValidTo);
  const double v = kCottonValidTo;
  const auto ks = SamplePoints({v}, v);
  ExpectOdd(*law, ks);
  CheckDerivatives(*law, ks, Mirrored({v}), v);
}

// With even powers the law is M = Σ cₖ |K|ᵏ⁻¹ K, not the raw polynomial at K < 0.
TEST(MomentCurvaturePolynomial, IsOddEvenWithEvenPowers) {
  auto law = MakePolynomialLaw({2.0, 3.0}, 1.0);  // M = 2K + 3K|K|
  EXPECT_DOUBLE_EQ(law->Moment(0.5), 1.75);
  EXPECT_DOUBLE_EQ(law->Moment(-0.5), -1.75);
  EXPECT_DOUBLE_EQ(law->Energy(-0.5), 0.25 + 0.125);  // K² + |K|³
  EXPECT_DOUBLE_EQ(law->Stiffness(-0.5), 5.0);
  const auto ks = SamplePoints({1.0}, 1.0);
  ExpectOdd(*law, ks);
  CheckDerivatives(*law, ks, Mirrored({1.0}), 1.0);
  ExpectExactIntegrals(*law, ks, Mirrored({1.0}));
}

TEST(MomentCurvaturePolynomial, CottonHasNoNegativeStiffnessUpTo2Point5PerCm) {
  auto law = MakePolynomialLaw(CottonSI(), kCottonValidTo);
  EXPECT_TRUE(NegativeStiffnessIntervals(*law).empty());
  EXPECT_TRUE(NegativeStiffnessIntervals(*law, 100000).empty());
  // The tangent dips but stays positive: its minimum on [0, 2.5] 1/cm is
  // 0.35907 gf·cm²/cm at K = 1.8901 1/cm (where d²M/dK² = 0), against
  // 1.33387 at K = 0 and 1.64568 at 2.5 1/cm.
  double s_min = kInf, k_min = 0;
  for (int i = 0; i <= 250000; ++i) {
    const double k = kCottonValidTo * i / 250000;
    if (law->Stiffness(k) < s_min) {
      s_min = law->Stiffness(k);
      k_min = k;
    }
  }
  const double s_unit = kGfCmPerCm / kPerCm;  // gf·cm²/cm in N·m²/m
  EXPECT_NEAR(s_min / s_unit, 0.359066, 1e-6);
  EXPECT_NEAR(k_min / kPerCm, 1.8901, 1e-4);
  EXPECT_NEAR(law->Stiffness(kCottonValidTo) / s_unit, 1.6456825, 1e-7);
  ::testing::Test::RecordProperty("min_stiffness_gf_cm2_per_cm", Sci(s_min / s_unit));
  ::testing::Test::RecordProperty("at_K_per_cm", std::to_string(k_min / kPerCm));
}

TEST(MomentCurvaturePolynomial, FindsTheIntervalOfASofteningFit) {
  // M = K − K² + K³/4: dM/dK = 1 − 2K + ¾K² = ¾(K − ⅔)(K − 2) < 0 on (⅔, 2).
  auto law = MakePolynomialLaw({1.0, -1.0, 0.25}, 3.0);
  const auto found = NegativeStiffnessIntervals(*law);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0][0], -2.0, 1e-12);
  EXPECT_NEAR(found[0][1], -2.0 / 3.0, 1e-12);
  EXPECT_NEAR(found[1][0], 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(found[1][1], 2.0, 1e-12);

  // M = K − K³ on |K| ≤ 1: dM/dK = 1 − 3K² < 0 for |K| > 1/√3, up to valid_to.
  auto cubic = MakePolynomialLaw({1.0, 0.0, -1.0}, 1.0);
  const auto ends = NegativeStiffnessIntervals(*cubic, 999);
  ASSERT_EQ(ends.size(), 2u);
  EXPECT_EQ(ends[0][0], -1.0);
  EXPECT_NEAR(ends[0][1], -1 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(ends[1][0], 1 / std::sqrt(3.0), 1e-12);
  EXPECT_EQ(ends[1][1], 1.0);
  // Beyond valid_to the law keeps the (negative) end tangent, but is not reported there.
  EXPECT_DOUBLE_EQ(cubic->Stiffness(5.0), -2.0);

  EXPECT_THROW(NegativeStiffnessIntervals(*law, 0), std::invalid_argument);
}

TEST(MomentCurvaturePolynomial, RejectsBadInput) {
  EXPECT_THROW(MakePolynomialLaw({}, 1.0), std::invalid_argument);
  EXPECT_THROW(MakePolynomialLaw({1.0}, 0.0), std::invalid_argument);
  EXPECT_THROW(MakePolynomialLaw({1.0}, -2.0), std::invalid_argument);
  EXPECT_THROW(MakePolynomialLaw({1.0}, kInf), std::invalid_argument);
  EXPECT_THROW(MakePolynomialLaw({1.0}, kNaN), std::invalid_argument);
  EXPECT_THROW(MakePolynomialLaw({1.0, kNaN}, 1.0), std::invalid_argument);
  EXPECT_THROW(MakePolynomialLaw({1.0, -kInf}, 1.0), std::invalid_argument);
  try {
    MakePolynomialLaw({}, 1.0);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no coefficients"), std::string::npos) << e.what();
  }
}

// ---- curve ----------------------------------------------------------------------

// A Kawabata-like K ≥ 0 curve in SI with steep and flat stretches, so the
// Fritsch–Carlson limiter acts.
std::vector<std::array<double, 2>> KawabataLike() {
  return {{0.0, 0.0},
          {20.0, 1.5e-3},
          {50.0, 2.0e-3},
          {80.0, 2.2e-3},
          {120.0, 3.5e-3},
          {170.0, 3.6e-3},
          {250.0, 6.0e-3}};
}

std::vector<double> Knots(const std::vector<std::array<double, 2>>& p) {
  std::vector<double> k;
  for (const auto& q : p) k.push_back(q[0]);
  return k;
}

TEST(MomentCurvatureCurve, PassesThroughItsPointsAndIsOdd) {
  const auto p = KawabataLike();
  auto law = MakeCurveLaw(p);
  EXPECT_EQ(law->ValidTo(), 250.0);
  EXPECT_EQ(law->Energy(0), 0);
  for (const auto& q : p) {
    EXPECT_EQ(law->Moment(q[0]), q[1]) << "K = " << q[0];
    EXPECT_EQ(law->Moment(-q[0]), -q[1]) << "K = " << q[0];
  }
  ExpectOdd(*law, SamplePoints(Knots(p), 250.0));
  for (const auto& q : p) {
    ExpectContinuousAt(*law, q[0]);
    ExpectContinuousAt(*law, -q[0]);
  }
}

TEST(MomentCurvatureCurve, DerivativesMatchFiniteDifferencesAcrossKnots) {
  const auto p = KawabataLike();
  auto law = MakeCurveLaw(p);
  const auto ks = SamplePoints(Knots(p), 250.0);
  CheckDerivatives(*law, ks, Mirrored(Knots(p)), 250.0);
}

TEST(MomentCurvatureCurve, EnergyIsTheExactIntegralOfEachPiece) {
  const auto p = KawabataLike();
  auto law = MakeCurveLaw(p);
  ExpectExactIntegrals(*law, SamplePoints(Knots(p), 250.0), Mirrored(Knots(p)));
}

TEST(MomentCurvatureCurve, IsMonotoneWhereTheDataAre) {
  // Rising, falling, flat, rising: each interval must keep its data's direction.
  const std::vector<std::array<double, 2>> p = {
      {0.0, 0.0}, {1.0, 2.0}, {2.0, 3.0}, {3.0, 2.5}, {4.0, 2.5}, {5.0, 4.0}, {5.5, 9.0}};
  for (const auto& data : {p, KawabataLike()}) {
    auto law = MakeCurveLaw(data);
    for (std::size_t i = 0; i + 1 < data.size(); ++i) {
      const double k0 = data[i][0], k1 = data[i + 1][0];
      const double dir = data[i + 1][1] - data[i][1];
      const int n = 2000;
      double prev = law->Moment(k0);
      for (int j = 1; j <= n; ++j) {
        const double k = k0 + (k1 - k0) * j / n;
        const double m = law->Moment(k);
        const double slack = 1e-15 * std::abs(m);
        if (dir > 0) {
          EXPECT_GE(m, prev - slack) << "K = " << k;
          EXPECT_GE(law->Stiffness(k), 0) << "K = " << k;
        } else if (dir < 0) {
          EXPECT_LE(m, prev + slack) << "K = " << k;
          EXPECT_LE(law->Stiffness(k), 0) << "K = " << k;
        } else {
          EXPECT_EQ(m, data[i][1]) << "K = " << k;
        }
        prev = m;
      }
    }
  }
  // The Kawabata-like data rise everywhere: no softening reported.
  EXPECT_TRUE(NegativeStiffnessIntervals(*MakeCurveLaw(KawabataLike()), 100000).empty());
  // The falling stretch (2, 3), whose end tangents are zero (extremum, flat).
  auto law = MakeCurveLaw(p);
  const auto found = NegativeStiffnessIntervals(*law);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_NEAR(found[0][0], -3.0, 1e-9);
  EXPECT_NEAR(found[0][1], -2.0, 1e-9);
  EXPECT_NEAR(found[1][0], 2.0, 1e-9);
  EXPECT_NEAR(found[1][1], 3.0, 1e-9);
  const auto ks = SamplePoints(Knots(p), 5.5);
  CheckDerivatives(*law, ks, Mirrored(Knots(p)), 5.5);
  ExpectExactIntegrals(*law, ks, Mirrored(Knots(p)));
}

TEST(MomentCurvatureCurve, PointsOnAStraightLineGiveThatLine) {
  const double b = 1.30808e-4;
  // Uneven spacing; with and without the origin; across K = 0.
  const std::vector<std::vector<double>> sets = {
      {0.0, 13.0, 37.5, 90.1, 250.0}, {10.0, 20.0, 50.0}, {-30.0, -5.0, 12.0, 40.0}};
  for (const auto& ks : sets) {
    std::vector<std::array<double, 2>> p;
    for (double k : ks) p.push_back({k, b * k});
    auto law = MakeCurveLaw(p);
    for (int i = -600; i <= 600; ++i) {
      const double k = 0.5 * i + 0.01;
      EXPECT_NEAR(law->Moment(k), b * k, 1e-13 * std::abs(b * k)) << "K = " << k;
      EXPECT_NEAR(law->Stiffness(k), b, 1e-12 * b) << "K = " << k;
      EXPECT_NEAR(law->Energy(k), 0.5 * b * k * k, 1e-13 * 0.5 * b * k * k) << "K = " << k;
    }
    EXPECT_EQ(law->Energy(0), 0);
    EXPECT_EQ(law->Moment(0), 0);
  }
}

TEST(MomentCurvatureCurve, AddsTheOriginAndMirrorsOneSidedData) {
  // K > 0 only: (0, 0) is added and the law is odd.
  const std::vector<std::array<double, 2>> pos = {{10.0, 1e-3}, {40.0, 2e-3}, {90.0, 5e-3}};
  auto law = MakeCurveLaw(pos);
  EXPECT_EQ(law->Moment(0), 0);
  EXPECT_EQ(law->Energy(0), 0);
  EXPECT_EQ(law->ValidTo(), 90.0);
  ExpectOdd(*law, SamplePoints(Knots(pos), 90.0));
  // K ≤ 0 only: the same odd law.
  std::vector<std::array<double, 2>> neg;
  for (auto it = pos.rbegin(); it != pos.rend(); ++it) neg.push_back({-(*it)[0], -(*it)[1]});
  auto mirrored = MakeCurveLaw(neg);
  for (double k : SamplePoints(Knots(pos), 90.0)) {
    EXPECT_EQ(mirrored->Moment(k), law->Moment(k)) << "K = " << k;
    EXPECT_EQ(mirrored->Energy(k), law->Energy(k)) << "K = " << k;
  }
}

TEST(MomentCurvatureCurve, TwoSidedDataAreUsedAsGiven) {
  // Stiffer in one direction; K = 0 is not a point and (0, 0) is inserted.
  const std::vector<std::array<double, 2>> p = {
      {-100.0, -2e-3}, {-40.0, -1.5e-3}, {-10.0, -0.8e-3}, {25.0, 1e-3}, {80.0, 1.6e-3}};
  auto law = MakeCurveLaw(p);
  EXPECT_EQ(law->ValidTo(), 100.0);
  EXPECT_EQ(law->Energy(0), 0);
  EXPECT_EQ(law->Moment(0), 0);
  for (const auto& q : p) EXPECT_EQ(law->Moment(q[0]), q[1]) << "K = " << q[0];
  EXPECT_NE(law->Moment(-25.0), -law->Moment(25.0));
  std::vector<double> breaks = Knots(p);
  breaks.push_back(0);
  std::vector<double> ks = SamplePoints(breaks, 100.0);
  CheckDerivatives(*law, ks, breaks, 100.0);
  ExpectExactIntegrals(*law, ks, breaks);
  for (double k : ks) {
    if (k != 0) {
      EXPECT_GT(law->Energy(k), 0) << "K = " << k;
    }
  }
  // Linear beyond both ends with the end tangents.
  EXPECT_EQ(law->Stiffness(-1000.0), law->Stiffness(-100.5));
  EXPECT_NEAR(law->Stiffness(-1000.0), law->Stiffness(-100.0), 1e-14 * law->Stiffness(-100.0));
  EXPECT_EQ(law->Stiffness(1000.0), law->Stiffness(80.0));
}

TEST(MomentCurvatureCurve, RejectsBadInput) {
  using P = std::vector<std::array<double, 2>>;
  EXPECT_THROW(MakeCurveLaw(P{}), std::invalid_argument);
  EXPECT_THROW(MakeCurveLaw(P{{1.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(MakeCurveLaw(P{{0.0, 0.0}, {2.0, 1.0}, {2.0, 1.5}}), std::invalid_argument);
  EXPECT_THROW(MakeCurveLaw(P{{0.0, 0.0}, {2.0, 1.0}, {1.0, 1.5}}), std::invalid_argument);
  EXPECT_THROW(MakeCurveLaw(P{{0.0, 0.0}, {kNaN, 1.0}}), std::invalid_argument);
  EXPECT_THROW(MakeCurveLaw(P{{0.0, 0.0}, {1.0, kInf}}), std::invalid_argument);
  EXPECT_THROW(MakeCurveLaw(P{{0.0, 1e-4}, {1.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(MakeCurveLaw(P{{-1.0, -1.0}, {0.0, 0.5}, {1.0, 1.0}}), std::invalid_argument);
  try {
    MakeCurveLaw(P{{0.0, 0.0}, {2.0, 1.0}, {2.0, 1.5}});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("strictly increasing"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace drape

namespace drape {
namespace {

TEST(MomentCurvatureLaw, AtGivesTheThreeSeparateValues) {
  std::vector<std::unique_ptr<MomentCurvatureLaw>> laws;
  laws.push_back(MakeLinearLaw(1.3e-4));
  laws.push_back(MakePolynomialLaw(CottonSI(), kCottonValidTo));
  laws.push_back(MakeCurveLaw({{50, 0.004}, {100, 0.007}, {200, 0.009}}));
  laws.push_back(MakeCurveLaw({{-100, -0.01}, {0, 0}, {80, 0.004}, {160, 0.012}}));
  for (const auto& law : laws)
    for (double k = -600; k <= 600; k += 7.3) {
      const MomentCurvatureLaw::Point p = law->At(k);
      // Equal up to the order in which the compiler fuses multiply-adds.
      EXPECT_DOUBLE_EQ(p.energy, law->Energy(k)) << k;
      EXPECT_DOUBLE_EQ(p.moment, law->Moment(k)) << k;
      EXPECT_DOUBLE_EQ(p.stiffness, law->Stiffness(k)) << k;
    }
}

}  // namespace
}  // namespace drape
