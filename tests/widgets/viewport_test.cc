// The Qt 6 ↔ VTK viewport under Xvfb: the fabric's pixels must reach the
// widget's framebuffer (a naive bridge renders black), and the workbench
// shows a run's steps as they arrive. Qt's QTest waits for the window.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <vtkGenericOpenGLRenderWindow.h>
#include <QApplication>
#include <QImage>
#include <QSignalSpy>
#include <QTest>

#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "support/strip_scene.h"
#include "support/test_paths.h"
#include "ui/render/display.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {
namespace {

// The fabric's face colour (0.93, 0.62, 0.33) or its back (0.47, 0.36,
// 0.62), shaded: saturated orange or violet.
bool IsFabric(QRgb p) {
  const QColor c(p);
  const int h = c.hsvHue(), s = c.hsvSaturation();
  return s > 80 && ((h >= 18 && h <= 40) || (h >= 250 && h <= 290));
}

int CountFabric(const QImage& image) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) n += IsFabric(image.pixel(x, y));
  return n;
}

class Widgets : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!DisplayProblem().empty()) return;
    QSurfaceFormat::setDefaultFormat(VtkViewport::defaultFormat());
    static int argc = 1;
    static char name[] = "widgets_tests";
    static char* argv[] = {name, nullptr};
    static QApplication app(argc, argv);
  }
  void SetUp() override {
    if (!DisplayProblem().empty()) GTEST_SKIP() << "no display: run under xvfb-run -a";
  }
};

TEST_F(Widgets, ViewportShowsTheFabricNotBlack) {
  test::StripSpec spec;
  spec.width = 0.1;
  Scene scene = test::CantileverStrip(spec);
  scene.fabric.mesh.elements = std::array<int, 2>{20, 10};
  const ShellModel model = BuildShellModel(scene);
  VtkViewport viewport;
  viewport.resize(480, 320);
  viewport.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&viewport));
  ShellState state = model.reference;
  RenderOptions options;
  options.camera.view = "top";
  viewport.makeCurrent();
  FrameRenderer renderer(
      scene, model, options, RunBounds(scene, {&state}), std::nullopt, viewport.renderWindow());
  viewport.doneCurrent();
  Frame frame;
  frame.state = &state;
  renderer.Update(frame);
  viewport.requestRender();
  QTest::qWait(100);
  const QImage image = viewport.grabFramebuffer();
  ASSERT_FALSE(image.isNull());
  EXPECT_EQ(image.width(), 480);
  int black = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) black += qGray(image.pixel(x, y)) < 10;
  const int fabric = CountFabric(image);
  std::printf("viewport 480 x 320: %d fabric pixels, %d black\n", fabric, black);
  // The 20 × 10 cm sheet fills about half the width from the top: tens of
  // thousands of pixels; the background is light, never black.
  EXPECT_GT(fabric, 10000);
  EXPECT_LT(black, 480 * 320 / 100);
  viewport.makeCurrent();
}

TEST_F(Widgets, WorkbenchShowsEveryStepOfARunInOrder) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(window.openScene(
      QString::fromStdString((test::ScenesDir() / "strip-convergence-20.json").string())));
  QSignalSpy finished(&window, &MainWindow::runFinished);
  window.run();
  ASSERT_TRUE(finished.wait(60000));
  const auto summary = finished.takeFirst().at(0).value<SolveSummary>();
  EXPECT_TRUE(summary.IsComplete()) << summary.message;
  EXPECT_EQ(window.stepCount(), summary.steps);
  QTest::qWait(100);
  const QImage shown = window.viewport()->grabFramebuffer();
  // The viewport draws what the offscreen renderer draws of the last step
  // (the same builder, camera and size): the same fabric, to a few pixels
  // of rasterisation.
  const Scene scene = ReadScene(test::ScenesDir() / "strip-convergence-20.json");
  const ShellModel model = BuildShellModel(scene);
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  StepState last;
  solver.Solve({[&](const StepState& s) {
    last = s;
    return StepDecision::kContinue;
  }});
  Eigen::AlignedBox3d bounds = RunBounds(scene, {&model.reference});
  for (const auto& p : GripperPathPoints(scene, model)) bounds.extend(p);
  RenderOptions options;
  options.width = shown.width();
  options.height = shown.height();
  FrameRenderer offscreen(scene, model, options, bounds);
  Frame frame;
  frame.state = &last.state;
  frame.step = last.step;
  frame.stage_name = last.stage_name;
  frame.lambda = last.lambda;
  offscreen.Show(frame);
  const std::vector<unsigned char> rgb = offscreen.CaptureRgb();
  int expected = 0;
  for (size_t i = 0; i + 2 < rgb.size(); i += 3)
    expected += IsFabric(qRgb(rgb[i], rgb[i + 1], rgb[i + 2]));
  const int fabric = CountFabric(shown);
  std::printf("fabric pixels: viewport %d, offscreen %d\n", fabric, expected);
  EXPECT_GT(expected, 2000);
  EXPECT_NEAR(fabric, expected, 0.05 * expected);
}

// The automation CI uses: open, run, screenshot, quit.
TEST_F(Widgets, StudioRunsAScriptAndWritesANonBlackScreenshot) {
  const std::string shot = (std::filesystem::temp_directory_path() /
                            ("drape-studio-" + std::to_string(getpid()) + ".png"))
                               .string();
  const std::string command = std::string(DRAPE_STUDIO) + " '" +
                              (test::ScenesDir() / "strip-fold.json").string() +
                              "' --run --screenshot '" + shot + "' --quit 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string out;
  char buf[512];
  while (fgets(buf, sizeof buf, pipe)) out += buf;
  const int status = pclose(pipe);
  ASSERT_EQ(status, 0) << out;
  EXPECT_NE(out.find("converged: 58 steps"), std::string::npos) << out;
  const QImage image(QString::fromStdString(shot));
  ASSERT_FALSE(image.isNull()) << shot;
  const int fabric = CountFabric(image);
  std::printf("screenshot %d x %d: %d fabric pixels\n", image.width(), image.height(), fabric);
  EXPECT_GT(fabric, 2000);
  std::filesystem::remove(shot);
}

}  // namespace
}  // namespace drape
