#include "ui/widgets/form_editor.h"

#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <exception>
#include <variant>

#include "core/fe/shell_model.h"
#include "core/model/scene_error.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/form_placement.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/typed_json.h"

namespace drape {
namespace {

const MeshShape* MeshAt(const Scene& scene, int index) {
  if (index < 0 || index >= static_cast<int>(scene.obstacles.size())) return nullptr;
  return std::get_if<MeshShape>(&scene.obstacles[index].shape);
}

}  // namespace

FormEditor::FormEditor(SceneDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* form = new QFormLayout;
  at_ = new QLineEdit(this);
  at_->setToolTip(
      "Where the form's origin stands (its base's middle for the dress form): x, y, z, in any "
      "unit, e.g. \"10 cm, 0, 0\" (mesh.at)");
  turn_ = new QLineEdit(this);
  turn_->setToolTip(
      "A turn about the vertical, in degrees or with a unit, e.g. \"90\" or "
      "\"1.2 rad\" (mesh.rotation_deg)");
  scale_ = new QLineEdit(this);
  scale_->setToolTip(
      "One factor for every direction, e.g. \"1.05\", or one per axis, "
      "\"1, 1, 1.1\"; a file drawn in millimetres takes 0.001 (mesh.scale)");
  form->addRow("stands at", at_);
  form->addRow("turned by (deg)", turn_);
  form->addRow("scale", scale_);
  layout->addLayout(form);
  lay_ = new QPushButton("Lay the fabric on it", this);
  lay_->setToolTip(
      "Puts the flat fabric just above the form: lowered straight down, where it first comes "
      "within a small gap of it (the fabric's elevation)");
  layout->addWidget(lay_);
  message_ = MakeMessageLabel(this);
  layout->addWidget(message_);
  for (QLineEdit* e : {at_, turn_, scale_})
    connect(e, &QLineEdit::editingFinished, this, [this] {
      place(at_->text(), turn_->text(), scale_->text());
    });
  connect(lay_, &QPushButton::clicked, this, &FormEditor::layFabricOn);
  new ScenePartWatch(
      document_,
      SceneDocument::Part::kObstacles | SceneDocument::Part::kFabric,
      [this] { Show(); },
      this);
  setObstacle(-1);
}

QString FormEditor::message() const {
  return message_->text();
}

void FormEditor::setObstacle(int index) {
  index_ = index;
  message_->clear();
  Show();
}

void FormEditor::setUnitSystem(UnitSystem system) {
  units_ = system;
  Show();
}

void FormEditor::Show() {
  const MeshShape* mesh = MeshAt(document_->scene(), index_);
  setVisible(mesh != nullptr);
  if (!mesh) return;
  const QSignalBlocker a(at_), t(turn_), s(scale_);
  at_->setText(ListText(mesh->at, units_));
  turn_->setText(QString::number(mesh->rotation_deg, 'g', 10));
  const Vec3& k = mesh->scale;
  scale_->setText(k[0] == k[1] && k[1] == k[2] ? QString::number(k[0], 'g', 10)
                                               : QString("%1, %2, %3")
                                                     .arg(k[0], 0, 'g', 10)
                                                     .arg(k[1], 0, 'g', 10)
                                                     .arg(k[2], 0, 'g', 10));
}

bool FormEditor::ApplyPlaced(const QString& what, const Scene& after) {
  const auto& model = document_->model();
  const Scene placed =
      model
          ? FollowingTheForm(document_->scene(), after, model->mesh, index_, document_->directory())
          : after;
  return ApplyOrSay(document_, message_, what, placed);
}

bool FormEditor::place(const QString& at, const QString& turn, const QString& scale) {
  if (!MeshAt(document_->scene(), index_)) return false;
  nlohmann::json document = document_->json();
  nlohmann::json& mesh = document["obstacles"][index_]["mesh"];
  mesh["at"] = TypedList(at);
  mesh["rotation_deg"] = TypedQuantity(turn);
  mesh["scale"] = scale.contains(',') ? TypedList(scale) : TypedQuantity(scale);
  Scene after;
  try {
    after = document_->parse(document);
  } catch (const std::exception& e) {
    const QString name = QString::fromStdString(document_->scene().obstacles[index_].name);
    message_->setText("place " + name + " — " + QString::fromStdString(e.what()));
    Show();  // the fields show the form as it is
    return false;
  }
  if (after == document_->scene()) return true;
  const QString name = QString::fromStdString(after.obstacles[index_].name);
  const bool done = ApplyPlaced("place " + name, after);
  if (!done) Show();
  return done;
}

bool FormEditor::layFabricOn() {
  const auto& model = document_->model();
  if (!MeshAt(document_->scene(), index_) || !model) return false;
  QString why;
  const auto above =
      FabricAbove(document_->scene(), model->mesh, index_, document_->directory(), &why);
  if (!above) {
    message_->setText(why);
    return false;
  }
  return ApplyOrSay(
      document_,
      message_,
      "lay the fabric on " + QString::fromStdString(document_->scene().obstacles[index_].name),
      *above);
}

}  // namespace drape
