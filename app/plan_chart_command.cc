// `drape plan-chart DIR [-o PNG]`: a plan's search drawn from its table
// (DIR/plan.csv, docs/plan.md) — the objective of each evaluation and the
// best so far; DIR/plan.png by default. `drape plan` draws it after each
// search.
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/render_program.h"
#ifdef DRAPE_WITH_RENDER
#include "ui/render/display.h"
#include "ui/render/plan_chart.h"
#endif

namespace drape::app {
namespace {

namespace fs = std::filesystem;

struct PlanChartArgs {
  std::string dir, output;
};

#ifdef DRAPE_WITH_RENDER
// One CSV line's cells, a quoted cell's doubled quotes undone.
std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"') {
      cells.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

// The plan's scene file's name, from DIR/plan.json; the folder's name
// when that cannot be read.
std::string SceneName(const fs::path& dir) {
  try {
    std::ifstream in(dir / "plan.json");
    return fs::path(nlohmann::json::parse(in).at("scene").get<std::string>()).filename().string();
  } catch (const std::exception&) {
    return fs::absolute(dir).lexically_normal().filename().string();
  }
}

// The evaluations of DIR/plan.csv; throws std::runtime_error naming the
// file when it is missing or not a plan's table.
std::vector<PlanChartPoint> ReadPoints(const fs::path& table) {
  std::ifstream in(table);
  if (!in)
    throw std::runtime_error("cannot open '" + table.string() + "' (is it a plan's folder?)");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = Cells(line);
  auto column = [&](const std::string& name) {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    throw std::runtime_error(table.string() + ": no column '" + name + "' (not a plan's table)");
  };
  const size_t objective = column("objective_m"), feasible = column("feasible");
  std::vector<PlanChartPoint> points;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = Cells(line);
    if (cells.size() != header.size()) continue;
    PlanChartPoint p;
    p.evaluation = static_cast<int>(points.size()) + 1;
    if (!cells[objective].empty()) p.objective = std::stod(cells[objective]);
    p.feasible = cells[feasible] == "yes";
    points.push_back(p);
  }
  return points;
}
#endif

int RunPlanChart(const PlanChartArgs& args) {
#ifndef DRAPE_WITH_RENDER
  (void)args;
  return RunInRenderProgram("plan-chart");
#else
  const fs::path dir = args.dir;
  const fs::path png = args.output.empty() ? dir / "plan.png" : fs::path(args.output);
  try {
    const std::vector<PlanChartPoint> points = ReadPoints(dir / "plan.csv");
    if (const std::string problem = DisplayProblem(); !problem.empty()) {
      std::cerr << "drape plan-chart: " << problem << "\n";
      return 1;
    }
    PlanChartOptions options;
    options.title =
        "Plan of " + SceneName(dir) + ": " + std::to_string(points.size()) + " evaluations";
    WritePlanChart(points, options, png);
  } catch (const std::exception& e) {
    std::cerr << "drape plan-chart: " << e.what() << "\n";
    return 1;
  }
  std::cerr << "  chart: " << png.string() << "\n";
  return 0;
#endif
}

}  // namespace

void AddPlanChartCommand(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<PlanChartArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plan-chart", "Draw a plan's search (each evaluation's objective, the best so far) to a PNG");
  cmd->add_option("plan", args->dir, "The plan's folder (drape plan -o DIR)")->required();
  cmd->add_option("-o,--output", args->output, "PNG file to write (default: DIR/plan.png)");
  cmd->callback([args, &runner] { runner = [args] { return RunPlanChart(*args); }; });
}

}  // namespace drape::app
