// The material dialog, in three tabs: the library as cards in a lab's
// figures (FabricCards), a fabric entered from a KES-FB or FAST summary
// (FabricSummaryForm), or a bending law imported from
// Kawabata (KES-FB2) data — file, branch, columns, law (the measured curve
// or the paper's polynomial) — with the measured points and the law drawn
// together (Qt Charts) and the fit's RMS error. The same reader and fits as
// the scene reader and `drape material fit`. Apply makes one undoable edit.
#pragma once

#include <QDialog>

#include <memory>
#include <optional>
#include <vector>

#include "core/model/scene.h"
#include "core/model/unit_system.h"

class QChart;
class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;
class QTabWidget;

namespace drape {

class MomentCurvatureLaw;

class FabricCards;
class FabricSummaryForm;
class SceneDocument;

class MaterialDialog : public QDialog {
  Q_OBJECT
 public:
  explicit MaterialDialog(SceneDocument* document, QWidget* parent = nullptr);

  // The controls, for tests and scripts.
  QLineEdit* file() const { return file_; }
  QComboBox* branch() const { return branch_; }
  QComboBox* law() const { return law_; }
  QSpinBox* degree() const { return degree_; }
  // The library as cards (Library tab); a fabric entered from a lab's
  // summary (its own tab).
  FabricCards* library() const { return cards_; }
  FabricSummaryForm* labSummary() const { return summary_; }
  QTabWidget* tabs() const { return tabs_; }
  // Chooses the library card of `name`; false when there is none.
  bool chooseLibrary(const QString& name);
  // "both" (one law), "warp" or "weft" (that direction's law only).
  QComboBox* direction() const { return direction_; }

  // Reads the file and fits the law; false with the reader's message (line
  // and problem) shown in the dialog.
  bool preview();
  QString message() const;
  int measuredPoints() const { return measured_points_; }
  // The previewed law into the scene's bending for direction() (one edit);
  // false if none, or when the engine refuses it (the message says why).
  bool applyBending();
  // The library fabric chosen into the scene (one edit).
  bool applyLibrary();

  // The plot's axes and values (and the message's numbers) in `system`;
  // the data are read and fitted in KES units (1/cm, gf·cm/cm) as before.
  void setUnitSystem(UnitSystem system);
  UnitSystem unitSystem() const { return units_; }
  QChart* chart() const { return chart_; }

 private:
  SceneDocument* document_;
  QLineEdit* file_;
  QComboBox *branch_, *law_, *direction_;
  QTabWidget* tabs_;
  FabricCards* cards_;
  FabricSummaryForm* summary_;
  QLineEdit *curvature_column_, *moment_column_;
  QSpinBox* degree_;
  QLabel* message_;
  QChart* chart_;
  void Draw();
  QString Summary() const;

  std::optional<BendingLaw> previewed_;
  int measured_points_ = 0;
  UnitSystem units_ = UnitSystem::kSI;
  // The last preview, for drawing it again in other units: the measured
  // points [1/m, N·m/m] and the law, which takes and gives KES units.
  struct Plot {
    std::vector<double> curvature, moment;
    std::shared_ptr<const MomentCurvatureLaw> law;
    QString law_name, read, warnings;
    double rms_kes = -1;  // gf·cm/cm; < 0 for the curve law
  };
  std::optional<Plot> plot_;
};

}  // namespace drape
