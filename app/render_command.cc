// `drape render INPUT -o image.png` and `drape animate RESULT -o movie`:
// offscreen pictures of a run (or a scene's reference state) with the
// renderer the workbench uses (ui/render).
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>

#include "app/commands.h"
#include "app/render_program.h"
#include "core/fe/element_fields.h"
#include "core/model/unit_system.h"
#ifdef DRAPE_WITH_RENDER
#include "app/run_input.h"
#include "core/io/result_reader.h"
#include "core/measure/drape_test_setup.h"
#include "core/model/scene_error.h"
#include "ui/render/animation.h"
#include "ui/render/display.h"
#include "ui/render/field_units.h"
#include "ui/render/frame_renderer.h"
#include "ui/render/reaction_chart.h"
#endif

namespace drape::app {
namespace {

namespace fs = std::filesystem;

// The options both commands share.
struct ViewArgs {
  std::string size = "1280x720";
  std::string field;
  std::string colour_map = "viridis";
  std::string camera = "iso";
  std::string units;  // empty: the scene's own
  std::vector<double> position, focal_point, view_up;
  bool edges = false, thickness = false, no_floor = false, no_paths = false, no_overlay = false;
  bool shadow = false, no_shadow = false;

  void AddTo(CLI::App* cmd) {
    cmd->add_option("--size", size, "Image size WIDTHxHEIGHT in pixels")->capture_default_str();
    std::string fields;
    for (const auto& f : Fields()) fields += std::string(fields.empty() ? "" : ", ") + f.name;
    cmd->add_option("--field", field, "Colour the fabric by a field: " + fields);
    cmd->add_option("--colour-map",
                    colour_map,
                    "Colours of --field: viridis (perceptually uniform) or rainbow")
        ->check(CLI::IsMember({"viridis", "rainbow"}))
        ->capture_default_str();
    cmd->add_option("--units",
                    units,
                    "Units of --field's colour bar and of --plot's forces: si, textile (cm, gf, "
                    "1/cm) or imperial (in, oz, 1/in); default the units the scene is written "
                    "in (SI for a result folder without its scene.json)")
        ->check(CLI::IsMember({"si", "textile", "imperial"}));
    cmd->add_option("--camera", camera, "View: iso, front, top or side")->capture_default_str();
    cmd->add_option("--camera-position", position, "Explicit camera position x,y,z [m]")
        ->expected(3)
        ->delimiter(',');
    cmd->add_option("--focal-point", focal_point, "Explicit focal point x,y,z [m]")
        ->expected(3)
        ->delimiter(',');
    cmd->add_option("--view-up", view_up, "Explicit view-up direction x,y,z")
        ->expected(3)
        ->delimiter(',');
    cmd->add_flag("--edges", edges, "Draw the mesh lines");
    cmd->add_flag("--thickness", thickness, "Draw both faces of the fabric, h apart");
    cmd->add_flag("--no-floor", no_floor, "No floor grid");
    cmd->add_flag("--no-paths", no_paths, "No gripper paths");
    cmd->add_flag("--no-overlay", no_overlay, "No text overlay");
    cmd->add_flag("--shadow",
                  shadow,
                  "The drapemeter's view of a Cusick test (a gravity stage and a support that "
                  "selects a circle): the shadow along gravity, the disc, the drape coefficient "
                  "and nodes; on by default with --camera top for such a scene");
    cmd->add_flag("--no-shadow", no_shadow, "No drapemeter's shadow, even with --camera top")
        ->excludes("--shadow");
  }

#ifdef DRAPE_WITH_RENDER
  // A scene file's units as written; a result folder keeps only SI numbers
  // (scene_resolved), so its own scene.json when there is one, else SI.
  static UnitSystem ScenesOwnUnits(const fs::path& input) {
    std::error_code ec;
    const bool result = fs::is_directory(input, ec) || input.filename() == "result.json";
    const fs::path scene = !result                       ? input
                           : fs::is_directory(input, ec) ? input / "scene.json"
                                                         : input.parent_path() / "scene.json";
    std::ifstream in(scene);
    if (!in) return UnitSystem::kSI;
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    return GuessUnitSystem(text);
  }

  // `input`: the scene or result drawn, whose own units are the default.
  UnitSystem Units(const fs::path& input) const {
    return units.empty() ? ScenesOwnUnits(input) : *UnitSystemNamed(units);
  }

