// `drape export RESULT -o DIR --format vtu|obj|ply|stl|csv [--step N|all]
// [--solid]`: the deformed surface for ParaView, CAD, 3-D printing or a
// spreadsheet. No display needed.
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/render_program.h"
#ifdef DRAPE_WITH_RENDER
#include "app/run_input.h"
#include "core/model/scene_error.h"
#include "ui/render/surface_export.h"
#endif

namespace drape::app {
namespace {

struct ExportArgs {
  std::string input, output, format = "vtu", step = "all";
  bool solid = false;
};

#ifndef DRAPE_WITH_RENDER
// VTK writes the files: the command runs in drape-vtk.
int RunExport(const ExportArgs&) {
  return RunInRenderProgram("export");
}
#else
int RunExport(const ExportArgs& args) {
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
  cmd->add_option("--format", args->format, "vtu (with run.pvd), obj, ply, stl or csv")
      ->check(CLI::IsMember({"vtu", "obj", "ply", "stl", "csv"}))
      ->capture_default_str();
  cmd->add_option("--step", args->step, "Step number, 0 for the reference, 'last' or 'all'")
      ->capture_default_str();
  cmd->add_flag("--solid",
                args->solid,
                "OBJ/PLY/STL: a closed solid of the fabric's thickness (for 3-D printing)");
  cmd->callback([args, &runner] { runner = [args] { return RunExport(*args); }; });
}

}  // namespace drape::app
