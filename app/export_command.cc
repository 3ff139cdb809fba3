// `drape export RESULT -o DIR --format vtu|obj|ply|stl|csv|dxf [--step
// N|all] [--solid]`: the deformed surface for ParaView, CAD, 3-D printing or
// a spreadsheet; with dxf, the part's outline projected on the table (xy),
// where a lay-down planner wants to know the ply's edge landed. No display
// needed.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "app/commands.h"
#include "app/render_program.h"
#include "app/run_input.h"
#include "core/io/dxf_pattern_writer.h"
#include "core/io/result_reader.h"
#include "core/model/mesh_boundary.h"
#include "core/model/scene_error.h"
#include "core/model/units.h"
#include "core/plan/gripper_trajectory.h"
#ifdef DRAPE_WITH_RENDER
#include "ui/render/surface_export.h"
#endif

namespace drape::app {
namespace {

struct ExportArgs {
  std::string input, output, format = "vtu", step = "all";
  bool solid = false;
  std::string speed = "0.1 m/s";
};

// DIR/trajectory.csv: each gripper's pose, time and force per step, for a
// robot cell (docs/plan.md "Trajectory").
int RunTrajectoryExport(const ExportArgs& args) {
  try {
    double speed = 0;
    try {
      speed = ParseQuantityAs(args.speed, Dimension{1, 0, -1, 0});  // m/s
    } catch (const UnitError& e) {
      throw std::invalid_argument("--speed: " + std::string(e.what()));
    }
    if (!(speed > 0))
      throw std::invalid_argument("--speed: must be greater than zero, found " + args.speed);
    const RunRecord record = ReadRunRecord(args.input);
    if (record.scene.grippers.empty())
      throw std::invalid_argument(args.input + ": the scene has no gripper to export");
    std::filesystem::create_directories(args.output);
    const std::filesystem::path file = std::filesystem::path(args.output) / "trajectory.csv";
    const auto points = GripperTrajectory(record, speed);
    WriteTrajectoryCsv(record, points, file);
    std::cerr << "  " << points.size() << " steps of " << record.scene.grippers.size() << " gripper"
              << (record.scene.grippers.size() == 1 ? "" : "s") << " in " << file.string() << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "drape export: " << e.what() << "\n";
  }
  return 1;
}

// The outline of each step asked for, one DXF-AAMA file each
// (outline-step-N.dxf): a pattern piece keeps its name and its notches
// follow the fabric.
int RunOutlineExport(const ExportArgs& args) {
  try {
    const RunInput run = ReadRunInput(args.input);
    std::vector<size_t> steps;
    if (args.step == "all") {
      for (size_t i = 0; i < run.states.size(); ++i) steps.push_back(i);
    } else {
      steps.push_back(StepIndex(run, args.step));
    }
    // One piece per part of the fabric: a pattern piece by its piece's
    // name, another by its part's (or FABRIC).
    const auto parts = FabricParts(run.scene);
    const auto spans = PartsOf(run.model.mesh);
    std::filesystem::create_directories(args.output);
    for (size_t i : steps) {
      std::vector<PatternPiece> pieces;
      for (std::size_t p = 0; p < spans.size() && p < parts.size(); ++p) {
        std::string name = parts[p]->name.empty() ? "FABRIC" : parts[p]->name;
        std::vector<PiecePoint> notches;
        if (const auto* pattern = std::get_if<PatternOutline>(&parts[p]->outline)) {
          name = pattern->piece;
          notches = pattern->shape.notches;
        }
        const auto& span = spans[p];
        pieces.push_back(
            ProjectedOutline(PartMesh(run.model.mesh, span),
                             run.states[i].positions.middleRows(span.first_node, span.nodes),
                             name,
                             notches));
      }
      // Two plies cut from one piece keep their parts' names apart.
      for (std::size_t p = 0; p < pieces.size(); ++p)
        for (std::size_t q = 0; q < p; ++q)
          if (pieces[q].name == pieces[p].name) pieces[p].name += "-" + parts[p]->name;
      const std::filesystem::path file =
          std::filesystem::path(args.output) / ("outline-step-" + std::to_string(i) + ".dxf");
      WriteDxfPattern(file, pieces);
    }
    std::cerr << "  " << steps.size() << " files in " << args.output << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "drape export: " << e.what() << "\n";
  }
  return 1;
}

#ifndef DRAPE_WITH_RENDER
// VTK writes the surfaces: that command runs in drape-vtk.
int RunExport(const ExportArgs& args) {
  if (args.format == "dxf") return RunOutlineExport(args);
  if (args.format == "trajectory") return RunTrajectoryExport(args);
  return RunInRenderProgram("export");
}
#else
int RunExport(const ExportArgs& args) {
  if (args.format == "dxf") return RunOutlineExport(args);
  if (args.format == "trajectory") return RunTrajectoryExport(args);
  try {
    const RunInput run = ReadRunInput(args.input);
    const SurfaceFormat format = args.format == "vtu"   ? SurfaceFormat::kVtu
                                 : args.format == "obj" ? SurfaceFormat::kObj
                                 : args.format == "ply" ? SurfaceFormat::kPly
                                 : args.format == "stl" ? SurfaceFormat::kStl
                                                        : SurfaceFormat::kCsv;
    std::vector<ExportedStep> steps;
    auto add = [&](size_t i) {
      steps.push_back({&run.states[i], static_cast<int>(i), run.stages[i], run.lambdas[i]});
    };
    if (args.step == "all") {
      for (size_t i = 0; i < run.states.size(); ++i) add(i);
    } else {
      add(StepIndex(run, args.step));
    }
    const auto files = ExportSurfaces(run.model, steps, format, args.output, args.solid);
    std::cerr << "  " << files.size() << " files in " << args.output << "\n";
    return 0;
  } catch (const SceneError& e) {
    std::cerr << "drape export: " << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "drape export: " << e.what() << "\n";
  }
  return 1;
}
#endif

}  // namespace

void AddExportCommand(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<ExportArgs>();
  CLI::App* cmd = app.add_subcommand("export", "Write the deformed surface of a result to files");
  cmd->add_option("input", args->input, "Result folder, its result.json, or a scene file")
      ->required();
  cmd->add_option("-o,--output", args->output, "Folder to write into")->required();
  cmd->add_option("--format",
                  args->format,
                  "vtu (with run.pvd), obj, ply, stl, csv, dxf (the outline on the table, "
                  "DXF-AAMA in mm), or trajectory (each gripper's pose, time and force per "
                  "step: DIR/trajectory.csv)")
      ->check(CLI::IsMember({"vtu", "obj", "ply", "stl", "csv", "dxf", "trajectory"}))
      ->capture_default_str();
  cmd->add_option("--step", args->step, "Step number, 0 for the reference, 'last' or 'all'")
      ->capture_default_str();
  cmd->add_option("--speed",
                  args->speed,
                  "trajectory: the speed of the fastest gripper along its path, e.g. \"5 cm/s\"")
      ->capture_default_str();
  cmd->add_flag("--solid",
                args->solid,
                "OBJ/PLY/STL: a closed solid of the fabric's thickness (for 3-D printing)");
  cmd->callback([args, &runner] { runner = [args] { return RunExport(*args); }; });
}

}  // namespace drape::app