  RenderOptions Options(const fs::path& input) const {
    RenderOptions o;
    o.units = Units(input);
    std::tie(o.width, o.height) = ParseSize(size);
    if (!field.empty()) {
      const auto f = FindField(field);
      if (!f) {
        std::string names;
        for (const auto& g : Fields()) names += std::string(names.empty() ? "" : ", ") + g.name;
        throw std::invalid_argument("--field: unknown field '" + field + "'; expected one of " +
                                    names);
      }
      o.field = f->kind;
    }
    o.colour_map = *ColourMapNamed(colour_map);
    if (camera != "iso" && camera != "front" && camera != "top" && camera != "side")
      throw std::invalid_argument("--camera: unknown view '" + camera +
                                  "'; expected iso, front, top or side");
    o.camera.view = camera;
    auto vec = [](const std::vector<double>& v) -> std::optional<Eigen::Vector3d> {
      if (v.size() != 3) return std::nullopt;
      return Eigen::Vector3d(v[0], v[1], v[2]);
    };
    o.camera.position = vec(position);
    o.camera.focal_point = vec(focal_point);
    o.camera.view_up = vec(view_up);
    o.edges = edges;
    o.thickness = thickness;
    o.floor = !no_floor;
    o.paths = !no_paths;
    o.overlay = !no_overlay;
    return o;
  }

