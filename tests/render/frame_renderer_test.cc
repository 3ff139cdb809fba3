// Offscreen pictures checked by content, not by pixels: the size, where the
// fabric projects for a known camera, the colour map's two ends on a bent
// strip, obstacles and grippers where they are. Runs under xvfb-run -a.
#include "ui/render/frame_renderer.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/io/scene_reader.h"
#include "core/measure/drape_test_setup.h"
#include "core/mechanics/director.h"
#include "core/solve/shell_solver.h"
#include "support/bent_strip.h"
#include "support/display_required.h"
#include "support/strip_scene.h"
#include "support/test_paths.h"
#include "ui/render/display.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // rows from the top
  std::array<int, 3> At(int x, int y) const {
    const size_t i = (static_cast<size_t>(y) * width + x) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

// Hue in degrees [0, 360) and saturation [0, 1] of an RGB pixel.
std::pair<double, double> HueSaturation(const std::array<int, 3>& p) {
  const double r = p[0] / 255.0, g = p[1] / 255.0, b = p[2] / 255.0;
  const double hi = std::max({r, g, b}), lo = std::min({r, g, b});
  if (hi - lo < 1e-9) return {0, 0};
  double h;
  if (hi == r)
    h = 60 * std::fmod((g - b) / (hi - lo), 6.0);
  else if (hi == g)
    h = 60 * ((b - r) / (hi - lo) + 2);
  else
    h = 60 * ((r - g) / (hi - lo) + 4);
  if (h < 0) h += 360;
  return {h, (hi - lo) / hi};
}

// The fabric's face colour (0.93, 0.62, 0.33), shaded: hue about 29°.
bool IsFabricFace(const std::array<int, 3>& p) {
  const auto [h, s] = HueSaturation(p);
  return s > 0.4 && h > 18 && h < 40;
}

// Where a world point lands in the picture (rows from the top).
Eigen::Vector2d Project(FrameRenderer& r, const Eigen::Vector3d& x) {
  vtkRenderer* ren = r.renderer();
  ren->SetWorldPoint(x.x(), x.y(), x.z(), 1.0);
  ren->WorldToDisplay();
  double d[3];
  ren->GetDisplayPoint(d);
  return {d[0], r.height() - 1 - d[1]};
}

class FrameRendererTest : public ::testing::Test {
 protected:
  void SetUp() override { DRAPE_REQUIRE_DISPLAY(); }
};

// A 20 × 10 cm sheet, flat, seen from the top.
Scene FlatSheet() {
  test::StripSpec spec;
  spec.width = 0.1;
  Scene scene = test::CantileverStrip(spec);
  scene.fabric.mesh.elements = std::array<int, 2>{20, 10};
  scene.probes.clear();
  return scene;
}

RenderOptions Bare(int w, int h) {
  RenderOptions o;
  o.width = w;
  o.height = h;
  o.floor = false;
  o.paths = false;
  o.overlay = false;
  return o;
}

TEST_F(FrameRendererTest, FlatSheetFromTheTopFillsItsRectangle) {
  const Scene scene = FlatSheet();
  const ShellModel model = BuildShellModel(scene);
  RenderOptions options = Bare(640, 480);
  options.camera.view = "top";
  ShellState state = model.reference;
  FrameRenderer renderer(scene, model, options, RunBounds(scene, {&state}));
  Frame frame;
  frame.state = &state;
  renderer.Show(frame);
  Image image{640, 480, renderer.CaptureRgb()};
  ASSERT_EQ(image.rgb.size(), 640u * 480 * 3);
  // The sheet spans x ∈ [0, 0.2], y ∈ [−0.05, 0.05] at z = 0.
  const Eigen::Vector2d a = Project(renderer, {0, -0.05, 0});
  const Eigen::Vector2d b = Project(renderer, {0.2, 0.05, 0});
  const double x0 = std::min(a.x(), b.x()), x1 = std::max(a.x(), b.x());
  const double y0 = std::min(a.y(), b.y()), y1 = std::max(a.y(), b.y());
  std::printf("sheet projects to x %.1f..%.1f, y %.1f..%.1f px\n", x0, x1, y0, y1);
  EXPECT_GT(x1 - x0, 300);  // fitted: it fills most of the width
  int inside = 0, inside_fabric = 0, outside = 0, outside_fabric = 0;
  const double slack = 3;  // pixels: anti-aliasing and the supports' glyphs at the root
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const bool fabric = IsFabricFace(image.At(x, y));
      if (x > x0 + slack && x < x1 - slack && y > y0 + slack && y < y1 - slack) {
        ++inside;
        inside_fabric += fabric;
      } else if (x < x0 - slack || x > x1 + slack || y < y0 - slack || y > y1 + slack) {
        ++outside;
        outside_fabric += fabric;
      }
    }
  // The clamped root's support glyphs cover a strip of the left edge.
  EXPECT_GT(inside_fabric, 0.97 * inside) << inside_fabric << " of " << inside;
  EXPECT_EQ(outside_fabric, 0) << "of " << outside;
}

