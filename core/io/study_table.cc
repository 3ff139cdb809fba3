#include "core/io/study_table.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "core/io/scene_reader.h"
#include "core/io/state_file.h"
#include "core/measure/drape_test_setup.h"
#include "core/model/mesh_transfer.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::optional<json> ReadResult(const fs::path& folder) {
  std::ifstream in(folder / "result.json");
  if (!in) return std::nullopt;
  try {
    return json::parse(in);
  } catch (const json::exception&) {
    return std::nullopt;  // a result being written, or damaged: as if missing
  }
}

template <typename T>
std::optional<T> Number(const json& j, const char* object, const char* key) {
  if (!j.contains(object) || !j[object].contains(key) || !j[object][key].is_number())
    return std::nullopt;
  return j[object][key].get<T>();
}

// The final deformed mesh of a run: its reference mesh and last state.
struct FinalShape {
  Mesh mesh;
  Eigen::MatrixX3d positions;
};

std::optional<FinalShape> ReadFinalShape(const fs::path& folder) {
  try {
    StateFile states = ReadStateFile(folder / "states.bin");
    if (states.steps.empty()) return std::nullopt;
    return FinalShape{std::move(states.mesh), states.steps.back().positions};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The Cusick test's numbers of the last step, when the run is one.
void MeasureDrapeOf(StudyRow& row, const json& result, const FinalShape& shape) {
  try {
    const Scene scene = SceneFromJson(result.at("scene_resolved"));
    const DrapeTestOptions test = DrapeTestFor(scene, shape.mesh, std::nullopt, std::nullopt);
    const DrapeMeasurement m = MeasureDrape(shape.positions, shape.mesh.quads, test);
    row.drape_coefficient = m.drape_coefficient;
    row.drape_nodes = static_cast<int>(m.nodes.size());
  } catch (const std::exception&) {
    // Not a drape test (or a result that does not read): no such columns.
  }
}

StudyRow ReadRow(const fs::path& study_dir, const StudyRun& run) {
  StudyRow row;
  row.run = run;
  const auto result = ReadResult(RunResultFolder(study_dir, run.name));
  if (!result) return row;
  const json& r = *result;
  row.status = r.value("status", "missing");
  row.solve_s = Number<double>(r, "timing", "total_s");
  row.peak_memory_bytes = Number<double>(r, "timing", "peak_memory_bytes");
  row.steps = Number<int>(r, "counts", "steps");
  row.iterations = Number<int>(r, "counts", "iterations");
  row.factorizations = Number<int>(r, "counts", "factorizations");
  if (r.contains("error_estimate") && r["error_estimate"].value("in_asymptotic_range", false)) {
    double largest = 0;
    for (const auto& [name, p] : r["error_estimate"]["probes"].items())
      largest = std::max(largest, p.value("error", 0.0));
    row.estimated_error = largest;
  }
  if (r.contains("final") && r["final"].contains("probes"))
    for (const auto& [name, p] : r["final"]["probes"].items())
      if (p.is_array() && p.size() == 3)
        row.probes.push_back(
            {name, {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()}, std::nullopt});
  if (row.status == "converged" && r.contains("scene_resolved"))
    if (const auto shape = ReadFinalShape(RunResultFolder(study_dir, run.name)))
      MeasureDrapeOf(row, r, *shape);
  return row;
}

void MeasureAgainst(StudyRow& row,
                    const StudyRow& reference,
                    const std::optional<FinalShape>& reference_shape,
                    const fs::path& study_dir) {
  if (row.status != "converged") return;
  for (StudyProbe& p : row.probes)
    for (const StudyProbe& q : reference.probes)
      if (q.name == p.name)
        p.error = std::hypot(p.position[0] - q.position[0],
                             p.position[1] - q.position[1],
                             p.position[2] - q.position[2]);
  if (!reference_shape) return;
  const auto shape = ReadFinalShape(RunResultFolder(study_dir, row.run.name));
  if (!shape) return;
  row.max_node_error =
      DeformedDistance(
          shape->mesh, shape->positions, reference_shape->mesh, reference_shape->positions)
          .max;
}

std::string Cell(const std::optional<double>& v) {
  if (!v || !std::isfinite(*v)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", *v);
  return text;
}

std::string Cell(const std::optional<int>& v) {
  return v ? std::to_string(*v) : "";
}

// A JSON value in one CSV cell: quoted when it holds a comma or a quote.
std::string Quoted(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

}  // namespace

fs::path RunFolder(const fs::path& study_dir, const std::string& name) {
  return study_dir / "runs" / name;
}
fs::path RunSceneFile(const fs::path& study_dir, const std::string& name) {
  return RunFolder(study_dir, name) / "scene.json";
}
fs::path RunResultFolder(const fs::path& study_dir, const std::string& name) {
  return RunFolder(study_dir, name) / "result";
}

bool RunEnded(const fs::path& study_dir, const std::string& name) {
  const auto result = ReadResult(RunResultFolder(study_dir, name));
  if (!result) return false;
  const std::string status = result->value("status", "");
  return status == "converged" || status == "failed";
}

std::vector<StudyRow> CollectStudy(const Study& study, const fs::path& study_dir) {
  std::vector<StudyRow> rows;
  for (const StudyRun& run : study.runs) rows.push_back(ReadRow(study_dir, run));
  if (!study.reference) return rows;
  StudyRow reference = ReadRow(study_dir, *study.reference);
  if (reference.status == "converged") {
    const auto shape = ReadFinalShape(RunResultFolder(study_dir, reference.run.name));
    for (StudyRow& row : rows) MeasureAgainst(row, reference, shape, study_dir);
  }
  rows.push_back(std::move(reference));
  return rows;
}

std::vector<bool> ParetoFront(const std::vector<StudyRow>& rows) {
  auto measured = [](const StudyRow& r) {
    return r.status == "converged" && r.solve_s && r.max_node_error;
  };
  std::vector<bool> front(rows.size(), false);
  for (size_t i = 0; i < rows.size(); ++i) {
    if (!measured(rows[i])) continue;
    front[i] = true;
    for (size_t j = 0; j < rows.size() && front[i]; ++j) {
      if (j == i || !measured(rows[j])) continue;
      const double ti = *rows[i].solve_s, ei = *rows[i].max_node_error;
      const double tj = *rows[j].solve_s, ej = *rows[j].max_node_error;
      // Errors within 1 % are the same answer: a slower run that is 0.1 %
      // nearer the reference buys nothing.
      constexpr double kSame = 1.01;
      if ((tj < ti && ej <= kSame * ei) || (tj <= ti && kSame * ej < ei)) front[i] = false;
    }
  }
  return front;
}

std::optional<DrapeSpread> SpreadOfDrape(const std::vector<StudyRow>& rows) {
  std::vector<double> dc, nodes;
  for (const StudyRow& row : rows)
    if (row.drape_coefficient && row.drape_nodes) {
      dc.push_back(*row.drape_coefficient);
      nodes.push_back(*row.drape_nodes);
    }
  if (dc.empty()) return std::nullopt;
  auto mean = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return s / v.size();
  };
  auto sd = [](const std::vector<double>& v, double m) {
    if (v.size() < 2) return 0.0;
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / (v.size() - 1));
  };
  DrapeSpread out;
  out.specimens = static_cast<int>(dc.size());
  out.mean_coefficient = mean(dc);
  out.sd_coefficient = sd(dc, out.mean_coefficient);
  out.mean_nodes = mean(nodes);
  out.sd_nodes = sd(nodes, out.mean_nodes);
  out.fewest_nodes = static_cast<int>(*std::min_element(nodes.begin(), nodes.end()));
  out.most_nodes = static_cast<int>(*std::max_element(nodes.begin(), nodes.end()));
  return out;
}

void WriteStudyCsv(const Study& study, const std::vector<StudyRow>& rows, const fs::path& file) {
  // Probe columns: every probe any run reports, in order of first appearance.
  std::vector<std::string> probes;
  for (const StudyRow& row : rows)
    for (const StudyProbe& p : row.probes)
      if (std::find(probes.begin(), probes.end(), p.name) == probes.end()) probes.push_back(p.name);

  const bool drape = std::any_of(
      rows.begin(), rows.end(), [](const StudyRow& r) { return r.drape_coefficient.has_value(); });

  const fs::path temporary = file.string() + ".part";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << "run";
    for (const std::string& key : study.keys) out << "," << Quoted(key);
    out << ",status,wall_s,steps,iterations,factorizations,peak_memory_bytes";
    for (const std::string& p : probes)
      out << "," << p << "_x_m," << p << "_y_m," << p << "_z_m," << p << "_error_m";
    out << ",max_node_error_m,estimated_error_m";
    if (drape) out << ",drape_coefficient,drape_nodes";
    out << "\n";
    for (const StudyRow& row : rows) {
      out << row.run.name;
      for (const std::string& key : study.keys) {
        std::string value;
        for (const StudySetting& s : row.run.settings)
          if (s.key == key) value = s.value;
        out << "," << Quoted(value);
      }
      out << "," << row.status << "," << Cell(row.solve_s) << "," << Cell(row.steps) << ","
          << Cell(row.iterations) << "," << Cell(row.factorizations) << ","
          << Cell(row.peak_memory_bytes);
      for (const std::string& name : probes) {
        const StudyProbe* found = nullptr;
        for (const StudyProbe& p : row.probes)
          if (p.name == name) found = &p;
        for (int c = 0; c < 3; ++c)
          out << "," << (found ? Cell(std::optional<double>(found->position[c])) : "");
        out << "," << (found ? Cell(found->error) : "");
      }
      out << "," << Cell(row.max_node_error) << "," << Cell(row.estimated_error);
      if (drape) out << "," << Cell(row.drape_coefficient) << "," << Cell(row.drape_nodes);
      out << "\n";
    }
    if (!out) throw std::runtime_error("cannot write '" + temporary.string() + "'");
  }
  fs::rename(temporary, file);
}

}  // namespace drape
