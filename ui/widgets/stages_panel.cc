#include "ui/widgets/stages_panel.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>

#include "core/model/scene.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/move_editor.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"

namespace drape {

StagesPanel::StagesPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget(this);
  layout->addWidget(list_, 1);
  auto* buttons = new QHBoxLayout;
  auto* up = new QPushButton("Up", this);
  auto* down = new QPushButton("Down", this);
  auto* remove = new QPushButton("Remove", this);
  new_kind_ = new QComboBox(this);
  for (StageKind k : {StageKind::kGravity, StageKind::kLoad, StageKind::kMove, StageKind::kHold})
    new_kind_->addItem(ToString(k));
  auto* add = new QPushButton("Add stage", this);
  buttons->addWidget(new_kind_);
  buttons->addWidget(add);
  buttons->addWidget(up);
  buttons->addWidget(down);
  buttons->addWidget(remove);
  layout->addLayout(buttons);
  auto* form = new QFormLayout;
  increment_ = new QDoubleSpinBox(this);
  increment_->setDecimals(8);
  increment_->setRange(1e-8, 1.0);
  increment_->setSingleStep(0.001);
  control_ = new QComboBox(this);
  control_->addItems({"arc length (passes limit points)", "load (plain Newton)"});
  increment_->setToolTip(
      "The first step's share of the stage (Δλ₀, initial_increment): 0.01 is 1 % of the "
      "stage's load or motion; later steps grow or shrink as the part allows");
  control_->setToolTip(
      "How steps are measured (control): along the path of the part's shape and the load "
      "together (arc length), which follows a part past where it gives way; or by the load "
      "alone (plain Newton), which stops there");
  form->addRow("first step", increment_);
  form->addRow("step by", control_);
  release_ = new QLineEdit(this);
  release_->setPlaceholderText("gripper names, comma separated");
  form->addRow("releases", release_);
  layout->addLayout(form);
  moves_ = new MoveEditor(document_, this);
  layout->addWidget(moves_);
  message_ = MakeMessageLabel(this);
  layout->addWidget(message_);
  connect(up, &QPushButton::clicked, this, [this] { moveSelected(-1); });
  connect(down, &QPushButton::clicked, this, [this] { moveSelected(1); });
  connect(remove, &QPushButton::clicked, this, &StagesPanel::removeSelected);
  connect(add, &QPushButton::clicked, this, [this] { addStage(new_kind_->currentText()); });
  connect(release_, &QLineEdit::editingFinished, this, [this] {
    if (!refreshing_) setRelease(release_->text());
  });
  connect(increment_, &QDoubleSpinBox::editingFinished, this, [this] {
    setIncrement(increment_->value());
  });
  connect(control_, &QComboBox::activated, this, &StagesPanel::setControl);
  connect(list_, &QListWidget::currentRowChanged, this, &StagesPanel::refresh);
  new ScenePartWatch(
      document_, SceneDocument::Part::kStages, [this] { refresh(); }, this);
  refresh();
}

QString StagesPanel::message() const {
  return message_->text();
}

bool StagesPanel::Apply(const QString& what, const Scene& after) {
  return ApplyOrSay(document_, message_, what, after);
}

bool StagesPanel::addStage(const QString& kind) {
  Scene after = document_->scene();
  Stage stage;
  stage.name = FreeName("stage", after.stages);
  const auto known = {StageKind::kGravity, StageKind::kLoad, StageKind::kMove, StageKind::kHold};
  const auto it =
      std::find_if(known.begin(), known.end(), [&](StageKind k) { return kind == ToString(k); });
  if (it == known.end()) return false;
  stage.kind = *it;
  if (stage.kind == StageKind::kMove) {
    if (after.grippers.empty()) {
      message_->setText("a move stage carries a gripper: add a gripper first");
      return false;
    }
    stage.moves.push_back({after.grippers.front().name, LinePath{{0, 0, 0.05}}, ""});
  }
  after.stages.push_back(stage);
  if (!Apply(QString("add %1 stage").arg(kind), after)) return false;
  list_->setCurrentRow(list_->count() - 1);
  return true;
}

bool StagesPanel::setRelease(const QString& names) {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  if (i < 0 || i >= static_cast<int>(after.stages.size())) return false;
  after.stages[i].release.clear();
  for (const QString& name : names.split(',', Qt::SkipEmptyParts))
    after.stages[i].release.push_back(name.trimmed().toStdString());
  return Apply(QString("%1 releases %2").arg(QString::fromStdString(after.stages[i].name), names),
               after);
}

bool StagesPanel::moveSelected(int by) {
  const int i = list_->currentRow(), j = i + by;
  Scene after = document_->scene();
  if (i < 0 || j < 0 || j >= static_cast<int>(after.stages.size())) return false;
  std::swap(after.stages[i], after.stages[j]);
  if (!Apply(QString("move stage %1").arg(QString::fromStdString(after.stages[j].name)), after))
    return false;
  list_->setCurrentRow(j);
  return true;
}

bool StagesPanel::removeSelected() {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  if (i < 0 || i >= static_cast<int>(after.stages.size())) return false;
  const QString name = QString::fromStdString(after.stages[i].name);
  after.stages.erase(after.stages.begin() + i);
  return Apply("remove stage " + name, after);
}

bool StagesPanel::setIncrement(double value) {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  if (refreshing_ || i < 0 || i >= static_cast<int>(after.stages.size())) return false;
  after.stages[i].initial_increment = value;
  return Apply(
      QString("first step of %1: %2").arg(QString::fromStdString(after.stages[i].name)).arg(value),
      after);
}

bool StagesPanel::setControl(int index) {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  if (refreshing_ || i < 0 || i >= static_cast<int>(after.stages.size())) return false;
  after.stages[i].control = index == 0 ? StepControl::kArcLength : StepControl::kLoad;
  return Apply(QString("control of %1").arg(QString::fromStdString(after.stages[i].name)), after);
}

void StagesPanel::refresh() {
  refreshing_ = true;
  const Scene& s = document_->scene();
  const int row = std::max(0, list_->currentRow());
  const QSignalBlocker block(list_);  // rebuilding the list is not a selection
  if (list_->count() != static_cast<int>(s.stages.size())) list_->clear();
  for (size_t k = 0; k < s.stages.size(); ++k) {
    const Stage& st = s.stages[k];
    QString text = QString("%1. %2 (%3")
                       .arg(k + 1)
                       .arg(QString::fromStdString(st.name))
                       .arg(ToString(st.kind));
    if (!st.moves.empty()) text += QString(", %1 moves").arg(st.moves.size());
    if (!st.release.empty()) text += ", releases";
    text += ")";
    if (static_cast<int>(k) < list_->count())
      list_->item(static_cast<int>(k))->setText(text);
    else
      list_->addItem(text);
  }
  if (!s.stages.empty()) {
    const int i = std::min(row, static_cast<int>(s.stages.size()) - 1);
    if (list_->currentRow() != i) list_->setCurrentRow(i);
    increment_->setValue(s.stages[i].initial_increment);
    control_->setCurrentIndex(s.stages[i].control == StepControl::kArcLength ? 0 : 1);
    QStringList release;
    for (const auto& name : s.stages[i].release) release << QString::fromStdString(name);
    release_->setText(release.join(", "));
  }
  moves_->setStage(s.stages.empty() ? -1 : list_->currentRow());
  refreshing_ = false;
}

}  // namespace drape
