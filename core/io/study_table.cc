#include "core/io/study_table.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "core/io/state_file.h"
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

void WriteStudyCsv(const Study& study, const std::vector<StudyRow>& rows, const fs::path& file) {
  // Probe columns: every probe any run reports, in order of first appearance.
  std::vector<std::string> probes;
  for (const StudyRow& row : rows)
    for (const StudyProbe& p : row.probes)
      if (std::find(probes.begin(), probes.end(), p.name) == probes.end()) probes.push_back(p.name);

  const fs::path temporary = file.string() + ".part";
  {
    std::ofstream out(temporary, std::ios::binary);
    out << "run";
    for (const std::string& key : study.keys) out << "," << Quoted(key);
    out << ",status,wall_s,steps,iterations,factorizations,peak_memory_bytes";
    for (const std::string& p : probes)
      out << "," << p << "_x_m," << p << "_y_m," << p << "_z_m," << p << "_error_m";
    out << ",max_node_error_m,estimated_error_m\n";
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
      out << "," << Cell(row.max_node_error) << "," << Cell(row.estimated_error) << "\n";
    }
    if (!out) throw std::runtime_error("cannot write '" + temporary.string() + "'");
  }
  fs::rename(temporary, file);
}

}  // namespace drape
