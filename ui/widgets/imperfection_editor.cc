#include "ui/widgets/imperfection_editor.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>

#include <cstdint>

#include <nlohmann/json.hpp>

#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"
#include "ui/widgets/typed_json.h"

namespace drape {

ImperfectionEditor::ImperfectionEditor(SceneDocument* document, QLabel* message, QWidget* parent)
    : QWidget(parent), document_(document), message_(message) {
  amplitude_ = new QLineEdit(this);
  amplitude_->setToolTip("largest out-of-plane offset, e.g. 0.05 mm; 0 for a flat part");
  seed_ = new QSpinBox(this);
  seed_->setRange(0, 1000000);
  pattern_ = new QComboBox(this);
  pattern_->addItems({"smooth", "nodal"});
  pattern_->setToolTip("smooth: random plane waves (the same at any mesh); nodal: each node");
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(amplitude_, 1);
  row->addWidget(new QLabel("seed", this));
  row->addWidget(seed_);
  row->addWidget(pattern_);
  connect(amplitude_, &QLineEdit::editingFinished, this, &ImperfectionEditor::Commit);
  connect(seed_, &QSpinBox::editingFinished, this, &ImperfectionEditor::Commit);
  connect(pattern_, &QComboBox::activated, this, &ImperfectionEditor::Commit);
  new ScenePartWatch(
      document_, SceneDocument::Part::kFabric, [this] { refresh(); }, this);
  refresh();
}

void ImperfectionEditor::Commit() {
  if (!refreshing_) setImperfection(amplitude_->text(), seed_->value(), pattern_->currentText());
}

bool ImperfectionEditor::setImperfection(const QString& amplitude,
                                         int seed,
                                         const QString& pattern) {
  // The scene reader reads the fabric, so wrong text gets its message.
  nlohmann::json document = document_->json();
  nlohmann::json& fabric = document["fabric"];
  const nlohmann::json a = TypedQuantity(amplitude);
  if (amplitude.trimmed().isEmpty() || (a.is_number() && a.get<double>() == 0.0)) {
    fabric.erase("imperfection");
  } else {
    nlohmann::json spec = fabric.value("imperfection", nlohmann::json::object());
    spec["amplitude"] = a;
    spec["seed"] = static_cast<std::uint64_t>(seed);
    spec["pattern"] = pattern.toStdString();
    fabric["imperfection"] = spec;
  }
  const bool done = ApplyOrSay(document_, message_, "imperfection " + amplitude, document);
  if (!done) refresh();  // the fields show the scene's imperfection again
  return done;
}

void ImperfectionEditor::setUnitSystem(UnitSystem system) {
  units_ = system;
  refresh();
}

void ImperfectionEditor::refresh() {
  refreshing_ = true;
  const auto& imperfection = document_->scene().fabric.imperfection;
  if (imperfection) {
    amplitude_->setText(QuantityText(imperfection->amplitude, Measure::kThickness, units_));
    seed_->setValue(static_cast<int>(imperfection->seed));
    pattern_->setCurrentIndex(imperfection->pattern == ImperfectionPattern::kSmooth ? 0 : 1);
  } else {
    amplitude_->setText("0");
  }
  refreshing_ = false;
}

}  // namespace drape
