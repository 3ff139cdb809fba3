#include "ui/widgets/fabric_editor.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

#include <nlohmann/json.hpp>

#include "core/model/overloaded.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/imperfection_editor.h"
#include "ui/widgets/mesh_summary.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/typed_json.h"

namespace drape {

FabricEditor::FabricEditor(SceneDocument* document, QWidget* parent)
    : QGroupBox("Fabric", parent), document_(document) {
  form_ = new QFormLayout(this);
  shape_ = new QComboBox(this);
  shape_->addItems({"rectangle", "disk", "polygon"});
  extent_ = new QLineEdit(this);
  center_ = new QLineEdit(this);
  element_size_ = new QLineEdit(this);
  element_size_->setToolTip("target element edge, e.g. 1 cm");
  nx_ = new QSpinBox(this);
  ny_ = new QSpinBox(this);
  for (QSpinBox* s : {nx_, ny_}) s->setRange(1, 400);
  message_ = MakeMessageLabel(this);
  imperfection_ = new ImperfectionEditor(document_, message_, this);
  mesh_info_ = new MeshSummary(document_, this);
  form_->addRow("outline", shape_);
  form_->addRow("size", extent_);
  form_->addRow("centre", center_);
  form_->addRow("elements along x", nx_);
  form_->addRow("elements along y", ny_);
  form_->addRow("element size", element_size_);
  form_->addRow("imperfection", imperfection_);
  form_->addRow(mesh_info_);
  form_->addRow(message_);
  ConnectFields();
  new ScenePartWatch(
      document_, SceneDocument::Part::kFabric, [this] { refresh(); }, this);
  refresh();
}

void FabricEditor::ConnectFields() {
  for (QSpinBox* s : {nx_, ny_})
    connect(s, &QSpinBox::editingFinished, this, &FabricEditor::EditMesh);
  connect(shape_, &QComboBox::activated, this, [this] {
    // Another shape starts from a part of about the same size.
    const QString shape = shape_->currentText();
    if (shape == "rectangle")
      setOutline(shape, "20 cm, 20 cm");
    else if (shape == "disk")
      setOutline(shape, "10 cm");
    else
      setOutline(shape, "-10 cm, -10 cm; 10 cm, -10 cm; 0, 10 cm");
  });
  for (QLineEdit* e : {extent_, center_})
    connect(e, &QLineEdit::editingFinished, this, [this] {
      if (!refreshing_) setOutline(shape_->currentText(), extent_->text(), center_->text());
    });
  connect(element_size_, &QLineEdit::editingFinished, this, [this] {
    if (!refreshing_) setElementSize(element_size_->text());
  });
}

QString FabricEditor::message() const {
  return message_->text();
}

bool FabricEditor::ApplyFabric(const QString& what, const nlohmann::json& fabric) {
  // The scene reader reads the fabric, so wrong text gets its message.
  nlohmann::json document = document_->json();
  document["fabric"] = fabric;
  const bool done = ApplyOrSay(document_, message_, what, document);
  if (!done) refresh();  // the fields show the scene's fabric again
  return done;
}

bool FabricEditor::setOutline(const QString& shape, const QString& extent, const QString& center) {
  nlohmann::json fabric = document_->json()["fabric"];
  nlohmann::json outline;
  if (shape == "rectangle") {
    outline["rectangle"] = {{"size", TypedList(extent)}, {"center", TypedList(center)}};
  } else if (shape == "disk") {
    outline["disk"] = {{"radius", TypedQuantity(extent)}, {"center", TypedList(center)}};
  } else if (shape == "polygon") {
    outline["polygon"] = TypedLists(extent);
  } else {
    return false;
  }
  const bool was_rectangle = fabric["outline"].contains("rectangle");
  fabric["outline"] = outline;
  // Element counts are for rectangles; other shapes are meshed by size.
  if (shape != "rectangle" && fabric["mesh"].contains("elements")) {
    fabric["mesh"].erase("elements");
    if (!fabric["mesh"].contains("size")) fabric["mesh"]["size"] = 0.01;
  }
  if (shape == "rectangle" && !was_rectangle && !fabric["mesh"].contains("elements"))
    fabric["mesh"] = {{"elements", {20, 20}}};
  return ApplyFabric(QString("%1 outline %2").arg(shape, extent), fabric);
}

bool FabricEditor::setElementSize(const QString& size) {
  nlohmann::json fabric = document_->json()["fabric"];
  fabric["mesh"] = {{"size", TypedQuantity(size)}};
  return ApplyFabric("element size " + size, fabric);
}

void FabricEditor::EditMesh() {
  if (refreshing_) return;
  Scene after = document_->scene();
  after.fabric.mesh.elements = std::array<int, 2>{nx_->value(), ny_->value()};
  document_->apply(QString("mesh %1 × %2").arg(nx_->value()).arg(ny_->value()), after);
}

void FabricEditor::setUnitSystem(UnitSystem system) {
  units_ = system;
  imperfection_->setUnitSystem(system);
  refresh();
}

void FabricEditor::ShowOutline() {
  const Outline& outline = document_->scene().fabric.outline;
  // A pattern piece comes from its file (File ▸ Import pattern…): shown,
  // not typed.
  const bool pattern = std::holds_alternative<PatternOutline>(outline);
  const int pattern_item = shape_->findText("pattern");
  if (pattern && pattern_item < 0) shape_->addItem("pattern");
  if (!pattern && pattern_item >= 0) shape_->removeItem(pattern_item);
  extent_->setReadOnly(pattern);
  std::visit(Overloaded{[&](const RectangleOutline& r) {
                          shape_->setCurrentText("rectangle");
                          extent_->setText(ListText(r.size, units_));
                          center_->setText(ListText(r.center, units_));
                        },
                        [&](const DiskOutline& d) {
                          shape_->setCurrentText("disk");
                          extent_->setText(QuantityText(d.radius, Measure::kLength, units_));
                          center_->setText(ListText(d.center, units_));
                        },
                        [&](const PolygonOutline& p) {
                          shape_->setCurrentText("polygon");
                          QStringList vertices;
                          for (const Vec2& v : p.vertices) vertices << ListText(v, units_);
                          extent_->setText(vertices.join("; "));
                        },
                        [&](const PatternOutline& p) {
                          shape_->setCurrentText("pattern");
                          extent_->setText(QString("%1 in %2")
                                               .arg(QString::fromStdString(p.piece),
                                                    QString::fromStdString(p.file)));
                        }},
             outline);
  if (auto* label = qobject_cast<QLabel*>(form_->labelForField(extent_)))
    label->setText(std::holds_alternative<RectangleOutline>(outline) ? "size"
                   : std::holds_alternative<DiskOutline>(outline)    ? "radius"
                   : pattern                                         ? "piece"
                                                                     : "vertices");
  form_->setRowVisible(center_, !std::holds_alternative<PolygonOutline>(outline) && !pattern);
}

void FabricEditor::refresh() {
  refreshing_ = true;
  const Fabric& fabric = document_->scene().fabric;
  ShowOutline();
  const bool by_count =
      std::holds_alternative<RectangleOutline>(fabric.outline) && fabric.mesh.elements.has_value();
  form_->setRowVisible(nx_, by_count);
  form_->setRowVisible(ny_, by_count);
  form_->setRowVisible(element_size_, !by_count);
  if (fabric.mesh.elements) {
    nx_->setValue((*fabric.mesh.elements)[0]);
    ny_->setValue((*fabric.mesh.elements)[1]);
  }
  element_size_->setText(
      fabric.mesh.size ? QuantityText(*fabric.mesh.size, Measure::kLength, units_) : QString());
  refreshing_ = false;
}

}  // namespace drape
