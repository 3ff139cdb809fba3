// `drape drag SCENE --gripper NAME --by dx,dy,dz [--frames N] -o DIR`: the
// workbench's live drag without the workbench, for tests and benchmarks.
// Solves the scene's stages, drags the gripper straight by the translation
// in N frames (core/solve/gripper_drag.h), writing each frame to
// DIR/frames.csv as it goes, then solves the dragged scene (DIR/scene.json:
// the scene with the drag as its last stage) from the start into DIR, as
// `drape run` would.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "app/commands.h"
#include "app/run_session.h"
#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"
#include "core/model/scene_error.h"
#include "core/model/unit_system.h"
#include "core/model/units.h"
#include "core/solve/gripper_drag.h"
#include "core/solve/shell_solver.h"

namespace drape::app {
namespace {

struct DragArgs {
  std::string scene;
  std::string output;
  std::string gripper;
  std::string by;
  int frames = 40;
  int threads = 0;
  bool quiet = false;
  std::string units;  // of the release's report; empty: the scene's own
};

inline constexpr char kFramesFileName[] = "frames.csv";

// "dx,dy,dz": numbers in metres or quantities with a length unit ("0,0,5 cm"
// gives the last its unit only). Throws std::invalid_argument.
Eigen::Vector3d ParseTranslation(const std::string& text) {
  Eigen::Vector3d by;
  std::stringstream in(text);
  std::string part;
  int k = 0;
  for (; std::getline(in, part, ','); ++k) {
    if (k == 3) break;
    const Quantity q = ParseQuantity(part);
    if (!(q.dimension == dim::kLength) && !(q.dimension == dim::kNone))
      throw std::invalid_argument("--by: '" + part + "' is not a length");
    by[k] = q.value_si;
  }
  if (k != 3 || std::getline(in, part, ','))
    throw std::invalid_argument("--by: '" + text +
                                "' is not three lengths dx,dy,dz (metres, or with a unit: "
                                "'0,0,5 cm')");
  if (!by.allFinite()) throw std::invalid_argument("--by: '" + text + "' is not finite");
  return by;
}

// The frames, one row each, flushed so that an interrupted drag keeps them.
class FramesCsv {
 public:
  explicit FramesCsv(const std::filesystem::path& file) : out_(file) {
    if (!out_) throw std::runtime_error("cannot write " + file.string());
    out_ << "frame,seconds,residual_ratio,corrections,factorizations,offset_x,offset_y,offset_z,"
            "event\n";
  }
  void Add(const DragFrame& f) {
    char row[256];
    std::snprintf(row,
                  sizeof row,
                  "%d,%.6g,%.6g,%d,%d,%.9g,%.9g,%.9g,%s\n",
                  f.frame,
                  f.seconds,
                  f.residual_ratio,
                  f.corrections,
                  f.factorizations,
                  f.offset.x(),
                  f.offset.y(),
                  f.offset.z(),
                  f.snapped ? "snap" : "");
    out_ << row << std::flush;
  }

