// What every scene editor does around an edit: a message line under the
// editor (why an edit was refused, in the reader's or the engine's words),
// the edit tried and its refusal shown there, and a name for a new item.
#pragma once

#include <QString>

#include <functional>
#include <string>

#include <nlohmann/json_fwd.hpp>

class QLabel;
class QWidget;

namespace drape {

class SceneDocument;
struct Scene;

// A word-wrapped red label, empty until something is refused.
QLabel* MakeMessageLabel(QWidget* parent);

// `document`->tryApply; the reason (or nothing) goes into `message`, after
// the edit's name: "thickness 0.5 mm — material.thickness: …".
bool ApplyOrSay(SceneDocument* document, QLabel* message, const QString& what, const Scene& after);
// The same for a scene's JSON form (SceneDocument::tryApplyJson).
bool ApplyOrSay(SceneDocument* document,
                QLabel* message,
                const QString& what,
                const nlohmann::json& scene_json);

// "stem N" for the first N ≥ `first` that `taken` does not report.
std::string FreeName(const std::string& stem,
                     int first,
                     const std::function<bool(const std::string&)>& taken);

// "stem N" that no item of `items` (each with a `name`) has, N from size + 1.
template <typename Items>
std::string FreeName(const std::string& stem, const Items& items) {
  return FreeName(stem, static_cast<int>(items.size()) + 1, [&](const std::string& name) {
    for (const auto& item : items)
      if (item.name == name) return true;
    return false;
  });
}

}  // namespace drape
