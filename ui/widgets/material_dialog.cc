#include "ui/widgets/material_dialog.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QPushButton>
#include <QScatterSeries>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>
#include <QValueAxis>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "core/io/kawabata_reader.h"
#include "core/io/material_library.h"
#include "core/mechanics/moment_curvature.h"
#include "core/mechanics/moment_curvature_fit.h"
#include "ui/widgets/fabric_cards.h"
#include "ui/widgets/fabric_summary_form.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"

namespace drape {
namespace {

constexpr double kPerCm = 100.0;           // 1/m per 1/cm
constexpr double kGfCmPerCm = 9.80665e-3;  // N·m/m per gf·cm/cm

}  // namespace

MaterialDialog::MaterialDialog(SceneDocument* document, QWidget* parent)
    : QDialog(parent), document_(document) {
  setWindowTitle("Material");
  auto* outer = new QVBoxLayout(this);
  tabs_ = new QTabWidget(this);
  outer->addWidget(tabs_, 1);

  // The library, as cards in a lab's figures.
  auto* library_page = new QWidget(this);
  auto* library_layout = new QVBoxLayout(library_page);
  cards_ = new FabricCards(document->directory(), library_page);
  library_layout->addWidget(cards_, 1);
  auto* use_library = new QPushButton("Use this fabric", library_page);
  library_layout->addWidget(use_library);
  connect(use_library, &QPushButton::clicked, this, &MaterialDialog::applyLibrary);
  connect(cards_, &QListWidget::itemDoubleClicked, this, &MaterialDialog::applyLibrary);
  tabs_->addTab(library_page, "Library");

  summary_ = new FabricSummaryForm(document, this);
  tabs_->addTab(summary_, "Lab summary (KES-FB, FAST)");

  // A measured bending law from a Kawabata file.
  auto* curve_page = new QWidget(this);
  auto* layout = new QVBoxLayout(curve_page);
  tabs_->addTab(curve_page, "Kawabata bending curve");

  auto* form = new QFormLayout;
  auto* file_row = new QHBoxLayout;
  file_ = new QLineEdit(this);
  auto* browse = new QPushButton("Browse…", this);
  file_row->addWidget(file_, 1);
  file_row->addWidget(browse);
  form->addRow("Kawabata file", file_row);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString f =
        QFileDialog::getOpenFileName(this, "Kawabata data", {}, "KES data (*.csv *.tsv *.txt)");
    if (!f.isEmpty()) {
      file_->setText(f);
      preview();
    }
  });
  branch_ = new QComboBox(this);
  branch_->addItems({"average", "loading", "unloading"});
  form->addRow("branch", branch_);
  curvature_column_ = new QLineEdit(this);
  curvature_column_->setPlaceholderText("found by name");
  moment_column_ = new QLineEdit(this);
  moment_column_->setPlaceholderText("found by name");
  form->addRow("curvature column", curvature_column_);
  form->addRow("moment column", moment_column_);
  law_ = new QComboBox(this);
  law_->addItem("measured curve (monotone spline through the points)", "curve");
  law_->addItem("polynomial M = Σ cₖ Kᵏ (the paper's fit)", "polynomial");
  form->addRow("law", law_);
  degree_ = new QSpinBox(this);
  degree_->setRange(1, 9);
  degree_->setValue(5);
  form->addRow("polynomial degree", degree_);
  direction_ = new QComboBox(this);
  direction_->addItem("warp and weft alike (one law)", "both");
  direction_->addItem("warp (the weft keeps its law)", "warp");
  direction_->addItem("weft (the warp keeps its law)", "weft");
  form->addRow("applies to", direction_);
  layout->addLayout(form);

  chart_ = new QChart;
  chart_->legend()->setAlignment(Qt::AlignBottom);
  auto* view = new QChartView(chart_, curve_page);
  view->setMinimumSize(480, 300);
  layout->addWidget(view, 1);
  auto* curve_buttons = new QDialogButtonBox(curve_page);
  QPushButton* show = curve_buttons->addButton("Preview", QDialogButtonBox::ActionRole);
  QPushButton* apply = curve_buttons->addButton("Apply bending law", QDialogButtonBox::ApplyRole);
  layout->addWidget(curve_buttons);
  connect(show, &QPushButton::clicked, this, &MaterialDialog::preview);
  connect(apply, &QPushButton::clicked, this, &MaterialDialog::applyBending);

  message_ = new QLabel(this);
  message_->setWordWrap(true);
  outer->addWidget(message_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  outer->addWidget(buttons);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  // An edit made here shows in the summary's fields.
  new ScenePartWatch(
      document_, SceneDocument::Part::kMaterial, [this] { summary_->showScene(); }, this);
}

