// The extremes matrix (issue 18; the table of outcomes and times is in
// docs/robustness.md). Each case is a scene at an edge of what a user may
// ask — gossamer and board-like sheets, one element and 200 × 200, needle
// elements, first increments of 10⁻⁶ and 1, tolerances of 10⁻¹² and 0.5,
// penalties of 1 and 10¹² N/m³, weightless parts, bending 10⁻¹² of normal,
// a gripper turned 720°, a strip stretched to three times its length, a
// gripper driven into a table, a sheet that must wrinkle on a ball, noisy and
// degenerate Kawabata files — run through `drape run` as a user would, under
// a wall-clock limit so that a hang fails instead of stalling CI.
//
// Every case's outcome is asserted: it converges and a property is checked
// against an independent answer (the heavy elastica ODE, a closed form, force
// balance, symmetry); or it fails (exit 2, status failed) with a message that
// names what to change; or it is refused (exit 1) naming the key. Whatever it
// ends as, no number in result.json, states.bin or a CSV export is NaN or
// infinite.
//
// The cases and how one is run; extremes_test.cc and extremes_slow_test.cc
// (the cases marked Slow) instantiate them.
#include <gtest/gtest.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/io/scene_writer.h"
#include "core/io/state_file.h"
#include "support/contact_scenes.h"
#include "support/drape_command.h"
#include "support/extreme_case.h"
#include "support/finite_outputs.h"
#include "support/strip_scene.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::CaseRun;
using test::Converges;
using test::Ends;
using test::ExpectElasticaTip;
using test::ExpectForceBalance;
using test::ExtremeCase;
using test::FinalProbe;
using test::GrippedStrip;
using test::kPeirceAlpha;
using test::LastReaction;
using test::MoveStage;
using test::Peirce;
using test::PeirceChecks;
using test::PeirceStrip;
using test::PeirceWithSolver;
using test::Stops;
using test::WriteKawabata;

