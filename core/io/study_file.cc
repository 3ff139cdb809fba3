#include "core/io/study_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>

#include "core/io/json_cursor.h"
#include "core/io/scene_key.h"
#include "core/io/scene_reader.h"
#include "core/io/text_file.h"
#include "core/model/scene_error.h"

namespace drape {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

constexpr int kStudyFormatVersion = 1;
// A grid larger than this is almost surely a mistake (a list where a value
// was meant); runs are processes, each taking seconds to hours.
constexpr size_t kMaxRuns = 100000;

// `ordered` is the same object as `settings` read with its keys in the
// order the user wrote them (the columns of study.csv follow it).
StudyRun RunOf(std::string name,
               const JsonCursor& settings,
               const ordered_json& ordered,
               std::vector<std::string>& keys) {
  if (!settings.value().is_object() || settings.value().empty())
    settings.Fail("expected an object of scene keys and their values");
  StudyRun run{std::move(name), {}};
  for (auto it = ordered.begin(); it != ordered.end(); ++it) {
    run.settings.push_back({it.key(), it.value().dump()});
    if (std::find(keys.begin(), keys.end(), it.key()) == keys.end()) keys.push_back(it.key());
  }
  return run;
}

std::string RunName(size_t index, size_t count) {
  const size_t width = std::max<size_t>(3, std::to_string(count).size());
  std::string number = std::to_string(index + 1);
  return "run_" + std::string(width - std::min(width, number.size()), '0') + number;
}

std::vector<StudyRun> ExpandGrid(const JsonCursor& grid,
                                 const ordered_json& ordered,
                                 std::vector<std::string>& keys) {
  if (!grid.value().is_object() || grid.value().empty())
    grid.Fail("expected an object: each scene key with the list of its values");
  std::vector<std::pair<std::string, std::vector<std::string>>> axes;
  size_t count = 1;
  for (auto it = ordered.begin(); it != ordered.end(); ++it) {
    const JsonCursor values = grid[it.key()];
    std::vector<std::string> texts;
    for (const JsonCursor& v : values.Items()) texts.push_back(v.value().dump());
    if (texts.empty()) values.Fail("expected at least one value");
    count *= texts.size();
    if (count > kMaxRuns)
      grid.Fail("more than " + std::to_string(kMaxRuns) +
                " runs: is a list of values given where one value was meant?");
    keys.push_back(it.key());
    axes.emplace_back(it.key(), std::move(texts));
  }
  std::vector<StudyRun> runs;
  for (size_t r = 0; r < count; ++r) {
    StudyRun run{RunName(r, count), {}};
    size_t rest = r;
    std::vector<StudySetting> settings(axes.size());
    for (size_t a = axes.size(); a-- > 0;) {
      settings[a] = {axes[a].first, axes[a].second[rest % axes[a].second.size()]};
      rest /= axes[a].second.size();
    }
    run.settings = std::move(settings);
    runs.push_back(std::move(run));
  }
  return runs;
}

void CheckRunScene(const Study& study, const StudyRun& run) {
  try {
    ParseScene(SceneTextOf(study, run), study.scene_file.parent_path());
  } catch (const SceneError& e) {
    throw SceneError("", Describe(run) + ": " + e.what());
  }
}

}  // namespace

std::string Describe(const StudyRun& run) {
  std::string text = run.name + " (";
  for (size_t i = 0; i < run.settings.size(); ++i)
    text += (i ? ", " : "") + run.settings[i].key + " = " + run.settings[i].value;
  return text + ")";
}

std::string SceneTextOf(const Study& study, const StudyRun& run) {
  ordered_json scene;
  try {
    scene = ordered_json::parse(study.scene_text);
  } catch (const json::parse_error& e) {
    throw SceneError("scene", study.scene_file.string() + " is not valid JSON: " + e.what());
  }
  for (const StudySetting& s : run.settings) SetSceneKey(scene, s.key, json::parse(s.value), "");
  MakeFilesAbsolute(scene, study.scene_file.parent_path());
  return scene.dump(2);
}

Study ReadStudy(const fs::path& file) {
  Study study;
  study.file = fs::absolute(file).lexically_normal();
  json document;
  ordered_json ordered;
  try {
    const std::string text = ReadTextFile(study.file, "study file");
    document = json::parse(text);
    ordered = ordered_json::parse(text);
  } catch (const json::parse_error& e) {
    throw SceneError("", "not valid JSON: " + std::string(e.what()));
  }
  const JsonCursor root(document, "");
  root.ExpectObject(
      {"drape_study", "scene", "grid", "list", "reference", "time_limit_s", "description"});
  if (root["drape_study"].Integer() != kStudyFormatVersion)
    root["drape_study"].Fail("this program reads study format 1");
  const JsonCursor scene = root["scene"];
  study.scene_file = (study.file.parent_path() / scene.String()).lexically_normal();
  try {
    study.scene_text = ReadTextFile(study.scene_file, "scene file");
  } catch (const SceneError& e) {
    scene.Fail(e.message());
  }
  if (root.OneOf({"grid", "list"}) == 0) {
    study.runs = ExpandGrid(root["grid"], ordered["grid"], study.keys);
  } else {
    const auto items = root["list"].Items();
    if (items.empty()) root["list"].Fail("expected at least one run");
    for (size_t i = 0; i < items.size(); ++i)
      study.runs.push_back(
          RunOf(RunName(i, items.size()), items[i], ordered["list"][i], study.keys));
  }
  if (auto reference = root.Find("reference"))
    study.reference = RunOf("reference", *reference, ordered["reference"], study.keys);
  if (auto limit = root.Find("time_limit_s")) {
    study.time_limit_s = limit->Number();
    if (*study.time_limit_s <= 0) limit->Fail("expected a number of seconds > 0");
  }
  for (const StudyRun& run : study.runs) CheckRunScene(study, run);
  if (study.reference) CheckRunScene(study, *study.reference);
  return study;
}

}  // namespace drape
