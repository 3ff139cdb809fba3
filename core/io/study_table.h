// The table of a study (DIR/study.csv, docs/format.md §6.2): one row per
// run, read back from the result folders the runs wrote, each measured
// against the reference run. Made the same way after `drape study` ran the
// runs itself and after a cluster did (`--collect`).
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/io/study_file.h"

namespace drape {

// Where a study keeps run NAME: DIR/runs/NAME/scene.json and its result
// folder DIR/runs/NAME/result.
std::filesystem::path RunFolder(const std::filesystem::path& study_dir, const std::string& name);
std::filesystem::path RunSceneFile(const std::filesystem::path& study_dir, const std::string& name);
std::filesystem::path RunResultFolder(const std::filesystem::path& study_dir,
                                      const std::string& name);

// Whether the run ended (converged or failed): a rerun skips it. A run
// cancelled, killed or never started is run again.
bool RunEnded(const std::filesystem::path& study_dir, const std::string& name);

struct StudyProbe {
  std::string name;
  std::array<double, 3> position{};  // final [m]
  std::optional<double> error;       // distance from the reference's [m]
};

struct StudyRow {
  StudyRun run;
  std::string status = "missing";  // result.json's, or missing
  std::optional<double> solve_s, peak_memory_bytes;
  std::optional<int> steps, iterations, factorizations;
  std::vector<StudyProbe> probes;
  // The largest distance between a node's final position and the same
  // material point on the reference (interpolated where meshes differ) [m].
  std::optional<double> max_node_error;
  // The run's own estimate (solver.error_estimate): its largest probe error.
  std::optional<double> estimated_error;
  // A Cusick test's (docs/cusick.md) drape coefficient and node count at
  // the last step of a converged run; empty for any other scene.
  std::optional<double> drape_coefficient;
  std::optional<int> drape_nodes;
};

// The mean and sample standard deviation of the drape coefficient and of
// the node count over the runs that have them, as a lab reports its
// specimens; empty when fewer than one run has them.
struct DrapeSpread {
  int specimens = 0;
  double mean_coefficient = 0, sd_coefficient = 0;
  double mean_nodes = 0, sd_nodes = 0;
  int fewest_nodes = 0, most_nodes = 0;
};
std::optional<DrapeSpread> SpreadOfDrape(const std::vector<StudyRow>& rows);

// Reads every run's result (and the reference's); a run without one is a
// row with status `missing`. Errors are measured only against a reference
// that converged.
std::vector<StudyRow> CollectStudy(const Study& study, const std::filesystem::path& study_dir);

// The rows no other beats on both time and error (the Pareto front): true
// for each row that converged with both numbers and is not dominated — no
// other such row faster and as accurate, or as fast and more accurate,
// errors within 1 % counting as equal. The reference (no error) is never
// on it.
std::vector<bool> ParetoFront(const std::vector<StudyRow>& rows);

// Writes the rows as CSV (header first; an empty cell where a number does
// not exist, never NaN). Throws std::runtime_error when it cannot write.
void WriteStudyCsv(const Study& study,
                   const std::vector<StudyRow>& rows,
                   const std::filesystem::path& file);

}  // namespace drape