QString MaterialDialog::message() const {
  return message_->text();
}

void MaterialDialog::setUnitSystem(UnitSystem system) {
  units_ = system;
  if (plot_) Draw();
}

// The last preview's points and law over the data's range, in units_.
void MaterialDialog::Draw() {
  chart_->removeAllSeries();
  for (QAbstractAxis* axis : chart_->axes()) chart_->removeAxis(axis);
  const DisplayUnit k_unit = UnitFor(Measure::kCurvature, units_);
  const DisplayUnit m_unit = UnitFor(Measure::kMomentPerWidth, units_);
  auto* measured = new QScatterSeries;
  measured->setName("measured");
  measured->setMarkerSize(6);
  for (size_t i = 0; i < plot_->curvature.size(); ++i)
    measured->append(plot_->curvature[i] / k_unit.si_factor, plot_->moment[i] / m_unit.si_factor);
  auto* fitted = new QLineSeries;
  fitted->setName(plot_->law_name);
  const auto [lo, hi] = std::minmax_element(plot_->curvature.begin(), plot_->curvature.end());
  for (int i = 0; i <= 200; ++i) {
    const double k = *lo + (*hi - *lo) * i / 200.0;  // [1/m]
    const double m = plot_->law->Moment(k / kPerCm) * kGfCmPerCm;
    fitted->append(k / k_unit.si_factor, m / m_unit.si_factor);
  }
  chart_->addSeries(measured);
  chart_->addSeries(fitted);
  auto* x_axis = new QValueAxis;
  x_axis->setTitleText(QString("curvature K [%1]").arg(QString::fromStdString(k_unit.label)));
  auto* y_axis = new QValueAxis;
  y_axis->setTitleText(QString("moment M [%1]").arg(QString::fromStdString(m_unit.label)));
  chart_->addAxis(x_axis, Qt::AlignBottom);
  chart_->addAxis(y_axis, Qt::AlignLeft);
  for (QAbstractSeries* series : chart_->series()) {
    series->attachAxis(x_axis);
    series->attachAxis(y_axis);
  }
  message_->setStyleSheet("");
  message_->setText(Summary());
}

QString MaterialDialog::Summary() const {
  const auto [lo, hi] = std::minmax_element(plot_->curvature.begin(), plot_->curvature.end());
  QString text = QString("%1\n%2 points, K from %3 to %4")
                     .arg(plot_->read)
                     .arg(plot_->curvature.size())
                     .arg(QString::fromStdString(FormatQuantity(*lo, Measure::kCurvature, units_)),
                          QString::fromStdString(FormatQuantity(*hi, Measure::kCurvature, units_)));
  if (plot_->rms_kes >= 0)
    text += ", RMS error " + QString::fromStdString(FormatQuantity(
                                 plot_->rms_kes * kGfCmPerCm, Measure::kMomentPerWidth, units_, 3));
  return text + plot_->warnings;
}

