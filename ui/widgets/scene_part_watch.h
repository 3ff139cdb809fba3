// What keeps an editor in step with the scene: the editor's refresh is
// called when a part of the scene it shows changed (an edit, its undo or
// redo, or another scene opened), and not for edits elsewhere, which would
// rebuild its lists and fields for nothing. The calls are counted, so a test
// can tell an editor was left alone.
#pragma once

#include <QObject>

#include <functional>

#include "ui/widgets/scene_document.h"

namespace drape {

class ScenePartWatch : public QObject {
  Q_OBJECT
 public:
  // Calls `refresh` when one of `shown` changed; a child of `editor`.
  ScenePartWatch(SceneDocument* document,
                 SceneDocument::Parts shown,
                 std::function<void()> refresh,
                 QObject* editor);

  SceneDocument::Parts shown() const { return shown_; }
  // Refreshes for changes of the scene since the editor was made.
  int refreshes() const { return refreshes_; }
  // The watch `editor` made for itself (not one of its child editors'), or
  // null.
  static const ScenePartWatch* of(const QObject* editor);

 private:
  SceneDocument::Parts shown_;
  std::function<void()> refresh_;
  int refreshes_ = 0;
};

}  // namespace drape