TEST_F(FrameRendererTest, PngHasTheRequestedSize) {
  const Scene scene = FlatSheet();
  const ShellModel model = BuildShellModel(scene);
  ShellState state = model.reference;
  FrameRenderer renderer(scene, model, Bare(333, 222), RunBounds(scene, {&state}));
  Frame frame;
  frame.state = &state;
  renderer.Show(frame);
  const fs::path file = fs::temp_directory_path() / "drape-render-size.png";
  renderer.WritePng(file);
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName(file.string().c_str());
  reader->Update();
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 333);
  EXPECT_EQ(dims[1], 222);
  fs::remove(file);
}

// The strip bent with curvature rising linearly from 0 at the root to
// 30 1/m at the tip (θ = 15 s²/L), so both ends of the map must show: for
// viridis (the default) its dark violet (68, 1, 84; hue 289°) and its
// yellow (253, 231, 37; hue 54°), for the rainbow blue and red.
TEST_F(FrameRendererTest, CurvatureFieldSpansTheColourMap) {
  for (ColourMap map : {ColourMap::kViridis, ColourMap::kRainbow}) {
    SCOPED_TRACE(ToString(map));
    test::StripSpec spec;
    Scene scene = test::CantileverStrip(spec);
    scene.probes.clear();
    const ShellModel model = BuildShellModel(scene);
    const ShellState state = test::BentStrip(spec, model);  // θ(s) = 15 s²/L
    RenderOptions options = Bare(800, 500);
    options.field = FieldKind::kCurvature;
    options.colour_map = map;
    options.camera.view = "top";  // the strip's face, bent up towards the camera
    FrameRenderer renderer(scene, model, options, RunBounds(scene, {&state}));
    Frame frame;
    frame.state = &state;
    renderer.Show(frame);
    Image image{800, 500, renderer.CaptureRgb()};
    const bool viridis = map == ColourMap::kViridis;
    int low = 0, high = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width * 3 / 4; ++x) {  // left of the colour bar
        const auto [h, s] = HueSaturation(image.At(x, y));
        if (s < 0.6) continue;
        low += viridis ? h > 275 && h < 305 : h > 225 && h < 255;
        high += viridis ? h > 45 && h < 62 : h < 12 || h > 348;
      }
    std::printf("%s: fabric pixels coloured as the map's low end: %d, high end: %d\n",
                ToString(map),
                low,
                high);
    EXPECT_GT(low, 50);
    EXPECT_GT(high, 50);
  }
}

// The friction field of a flat sheet seen from the top, its left half
// sticking (1) and its right half sliding (2): the field's fixed range
// [0, 2] puts sliding at viridis's yellow end (hue 54°) and sticking at its
// middle, teal (33, 145, 140; hue 177°); a frame without the field's values
// (a run without friction, or an earlier step) is one message.
TEST_F(FrameRendererTest, FrictionFieldShowsStickingAndSlidingNodes) {
  const Scene scene = FlatSheet();
  const ShellModel model = BuildShellModel(scene);
  RenderOptions options = Bare(640, 480);
  options.camera.view = "top";
  options.field = FieldKind::kFrictionState;
  ShellState state = model.reference;
  FrameRenderer renderer(scene, model, options, RunBounds(scene, {&state}));
  Frame frame;
  frame.state = &state;
  EXPECT_THROW(
      {
        try {
          renderer.Show(frame);
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("stick and slide is stored for the last step"),
                    std::string::npos)
              << e.what();
          throw;
        }
      },
      std::invalid_argument);
  for (int i = 0; i < model.NodeCount(); ++i)
    frame.friction_state.push_back(model.reference.positions(i, 0) < 0.1 ? 1.0 : 2.0);
  renderer.Show(frame);
  Image image{640, 480, renderer.CaptureRgb()};
  const Eigen::Vector2d left = Project(renderer, {0.04, 0, 0});
  const Eigen::Vector2d right = Project(renderer, {0.16, 0, 0});
  const auto [left_hue, left_saturation] =
      HueSaturation(image.At(static_cast<int>(left.x()), static_cast<int>(left.y())));
  const auto [right_hue, right_saturation] =
      HueSaturation(image.At(static_cast<int>(right.x()), static_cast<int>(right.y())));
  std::printf("sticking half: hue %.0f°, sliding half: hue %.0f°\n", left_hue, right_hue);
  EXPECT_GT(left_saturation, 0.5);
  EXPECT_GT(right_saturation, 0.5);
  EXPECT_NEAR(left_hue, 177, 15);
  EXPECT_NEAR(right_hue, 54, 10);
}

