#include "ui/widgets/fabric_summary_form.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include <exception>
#include <stdexcept>

#include "core/model/scene.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/scene_document.h"

namespace drape {
namespace {

QDoubleSpinBox* Field(
    QWidget* parent, double top, int decimals, const QString& unit, const QString& tip) {
  auto* box = new QDoubleSpinBox(parent);
  box->setRange(0, top);
  box->setDecimals(decimals);
  box->setSuffix(" " + unit);
  box->setToolTip(tip);
  return box;
}

}  // namespace

FabricSummaryForm::FabricSummaryForm(SceneDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);
  auto* intro = new QLabel(
      "A fabric as a KES-FB or FAST summary gives it. FAST's B in µN·m is B/98.07 here; its "
      "extensibility E100 and KES-FB1's EMT give the stiffness per width as 100·load/strain.",
      this);
  intro->setWordWrap(true);
  layout->addWidget(intro);
  auto* form = new QFormLayout;
  thickness_ = Field(this, 20, 3, "mm", "T: KES-FB3 at 0.5 gf/cm², FAST T2");
  weight_ = Field(this, 5000, 1, "g/m²", "W: mass per area");
  bending_warp_ = Field(this, 1000, 4, "gf·cm²/cm", "B of the warp (KES-FB2 B-1)");
  bending_weft_ = Field(this, 1000, 4, "gf·cm²/cm", "B of the weft (KES-FB2 B-2)");
  shear_ = Field(this, 1000, 3, "gf/(cm·deg)", "G: shear rigidity (KES-FB1)");
  tensile_warp_ = Field(this,
                        1e6,
                        1,
                        "gf/cm",
                        "The membrane's stiffness per width along the warp: force per width "
                        "over strain (KES-FB1: 500 gf/cm over EMT)");
  tensile_weft_ = Field(this, 1e6, 1, "gf/cm", "The same along the weft");
  poisson_ = Field(this, 0.99, 3, "", "ν₁₂: summaries give none; 0.3 is usual");
  form->addRow("thickness T", thickness_);
  form->addRow("weight W", weight_);
  form->addRow("bending B, warp", bending_warp_);
  form->addRow("bending B, weft", bending_weft_);
  form->addRow("shear G", shear_);
  form->addRow("stretch stiffness, warp", tensile_warp_);
  form->addRow("stretch stiffness, weft", tensile_weft_);
  form->addRow("Poisson's ratio ν₁₂", poisson_);
  layout->addLayout(form);
  auto* use = new QPushButton("Use these figures", this);
  layout->addWidget(use);
  message_ = MakeMessageLabel(this);
  layout->addWidget(message_);
  layout->addStretch(1);
  connect(use, &QPushButton::clicked, this, &FabricSummaryForm::apply);
  showScene();
}

QString FabricSummaryForm::message() const {
  return message_->text();
}

FabricSummary FabricSummaryForm::summary() const {
  FabricSummary s;
  s.thickness_mm = thickness_->value();
  s.weight_g_per_m2 = weight_->value();
  s.bending_warp = bending_warp_->value();
  s.bending_weft = bending_weft_->value();
  s.shear = shear_->value();
  s.tensile_warp = tensile_warp_->value();
  s.tensile_weft = tensile_weft_->value();
  s.poisson_ratio = poisson_->value();
  return s;
}

void FabricSummaryForm::setSummary(const FabricSummary& s) {
  thickness_->setValue(s.thickness_mm);
  weight_->setValue(s.weight_g_per_m2);
  bending_warp_->setValue(s.bending_warp);
  bending_weft_->setValue(s.bending_weft);
  shear_->setValue(s.shear);
  tensile_warp_->setValue(s.tensile_warp);
  tensile_weft_->setValue(s.tensile_weft);
  poisson_->setValue(s.poisson_ratio);
}

void FabricSummaryForm::showScene() {
  try {
    const TextileFigures f = FiguresOf(document_->scene().material);
    setSummary({f.thickness_mm,
                f.weight_g_per_m2,
                f.bending_warp,
                f.bending_weft,
                f.shear,
                f.tensile_warp,
                f.tensile_weft,
                f.poisson_ratio});
  } catch (const std::exception&) {
    // A scene whose law cannot be built keeps the fields as they are.
  }
}

bool FabricSummaryForm::apply() {
  Scene after = document_->scene();
  const Material before = after.material;
  try {
    after.material = MaterialFromSummary(summary());
  } catch (const std::invalid_argument& e) {
    message_->setText(QString::fromStdString(e.what()));
    return false;
  }
  after.material.angle_deg = before.angle_deg;
  after.material.angle_from_grain = before.angle_from_grain;
  return ApplyOrSay(document_, message_, "fabric from a lab summary", after);
}

}  // namespace drape
