#include "ui/widgets/obstacles_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <exception>

#include "core/fe/shell_model.h"
#include "core/io/scene_writer.h"
#include "core/model/scene.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/form_editor.h"
#include "ui/widgets/form_placement.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/typed_json.h"

namespace drape {
namespace {

// A new obstacle of `kind` just under a part at z = 0 of about 20 cm.
ObstacleShape DefaultShape(const QString& kind) {
  if (kind == "block") return BoxShape{{-0.05, -0.05, -0.10}, {0.05, 0.05, -0.01}, 0.005};
  if (kind == "rod") return CylinderShape{{0, 0, -0.02}, {0, 1, 0}, 0.01, std::nullopt};
  if (kind == "sphere") return SphereShape{{0, 0, -0.06}, 0.05};
  return PlaneShape{{0, 0, -0.05}, {0, 0, 1}};
}

}  // namespace

ObstaclesPanel::ObstaclesPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  list_ = new QListWidget(this);
  layout->addWidget(list_, 1);
  auto* row = new QHBoxLayout;
  kind_ = new QComboBox(this);
  kind_->addItems({"table", "block", "rod", "sphere"});
  try {
    for (const FormChoice& form : FormCatalogue()) {
      kind_->addItem(form.name, form.file);
      kind_->setItemData(kind_->count() - 1, form.measurements, Qt::ToolTipRole);
    }
  } catch (const std::exception&) {
    // Without the catalogue the shapes are still offered.
  }
  kind_->setToolTip(
      "What to add: a shape placed under the part, or a form stood under it with "
      "the fabric laid on top");
  auto* add = new QPushButton("Add", this);
  auto* remove = new QPushButton("Remove", this);
  row->addWidget(kind_, 1);
  row->addWidget(add);
  row->addWidget(remove);
  layout->addLayout(row);
  form_ = new FormEditor(document_, this);
  layout->addWidget(form_);
  text_label_ = new QLabel(this);
  layout->addWidget(text_label_);
  text_ = new QPlainTextEdit(this);
  text_->setTabChangesFocus(true);
  layout->addWidget(text_, 1);
  auto* apply = new QPushButton("Apply", this);
  layout->addWidget(apply);
  auto* contact = new QFormLayout;
  law_ = new QComboBox(this);
  law_->addItems({"penalty", "barrier"});
  law_->setToolTip(
      "How obstacles push on the fabric (contact.law): penalty, a pressure in proportion to how "
      "far the fabric is inside; barrier, a force that grows without bound as the fabric's "
      "surface nears the obstacle, so it never gets inside (the fabric must start clear of it)");
  penalty_ = new QLineEdit(this);
  penalty_->setToolTip("\"auto\" (from the fabric's stiffness) or a value, e.g. 1e8 N/m^3");
  barrier_ = new QLineEdit(this);
  barrier_->setToolTip(
      "The gap below which the barrier pushes: \"auto\" (half the thickness) or a length, e.g. "
      "0.1 mm");
  friction_ = new QLineEdit(this);
  friction_->setToolTip("Coulomb coefficient μ, 0 for frictionless");
  contact->addRow("contact law", law_);
  contact->addRow("contact penalty", penalty_);
  contact->addRow("barrier distance", barrier_);
  contact->addRow("friction μ", friction_);
  connect(law_, &QComboBox::activated, this, [this] { setContactLaw(law_->currentText()); });
  connect(barrier_, &QLineEdit::editingFinished, this, [this] {
    if (barrier_->text() != barrier_shown_) setBarrierDistance(barrier_->text());
  });
  self_ = new QCheckBox("keep the fabric's layers a thickness apart", this);
  self_->setToolTip(
      "Self-contact (contact.self): where the fabric folds onto itself, a barrier keeps its "
      "layers' mid-surfaces the material's thickness apart, and no step passes through");
  contact->addRow("self-contact", self_);
  connect(self_, &QCheckBox::toggled, this, [this](bool on) {
    if (on != document_->scene().contact.value_or(Contact{}).self) setSelfContact(on);
  });
  layout->addLayout(contact);
  for (QLineEdit* e : {penalty_, friction_})
    connect(e, &QLineEdit::editingFinished, this, [this] {
      if (penalty_->text() != penalty_shown_ || friction_->text() != friction_shown_)
        setContact(penalty_->text(), friction_->text());
    });
  message_ = MakeMessageLabel(this);
  layout->addWidget(message_);
  connect(add, &QPushButton::clicked, this, [this] { this->add(kind_->currentText()); });
  connect(remove, &QPushButton::clicked, this, &ObstaclesPanel::removeSelected);
  connect(apply, &QPushButton::clicked, this, [this] { applyText(text_->toPlainText()); });
  connect(list_, &QListWidget::currentRowChanged, this, &ObstaclesPanel::refresh);
  new ScenePartWatch(
      document_,
      SceneDocument::Part::kObstacles | SceneDocument::Part::kContact,
      [this] { refresh(); },
      this);
  refresh();
}