TEST_F(FrameRendererTest, ObstaclesAndGrippersAreWhereTheSceneSays) {
  Scene scene = FlatSheet();
  // A sphere beside the sheet and a gripper at its far corner.
  scene.obstacles.push_back({"ball", SphereShape{{0.1, 0.15, 0.0}, 0.03}});
  scene.grippers.push_back(
      {"corner", Selection{PointSelection{{0.2, 0.05}}, {}}, Fixity::kPosition});
  const ShellModel model = BuildShellModel(scene);
  ShellState state = model.reference;
  state.obstacles.assign(1, ObstaclePlacement{});
  RenderOptions options = Bare(640, 480);
  options.camera.view = "top";
  FrameRenderer renderer(scene, model, options, RunBounds(scene, {&state}));
  Frame frame;
  frame.state = &state;
  renderer.Show(frame);
  Image image{640, 480, renderer.CaptureRgb()};
  // The sphere's centre: the obstacle grey (neutral, lit).
  const Eigen::Vector2d ball = Project(renderer, {0.1, 0.15, 0.03});
  const auto [h_ball, s_ball] = HueSaturation(image.At(int(ball.x()), int(ball.y())));
  EXPECT_LT(s_ball, 0.2) << "hue " << h_ball;
  EXPECT_FALSE(IsFabricFace(image.At(int(ball.x()), int(ball.y()))));
  // The gripper's glyph: red, at the corner node.
  const Eigen::Vector2d grip = Project(renderer, {0.2, 0.05, 0});
  const auto [h_grip, s_grip] = HueSaturation(image.At(int(grip.x()), int(grip.y())));
  EXPECT_GT(s_grip, 0.5);
  EXPECT_TRUE(h_grip < 15 || h_grip > 345) << "hue " << h_grip;

  // A stage that releases it: from that stage's states on, no glyph; the
  // stage before (here the reference state: no stage yet) still shows it.
  const int released_in = static_cast<int>(scene.stages.size());
  Stage release;
  release.name = "let go";
  release.kind = StageKind::kHold;
  release.release = {"corner"};
  scene.stages.push_back(release);
  FrameRenderer again(scene, model, options, RunBounds(scene, {&state}));
  auto at_corner = [&](int stage) {
    frame.stage = stage;
    again.Show(frame);
    Image picture{640, 480, again.CaptureRgb()};
    const Eigen::Vector2d p = Project(again, {0.2, 0.05, 0});
    return picture.At(int(p.x()), int(p.y()));
  };
  const auto [h_held, s_held] = HueSaturation(at_corner(released_in - 1));
  EXPECT_TRUE(s_held > 0.5 && (h_held < 15 || h_held > 345)) << "hue " << h_held;
  const auto [h_free, s_free] = HueSaturation(at_corner(released_in));
  EXPECT_FALSE(s_free > 0.5 && (h_free < 15 || h_free > 345)) << "hue " << h_free;
}

