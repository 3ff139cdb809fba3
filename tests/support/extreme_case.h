// The extremes matrix's cases (tests/extremes/extreme_cases.cc): what a
// case is and how it must end, the independent answers its property checks
// compare with (the heavy elastica ODE, force balance), and the scenes the
// cases are built from.
#pragma once

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/model/imperfection.h"
#include "core/model/scene.h"
#include "support/heavy_elastica.h"
#include "support/strip_scene.h"

namespace drape::test {

enum class Ends { kConverged, kFailed, kRefused };

inline const char* ToString(Ends e) {
  return e == Ends::kConverged ? "converged" : e == Ends::kFailed ? "failed" : "refused";
}

struct CaseRun {
  int exit_code = -1;
  std::string output;     // what drape printed
  nlohmann::json result;  // result.json; null when refused
  double seconds = 0;
};

struct ExtremeCase {
  std::string name;
  // Writes what the scene needs into the folder (e.g. a Kawabata file) and
  // returns the scene.
  std::function<Scene(const std::filesystem::path& dir)> scene;
  Ends ends = Ends::kConverged;
  // Converged: the property checked. Failed or refused: what the message
  // must name (a key, or the cause).
  std::function<void(const Scene&, const CaseRun&)> check;
  std::vector<std::string> message_names;
  double time_limit_s = 60;
  // Tens of seconds here, minutes under the sanitizers: run by
  // extremes_slow_test.cc, in the slow tier (tests/CMakeLists.txt).
  bool slow = false;
};

inline ExtremeCase Slow(ExtremeCase c) {
  c.slow = true;
  return c;
}

using SceneMaker = std::function<Scene(const std::filesystem::path& dir)>;
using Property = std::function<void(const Scene&, const CaseRun&)>;

inline ExtremeCase Converges(std::string name,
                             SceneMaker scene,
                             Property check,
                             double limit_s = 60) {
  ExtremeCase c;
  c.name = std::move(name);
  c.scene = std::move(scene);
  c.check = std::move(check);
  c.time_limit_s = limit_s;
  return c;
}

// Ends `ends` (failed or refused) with a message naming each of `names`.
inline ExtremeCase Stops(std::string name,
                         SceneMaker scene,
                         Ends ends,
                         std::vector<std::string> names) {
  ExtremeCase c;
  c.name = std::move(name);
  c.scene = std::move(scene);
  c.ends = ends;
  c.message_names = std::move(names);
  return c;
}

// gtest names a case by its name, not its bytes.
inline void PrintTo(const ExtremeCase& c, std::ostream* os) {
  *os << c.name;
}

// ---- independent answers ---------------------------------------------------

inline Eigen::Vector3d FinalProbe(const CaseRun& run, const std::string& name) {
  const nlohmann::json& p = run.result["final"]["probes"][name];
  return {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
}

inline Eigen::Vector3d LastReaction(const CaseRun& run, const std::string& name) {
  const nlohmann::json& r = run.result["steps"].back()["reactions"][name];
  return {r[0].get<double>(), r[1].get<double>(), r[2].get<double>()};
}

inline double RectangleArea(const Scene& scene) {
  const auto& r = std::get<RectangleOutline>(scene.fabric.outline);
  return r.size[0] * r.size[1];
}

// Supports, grippers and obstacles together carry the part's weight: their
// forces sum to minus it (docs/format.md §5.1), here to `relative` of it or of
// the largest force, whichever is larger.
inline void ExpectForceBalance(const Scene& scene, const CaseRun& run, double relative = 1e-6) {
  const nlohmann::json& last = run.result["steps"].back();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double largest = 0;
  for (const auto& [name, r] : last["reactions"].items()) {
    const Eigen::Vector3d f(r[0].get<double>(), r[1].get<double>(), r[2].get<double>());
    sum += f;
    largest = std::max(largest, f.norm());
  }
  if (last.contains("contact")) {
    const nlohmann::json& c = last["contact"]["force"];
    const Eigen::Vector3d f(c[0].get<double>(), c[1].get<double>(), c[2].get<double>());
    sum += f;
    largest = std::max(largest, f.norm());
  }
  const Eigen::Vector3d weight = scene.material.areal_weight * RectangleArea(scene) *
                                 Eigen::Vector3d(0, 0, -1) * last["lambda"].get<double>();
  EXPECT_LT((sum + weight).norm(), relative * std::max(weight.norm(), largest))
      << "reactions + contact = " << sum.transpose() << " N, weight " << weight.transpose();
}

// The cantilever's tip against the heavy elastica with the scene's α.
inline void ExpectElasticaTip(const CaseRun& run, double length, double alpha, double within) {
  const ElasticaEnd exact = SolveHeavyElastica(alpha);
  const Eigen::Vector3d tip = FinalProbe(run, "tip") / length;
  const double error = std::hypot(tip.x() - exact.x, tip.z() - exact.z);
  EXPECT_LT(error, within) << "tip/L (" << tip.x() << ", " << tip.z() << "), elastica (" << exact.x
                           << ", " << exact.z << ")";
  std::printf("  elastica α = %g: tip error %.2e L\n", alpha, error);
}

// ---- the scenes ------------------------------------------------------------

// Peirce's strip (α = wbL³/EI = 8: the chord at 41.5°) with its weight
// chosen from the section's bending stiffness, so that thickness, modulus
// and Poisson's ratio change nothing in the answer. A narrow strip bends as
// a beam (EI = E b h³ / 12, its cross-section free to curve the other way);
// a `plate` as wide as it is long bends cylindrically, D = E h³ / 12(1 − ν²).
constexpr double kPeirceAlpha = 8;

inline Scene PeirceStrip(StripSpec spec,
                         double poisson = 0,
                         double increment = 0.05,
                         bool plate = false,
                         double alpha = kPeirceAlpha) {
  Scene scene = HeavyStrip(spec, alpha, increment);
  scene.material.membrane = IsotropicMembrane{spec.youngs_modulus, poisson};
  if (plate) scene.material.areal_weight /= (1 - poisson * poisson);
  return scene;
}

// 1e-3 L: four times the largest error a case measured (6.4e-4 L at h = 5 mm;
// the 40-element strip's own is 2.3e-4 L), far below what locking, a wrong
// branch or a half-converged state would leave.
inline void PeirceChecks(const Scene& scene, const CaseRun& run, double within = 1e-3) {
  ExpectElasticaTip(run, 0.2, kPeirceAlpha, within);
  ExpectForceBalance(scene, run);
}

inline ExtremeCase Peirce(std::string name,
                          StripSpec spec,
                          double poisson = 0,
                          double within = 1e-3) {
  return Converges(
      std::move(name),
      [spec, poisson](const std::filesystem::path&) { return PeirceStrip(spec, poisson); },
      [within](const Scene& s, const CaseRun& r) { PeirceChecks(s, r, within); });
}

inline ExtremeCase PeirceWithSolver(std::string name,
                                    std::function<void(Scene&)> edit,
                                    std::function<void(const Scene&, const CaseRun&)> check) {
  return Converges(
      std::move(name),
      [edit](const std::filesystem::path&) {
        Scene scene = PeirceStrip({});
        edit(scene);
        return scene;
      },
      std::move(check));
}

// A weightless strip, clamped at x = 0 and held at x = L by a gripper.
inline Scene GrippedStrip(double length, double width, int nx, int ny, Fixity hold) {
  StripSpec spec{length, width, 5e-4, 1e6, nx};
  Scene scene = CantileverStrip(spec);
  scene.fabric.mesh.elements = std::array<int, 2>{nx, ny};
  scene.grippers.push_back({"end", Selection{EdgeSelection{Side::kRight}, {}}, hold});
  scene.probes.push_back({"middle", {length / 2, 0.0}});
  return scene;
}

inline Stage MoveStage(const std::string& gripper, Path path, double increment) {
  Stage stage;
  stage.name = "move";
  stage.kind = StageKind::kMove;
  stage.initial_increment = increment;
  stage.moves.push_back({gripper, std::move(path), ""});
  return stage;
}

// Kawabata data of a linear law M = B K over a full KES cycle, with
// relative noise `noise` on M (seeded), in SI units (the header says so).
inline void WriteKawabata(const std::filesystem::path& file,
                          double rigidity,
                          double noise,
                          int points_per_branch) {
  std::ofstream out(file);
  out << "curvature (1/m),moment (N*m/m)\n";
  SplitMix64 rng(1802);
  const double k_max = 100;  // 1/m
  auto row = [&](double k) {
    const double u = static_cast<double>(rng.Next() >> 11) / 9007199254740992.0;  // [0, 1)
    out << k << "," << rigidity * k * (1 + noise * (2 * u - 1)) << "\n";
  };
  const int n = points_per_branch;
  for (int i = 0; i <= n; ++i) row(k_max * i / n);
  for (int i = n - 1; i >= 0; --i) row(k_max * i / n);
  for (int i = 1; i <= n; ++i) row(-k_max * i / n);
  for (int i = n - 1; i >= 0; --i) row(-k_max * i / n);
}

// The whole matrix (extreme_cases.cc), the slow cases or the rest.
std::vector<ExtremeCase> ExtremeCases(bool slow);

// Runs a case through `drape run` and checks how it ended, its property and
// that every number it wrote is finite.
void RunExtremeCase(const ExtremeCase& c);

// A case's name as a test name: letters and digits, the rest '_'.
std::string TestName(const ::testing::TestParamInfo<ExtremeCase>& info);

}  // namespace drape::test
