// A field for one quantity typed with its unit ("0.5 mm"), checked as it is
// committed by the same unit parser as the scene reader: what is wrong shows
// under it, and the field keeps its last valid value.
#pragma once

#include <QString>
#include <QWidget>

#include <functional>
#include <optional>

#include "core/model/unit_system.h"
#include "core/model/units.h"

class QLabel;
class QLineEdit;

namespace drape {

// A quantity typed with its unit ("0.5 mm"), accepted when it has the
// field's dimension and passes `check` (which returns "" or what is wrong);
// a bare number is in SI units, as in a scene file.
// Any unit the scene reader takes for the measure is accepted; values the
// user did not type are shown in the field's unit system.
class QuantityField : public QWidget {
  Q_OBJECT
 public:
  QuantityField(Dimension dimension,
                const QString& unit_hint,
                std::function<QString(double)> check,
                QWidget* parent = nullptr);
  QuantityField(Measure measure,
                const QString& unit_hint,
                std::function<QString(double)> check,
                QWidget* parent = nullptr);
  // Shows `text` for the SI value `si`, unless the field already shows that
  // value in the user's own unit.
  void setValue(double si, const QString& text);
  // Shows `si` in the unit system's unit (as setValue, keeping the user's
  // own text for the same value while the system stays the same).
  void setValue(double si, UnitSystem system);
  double value() const { return value_; }
  QLineEdit* edit() const { return edit_; }
  QString message() const;

 signals:
  void committed(double si, const QString& text);

 private:
  void Commit();

  Dimension dimension_;
  std::optional<Measure> measure_;  // when the dimension alone does not say the unit
  std::function<QString(double)> check_;
  std::optional<UnitSystem> shown_in_;  // the system of the last setValue(si, system)
  QLineEdit* edit_;
  QLabel* message_;
  double value_ = 0;
  QString text_;
};

}  // namespace drape