// The shipped strip fold's last state seen from above: where the upper
// layer lies on the lower, only its own face shows (the back, its underside
// before the fold). Without self-contact the layers cross there and the
// lower layer's front face shows through in stripes: the check can fail.
int LowerFaceShowingThroughTheUpperLayer(bool self_contact) {
  Scene scene = ReadScene(test::ScenesDir() / "strip-fold.json");
  scene.contact->self = self_contact;
  ShellSolver solver(scene, SolverOptions::FromScene(scene.solver));
  ShellState last;
  const SolveSummary summary = solver.Solve({[&](const StepState& s) {
    last = s.state;
    return StepDecision::kContinue;
  }});
  EXPECT_TRUE(summary.IsComplete()) << summary.FullReport();
  const ShellModel model = BuildShellModel(scene);
  // The flat part of the upper layer: nodes of the left half (before the
  // fold) now within 3 h of the table, one element in from its ends.
  double x0 = INFINITY, x1 = -INFINITY;
  for (int i = 0; i < model.NodeCount(); ++i)
    if (model.reference.positions(i, 0) < -0.03 && last.positions(i, 2) < 3 * model.thickness) {
      x0 = std::min(x0, last.positions(i, 0));
      x1 = std::max(x1, last.positions(i, 0));
    }
  EXPECT_GT(x1 - x0, 0.03);  // a few centimetres of it lie flat
  x0 += 0.005;
  x1 -= 0.005;
  RenderOptions options = Bare(1000, 400);
  options.camera.view = "top";
  FrameRenderer renderer(scene, model, options, RunBounds(scene, {&last}));
  Frame frame;
  frame.state = &last;
  renderer.Show(frame);
  const Image image{1000, 400, renderer.CaptureRgb()};
  const Eigen::Vector2d a = Project(renderer, {x0, -0.008, 0});
  const Eigen::Vector2d b = Project(renderer, {x1, 0.008, 0});
  int pixels = 0, front = 0;
  for (int y = static_cast<int>(std::min(a.y(), b.y())); y < std::max(a.y(), b.y()); ++y)
    for (int x = static_cast<int>(std::min(a.x(), b.x())); x < std::max(a.x(), b.x()); ++x) {
      ++pixels;
      front += IsFabricFace(image.At(x, y));
    }
  std::printf("self-contact %s: %d of %d pixels over the upper layer show the lower one\n",
              self_contact ? "on" : "off",
              front,
              pixels);
  EXPECT_GT(pixels, 1000);
  return front;
}

TEST_F(FrameRendererTest, FoldedLayersDrawWithoutZFighting) {
  EXPECT_EQ(LowerFaceShowingThroughTheUpperLayer(true), 0);
  EXPECT_GT(LowerFaceShowingThroughTheUpperLayer(false), 100);
}

// A preview's ghost (issue 20) over the flat sheet, from the top: a draft
// sheet on a coarser mesh (10 × 5), moved half a sheet along x and 1 cm up,
// so that one half of it lies over the fabric and the other over the
// background. Where it lies over the fabric the picture changes (the ghost
// shows) but differs from the ghost over the background (the fabric behind
// still shows: translucent), and it has no colour field of its own.
TEST_F(FrameRendererTest, GhostIsTranslucentOverTheFabric) {
  const Scene scene = FlatSheet();
  const ShellModel model = BuildShellModel(scene);
  Scene coarse = scene;
  coarse.fabric.mesh.elements = std::array<int, 2>{10, 5};
  const ShellModel draft = BuildShellModel(coarse);
  ShellState ghost = draft.reference;
  ghost.positions.col(0).array() += 0.1;
  ghost.positions.col(2).array() += 0.01;
  ShellState state = model.reference;
  RenderOptions options = Bare(640, 480);
  options.camera.view = "top";
  options.field = FieldKind::kCurvature;  // the fabric's field must not colour the ghost
  FrameRenderer renderer(scene, model, options, RunBounds(scene, {&state, &ghost}));
  Frame frame;
  frame.state = &state;
  renderer.Show(frame);
  const Image before{640, 480, renderer.CaptureRgb()};
  renderer.SetGhost(draft.mesh, ghost);
  EXPECT_TRUE(renderer.HasGhost());
  renderer.Show(frame);
  const Image after{640, 480, renderer.CaptureRgb()};
  renderer.WritePng(fs::temp_directory_path() / "drape-render-ghost.png");
  // Pixel centres: the sheet alone at x = 0.05, ghost over the sheet at
  // 0.15, ghost alone at 0.25 (all at y = 0).
  auto at = [&](const Image& image, double x) {
    const Eigen::Vector2d p = Project(renderer, {x, 0, 0});
    return image.At(static_cast<int>(p.x()), static_cast<int>(p.y()));
  };
  auto distance = [](const std::array<int, 3>& a, const std::array<int, 3>& b) {
    return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
  };
  const auto sheet = at(after, 0.05), over = at(after, 0.15), alone = at(after, 0.25);
  std::printf("sheet %d %d %d, ghost over sheet %d %d %d, ghost alone %d %d %d\n",
              sheet[0],
              sheet[1],
              sheet[2],
              over[0],
              over[1],
              over[2],
              alone[0],
              alone[1],
              alone[2]);
  EXPECT_EQ(distance(at(before, 0.05), sheet), 0);   // no ghost there
  EXPECT_GT(distance(at(before, 0.15), over), 60);   // the ghost shows over the fabric
  EXPECT_GT(distance(at(before, 0.25), alone), 60);  // and over the background
  EXPECT_GT(distance(over, alone), 60);              // the fabric behind shows through
  const auto [hue, saturation] = HueSaturation(alone);
  EXPECT_GT(hue, 190);  // light blue, not a colour of the map
  EXPECT_LT(hue, 230);
  EXPECT_LT(saturation, 0.5);
  renderer.ClearGhost();
  EXPECT_FALSE(renderer.HasGhost());
  renderer.Show(frame);
  const Image cleared{640, 480, renderer.CaptureRgb()};
  EXPECT_EQ(cleared.rgb, before.rgb);
}

