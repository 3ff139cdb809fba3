// The rigid obstacles of a scene: add a table, block, rod, sphere or a form
// (the fabric laid on it; FormEditor places it by hand), edit
// one as the scene file writes it (JSON, units allowed: "5 cm"), remove
// one; and the contact's law (penalty or barrier), its penalty or barrier
// distance, and friction. The text is read by the scene reader, so a wrong key
// or value gets the reader's message naming it. The selected obstacle also gets a handle in the
// viewport to move it (MainWindow).
#pragma once

#include <QWidget>

#include <nlohmann/json.hpp>

#include "core/model/unit_system.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPlainTextEdit;

namespace drape {

class FormEditor;
class SceneDocument;
struct Scene;

class ObstaclesPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ObstaclesPanel(SceneDocument* document, QWidget* parent = nullptr);

  QListWidget* list() const { return list_; }
  QPlainTextEdit* text() const { return text_; }
  QString message() const;

  // kind: "table", "block", "rod" or "sphere", placed under the part, or a
  // form of the catalogue by its name ("Dress form, medium"), stood on the
  // floor under the fabric's middle with the fabric laid on it.
  bool add(const QString& kind);
  // The selected form's placement (shown when the obstacle is a mesh).
  FormEditor* form() const { return form_; }
  bool removeSelected();
  // The selected obstacle from its JSON text.
  bool applyText(const QString& json);
  // How the fabric touches every obstacle: penalty k per area ("auto" or,
  // e.g., "1e8 N/m^3"; ignored under the barrier law) and Coulomb friction μ.
  bool setContact(const QString& penalty, const QString& friction);
  // contact.law: "penalty" or "barrier".
  bool setContactLaw(const QString& law);
  // The barrier's distance d̂ ("auto": half the thickness, or e.g. "0.1 mm").
  bool setBarrierDistance(const QString& distance);
  // Whether the fabric's layers are kept a thickness apart (contact.self).
  bool setSelfContact(bool on);
  QCheckBox* selfContact() const { return self_; }
  QLineEdit* penalty() const { return penalty_; }
  QLineEdit* barrierDistance() const { return barrier_; }
  QComboBox* contactLaw() const { return law_; }

 public slots:
  void refresh();
  // The obstacle's lengths and the contact penalty shown in `system`'s
  // units (typing takes any unit).
  void setUnitSystem(UnitSystem system);

 signals:
  void obstacleSelected(int index);  // -1: none

 private:
  bool Apply(const QString& what, const Scene& after);
  bool AddForm(int item);
  void ShowContact();
  void ShowText();

  SceneDocument* document_;
  QListWidget* list_;
  QComboBox* kind_;
  FormEditor* form_;
  QPlainTextEdit* text_;
  bool ApplyContact(const QString& what, nlohmann::json document);

  QComboBox* law_;
  QLineEdit *penalty_, *barrier_, *friction_;
  QCheckBox* self_;
  // As refresh() wrote them.
  QString penalty_shown_, barrier_shown_, friction_shown_;
  QLabel* message_;
  QLabel* text_label_ = nullptr;
  UnitSystem units_ = UnitSystem::kSI;
};

}  // namespace drape