QString ObstaclesPanel::message() const {
  return message_->text();
}

bool ObstaclesPanel::Apply(const QString& what, const Scene& after) {
  return ApplyOrSay(document_, message_, what, after);
}

bool ObstaclesPanel::add(const QString& kind) {
  const int form = kind_->findText(kind);
  if (form >= 0 && !kind_->itemData(form).isNull()) return AddForm(form);
  Scene after = document_->scene();
  after.obstacles.push_back({FreeName(kind.toStdString(), after.obstacles), DefaultShape(kind)});
  if (!Apply("add a " + kind, after)) return false;
  list_->setCurrentRow(list_->count() - 1);
  return true;
}

// A form stands on the floor under the fabric's middle and the fabric is
// laid on it: one edit.
bool ObstaclesPanel::AddForm(int item) {
  const auto& model = document_->model();
  if (!model) return false;
  const FormChoice form{kind_->itemText(item), kind_->itemData(item).toString(), {}};
  Scene after = WithForm(document_->scene(), model->mesh, form);
  QString why;
  const auto above = FabricAbove(after,
                                 model->mesh,
                                 static_cast<int>(after.obstacles.size()) - 1,
                                 document_->directory(),
                                 &why);
  if (!above) {
    message_->setText(why);
    return false;
  }
  if (!Apply("add " + form.name + ", the fabric laid on it", *above)) return false;
  list_->setCurrentRow(list_->count() - 1);
  return true;
}

bool ObstaclesPanel::removeSelected() {
  const int i = list_->currentRow();
  Scene after = document_->scene();
  if (i < 0 || i >= static_cast<int>(after.obstacles.size())) return false;
  const QString name = QString::fromStdString(after.obstacles[i].name);
  after.obstacles.erase(after.obstacles.begin() + i);
  return Apply("remove " + name, after);
}

bool ObstaclesPanel::applyText(const QString& text) {
  const int i = list_->currentRow();
  if (i < 0 || i >= static_cast<int>(document_->scene().obstacles.size())) return false;
  nlohmann::json document = document_->json();
  try {
    document["obstacles"][i] = nlohmann::json::parse(text.toStdString());
  } catch (const nlohmann::json::parse_error& e) {
    message_->setText(QString("not JSON: %1").arg(e.what()));
    return false;
  }
  return ApplyOrSay(document_,
                    message_,
                    "edit " + QString::fromStdString(document_->scene().obstacles[i].name),
                    document);
}

bool ObstaclesPanel::ApplyContact(const QString& what, nlohmann::json document) {
  const bool done = ApplyOrSay(document_, message_, what, std::move(document));
  if (!done) refresh();  // the fields show the scene's values again
  return done;
}

bool ObstaclesPanel::setContact(const QString& penalty, const QString& friction) {
  nlohmann::json document = document_->json();
  // The other contact keys (law, self-contact) stay as they are.
  const bool barrier = document_->scene().contact.value_or(Contact{}).law == ContactLaw::kBarrier;
  if (!barrier)
    document["contact"]["penalty"] =
        penalty.trimmed() == "auto" ? nlohmann::json("auto") : TypedQuantity(penalty);
  document["contact"]["friction"] = TypedQuantity(friction);
  return ApplyContact(barrier ? QString("contact: friction %1").arg(friction)
                              : QString("contact: penalty %1, friction %2").arg(penalty, friction),
                      document);
}

