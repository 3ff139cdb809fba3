// Verification of penalty contact (node_contact.h): the tangent blocks and
// forces against finite differences of the energy on every analytic
// obstacle shape, placed and not, nodes inside and outside.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/contact/node_contact.h"
#include "core/fe/shell_model.h"
#include "core/model/obstacle_geometry.h"
#include "support/contact_scenes.h"

namespace drape {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// ---- tangent blocks against finite differences ------------------------------

constexpr double kFdStep = 1e-7;  // [m]

// A small model whose nodes the test moves around at will: only its node
// count, tributary areas and thickness matter to NodeContact.
constexpr double kTinyX = 0.03, kTinyY = 0.02;
constexpr int kTinyNx = 3, kTinyNy = 2;
constexpr double kTinyThickness = 1e-3;  // h/2 = 0.5 mm of room for penetrations

ShellModel TinyModel() {
  test::SheetSpec spec;
  spec.thickness = kTinyThickness;
  Scene scene = test::FreeSheet(spec);
  scene.fabric.outline = RectangleOutline{{kTinyX, kTinyY}, {0.0, 0.0}};
  scene.fabric.mesh.elements = std::array<int, 2>{kTinyNx, kTinyNy};
  return BuildShellModel(scene);
}

// The consistent share ∫ N_I dA of a structured grid of equal rectangles,
// counted independently of the Gauss points: a quarter of the element's area
// from each element the node belongs to.
std::vector<double> GridNodalAreas(const ShellModel& model) {
  const double element_area = kTinyX * kTinyY / (kTinyNx * kTinyNy);
  std::vector<double> area(model.NodeCount(), 0.0);
  for (int e = 0; e < model.mesh.ElementCount(); ++e)
    for (int k = 0; k < 4; ++k) area[model.mesh.quads(e, k)] += element_area / 4;
  return area;
}

struct FdCase {
  std::string label;
  Obstacle obstacle;
  Eigen::Vector3d lo, hi;  // where seed points are drawn, in the obstacle's own frame
  ObstaclePlacement placement;
};

ObstaclePlacement Turned(const Eigen::Vector3d& axis, double angle, const Eigen::Vector3d& by) {
  ObstaclePlacement p;
  p.rotation = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  p.translation = by;
  return p;
}

std::vector<FdCase> FdCases() {
  using V = Eigen::Vector3d;
  std::vector<FdCase> cases;
  const double n = 1 / std::sqrt(14.0);
  cases.push_back({"plane",
                   {"plane", PlaneShape{{0.01, -0.02, 0.003}, {n, 2 * n, 3 * n}}},
                   V(-0.02, -0.04, -0.02),
                   V(0.04, 0.0, 0.03),
                   {}});
  cases.push_back({"sphere",
                   {"sphere", SphereShape{{0.01, 0.02, -0.03}, 0.006}},
                   V(0.0, 0.01, -0.04),
                   V(0.02, 0.03, -0.02),
                   {}});
  cases.push_back({"infinite cylinder",
                   {"rod", CylinderShape{{0, 0, 0.01}, {2.0 / 3, 2.0 / 3, 1.0 / 3}, 0.004, {}}},
                   V(-0.02, -0.02, 0.0),
                   V(0.02, 0.02, 0.02),
                   {}});
  // Seeds all round a finite cylinder land on its side, its caps and its
  // rims; a placement turns and shifts it.
  cases.push_back({"finite cylinder",
                   {"can", CylinderShape{{0.02, 0, 0}, {0, 0.6, 0.8}, 0.005, 0.012}},
                   V(0.012, -0.01, -0.01),
                   V(0.028, 0.01, 0.01),
                   {}});
  cases.push_back({"finite cylinder, placed",
                   {"can", CylinderShape{{0.02, 0, 0}, {0, 0.6, 0.8}, 0.005, 0.012}},
                   V(0.012, -0.01, -0.01),
                   V(0.028, 0.01, 0.01),
                   Turned(V(1, -2, 0.5), 0.7, V(0.003, -0.01, 0.02))});
  cases.push_back({"rounded box",
                   {"box", BoxShape{{-0.01, -0.02, -0.015}, {0.02, 0.01, 0.005}, 0.004}},
                   V(-0.02, -0.03, -0.025),
                   V(0.03, 0.02, 0.015),
                   {}});
  cases.push_back({"rounded box, placed",
                   {"box", BoxShape{{-0.01, -0.02, -0.015}, {0.02, 0.01, 0.005}, 0.004}},
                   V(-0.02, -0.03, -0.025),
                   V(0.03, 0.02, 0.015),
                   Turned(V(0.3, 1, -1), -1.1, V(-0.02, 0.005, 0.01))});
  return cases;
}

TEST(NodeContact, TangentBlocksMatchFiniteDifferencesOnEveryShape) {
  const auto start = Clock::now();
  const ShellModel model = TinyModel();
  const int nodes = model.NodeCount();
  const double half = kTinyThickness / 2;
  const double penalty = 1e7;  // [N/m³]; only scales every quantity compared
  const std::vector<double> area = GridNodalAreas(model);
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto random = [&](int size) {
    Eigen::VectorXd v(size);
    for (int k = 0; k < size; ++k) v[k] = 2 * unit(rng) - 1;
    return v;
  };

  for (const FdCase& c : FdCases()) {
    // The test's own distance function: the scene's shape queried in its own
    // frame, so NodeContact's turning of normals and Hessians is checked too.
    const auto geometry = MakeObstacleGeometry(c.obstacle, ".");
    auto distance = [&](const Eigen::Vector3d& x) {
      return geometry->Query(c.placement.ToScene(x)).distance;
    };
    for (double stabilization : {0.0, 30.0}) {
      std::vector<NamedObstacle> obstacles;
      obstacles.push_back({c.obstacle.name, MakeObstacleGeometry(c.obstacle, ".")});
      NodeContact contact(model, std::move(obstacles), NormalLaw{penalty}, stabilization);
      for (int i = 0; i < nodes; ++i)
        ASSERT_NEAR(contact.nodal_area()[i], area[i], 1e-12 * area[i]) << "node " << i;

      int penetrating = 0, clear = 0;
      double largest_curvature_term = 0;  // |g| ‖∇∇d‖ / ‖n nᵀ + g ∇∇d‖
      // Penetrating nodes by how many directions d curves in: a face (0), a
      // cylinder's side or a box's edge (1), a sphere, a rim or a corner (2).
      std::array<int, 3> curved = {0, 0, 0};
      double worst_block = 0, worst_force = 0, worst_rate = 0;
      for (int round = 0; round < 8; ++round) {
        // Each node on the surface at a chosen distance: a seed pulled along
        // the normal (exact for a signed distance, whose gradient has unit
        // length and points away from the nearest surface point). Most are
        // inside the fabric's half thickness (g < 0, up to h deep), a quarter
        // clear of it (no force, no stiffness).
        ShellState state = model.reference;
        if (!c.placement.IsIdentity()) state.obstacles = {c.placement};
        ShellState anchors = model.reference;
        for (int i = 0; i < nodes; ++i) {
          const bool inside = (i + round) % 4 != 0;
          Eigen::Vector3d s;
          for (int tries = 0;; ++tries) {
            ASSERT_LT(tries, 1000) << c.label;
            for (int k = 0; k < 3; ++k) s[k] = c.lo[k] + (c.hi[k] - c.lo[k]) * unit(rng);
            const double target = inside ? half - (0.02 + 0.96 * unit(rng)) * kTinyThickness
                                         : half + (0.05 + unit(rng)) * kTinyThickness;
            const DistanceQuery seed = geometry->Query(s);
            s -= (seed.distance - target) * seed.normal;
            // Moving deeper can cross the medial surface inside a shape with
            // edges (a finite cylinder's rim), where d has a kink and no
            // tangent exists; and the curvature of d jumps where regions
            // meet (face to rounded edge). Keep nodes 1 µm (10 FD steps)
            // from both: the same nearest point, and a normal and Hessian
            // that vary smoothly around. Near a rim the level sets of d are
            // tubes of radius d about the rim circle; keep that radius at
            // 0.2 mm or more (‖∇∇d‖ ≤ 5000/m) so the central differences'
            // truncation, (step/ρ)², stays below 2.5e-7.
            const DistanceQuery q = geometry->Query(s);
            bool smooth = std::abs(q.distance - target) < 1e-12 && q.hessian.norm() <= 5e3 &&
                          (q.normal - seed.normal).norm() < 1e-9;
            for (int k = 0; k < 3 && smooth; ++k)
              for (double side : {-1e-6, 1e-6}) {
                const DistanceQuery near = geometry->Query(s + side * Eigen::Vector3d::Unit(k));
                smooth = smooth &&
                         (near.normal - q.normal).norm() < 2e-6 * q.hessian.norm() + 1e-9 &&
                         (near.hessian - q.hessian).norm() < 0.05 * q.hessian.norm() + 1e-9;
              }
            if (smooth) break;
          }
          state.positions.row(i) = c.placement.ToWorld(s).transpose();
          anchors.positions.row(i) = state.positions.row(i) + 1e-4 * random(3).transpose();
        }
        contact.Commit(anchors);  // the springs pull towards somewhere else

        auto internal = [&](const ShellState& s) {
          Eigen::VectorXd f = Eigen::VectorXd::Zero(model.DofCount());
          contact.Add(s, f, nullptr, nullptr, nullptr);
          return f;
        };
        // ½ k A g² (g < 0) and ½ k_s |x − anchor|², from the test's own
        // distance and areas.
        auto energy = [&](const ShellState& s) {
          double e = 0;
          for (int i = 0; i < nodes; ++i) {
            const Eigen::Vector3d x = s.positions.row(i).transpose();
            const double g = distance(x) - half;
            if (g < 0) e += 0.5 * penalty * area[i] * g * g;
            e +=
                0.5 * stabilization * (s.positions.row(i) - anchors.positions.row(i)).squaredNorm();
          }
          return e;
        };

        Eigen::VectorXd f = Eigen::VectorXd::Zero(model.DofCount());
        Eigen::VectorXd rate = Eigen::VectorXd::Zero(model.DofCount());
        const Eigen::VectorXd velocity = random(model.DofCount());
        std::vector<Eigen::Matrix3d> blocks;
        contact.Add(state, f, &blocks, &velocity, &rate);
        ASSERT_EQ(static_cast<int>(blocks.size()), nodes);

        for (int i = 0; i < nodes; ++i) {
          const Eigen::Vector3d x = state.positions.row(i).transpose();
          const DistanceQuery q = geometry->Query(c.placement.ToScene(x));
          const double g = q.distance - half;
          // Nodes are placed well outside NodeContact's "touching" band
          // (|g| ≤ 1e-9 h/2), where the tangent is not the force's derivative.
          ASSERT_GT(std::abs(g), 1e-6 * half) << c.label << " node " << i;
          const double ka = penalty * area[i];
          Eigen::Matrix3d fd;
          Eigen::Vector3d fd_force;
          for (int k = 0; k < 3; ++k) {
            ShellState plus = state, minus = state;
            plus.positions(i, k) += kFdStep;
            minus.positions(i, k) -= kFdStep;
            const Eigen::VectorXd df = internal(plus) - internal(minus);
            fd.col(k) = df.segment<3>(kDofsPerNode * i) / (2 * kFdStep);
            fd_force[k] = (energy(plus) - energy(minus)) / (2 * kFdStep);
            // Contact is local to the node: nothing else, and no rotation
            // DOF, feels it.
            Eigen::VectorXd elsewhere = df;
            elsewhere.segment<3>(kDofsPerNode * i).setZero();
            EXPECT_EQ(elsewhere.lpNorm<Eigen::Infinity>(), 0.0) << c.label << " node " << i;
          }
          const Eigen::Matrix3d& block = blocks[i];
          // Central differences: truncation ~ (step/ρ)² with ρ ≥ 0.2 mm the
          // smallest radius of curvature of d met here (near a rim), i.e.
          // ≤ 2.5e-7 of the block; round-off ~ 1e-16 ‖x‖ / step ~ 1e-11. The
          // curvature term g ∇∇d is up to tens of percent of the block (see
          // the print-out), so a wrong Hessian, a wrong sign of g or a normal
          // not turned with the placement fails by orders of magnitude.
          // Relative to the block, or to k A where a clear node has none.
          const double scale = std::max(block.norm(), ka);
          const double block_error = (block - fd).norm() / scale;
          EXPECT_LT(block_error, 1e-6) << c.label << " node " << i << " g = " << g << "\nblock\n"
                                       << block << "\nFD\n"
                                       << fd;
          EXPECT_LE((block - block.transpose()).norm(), 1e-14 * scale);
          worst_block = std::max(worst_block, block_error);
          // Force against the energy: E‴ = k A (3 ∇g ⊗ ∇∇d + g ∇∇∇d) puts
          // the truncation at ~ step² k A ‖∇∇d‖ (≤ 5e-8 N, 2.5e-6 of the
          // smallest force here), over the relative 1e-6.
          const Eigen::Vector3d force = f.segment<3>(kDofsPerNode * i);
          const double force_error = (force - fd_force).norm();
          EXPECT_LT(force_error,
                    1e-6 * force.norm() + kFdStep * kFdStep * ka * (q.hessian.norm() + 1e-3))
              << c.label << " node " << i << " g = " << g;
          if (force.norm() > 0) worst_force = std::max(worst_force, force_error / force.norm());
          EXPECT_EQ(f.segment<2>(kDofsPerNode * i + 3).norm(), 0.0);
          // The rate is the contact part of the block (the springs are not in
          // it; they only reach the rows of held nodes, which are reactions)
          // times the nodal velocity.
          const Eigen::Matrix3d contact_block = block - stabilization * Eigen::Matrix3d::Identity();
          const Eigen::Vector3d expected = contact_block * velocity.segment<3>(kDofsPerNode * i);
          const double rate_error = (rate.segment<3>(kDofsPerNode * i) - expected).norm();
          EXPECT_LE(rate_error, 1e-14 * scale * velocity.norm()) << c.label << " node " << i;
          worst_rate = std::max(worst_rate, rate_error / (scale * velocity.norm()));
          EXPECT_EQ(rate.segment<2>(kDofsPerNode * i + 3).norm(), 0.0);
          if (g < 0) {
            ++penetrating;
            const Eigen::Matrix3d& r = c.placement.rotation;
            const Eigen::Vector3d normal = r * q.normal;
            const Eigen::Matrix3d unit_block =
                normal * normal.transpose() + g * r * q.hessian * r.transpose();
            largest_curvature_term = std::max(largest_curvature_term,
                                              std::abs(g) * q.hessian.norm() / unit_block.norm());
            const Eigen::Vector3d curvatures =
                Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(q.hessian).eigenvalues();
            ++curved[(curvatures.array().abs() > 1e-6 * q.hessian.norm() + 1e-9).count()];
            // The independent block k A (n nᵀ + g ∇∇d) (+ k_s I), in world axes.
            EXPECT_LT(
                (block - ka * unit_block - stabilization * Eigen::Matrix3d::Identity()).norm(),
                1e-12 * block.norm());
          } else {
            ++clear;
            EXPECT_EQ((block - stabilization * Eigen::Matrix3d::Identity()).norm(), 0.0);
            EXPECT_EQ(rate.segment<3>(kDofsPerNode * i).norm(), 0.0);
          }
        }
      }
      std::printf(
          "%-24s k_s = %4.1f N/m: %2d penetrating (flat/1/2 curved directions: %2d/%2d/%2d), %2d "
          "clear; largest |g|‖∇∇d‖/‖block‖ = %.3f; worst relative errors: block %.1e, force "
          "%.1e, rate %.1e\n",
          c.label.c_str(),
          stabilization,
          penetrating,
          curved[0],
          curved[1],
          curved[2],
          clear,
          largest_curvature_term,
          worst_block,
          worst_force,
          worst_rate);
      // Curved shapes must exercise the curvature term well above the
      // tolerance, or the block check would not see a wrong Hessian.
      if (c.label != "plane") {
        EXPECT_GT(largest_curvature_term, 1e-2) << c.label;
      }
      // The seeds reach every region of the shapes: faces,
      // rounded edges and corners of the box; side, caps and rims of the
      // finite cylinder.
      if (c.label.starts_with("rounded box") || c.label.starts_with("finite cylinder")) {
        EXPECT_GT(*std::min_element(curved.begin(), curved.end()), 0) << c.label;
      }
    }
  }
  std::printf("finite-difference checks: %.2f s\n", SecondsSince(start));
}

}  // namespace
}  // namespace drape
