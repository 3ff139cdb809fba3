// `drape measure RESULT --drape-coefficient [--support-radius R] [--center x,y]
// [--step N|last] [--json] [--profile FILE]`: the Cusick drape test on a
// state of a result, as a drapemeter reports it (docs/cusick.md).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "app/commands.h"
#include "app/run_input.h"
#include "core/measure/drape_test_setup.h"
#include "core/model/units.h"

namespace drape::app {
namespace {

struct MeasureArgs {
  std::string input, step = "last", support_radius, center, profile;
  bool drape_coefficient = false, json = false;
};

double ParseLength(const std::string& option, const std::string& text) {
  const Quantity q = ParseQuantity(text);
  if (!(q.dimension == dim::kLength) && !(q.dimension == dim::kNone))
    throw std::invalid_argument(option + ": '" + text + "' is not a length (e.g. '9 cm')");
  if (!std::isfinite(q.value_si))
    throw std::invalid_argument(option + ": '" + text + "' is not finite");
  return q.value_si;
}

Vec2 ParsePoint(const std::string& option, const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    throw std::invalid_argument(option + ": '" + text + "' is not x,y (e.g. '0,0' or '1 cm,0')");
  return {ParseLength(option, text.substr(0, comma)), ParseLength(option, text.substr(comma + 1))};
}

double Degrees(double radians) {
  return radians * 180 / M_PI;
}

void WriteProfile(const std::string& file, const RadialProfile& profile) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("--profile: cannot write " + file);
  out << "angle_deg,radius_m\n" << std::setprecision(10);
  for (size_t k = 0; k < profile.angle.size(); ++k)
    out << Degrees(profile.angle[k]) << "," << profile.radius[k] << "\n";
}

nlohmann::json AsJson(const DrapeMeasurement& m, int step, double lambda) {
  nlohmann::json angles = nlohmann::json::array(), amplitudes = nlohmann::json::array();
  for (const DrapeNode& n : m.nodes) {
    angles.push_back(Degrees(n.angle));
    amplitudes.push_back(n.amplitude);
  }
  return {{"drape_coefficient", m.drape_coefficient},
          {"nodes", m.nodes.size()},
          {"shadow_area_m2", m.shadow_area},
          {"disc_area_m2", m.disc_area},
          {"specimen_area_m2", m.specimen_area},
          {"node_angles_deg", angles},
          {"node_amplitudes_m", amplitudes},
          {"step", step},
          {"lambda", lambda}};
}

void Report(const DrapeMeasurement& m, int step, double lambda) {
  std::cout << std::fixed << std::setprecision(3) << "drape coefficient " << m.drape_coefficient
            << " (step " << step << ", λ = " << std::setprecision(4) << lambda << ")\n"
            << std::setprecision(1) << "  shadow " << m.shadow_area * 1e4 << " cm², disc "
            << m.disc_area * 1e4 << " cm², specimen " << m.specimen_area * 1e4 << " cm²\n"
            << "  " << m.nodes.size() << (m.nodes.size() == 1 ? " node" : " nodes");
  for (size_t k = 0; k < m.nodes.size(); ++k)
    std::cout << (k == 0 ? ": " : ", ") << std::setprecision(1) << Degrees(m.nodes[k].angle)
              << "° (" << std::setprecision(2) << m.nodes[k].amplitude * 100 << " cm)";
  std::cout << "\n";
}

int RunMeasure(const MeasureArgs& args) {
  try {
    if (!args.drape_coefficient)
      throw std::invalid_argument("say what to measure: --drape-coefficient");
    const RunInput run = ReadRunInput(args.input);
    if (!run.is_result)
      throw std::invalid_argument(args.input +
                                  " is a scene: measure the result of `drape run` instead");
    const size_t i = StepIndex(run, args.step);
    std::optional<double> radius;
    if (!args.support_radius.empty()) radius = ParseLength("--support-radius", args.support_radius);
    std::optional<Vec2> centre;
    if (!args.center.empty()) centre = ParsePoint("--center", args.center);
    const DrapeTestOptions options = DrapeTestFor(run.scene, run.model.mesh, radius, centre);
    const DrapeMeasurement m = MeasureDrape(run.states[i].positions, run.model.mesh.quads, options);
    if (!args.profile.empty()) WriteProfile(args.profile, m.profile);
    if (args.json)
      std::cout << AsJson(m, static_cast<int>(i), run.lambdas[i]).dump(2) << "\n";
    else
      Report(m, static_cast<int>(i), run.lambdas[i]);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "drape measure: " << e.what() << "\n";
  }
  return 1;
}

}  // namespace

void AddMeasureCommand(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<MeasureArgs>();
  CLI::App* cmd = app.add_subcommand(
      "measure", "Measure a result as a lab would: the Cusick drape coefficient and its nodes");
  cmd->add_option("input", args->input, "Result folder or its result.json")->required();
  cmd->add_flag("--drape-coefficient",
                args->drape_coefficient,
                "The drape coefficient (BS 5058, ISO 9073-9), its nodes and the shadow's area");
  cmd->add_option("--support-radius",
                  args->support_radius,
                  "The support disc's radius ('9 cm'); default: the support that selects a circle");
  cmd->add_option("--center",
                  args->center,
                  "The disc's centre x,y on the flat part ('0,0'); default: that support's centre");
  cmd->add_option("--step", args->step, "Step number, 0 for the reference, or 'last'")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print the numbers as JSON");
  cmd->add_option("--profile", args->profile, "Write the shadow's outline (angle, radius) as CSV");
  cmd->callback([args, &runner] { runner = [args] { return RunMeasure(*args); }; });
}

}  // namespace drape::app
