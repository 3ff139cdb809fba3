// The drapemeter's numbers against shapes whose shadow is known exactly: a
// skirt hanging from a disc with an n-fold wavy hem (its outline a polygon
// whose area is summed here by the shoelace, and in the limit a closed
// form), a cone, a skirt folded back under itself, and a raster of the
// triangles computed here without the library.
#include "core/measure/drape_coefficient.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "support/shadow_raster.h"

namespace drape {
namespace {

constexpr double kSpecimen = 0.15;  // [m], the standard 30 cm specimen
constexpr double kDisc = 0.09;      // [m], on 18 cm discs
constexpr double kHanging = kSpecimen - kDisc;

struct Surface {
  Eigen::MatrixX3d positions;
  Eigen::Matrix<int, Eigen::Dynamic, 4> quads;
};

// A polar mesh of the flat specimen (a centre node, `rings` rings of
// `around` nodes) deformed by `place(ρ, φ)`. The centre's quads repeat the
// centre node; their second triangle has no area.
template <typename Place>
Surface PolarSurface(int rings, int around, Place place) {
  Surface s;
  s.positions.resize(1 + rings * around, 3);
  s.positions.row(0) = place(0.0, 0.0).transpose();
  auto node = [&](int ring, int k) { return 1 + (ring - 1) * around + (k % around); };
  for (int j = 1; j <= rings; ++j)
    for (int k = 0; k < around; ++k)
      s.positions.row(node(j, k)) = place(kSpecimen * j / rings, 2 * M_PI * k / around).transpose();
  s.quads.resize(rings * around, 4);
  for (int k = 0; k < around; ++k) s.quads.row(k) << 0, node(1, k), node(1, k + 1), 0;
  for (int j = 2; j <= rings; ++j)
    for (int k = 0; k < around; ++k)
      s.quads.row((j - 1) * around + k) << node(j - 1, k), node(j, k), node(j, k + 1),
          node(j - 1, k + 1);
  return s;
}

// The material point at radius ρ, angle φ of the flat specimen: flat on the
// disc, and beyond it hanging at the horizontal reach f(φ) per unit length.
template <typename Reach>
Eigen::Vector3d Hang(double rho, double phi, Reach f) {
  if (rho <= kDisc) return {rho * std::cos(phi), rho * std::sin(phi), 0};
  const double s = rho - kDisc, reach = f(phi);
  const double r = kDisc + s * reach;
  return {r * std::cos(phi), r * std::sin(phi), -s * std::sqrt(1 - reach * reach)};
}

DrapeTestOptions StandardTest() {
  DrapeTestOptions o;
  o.disc_radius = kDisc;
  o.specimen_area = M_PI * kSpecimen * kSpecimen;
  return o;
}

// Area of the polygon through (r_k cos φ_k, r_k sin φ_k), φ_k = 2πk/n.
double StarPolygonArea(const std::vector<double>& r) {
  const int n = static_cast<int>(r.size());
  double area = 0;
  for (int k = 0; k < n; ++k) area += 0.5 * r[k] * r[(k + 1) % n] * std::sin(2 * M_PI / n);
  return area;
}

TEST(DrapeMeasure, AWavyHemGivesItsAreaItsNodesAndTheirAmplitudes) {
  const int n = 7, around = 1440;
  const double c = 0.5, a = 0.2;
  auto reach = [&](double phi) { return c + a * std::cos(n * phi); };
  const Surface s =
      PolarSurface(30, around, [&](double rho, double phi) { return Hang(rho, phi, reach); });
  const DrapeMeasurement m = MeasureDrape(s.positions, s.quads, StandardTest());

  std::vector<double> hem(around);
  for (int k = 0; k < around; ++k) hem[k] = kDisc + kHanging * reach(2 * M_PI * k / around);
  // Exact but for the union's 1 nm grid.
  EXPECT_NEAR(m.shadow_area / StarPolygonArea(hem), 1, 1e-7);
  // The smooth hem's area, π(R_d + Lc)² + (π/2)(La)²: the polygon of 1440
  // sides is within 1e-5 of it.
  const double smooth =
      M_PI * std::pow(kDisc + kHanging * c, 2) + 0.5 * M_PI * std::pow(kHanging * a, 2);
  EXPECT_NEAR(m.shadow_area / smooth, 1, 1e-5);
  const double dc =
      (smooth - M_PI * kDisc * kDisc) / (M_PI * (kSpecimen * kSpecimen - kDisc * kDisc));
  EXPECT_NEAR(m.drape_coefficient, dc, 1e-4);

  ASSERT_EQ(m.nodes.size(), size_t(n));
  for (int j = 0; j < n; ++j) {
    EXPECT_NEAR(m.nodes[j].angle, 2 * M_PI * j / n, 0.5 * M_PI / 180) << "node " << j;
    // Between rays 0.25° apart the peak is missed by at most
    // La(1 − cos(n·0.125°)) = 2.9e-6 m.
    EXPECT_NEAR(m.nodes[j].radius, kDisc + kHanging * (c + a), 3e-6);
    EXPECT_NEAR(m.nodes[j].amplitude, 2 * kHanging * a, 6e-6);
  }
  // The profile is the hem itself (each ray passes through a vertex).
  ASSERT_EQ(m.profile.radius.size(), size_t(1440));
  for (int k = 0; k < around; k += 37) EXPECT_NEAR(m.profile.radius[k], hem[k], 1e-8);
}

TEST(DrapeMeasure, AConeHasNoNodesAndTheDiscSpecimenRatioOfItsReach) {
  const double reach = 0.6;
  const Surface s = PolarSurface(20, 720, [&](double rho, double phi) {
    return Hang(rho, phi, [&](double) { return reach; });
  });
  const DrapeMeasurement m = MeasureDrape(s.positions, s.quads, StandardTest());
  const double outer = kDisc + reach * kHanging;
  // The polygon of 720 sides, exactly, and the circle's DC to (2π/720)²/6.
  EXPECT_NEAR(m.shadow_area / (0.5 * 720 * outer * outer * std::sin(2 * M_PI / 720)), 1, 1e-7);
  EXPECT_NEAR(m.drape_coefficient,
              (outer * outer - kDisc * kDisc) / (kSpecimen * kSpecimen - kDisc * kDisc),
              1e-4);
  EXPECT_TRUE(m.nodes.empty());
  // The flat specimen: DC 1.
  const Surface flat = PolarSurface(
      20, 720, [&](double rho, double phi) { return Hang(rho, phi, [](double) { return 1.0; }); });
  EXPECT_NEAR(MeasureDrape(flat.positions, flat.quads, StandardTest()).drape_coefficient, 1, 1e-4);
}

// The hem folded back under the skirt: its reach rises to 0.8 halfway down
// and falls back to 0.2 at the hem, so two layers lie over one another. The
// shadow is the disc of the widest ring, once, not the sum of the layers.
TEST(DrapeMeasure, FoldsThatLieOverOneAnotherCountOnce) {
  const int rings = 20, around = 720;
  auto place = [&](double rho, double phi) -> Eigen::Vector3d {
    if (rho <= kDisc) return {rho * std::cos(phi), rho * std::sin(phi), 0};
    const double t = (rho - kDisc) / kHanging;  // 0 at the disc's edge, 1 at the hem
    const double r = kDisc + kHanging * 0.8 * std::sin(M_PI * t) + 0.2 * kHanging * t;
    return {r * std::cos(phi), r * std::sin(phi), -kHanging * t};
  };
  const Surface s = PolarSurface(rings, around, place);
  const DrapeMeasurement m = MeasureDrape(s.positions, s.quads, StandardTest());
  double widest = 0;
  for (int j = 1; j <= rings; ++j) widest = std::max(widest, place(kSpecimen * j / rings, 0).x());
  EXPECT_NEAR(
      m.shadow_area / (0.5 * around * widest * widest * std::sin(2 * M_PI / around)), 1, 1e-7);
  double layers = 0;  // what summing the triangles' projections would give
  for (int e = 0; e < s.quads.rows(); ++e) {
    auto xy = [&](int k) { return Eigen::Vector2d(s.positions.row(s.quads(e, k)).head<2>()); };
    const Eigen::Vector2d p0 = xy(0), p1 = xy(1), p2 = xy(2), p3 = xy(3);
    auto area = [](Eigen::Vector2d a, Eigen::Vector2d b, Eigen::Vector2d c) {
      const Eigen::Vector2d u = b - a, v = c - a;
      return 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
    };
    layers += area(p0, p1, p2) + area(p0, p2, p3);
  }
  EXPECT_GT(layers, 1.2 * m.shadow_area);
}

TEST(DrapeMeasure, TheShadowAgreesWithARasterOfTheTriangles) {
  // A skirt of 5 lobes whose hem also folds under (reach 0.3 … 0.9 … 0.5).
  auto place = [&](double rho, double phi) -> Eigen::Vector3d {
    if (rho <= kDisc) return {rho * std::cos(phi), rho * std::sin(phi), 0};
    const double t = (rho - kDisc) / kHanging;
    const double lobe = 0.6 + 0.3 * std::cos(5 * phi + 0.3);
    const double r = kDisc + kHanging * lobe * (std::sin(0.5 * M_PI * t) - 0.3 * t * t);
    return {r * std::cos(phi), r * std::sin(phi), -kHanging * t};
  };
  const Surface s = PolarSurface(24, 360, place);
  const DrapeMeasurement m = MeasureDrape(s.positions, s.quads, StandardTest());
  // Independently: the triangles rasterised on a 0.1 mm grid.
  EXPECT_NEAR(m.shadow_area / test::RasterShadowArea(s.positions, s.quads, 1e-4), 1, 1e-3);
  EXPECT_EQ(m.nodes.size(), 5u);
}

// Gravity along −y instead of −z, the part turned with it: the same numbers.
TEST(DrapeMeasure, TheShadowFollowsGravitysDirection) {
  const Surface s = PolarSurface(20, 720, [](double rho, double phi) {
    return Hang(rho, phi, [](double phi) { return 0.5 + 0.2 * std::cos(6 * phi); });
  });
  const DrapeMeasurement upright = MeasureDrape(s.positions, s.quads, StandardTest());
  // x → x, y → z, z → −y: what hung along −z hangs along −y.
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::MatrixX3d turned = s.positions * turn.transpose();
  DrapeTestOptions o = StandardTest();
  o.down = turn * Eigen::Vector3d(0, 0, -1);
  const DrapeMeasurement m = MeasureDrape(turned, s.quads, o);
  EXPECT_NEAR(m.drape_coefficient, upright.drape_coefficient, 1e-9);
  EXPECT_EQ(m.nodes.size(), 6u);
}

// The rule on a profile written here: two lobes, a ripple between them too
// small to count, and a shoulder on one lobe's flank below the threshold.
TEST(DrapeNodes, ProminenceKeepsLobesAndDropsRipples) {
  RadialProfile p;
  const int n = 360;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n;
    p.angle.push_back(t);
    // Lobes at 0 (1.0) and π (0.8) over a base of 0.5, and a 1 mm ripple
    // at π/2, where the lobes have fallen to e^-27 of their height.
    auto bump = [&](double at, double width) {
      const double d = std::remainder(t - at, 2 * M_PI);
      return std::exp(-std::pow(d / width, 2));
    };
    const double r =
        0.5 + 0.5 * bump(0, 0.3) + 0.3 * bump(M_PI, 0.3) + 0.001 * bump(M_PI / 2, 0.03);
    p.radius.push_back(r);
  }
  const auto nodes = FindDrapeNodes(p, 0.01);
  ASSERT_EQ(nodes.size(), 2u);
  EXPECT_NEAR(nodes[0].angle, 0, 1e-12);
  EXPECT_NEAR(nodes[1].angle, M_PI, 1e-12);
  // Amplitudes: each lobe above the mean of the minima (0.5) on either side.
  EXPECT_NEAR(nodes[0].amplitude, 0.5, 1e-9);
  EXPECT_NEAR(nodes[1].amplitude, 0.3, 1e-9);
  EXPECT_NEAR(nodes[1].radius, 0.8, 1e-12);
  // With the threshold below the ripple it is a node as well.
  EXPECT_EQ(FindDrapeNodes(p, 0.0005).size(), 3u);
  // A round outline has none.
  RadialProfile round{p.angle, std::vector<double>(n, 0.12)};
  EXPECT_TRUE(FindDrapeNodes(round, 1e-6).empty());
}

TEST(DrapeMeasure, ADiscAsLargeAsTheSpecimenIsRefused) {
  const Surface s = PolarSurface(4, 16, [](double rho, double phi) {
    return Eigen::Vector3d(rho * std::cos(phi), rho * std::sin(phi), 0);
  });
  DrapeTestOptions o = StandardTest();
  o.disc_radius = kSpecimen;
  EXPECT_THROW(MeasureDrape(s.positions, s.quads, o), std::invalid_argument);
  o.disc_radius = 0;
  EXPECT_THROW(MeasureDrape(s.positions, s.quads, o), std::invalid_argument);
  Eigen::MatrixX3d bad = s.positions;
  bad(3, 2) = NAN;
  EXPECT_THROW(MeasureDrape(bad, s.quads, StandardTest()), std::invalid_argument);
}

}  // namespace
}  // namespace drape