std::vector<ExtremeCase> AllCases() {
  std::vector<ExtremeCase> cases;
  const test::StripSpec base;  // 0.2 × 0.01 m, h 0.5 mm, E 1 MPa, 40 × 1

  // Material: the same elastica from gossamer to board.
  cases.push_back(Slow(Peirce("thickness_1e-5_m", {0.2, 0.01, 1e-5, 1e6, 40})));
  cases.push_back(Peirce("thickness_5e-3_m", {0.2, 0.01, 5e-3, 1e6, 40}));
  cases.push_back(Peirce("modulus_1e4_Pa", {0.2, 0.01, 5e-4, 1e4, 40}));
  cases.push_back(Peirce("modulus_1e10_Pa", {0.2, 0.01, 5e-4, 1e10, 40}));
  // A 2 mm strip is a beam only nearly: its anticlastic curvature is not
  // wholly free (measured 3.5e-3 L from the beam's elastica).
  cases.push_back(Peirce("poisson_0_49", {0.2, 0.002, 5e-4, 1e6, 40}, 0.49, 5e-3));
  // Needle elements: 5 mm along the strip, 100 mm across it.
  cases.push_back(Peirce("aspect_ratio_20", {0.2, 0.1, 5e-4, 1e6, 40}));

  // Meshes: one element (force balance only: one element cannot bend like
  // the elastica), and 200 × 200 (symmetry across the clamp's mid-line).
  cases.push_back(Converges(
      "mesh_1x1",
      [](const fs::path&) {
        // α = 1: a single element can bend that far (at α = 8 its one
        // curvature cannot follow the elastica and the path meets a
        // bifurcation at λ = 0.9992 with no stable branch).
        return PeirceStrip({0.2, 0.01, 5e-4, 1e6, 1}, 0, 0.05, false, 1);
      },
      [](const Scene& s, const CaseRun& r) {
        ExpectForceBalance(s, r);
        ExpectElasticaTip(r, 0.2, 1, 0.01);
      }));
  cases.push_back(Slow(Converges(
      "mesh_200x200",
      [](const fs::path&) {
        test::StripSpec s = {0.2, 0.2, 5e-4, 1e6, 200};
        // α = 0.5: a small deflection, so that one step of a few Newton
        // iterations does it (each factorisation of 200 000 unknowns takes
        // seconds).
        Scene scene = PeirceStrip(s, 0.3, 1.0, true, 0.5);
        scene.fabric.mesh.elements = std::array<int, 2>{200, 200};
        scene.probes.push_back({"corner_up", {0.2, 0.1}});
        scene.probes.push_back({"corner_down", {0.2, -0.1}});
        return scene;
      },
      [](const Scene& s, const CaseRun& r) {
        ExpectForceBalance(s, r);
        const Eigen::Vector3d up = FinalProbe(r, "corner_up");
        const Eigen::Vector3d down = FinalProbe(r, "corner_down");
        EXPECT_NEAR(up.x(), down.x(), 1e-9);
        EXPECT_NEAR(up.y(), -down.y(), 1e-9);
        EXPECT_NEAR(up.z(), down.z(), 1e-9);
        // Held flat across its width except near its free edges, the plate
        // hangs between the elastica with the plate's rigidity D (α = 0.5)
        // and the one with the beam's, D (1 − ν²) (α = 0.5 / 0.91).
        const double z = FinalProbe(r, "tip").z() / 0.2;
        EXPECT_LT(z, test::SolveHeavyElastica(0.5).z);
        EXPECT_GT(z, test::SolveHeavyElastica(0.5 / (1 - 0.3 * 0.3)).z);
      },
      900)));

  // Path following: first increments, tolerances.
  cases.push_back(PeirceWithSolver(
      "increment_1e-6",
      [](Scene& s) { s.stages[0].initial_increment = 1e-6; },
      [](const Scene& s, const CaseRun& r) { PeirceChecks(s, r); }));
  cases.push_back(PeirceWithSolver(
      "increment_1",
      [](Scene& s) { s.stages[0].initial_increment = 1; },
      [](const Scene& s, const CaseRun& r) { PeirceChecks(s, r); }));
  cases.push_back(PeirceWithSolver(
      "tolerance_1e-12",
      [](Scene& s) { s.solver.tolerance = 1e-12; },
      [](const Scene& s, const CaseRun& r) { PeirceChecks(s, r); }));
  cases.push_back(PeirceWithSolver(
      "tolerance_0_5",
      [](Scene& s) { s.solver.tolerance = 0.5; },
      [](const Scene&, const CaseRun& r) {
        for (const json& step : r.result["steps"])
          EXPECT_LE(step["residual_ratio"].get<double>(), 0.5);
        // Up to half the residual left in a step, yet the last steps
        // converge further than asked: the tip within 2e-3 L of the
        // elastica (measured 7.0e-4 L, against 2.3e-4 L at 1e-5).
        ExpectElasticaTip(r, 0.2, kPeirceAlpha, 2e-3);
      }));

  // Contact penalties: a sheet lying on a table under its weight sinks by
  // w / k (a soft penalty lets it sink two metres: the result says so).
  auto sheet_on_table = [](double penalty) {
    return [penalty](const fs::path&) {
      Scene scene = test::SheetOnTable(test::SheetSpec{});
      scene.contact->penalty = penalty;
      return scene;
    };
  };
  cases.push_back(
      Converges("penalty_1_N_per_m3", sheet_on_table(1), [](const Scene& s, const CaseRun& r) {
        ExpectForceBalance(s, r);
        // A uniform pressure w on a foundation of stiffness k: it sinks w / k.
        EXPECT_NEAR(r.result["contact"]["max_penetration"].get<double>(),
                    s.material.areal_weight / 1.0,
                    1e-3 * s.material.areal_weight);
      }));
  cases.push_back(Converges(
      "penalty_1e12_N_per_m3", sheet_on_table(1e12), [](const Scene& s, const CaseRun& r) {
        ExpectForceBalance(s, r);
        EXPECT_LT(r.result["contact"]["max_penetration"].get<double>(),
                  10 * s.material.areal_weight / 1e12);
      }));

  // Loads: a weightless part under gravity; bending 10⁻¹² of the plate's.
  cases.push_back(Stops("weightless",
                        [](const fs::path&) {
                          Scene scene = PeirceStrip({});
                          scene.material.areal_weight = 0;
                          return scene;
                        },
                        Ends::kRefused,
                        {"material.areal_weight"}));
  // The flat strip then has (almost) no stiffness against its weight: no
  // first step can be taken, and its tangent is singular to round-off, so
  // what the minimiser makes of it depends on the build's rounding. Under
  // stable branching the release build snaps from its start and hangs
  // straight down (tip at −L, as a string would), then past λ = 0.068 finds
  // no rest state to jump to; the sanitized build finds none from the start
  // ("barely resists its load … nor does it come to rest"). Both say so.
  cases.push_back(Stops("bending_1e-12_of_normal",
                        [](const fs::path&) {
                          Scene scene = PeirceStrip({});
                          const double plate = 1e6 * std::pow(5e-4, 3) / 12;
                          scene.material.bending.warp = LinearBending{1e-12 * plate};
                          return scene;
                        },
                        Ends::kFailed,
                        {"no rest state"}));

  // Grippers: two full turns about the strip's axis; a strip pulled to
  // three times its length; an end driven into a table.
  auto twisted = [](double width, double pull, int max_steps) {
    return [=](const fs::path&) {
      Scene scene = GrippedStrip(0.2, width, 40, 2, Fixity::kClamp);
      if (pull > 0) scene.stages.push_back(MoveStage("end", LinePath{{pull, 0, 0}}, 0.5));
      scene.stages.push_back(MoveStage("end", ArcPath{{0.2 + pull, 0, 0}, {1, 0, 0}, 720}, 0.01));
      scene.stages.back().name = "twist";
      scene.solver.max_steps = max_steps;
      return scene;
    };
  };
  // A narrow strip twists into a helicoid, slack or pulled 2 %. A helicoid
  // maps onto itself under a half turn about its axis, so the centre line
  // stays on it.
  auto helicoid = [](const Scene& s, const CaseRun& r) {
    ExpectForceBalance(s, r, 1e-8);
    const Eigen::Vector3d middle = FinalProbe(r, "middle");
    EXPECT_LT(std::hypot(middle.y(), middle.z()), 1e-6 * 0.2);
  };
  cases.push_back(Converges("gripper_turns_720_deg", twisted(0.005, 0, 5000), helicoid));
  cases.push_back(Converges("gripper_turns_720_deg_pulled", twisted(0.005, 0.004, 5000), helicoid));
  // Four times wider (η b = 1.26 at two turns), it buckles out of the
  // helicoid at 226° even pulled 10 %: twist turns into writhe, as a
  // telephone cord coils, the loop presses on itself and the path creeps.
  cases.push_back(Stops("gripper_turns_720_deg_wide",
                        twisted(0.02, 0.02, 300),
                        Ends::kFailed,
                        {"snap", "stages[1]"}));
  // ν = 0, Green–Lagrange strain (s² − 1)/2 and S = E times it: the force
  // per reference width is E h s (s² − 1)/2 at stretch s.
  auto stretched = [](double stretch) {
    return [=](const fs::path&) {
      Scene scene = GrippedStrip(0.1, 0.01, 10, 1, Fixity::kPosition);
      scene.stages.push_back(MoveStage("end", LinePath{{0.1 * (stretch - 1), 0, 0}}, 0.05));
      return scene;
    };
  };
  auto stretch_force = [](double stretch) {
    return [=](const Scene&, const CaseRun& r) {
      const double expected = 1e6 * 5e-4 * 0.01 * stretch * (stretch * stretch - 1) / 2;
      EXPECT_NEAR(LastReaction(r, "end").x(), expected, 1e-6 * expected);
      EXPECT_NEAR(LastReaction(r, "root").x(), -expected, 1e-6 * expected);
    };
  };
  cases.push_back(Converges("strip_stretched_3x", stretched(3), stretch_force(3)));
  cases.push_back(Converges("strip_stretched_10x", stretched(10), stretch_force(10)));
  cases.push_back(Stops(
      "gripper_into_table",
      [](const fs::path&) {
        Scene scene = GrippedStrip(0.2, 0.02, 20, 2, Fixity::kPosition);
        scene.material.areal_weight = 1.5;
        scene.obstacles.push_back({"table", PlaneShape{{0, 0, -0.5 * 5e-4 - 1e-4}, {0, 0, 1}}});
        scene.contact = Contact{};
        scene.stages.push_back(MoveStage("end", LinePath{{0, 0, -0.02}}, 0.05));
        return scene;
      },
      Ends::kFailed,
      {"gripper 'end'", "inside obstacle 'table'", "stages[0].moves"}));

  // A disk that must wrinkle over a ball much smaller than itself.
  cases.push_back(Stops("sheet_wrinkling_on_small_ball",
                        [](const fs::path&) {
                          Scene scene = test::SheetOverSphere(test::SheetSpec{}, 0.03);
                          scene.solver.branching = Branching::kStable;
                          return scene;
                        },
                        Ends::kFailed,
                        {"solver.branching"}));

  // Parts held by nothing but contact on small forms, as issue 18 measured
  // them: each fails, and its message names the cause and the key.
  auto on_dress_form = [](double width, double length, int nx, int ny) {
    Scene scene;
    scene.name = "on the dress form";
    scene.fabric.outline = RectangleOutline{{length, width}, {0, 0}};
    scene.fabric.mesh.elements = std::array<int, 2>{nx, ny};
    scene.fabric.elevation = 0.60025;  // h/2 above the neck
    scene.material.thickness = 5e-4;
    scene.material.areal_weight = 2;
    scene.material.membrane = IsotropicMembrane{1e6, 0.3};
    scene.material.bending.warp = LinearBending{};
    MeshShape form;
    form.file = (test::SourceDir() / "resources" / "forms" / "dress-form.obj").string();
    scene.obstacles.push_back({"form", form});
    scene.contact = Contact{};
    Stage stage;
    stage.name = "drop";
    scene.stages.push_back(stage);
    return scene;
  };
  // A 50 × 50 cm sheet laid on the neck: frictionless, it slides off.
  cases.push_back(Slow(Stops("sheet_resting_on_dress_form",
                             [=](const fs::path&) { return on_dress_form(0.5, 0.5, 25, 25); },
                             Ends::kFailed,
                             {"frictionless", "contact.friction"})));
  // With friction it holds, but must wrinkle over the neck. Under the
  // lagged friction (issue 35), with friction restarting where a snap lands,
  // it climbs to λ = 0.417 in 354 steps, 15 snaps and 8 branch switches, and
  // stops there (the corrector runs back along the path), 190 s; before, the
  // regularised friction diverged at λ = 0.00097. Not yet a drape: here it
  // is held to 60 steps, and must say so naming the key.
  cases.push_back(Slow(Stops("sheet_resting_on_dress_form_with_friction",
                             [=](const fs::path&) {
                               Scene scene = on_dress_form(0.5, 0.5, 25, 25);
                               scene.contact->friction = 0.3;
                               scene.solver.max_steps = 60;
                               return scene;
                             },
                             Ends::kFailed,
                             {"solver.max_steps"})));
  // The scarf (resources/scenes/dress-form-drape.json) with a penalty ten
  // times the automatic one.
  cases.push_back(Stops("scarf_with_stiff_penalty",
                        [=](const fs::path&) {
                          Scene scene = on_dress_form(0.05, 0.7, 70, 4);
                          scene.contact->penalty = 4e7;
                          scene.solver.branching = Branching::kFundamental;
                          return scene;
                        },
                        Ends::kFailed,
                        {"contact.penalty", "\"auto\""}));
  // A very soft strip (E = 1 MPa, h = 0.1 mm, 0.5 N/m²) dropped over a rod.
  // 6.5 s here since issue 35's friction work (1.5 s before; not yet
  // understood), past its 60 s limit under the sanitizers: the slow tier.
  cases.push_back(Slow(Stops(
      "soft_strip_over_rod",
      [](const fs::path&) {
        Scene scene;
        scene.name = "soft strip over a rod";
        scene.fabric.outline = RectangleOutline{{0.3, 0.05}, {0, 0}};
        scene.fabric.mesh.elements = std::array<int, 2>{60, 4};
        scene.material.thickness = 1e-4;
        scene.material.areal_weight = 0.5;
        scene.material.membrane = IsotropicMembrane{1e6, 0.3};
        scene.material.bending.warp = LinearBending{};
        scene.obstacles.push_back({"rod", CylinderShape{{0, 0, -0.01005}, {0, 1, 0}, 0.01, {}}});
        scene.contact = Contact{};
        Stage stage;
        stage.name = "drop";
        scene.stages.push_back(stage);
        return scene;
      },
      Ends::kFailed,
      {"frictionless", "contact.friction"})));

  // Kawabata files: 20 % noise on a linear law (the averaged branches still
  // give the elastica), and a file whose moments never change.
  auto kawabata = [](std::string file, double rigidity, double noise, int points) {
    return [=](const fs::path& dir) {
      Scene scene = PeirceStrip({});
      WriteKawabata(dir / file, rigidity, noise, points);
      CurveBending law;
      law.file = (dir / file).string();
      scene.material.bending.warp = law;
      return scene;
    };
  };
  const double plate = 1e6 * std::pow(5e-4, 3) / 12;
  cases.push_back(Converges("kawabata_noisy",
                            kawabata("noisy.csv", plate, 0.2, 50),
                            [](const Scene& s, const CaseRun& r) { PeirceChecks(s, r, 0.02); }));
  cases.push_back(
      Stops("kawabata_flat", kawabata("flat.csv", 0, 0, 20), Ends::kRefused, {"material.bending"}));
  return cases;
}

