#include "core/plan/plan_table.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace drape {
namespace {

std::string Cell(std::optional<double> value) {
  if (!value || !std::isfinite(*value)) return "";
  char text[40];
  std::snprintf(text, sizeof text, "%.9g", *value);
  return text;
}

std::string Quoted(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// The constraints a plan checks, in the order EvaluationOutcome lists them.
std::vector<std::pair<std::string, std::string>> ConstraintColumns(const PlanConstraints& k) {
  std::vector<std::pair<std::string, std::string>> columns;
  if (k.stable) columns.emplace_back("stable", "pivots");
  if (k.layers) columns.emplace_back("layers", "m");
  if (k.grippers_outside) columns.emplace_back("grippers_outside", "m");
  if (k.max_gripper_force) columns.emplace_back("max_gripper_force", "N");
  if (k.no_slip) columns.emplace_back("no_slip", "nodes");
  return columns;
}

}  // namespace

void WritePlanCsv(const Plan& plan,
                  const std::vector<PlanEvaluation>& evaluations,
                  const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
  out << "start,evaluation";
  for (const PlanParameter& p : plan.parameters)
    out << "," << Quoted(p.key + (p.unit.empty() ? "" : "_" + p.unit));
  out << ",objective_m";
  for (const ProbeTarget& t : plan.objective.probes) out << "," << Quoted(t.probe + "_distance_m");
  if (plan.objective.flat) out << ",flat_gap_m";
  out << ",path_length_m";
  const auto constraints = ConstraintColumns(plan.constraints);
  for (const auto& [name, unit] : constraints) out << "," << name << "_margin_" << unit;
  out << ",status,progress,feasible,search_value_m,wall_s\n";
  for (const PlanEvaluation& e : evaluations) {
    const EvaluationOutcome& o = e.outcome;
    out << e.start + 1 << "," << e.index;
    for (size_t i = 0; i < plan.parameters.size(); ++i) {
      const PlanParameter& p = plan.parameters[i];
      const double factor = p.unit.empty() ? 1.0 : ParseUnit(p.unit).si_factor;
      out << "," << Cell(e.x[i] / factor);
    }
    out << "," << Cell(o.objective);
    for (size_t i = 0; i < plan.objective.probes.size(); ++i)
      out << ","
          << Cell(i < o.probe_distances.size() ? std::optional(o.probe_distances[i])
                                               : std::nullopt);
    if (plan.objective.flat) out << "," << Cell(o.flat_gap);
    out << "," << Cell(o.path_length);
    for (const auto& [name, unit] : constraints) {
      std::optional<double> margin;
      for (const ConstraintMargin& c : o.constraints)
        if (c.name == name) margin = c.margin;
      out << "," << Cell(margin);
    }
    out << "," << o.status << "," << Cell(o.progress) << "," << (o.Feasible() ? "yes" : "no") << ","
        << Cell(e.value) << "," << Cell(o.wall_s) << "\n";
  }
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
}

}  // namespace drape
