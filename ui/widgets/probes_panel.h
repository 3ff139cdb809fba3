// The probes of a scene: named points of the part (reference x, y) whose
// positions each step reports and the probe plot draws. Add one at typed
// coordinates or at the node picked in the viewport; remove one. Checked by
// the reader's and the engine's rules (a probe off the part is refused).
#pragma once

#include <QWidget>

#include <array>
#include <vector>

#include "core/model/unit_system.h"

class QLabel;
class QLineEdit;
class QListWidget;

namespace drape {

class SceneDocument;
struct Scene;

class ProbesPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ProbesPanel(SceneDocument* document, QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }
  QLineEdit* at() const { return at_; }
  QString message() const;

  // A probe at reference (x, y) [m].
  bool add(double x, double y);
  bool removeSelected();

 public slots:
  void refresh();
  // Positions shown in `system`'s unit of length (typing takes any unit).
  void setUnitSystem(UnitSystem system);
  // Reference positions of the picked nodes: "Add at picked" uses the last.
  void setPicked(const std::vector<std::array<double, 2>>& at);

 private:
  bool Apply(const QString& what, const Scene& after);

  SceneDocument* document_;
  QListWidget* list_;
  QLineEdit* at_;
  QLabel* message_;
  std::vector<std::array<double, 2>> picked_;
  UnitSystem units_ = UnitSystem::kSI;
};

}  // namespace drape
