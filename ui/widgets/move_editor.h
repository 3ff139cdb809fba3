// The moves of one stage: what each carries (a gripper, or an obstacle) and
// its path — a line, an arc or keyframes — typed as quantities with units
// ("1 cm, 0, 0") and read by the scene reader, whose message is shown when
// the text is not a path. The selected move's path can also be dragged by
// its handles in the viewport (PathHandles); both are undoable edits.
#pragma once

#include <QWidget>

#include "core/model/unit_system.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QListWidget;

namespace drape {

class SceneDocument;
struct Scene;

class MoveEditor : public QWidget {
  Q_OBJECT
 public:
  explicit MoveEditor(SceneDocument* document, QWidget* parent = nullptr);

  int stage() const { return stage_; }
  int currentMove() const;
  QListWidget* list() const { return list_; }
  QString message() const;

  // A new move of the named gripper (or, as "obstacle NAME", obstacle) by
  // 5 cm up, selected.
  bool addMove(const QString& carried);
  bool removeSelected();
  // The selected move's path: kind "line", "arc" or "keyframes", with the
  // fields' texts (by; centre, axis, angle; points "x, y, z; …" and
  // interpolation "linear" or "smooth").
  bool setPath(const QString& kind,
               const QString& first,
               const QString& second = {},
               const QString& third = {});

 public slots:
  void setStage(int stage);
  void refresh();
  // Paths shown in `system`'s lengths (typing takes any unit).
  void setUnitSystem(UnitSystem system);

 signals:
  // The move shown (-1 when none): its handles go into the viewport.
  void moveSelected(int stage, int move);

 private:
  void ShowKind(const QString& kind);
  void CommitFields();
  bool Apply(const QString& what, const Scene& after);

  SceneDocument* document_;
  int stage_ = -1;
  QListWidget* list_;
  QComboBox *carried_, *kind_;
  QFormLayout* form_;
  QLineEdit *first_, *second_, *third_;
  QLabel* message_;
  UnitSystem units_ = UnitSystem::kSI;
  bool refreshing_ = false;
};

}  // namespace drape
