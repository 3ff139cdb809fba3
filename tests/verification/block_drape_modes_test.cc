// Which drape mode the block drape reaches, and what selects it.
//
// Eischen, Deng & Clapp, "Finite-element modeling and control of flexible
// fabric parts", IEEE CG&A 1996, "Fabric draping over a block": a 10 × 10 in
// polyester sheet (h = 0.02135 in, E = 2688 oz/in², ν = 0.3, w = 5.425e-3
// oz/in²) pinned at four points sags under its own weight. Table 1: with
// Δλ₀ = 0.00025 the first load step converges smoothly (5 iterations) into
// the "large-deflection mode" (Fig. 7a); with Δλ₀ = 0.00125 it is erratic (13
// iterations, λ even negative on the way) and ends in a "buckling mode" (Fig.
// 7b). With a random nodal waviness |z| ≤ 1e-4 in (20 patterns, all at
// Δλ₀ = 0.00025) four different drape modes appear (Fig. 9), none buckled.
//
// What our engine does with resources/scenes/block-drape.json and
// block-drape-buckling.json (20 × 20 mesh, corners of the sheet pinned):
//
// * Both Δλ₀, under arc-length and under load control, reach one and the
//   same drape: centre sag 0.691 in, all four edge midpoints 0.520 in, D4
//   symmetric to round-off (≈1e-14 of the sag), no negative pivot at any
//   converged step, no stability event. Δλ₀ does not select the mode.
//
//   Why. It is not that our first step is small: the arc-length first step
//   is sized as Δs = Δλ₀ ‖(∂u/∂λ, ψ)‖ with the *linear* tangent of the flat
//   sheet, far more flexible than the membrane-stiffened sheet, so the
//   first step's sphere reaches well past Δλ₀: λ ≈ 0.009 (37 Δλ₀) for
//   0.00025 and λ ≈ 0.5 (400 Δλ₀) for 0.00125. Under load control the
//   Δλ₀ = 0.00125 first step takes 13 iterations with the residual going up
//   and down, as erratic as the paper's. It still lands on the symmetric
//   drape because (1) the problem (mesh, supports, load) is D4 symmetric
//   and Newton iterates from the symmetric flat state stay symmetric up to
//   round-off, so only symmetric equilibria can be reached; (2) the tangent
//   is positive definite at every iterate of every step (CHOLMOD's LLᵀ
//   never falls back to LDLᵀ), so there is no unstable direction for
//   round-off to grow along; and (3) we found no other stable equilibrium
//   at all: Newton with an energy line search from 50 perturbed starts
//   (x²−y², xy, tilts, edge waves, a bowl, random smooth fields; 0.1–1 in,
//   both signs) came back to this drape or, when it converged elsewhere,
//   to saddles with 4–430 negative pivots and a higher potential energy.
//
// * Imperfection seeds do NOT select different modes in this scene: nodal
//   waviness of 1e-4 in moves the drape by about twice the amplitude (mirror
//   asymmetry 2–4e-4 of the sag) and the response is linear in the amplitude
//   (1e-2 in gives ×100), the signature of a path far from any bifurcation.
//   The paper's four Fig. 9 modes are not reproduced by the corner-pinned
//   sheet; the tests below pin down that finding.
//
// Where the paper's behaviour may come from: its Fig. 8 plots the mode
// against b/L, which suggests a block smaller than the sheet, the sheet
// pinned at the block's corners and overhanging. With the sheet pinned at
// (±4 in, ±4 in) on a 10 × 10 mesh we measured Table 1's pattern — Δλ₀ =
// 0.00025 smooth and stable, 0.00125 a different symmetric drape (centre
// 0.448 in against 0.472 in) with 4 negative pivots, i.e. an unstable
// equilibrium — but on a 20 × 20 mesh both Δλ₀ reach the smooth drape, and
// pins at ±3 in put a bifurcation (0 → 4 negative pivots at λ ≈ 0.026) on
// the symmetric path that the arc-length steps jump over. Too dependent on
// mesh and step sizes to be a test; not the shipped scenes' geometry.
//
// The tests print a table per case (the log doubles as the report).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/test_paths.h"

