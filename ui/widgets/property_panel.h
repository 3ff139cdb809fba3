// Property editors for the scene's fabric, material and solver: each field
// shows its unit, is checked as it is committed (the same unit parser and
// limits as the scene reader), shows what is wrong in place and keeps its
// last valid value. Every accepted change goes to the SceneDocument as one
// undoable edit.
#pragma once

#include <QWidget>

#include <functional>
#include <memory>
#include <optional>

#include <nlohmann/json_fwd.hpp>

#include "core/fe/shell_model.h"
#include "core/model/unit_system.h"
#include "core/model/units.h"
#include "ui/widgets/quantity_field.h"

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QDoubleSpinBox;
class QSpinBox;

namespace drape {

class SceneDocument;

class PropertyPanel : public QWidget {
  Q_OBJECT
 public:
  explicit PropertyPanel(SceneDocument* document, QWidget* parent = nullptr);

  // For tests and scripts: the fields by name.
  QuantityField* thickness() const { return thickness_; }
  QuantityField* weight() const { return weight_; }
  QuantityField* modulus() const { return modulus_; }
  QComboBox* outlineShape() const { return shape_; }
  QLineEdit* outlineExtent() const { return extent_; }
  QLineEdit* outlineCenter() const { return center_; }
  QLineEdit* elementSize() const { return element_size_; }
  QSpinBox* elementsX() const { return nx_; }
  QSpinBox* elementsY() const { return ny_; }
  QComboBox* solverPreset() const { return preset_; }
  QuantityField* tolerance() const { return tolerance_; }
  QSpinBox* targetIterations() const { return target_iterations_; }
  QSpinBox* maxSteps() const { return max_steps_; }
  QDoubleSpinBox* timeLimit() const { return time_limit_; }
  QComboBox* branching() const { return branching_; }
  QSpinBox* sequencing() const { return sequencing_; }
  QCheckBox* errorEstimate() const { return error_estimate_; }
  QLabel* meshInfo() const { return mesh_info_; }
  // The model meshInfo() counts: the document's, never meshed here.
  const std::shared_ptr<const ShellModel>& model() const { return model_; }
  QString fabricMessage() const;
  QString materialMessage() const;
  QComboBox* membrane() const { return membrane_; }
  QuantityField* e1() const { return e1_; }
  QuantityField* e2() const { return e2_; }
  QuantityField* nu12() const { return nu12_; }
  QuantityField* g12() const { return g12_; }
  // Isotropic ↔ orthotropic, keeping the material's stiffness (E₁ = E₂ = E,
  // ν₁₂ = ν, G₁₂ = E/2(1 + ν); back: E = E₁, ν = ν₁₂).
  bool setOrthotropic(bool on);

  // The outline: shape "rectangle" (extent "width, height"), "disk" (extent
  // the radius) or "polygon" (extent "x, y; x, y; …"), with its centre
  // ("x, y"; not for polygons); units allowed. Read by the scene reader;
  // false with its message when wrong.
  bool setOutline(const QString& shape, const QString& extent, const QString& center = "0, 0");
  // The target element edge of outlines meshed by size.
  bool setElementSize(const QString& size);
  // A small out-of-plane imperfection of the flat part (to start buckling):
  // amplitude (typed, "0" for none), seed, pattern "smooth" or "nodal".
  bool setImperfection(const QString& amplitude, int seed, const QString& pattern);

  UnitSystem unitSystem() const { return units_; }

 public slots:
  void refresh();  // from the document's scene
  // Every field shows its value in `system` from now on (typing takes any unit).
  void setUnitSystem(UnitSystem system);

 private:
  void EditMesh();
  bool ApplyFabric(const QString& what, const nlohmann::json& fabric);

  SceneDocument* document_;
  QFormLayout* fabric_form_;
  QComboBox* shape_;
  QLineEdit *extent_, *center_, *element_size_, *imperfection_;
  QSpinBox* seed_;
  QComboBox* pattern_;
  QSpinBox *nx_, *ny_;
  QLabel *mesh_info_, *fabric_message_;
  QuantityField *thickness_, *weight_, *modulus_, *poisson_, *angle_;
  QuantityField *e1_, *e2_, *nu12_, *g12_;
  QComboBox* membrane_;
  QFormLayout* material_form_;
  QLabel* material_message_;
  QComboBox* preset_;
  QComboBox* branching_;
  QuantityField* tolerance_;
  QSpinBox *target_iterations_, *max_steps_, *sequencing_;
  QDoubleSpinBox* time_limit_;
  QCheckBox* error_estimate_;
  std::shared_ptr<const ShellModel> model_;
  UnitSystem units_ = UnitSystem::kSI;
  bool refreshing_ = false;
};

}  // namespace drape
