#include "ui/widgets/property_panel.h"

#include <QVBoxLayout>

namespace drape {

PropertyPanel::PropertyPanel(SceneDocument* document, QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  fabric_ = new FabricEditor(document, this);
  material_ = new MaterialEditor(document, this);
  // The solver group has no message line of its own: a refused solver edit
  // is said under the material, as before the groups were split.
  solver_ = new SolverEditor(document, material_->messageLabel(), this);
  layout->addWidget(fabric_);
  layout->addWidget(material_);
  layout->addWidget(solver_);
  layout->addStretch(1);
}

void PropertyPanel::setUnitSystem(UnitSystem system) {
  if (system == units_) return;
  units_ = system;
  fabric_->setUnitSystem(system);
  material_->setUnitSystem(system);
}

void PropertyPanel::refresh() {
  fabric_->refresh();
  fabric_->imperfection()->refresh();
  fabric_->meshInfo()->refresh();
  material_->refresh();
  solver_->refresh();
}

}  // namespace drape