 private:
  std::ofstream out_;
};

int RunDrag(const DragArgs& args) {
  CancellationToken cancel;
  InterruptGuard guard(cancel);
  const std::string command = "drape drag";
  Scene scene;
  Eigen::Vector3d by;
  SolverOptions options;
  std::unique_ptr<ShellSolver> solver;
  try {
    by = ParseTranslation(args.by);
    scene = ReadScene(args.scene);
    options = SolverOptions::FromScene(scene.solver);
    options.threads = args.threads;
    solver = std::make_unique<ShellSolver>(scene, options);
  } catch (const SceneError& e) {
    std::cerr << command << ": " << args.scene << ": " << e.what() << "\n";
    return 1;
  } catch (const std::invalid_argument& e) {
    std::cerr << command << ": " << e.what() << "\n";
    return 1;
  }

  if (!args.quiet) std::cerr << "  solving the scene's stages\n";
  const SolveSummary before = solver->Solve({}, &cancel);
  if (!before.IsComplete()) {
    std::cerr << command << ": " << args.scene << ": the scene's stages did not complete ("
              << before.message << "): there is no end state to drag from\n";
    return ExitCode(before.termination);
  }
  std::unique_ptr<GripperDrag> drag;
  try {
    DragSettings settings;
    drag = std::make_unique<GripperDrag>(solver->BasisForDrag(args.gripper), settings);
  } catch (const std::invalid_argument& e) {
    std::cerr << command << ": --gripper: " << e.what() << "\n";
    return 1;
  }

  const std::filesystem::path dir = args.output;
  std::unique_ptr<FramesCsv> frames;
  try {
    std::filesystem::create_directories(dir);
    frames = std::make_unique<FramesCsv>(dir / kFramesFileName);
  } catch (const std::exception& e) {
    std::cerr << command << ": " << e.what() << "\n";
    return 1;
  }
  double worst = 0, total_s = 0;
  int snaps = 0;
  for (int f = 1; f <= args.frames; ++f) {
    if (cancel.IsCancelled()) {
      std::cerr << command << ": cancelled after frame " << f - 1 << "; "
                << (dir / kFramesFileName).string() << " keeps them\n";
      return 130;
    }
    const DragFrame frame = drag->MoveTo(by * (static_cast<double>(f) / args.frames));
    frames->Add(frame);
    worst = std::max(worst, frame.residual_ratio);
    total_s += frame.seconds;
    snaps += frame.snapped;
    if (!args.quiet && !frame.not_followed.empty())
      std::cerr << "  frame " << f << ": " << frame.not_followed << "\n";
  }
  if (!args.quiet) {
    char line[200];
    std::snprintf(line,
                  sizeof line,
                  "  dragged '%s' in %d frames: %.3g s each on average (%.1f Hz), residual "
                  "ratio at most %.3g, %d snap%s\n",
                  args.gripper.c_str(),
                  args.frames,
                  total_s / args.frames,
                  args.frames / std::max(total_s, 1e-9),
                  worst,
                  snaps,
                  snaps == 1 ? "" : "s");
    std::cerr << line << "  released: solving the dragged scene from the start\n";
  }

  const Scene dragged = DraggedScene(scene, args.gripper, by);
  try {
    WriteScene(WithAbsoluteReferences(dragged, std::filesystem::path(args.scene).parent_path()),
               dir / "scene.json");
  } catch (const std::exception& e) {
    std::cerr << command << ": " << e.what() << "\n";
    return 1;
  }
  ShellSolver release(dragged, options);
  SolveReport report;
  report.command = command;
  report.quiet = args.quiet;
  report.units = args.units.empty() ? ScenesOwnUnits(args.scene) : *UnitSystemNamed(args.units);
  return SolveIntoFolder(dragged, release, args.output, report, cancel);
}

}  // namespace

void AddDragCommand(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<DragArgs>();
  CLI::App* cmd = app.add_subcommand(
      "drag",
      "Solve a scene, drag one of its grippers straight by a translation in frames (the "
      "workbench's live drag), then solve the dragged scene into a result folder");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
  cmd->add_option("--gripper", args->gripper, "The gripper to drag (held at the scene's end)")
      ->required();
  cmd->add_option("--by", args->by, "Translation dx,dy,dz in metres, or with a unit (\"0,0,5 cm\")")
      ->required();
  cmd->add_option("--frames", args->frames, "Frames the drag takes (default 40)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("-o,--output",
                  args->output,
                  "Folder for frames.csv, scene.json and the released run's result")
      ->required();
  cmd->add_option("--threads", args->threads, "Threads for assembly (0: all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("-q,--quiet", args->quiet, "No report");
  cmd->add_option("--units",
                  args->units,
                  "Units of the release's report (as drape run --units); default the units the "
                  "scene is written in")
      ->check(CLI::IsMember({"si", "textile", "imperial"}));
  cmd->callback([args, &runner] { runner = [args] { return RunDrag(*args); }; });
}

}  // namespace drape::app
