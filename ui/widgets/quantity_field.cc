#include "ui/widgets/quantity_field.h"

#include <cmath>

#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace drape {

QuantityField::QuantityField(Dimension dimension,
                             const QString& unit_hint,
                             std::function<QString(double)> check,
                             QWidget* parent)
    : QWidget(parent), dimension_(dimension), check_(std::move(check)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  edit_ = new QLineEdit(this);
  edit_->setPlaceholderText(unit_hint);
  edit_->setToolTip("a number and its unit, e.g. " + unit_hint);
  message_ = new QLabel(this);
  message_->setStyleSheet("color: #b00020");
  message_->setWordWrap(true);
  message_->hide();
  layout->addWidget(edit_);
  layout->addWidget(message_);
  connect(edit_, &QLineEdit::editingFinished, this, &QuantityField::Commit);
}

QuantityField::QuantityField(Measure measure,
                             const QString& unit_hint,
                             std::function<QString(double)> check,
                             QWidget* parent)
    : QuantityField(DimensionOf(measure), unit_hint, std::move(check), parent) {
  measure_ = measure;
}

void QuantityField::setValue(double si, UnitSystem system) {
  // Another system shows every value anew, the user's own text too.
  if (shown_in_ != system) text_.clear();
  shown_in_ = system;
  const DisplayUnit unit = measure_ ? UnitFor(*measure_, system) : UnitFor(dimension_, system);
  if (!unit.label.empty())
    edit_->setToolTip(QString("in %1, or a number with any unit of the scene reader, e.g. %2")
                          .arg(QString::fromStdString(unit.label), edit_->placeholderText()));
  const std::string text = measure_ ? FormatQuantity(si, *measure_, system, 6)
                                    : FormatQuantity(si, dimension_, system, 6);
  setValue(si, QString::fromStdString(text));
}

void QuantityField::setValue(double si, const QString& text) {
  // The same value keeps the unit the user typed it in.
  if (!(si == value_ && !text_.isEmpty())) text_ = text;
  value_ = si;
  edit_->setText(text_);
  message_->hide();
}

QString QuantityField::message() const {
  return message_->isVisible() ? message_->text() : QString();
}

void QuantityField::Commit() {
  const QString text = edit_->text().trimmed();
  if (text == text_) return;
  QString problem;
  double si = 0;
  bool bare = false;
  const double number = text.toDouble(&bare);
  try {
    // A bare number is SI, as the scene reader reads a JSON number (the
    // editors warn of values no fabric has: "0.5 read as 0.5 m"); an angle
    // in degrees, as under the reader's `_deg` keys.
    const bool angle = dimension_ == dim::kAngle;
    si = bare && std::isfinite(number) ? (angle ? number * M_PI / 180.0 : number)
         : measure_                    ? ParseMeasure(text.toStdString(), *measure_)
                                       : ParseQuantityAs(text.toStdString(), dimension_);
    problem = check_ ? check_(si) : QString();
  } catch (const UnitError& e) {
    problem = QString::fromStdString(e.what());
  }
  if (!problem.isEmpty()) {
    // The message stays; the field goes back to its last valid value.
    message_->setText(problem);
    message_->show();
    edit_->setText(text_);
    return;
  }
  message_->hide();
  value_ = si;
  text_ = text;
  emit committed(si, text);
}

}  // namespace drape
