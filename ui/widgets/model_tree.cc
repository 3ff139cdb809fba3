#include "ui/widgets/model_tree.h"

#include <QHeaderView>

#include "core/model/overloaded.h"
#include "core/model/scene.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/selection_rule.h"
#include "ui/widgets/typed_json.h"

namespace drape {
namespace {

constexpr int kPartRole = Qt::UserRole, kIndexRole = Qt::UserRole + 1, kMoveRole = Qt::UserRole + 2;

QTreeWidgetItem* Add(QTreeWidgetItem* parent,
                     const QString& name,
                     const QString& summary,
                     ModelTree::Part part,
                     int index = -1,
                     int move = -1) {
  auto* item = new QTreeWidgetItem(parent, {name, summary});
  item->setData(0, kPartRole, static_cast<int>(part));
  item->setData(0, kIndexRole, index);
  item->setData(0, kMoveRole, move);
  return item;
}

QString Shown(double si, Measure measure, UnitSystem system) {
  return QString::fromStdString(FormatQuantity(si, measure, system));
}

QString OutlineSummary(const Fabric& f, UnitSystem system) {
  return std::visit(
      Overloaded{[&](const RectangleOutline& r) {
                   return QString("rectangle %1 × %2")
                       .arg(QString::fromStdString(
                                FormatNumber(r.size[0], UnitFor(Measure::kLength, system))),
                            Shown(r.size[1], Measure::kLength, system));
                 },
                 [&](const DiskOutline& d) {
                   return QString("disk r = %1").arg(Shown(d.radius, Measure::kLength, system));
                 },
                 [](const PolygonOutline& p) {
                   return QString("polygon, %1 vertices").arg(p.vertices.size());
                 },
                 [](const PatternOutline& p) {
                   const auto holes = p.shape.holes.size();
                   return QString("pattern piece %1%2")
                       .arg(QString::fromStdString(p.piece),
                            holes == 0   ? QString()
                            : holes == 1 ? QString(", 1 cut-out")
                                         : QString(", %1 cut-outs").arg(holes));
                 }},
      f.outline);
}

// The parts the tree sums up: nearly any edit changes it, but not the name,
// description, contact or gravity, which it does not show.
SceneDocument::Parts SummedUp() {
  using P = SceneDocument::Part;
  return P::kFabric | P::kMaterial | P::kSupports | P::kGrippers | P::kLoads | P::kObstacles |
         P::kStages | P::kProbes | P::kSolver;
}

}  // namespace

ModelTree::ModelTree(SceneDocument* document, QWidget* parent)
    : QTreeWidget(parent), document_(document) {
  setColumnCount(2);
  setHeaderLabels({"scene", ""});
  header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  connect(this, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* item) {
    if (item)
      emit chosen(static_cast<Part>(item->data(0, kPartRole).toInt()),
                  item->data(0, kIndexRole).toInt(),
                  item->data(0, kMoveRole).toInt());
  });
  connect(this, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
    emit opened(static_cast<Part>(item->data(0, kPartRole).toInt()),
                item->data(0, kIndexRole).toInt(),
                item->data(0, kMoveRole).toInt());
  });
  new ScenePartWatch(
      document_, SummedUp(), [this] { refresh(); }, this);
  refresh();
}

QTreeWidgetItem* ModelTree::item(Part part, int index, int move) const {
  for (int i = 0; i < topLevelItemCount(); ++i) {
    QTreeWidgetItem* top = topLevelItem(i);
    if (top->data(0, kPartRole).toInt() != static_cast<int>(part)) continue;
    if (index < 0) return top;
    QTreeWidgetItem* child = index < top->childCount() ? top->child(index) : nullptr;
    if (!child || move < 0) return child;
    return move < child->childCount() ? child->child(move) : nullptr;
  }
  return nullptr;
}

void ModelTree::setUnitSystem(UnitSystem system) {
  units_ = system;
  refresh();
}

void ModelTree::refresh() {
  const Scene& s = document_->scene();
  const QSignalBlocker block(this);  // rebuilding is not a choice
  clear();
  auto* root = invisibleRootItem();
  // Of several parts, the editor edits the first; the tree says so.
  Add(root,
      "Fabric",
      s.other_parts.empty()
          ? OutlineSummary(s.fabric, units_)
          : QString("%1 parts; the editor shows '%2': %3")
                .arg(s.other_parts.size() + 1)
                .arg(QString::fromStdString(s.fabric.name), OutlineSummary(s.fabric, units_)),
      Part::kFabric);
  Add(root,
      "Material",
      QString("h = %1, w = %2")
          .arg(Shown(s.material.thickness, Measure::kThickness, units_),
               Shown(s.material.areal_weight, Measure::kArealWeight, units_)),
      Part::kMaterial);
  auto* supports = Add(root, "Supports", QString::number(s.supports.size()), Part::kSupports);
  for (size_t i = 0; i < s.supports.size(); ++i)
    Add(supports,
        QString::fromStdString(s.supports[i].name),
        QString("%1, %2").arg(DescribeSelection(s.supports[i].select, units_),
                              ToString(s.supports[i].fix)),
        Part::kSupports,
        static_cast<int>(i));
  auto* grippers = Add(root, "Grippers", QString::number(s.grippers.size()), Part::kGrippers);
  for (size_t i = 0; i < s.grippers.size(); ++i)
    Add(grippers,
        QString::fromStdString(s.grippers[i].name),
        QString("%1, %2").arg(DescribeSelection(s.grippers[i].select, units_),
                              ToString(s.grippers[i].hold)),
        Part::kGrippers,
        static_cast<int>(i));
  auto* loads = Add(root, "Loads", QString::number(s.loads.size()), Part::kLoads);
  for (size_t i = 0; i < s.loads.size(); ++i)
    Add(loads,
        QString::fromStdString(s.loads[i].name),
        QString("(%1)").arg(ListText(s.loads[i].force, Measure::kForce, units_)),
        Part::kLoads,
        static_cast<int>(i));
  auto* obstacles = Add(root, "Obstacles", QString::number(s.obstacles.size()), Part::kObstacles);
  for (size_t i = 0; i < s.obstacles.size(); ++i)
    Add(obstacles,
        QString::fromStdString(s.obstacles[i].name),
        {},
        Part::kObstacles,
        static_cast<int>(i));
  auto* stages = Add(root, "Stages", QString::number(s.stages.size()), Part::kStages);
  for (size_t i = 0; i < s.stages.size(); ++i) {
    const Stage& st = s.stages[i];
    auto* stage =
        Add(stages,
            QString::fromStdString(st.name),
            QString("%1, first step %2 %").arg(ToString(st.kind)).arg(100 * st.initial_increment),
            Part::kStages,
            static_cast<int>(i));
    for (size_t m = 0; m < st.moves.size(); ++m)
      Add(stage,
          QString::fromStdString(st.moves[m].gripper.empty() ? st.moves[m].obstacle
                                                             : st.moves[m].gripper),
          "move",
          Part::kStages,
          static_cast<int>(i),
          static_cast<int>(m));
  }
  auto* probes = Add(root, "Probes", QString::number(s.probes.size()), Part::kProbes);
  for (size_t i = 0; i < s.probes.size(); ++i)
    Add(probes,
        QString::fromStdString(s.probes[i].name),
        QString("(%1)").arg(ListText(s.probes[i].at, units_)),
        Part::kProbes,
        static_cast<int>(i));
  Add(root,
      "Solver",
      QString("tolerance %1, %2 iterations per step")
          .arg(s.solver.tolerance)
          .arg(s.solver.target_iterations),
      Part::kSolver);
  expandAll();
}

}  // namespace drape
