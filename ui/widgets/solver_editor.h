// The solver's group of the property panel: an accuracy preset (or custom),
// the preset's numbers each in its own field (changed by hand, the settings
// are custom), the run's limits, what happens where the part buckles, mesh
// sequencing and the error estimate.
#pragma once

#include <QGroupBox>

#include <functional>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QSpinBox;

namespace drape {

class QuantityField;
class SceneDocument;
struct Scene;

class SolverEditor : public QGroupBox {
  Q_OBJECT
 public:
  // A checked edit refused (a sequencing factor that does not divide the
  // mesh) is said in `message`.
  SolverEditor(SceneDocument* document, QLabel* message, QWidget* parent = nullptr);

  QComboBox* preset() const { return preset_; }
  QuantityField* tolerance() const { return tolerance_; }
  QSpinBox* targetIterations() const { return target_iterations_; }
  QSpinBox* maxSteps() const { return max_steps_; }
  QDoubleSpinBox* timeLimit() const { return time_limit_; }
  QComboBox* branching() const { return branching_; }
  QSpinBox* sequencing() const { return sequencing_; }
  QCheckBox* errorEstimate() const { return error_estimate_; }

 public slots:
  void refresh();  // from the document's scene

 private:
  void MakePreset(QFormLayout* form);
  void MakeLimits(QFormLayout* form);
  void MakeChoices(QFormLayout* form);
  void ConnectNumbers();
  void ConnectChoices();
  // Checked by the reader's and the engine's rules: refused, the fields
  // show the scene's values again.
  void ApplyChecked(const QString& what, const std::function<void(Scene&)>& change);
  // Not checked: a scene the engine cannot model is taken back with its
  // message all the same (DocumentController).
  void Apply(const QString& what, const std::function<void(Scene&)>& change);

  SceneDocument* document_;
  QLabel* message_;
  QComboBox *preset_, *branching_;
  QuantityField* tolerance_;
  QSpinBox *target_iterations_, *max_steps_, *sequencing_;
  QDoubleSpinBox* time_limit_;
  QCheckBox* error_estimate_;
  bool refreshing_ = false;
};

}  // namespace drape
