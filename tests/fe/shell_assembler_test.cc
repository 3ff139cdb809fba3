// The shell assembler called directly (shell_assembler.h), on small sheets:
//  - the internal force is the gradient of the assembled energy, the
//    tangent the derivative of the internal force, and the λ-rate K v the
//    derivative along the prescribed velocity (central differences of the
//    code's own energy and force);
//  - a uniform stretch stores the closed-form membrane energy and forces;
//  - internal forces are self-equilibrated (the energy is invariant under
//    rigid motions);
//  - the pattern holds exactly the free DOF pairs that share an element (or
//    a coupled node pair), counted by hand;
//  - colours: the parallel assembly equals a plain element-by-element sum.
#include "core/fe/shell_assembler.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <utility>
#include <vector>

#include "core/fe/dof_map.h"
#include "core/fe/element_state.h"
#include "core/fe/shell_model.h"
#include "core/mechanics/director.h"
#include "support/random_element.h"
#include "support/strip_scene.h"
#include "support/strip_system.h"

namespace drape {
namespace {

// A square sheet a × a of nx × ny elements, clamped on its left edge
// (E = 1 MPa, ν = 0.3, h = 0.5 mm, weightless).
constexpr double kSide = 0.1;

Scene Sheet(int nx, int ny, double poisson = 0.3) {
  test::StripSpec spec;
  spec.length = kSide;
  spec.width = kSide;
  Scene scene = test::CantileverStrip(spec);
  scene.fabric.mesh.elements = std::array<int, 2>{nx, ny};
  scene.material.membrane = IsotropicMembrane{spec.youngs_modulus, poisson};
  return scene;
}

// The reference sheet moved by a large rigid rotation, its nodes shifted by
// up to 2 % of the side and each node turned by up to 0.6 rad more: every
// membrane, bending and shear term is active.
ShellState RandomState(const ShellModel& model, std::uint64_t seed) {
  SplitMix64 rng(seed);
  const Eigen::Matrix3d rigid = ExpRotation(test::RandomVector(rng, 1.0));
  ShellState state = model.reference;
  for (int i = 0; i < model.NodeCount(); ++i) {
    const Eigen::Vector3d x = model.reference.positions.row(i).transpose();
    state.positions.row(i) = (rigid * (x + test::RandomVector(rng, 0.02 * kSide))).transpose();
    state.rotations[i] = ExpRotation(test::RandomVector(rng, 0.6)) * rigid * state.rotations[i];
  }
  return state;
}

// `state` moved by `h` along full DOF `d` (Δu, or Λ ← exp(ŵ)Λ).
ShellState Moved(const ShellState& state, int d, double h) {
  Eigen::VectorXd increment = Eigen::VectorXd::Zero(kDofsPerNode * state.NodeCount());
  increment(d) = h;
  ShellState moved = state;
  ApplyIncrement(increment, moved);
  return moved;
}

// Steps for the differences: the translations' in metres, the rotations' in
// radians, each about where truncation (∝ h², or h⁴) meets round-off
// (∝ ε/h) — see each test for what was measured.
double Step(int d, double translation, double rotation) {
  return d % kDofsPerNode < 3 ? translation : rotation;
}

// The full symmetric matrix from the assembled upper triangle.
Eigen::MatrixXd Symmetric(const Eigen::SparseMatrix<double>& upper) {
  const Eigen::MatrixXd u = Eigen::MatrixXd(upper);
  Eigen::MatrixXd full = u + u.transpose();
  full.diagonal() = u.diagonal();
  return full;
}

// Over the free DOFs, max |A_ij − K_ij| / √|K_ii K_jj|: each entry against
// the diagonal scales of its row and column (the Jacobi scaling), so the
// small bending and rotation entries are held as tightly as the membrane's.
double ScaledError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& k) {
  double worst = 0;
  for (int i = 0; i < k.rows(); ++i)
    for (int j = 0; j < k.cols(); ++j)
      worst = std::max(worst, std::abs(a(i, j) - k(i, j)) / std::sqrt(std::abs(k(i, i) * k(j, j))));
  return worst;
}

// ‖a − b‖/‖b‖ over the translation (rotations: false) or rotation entries of
// full vectors (5 per node).
double PartError(const Eigen::VectorXd& a, const Eigen::VectorXd& b, bool rotations) {
  double error = 0, norm = 0;
  for (int d = 0; d < b.size(); ++d)
    if ((d % kDofsPerNode >= 3) == rotations) {
      error += (a(d) - b(d)) * (a(d) - b(d));
      norm += b(d) * b(d);
    }
  return std::sqrt(error / norm);
}

// ---- derivatives ----------------------------------------------------------------------

// Fourth-order central differences of the assembled energy over every DOF
// (fixed ones too) with h = 1e-5 m and 1e-4 rad: truncation O(h⁴) is below
// round-off (ε E/h). Measured over three states: translations 5.1e-13,
// rotations 2.9e-12 relative.
TEST(ShellAssembler, InternalForceIsTheGradientOfTheEnergy) {
  const ShellModel model = BuildShellModel(Sheet(2, 2));
  const DofMap dofs = test::HeldDofs(model);
  const ShellAssembler assembler(model, dofs);
  for (std::uint64_t seed : {1, 2, 3}) {
    const ShellState state = RandomState(model, seed);
    Eigen::VectorXd force, scratch;
    assembler.Assemble(state, force, nullptr);
    auto energy = [&](int d, double h) {
      return assembler.Assemble(Moved(state, d, h), scratch, nullptr);
    };
    Eigen::VectorXd fd(force.size());
    for (int d = 0; d < force.size(); ++d) {
      const double h = Step(d, 1e-5, 1e-4);
      fd(d) =
          (-energy(d, 2 * h) + 8 * energy(d, h) - 8 * energy(d, -h) + energy(d, -2 * h)) / (12 * h);
    }
    const double translations = PartError(fd, force, false);
    const double rotations = PartError(fd, force, true);
    std::printf("state %d: forces %.2e, moments %.2e off\n",
                static_cast<int>(seed),
                translations,
                rotations);
    EXPECT_LT(translations, 2e-12);
    EXPECT_LT(rotations, 1e-11);
  }
}

// K's column j against (F(q + h e_j) − F(q − h e_j))/2h over the free rows,
// every free column, with h = 1e-7 m (1e-6 of the side) and 1e-6 rad: the
// truncation error, ∝ h², falls to there (5e-10 at ten times the steps),
// below which round-off, ∝ ε‖F‖/h, takes over (3e-9 at a tenth). Measured
// over three states: at most 3.7e-10 of √|K_ii K_jj|.
TEST(ShellAssembler, TangentColumnsAreCentralDifferencesOfTheInternalForce) {
  const ShellModel model = BuildShellModel(Sheet(2, 2));
  const DofMap dofs = test::HeldDofs(model);
  const ShellAssembler assembler(model, dofs);
  for (std::uint64_t seed : {4, 5, 6}) {
    const ShellState state = RandomState(model, seed);
    Eigen::VectorXd force, plus, minus;
    Eigen::SparseMatrix<double> tangent = assembler.Pattern();
    assembler.Assemble(state, force, &tangent);
    const Eigen::MatrixXd k = Symmetric(tangent);
    Eigen::MatrixXd fd(dofs.FreeCount(), dofs.FreeCount());
    for (int d = 0; d < dofs.DofCount(); ++d) {
      const int j = dofs.Free(d);
      if (j < 0) continue;
      const double h = Step(d, 1e-7, 1e-6);
      assembler.Assemble(Moved(state, d, h), plus, nullptr);
      assembler.Assemble(Moved(state, d, -h), minus, nullptr);
      fd.col(j) = dofs.Restrict(plus - minus) / (2 * h);
    }
    const double error = ScaledError(fd, k);
    std::printf("state %d: %.2e\n", static_cast<int>(seed), error);
    EXPECT_LT(error, 1.5e-9);
  }
}

// With the clamped edge moving at a random velocity v (translations and
// rotations of its nodes), the rate K v over all DOFs — the fixed ones' rows
// too — against (F(q + h v) − F(q − h v))/2h, h as for the tangent.
// Measured over two states: forces 2.7e-11, moments 7.3e-11 relative.
TEST(ShellAssembler, RateIsTheDerivativeOfTheForceAlongThePrescribedVelocity) {
  const ShellModel model = BuildShellModel(Sheet(2, 2));
  const DofMap dofs = test::HeldDofs(model);
  const ShellAssembler assembler(model, dofs);
  SplitMix64 rng(9);
  for (std::uint64_t seed : {7, 8}) {
    const ShellState state = RandomState(model, seed);
    Eigen::VectorXd velocity = Eigen::VectorXd::Zero(model.DofCount());
    for (int d = 0; d < model.DofCount(); ++d)
      if (dofs.IsFixed(d)) velocity(d) = test::Uniform(rng, -1, 1) * Step(d, 0.01, 0.1);
    Eigen::VectorXd force, rate, plus, minus;
    Eigen::SparseMatrix<double> tangent = assembler.Pattern();
    assembler.Assemble(state, force, &tangent, &velocity, &rate);
    const double h = 1e-5;  // × |v| ≤ 0.01 m, 0.1 rad: 1e-7 m, 1e-6 rad
    ShellState ahead = state, behind = state;
    ApplyIncrement(h * velocity, ahead);
    ApplyIncrement(-h * velocity, behind);
    assembler.Assemble(ahead, plus, nullptr);
    assembler.Assemble(behind, minus, nullptr);
    const Eigen::VectorXd fd = (plus - minus) / (2 * h);
    const double forces = PartError(fd, rate, false), moments = PartError(fd, rate, true);
    std::printf(
        "state %d: forces %.2e, moments %.2e off\n", static_cast<int>(seed), forces, moments);
    EXPECT_LT(forces, 3e-10);
    EXPECT_LT(moments, 3e-10);
  }
}

// ---- closed forms -----------------------------------------------------------------------

// x → (1 + e)x with y, the directors and all else kept: a uniform membrane
// strain ε_xx = ((1 + e)² − 1)/2 (Green), ε_yy = γ = 0, no bending or shear.
// Plane stress with ν: N_xx = Eh ε_xx/(1 − ν²), N_yy = ν N_xx; energy ½ N_xx
// ε_xx over the area; the nodal forces those of the first Piola traction,
// N_xx(1 + e) on the x = L edge and N_yy on the y = ±b/2 edges, shared ½, 1,
// ½ along each edge (the bilinear shape functions' integrals), nothing
// inside. Exact on the mesh (uniform fields): measured energy 1.1e-16, forces
// 3.2e-15 of the largest off.
TEST(ShellAssembler, UniformStretchStoresTheClosedFormMembraneEnergyAndForces) {
  const int nx = 3, ny = 2;
  const double e = 0.1, nu = 0.3, young = 1e6, h = 5e-4;
  const ShellModel model = BuildShellModel(Sheet(nx, ny, nu));
  const DofMap dofs = test::HeldDofs(model);
  const ShellAssembler assembler(model, dofs);
  ShellState state = model.reference;
  state.positions.col(0) *= 1 + e;
  Eigen::VectorXd force;
  const double energy = assembler.Assemble(state, force, nullptr);

  const double strain = ((1 + e) * (1 + e) - 1) / 2;
  const double nxx = young * h * strain / (1 - nu * nu), nyy = nu * nxx;
  const double exact_energy = 0.5 * nxx * strain * kSide * kSide;
  Eigen::VectorXd exact = Eigen::VectorXd::Zero(model.DofCount());
  for (int i = 0; i < model.NodeCount(); ++i) {
    const int ix = static_cast<int>(std::lround(model.reference.positions(i, 0) / (kSide / nx)));
    const int iy =
        static_cast<int>(std::lround((model.reference.positions(i, 1) + kSide / 2) / (kSide / ny)));
    const double along_y = (iy == 0 || iy == ny ? 0.5 : 1.0) * kSide / ny;  // edge shares
    const double along_x = (ix == 0 || ix == nx ? 0.5 : 1.0) * kSide / nx;
    const double side_x = ix == nx ? 1 : ix == 0 ? -1 : 0;
    const double side_y = iy == ny ? 1 : iy == 0 ? -1 : 0;
    exact(kDofsPerNode * i) = side_x * nxx * (1 + e) * along_y;
    exact(kDofsPerNode * i + 1) = side_y * nyy * along_x;
  }
  const double energy_error = std::abs(energy / exact_energy - 1);
  const double force_error = (force - exact).cwiseAbs().maxCoeff() / exact.cwiseAbs().maxCoeff();
  std::printf("energy %.2e, forces %.2e off\n", energy_error, force_error);
  EXPECT_LT(energy_error, 5e-16);
  EXPECT_LT(force_error, 1.5e-14);
}

// The energy does not change under a rigid motion, so the internal forces
// have no resultant: Σ f_i = 0 and Σ (x_i × f_i + m_i) = 0, m_i = f_a g₁ +
// f_b g₂ the nodal moment (the work conjugate of w = a g₁ + b g₂).
// Measured over three states: at most 4.3e-17 and 3.5e-17 of Σ|f_i| and
// Σ(|x_i||f_i| + |m_i|).
TEST(ShellAssembler, InternalForcesHaveNoResultantForceOrMoment) {
  const ShellModel model = BuildShellModel(Sheet(3, 2));
  const DofMap dofs = test::HeldDofs(model);
  const ShellAssembler assembler(model, dofs);
  for (std::uint64_t seed : {10, 11, 12}) {
    const ShellState state = RandomState(model, seed);
    Eigen::VectorXd f;
    assembler.Assemble(state, f, nullptr);
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    double force_scale = 0, moment_scale = 0;
    for (int i = 0; i < model.NodeCount(); ++i) {
      const Eigen::Vector3d x = state.positions.row(i).transpose();
      const Eigen::Vector3d fi = f.segment<3>(kDofsPerNode * i);
      const Eigen::Vector3d mi = f(kDofsPerNode * i + 3) * state.rotations[i].col(0) +
                                 f(kDofsPerNode * i + 4) * state.rotations[i].col(1);
      force += fi;
      moment += x.cross(fi) + mi;
      force_scale += fi.norm();
      moment_scale += x.norm() * fi.norm() + mi.norm();
    }
    std::printf("state %d: resultant %.2e, moment %.2e\n",
                static_cast<int>(seed),
                force.norm() / force_scale,
                moment.norm() / moment_scale);
    EXPECT_LT(force.norm(), 2e-16 * force_scale);
    EXPECT_LT(moment.norm(), 2e-16 * moment_scale);
  }
}

// ---- pattern and colours ------------------------------------------------------------------

// The 2 × 2 sheet clamped on its left edge: 6 free nodes of 5 DOFs. Two
// nodes share an element iff they are neighbours on the 3 × 3 grid (|Δi|,
// |Δj| ≤ 1): among the free ones 11 pairs (2 + 2 vertical, 3 across, 4
// diagonal), each a full 5 × 5 block, and every node's own upper triangle
// (15): 11·25 + 6·15 = 365 entries. A coupled pair beyond the elements adds
// its 3 × 3 translational block: 9 more.
TEST(ShellAssembler, PatternHoldsTheFreeDofPairsThatShareAnElementOrACoupling) {
  const ShellModel model = BuildShellModel(Sheet(2, 2));
  const DofMap dofs = test::HeldDofs(model);
  ASSERT_EQ(dofs.FreeCount(), 30);
  auto grid = [&](int node) {
    return std::pair<int, int>(
        static_cast<int>(std::lround(model.reference.positions(node, 0) / (kSide / 2))),
        static_cast<int>(
            std::lround((model.reference.positions(node, 1) + kSide / 2) / (kSide / 2))));
  };
  auto node_of = [&](int i, int j) {
    for (int n = 0; n < model.NodeCount(); ++n)
      if (grid(n) == std::pair<int, int>(i, j)) return n;
    return -1;
  };
  // (1, 2) and (2, 0): free, two rows apart.
  const int a = node_of(1, 2), b = node_of(2, 0);
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  for (bool coupled : {false, true}) {
    std::vector<std::pair<int, int>> pairs;
    if (coupled) pairs.push_back({a, b});
    const ShellAssembler assembler(model, dofs, pairs);
    const Eigen::SparseMatrix<double>& pattern = assembler.Pattern();
    EXPECT_EQ(pattern.rows(), 30);
    EXPECT_EQ(pattern.cols(), 30);
    EXPECT_EQ(pattern.nonZeros(), coupled ? 365 + 9 : 365);
    std::set<std::pair<int, int>> stored;
    for (int c = 0; c < pattern.outerSize(); ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(pattern, c); it; ++it)
        stored.insert({static_cast<int>(it.row()), static_cast<int>(it.col())});
    for (int p = 0; p < model.DofCount(); ++p)
      for (int q = 0; q < model.DofCount(); ++q) {
        const int r = dofs.Free(p), c = dofs.Free(q);
        if (r < 0 || c < 0 || r > c) continue;
        const int np = p / kDofsPerNode, nq = q / kDofsPerNode;
        const auto [ip, jp] = grid(np);
        const auto [iq, jq] = grid(nq);
        const bool neighbours = std::abs(ip - iq) <= 1 && std::abs(jp - jq) <= 1;
        const bool pair = coupled && ((np == a && nq == b) || (np == b && nq == a)) &&
                          p % kDofsPerNode < 3 && q % kDofsPerNode < 3;
        EXPECT_EQ(stored.count({r, c}), neighbours || pair ? 1u : 0u) << "DOFs " << p << ", " << q;
      }
  }
}

// Elements that share a node must differ in colour; the greedy colouring of
// a structured mesh needs exactly what that forces: a strip of
// elements in a row 2 (each shares nodes with the next only), a 2 × 2 or
// larger grid 4 (four elements meet at an inner node).
TEST(ShellAssembler, ColoursAStripWithTwoAndAGridWithFour) {
  const struct { int nx, ny, colours; } cases[] = {{8, 1, 2}, {2, 2, 4}, {16, 16, 4}};
  for (const auto& c : cases) {
    const ShellModel model = BuildShellModel(Sheet(c.nx, c.ny));
    const ShellAssembler assembler(model, test::HeldDofs(model));
    EXPECT_EQ(assembler.ColorCount(), c.colours) << c.nx << " × " << c.ny;
  }
}

// 16 × 16 elements: 64 in each colour, enough that each colour is assembled
// in parallel. The result against a plain serial sum of the element
// energies, forces and Hessians (EvaluateShellElement), scattered by node
// number: equal to the round-off of the summation order (measured: energy
// 0, force 7.4e-17, tangent 6.5e-17 relative).
TEST(ShellAssembler, ParallelAssemblyEqualsTheSerialSumOfTheElements) {
  const ShellModel model = BuildShellModel(Sheet(16, 16));
  const DofMap dofs = test::HeldDofs(model);
  const ShellAssembler assembler(model, dofs);
  const ShellState state = RandomState(model, 13);
  Eigen::VectorXd force;
  Eigen::SparseMatrix<double> tangent = assembler.Pattern();
  const double energy = assembler.Assemble(state, force, &tangent);

  double sum = 0;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.DofCount());
  std::vector<Eigen::Triplet<double>> entries;
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    const ShellElementState element = ElementStateOf(model, state, e);
    ElementEnergy result;
    EvaluateShellElement(
        model.elements[e], model.section, element, ElementOutput::kHessian, result);
    sum += result.value;
    for (int a = 0; a < 20; ++a) {
      const int p = kDofsPerNode * model.mesh.quads(e, a / kDofsPerNode) + a % kDofsPerNode;
      f(p) += result.gradient(a);
      for (int b = 0; b < 20; ++b) {
        const int q = kDofsPerNode * model.mesh.quads(e, b / kDofsPerNode) + b % kDofsPerNode;
        const int r = dofs.Free(p), c = dofs.Free(q);
        if (r >= 0 && c >= 0 && r <= c) entries.emplace_back(r, c, result.hessian(a, b));
      }
    }
  }
  Eigen::SparseMatrix<double> serial(dofs.FreeCount(), dofs.FreeCount());
  serial.setFromTriplets(entries.begin(), entries.end());
  const double energy_error = std::abs(energy - sum) / std::abs(sum);
  const double force_error = (force - f).norm() / f.norm();
  const double tangent_error = Eigen::SparseMatrix<double>(tangent - serial).norm() / serial.norm();
  std::printf(
      "energy %.2e, force %.2e, tangent %.2e off\n", energy_error, force_error, tangent_error);
  EXPECT_LT(energy_error, 5e-16);
  EXPECT_LT(force_error, 5e-16);
  EXPECT_LT(tangent_error, 5e-16);
}

