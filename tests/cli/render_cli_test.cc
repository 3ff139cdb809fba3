// `drape render`, `drape animate`, `drape export` end to end on the solved
// strip fold (resources/scenes/strip-fold.json): files of the asked size and frame count (ffprobe),
// no broken file on failure, one clear message without a display.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/drape_command.h"
#include "support/test_paths.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using test::RunDrape;

// PNG width and height from the IHDR chunk (bytes 16–23, big-endian).
std::pair<uint32_t, uint32_t> PngSize(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  unsigned char b[24] = {};
  in.read(reinterpret_cast<char*>(b), 24);
  auto be = [&](int i) {
    return uint32_t(b[i]) << 24 | uint32_t(b[i + 1]) << 16 | uint32_t(b[i + 2]) << 8 | b[i + 3];
  };
  return {be(16), be(20)};
}

// "frames,width,height" of a movie's first video stream, as ffprobe counts.
std::string Probe(const fs::path& movie) {
  FILE* pipe = popen(("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                      "stream=nb_read_frames,width,height -of csv=p=0 '" +
                      movie.string() + "' 2>&1")
                         .c_str(),
                     "r");
  std::string out;
  char buf[256];
  while (fgets(buf, sizeof buf, pipe)) out += buf;
  pclose(pipe);
  while (!out.empty() && (out.back() == '\n' || out.back() == ',')) out.pop_back();
  return out;
}

class RenderCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // One folder per process: CTest runs these tests side by side.
    dir_ = fs::temp_directory_path() / ("drape-render-cli-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    // The paper's strip fold (Table 3).
    const auto r = RunDrape("run '" + (test::ScenesDir() / "strip-fold.json").string() + "' -o '" +
                            (dir_ / "fold").string() + "' --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }
  static std::string Fold() { return "'" + (dir_ / "fold").string() + "'"; }
  static std::string Out(const std::string& name) { return "'" + (dir_ / name).string() + "'"; }
  // Steps of the run, and the reference state: frames of an animation.
  static int States() {
    int n = 0;
    std::ifstream csv(dir_ / "fold" / "steps.csv");
    std::string line;
    while (std::getline(csv, line)) ++n;
    return n;  // header + steps = steps + reference
  }
  static fs::path dir_;
};
fs::path RenderCli::dir_;

TEST_F(RenderCli, RenderWritesAPngOfTheAskedSize) {
  const auto r = RunDrape("render " + Fold() + " -o " + Out("last.png") +
                          " --size 321x203 --field curvature --camera top");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(PngSize(dir_ / "last.png"), std::make_pair(321u, 203u));
  // A scene renders its reference state.
  const auto s = RunDrape("render '" + (test::ScenesDir() / "strip-fold.json").string() + "' -o " +
                          Out("scene.png") + " --step 0 --size 200x100");
  ASSERT_EQ(s.exit_code, 0) << s.output;
  EXPECT_EQ(PngSize(dir_ / "scene.png"), std::make_pair(200u, 100u));
}

// The top of the colour bar `drape render` reports ("curvature [1/cm]: 0 to
// 0.5235"), after the title given; NaN when the line is missing.
double BarTop(const std::string& output, const std::string& title) {
  const auto at = output.find(title + ": ");
  if (at == std::string::npos) return NAN;
  const auto to = output.find(" to ", at);
  return to == std::string::npos ? NAN : std::stod(output.substr(to + 4));
}

// --units: the colour bar's title names the unit and its numbers are the
// SI ones over the unit's factor (1 cm = 0.01 m, 1 in = 0.0254 m); without
// it, a scene's own units (the strip fold is written in cm) and SI for a
// result folder that has no scene.json.
TEST_F(RenderCli, UnitsNameAndScaleTheColourBar) {
  auto render = [&](const std::string& input, const std::string& more) {
    const auto r = RunDrape("render " + input + " -o " + Out("units.png") +
                            " --size 400x300 --field curvature" + more);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return r.output;
  };
  const double si = BarTop(render(Fold(), " --units si"), "curvature [1/m]");
  ASSERT_GT(si, 10) << "the fold's curvature, 1/m";
  EXPECT_NEAR(
      BarTop(render(Fold(), " --units textile"), "curvature [1/cm]"), si / 100, 5e-4 * si / 100);
  EXPECT_NEAR(BarTop(render(Fold(), " --units imperial"), "curvature [1/in]"),
              si * 0.0254,
              5e-4 * si * 0.0254);
  EXPECT_NEAR(BarTop(render(Fold(), ""), "curvature [1/m]"), si, 5e-4 * si);
  const std::string scene = "'" + (test::ScenesDir() / "strip-fold.json").string() + "'";
  EXPECT_EQ(BarTop(render(scene, ""), "curvature [1/cm]"), 0.0) << "flat: no curvature";
  const auto r = RunDrape("render " + Fold() + " -o " + Out("x.png") + " --units metric");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--units"), std::string::npos) << r.output;
}

TEST_F(RenderCli, BadArgumentsAreOneMessageAndExitOne) {
  auto r = RunDrape("render " + Fold() + " -o " + Out("x.png") + " --step 999");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--step: '999' is not a step of this result"), std::string::npos)
      << r.output;
  r = RunDrape("render " + Fold() + " -o " + Out("x.png") + " --field curvatur");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--field: unknown field 'curvatur'"), std::string::npos) << r.output;
  r = RunDrape("render " + Fold() + " -o " + Out("x.png") + " --size 12x9000");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--size"), std::string::npos) << r.output;
  // The strip fold is no drape test: no support selects a disc.
  r = RunDrape("render " + Fold() + " -o " + Out("x.png") + " --shadow");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--shadow: no support disc"), std::string::npos) << r.output;
  r = RunDrape("render '/no/such/result' -o " + Out("x.png"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("/no/such/result"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

// --plot reactions: the chart of each hold's |F| against the step instead of
// the fabric (its pixels: tests/render/reaction_chart_test.cc).
TEST_F(RenderCli, PlotReactionsDrawsAChart) {
  auto r = RunDrape("render " + Fold() + " --plot reactions -o " + Out("reactions.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(PngSize(dir_ / "reactions.png"), std::make_pair(1280u, 720u));
  r = RunDrape("render " + Fold() + "/result.json --plot reactions -o " + Out("small.png") +
               " --size 640x400");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(PngSize(dir_ / "small.png"), std::make_pair(640u, 400u));
  // --units picks the force axis' unit (its pixels: reaction_chart_test.cc).
  r = RunDrape("render " + Fold() + " --plot reactions --units textile -o " + Out("gf.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "gf.png"));
}

TEST_F(RenderCli, PlotReactionsRefusesWhatItCannotDraw) {
  auto expect_refused = [](const std::string& arguments, const std::string& message) {
    const auto r = RunDrape(arguments);
    EXPECT_EQ(r.exit_code, 1) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << arguments << "\n" << r.output;
  };
  const std::string plot = " --plot reactions -o " + Out("refused.png");
  expect_refused("render '" + (test::ScenesDir() / "strip-fold.json").string() + "'" + plot,
                 "strip-fold.json: a scene has no reactions; --plot reactions draws a result");
  expect_refused("render " + Fold() + " --plot forces -o " + Out("refused.png"),
                 "--plot: forces not in {reactions}");
  expect_refused("render " + Fold() + plot + " --step 3", "--step excludes --plot");
  expect_refused("render " + Fold() + plot + " --field curvature", "--field excludes --plot");
  expect_refused("render " + Fold() + plot + " --size 10x10", "--size");

  // A copy of the fold with one value changed at a time.
  const fs::path copy = dir_ / "fold-copy";
  fs::create_directories(copy);
  std::ifstream in(dir_ / "fold" / "result.json");
  const nlohmann::json original = nlohmann::json::parse(in);
  auto with = [&](const nlohmann::json& doc, const std::string& states) {
    std::ofstream(copy / "result.json") << doc.dump();
    fs::copy_file(
        dir_ / "fold" / "states.bin", copy / "states.bin", fs::copy_options::overwrite_existing);
    if (!states.empty()) fs::resize_file(copy / "states.bin", std::stoul(states));
    return "render '" + copy.string() + "'" + plot;
  };
  // A NaN (written as null) is refused by the reader, naming the key.
  nlohmann::json doc = original;
  doc["steps"][5]["reactions"]["end"][0] = nullptr;
  expect_refused(with(doc, ""), "result.json: steps[5].reactions.end: [null,");
  // Components a double holds whose magnitude it does not.
  doc = original;
  doc["steps"][5]["reactions"]["end"] = {1.7e308, 1.7e308, 0.0};
  expect_refused(with(doc, ""),
                 "result.json: reaction of 'end (gripper)' at step 6: |F| = inf N is not a "
                 "finite magnitude; nothing drawn");
  // No step at all: result.json lists none and states.bin ends after its
  // mesh (magic, header, 3N positions, 4E quads).
  doc = original;
  doc["steps"] = nlohmann::json::array();
  doc["status"] = "failed";
  const int nodes = doc["mesh"]["nodes"], elements = doc["mesh"]["elements"];
  const size_t mesh_bytes = 8 + 16 + 24 * nodes + 16 * elements + (elements % 2 ? 4 : 0);
  expect_refused(with(doc, std::to_string(mesh_bytes)),
                 "result.json: the run has no converged step (status 'failed'), so there are no "
                 "reactions to plot");
  EXPECT_FALSE(fs::exists(dir_ / "refused.png"));
}

TEST_F(RenderCli, AnimateMp4HasOneFramePerStep) {
  const auto r = RunDrape("animate " + Fold() + " -o " + Out("fold.mp4") + " --size 320x240");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(Probe(dir_ / "fold.mp4"), "320,240," + std::to_string(States()));
  EXPECT_FALSE(fs::exists(dir_ / "fold.partial.mp4"));
}

TEST_F(RenderCli, AnimateGifOgvAndFramesOpen) {
  auto r = RunDrape("animate " + Fold() + " -o " + Out("fold.gif") +
                    " --size 160x120 --duration 1.2 --fps 10");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(Probe(dir_ / "fold.gif"), "160,120,12");
  r = RunDrape("animate " + Fold() + " -o " + Out("fold.ogv") + " --size 160x120");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(Probe(dir_ / "fold.ogv"), "160,120," + std::to_string(States()));
  r = RunDrape("animate " + Fold() + " -o " + Out("frames") + " --size 160x120");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  int pngs = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "frames"))
    pngs += e.path().extension() == ".png";
  EXPECT_EQ(pngs, States());
  EXPECT_EQ(PngSize(dir_ / "frames" / "frame_0001.png"), std::make_pair(160u, 120u));
}

TEST_F(RenderCli, InterruptedAnimationLeavesNoMovie) {
  // A long animation, interrupted once it is under way: exit 130, and
  // neither the movie nor its partial file remains.
  const std::string script = "(" + std::string(test::DrapeCli()) + " animate " + Fold() + " -o " +
                             Out("long.mp4") +
                             " --size 320x240 --duration 120 --fps 30 & pid=$!; sleep 2; kill -INT "
                             "$pid; wait $pid; echo exit=$?) 2>&1";
  FILE* pipe = popen(script.c_str(), "r");
  std::string out;
  char buf[512];
  while (fgets(buf, sizeof buf, pipe)) out += buf;
  pclose(pipe);
  EXPECT_NE(out.find("exit=130"), std::string::npos) << out;
  EXPECT_NE(out.find("cancelled after"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir_ / "long.mp4"));
  EXPECT_FALSE(fs::exists(dir_ / "long.partial.mp4"));
}

TEST_F(RenderCli, ExportWritesEveryStepAndACollection) {
  auto r = RunDrape("export " + Fold() + " -o " + Out("vtu") + " --format vtu");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir_ / "vtu" / "run.pvd"));
  int vtu = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "vtu")) vtu += e.path().extension() == ".vtu";
  EXPECT_EQ(vtu, States());
  r = RunDrape("export " + Fold() + " -o " + Out("stl") + " --format stl --step last --solid");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = RunDrape("export " + Fold() + " -o " + Out("bad") + " --format step");
  EXPECT_NE(r.exit_code, 0);
}

TEST_F(RenderCli, RunRendersEveryNthStepWhileSolving) {
  const auto r = RunDrape("run '" + (test::ScenesDir() / "strip-convergence-20.json").string() +
                          "' -o " + Out("framed") + " --quiet --render-every 10");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream csv(dir_ / "framed" / "steps.csv");
  std::string line;
  int steps = -1;  // the header
  while (std::getline(csv, line)) ++steps;
  int pngs = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "framed" / "frames"))
    pngs += e.path().extension() == ".png";
  EXPECT_EQ(pngs, steps / 10);
  EXPECT_EQ(PngSize(dir_ / "framed" / "frames" / "step_0010.png"), std::make_pair(1280u, 720u));
}

// `drape` hands the commands that draw to drape-vtk (app/render_program.h):
// laid out as `cmake --install` does, it finds it in ../libexec/drape; where
// there is none, it says so and exits 1 (and the other commands still work).
TEST_F(RenderCli, AnInstalledDrapeFindsItsRenderProgram) {
  const fs::path prefix = dir_ / "installed";
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "libexec/drape");
  fs::copy_file(test::DrapeCli(), prefix / "bin/drape");
  const std::string drape = (prefix / "bin/drape").string();
  const std::string export_csv =
      " export " + Fold() + " -o " + Out("installed-csv") + " --format csv --step last";

  auto alone = test::RunCommand(drape + export_csv);
  EXPECT_EQ(alone.exit_code, 1) << alone.output;
  EXPECT_NE(alone.output.find("drape export: this installation has no renderer"), std::string::npos)
      << alone.output;
  EXPECT_EQ(test::RunCommand(drape + " validate '" +
                             (test::ScenesDir() / "strip-fold.json").string() + "'")
                .exit_code,
            0);

  fs::copy_file(fs::path(test::DrapeCli()).parent_path() / "drape-vtk",
                prefix / "libexec/drape/drape-vtk");
  const auto installed = test::RunCommand(drape + export_csv);
  ASSERT_EQ(installed.exit_code, 0) << installed.output;
  // The last step's nodes and elements.
  int csv = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "installed-csv"))
    csv += e.path().extension() == ".csv";
  EXPECT_EQ(csv, 2);
}

TEST_F(RenderCli, WithoutADisplayRenderingSaysToUseXvfb) {
  for (const std::string& command : {"render " + Fold() + " -o " + Out("nodisplay.png"),
                                     "animate " + Fold() + " -o " + Out("nodisplay.mp4")}) {
    const std::string env_command =
        "env -u DISPLAY " + std::string(test::DrapeCli()) + " " + command + " 2>&1";
    FILE* pipe = popen(env_command.c_str(), "r");
    std::string out;
    char buf[512];
    while (fgets(buf, sizeof buf, pipe)) out += buf;
    const int status = pclose(pipe);
    EXPECT_TRUE(WIFEXITED(status)) << "killed by a signal: " << out;
    EXPECT_EQ(WEXITSTATUS(status), 1) << out;
    EXPECT_NE(out.find("xvfb-run -a"), std::string::npos) << out;
  }
  EXPECT_FALSE(fs::exists(dir_ / "nodisplay.png"));
  EXPECT_FALSE(fs::exists(dir_ / "nodisplay.mp4"));
}

}  // namespace
}  // namespace drape
