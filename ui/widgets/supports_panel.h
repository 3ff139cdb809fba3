// The supports of a scene: each one's name, which nodes it holds (a
// selection rule of reference coordinates, so it holds at any mesh density)
// and how (position or clamp). Add one on an edge, at the corners or at a
// point; change its rule or fixity; remove it. Every change is checked by the
// scene reader's and the engine's own rules first (a rule that matches no
// node is refused with its message) and is one undoable edit.
#pragma once

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListWidget;

namespace drape {

class SceneDocument;
struct Scene;

class SupportsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit SupportsPanel(SceneDocument* document, QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }
  QString message() const;

  // rule: "left", "right", "bottom", "top" (an edge), "corners", or "point"
  // (at x, y [m]); fixity 0: position, 1: clamp.
  bool addSupport(const QString& rule, int fixity, double x = 0, double y = 0);
  bool setFixity(int fixity);  // of the selected support
  bool removeSelected();

 public slots:
  void refresh();

 private:
  bool Apply(const QString& what, const Scene& after);

  SceneDocument* document_;
  QListWidget* list_;
  QComboBox *rule_, *fixity_;
  QDoubleSpinBox *x_, *y_;
  QLabel* message_;
  bool refreshing_ = false;
};

}  // namespace drape