bool MaterialDialog::preview() {
  previewed_.reset();
  plot_.reset();
  measured_points_ = 0;
  chart_->removeAllSeries();
  for (QAbstractAxis* axis : chart_->axes()) chart_->removeAxis(axis);
  KawabataOptions options;
  options.branch = branch_->currentIndex() == 0   ? KawabataBranch::kAverage
                   : branch_->currentIndex() == 1 ? KawabataBranch::kLoading
                                                  : KawabataBranch::kUnloading;
  options.curvature_column = curvature_column_->text().trimmed().toStdString();
  options.moment_column = moment_column_->text().trimmed().toStdString();
  try {
    const KawabataCurve curve = ReadKawabata(file_->text().toStdString(), options);
    std::vector<double> k, m;
    for (size_t i = 0; i < curve.curvature.size(); ++i) {
      k.push_back(curve.curvature[i] / kPerCm);
      m.push_back(curve.moment[i] / kGfCmPerCm);
    }
    std::shared_ptr<const MomentCurvatureLaw> law;
    double rms = 0;
    if (law_->currentData().toString() == "polynomial") {
      const PolynomialFit fit = FitOddPolynomial(k, m, degree_->value());
      law = MakePolynomialLaw(fit.coefficients, fit.valid_to);
      rms = fit.rms_error;
      PolynomialBending p;
      for (size_t i = 0; i < fit.coefficients.size(); ++i)
        p.coefficients.push_back(fit.coefficients[i] * kGfCmPerCm * std::pow(kPerCm, -(i + 1.0)));
      p.valid_to = fit.valid_to * kPerCm;
      previewed_ = p;
    } else {
      std::vector<std::array<double, 2>> points;
      for (size_t i = 0; i < k.size(); ++i) points.push_back({k[i], m[i]});
      law = MakeCurveLaw(points);
      CurveBending c;
      for (size_t i = 0; i < curve.curvature.size(); ++i)
        c.points.push_back({curve.curvature[i], curve.moment[i]});
      c.file = file_->text().toStdString();
      c.branch = branch_->currentText().toStdString();
      c.curvature_column = options.curvature_column;
      c.moment_column = options.moment_column;
      previewed_ = c;
    }
    Plot plot;
    plot.curvature = curve.curvature;
    plot.moment = curve.moment;
    plot.law = std::move(law);
    plot.law_name = law_->currentData().toString() == "polynomial" ? "polynomial fit" : "curve law";
    plot.read = QString("read %1 and %2")
                    .arg(QString::fromStdString(curve.curvature_read),
                         QString::fromStdString(curve.moment_read));
    plot.rms_kes = law_->currentData().toString() == "polynomial" ? rms : -1;
    for (const auto& w : curve.warnings) plot.warnings += "\nwarning: " + QString::fromStdString(w);
    plot_ = std::move(plot);
    measured_points_ = static_cast<int>(k.size());
    Draw();
    return true;
  } catch (const std::exception& e) {
    message_->setStyleSheet("color: #b00020");
    message_->setText(QString::fromStdString(e.what()));
    return false;
  }
}

bool MaterialDialog::applyBending() {
  if (!previewed_ && !preview()) return false;
  Scene after = document_->scene();
  Bending& bending = after.material.bending;
  // One law for one direction keeps the other's (the old single law when
  // there was one): the part becomes direction dependent, never silently
  // isotropic.
  // The hysteresis (2HB) stays with its direction; one the replaced law's
  // file measured is kept as the number it was.
  const QString direction = direction_->currentData().toString();
  Hysteresis warp_hysteresis = bending.warp_hysteresis;
  Hysteresis weft_hysteresis = bending.weft ? bending.weft_hysteresis : warp_hysteresis;
  if (direction == "both") {
    warp_hysteresis.measured = false;
    bending = Bending{*previewed_, std::nullopt, warp_hysteresis, {}};
  } else {
    const BendingLaw weft = bending.weft ? *bending.weft : bending.warp;
    if (direction == "warp") {
      warp_hysteresis.measured = false;
      bending = Bending{*previewed_, weft, warp_hysteresis, weft_hysteresis};
    } else {
      weft_hysteresis.measured = false;
      bending = Bending{bending.warp, *previewed_, warp_hysteresis, weft_hysteresis};
    }
  }
  QString problem;
  const bool done = document_->tryApply(QString("%1 bending law from %2")
                                            .arg(direction == "both" ? QString("the") : direction,
                                                 QFileInfo(file_->text()).fileName()),
                                        after,
                                        &problem);
  if (!done) {
    message_->setStyleSheet("color: #b00020");
    message_->setText(problem);
  }
  return done;
}

bool MaterialDialog::chooseLibrary(const QString& name) {
  return cards_->choose(name);
}

bool MaterialDialog::applyLibrary() {
  const QString name = cards_->chosen();
  if (name.isEmpty()) return false;
  // The scene reader resolves the name, as for a scene that names it.
  nlohmann::json document = document_->json();
  document["material"] = {{"library", name.toStdString()}};
  QString problem;
  if (!document_->tryApplyJson("material " + name, document, &problem)) {
    message_->setStyleSheet("color: #b00020");
    message_->setText(problem);
    return false;
  }
  return true;
}

}  // namespace drape
