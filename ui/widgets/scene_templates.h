// The scenes a new document starts from, as a user looks for them: titled
// and grouped (start here, the paper's experiments, more examples) by the
// catalogue resources/templates.json, each a shipped scene file.
#pragma once

#include <QString>

#include <vector>

namespace drape {

struct SceneTemplate {
  QString title;        // as the menu shows it
  QString file;         // the scene, absolute
  QString description;  // the scene's own "description", for a tooltip
};

struct TemplateGroup {
  QString title;
  std::vector<SceneTemplate> templates;
};

// The catalogue in its order. Throws std::runtime_error naming the
// catalogue and what is wrong (unreadable, a key missing, a scene that is
// not there).
std::vector<TemplateGroup> SceneTemplates();

// The blank scene File ▸ New starts from: the first template of the first group.
SceneTemplate BlankTemplate();

}  // namespace drape
