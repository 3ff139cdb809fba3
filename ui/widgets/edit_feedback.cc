#include "ui/widgets/edit_feedback.h"

#include <QLabel>
#include <nlohmann/json.hpp>

#include "ui/widgets/scene_document.h"

namespace drape {

QLabel* MakeMessageLabel(QWidget* parent) {
  auto* label = new QLabel(parent);
  label->setWordWrap(true);
  label->setStyleSheet("color: #b00020");
  return label;
}

namespace {

// The edit in the editor's words (the field and the value typed) beside the
// reader's or the engine's message, which names the scene key.
void Say(QLabel* message, const QString& what, const QString& problem) {
  message->setText(problem.isEmpty() ? QString() : what + " — " + problem);
}

}  // namespace

bool ApplyOrSay(SceneDocument* document, QLabel* message, const QString& what, const Scene& after) {
  QString problem;
  const bool done = document->tryApply(what, after, &problem);
  Say(message, what, problem);
  return done;
}

bool ApplyOrSay(SceneDocument* document,
                QLabel* message,
                const QString& what,
                const nlohmann::json& scene_json) {
  QString problem;
  const bool done = document->tryApplyJson(what, scene_json, &problem);
  Say(message, what, problem);
  return done;
}

std::string FreeName(const std::string& stem,
                     int first,
                     const std::function<bool(const std::string&)>& taken) {
  int n = first;
  while (taken(stem + " " + std::to_string(n))) ++n;
  return stem + " " + std::to_string(n);
}

}  // namespace drape
