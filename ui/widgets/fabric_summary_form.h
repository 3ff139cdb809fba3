// A fabric entered from a lab's summary (KES-FB or FAST): thickness,
// weight, bending rigidity of warp and weft, shear rigidity and the
// membrane's stiffness per width, in the units the instruments report;
// shown for the scene's fabric, applied as one undoable edit
// (MaterialFromSummary: linear bending, an orthotropic membrane).
#pragma once

#include <QWidget>

#include "core/fe/textile_figures.h"

class QDoubleSpinBox;
class QLabel;

namespace drape {

class SceneDocument;

class FabricSummaryForm : public QWidget {
  Q_OBJECT
 public:
  explicit FabricSummaryForm(SceneDocument* document, QWidget* parent = nullptr);

  FabricSummary summary() const;
  void setSummary(const FabricSummary& summary);
  // The scene's material becomes the summary's (its warp angle kept).
  bool apply();
  QString message() const;

 public slots:
  void showScene();  // the fields from the scene's fabric

 private:
  SceneDocument* document_;
  QDoubleSpinBox *thickness_, *weight_, *bending_warp_, *bending_weft_, *shear_;
  QDoubleSpinBox *tensile_warp_, *tensile_weft_, *poisson_;
  QLabel* message_;
};

}  // namespace drape
