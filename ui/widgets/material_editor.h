// The material's group of the property panel: thickness, areal weight, the
// membrane (isotropic E, ν or orthotropic E₁, E₂, ν₁₂, G₁₂) and the warp
// angle, each a QuantityField. A value the reader's or the engine's rules
// refuse (an orthotropic ν₁₂ must keep the law stable) is said under the
// group and the field shows the scene's value again.
#pragma once

#include <QGroupBox>

#include <functional>

#include "core/model/unit_system.h"

class QComboBox;
class QFormLayout;
class QLabel;

namespace drape {

class QuantityField;
class SceneDocument;
struct Material;
struct Scene;

class MaterialEditor : public QGroupBox {
  Q_OBJECT
 public:
  explicit MaterialEditor(SceneDocument* document, QWidget* parent = nullptr);

  QuantityField* thickness() const { return thickness_; }
  QuantityField* weight() const { return weight_; }
  QuantityField* modulus() const { return modulus_; }
  QuantityField* poisson() const { return poisson_; }
  QuantityField* angle() const { return angle_; }
  QComboBox* membrane() const { return membrane_; }
  QuantityField* e1() const { return e1_; }
  QuantityField* e2() const { return e2_; }
  QuantityField* nu12() const { return nu12_; }
  QuantityField* g12() const { return g12_; }
  // The message line under the group: why the last edit was refused.
  QLabel* messageLabel() const { return message_; }
  QString message() const;
  // Values no fabric has (core/fe/fabric_plausibility.h), one per line, each
  // with the field's name, the scene key and the likely slip: "thickness
  // (material.thickness): 0.5 read as 0.5 m, thicker than any fabric
  // (0.05–5 mm); did you mean 0.5 mm?". Empty when all are plausible.
  QString warnings() const;

  // Isotropic ↔ orthotropic, keeping the material's stiffness (E₁ = E₂ = E,
  // ν₁₂ = ν, G₁₂ = E/2(1 + ν); back: E = E₁, ν = ν₁₂).
  bool setOrthotropic(bool on);

 public slots:
  void refresh();  // from the document's scene
  void setUnitSystem(UnitSystem system);

 private:
  void MakeFields();
  void LayOut();
  void ConnectFields();
  void ShowWarnings(const Material& material);
  // Commits of `field` change the scene by `change` (with the SI value),
  // as an edit named `what` and the typed text.
  void EditBy(QuantityField* field,
              const QString& what,
              std::function<void(Scene&, double)> change);

  SceneDocument* document_;
  QFormLayout* form_;
  QuantityField *thickness_, *weight_, *modulus_, *poisson_, *angle_;
  QuantityField *e1_, *e2_, *nu12_, *g12_;
  QComboBox* membrane_;
  QLabel* message_;
  QLabel* warnings_;
  UnitSystem units_ = UnitSystem::kSI;
  bool refreshing_ = false;
};

}  // namespace drape