bool ObstaclesPanel::setContactLaw(const QString& law) {
  nlohmann::json document = document_->json();
  nlohmann::json& contact = document["contact"];
  contact["law"] = law.toStdString();
  // Each law's own setting goes with it.
  if (law == "barrier") {
    contact.erase("penalty");
  } else {
    contact.erase("barrier_distance");
    if (!contact.contains("penalty")) contact["penalty"] = "auto";
  }
  return ApplyContact("contact law: " + law, document);
}

bool ObstaclesPanel::setBarrierDistance(const QString& distance) {
  nlohmann::json document = document_->json();
  if (distance.trimmed() == "auto")
    document["contact"].erase("barrier_distance");
  else
    document["contact"]["barrier_distance"] = TypedQuantity(distance);
  return ApplyContact("barrier distance " + distance, document);
}

bool ObstaclesPanel::setSelfContact(bool on) {
  nlohmann::json document = document_->json();
  document["contact"]["self"] = on;
  const bool done =
      ApplyOrSay(document_, message_, on ? "self-contact on" : "self-contact off", document);
  if (!done) refresh();
  return done;
}

void ObstaclesPanel::refresh() {
  const Scene& s = document_->scene();
  const int row = list_->currentRow();
  {
    const QSignalBlocker block(list_);  // rebuilding the list is not a selection
    list_->clear();
    const auto json = SceneToJson(s);
    for (size_t k = 0; k < s.obstacles.size(); ++k) {
      const auto& o = json["obstacles"][k];
      QString kind = "mesh";
      for (const char* shape : {"plane", "box", "cylinder", "sphere"})
        if (o.contains(shape)) kind = shape;
      list_->addItem(QString("%1 (%2)").arg(QString::fromStdString(s.obstacles[k].name), kind));
    }
    if (!s.obstacles.empty())
      list_->setCurrentRow(std::clamp(row, 0, static_cast<int>(s.obstacles.size()) - 1));
  }
  ShowText();
  ShowContact();
  form_->setObstacle(list_->currentRow());
  emit obstacleSelected(list_->currentRow());
}

void ObstaclesPanel::setUnitSystem(UnitSystem system) {
  units_ = system;
  form_->setUnitSystem(system);
  ShowText();
  ShowContact();
}

void ObstaclesPanel::ShowText() {
  const int i = list_->currentRow();
  const Scene& s = document_->scene();
  const bool any = i >= 0 && i < static_cast<int>(s.obstacles.size());
  text_->setPlainText(any ? QString::fromStdString(
                                FormatJson(ObstacleInUnits(SceneToJson(s)["obstacles"][i], units_)))
                          : QString());
  text_->setEnabled(any);
  text_label_->setText(
      QString("The selected obstacle as the scene file writes it (lengths in %1; any unit):")
          .arg(QString::fromStdString(UnitFor(Measure::kLength, units_).label)));
}

void ObstaclesPanel::ShowContact() {
  const Contact contact = document_->scene().contact.value_or(Contact{});
  penalty_shown_ = contact.penalty
                       ? QuantityText(*contact.penalty, Measure::kPenaltyPerArea, units_)
                       : QString("auto");
  barrier_shown_ = contact.barrier_distance
                       ? QuantityText(*contact.barrier_distance, Measure::kLength, units_)
                       : QString("auto");
  friction_shown_ = QString::number(contact.friction);
  penalty_->setText(penalty_shown_);
  barrier_->setText(barrier_shown_);
  friction_->setText(friction_shown_);
  const bool barrier = contact.law == ContactLaw::kBarrier;
  {
    const QSignalBlocker block(law_);
    law_->setCurrentIndex(barrier ? 1 : 0);
  }
  penalty_->setEnabled(!barrier);
  barrier_->setEnabled(barrier);
  const QSignalBlocker block(self_);
  self_->setChecked(contact.self);
}

}  // namespace drape
