#include "ui/widgets/editor_docks.h"

#include <QDockWidget>
#include <QScrollArea>
#include <QListWidget>
#include <QMainWindow>
#include <QTabWidget>

#include <initializer_list>

#include "ui/widgets/holds_panel.h"
#include "ui/widgets/loads_panel.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/move_editor.h"
#include "ui/widgets/obstacles_panel.h"
#include "ui/widgets/plan_dock.h"
#include "ui/widgets/probe_plot.h"
#include "ui/widgets/probes_panel.h"
#include "ui/widgets/property_panel.h"
#include "ui/widgets/reaction_plot.h"
#include "ui/widgets/run_monitor.h"
#include "ui/widgets/run_plot.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/stages_panel.h"

namespace drape {

EditorDocks::EditorDocks(SceneDocument* document, RunMonitor* monitor, QMainWindow* window)
    : QObject(window), document_(document), window_(window) {
  DockEditors();
  DockPlots(monitor);
  // Seven editors share the left dock area: their tabs stand on its side.
  window->setTabPosition(Qt::LeftDockWidgetArea, QTabWidget::West);
  connect(tree_, &ModelTree::chosen, this, [this](ModelTree::Part part, int index, int move) {
    showEditor(static_cast<int>(part), index, move);
  });
}

QDockWidget* EditorDocks::AddDock(const QString& title,
                                  QWidget* widget,
                                  Qt::DockWidgetArea area,
                                  QDockWidget* tab_with) {
  auto* dock = new QDockWidget(title, window_);
  dock->setObjectName(title);  // for saveState
  dock->setWidget(widget);
  window_->addDockWidget(area, dock);
  if (tab_with) window_->tabifyDockWidget(tab_with, dock);
  return dock;
}

void EditorDocks::DockEditors() {
  tree_ = new ModelTree(document_, window_);
  tree_->setMinimumHeight(170);
  QDockWidget* tree_dock = AddDock("Scene", tree_, Qt::LeftDockWidgetArea, nullptr);
  properties_ = new PropertyPanel(document_, window_);
  QDockWidget* properties_dock =
      AddDock("Properties", properties_, Qt::LeftDockWidgetArea, nullptr);
  // The tree above, the editors tabbed below it.
  window_->splitDockWidget(tree_dock, properties_dock, Qt::Vertical);
  auto editor = [&](const QString& title, QWidget* panel) {
    return AddDock(title, panel, Qt::LeftDockWidgetArea, properties_dock);
  };
  supports_ = new HoldsPanel(HoldsPanel::Role::kSupports, document_, window_);
  QDockWidget* supports_dock = editor("Supports", supports_);
  grippers_ = new HoldsPanel(HoldsPanel::Role::kGrippers, document_, window_);
  QDockWidget* grippers_dock = editor("Grippers", grippers_);
  loads_ = new LoadsPanel(document_, window_);
  QDockWidget* loads_dock = editor("Loads", loads_);
  obstacles_ = new ObstaclesPanel(document_, window_);
  QDockWidget* obstacles_dock = editor("Obstacles", obstacles_);
  stages_ = new StagesPanel(document_, window_);
  QDockWidget* stages_dock = editor("Stages", stages_);
  probes_ = new ProbesPanel(document_, window_);
  QDockWidget* probes_dock = editor("Probes", probes_);
  // In ModelTree::Part's order.
  editor_docks_ = {properties_dock,
                   properties_dock,
                   supports_dock,
                   grippers_dock,
                   obstacles_dock,
                   stages_dock,
                   probes_dock,
                   properties_dock,
                   loads_dock};
  properties_dock->raise();
  window_->resizeDocks({tree_dock, properties_dock}, {220, 700}, Qt::Vertical);
  // A dock tabbed behind another still says isVisible(); the signal says
  // when its tab is selected or unselected.
  connect(stages_dock, &QDockWidget::visibilityChanged, this, &EditorDocks::stagesShown);
  connect(grippers_dock, &QDockWidget::visibilityChanged, this, &EditorDocks::grippersShown);
  connect(obstacles_dock, &QDockWidget::visibilityChanged, this, &EditorDocks::obstaclesShown);
  connect(properties_dock, &QDockWidget::visibilityChanged, this, &EditorDocks::propertiesShown);
}

void EditorDocks::DockPlots(RunMonitor* monitor) {
  QDockWidget* run = AddDock("Run", monitor->plot(), Qt::BottomDockWidgetArea, nullptr);
  AddDock("Probe plot", monitor->probePlot(), Qt::BottomDockWidgetArea, run);
  AddDock("Residuals", monitor->residualPlot(), Qt::BottomDockWidgetArea, run);
  AddDock("Reactions", monitor->reactionPlot(), Qt::BottomDockWidgetArea, run);
  plan_ = new PlanDock(document_, window_);
  // Scrolled: its tables must not make the bottom docks (and the window)
  // taller than the plots need.
  auto* scroll = new QScrollArea(window_);
  scroll->setWidget(plan_);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  AddDock("Plan", scroll, Qt::BottomDockWidgetArea, run);
  run->raise();
}

void EditorDocks::showEditor(int part, int index, int move) {
  if (part < 0 || part >= static_cast<int>(editor_docks_.size())) return;
  editor_docks_[part]->raise();
  if (index < 0) return;
  switch (static_cast<ModelTree::Part>(part)) {
    case ModelTree::Part::kSupports:
      return supports_->list()->setCurrentRow(index);
    case ModelTree::Part::kGrippers:
      return grippers_->list()->setCurrentRow(index);
    case ModelTree::Part::kObstacles:
      return obstacles_->list()->setCurrentRow(index);
    case ModelTree::Part::kStages:
      stages_->list()->setCurrentRow(index);
      if (move >= 0) stages_->moves()->list()->setCurrentRow(move);
      return;
    case ModelTree::Part::kProbes:
      return probes_->list()->setCurrentRow(index);
    case ModelTree::Part::kLoads:
      return loads_->list()->setCurrentRow(index);
    default:
      return;
  }
}

void EditorDocks::setUnitSystem(UnitSystem system) {
  properties_->setUnitSystem(system);
  loads_->setUnitSystem(system);
  supports_->setUnitSystem(system);
  grippers_->setUnitSystem(system);
  probes_->setUnitSystem(system);
  obstacles_->setUnitSystem(system);
  tree_->setUnitSystem(system);
  stages_->moves()->setUnitSystem(system);
}

void EditorDocks::setEditable(bool editable) {
  for (QWidget* editor : std::initializer_list<QWidget*>{
           properties_, stages_, supports_, grippers_, obstacles_, loads_, probes_})
    editor->setEnabled(editable);
}

void EditorDocks::setPicked(const std::vector<int>& nodes,
                            const std::vector<std::array<double, 2>>& at) {
  supports_->setPickedNodes(nodes, at);
  grippers_->setPickedNodes(nodes, at);
  loads_->setPickedNodes(nodes, at);
  probes_->setPicked(at);
}

}  // namespace drape
