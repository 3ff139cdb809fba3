// The fabric's imperfection: a small out-of-plane offset of the flat part
// (to start buckling), its amplitude typed with its unit, its random seed
// and its pattern. Read by the scene reader, so wrong text gets its message.
#pragma once

#include <QWidget>

#include "core/model/unit_system.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace drape {

class SceneDocument;

class ImperfectionEditor : public QWidget {
  Q_OBJECT
 public:
  // A refused edit is said in `message`: the fabric's message line, as the
  // imperfection is one row of the fabric.
  ImperfectionEditor(SceneDocument* document, QLabel* message, QWidget* parent = nullptr);

  QLineEdit* amplitude() const { return amplitude_; }
  QSpinBox* seed() const { return seed_; }
  QComboBox* pattern() const { return pattern_; }

  // Amplitude typed ("0" or nothing for none), seed, pattern "smooth" or
  // "nodal"; false with the reader's message when wrong.
  bool setImperfection(const QString& amplitude, int seed, const QString& pattern);

 public slots:
  void refresh();  // from the document's scene
  void setUnitSystem(UnitSystem system);

 private:
  void Commit();

  SceneDocument* document_;
  QLabel* message_;
  QLineEdit* amplitude_;
  QSpinBox* seed_;
  QComboBox* pattern_;
  UnitSystem units_ = UnitSystem::kSI;
  bool refreshing_ = false;
};

}  // namespace drape
