// The workbench's docks: the scene tree above the seven editors of the
// scene (properties, supports, grippers, loads, obstacles, stages, probes),
// tabbed at the left, and the run's plots tabbed at the bottom. It raises
// the editor of what the tree chooses, passes picked nodes to the editors
// that use them, shows every editor in one unit system, and locks them all
// while a run works on the scene.
#pragma once

#include <QObject>

#include <array>
#include <vector>

#include "core/model/unit_system.h"

class QDockWidget;
class QMainWindow;

namespace drape {

class HoldsPanel;
class LoadsPanel;
class ModelTree;
class ObstaclesPanel;
class PlanDock;
class ProbesPanel;
class PropertyPanel;
class RunMonitor;
class SceneDocument;
class StagesPanel;

class EditorDocks : public QObject {
  Q_OBJECT
 public:
  // Docks the editors of `document` and `monitor`'s plots in `window`.
  EditorDocks(SceneDocument* document, RunMonitor* monitor, QMainWindow* window);

  ModelTree* tree() const { return tree_; }
  PropertyPanel* properties() const { return properties_; }
  StagesPanel* stages() const { return stages_; }
  HoldsPanel* supports() const { return supports_; }
  HoldsPanel* grippers() const { return grippers_; }
  ObstaclesPanel* obstacles() const { return obstacles_; }
  LoadsPanel* loads() const { return loads_; }
  ProbesPanel* probes() const { return probes_; }
  PlanDock* plan() const { return plan_; }

  // Every editor's fields (and the tree's summaries) in `system`.
  void setUnitSystem(UnitSystem system);
  // Off while a run works on the scene it started with.
  void setEditable(bool editable);
  // Nodes picked in the view and their flat reference points: for the
  // selections of supports, grippers and loads, and a probe's point.
  void setPicked(const std::vector<int>& nodes, const std::vector<std::array<double, 2>>& at);
  // The editor of ModelTree::Part `part` raised, item `index` (and a
  // stage's move `move`) selected; -1 selects nothing.
  void showEditor(int part, int index, int move);

 signals:
  // The stages', grippers', obstacles' or properties' tab came up or went
  // away: their handles show in the view only then.
  void stagesShown(bool shown);
  void grippersShown(bool shown);
  void obstaclesShown(bool shown);
  void propertiesShown(bool shown);

 private:
  void DockEditors();
  void DockPlots(RunMonitor* monitor);
  QDockWidget* AddDock(const QString& title,
                       QWidget* widget,
                       Qt::DockWidgetArea area,
                       QDockWidget* tab_with);

  SceneDocument* document_;
  QMainWindow* window_;
  ModelTree* tree_ = nullptr;
  PropertyPanel* properties_ = nullptr;
  StagesPanel* stages_ = nullptr;
  HoldsPanel *supports_ = nullptr, *grippers_ = nullptr;
  ObstaclesPanel* obstacles_ = nullptr;
  LoadsPanel* loads_ = nullptr;
  PlanDock* plan_ = nullptr;
  ProbesPanel* probes_ = nullptr;
  std::vector<QDockWidget*> editor_docks_;  // by ModelTree::Part
};

}  // namespace drape
