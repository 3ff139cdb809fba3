#include "ui/widgets/scene_part_watch.h"

namespace drape {

ScenePartWatch::ScenePartWatch(SceneDocument* document,
                               SceneDocument::Parts shown,
                               std::function<void()> refresh,
                               QObject* editor)
    : QObject(editor), shown_(shown), refresh_(std::move(refresh)) {
  connect(document, &SceneDocument::partsChanged, this, [this](SceneDocument::Parts parts) {
    if (!(parts & shown_)) return;
    ++refreshes_;
    refresh_();
  });
}

const ScenePartWatch* ScenePartWatch::of(const QObject* editor) {
  return editor ? editor->findChild<const ScenePartWatch*>(QString(), Qt::FindDirectChildrenOnly)
                : nullptr;
}

}  // namespace drape
