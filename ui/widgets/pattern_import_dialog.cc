#include "ui/widgets/pattern_import_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/io/dxf_pattern_reader.h"
#include "core/model/outline_geometry.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/typed_json.h"

namespace drape {
namespace {

// "FRONT — 1 220 cm², 4 notches, grain 30°" for the piece list's tooltip.
QString Summary(const PatternPiece& piece) {
  const double area = PieceArea(piece);
  QString text = QString("%1 cm², %2 notches, %3 drill holes")
                     .arg(area * 1e4, 0, 'f', 1)
                     .arg(piece.notches.size())
                     .arg(piece.drills.size());
  if (!piece.holes.empty()) text += QString(", %1 cut-outs").arg(piece.holes.size());
  text += piece.grain ? QString(", grain %1°").arg(GrainAngleDeg(piece), 0, 'f', 1)
                      : QString(", no grain line");
  return text;
}

}  // namespace

PatternImportDialog::PatternImportDialog(SceneDocument* document, QWidget* parent)
    : QDialog(parent), document_(document) {
  setWindowTitle("Import pattern");
  auto* form = new QFormLayout(this);
  file_ = new QLineEdit(this);
  file_->setPlaceholderText("a DXF in the AAMA layout (ASTM D6673)");
  auto* browse = new QPushButton("Browse…", this);
  auto* file_row = new QHBoxLayout;
  file_row->addWidget(file_);
  file_row->addWidget(browse);
  form->addRow("pattern file", file_row);
  piece_ = new QComboBox(this);
  piece_->setToolTip("the pattern's pieces (one block each in the file)");
  form->addRow("piece", piece_);
  position_ = new QLineEdit("0, 0", this);
  position_->setToolTip("where the piece's origin lies on the table: x, y; units allowed");
  form->addRow("position", position_);
  rotation_ = new QLineEdit("0", this);
  rotation_->setToolTip("turned counter-clockwise by this angle [deg] about its origin");
  form->addRow("rotation [deg]", rotation_);
  flip_ = new QCheckBox("turned over (its other face up)", this);
  form->addRow("", flip_);
  element_size_ = new QLineEdit("1 cm", this);
  element_size_->setToolTip("the mesh's target element edge, e.g. 1 cm");
  form->addRow("element size", element_size_);
  message_ = MakeMessageLabel(this);
  form->addRow(message_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
  buttons->addButton("Import", QDialogButtonBox::AcceptRole);
  form->addRow(buttons);

  connect(browse, &QPushButton::clicked, this, [this] {
    const QString file =
        QFileDialog::getOpenFileName(this, "Import pattern", {}, "Pattern files (*.dxf *.DXF)");
    if (file.isEmpty()) return;
    file_->setText(file);
    load();
  });
  connect(file_, &QLineEdit::editingFinished, this, [this] { load(); });
  connect(piece_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index >= 0) message_->setText(piece_->itemData(index, Qt::ToolTipRole).toString());
  });
  connect(buttons, &QDialogButtonBox::accepted, this, [this] {
    if (importPiece()) accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

QString PatternImportDialog::message() const {
  return message_->text();
}

bool PatternImportDialog::load() {
  piece_->clear();
  has_grain_.clear();
  try {
    const DxfPattern pattern = ReadDxfPattern(file_->text().toStdString());
    for (const PatternPiece& piece : pattern.pieces) {
      piece_->addItem(QString::fromStdString(piece.name));
      piece_->setItemData(piece_->count() - 1, Summary(piece), Qt::ToolTipRole);
      has_grain_.push_back(piece.grain.has_value());
    }
    message_->setText(piece_->itemData(0, Qt::ToolTipRole).toString());
    return true;
  } catch (const DxfPatternError& e) {
    message_->setText(QString::fromStdString(e.what()));
    return false;
  }
}

QString PatternImportDialog::SceneReference() const {
  const std::filesystem::path file = std::filesystem::absolute(file_->text().toStdString());
  if (document_->file().isEmpty()) return QString::fromStdString(file.string());
  const std::filesystem::path relative =
      file.lexically_normal().lexically_relative(std::filesystem::absolute(document_->directory()));
  const bool inside = !relative.empty() && *relative.begin() != "..";
  return QString::fromStdString(inside ? relative.string() : file.string());
}

bool PatternImportDialog::importPiece() {
  if (piece_->count() == 0 && !load()) return false;
  try {
    nlohmann::json pattern{{"file", SceneReference().toStdString()},
                           {"piece", piece_->currentText().toStdString()},
                           {"at", TypedList(position_->text())},
                           {"rotation_deg", TypedQuantity(rotation_->text())},
                           {"flip", flip_->isChecked()}};
    nlohmann::json scene = document_->json();
    scene["fabric"]["outline"] = {{"pattern", pattern}};
    scene["fabric"]["mesh"] = {{"size", TypedQuantity(element_size_->text())}};
    const int index = piece_->currentIndex();
    if (index >= 0 && index < static_cast<int>(has_grain_.size()) && has_grain_[index])
      scene["material"]["angle_deg"] = "grain";
    return ApplyOrSay(document_,
                      message_,
                      QString("import piece %1 of %2")
                          .arg(piece_->currentText(), QFileInfo(file_->text()).fileName()),
                      scene);
  } catch (const std::exception& e) {
    message_->setText(QString::fromStdString(e.what()));
    return false;
  }
}

}  // namespace drape