// The drapemeter's view of a skirt hanging from an 18 cm disc as a cone
// whose rim reaches 12 cm: from the top, the dark shadow covers the disc of
// 12 cm and nothing beyond it, the disc's rim is drawn red, and the image's
// dark area is π (12 cm)² at the picture's scale.
TEST_F(FrameRendererTest, TheDrapemetersViewFillsTheShadowAndDrawsTheDisc) {
  // The shipped Cusick test's specimen, disc and fabric; no probe labels.
  Scene scene = ReadScene(test::ScenesDir() / "cusick-drape.json");
  scene.probes.clear();
  const ShellModel model = BuildShellModel(scene);
  ShellState state = model.reference;
  constexpr double kReach = 0.5, kRim = 0.09 + kReach * 0.06;
  for (int i = 0; i < model.NodeCount(); ++i) {
    const double x = state.positions(i, 0), y = state.positions(i, 1);
    const double rho = std::hypot(x, y), s = std::max(0.0, rho - 0.09);
    if (s == 0) continue;
    const double r = 0.09 + kReach * s;
    state.positions.row(i) << r * x / rho, r * y / rho, -s * std::sqrt(1 - kReach * kReach);
  }
  RenderOptions options = Bare(640, 480);
  options.camera.view = "top";
  options.floor = true;  // asked for, but no grid may cross the shadow
  options.drape_shadow = DrapeTestFor(scene, model.mesh, std::nullopt, std::nullopt);
  FrameRenderer renderer(scene, model, options, RunBounds(scene, {&model.reference, &state}));
  Frame frame;
  frame.state = &state;
  renderer.Show(frame);
  const Image image{640, 480, renderer.CaptureRgb()};
  renderer.WritePng(fs::temp_directory_path() / "drape-render-drapemeter.png");
  const Eigen::Vector2d centre = Project(renderer, {0, 0, 0});
  const double metre = (Project(renderer, {0.1, 0, 0}) - centre).norm() / 0.1;  // [px/m]
  auto dark = [](const std::array<int, 3>& p) { return p[0] + p[1] + p[2] < 3 * 150; };
  auto at = [&](double r, double angle) {
    return image.At(static_cast<int>(centre.x() + metre * r * std::cos(angle)),
                    static_cast<int>(centre.y() - metre * r * std::sin(angle)));
  };
  for (double angle = 0.1; angle < 6.2; angle += 0.5) {
    EXPECT_TRUE(dark(at(0.05, angle))) << "inside the disc at " << angle;
    EXPECT_TRUE(dark(at(0.105, angle))) << "between the disc's rim and the shadow's, " << angle;
    EXPECT_FALSE(dark(at(0.135, angle))) << "beyond the shadow at " << angle;
    bool red = false;  // the 2.5 px line, within a pixel of where the disc's rim projects
    for (double dr = -1.5; dr <= 1.5; dr += 0.5) {
      const auto p = at(0.09 + dr / metre, angle);
      red |= p[0] > p[1] + 60;
    }
    EXPECT_TRUE(red) << "the disc's rim is red at " << angle;
  }
  int dark_pixels = 0;  // inside the specimen's grey rim (at 15 cm), which is dark too
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (std::hypot(x + 0.5 - centre.x(), y + 0.5 - centre.y()) < 0.14 * metre)
        dark_pixels += dark(image.At(x, y));
  const double expected = M_PI * std::pow(kRim * metre, 2);
  EXPECT_NEAR(dark_pixels / expected, 1, 0.01) << dark_pixels << " px against " << expected;
}

}  // namespace
}  // namespace drape
