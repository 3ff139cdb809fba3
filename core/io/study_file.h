// A study (docs/format.md §6): one scene, the keys to vary over a grid or a
// list, and a reference run that the others are measured against. `drape
// study` turns it into one scene per run and runs them.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace drape {

// One varied key — a JSON path into the scene such as
// `stages[1].initial_increment` — and its value as JSON text (`1e-05`,
// `[40, 4]`, `"2 cm"`).
struct StudySetting {
  std::string key;
  std::string value;
};

struct StudyRun {
  std::string name;                    // "run_007", or "reference"
  std::vector<StudySetting> settings;  // in the study's key order
};

struct Study {
  std::filesystem::path file;          // the study file, absolute
  std::filesystem::path scene_file;    // absolute
  std::string scene_text;              // the scene file as read
  std::vector<std::string> keys;       // every varied key, in order of first appearance
  std::vector<StudyRun> runs;          // the grid expanded (last key fastest), or the list
  std::optional<StudyRun> reference;   // absent: errors are not measured
  std::optional<double> time_limit_s;  // per run (drape run --time-limit)
};

// Reads and checks a study file. Every run's scene (and the reference's) is
// read too, so a value the scene reader refuses fails here, naming the run,
// its settings and the scene's key. Throws SceneError.
Study ReadStudy(const std::filesystem::path& file);

// The scene of one run as JSON text: the study's scene with the run's
// settings, every relative `file` made absolute so that it reads from
// anywhere. Throws SceneError naming the key when a path does not lead into
// the scene (an index past the end of an array, a member of a number).
std::string SceneTextOf(const Study& study, const StudyRun& run);

// `run_007 (fabric.mesh.elements = [40,4], solver.tolerance = 1e-05)`.
std::string Describe(const StudyRun& run);

}  // namespace drape
