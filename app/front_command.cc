// `drape front DIR [-o PNG]`: the speed–accuracy front of a study (DIR is the
// study's folder, docs/format.md §7), drawn from its runs' results;
// DIR/front.png by default. `drape study` draws it after each study.
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/render_program.h"
#ifdef DRAPE_WITH_RENDER
#include "core/io/study_file.h"
#include "core/io/study_table.h"
#include "core/model/scene_error.h"
#include "ui/render/display.h"
#include "ui/render/front_chart.h"
#endif

namespace drape::app {
namespace {

namespace fs = std::filesystem;

struct FrontArgs {
  std::string study_dir;
  std::string output;
};

#ifdef DRAPE_WITH_RENDER
// "run_003 [20,2] 1e-05": the run and the values it varies.
std::string Label(const StudyRun& run) {
  std::string label = run.name;
  for (const StudySetting& s : run.settings) label += " " + s.value;
  return label;
}
#endif

int RunFront(const FrontArgs& args) {
#ifndef DRAPE_WITH_RENDER
  (void)args;
  return RunInRenderProgram("front");
#else
  const fs::path dir = args.study_dir;
  const fs::path png = args.output.empty() ? dir / "front.png" : fs::path(args.output);
  Study study;
  try {
    study = ReadStudy(dir / "study.json");
  } catch (const SceneError& e) {
    std::cerr << "drape front: " << (dir / "study.json").string() << ": " << e.what() << "\n";
    return 1;
  }
  if (!study.reference) {
    std::cerr << "drape front: " << (dir / "study.json").string()
              << ": the study has no reference run, so its errors are not measured\n";
    return 1;
  }
  if (const std::string problem = DisplayProblem(); !problem.empty()) {
    std::cerr << "drape front: " << problem << "\n";
    return 1;
  }
  const std::vector<StudyRow> rows = CollectStudy(study, dir);
  const std::vector<bool> front = ParetoFront(rows);
  std::vector<FrontPoint> points;
  for (size_t i = 0; i < rows.size(); ++i)
    if (rows[i].solve_s && rows[i].max_node_error)
      points.push_back({Label(rows[i].run), *rows[i].solve_s, *rows[i].max_node_error, front[i]});
  FrontChartOptions options;
  options.title = "Speed against accuracy: " + study.scene_file.filename().string() + " (" +
                  std::to_string(points.size()) + " runs)";
  try {
    WriteFrontChart(points, options, png);
  } catch (const std::exception& e) {
    std::cerr << "drape front: " << e.what() << "\n";
    return 2;
  }
  std::cerr << "  front: " << png.string() << "\n";
  return 0;
#endif
}

}  // namespace

void AddFrontCommand(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<FrontArgs>();
  CLI::App* cmd = app.add_subcommand(
      "front", "Draw a study's speed-accuracy front (time against error) to a PNG");
  cmd->add_option("study", args->study_dir, "The study's folder (drape study -o DIR)")->required();
  cmd->add_option("-o,--output", args->output, "PNG file to write (default: DIR/front.png)");
  cmd->callback([args, &runner] { runner = [args] { return RunFront(*args); }; });
}

}  // namespace drape::app
