// Membrane and bending patch tests on the distorted MacNeal–Harder patch
// (MacNeal & Harder 1985, Finite Elements in Analysis and Design 1): the
// corner nodes are prescribed from an exact field and clamped, the interior
// nodes start at the reference state, and Newton must bring them onto the
// exact field.
//
// Membrane: φ = F X with F = R·U (U an in-plane stretch and shear, R a large
// rotation about a tilted axis), Λ = R. The Green–Lagrange strain is constant
// and bending and shear vanish, so the element reproduces it to round-off even
// though the rotation is finite.
//
// Bending: w = ½(κx x² + κy y² + 2κxy xy), in-plane displacement zero,
// t = normalize(−w,x, −w,y, 1). Curvature is constant and the MITC4 shear at
// the tying points vanishes to first order, so the linear response is exact;
// the geometric nonlinearity (membrane strain ½ w,i w,j) enters at
// O((L/h)² (κL)²) relative, which sets how small κ must be.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "core/continuation/equilibrium_system.h"
#include "core/continuation/newton_corrector.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/mechanics/director.h"
#include "core/model/mesh.h"
#include "core/model/scene.h"

namespace drape {
namespace {

constexpr double kLx = 0.24, kLy = 0.12;  // the patch [m]
constexpr double kThickness = 0.001;      // [m]
constexpr int kCorners[4] = {0, 1, 2, 3};
constexpr int kInterior[4] = {4, 5, 6, 7};

Mesh MacNealHarderPatch() {
  Mesh mesh;
  mesh.positions.resize(8, 3);
  mesh.positions << 0.00, 0.00, 0,  //
      0.24, 0.00, 0,                //
      0.24, 0.12, 0,                //
      0.00, 0.12, 0,                //
      0.04, 0.02, 0,                //
      0.18, 0.03, 0,                //
      0.16, 0.08, 0,                //
      0.08, 0.08, 0;
  mesh.quads.resize(5, 4);
  mesh.quads << 0, 1, 5, 4,  // bottom
      1, 2, 6, 5,            // right
      2, 3, 7, 6,            // top
      3, 0, 4, 7,            // left
      4, 5, 6, 7;            // centre
  return mesh;
}

Scene PatchScene() {
  Scene scene;
  scene.name = "MacNeal-Harder patch";
  scene.fabric.outline = RectangleOutline{{kLx, kLy}, {kLx / 2, kLy / 2}};
  scene.material.thickness = kThickness;
  scene.material.areal_weight = 0.0;
  scene.material.membrane = IsotropicMembrane{1e6, 0.25};
  scene.material.bending.warp = LinearBending{};
  return scene;
}

ShellModel PatchModel() {
  return BuildShellModel(PatchScene(), MacNealHarderPatch());
}

// An exact field: position and orientation of the material point X = (x, y).
struct ExactField {
  std::function<Eigen::Vector3d(double x, double y)> position;
  std::function<Eigen::Matrix3d(double x, double y)> rotation;
};

// The reference state with the corners (and, when asked, the interior nodes)
// on the exact field.
ShellState Prescribe(const ShellModel& model, const ExactField& field, bool interior_too) {
  ShellState state = model.reference;
  for (int i = 0; i < model.NodeCount(); ++i) {
    const bool corner =
        std::find(std::begin(kCorners), std::end(kCorners), i) != std::end(kCorners);
    if (!corner && !interior_too) continue;
    const double x = model.mesh.positions(i, 0), y = model.mesh.positions(i, 1);
    state.positions.row(i) = field.position(x, y).transpose();
    state.rotations[i] = field.rotation(x, y);
  }
  return state;
}

DofMap ClampedCorners(const ShellModel& model) {
  DofMap dofs(model.NodeCount());
  for (int c : kCorners) dofs.FixNode(c, Fixity::kClamp);
  return dofs;
}

// Newton with zero external force.
NewtonOutcome SolvePatch(EquilibriumSystem& system,
                         const NewtonSettings& settings,
                         ShellState& state) {
  const int n = static_cast<int>(system.InternalForce().size());
  return SolveEquilibrium(
      system,
      [n](const ShellState&) -> Eigen::VectorXd { return Eigen::VectorXd::Zero(n); },
      settings,
      state,
      nullptr);
}

std::string History(const NewtonOutcome& out) {
  std::string s;
  for (double r : out.residuals) {
    char buf[32];
    std::snprintf(buf, sizeof buf, " %.2e", r);
    s += buf;
  }
  return s;
}

// Largest |φ − φ_exact| and |t − t_exact| over the interior nodes.
struct NodalErrors {
  double position = 0;
  double in_plane = 0;  // of the x, y components
  double normal = 0;    // of the z component
  double director = 0;
};

NodalErrors InteriorErrors(const ShellModel& model,
                           const ExactField& field,
                           const ShellState& state) {
  NodalErrors e;
  for (int i : kInterior) {
    const double x = model.mesh.positions(i, 0), y = model.mesh.positions(i, 1);
    const Eigen::Vector3d d = state.positions.row(i).transpose() - field.position(x, y);
    e.position = std::max(e.position, d.norm());
    e.in_plane = std::max(e.in_plane, d.head<2>().norm());
    e.normal = std::max(e.normal, std::abs(d.z()));
    const Eigen::Vector3d dt = state.Director(i) - field.rotation(x, y).col(2);
    e.director = std::max(e.director, dt.norm());
  }
  return e;
}

// ---- mesh ------------------------------------------------------------------

TEST(PatchMesh, QuadsAreCounterClockwiseAndTileTheRectangle) {
  const Mesh mesh = MacNealHarderPatch();
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    for (int k = 0; k < 4; ++k) {  // every corner convex, turning left
      const Eigen::Vector3d p = mesh.positions.row(mesh.quads(e, k));
      const Eigen::Vector3d next = mesh.positions.row(mesh.quads(e, (k + 1) % 4));
      const Eigen::Vector3d prev = mesh.positions.row(mesh.quads(e, (k + 3) % 4));
      EXPECT_GT((next - p).cross(prev - p).z(), 0) << "element " << e << " corner " << k;
    }
  }
  EXPECT_NEAR(ProjectedArea(mesh), kLx * kLy, 1e-15);
  const ShellModel model = PatchModel();
  for (int i = 0; i < model.NodeCount(); ++i)
    EXPECT_TRUE(model.reference.rotations[i].isIdentity(1e-15)) << "node " << i;
}

// ---- membrane ----------------------------------------------------------------

struct MembraneCase {
  const char* name;
  Eigen::Vector3d axis;  // of R, any length
  double angle;          // of R [rad]
  Eigen::Matrix2d u;     // in-plane part of U
};

// The field with U replaced by I + s(U − I) and the rotation angle scaled
// by r, so that the corners can be moved there in steps.
ExactField MembraneField(const MembraneCase& c, double s = 1.0, double r = 1.0) {
  const Eigen::Matrix3d rotation = ExpRotation(r * c.angle * c.axis.normalized());
  Eigen::Matrix3d u = Eigen::Matrix3d::Identity();
  u.topLeftCorner<2, 2>() += s * (c.u - Eigen::Matrix2d::Identity());
  const Eigen::Matrix3d f = rotation * u;
  return {[f](double x, double y) -> Eigen::Vector3d { return f * Eigen::Vector3d(x, y, 0); },
          [rotation](double, double) -> Eigen::Matrix3d { return rotation; }};
}

Eigen::Matrix2d InPlane(double a, double b, double c, double d) {
  Eigen::Matrix2d m;
  m << a, b, c, d;
  return m;
}

// Both principal stretches above 1 in every case, so the exact state is a
// stable equilibrium of the thin patch (compression would buckle it).
const MembraneCase kMembraneCases[] = {
    {"stretch_shear_1rad_tilted", {1, 2, 3}, 1.0, InPlane(1.03, 0.01, 0.005, 1.02)},
    {"shear_2p5rad", {-1, 0.5, 0.3}, 2.5, InPlane(1.02, 0.015, -0.01, 1.04)},
    {"large_stretch_in_plane_spin", {0.2, -0.1, 1}, 0.7, InPlane(1.2, 0.05, 0.0, 1.1)},
    {"flip_upside_down", {1, 1, 0}, 3.0, InPlane(1.01, 0.0, 0.02, 1.01)},
};

// Steps of the corner motion (see below). A rotation step with an in-plane
// spin compresses parts of the sheet until the interior follows; it must stay
// below the tension: stretch_shear_1rad_tilted (2 % tension, spin 0.8 of the
// angle) still converges with 0.01 rad steps and goes astray with 0.02 rad.
constexpr double kMembraneStepStrain = 0.05;
constexpr double kMembraneStepAngle = 0.005;  // [rad]

class PatchMembrane : public ::testing::TestWithParam<MembraneCase> {};

TEST_P(PatchMembrane, ReproducesAffineFiniteDeformationToRoundOff) {
  const MembraneCase& c = GetParam();
  const ShellModel model = PatchModel();
  const DofMap dofs = ClampedCorners(model);
  const ExactField field = MembraneField(c);

  // At the exact state: the energy is that of the constant Green–Lagrange
  // strain E = ½(UᵀU − I), and the interior nodes are in equilibrium.
  {
    const ShellState exact = Prescribe(model, field, /*interior_too=*/true);
    EquilibriumSystem system(model, dofs);
    const double energy = system.Assemble(exact, /*with_tangent=*/false);
    const Eigen::Matrix2d strain = 0.5 * (c.u.transpose() * c.u - Eigen::Matrix2d::Identity());
    const Eigen::Vector3d e(strain(0, 0), strain(1, 1), 2 * strain(0, 1));
    const double expected = 0.5 * kLx * kLy * e.dot(model.section.membrane * e);
    EXPECT_NEAR(energy, expected, 1e-12 * expected);
    const double reaction = system.InternalForce().cwiseAbs().maxCoeff();
    EXPECT_GT(reaction, 0.1);
    EXPECT_LE(system.Residual(Eigen::VectorXd::Zero(model.DofCount())).cwiseAbs().maxCoeff(),
              1e-12 * reaction);
  }

  // Newton from the reference state straight to a finite rotation of the
  // corners finds other equilibria (interior directors turned over, negative
  // pivots) or diverges: an unstressed thin sheet has almost no stiffness
  // against the out-of-plane motion. So the corners are moved in steps, each
  // solved from the last, the first from the reference state: first the
  // in-plane stretch (which puts the sheet in tension), then the rotation.
  ShellState state = model.reference;
  const NodalErrors before = InteriorErrors(model, field, state);
  EXPECT_GT(before.position, 0.01 * kLx);  // the solver has to move them

  NewtonSettings settings;
  // Below the reach of double precision: the iteration ends at the
  // residual's round-off floor (reactions are O(1) N).
  settings.tolerance = 1e-14;
  settings.max_iterations = 60;
  const double stretch = (c.u - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff();
  const int stretch_steps = std::max(1, static_cast<int>(std::ceil(stretch / kMembraneStepStrain)));
  const int rotation_steps = std::max(1, static_cast<int>(std::ceil(c.angle / kMembraneStepAngle)));
  int iterations = 0, most_iterations = 0;
  EquilibriumSystem system(model, dofs);
  for (int k = 1; k <= stretch_steps + rotation_steps; ++k) {
    const ExactField at =
        MembraneField(c,
                      std::min(1.0, static_cast<double>(k) / stretch_steps),
                      static_cast<double>(std::max(0, k - stretch_steps)) / rotation_steps);
    for (int i : kCorners) {
      const double x = model.mesh.positions(i, 0), y = model.mesh.positions(i, 1);
      state.positions.row(i) = at.position(x, y).transpose();
      state.rotations[i] = at.rotation(x, y);
    }
    const NewtonOutcome out = SolvePatch(system, settings, state);
    ASSERT_EQ(out.status, NewtonOutcome::Status::kConverged)
        << "step " << k << ": " << out.reason << History(out);
    EXPECT_EQ(out.negative_pivots, 0) << "step " << k;
    iterations += out.iterations;
    most_iterations = std::max(most_iterations, out.iterations);
  }

  const NodalErrors after = InteriorErrors(model, field, state);
  std::printf(
      "  [membrane %s] %d steps, %d Newton iterations (at most %d a step): "
      "|dphi|/L %.1e, |dt| %.1e\n",
      c.name,
      stretch_steps + rotation_steps,
      iterations,
      most_iterations,
      after.position / kLx,
      after.director);
  EXPECT_LE(after.position, 1e-10 * kLx);
  EXPECT_LE(after.director, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Patch,
                         PatchMembrane,
                         ::testing::ValuesIn(kMembraneCases),
                         [](const auto& info) { return std::string(info.param.name); });

// ---- bending -------------------------------------------------------------------

struct BendingCase {
  const char* name;
  double kx, ky, kxy;  // curvatures, scaled so that the largest is κL = kappa_l
};

ExactField BendingField(double kx, double ky, double kxy) {
  return {[=](double x, double y) -> Eigen::Vector3d {
            return {x, y, 0.5 * (kx * x * x + ky * y * y + 2 * kxy * x * y)};
          },
          [=](double x, double y) -> Eigen::Matrix3d {
            const Eigen::Vector3d t =
                Eigen::Vector3d(-(kx * x + kxy * y), -(ky * y + kxy * x), 1).normalized();
            return RotationFromDirector(t);
          }};
}

ExactField BendingField(const BendingCase& c, double kappa_l) {
  const double k = kappa_l / kLx;
  return BendingField(k * c.kx, k * c.ky, k * c.kxy);
}

// Scales of the exact field over the patch's nodes: max |w| and max |t_xy|.
struct BendingScales {
  double w = 0, slope = 0;
};

BendingScales Scales(const ShellModel& model, const ExactField& field) {
  BendingScales s;
  for (int i = 0; i < model.NodeCount(); ++i) {
    const double x = model.mesh.positions(i, 0), y = model.mesh.positions(i, 1);
    s.w = std::max(s.w, std::abs(field.position(x, y).z()));
    s.slope = std::max(s.slope, field.rotation(x, y).col(2).head<2>().norm());
  }
  return s;
}

const BendingCase kBendingCases[] = {
    {"kappa_x", 1, 0, 0},
    {"kappa_y", 0, 1, 0},
    {"twist", 0, 0, 1},
    {"mixed", 1, -0.6, 0.8},
};

struct BendingResult {
  NewtonOutcome outcome;
  BendingScales scale;
  NodalErrors before, after;
};

BendingResult SolveBending(const BendingCase& c, double kappa_l) {
  const ShellModel model = PatchModel();
  const DofMap dofs = ClampedCorners(model);
  const ExactField field = BendingField(c, kappa_l);
  BendingResult r;
  r.scale = Scales(model, field);
  ShellState state = Prescribe(model, field, /*interior_too=*/false);
  r.before = InteriorErrors(model, field, state);
  // The residual stalls at the round-off of the membrane forces (E h = 1e3 N/m
  // on coordinates of 0.24 m), which is not small against bending forces of
  // a tiny curvature: the iteration ends at that round-off floor.
  NewtonSettings settings;
  settings.tolerance = 1e-14;
  settings.max_iterations = 30;
  EquilibriumSystem system(model, dofs);
  r.outcome = SolvePatch(system, settings, state);
  r.after = InteriorErrors(model, field, state);
  return r;
}

// Largest generalised force over some nodes, split into the in-plane force
// |F_xy| [N], the transverse force |F_z| [N] and the moment |(M_a, M_b)| [N·m]
// (the rotation components are in each node's orthonormal tangent basis).
struct ForceSizes {
  double in_plane = 0, transverse = 0, moment = 0;
};

template <typename Nodes>
ForceSizes Sizes(const Eigen::VectorXd& full, const Nodes& nodes) {
  ForceSizes s;
  for (int i : nodes) {
    s.in_plane = std::max(s.in_plane, full.segment<2>(kDofsPerNode * i).norm());
    s.transverse = std::max(s.transverse, std::abs(full(kDofsPerNode * i + 2)));
    s.moment = std::max(s.moment, full.segment<2>(kDofsPerNode * i + 3).norm());
  }
  return s;
}

class PatchBending : public ::testing::TestWithParam<BendingCase> {};

// The geometric nonlinearity is the membrane strain ½ w,i w,j, held by the
// clamped corners: relative to bending it is O(12 (L/h)² (κL)²) with
// L/h = 240, i.e. ~1e-5 of w at κL = 1e-5 (measured: |Δw|/w 1e-7, |Δt|/t_xy
// 3e-7, |Δu_xy|/w 1.2e-6). At κL = 1e-6 all three are far below 1e-6, while
// w ~ 1e-7 m stays ~1e9 times the round-off of the coordinates.
constexpr double kKappaL = 1e-6;
constexpr double kBendingTolerance = 1e-6;

TEST_P(PatchBending, ReproducesConstantCurvature) {
  const BendingCase& c = GetParam();
  const BendingResult r = SolveBending(c, kKappaL);
  ASSERT_EQ(r.outcome.status, NewtonOutcome::Status::kConverged)
      << r.outcome.reason << History(r.outcome);
  EXPECT_GT(r.before.normal, 0.1 * r.scale.w);  // the solver has to move them
  std::printf("  [bending %s, kL = %.0e] w/h %.1e: |dw|/w %.2e, |du_xy|/w %.2e, |dt|/t_xy %.2e\n",
              c.name,
              kKappaL,
              r.scale.w / kThickness,
              r.after.normal / r.scale.w,
              r.after.in_plane / r.scale.w,
              r.after.director / r.scale.slope);
  EXPECT_LE(r.after.normal, kBendingTolerance * r.scale.w);
  EXPECT_LE(r.after.in_plane, kBendingTolerance * r.scale.w);
  EXPECT_LE(r.after.director, kBendingTolerance * r.scale.slope);
}

// What is left is geometric nonlinearity, not discretisation error: it grows
// like (κL)², ×100 for κL ×10, where an element failing the patch test would
// leave an error proportional to the field (the same relative error).
TEST_P(PatchBending, RemainingErrorIsGeometricNonlinearity) {
  const BendingCase& c = GetParam();
  const BendingResult small = SolveBending(c, 1e-5);
  const BendingResult large = SolveBending(c, 1e-4);
  ASSERT_EQ(small.outcome.status, NewtonOutcome::Status::kConverged) << small.outcome.reason;
  ASSERT_EQ(large.outcome.status, NewtonOutcome::Status::kConverged) << large.outcome.reason;
  const double w_small = small.after.normal / small.scale.w;
  const double w_large = large.after.normal / large.scale.w;
  const double t_small = small.after.director / small.scale.slope;
  const double t_large = large.after.director / large.scale.slope;
  std::printf(
      "  [bending %s] kL = 1e-5 → 1e-4: |dw|/w %.2e → %.2e (×%.1f), |dt|/t_xy %.2e → %.2e "
      "(×%.1f)\n",
      c.name,
      w_small,
      w_large,
      w_large / w_small,
      t_small,
      t_large,
      t_large / t_small);
  EXPECT_GT(w_large, 50 * w_small);
  EXPECT_LT(w_large, 200 * w_small);
  EXPECT_GT(t_large, 50 * t_small);
  EXPECT_LT(t_large, 200 * t_small);
}

// Before any solve, with the interior nodes on the exact field too: the
// energy is that of constant curvature, ½A κᵀD_bκ, and the interior nodes are
// in equilibrium while the clamped corners carry moments. The in-plane nodal
// forces are left out: they come only from the membrane strain ½ w,i w,j
// (even in κ, no linear part) and are unbalanced at the corners as well as
// inside. With the interior nodes at the reference state instead, the
// residual is far larger than the reactions, so the check can fail.
TEST_P(PatchBending, ExactFieldIsInEquilibriumBeforeSolving) {
  const BendingCase& c = GetParam();
  const double kappa_l = 1e-7;  // nonlinear terms ~1e-9 of the bending ones
  const ShellModel model = PatchModel();
  const DofMap dofs = ClampedCorners(model);
  const ExactField field = BendingField(c, kappa_l);
  EquilibriumSystem system(model, dofs);

  const double energy = system.Assemble(Prescribe(model, field, true), /*with_tangent=*/false);
  const double k = kappa_l / kLx;
  const Eigen::Vector3d kappa(k * c.kx, k * c.ky, 2 * k * c.kxy);  // (w,xx, w,yy, 2w,xy)
  const double expected = 0.5 * kLx * kLy * kappa.dot(model.section.bending * kappa);
  EXPECT_GT(energy, 0);
  EXPECT_NEAR(energy, expected, 1e-6 * expected);
  const ForceSizes reaction = Sizes(system.InternalForce(), kCorners);
  const ForceSizes residual = Sizes(system.InternalForce(), kInterior);
  EXPECT_GT(reaction.moment, 0);
  EXPECT_LE(residual.moment, 1e-6 * reaction.moment);
  EXPECT_LE(residual.transverse * kLx, 1e-6 * reaction.moment);

  system.Assemble(Prescribe(model, field, false), /*with_tangent=*/false);
  const ForceSizes reference = Sizes(system.InternalForce(), kInterior);
  EXPECT_GT(reference.moment, 1e3 * reaction.moment);
  EXPECT_GT(reference.transverse * kLx, 1e3 * reaction.moment);
  std::printf(
      "  [bending %s, kL = %.0e] energy/½Aκ·Dκ - 1 = %.1e; interior |M|, |F_z|·L over corner |M|: "
      "exact %.1e, %.1e; reference %.1e, %.1e\n",
      c.name,
      kappa_l,
      energy / expected - 1,
      residual.moment / reaction.moment,
      residual.transverse * kLx / reaction.moment,
      reference.moment / reaction.moment,
      reference.transverse * kLx / reaction.moment);
}

INSTANTIATE_TEST_SUITE_P(Patch,
                         PatchBending,
                         ::testing::ValuesIn(kBendingCases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace drape
