#include "ui/widgets/probes_panel.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

#include "core/model/scene.h"
#include "core/model/units.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/typed_json.h"

namespace drape {

ProbesPanel::ProbesPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget(this);
  layout->addWidget(list_, 1);
  auto* form = new QFormLayout;
  at_ = new QLineEdit(this);
  at_->setPlaceholderText("x, y (e.g. 5 cm, 0)");
  form->addRow("at (reference)", at_);
  layout->addLayout(form);
  auto* row = new QHBoxLayout;
  auto* add = new QPushButton("Add", this);
  auto* add_picked = new QPushButton("Add at picked node", this);
  auto* remove = new QPushButton("Remove", this);
  row->addWidget(add);
  row->addWidget(add_picked);
  row->addWidget(remove);
  layout->addLayout(row);
  message_ = MakeMessageLabel(this);
  layout->addWidget(message_);
  connect(add, &QPushButton::clicked, this, [this] {
    try {
      const Vec2 at = TypedPoint(at_->text());
      this->add(at[0], at[1]);
    } catch (const UnitError& e) {
      message_->setText(QString("at: %1").arg(e.what()));
    }
  });
  connect(add_picked, &QPushButton::clicked, this, [this] {
    if (picked_.empty())
      message_->setText("no nodes picked: turn on Pick nodes and click the fabric");
    else
      this->add(picked_.back()[0], picked_.back()[1]);
  });
  connect(remove, &QPushButton::clicked, this, &ProbesPanel::removeSelected);
  new ScenePartWatch(
      document_, SceneDocument::Part::kProbes, [this] { refresh(); }, this);
  refresh();
}

QString ProbesPanel::message() const {
  return message_->text();
}

void ProbesPanel::setPicked(const std::vector<std::array<double, 2>>& at) {
  picked_ = at;
}

bool ProbesPanel::Apply(const QString& what, const Scene& after) {
  return ApplyOrSay(document_, message_, what, after);
}

bool ProbesPanel::add(double x, double y) {
  Scene after = document_->scene();
  after.probes.push_back({FreeName("probe", after.probes), {x, y}});
  if (!Apply(QString("add a probe at (%1)").arg(ListText(Vec2{x, y}, units_)), after)) return false;
  list_->setCurrentRow(list_->count() - 1);
  return true;
}

bool ProbesPanel::removeSelected() {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  if (i < 0 || i >= static_cast<int>(after.probes.size())) return false;
  const QString name = QString::fromStdString(after.probes[i].name);
  after.probes.erase(after.probes.begin() + i);
  return Apply("remove " + name, after);
}

void ProbesPanel::refresh() {
  const Scene& s = document_->scene();
  const int row = list_->currentRow();
  const QSignalBlocker block(list_);
  list_->clear();
  for (const Probe& p : s.probes)
    list_->addItem(
        QString("%1 at (%2)").arg(QString::fromStdString(p.name), ListText(p.at, units_)));
  if (!s.probes.empty())
    list_->setCurrentRow(std::clamp(row, 0, static_cast<int>(s.probes.size()) - 1));
}

void ProbesPanel::setUnitSystem(UnitSystem system) {
  units_ = system;
  // Coordinates being typed are shown in the new unit too; text that does
  // not read stays as typed (Add says what is wrong).
  try {
    at_->setText(ListText(TypedPoint(at_->text()), units_));
  } catch (const UnitError&) {
  }
  refresh();
}

}  // namespace drape