// With bending hysteresis each element is evaluated with its own slip: the
// assembled energy is the sum of the elements' own evaluations, each given
// its slip (distinct per element, so a mix-up shows); a slip of another
// mesh is refused.
TEST(ShellAssembler, EachElementBendsWithItsOwnSlip) {
  Scene scene = Sheet(3, 2);
  scene.material.bending.warp_hysteresis.width = 1e-4;
  const ShellModel model = BuildShellModel(scene);
  ASSERT_TRUE(model.section.friction);
  ShellState state = RandomState(model, 7);
  SplitMix64 rng(11);
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    ElementSlip slip;
    for (int c = 0; c < slip.cols(); ++c) slip.col(c) = test::RandomVector(rng, 20.0);
    state.bending_slip.push_back(slip);
  }
  const DofMap dofs(model.NodeCount());
  const ShellAssembler assembler(model, dofs);
  Eigen::VectorXd internal;
  const double energy = assembler.Assemble(state, internal, nullptr);
  double sum = 0;
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    const ShellElementState element = ElementStateOf(model, state, e);
    ElementEnergy result;
    EvaluateShellElement(model.elements[e],
                         model.section,
                         element,
                         ElementOutput::kEnergy,
                         result,
                         &state.bending_slip[e]);
    sum += result.value;
  }
  EXPECT_NEAR(energy, sum, 1e-12 * std::abs(sum));
  ShellState no_slip = state;
  no_slip.bending_slip.clear();
  EXPECT_GT(std::abs(assembler.Assemble(no_slip, internal, nullptr) - energy), 1e-6 * energy);
  state.bending_slip.pop_back();
  EXPECT_THROW(assembler.Assemble(state, internal, nullptr), std::invalid_argument);
}

}  // namespace
}  // namespace drape