  // The drapemeter's view for a Cusick test: asked for, or seen from above.
  void AddShadow(RenderOptions& o, const Scene& scene, const Mesh& mesh) const {
    if (no_shadow || (!shadow && camera != "top")) return;
    try {
      o.drape_shadow = DrapeTestFor(scene, mesh, std::nullopt, std::nullopt);
    } catch (const DrapeTestError& e) {
      if (shadow) throw std::invalid_argument(std::string("--shadow: ") + e.what());
    }
  }
#endif
};

struct RenderArgs {
  std::string input, output, step = "last";
  std::string plot;  // "reactions": a chart instead of the 3-D view
  ViewArgs view;
};

struct AnimateArgs {
  std::string input, output;
  double fps = 25;
  double duration = 0;
  ViewArgs view;
};

#ifdef DRAPE_WITH_RENDER

std::vector<const ShellState*> Pointers(const RunInput& run) {
  std::vector<const ShellState*> states;
  for (const auto& s : run.states) states.push_back(&s);
  return states;
}

Frame FrameOf(const RunInput& run, size_t i) {
  Frame f;
  f.state = &run.states[i];
  f.step = static_cast<int>(i);
  f.stage_name = run.stage_names[i];
  f.stage = run.stages[i];
  f.lambda = run.lambdas[i];
  if (i + 1 == run.states.size() && run.is_result) {
    f.contact_pressure = run.final_contact_pressure;
    f.friction_state = run.final_friction_state;
  }
  return f;
}

// Every error a rendering command reports: one line, exit 1.
template <typename Body>
int Guarded(const char* command, Body body) {
  const std::string display = DisplayProblem();
  if (!display.empty()) {
    std::cerr << "drape " << command << ": " << display << "\n";
    return 1;
  }
  try {
    return body();
  } catch (const SceneError& e) {
    std::cerr << "drape " << command << ": " << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "drape " << command << ": " << e.what() << "\n";
  }
  return 1;
}

// ---- render ------------------------------------------------------------------

// "curvature [1/cm]: 0 to 0.5235": what the colour bar spans, in its units.
std::string ColourBarSummary(const RunInput& run, const Frame& frame, const RenderOptions& o) {
  const std::array<double, 2> range =
      FieldRange(*o.field, run.model, {frame.state}, frame.contact_pressure);
  const DisplayUnit unit = UnitFor(FieldMeasure(*o.field), o.units);
  return FieldTitle(*o.field, o.units) + ": " + FormatNumber(range[0], unit) + " to " +
         FormatNumber(range[1], unit);
}

// --plot reactions: |F| of each gripper and support against the step, the
// stages marked, from result.json alone (no model is built).
int RunReactionPlot(const RenderArgs& args) {
  ReactionChartOptions options;
  std::tie(options.width, options.height) = ParseSize(args.view.size);
  if (!IsResultInput(args.input))
    throw std::invalid_argument(args.input +
                                ": a scene has no reactions; --plot reactions draws a result "
                                "(drape run SCENE -o DIR, then drape render DIR --plot reactions)");
  const RunRecord record = ReadRunRecord(args.input);
  const fs::path file = record.directory / "result.json";
  bool any = false;
  for (const RecordedStep& step : record.steps) any |= !step.reactions.empty();
  if (!any)
    throw std::invalid_argument(
        file.string() + ": " +
        (record.steps.empty() ? "the run has no converged step (status '" + record.status + "')"
                              : std::string("no step records a reaction")) +
        ", so there are no reactions to plot");
  // Grippers first (what a gripper must carry is the question), then
  // supports, as the scene lists them; the legend names which is which.
  std::vector<std::string> names, kinds;
  for (const auto& g : record.scene.grippers) names.push_back(g.name), kinds.push_back("gripper");
  for (const auto& s : record.scene.supports) names.push_back(s.name), kinds.push_back("support");
  std::vector<ReactionSeries> series;
  for (size_t k = 0; k < names.size(); ++k)
    series.push_back({names[k] + " (" + kinds[k] + ")", {}, {}});
  for (const RecordedStep& step : record.steps)
    for (const NamedVector& r : step.reactions) {
      const auto at = std::find(names.begin(), names.end(), r.name) - names.begin();
      if (at == static_cast<long>(names.size())) {
        names.push_back(r.name);
        series.push_back({r.name, {}, {}});
      }
      series[at].steps.push_back(step.step);
      // Not r.value.norm(): components of 1e200 N would square to inf.
      series[at].forces.push_back(std::hypot(r.value.x(), r.value.y(), r.value.z()));
    }
  // Where each stage starts, among the steps drawn (those only states.bin
  // has, in a run still going, carry no reactions).
  int previous_stage = -1;
  for (const RecordedStep& s : record.steps)
    if (!s.reactions.empty() && (options.stages.empty() || s.stage != previous_stage)) {
      options.stages.push_back(
          {static_cast<double>(s.step),
           s.stage_name.empty() ? "stage " + std::to_string(s.stage) : s.stage_name});
      previous_stage = s.stage;
    }
  options.force_unit = UnitFor(Measure::kForce, args.view.Units(args.input));
  options.title = "Reactions: " + (record.scene.name.empty() ? record.directory.filename().string()
                                                             : record.scene.name);
  if (record.status != "converged" && !record.status.empty())
    options.title += " (" + record.status + ")";
  try {
    WriteReactionChart(series, options, args.output);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(file.string() + ": " + e.what());
  }
  return 0;
}

int RunRender(const RenderArgs& args) {
  return Guarded("render", [&] {
    if (args.plot == "reactions") return RunReactionPlot(args);
    RenderOptions options = args.view.Options(args.input);
    const RunInput run = ReadRunInput(args.input);
    args.view.AddShadow(options, run.scene, run.model.mesh);
    const size_t i = StepIndex(run, args.step);
    FrameRenderer renderer(run.scene, run.model, options, RunBounds(run.scene, Pointers(run)));
    const Frame frame = FrameOf(run, i);
    renderer.Show(frame);
    renderer.WritePng(args.output);
    if (options.field) std::cerr << "  " << ColourBarSummary(run, frame, options) << "\n";
    return 0;
  });
}

// ---- animate -----------------------------------------------------------------

std::atomic<bool> g_interrupted{false};
void OnInterrupt(int) {
  g_interrupted = true;
}

int RunAnimate(const AnimateArgs& args) {
  return Guarded("animate", [&]() -> int {
    AnimationOptions options;
    options.view = args.view.Options(args.input);
    options.fps = args.fps;
    options.duration = args.duration;
    const RunInput run = ReadRunInput(args.input);
    if (!run.is_result)
      throw std::invalid_argument(args.input + ": a scene has one state; animate a result folder");
    args.view.AddShadow(options.view, run.scene, run.model.mesh);
    const AnimationInput input{
        &run.scene, &run.model, Pointers(run), run.stage_names, run.lambdas, run.stages};
    g_interrupted = false;
    std::signal(SIGINT, OnInterrupt);
    std::signal(SIGTERM, OnInterrupt);
    const bool terminal = isatty(STDERR_FILENO);
    const auto start = std::chrono::steady_clock::now();
    int last_done = 0;
    const int frames = WriteAnimation(
        input,
        options,
        args.output,
        [&](int done, int all) {
          last_done = done;
          if (!terminal) return;
          const double elapsed =
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const double eta = elapsed / done * (all - done);
          std::fprintf(
              stderr, "\r\033[K  frame %d/%d, %.1f s, ETA %.1f s", done, all, elapsed, eta);
        },
        &g_interrupted);
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    if (terminal) std::fprintf(stderr, "\r\033[K");
    if (frames < 0) {
      std::cerr << "drape animate: cancelled after " << last_done << " frames; no movie written\n";
      return 130;
    }
    std::cerr << "  " << frames << " frames at " << args.fps << " fps: " << args.output << "\n";
    return 0;
  });
}

#else
int RunRender(const RenderArgs&) {
  return RunInRenderProgram("render");
}
int RunAnimate(const AnimateArgs&) {
  return RunInRenderProgram("animate");
}
#endif

}  // namespace

#ifdef DRAPE_WITH_RENDER
StepObserver MakeRenderObserver(const Scene& scene,
                                const ShellModel& model,
                                const fs::path& directory,
                                int every) {
  const std::string display = DisplayProblem();
  if (!display.empty()) throw std::runtime_error(display);
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw std::runtime_error("cannot create " + directory.string() + ": " + ec.message());
  // The run is not known yet: fit the camera to the part and where its
  // grippers will take it.
  Eigen::AlignedBox3d bounds = RunBounds(scene, {&model.reference});
  for (const auto& path : GripperPathPoints(scene, model)) bounds.extend(path);
  auto renderer = std::make_shared<FrameRenderer>(scene, model, RenderOptions{}, bounds);
  return [renderer, directory, every](const StepState& s) {
    if (s.step % every != 0) return StepDecision::kContinue;
    Frame f;
    f.state = &s.state;
    f.step = s.step;
    f.stage_name = s.stage_name;
    f.lambda = s.lambda;
    renderer->Show(f);
    char name[64];
    std::snprintf(name, sizeof name, "step_%04d.png", s.step);
    renderer->WritePng(directory / name);
    return StepDecision::kContinue;
  };
}
#endif

void AddRenderCommands(CLI::App& app, CommandRunner& runner) {
  auto render = std::make_shared<RenderArgs>();
  CLI::App* r = app.add_subcommand("render", "Render a step of a result (or a scene) to a PNG");
  r->add_option("input", render->input, "Result folder, its result.json, or a scene file")
      ->required();
  r->add_option("-o,--output", render->output, "PNG file to write")->required();
  r->add_option("--step", render->step, "Step number, 0 for the reference state, or 'last'")
      ->capture_default_str();
  render->view.AddTo(r);
  CLI::Option* plot =
      r->add_option("--plot",
                    render->plot,
                    "Draw a chart instead of the fabric: 'reactions', |F| of each gripper and "
                    "support against the step (a result; only --size and --units apply)")
          ->check(CLI::IsMember({"reactions"}));
  // The chart covers every step and has no camera: the 3-D view's options
  // would be ignored, so they are refused.
  for (const char* name : {"--step",
                           "--field",
                           "--colour-map",
                           "--camera",
                           "--camera-position",
                           "--focal-point",
                           "--view-up",
                           "--edges",
                           "--thickness",
                           "--no-floor",
                           "--no-paths",
                           "--no-overlay",
                           "--shadow",
                           "--no-shadow"})
    plot->excludes(r->get_option(name));
  r->callback([render, &runner] { runner = [render] { return RunRender(*render); }; });

  auto animate = std::make_shared<AnimateArgs>();
  CLI::App* a = app.add_subcommand(
      "animate", "Animate a result: MP4 or GIF (ffmpeg), OGV, or a folder of PNG frames");
  a->add_option("input", animate->input, "Result folder or its result.json")->required();
  a->add_option("-o,--output", animate->output, "movie.mp4, movie.gif, movie.ogv, or a folder")
      ->required();
  a->add_option("--fps", animate->fps, "Frames per second")->capture_default_str();
  a->add_option("--duration",
                animate->duration,
                "Length in seconds, the run interpolated in time (default: one frame per step)");
  animate->view.AddTo(a);
  a->callback([animate, &runner] { runner = [animate] { return RunAnimate(*animate); }; });
}

}  // namespace drape::app
