// The scene as a tree: fabric, material, supports, grippers, loads, obstacles,
// stages with their moves, probes and solver, each with a one-line summary
// ("rectangle 20 × 20 cm") in the unit system chosen.
// Choosing an item says which part of the scene to edit; the main window
// shows its editor.
#pragma once

#include <QTreeWidget>

#include "core/model/unit_system.h"

namespace drape {

class SceneDocument;

class ModelTree : public QTreeWidget {
  Q_OBJECT
 public:
  enum class Part {
    kFabric,
    kMaterial,
    kSupports,
    kGrippers,
    kObstacles,
    kStages,
    kProbes,
    kSolver,
    kLoads  // (shown after the grippers)
  };

  explicit ModelTree(SceneDocument* document, QWidget* parent = nullptr);

  // The item for `part` (index -1: its heading; `move` a stage's move).
  QTreeWidgetItem* item(Part part, int index = -1, int move = -1) const;

 public slots:
  void refresh();
  // Summaries in `system`'s units.
  void setUnitSystem(UnitSystem system);

 signals:
  void chosen(drape::ModelTree::Part part, int index, int move);
  void opened(drape::ModelTree::Part part, int index, int move);  // double click

 private:
  SceneDocument* document_;
  UnitSystem units_ = UnitSystem::kSI;
};

}  // namespace drape