namespace drape {
namespace {

constexpr double kInch = 0.0254;

// The scene with probes at the four edge midpoints added.
Scene BlockDrapeScene(const char* file, StepControl control) {
  Scene scene = ReadScene(test::ScenesDir() / file);
  scene.fabric.mesh.elements = std::array<int, 2>{20, 20};
  scene.stages[0].control = control;
  scene.probes.push_back({"east", {5 * kInch, 0}});
  scene.probes.push_back({"west", {-5 * kInch, 0}});
  scene.probes.push_back({"north", {0, 5 * kInch}});
  scene.probes.push_back({"south", {0, -5 * kInch}});
  return scene;
}

// The final drape and how the run got there.
struct Drape {
  std::string label;
  bool complete = false;
  int steps = 0, iterations = 0;
  double first_lambda = 0;  // λ after the first converged step
  int first_iterations = 0;
  std::vector<double> first_residuals;
  double centre = 0;              // sag [m], positive down
  std::array<double, 4> edges{};  // east, west, north, south sags [m]
  std::array<double, 4> asymmetry{};  // max |z − z∘g| [m], g: x ↦ −x, y ↦ −y, x ↔ y, x ↔ −y
  int final_pivots = -1;              // of the converged final state
  int max_pivots = 0;                 // over every converged step
  int stability_events = 0;
  int indefinite_factorizations = 0;  // tangents that were not positive definite
  Eigen::VectorXd z;                  // final z of every node [m]
  double MaxAsymmetry() const { return *std::max_element(asymmetry.begin(), asymmetry.end()); }
};

double ProbeSag(const StepState& s, const std::string& name) {
  for (const auto& p : s.probes)
    if (p.name == name) return -p.value.z();
  ADD_FAILURE() << "no probe " << name;
  return 0;
}

// For each node, the node at the image of its reference (x, y) under g.
template <typename Map>
std::vector<int> ImageNodes(const Eigen::Matrix<double, Eigen::Dynamic, 3>& xyz, Map g) {
  const int n = static_cast<int>(xyz.rows());
  std::vector<int> image(n, -1);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d target = g(Eigen::Vector2d(xyz(i, 0), xyz(i, 1)));
    for (int j = 0; j < n; ++j)
      if ((Eigen::Vector2d(xyz(j, 0), xyz(j, 1)) - target).norm() < 1e-9) image[i] = j;
    EXPECT_GE(image[i], 0) << "the mesh is not D4 symmetric at node " << i;
  }
  return image;
}

Drape RunDrape(const std::string& label, const Scene& scene) {
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  Drape d;
  d.label = label;
  StepState last;
  SolveSummary summary = solver.Solve({[&](const StepState& s) {
    if (s.step == 1) {
      d.first_lambda = s.lambda;
      d.first_iterations = s.iterations;
      d.first_residuals = s.residuals;
    }
    d.max_pivots = std::max(d.max_pivots, s.negative_pivots);
    last = s;
    return StepDecision::kContinue;
  }});
  d.complete = summary.IsComplete();
  EXPECT_TRUE(d.complete) << label << "\n" << summary.FullReport();
  d.steps = summary.steps;
  d.iterations = summary.iterations;
  d.stability_events = static_cast<int>(summary.stability_events.size());
  d.indefinite_factorizations = summary.indefinite_factorizations;
  if (summary.steps == 0) return d;
  d.final_pivots = last.negative_pivots;
  d.centre = ProbeSag(last, "centre");
  d.edges = {ProbeSag(last, "east"),
             ProbeSag(last, "west"),
             ProbeSag(last, "north"),
             ProbeSag(last, "south")};
  d.z = last.state.positions.col(2);
  const auto& reference = solver.model().mesh.positions;
  using V = Eigen::Vector2d;
  const std::array<std::vector<int>, 4> images = {
      ImageNodes(reference, [](V p) { return V(-p.x(), p.y()); }),
      ImageNodes(reference, [](V p) { return V(p.x(), -p.y()); }),
      ImageNodes(reference, [](V p) { return V(p.y(), p.x()); }),
      ImageNodes(reference, [](V p) { return V(-p.y(), -p.x()); })};
  for (int g = 0; g < 4; ++g)
    for (int i = 0; i < d.z.size(); ++i)
      if (images[g][i] >= 0)
        d.asymmetry[g] = std::max(d.asymmetry[g], std::abs(d.z(i) - d.z(images[g][i])));
  return d;
}

// max over nodes |z_a − z_b|: how far apart two drapes are [m].
double Distance(const Drape& a, const Drape& b) {
  return (a.z - b.z).cwiseAbs().maxCoeff();
}

void PrintHeader() {
  std::printf("  %-26s %5s %5s %9s %3s | %-41s | %8s %8s | %3s %3s %3s %4s\n",
              "case",
              "steps",
              "iters",
              "lambda1",
              "it1",
              "sag [in]: centre  east   west   north  south",
              "asym/sag",
              "dist/sag",
              "piv",
              "max",
              "ev",
              "ldlt");
}

// `dist`: distance to the reference drape, relative to its sag.
void PrintRow(const Drape& d, double dist) {
  std::printf(
      "  %-26s %5d %5d %9.3e %3d | %9.4f %6.4f %6.4f %6.4f %6.4f | %8.1e %8.1e | %3d %3d %3d %4d\n",
      d.label.c_str(),
      d.steps,
      d.iterations,
      d.first_lambda,
      d.first_iterations,
      d.centre / kInch,
      d.edges[0] / kInch,
      d.edges[1] / kInch,
      d.edges[2] / kInch,
      d.edges[3] / kInch,
      d.MaxAsymmetry() / d.centre,
      dist,
      d.final_pivots,
      d.max_pivots,
      d.stability_events,
      d.indefinite_factorizations);
}

void PrintFirstStep(const Drape& d) {
  std::printf("  %-26s first step |R|/|R0|:", d.label.c_str());
  for (double r : d.first_residuals) std::printf(" %.1e", r);
  std::printf("\n");
}

// The smooth mode: D4 symmetric, the four edges alike, stable all the way.
void ExpectSmoothSymmetricStable(const Drape& d) {
  EXPECT_EQ(d.max_pivots, 0) << d.label << ": a negative pivot on the path";
  EXPECT_EQ(d.final_pivots, 0) << d.label;
  EXPECT_EQ(d.stability_events, 0) << d.label;
  EXPECT_EQ(d.indefinite_factorizations, 0) << d.label << ": a tangent not positive definite";
  EXPECT_LT(d.MaxAsymmetry(), 1e-9 * d.centre) << d.label << ": D4 symmetry broken";
  for (double edge : d.edges) EXPECT_NEAR(edge, d.edges[0], 1e-9 * d.centre) << d.label;
  EXPECT_GT(d.centre, d.edges[0]) << d.label << ": the middle sags most";
}

TEST(BlockDrapeModes, BothInitialIncrementsReachTheSameSymmetricStableDrape) {
  struct Case {
    const char* file;
    double increment;
    StepControl control;
  };
  const Case cases[] = {{"block-drape.json", 0.00025, StepControl::kArcLength},
                        {"block-drape-buckling.json", 0.00125, StepControl::kArcLength},
                        {"block-drape.json", 0.00025, StepControl::kLoad},
                        {"block-drape-buckling.json", 0.00125, StepControl::kLoad}};
  std::vector<Drape> drapes;
  for (const Case& c : cases) {
    const Scene scene = BlockDrapeScene(c.file, c.control);
    ASSERT_EQ(scene.stages[0].initial_increment, c.increment) << c.file;
    char label[64];
    std::snprintf(label,
                  sizeof label,
                  "dl0 = %.5f %s",
                  c.increment,
                  c.control == StepControl::kLoad ? "load" : "arc-length");
    drapes.push_back(RunDrape(label, scene));
    if (!drapes.back().complete) return;
  }
  std::printf(
      "  paper, Table 1: dl0 = 0.00025 smooth (first step 5 it, lambda 4.8e-4), "
      "0.00125 buckled (13 it, lambda 8.1e-3)\n");
  PrintHeader();
  for (const Drape& d : drapes) PrintRow(d, Distance(d, drapes[0]) / drapes[0].centre);
  for (const Drape& d : drapes) PrintFirstStep(d);

  for (const Drape& d : drapes) {
    ExpectSmoothSymmetricStable(d);
    // The same drape, to the Newton tolerance, whatever Δλ₀ and control.
    EXPECT_LT(Distance(d, drapes[0]), 1e-5 * drapes[0].centre) << d.label;
  }
  // Δλ₀ does change the stepping, not the result: the larger one covers
  // more of the load in its first arc-length step (measured: λ 0.50 against
  // 0.0094), and its first load-controlled step needs more Newton
  // iterations (13 against 9, residual up and down).
  EXPECT_GT(drapes[1].first_lambda, drapes[0].first_lambda);
  EXPECT_GT(drapes[3].first_iterations, drapes[2].first_iterations);
  // (The sag itself, about 0.69 in in the middle and 0.52 in at the edges,
  // is printed, not asserted: it is our own result, and its mesh dependence
  // is what the ShellSolver mesh-convergence tests check.)
}

TEST(BlockDrapeModes, ImperfectionSeedsPerturbButDoNotSelectModesOfTheCornerPinnedSheet) {
  const Scene flat = BlockDrapeScene("block-drape.json", StepControl::kArcLength);
  ASSERT_EQ(flat.stages[0].initial_increment, 0.00025);
  const Drape perfect = RunDrape("flat", flat);
  if (!perfect.complete) return;

  // The paper's waviness: each node uniform in ±1e-4 in, Δλ₀ = 0.00025.
  auto wavy = [&](std::uint64_t seed, double amplitude) {
    Scene scene = flat;
    scene.fabric.imperfection =
        ImperfectionSpec{amplitude, seed, ImperfectionPattern::kNodal, std::nullopt};
    char label[64];
    std::snprintf(
        label, sizeof label, "nodal +-%.0e in, seed %d", amplitude / kInch, static_cast<int>(seed));
    return RunDrape(label, scene);
  };
  const double amplitude = 1e-4 * kInch;
  std::vector<Drape> seeds;
  for (std::uint64_t seed : {1, 2, 3, 4}) seeds.push_back(wavy(seed, amplitude));
  // A hundred times the waviness, to see how the drape responds to it.
  const Drape large = wavy(1, 100 * amplitude);

  PrintHeader();
  PrintRow(perfect, 0);
  for (const Drape& d : seeds) PrintRow(d, Distance(d, perfect) / perfect.centre);
  PrintRow(large, Distance(large, perfect) / perfect.centre);

  for (const Drape& d : seeds) {
    if (!d.complete) continue;
    // Stable all the way, like the paper's wavy runs ("none of these is a
    // buckling mode")...
    EXPECT_EQ(d.max_pivots, 0) << d.label;
    EXPECT_EQ(d.final_pivots, 0) << d.label;
    EXPECT_EQ(d.stability_events, 0) << d.label;
    EXPECT_EQ(d.indefinite_factorizations, 0) << d.label;
    // ...but one mode, not four: the drape moves by the order of the
    // waviness (measured: about twice it), not by the order of the sag, and
    // every mirror of the square stays a symmetry up to that.
    EXPECT_LT(Distance(d, perfect), 10 * amplitude) << d.label;
    EXPECT_GT(d.MaxAsymmetry(), 0.5 * amplitude) << d.label << ": the waviness should show";
    EXPECT_LT(d.MaxAsymmetry(), 10 * amplitude) << d.label;
    for (int e = 0; e < 4; ++e)
      EXPECT_NEAR(d.edges[e], perfect.edges[e], 10 * amplitude) << d.label << " edge " << e;
  }
  // Linear in the waviness (×100 in, ×100 out within 30 %): no bifurcation
  // near the path that a small imperfection could tip one way or the other.
  if (large.complete && seeds[0].complete) {
    EXPECT_EQ(large.max_pivots, 0);
    const double gain = large.MaxAsymmetry() / seeds[0].MaxAsymmetry();
    std::printf("  asymmetry x%.1f for a waviness x100 (seed 1)\n", gain);
    EXPECT_GT(gain, 70);
    EXPECT_LT(gain, 130);
  }
}

}  // namespace
}  // namespace drape
