// File ▸ Import pattern…: a piece of a pattern file (DXF in the AAMA
// layout) as the fabric's outline — the file, the piece (each listed with
// its area, notches and grain line), where it lies on the table (position,
// rotation, turned over) and the element size. Import is one undoable
// edit, checked by the scene reader like any other.
#pragma once

#include <QDialog>

#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;

namespace drape {

class SceneDocument;

class PatternImportDialog : public QDialog {
  Q_OBJECT
 public:
  explicit PatternImportDialog(SceneDocument* document, QWidget* parent = nullptr);

  // The controls, for tests and scripts.
  QLineEdit* file() const { return file_; }
  QComboBox* piece() const { return piece_; }
  QLineEdit* position() const { return position_; }
  QLineEdit* rotation() const { return rotation_; }
  QCheckBox* flip() const { return flip_; }
  QLineEdit* elementSize() const { return element_size_; }
  QString message() const;

  // Reads file() and lists its pieces; false with the reader's message.
  bool load();
  // The chosen piece as the fabric's outline, its grain line (when it has
  // one) as the warp (one edit); false with the reason shown.
  bool importPiece();

 private:
  // The file as the scene names it: relative to the scene's folder when it
  // lies in it, else absolute.
  QString SceneReference() const;

  SceneDocument* document_;
  QLineEdit *file_, *position_, *rotation_, *element_size_;
  QComboBox* piece_;
  QCheckBox* flip_;
  QLabel* message_;
  std::vector<bool> has_grain_;  // per listed piece
};

}  // namespace drape
