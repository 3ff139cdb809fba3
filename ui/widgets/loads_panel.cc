#include "ui/widgets/loads_panel.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>
#include <nlohmann/json.hpp>

#include <algorithm>

#include "core/io/scene_writer.h"
#include "core/model/scene.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/selection_rule.h"
#include "ui/widgets/typed_json.h"

namespace drape {
LoadsPanel::LoadsPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget(this);
  layout->addWidget(list_, 1);
  auto* form = new QFormLayout;
  rule_ = new SelectionRuleEditor(form, "on", this);
  force_ = new QLineEdit("0, 0, -1 gf", this);
  force_->setToolTip("total force x, y, z shared by the nodes; units allowed (N, gf, oz)");
  moment_ = new QLineEdit("0, 0, 0", this);
  moment_->setToolTip("total moment x, y, z; units allowed (N*m, gf*cm)");
  form->addRow("force", force_);  // the values carry their units
  form->addRow("moment", moment_);
  layout->addLayout(form);
  auto* buttons = new QHBoxLayout;
  auto* add = new QPushButton("Add load", this);
  auto* apply = new QPushButton("Apply force", this);
  apply->setToolTip("the selected load gets the force and moment typed above");
  auto* remove = new QPushButton("Remove", this);
  buttons->addWidget(add);
  buttons->addWidget(apply);
  buttons->addWidget(remove);
  layout->addLayout(buttons);
  message_ = MakeMessageLabel(this);
  layout->addWidget(message_);
  connect(add, &QPushButton::clicked, this, [this] {
    QString problem;
    if (const auto selection = rule_->current(&problem))
      AddLoad(*selection, force_->text(), moment_->text());
    else
      message_->setText(problem);
  });
  connect(
      apply, &QPushButton::clicked, this, [this] { setForce(force_->text(), moment_->text()); });
  connect(remove, &QPushButton::clicked, this, &LoadsPanel::removeSelected);
  connect(list_, &QListWidget::currentRowChanged, this, &LoadsPanel::refresh);
  new ScenePartWatch(
      document_, SceneDocument::Part::kLoads, [this] { refresh(); }, this);
  rule_->followFabric(document_);
  refresh();
}

QString LoadsPanel::message() const {
  return message_->text();
}

void LoadsPanel::setPickedNodes(const std::vector<int>& nodes,
                                const std::vector<std::array<double, 2>>& at) {
  rule_->setPicked(nodes, at);
}

// `with` holds the load at `index`; its force and moment come from the
// typed text, read by the scene reader (so a wrong one gets its message).
bool LoadsPanel::ApplyLoad(int index,
                           const Scene& with,
                           const QString& force,
                           const QString& moment) {
  nlohmann::json document = nlohmann::json::parse(SceneToJson(with).dump());
  document["loads"][index]["force"] = TypedList(force);
  document["loads"][index]["moment"] = TypedList(moment);
  return ApplyOrSay(
      document_,
      message_,
      QString("%1: force (%2)").arg(QString::fromStdString(with.loads[index].name), force),
      document);
}

bool LoadsPanel::add(
    const QString& rule, const QString& force, const QString& moment, double x, double y) {
  QString problem;
  const auto selection = rule_->selection(rule, x, y, &problem);
  if (!selection) {
    message_->setText(problem);
    return false;
  }
  return AddLoad(*selection, force, moment);
}

bool LoadsPanel::AddLoad(const Selection& selection, const QString& force, const QString& moment) {
  Scene with = document_->scene();
  with.loads.push_back({FreeName("load", with.loads), selection, {}, {}});
  if (!ApplyLoad(static_cast<int>(with.loads.size()) - 1, with, force, moment)) return false;
  list_->setCurrentRow(list_->count() - 1);
  return true;
}

bool LoadsPanel::setForce(const QString& force, const QString& moment) {
  const int i = list_->currentRow();
  if (i < 0 || i >= static_cast<int>(document_->scene().loads.size())) return false;
  return ApplyLoad(i, document_->scene(), force, moment);
}

bool LoadsPanel::removeSelected() {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  if (i < 0 || i >= static_cast<int>(after.loads.size())) return false;
  const QString name = QString::fromStdString(after.loads[i].name);
  after.loads.erase(after.loads.begin() + i);
  return ApplyOrSay(document_, message_, "remove " + name, after);
}

void LoadsPanel::setUnitSystem(UnitSystem system) {
  units_ = system;
  rule_->setUnitSystem(system);
  refresh();
}

void LoadsPanel::refresh() {
  const Scene& s = document_->scene();
  const int row = list_->currentRow();
  {
    const QSignalBlocker block(list_);
    list_->clear();
    for (const PointLoad& l : s.loads)
      list_->addItem(
          QString("%1: (%2) on %3")
              .arg(QString::fromStdString(l.name), ListText(l.force, Measure::kForce, units_))
              .arg(DescribeSelection(l.select, units_)));
    if (!s.loads.empty())
      list_->setCurrentRow(std::clamp(row, 0, static_cast<int>(s.loads.size()) - 1));
  }
  const int i = list_->currentRow();
  if (i >= 0) {
    force_->setText(ListText(s.loads[i].force, Measure::kForce, units_));
    moment_->setText(ListText(s.loads[i].moment, Measure::kMoment, units_));
    rule_->show(s.loads[i].select);
  }
}

}  // namespace drape
