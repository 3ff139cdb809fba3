#include "ui/widgets/move_editor.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>
#include <nlohmann/json.hpp>

#include "core/model/overloaded.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/typed_json.h"

namespace drape {
namespace {

QString KindOf(const Path& path) {
  return std::visit(Overloaded{[](const LinePath&) { return QString("line"); },
                               [](const ArcPath&) { return QString("arc"); },
                               [](const KeyframesPath&) { return QString("keyframes"); }},
                    path);
}

QString Describe(const Move& m, UnitSystem units) {
  const QString what = m.gripper.empty() ? "obstacle " + QString::fromStdString(m.obstacle)
                                         : QString::fromStdString(m.gripper);
  return std::visit(
      Overloaded{[&](const LinePath& p) {
                   return QString("%1: line by (%2)").arg(what, ListText(p.by, units));
                 },
                 [&](const ArcPath& p) {
                   return QString("%1: arc %2° about (%3)")
                       .arg(what)
                       .arg(p.angle_deg)
                       .arg(ListText(p.axis));
                 },
                 [&](const KeyframesPath& p) {
                   return QString("%1: %2 keyframes").arg(what).arg(p.points.size());
                 }},
      m.path);
}

}  // namespace

MoveEditor::MoveEditor(SceneDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  list_ = new QListWidget(this);
  list_->setMaximumHeight(90);
  layout->addWidget(new QLabel("Moves of the stage (drag their handles in the view):", this));
  layout->addWidget(list_);
  auto* row = new QHBoxLayout;
  carried_ = new QComboBox(this);
  carried_->setToolTip("what the new move carries: a gripper or an obstacle");
  auto* add = new QPushButton("Add move", this);
  auto* remove = new QPushButton("Remove move", this);
  row->addWidget(carried_, 1);
  row->addWidget(add);
  row->addWidget(remove);
  layout->addLayout(row);
  form_ = new QFormLayout;
  kind_ = new QComboBox(this);
  kind_->addItems({"line", "arc", "keyframes"});
  first_ = new QLineEdit(this);
  second_ = new QLineEdit(this);
  third_ = new QLineEdit(this);
  form_->addRow("path", kind_);
  form_->addRow("by", first_);
  form_->addRow("axis", second_);
  form_->addRow("angle", third_);
  layout->addLayout(form_);
  message_ = MakeMessageLabel(this);
  layout->addWidget(message_);
  connect(add, &QPushButton::clicked, this, [this] { addMove(carried_->currentText()); });
  connect(remove, &QPushButton::clicked, this, &MoveEditor::removeSelected);
  connect(kind_, &QComboBox::activated, this, [this] {
    // A new kind starts from a path of that kind at the fields' defaults.
    const QString kind = kind_->currentText();
    if (kind == "line")
      setPath(kind, "0, 0, 5 cm");
    else if (kind == "arc")
      setPath(kind, "0, 0, 0", "0, 1, 0", "90");
    else
      setPath(kind, "0, 0, 5 cm; 5 cm, 0, 5 cm", "smooth");
  });
  for (QLineEdit* e : {first_, second_, third_})
    connect(e, &QLineEdit::editingFinished, this, &MoveEditor::CommitFields);
  connect(list_, &QListWidget::currentRowChanged, this, &MoveEditor::refresh);
  // What a move carries is chosen from the grippers and the obstacles.
  new ScenePartWatch(
      document_,
      SceneDocument::Part::kStages | SceneDocument::Part::kGrippers |
          SceneDocument::Part::kObstacles,
      [this] { refresh(); },
      this);
  refresh();
}

QString MoveEditor::message() const {
  return message_->text();
}

int MoveEditor::currentMove() const {
  return list_->currentRow();
}

void MoveEditor::setStage(int stage) {
  if (stage == stage_) return;
  stage_ = stage;
  const QSignalBlocker block(list_);
  list_->clear();
  refresh();
}

bool MoveEditor::Apply(const QString& what, const Scene& after) {
  return ApplyOrSay(document_, message_, what, after);
}

bool MoveEditor::addMove(const QString& carried) {
  Scene after = document_->scene();
  if (stage_ < 0 || stage_ >= static_cast<int>(after.stages.size()) || carried.isEmpty())
    return false;
  Move move;
  if (carried.startsWith("obstacle "))
    move.obstacle = carried.mid(9).toStdString();
  else
    move.gripper = carried.toStdString();
  move.path = LinePath{{0, 0, 0.05}};
  after.stages[stage_].moves.push_back(move);
  if (!Apply("add a move of " + carried, after)) return false;
  list_->setCurrentRow(list_->count() - 1);
  return true;
}

bool MoveEditor::removeSelected() {
  Scene after = document_->scene();
  const int m = currentMove();
  if (stage_ < 0 || stage_ >= static_cast<int>(after.stages.size()) || m < 0 ||
      m >= static_cast<int>(after.stages[stage_].moves.size()))
    return false;
  after.stages[stage_].moves.erase(after.stages[stage_].moves.begin() + m);
  return Apply("remove a move", after);
}

bool MoveEditor::setPath(const QString& kind,
                         const QString& first,
                         const QString& second,
                         const QString& third) {
  const Scene& scene = document_->scene();
  const int m = currentMove();
  if (stage_ < 0 || stage_ >= static_cast<int>(scene.stages.size()) || m < 0 ||
      m >= static_cast<int>(scene.stages[stage_].moves.size()))
    return false;
  nlohmann::json path;
  if (kind == "line") {
    path["line"] = {{"by", TypedList(first)}};
  } else if (kind == "arc") {
    path["arc"] = {{"center", TypedList(first)},
                   {"axis", TypedList(second)},
                   {"angle_deg", TypedQuantity(third)}};
  } else if (kind == "keyframes") {
    path["keyframes"] = {
        {"points", TypedLists(first)},
        {"interpolation", second.trimmed().isEmpty() ? "linear" : second.trimmed().toStdString()}};
  } else {
    return false;
  }
  // The scene reader reads the path, so a wrong one gets its message (with
  // the key's place: stages[i].moves[j].path…).
  nlohmann::json document = document_->json();
  document["stages"][stage_]["moves"][m]["path"] = path;
  return ApplyOrSay(document_,
                    message_,
                    QString("%1 path of a move of stage %2").arg(kind).arg(stage_ + 1),
                    document);
}

void MoveEditor::CommitFields() {
  if (refreshing_) return;
  setPath(kind_->currentText(), first_->text(), second_->text(), third_->text());
}

void MoveEditor::ShowKind(const QString& kind) {
  const bool arc = kind == "arc", keys = kind == "keyframes";
  auto label = [&](QWidget* field, const QString& text) {
    if (auto* l = qobject_cast<QLabel*>(form_->labelForField(field))) l->setText(text);
  };
  label(first_, arc ? "centre" : keys ? "points" : "by");  // the values carry their units
  label(second_, keys ? "interpolation" : "axis");
  label(third_, "angle [deg]");
  form_->setRowVisible(second_, arc || keys);
  form_->setRowVisible(third_, arc);
  first_->setToolTip(keys ? "offsets from the start, \"x, y, z; x, y, z\"; units allowed (5 cm)"
                          : "x, y, z; units allowed (5 cm)");
}

void MoveEditor::setUnitSystem(UnitSystem system) {
  units_ = system;
  refresh();
}

void MoveEditor::refresh() {
  refreshing_ = true;
  const Scene& scene = document_->scene();
  carried_->clear();
  for (const Gripper& g : scene.grippers) carried_->addItem(QString::fromStdString(g.name));
  for (const Obstacle& o : scene.obstacles)
    carried_->addItem("obstacle " + QString::fromStdString(o.name));
  const bool valid = stage_ >= 0 && stage_ < static_cast<int>(scene.stages.size());
  const std::vector<Move> none;
  const auto& moves = valid ? scene.stages[stage_].moves : none;
  const int row = list_->currentRow();
  {
    const QSignalBlocker block(list_);
    list_->clear();
    for (const Move& m : moves) list_->addItem(Describe(m, units_));
    if (!moves.empty())
      list_->setCurrentRow(std::clamp(row, 0, static_cast<int>(moves.size()) - 1));
  }
  const int m = list_->currentRow();
  for (QWidget* w : std::initializer_list<QWidget*>{kind_, first_, second_, third_})
    w->setEnabled(m >= 0);
  if (m >= 0) {
    const Path& path = moves[m].path;
    kind_->setCurrentText(KindOf(path));
    ShowKind(KindOf(path));
    std::visit(Overloaded{[&](const LinePath& p) { first_->setText(ListText(p.by, units_)); },
                          [&](const ArcPath& p) {
                            first_->setText(ListText(p.center, units_));
                            second_->setText(ListText(p.axis));
                            third_->setText(QString::number(p.angle_deg));
                          },
                          [&](const KeyframesPath& p) {
                            QStringList points;
                            for (const Vec3& v : p.points) points << ListText(v, units_);
                            first_->setText(points.join("; "));
                            second_->setText(ToString(p.interpolation));
                          }},
               path);
  }
  refreshing_ = false;
  emit moveSelected(valid && m >= 0 ? stage_ : -1, m);
}

}  // namespace drape
