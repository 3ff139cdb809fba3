// Property editors for the scene's fabric, material and solver, one group
// each (FabricEditor, MaterialEditor, SolverEditor), arranged one above the
// other. Each field shows its unit, is checked as it is committed (the same
// unit parser and limits as the scene reader), shows what is wrong in place
// and keeps its last valid value; every accepted change goes to the
// SceneDocument as one undoable edit, and each group redraws only when its
// part of the scene changed.
#pragma once

#include <QWidget>

#include <memory>

#include "core/fe/shell_model.h"
#include "core/model/unit_system.h"
#include "ui/widgets/fabric_editor.h"
#include "ui/widgets/imperfection_editor.h"
#include "ui/widgets/material_editor.h"
#include "ui/widgets/mesh_summary.h"
#include "ui/widgets/quantity_field.h"
#include "ui/widgets/solver_editor.h"

namespace drape {

class SceneDocument;

class PropertyPanel : public QWidget {
  Q_OBJECT
 public:
  explicit PropertyPanel(SceneDocument* document, QWidget* parent = nullptr);

  FabricEditor* fabric() const { return fabric_; }
  MaterialEditor* material() const { return material_; }
  SolverEditor* solver() const { return solver_; }

  // For tests and scripts: the fields by name.
  QuantityField* thickness() const { return material_->thickness(); }
  QuantityField* weight() const { return material_->weight(); }
  QuantityField* modulus() const { return material_->modulus(); }
  QComboBox* outlineShape() const { return fabric_->outlineShape(); }
  QLineEdit* outlineExtent() const { return fabric_->outlineExtent(); }
  QLineEdit* outlineCenter() const { return fabric_->outlineCenter(); }
  QLineEdit* elementSize() const { return fabric_->elementSize(); }
  QSpinBox* elementsX() const { return fabric_->elementsX(); }
  QSpinBox* elementsY() const { return fabric_->elementsY(); }
  QComboBox* solverPreset() const { return solver_->preset(); }
  QuantityField* tolerance() const { return solver_->tolerance(); }
  QSpinBox* targetIterations() const { return solver_->targetIterations(); }
  QSpinBox* maxSteps() const { return solver_->maxSteps(); }
  QDoubleSpinBox* timeLimit() const { return solver_->timeLimit(); }
  QComboBox* branching() const { return solver_->branching(); }
  QSpinBox* sequencing() const { return solver_->sequencing(); }
  QCheckBox* errorEstimate() const { return solver_->errorEstimate(); }
  QLabel* meshInfo() const { return fabric_->meshInfo(); }
  // The model meshInfo() counts: the document's, never meshed here.
  const std::shared_ptr<const ShellModel>& model() const { return fabric_->meshInfo()->model(); }
  QString fabricMessage() const { return fabric_->message(); }
  // Why the last material or checked solver edit was refused.
  QString materialMessage() const { return material_->message(); }
  QComboBox* membrane() const { return material_->membrane(); }
  QuantityField* e1() const { return material_->e1(); }
  QuantityField* e2() const { return material_->e2(); }
  QuantityField* nu12() const { return material_->nu12(); }
  QuantityField* g12() const { return material_->g12(); }
  bool setOrthotropic(bool on) { return material_->setOrthotropic(on); }
  bool setOutline(const QString& shape, const QString& extent, const QString& center = "0, 0") {
    return fabric_->setOutline(shape, extent, center);
  }
  bool setElementSize(const QString& size) { return fabric_->setElementSize(size); }
  bool setImperfection(const QString& amplitude, int seed, const QString& pattern) {
    return fabric_->imperfection()->setImperfection(amplitude, seed, pattern);
  }

  UnitSystem unitSystem() const { return units_; }

 public slots:
  void refresh();  // every group from the document's scene
  // Every field shows its value in `system` from now on (typing takes any unit).
  void setUnitSystem(UnitSystem system);

 private:
  FabricEditor* fabric_;
  MaterialEditor* material_;
  SolverEditor* solver_;
  UnitSystem units_ = UnitSystem::kSI;
};

}  // namespace drape