// ---- running one case ------------------------------------------------------

CaseRun RunCase(const ExtremeCase& c, const Scene& scene, const fs::path& dir) {
  WriteScene(scene, dir / "scene.json");
  CaseRun run;
  const auto start = std::chrono::steady_clock::now();
  const test::CommandResult r =
      test::RunDrape("run '" + (dir / "scene.json").string() + "' -o '" + (dir / "out").string() +
                     "' --time-limit " + std::to_string(c.time_limit_s));
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.exit_code = r.exit_code;
  run.output = r.output;
  if (fs::exists(dir / "out" / "result.json")) {
    std::ifstream in(dir / "out" / "result.json");
    run.result = json::parse(in);
  }
  return run;
}

void ExpectFiniteOutputs(const fs::path& out) {
  std::vector<std::string> nulls;
  std::ifstream in(out / "result.json");
  test::CollectNulls(json::parse(in), "", nulls);
  EXPECT_TRUE(nulls.empty()) << "result.json: " << nulls.size() << " non-finite numbers, first at "
                             << nulls.front();
  if (!fs::exists(out / "states.bin")) return;
  const StateFile states = ReadStateFile(out / "states.bin");
  EXPECT_EQ(test::FirstNonFiniteStep(states), -1) << "states.bin";
#ifdef DRAPE_WITH_EXPORT
  if (states.steps.empty()) return;
  const test::CommandResult exported = test::RunDrape(
      "export '" + out.string() + "' -o '" + (out / "csv").string() + "' --format csv --step last");
  ASSERT_EQ(exported.exit_code, 0) << exported.output;
  for (const auto& entry : fs::directory_iterator(out / "csv")) {
    std::string first;
    EXPECT_EQ(test::NonFiniteTokens(entry.path(), &first), 0) << entry.path() << ": " << first;
  }
#endif
}

}  // namespace

