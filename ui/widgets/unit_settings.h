// The unit system the workbench shows quantities in: chosen by the user
// (SI, textile, imperial) or the scene's own (guessed from the units its
// file is written in, GuessUnitSystem), kept in QSettings ("units") across
// sessions. Panels, plots and the colour bar connect to changed().
#pragma once

#include <QActionGroup>
#include <QObject>
#include <QPointer>

#include <optional>

#include "core/model/unit_system.h"

class QMenu;
class QWidget;

namespace drape {

class SceneDocument;

class UnitSettings : public QObject {
  Q_OBJECT
 public:
  // Reads the saved choice; the scene's own until a scene is told.
  explicit UnitSettings(QObject* parent = nullptr);

  // The system in effect: the chosen one, or the scene's.
  UnitSystem system() const { return choice_.value_or(scene_); }
  // The user's choice; nullopt: the scene's own.
  std::optional<UnitSystem> choice() const { return choice_; }
  UnitSystem sceneSystem() const { return scene_; }

  // "Units ▸ SI / Textile / Imperial / Scene's own", checkable, one of them
  // checked, following setChoice() from anywhere. Owned by `parent`.
  QMenu* menu(QWidget* parent = nullptr);

 public slots:
  // Saved in QSettings; emits changed() when the system in effect changes.
  void setChoice(std::optional<UnitSystem> choice);
  // The same for this session only (drape-studio --units): not saved.
  void useChoice(std::optional<UnitSystem> choice);
  // The scene's own system (for "Scene's own"); emits changed() when in effect.
  void setSceneSystem(UnitSystem system);
  // The scene's own system guessed from the units its file is written in
  // (the document's JSON is SI, so the file is read); a file that cannot be
  // read, or a document without one (a template), keeps the last system.
  void followSceneFile(const QString& file);
  void followScene(const SceneDocument* document);

 signals:
  void changed(UnitSystem system);

 private:
  void Set(std::optional<UnitSystem> choice, UnitSystem scene);

  std::optional<UnitSystem> choice_;
  UnitSystem scene_ = UnitSystem::kSI;
  QPointer<QActionGroup> group_;  // the last menu()'s, gone with its menu
};

}  // namespace drape
