// The workbench's menus and its toolbar: File (recent files, templates,
// pattern import, recovery), Edit (undo, redo, material, picking), View (the timeline's
// steps, play, the cameras), Units (UnitSettings::menu) and the toolbar (open, save, the run's
// controls, the exports); each calls the window or its parts. Which are
// enabled follows the window's state (update()).
#pragma once

#include <QObject>

class QAction;

namespace drape {

class MainWindow;

class WorkbenchActions : public QObject {
  Q_OBJECT
 public:
  explicit WorkbenchActions(MainWindow* window);

  // `loaded`: a scene is open; `running`: a run works on it (no edits);
  // `estimating`: the run is done, its error estimate under way.
  void update(bool loaded, bool running, bool paused, bool estimating);

  QAction* material() const { return material_; }
  QAction* pick() const { return pick_; }
  QAction* undo() const { return undo_; }
  QAction* redo() const { return redo_; }
  QAction* runAction() const { return run_; }
  QAction* pause() const { return pause_; }
  QAction* step() const { return step_; }
  QAction* stop() const { return stop_; }

 private:
  void BuildFileMenu();
  void BuildViewMenu();
  void BuildToolBar();

  MainWindow* window_;
  QAction *undo_ = nullptr, *redo_ = nullptr, *material_ = nullptr, *pick_ = nullptr;
  QAction *open_ = nullptr, *run_ = nullptr, *pause_ = nullptr, *step_ = nullptr, *stop_ = nullptr;
};

}  // namespace drape
