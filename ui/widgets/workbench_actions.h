// The workbench's menus, as every desktop program has them, and its toolbar:
// File (new, templates, open, recent, save, pattern import, export,
// recovery, quit), Edit (undo, redo, material, picking), View (the
// timeline's steps, play, the cameras), Units (UnitSettings::menu), Run
// (run, pause, step, stop) and Help (the manual, the scene file reference,
// about). Each calls the window or its parts; which are enabled follows the
// window's state (update()). Each action has an object name ("file.new",
// "run.stop", …) by which tests find it.
#pragma once

#include <QObject>

#include "ui/widgets/user_prompts.h"

class QAction;
class QMenu;

namespace drape {

class MainWindow;

class WorkbenchActions : public QObject {
  Q_OBJECT
 public:
  explicit WorkbenchActions(MainWindow* window);

  // `loaded`: a scene is open; `running`: a run works on it (no edits);
  // `estimating`: the run is done, its error estimate under way.
  void update(bool loaded, bool running, bool paused, bool estimating);

  // The dialogs' answers; a test sets its own.
  void setPrompts(UserPrompts prompts) { prompts_ = std::move(prompts); }

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
  void BuildTemplateMenu(QMenu* menu);
  void BuildExportMenu(QMenu* menu);
  void BuildEditMenu();
  void BuildViewMenu();
  void BuildRunMenu();
  void BuildHelpMenu();
  void BuildToolBar();
  // An action named `name` (its object name) in `menu`.
  QAction* Add(QMenu* menu, const char* name, const QString& text);
  // Whether the scene open now may be replaced (its changes saved or let go).
  bool MayReplace();
  void SaveScene(bool ask_where);
  void ShowAbout();

  MainWindow* window_;
  UserPrompts prompts_;
  QAction *new_ = nullptr, *open_ = nullptr, *save_ = nullptr, *save_as_ = nullptr;
  QAction *import_ = nullptr, *recover_ = nullptr, *quit_ = nullptr;
  QAction *export_image_ = nullptr, *export_vtu_ = nullptr, *export_animation_ = nullptr;
  QMenu *templates_ = nullptr, *recent_ = nullptr, *export_ = nullptr;
  QAction *undo_ = nullptr, *redo_ = nullptr, *material_ = nullptr, *pick_ = nullptr;
  QAction* clear_picked_ = nullptr;
  QAction *run_ = nullptr, *pause_ = nullptr, *step_ = nullptr, *stop_ = nullptr;
};

}  // namespace drape
