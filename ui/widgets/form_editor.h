// A mesh obstacle (a form) placed by hand: where its origin stands, its
// turn about the vertical and its scale, typed in any unit, each change one
// undoable edit read by the scene reader (a wrong value gets its message
// with the key). A fabric lying just above the form keeps lying just above
// it; "Lay the fabric on it" puts it there.
#pragma once

#include <QWidget>

#include "core/model/unit_system.h"

class QLabel;
class QLineEdit;
class QPushButton;

namespace drape {

class SceneDocument;
struct Scene;

class FormEditor : public QWidget {
  Q_OBJECT
 public:
  explicit FormEditor(SceneDocument* document, QWidget* parent = nullptr);

  // The obstacle edited: shown only when it is a mesh.
  void setObstacle(int index);
  void setUnitSystem(UnitSystem system);

  // As typed: `at` "x, y, z" (lengths, any unit), `turn` degrees or an
  // angle with its unit, `scale` one factor or "sx, sy, sz".
  bool place(const QString& at, const QString& turn, const QString& scale);
  // The fabric's elevation just above the form.
  bool layFabricOn();

  QLineEdit* at() const { return at_; }
  QLineEdit* turn() const { return turn_; }
  QLineEdit* scale() const { return scale_; }
  QString message() const;

 private:
  void Show();
  bool ApplyPlaced(const QString& what, const Scene& after);

  SceneDocument* document_;
  int index_ = -1;
  UnitSystem units_ = UnitSystem::kSI;
  QLineEdit *at_, *turn_, *scale_;
  QPushButton* lay_;
  QLabel* message_;
};

}  // namespace drape
