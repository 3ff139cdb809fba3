#include "ui/widgets/material_editor.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QStringList>

#include <cmath>
#include <initializer_list>

#include "core/fe/fabric_plausibility.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/quantity_field.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"

namespace drape {
namespace {

QString Positive(double v) {
  return v > 0 && std::isfinite(v) ? QString() : "must be > 0";
}
QString NonNegative(double v) {
  return v >= 0 && std::isfinite(v) ? QString() : "must be ≥ 0";
}

// A change of one kind of membrane's constants: a field of the other kind
// (hidden) changes nothing.
std::function<void(Scene&, double)> Orthotropic(void (*set)(OrthotropicMembrane&, double)) {
  return [set](Scene& s, double v) {
    if (auto* m = std::get_if<OrthotropicMembrane>(&s.material.membrane)) set(*m, v);
  };
}

std::function<void(Scene&, double)> Isotropic(void (*set)(IsotropicMembrane&, double)) {
  return [set](Scene& s, double v) {
    if (auto* m = std::get_if<IsotropicMembrane>(&s.material.membrane)) set(*m, v);
  };
}

}  // namespace

MaterialEditor::MaterialEditor(SceneDocument* document, QWidget* parent)
    : QGroupBox("Material", parent), document_(document) {
  MakeFields();
  LayOut();
  ConnectFields();
  new ScenePartWatch(
      document_, SceneDocument::Part::kMaterial, [this] { refresh(); }, this);
  refresh();
}

void MaterialEditor::MakeFields() {
  thickness_ = new QuantityField(Measure::kThickness, "0.5 mm", Positive, this);
  // A weight per area, or a mass per area (g/m²) as the reader's areal_density.
  weight_ = new QuantityField(Measure::kArealWeight, "180 g/m^2", NonNegative, this);
  modulus_ = new QuantityField(dim::kPressure, "60450 gf/cm^2", Positive, this);
  poisson_ = new QuantityField(
      dim::kNone,
      "0.3",
      [](double v) { return v >= 0 && v < 0.5 ? QString() : QString("must lie in [0, 0.5)"); },
      this);
  angle_ = new QuantityField(dim::kAngle, "45 deg", nullptr, this);
  membrane_ = new QComboBox(this);
  membrane_->addItems({"isotropic", "orthotropic (warp 1, weft 2)"});
  e1_ = new QuantityField(dim::kPressure, "60450 gf/cm^2", Positive, this);
  e2_ = new QuantityField(dim::kPressure, "30000 gf/cm^2", Positive, this);
  nu12_ = new QuantityField(dim::kNone, "0.2", NonNegative, this);
  g12_ = new QuantityField(dim::kPressure, "5000 gf/cm^2", Positive, this);
  message_ = MakeMessageLabel(this);
  warnings_ = new QLabel(this);
  warnings_->setWordWrap(true);
  warnings_->setStyleSheet("color: #b35900");
  warnings_->setToolTip(
      "Values no fabric has: most often a unit that slipped (a bare number is read in SI "
      "units: metres, N/m²). The scene still runs as it is.");
}

void MaterialEditor::LayOut() {
  form_ = new QFormLayout(this);
  form_->addRow("thickness h", thickness_);
  form_->addRow("areal weight w", weight_);
  form_->addRow("membrane", membrane_);
  form_->addRow("Young's modulus E", modulus_);
  form_->addRow("Poisson's ratio ν", poisson_);
  form_->addRow("E₁ (warp)", e1_);
  form_->addRow("E₂ (weft)", e2_);
  form_->addRow("ν₁₂", nu12_);
  form_->addRow("G₁₂", g12_);
  form_->addRow("warp angle", angle_);
  form_->addRow(message_);
  form_->addRow(warnings_);
}

void MaterialEditor::EditBy(QuantityField* field,
                            const QString& what,
                            std::function<void(Scene&, double)> change) {
  connect(
      field, &QuantityField::committed, this, [this, what, change](double si, const QString& text) {
        if (refreshing_) return;
        Scene after = document_->scene();
        change(after, si);
        // Checked by the reader's and the engine's rules; a refused value goes
        // back to the scene's.
        if (!ApplyOrSay(document_, message_, what + " " + text, after)) refresh();
      });
}

void MaterialEditor::ConnectFields() {
  EditBy(thickness_, "thickness", [](Scene& s, double v) { s.material.thickness = v; });
  EditBy(weight_, "areal weight", [](Scene& s, double v) { s.material.areal_weight = v; });
  EditBy(modulus_, "Young's modulus", Isotropic([](IsotropicMembrane& m, double v) {
           m.youngs_modulus = v;
         }));
  EditBy(poisson_, "Poisson's ratio", Isotropic([](IsotropicMembrane& m, double v) {
           m.poisson_ratio = v;
         }));
  EditBy(e1_, "E₁", Orthotropic([](OrthotropicMembrane& m, double v) { m.e1 = v; }));
  EditBy(e2_, "E₂", Orthotropic([](OrthotropicMembrane& m, double v) { m.e2 = v; }));
  EditBy(nu12_, "ν₁₂", Orthotropic([](OrthotropicMembrane& m, double v) { m.nu12 = v; }));
  EditBy(g12_, "G₁₂", Orthotropic([](OrthotropicMembrane& m, double v) { m.g12 = v; }));
  // A typed angle replaces one taken from a pattern piece's grain line.
  EditBy(angle_, "warp angle", [](Scene& s, double v) {
    s.material.angle_deg = v * 180.0 / M_PI;
    s.material.angle_from_grain = false;
  });
  connect(membrane_, &QComboBox::activated, this, [this](int i) { setOrthotropic(i == 1); });
}

QString MaterialEditor::message() const {
  return message_->text();
}

QString MaterialEditor::warnings() const {
  return warnings_->text();
}

// Each in the field's name beside the scene key; a bare number typed into
// the field is said as read ("0.5 read as 0.5 m").
void MaterialEditor::ShowWarnings(const Material& material) {
  QStringList lines;
  for (const Implausible& value : ImplausibleFabric(material)) {
    QString read_as = QString::fromStdString(value.read_as);
    const QuantityField* field = value.key == "material.thickness"      ? thickness_
                                 : value.key == "material.areal_weight" ? weight_
                                                                        : nullptr;
    bool bare = false;
    if (field) field->edit()->text().trimmed().toDouble(&bare);
    if (bare) read_as = field->edit()->text().trimmed() + " read as " + read_as;
    QString line = QString("%1 (%2): %3, %4")
                       .arg(QString::fromStdString(value.quantity),
                            QString::fromStdString(value.key),
                            read_as,
                            QString::fromStdString(value.why));
    if (!value.did_you_mean.empty())
      line += QString("; did you mean %1?").arg(QString::fromStdString(value.did_you_mean));
    lines << line;
  }
  warnings_->setText(lines.join("\n"));
  warnings_->setVisible(!lines.isEmpty());
}

bool MaterialEditor::setOrthotropic(bool on) {
  Scene after = document_->scene();
  Membrane& m = after.material.membrane;
  if (on == std::holds_alternative<OrthotropicMembrane>(m)) return true;
  if (const auto* iso = std::get_if<IsotropicMembrane>(&m)) {
    // The same material, described by its directions: E₁ = E₂ = E, ν₁₂ = ν,
    // G₁₂ = E / 2(1 + ν); then each can be changed.
    const double e = iso->youngs_modulus, nu = iso->poisson_ratio;
    m = OrthotropicMembrane{e, e, nu, e / (2 * (1 + nu))};
  } else {
    const auto& o = std::get<OrthotropicMembrane>(m);
    m = IsotropicMembrane{o.e1, o.nu12};
  }
  const bool done =
      ApplyOrSay(document_, message_, on ? "orthotropic membrane" : "isotropic membrane", after);
  if (!done) refresh();
  return done;
}

void MaterialEditor::setUnitSystem(UnitSystem system) {
  units_ = system;
  refresh();
}

void MaterialEditor::refresh() {
  refreshing_ = true;
  const Material& material = document_->scene().material;
  thickness_->setValue(material.thickness, units_);
  weight_->setValue(material.areal_weight, units_);
  const auto* iso = std::get_if<IsotropicMembrane>(&material.membrane);
  const auto* orthotropic = std::get_if<OrthotropicMembrane>(&material.membrane);
  membrane_->setCurrentIndex(iso ? 0 : 1);
  for (QWidget* f : std::initializer_list<QWidget*>{modulus_, poisson_})
    form_->setRowVisible(f, iso != nullptr);
  for (QWidget* f : std::initializer_list<QWidget*>{e1_, e2_, nu12_, g12_})
    form_->setRowVisible(f, orthotropic != nullptr);
  if (iso) {
    modulus_->setValue(iso->youngs_modulus, units_);
    poisson_->setValue(iso->poisson_ratio, QString::number(iso->poisson_ratio));
  }
  if (orthotropic) {
    e1_->setValue(orthotropic->e1, units_);
    e2_->setValue(orthotropic->e2, units_);
    nu12_->setValue(orthotropic->nu12, QString::number(orthotropic->nu12));
    g12_->setValue(orthotropic->g12, units_);
  }
  angle_->setValue(material.angle_deg * M_PI / 180, QString("%1 deg").arg(material.angle_deg));
  ShowWarnings(material);
  angle_->setToolTip(material.angle_from_grain
                         ? "from the pattern piece's grain line; type an angle to set another"
                         : "the warp's direction from the part's x axis; 45 deg is a bias cut");
  refreshing_ = false;
}

}  // namespace drape