namespace test {

void RunExtremeCase(const ExtremeCase& c) {
  const fs::path dir = fs::temp_directory_path() / ("drape-extremes-" + c.name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Scene scene = c.scene(dir);
  const CaseRun run = RunCase(c, scene, dir);
  const std::string status = run.result.is_null() ? "-" : run.result["status"].get<std::string>();
  std::printf("| %s | %s (exit %d) | %.2f s |\n",
              c.name.c_str(),
              status.c_str(),
              run.exit_code,
              run.seconds);

  if (run.exit_code != 0)
    std::printf("  %s\n", run.output.substr(0, run.output.find('\n')).c_str());
  const int expected_exit = c.ends == Ends::kConverged ? 0 : c.ends == Ends::kFailed ? 2 : 1;
  ASSERT_EQ(run.exit_code, expected_exit) << "expected " << ToString(c.ends) << "; drape said:\n"
                                          << run.output;
  if (c.ends != Ends::kRefused) {
    ASSERT_FALSE(run.result.is_null());
    EXPECT_EQ(status, ToString(c.ends));
    ExpectFiniteOutputs(dir / "out");
  }
  if (c.ends == Ends::kConverged) {
    c.check(scene, run);
  } else {
    for (const std::string& name : c.message_names)
      EXPECT_NE(run.output.find(name), std::string::npos)
          << "the message does not name '" << name << "':\n"
          << run.output;
    EXPECT_EQ(run.output.find("time limit"), std::string::npos) << run.output;
  }
  if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

std::vector<ExtremeCase> ExtremeCases(bool slow) {
  std::vector<ExtremeCase> cases;
  for (ExtremeCase& c : AllCases())
    if (c.slow == slow) cases.push_back(std::move(c));
  return cases;
}

std::string TestName(const ::testing::TestParamInfo<ExtremeCase>& info) {
  std::string name = info.param.name;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

}  // namespace test
}  // namespace drape
