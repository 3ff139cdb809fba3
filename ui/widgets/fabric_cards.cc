#include "ui/widgets/fabric_cards.h"

#include <cmath>
#include <exception>
#include <string>

#include "core/fe/textile_figures.h"
#include "core/io/library_fabric.h"
#include "core/io/material_library.h"

namespace drape {
namespace {

// Two lines: the file's own name, then its figures; B once when warp and
// weft agree.
QString CardText(const std::string& name, const std::filesystem::path& dir) {
  QString title = QString::fromStdString(name);
  try {
    if (const auto file = FindLibraryMaterial(name, MaterialLibraryDirs(dir)))
      title = QString::fromStdString(ReadLibraryMaterial(*file).name);
    const TextileFigures f = FiguresOf(LibraryFabric(name, dir));
    const QString bending = std::abs(f.bending_warp - f.bending_weft) <= 1e-9 * f.bending_warp
                                ? QString("B %1").arg(f.bending_warp, 0, 'g', 3)
                                : QString("B warp %1, weft %2")
                                      .arg(f.bending_warp, 0, 'g', 3)
                                      .arg(f.bending_weft, 0, 'g', 3);
    return QString("%1\n%2 gf·cm²/cm · G %3 gf/(cm·deg) · %4 g/m² · %5 mm  [%6]")
        .arg(title, bending)
        .arg(f.shear, 0, 'g', 3)
        .arg(f.weight_g_per_m2, 0, 'f', 0)
        .arg(f.thickness_mm, 0, 'g', 3)
        .arg(QString::fromStdString(name));
  } catch (const std::exception& e) {
    return QString("%1\ncannot be read: %2").arg(title, e.what());
  }
}

}  // namespace

FabricCards::FabricCards(const std::filesystem::path& scene_directory, QWidget* parent)
    : QListWidget(parent) {
  setAlternatingRowColors(true);
  setWordWrap(true);
  setToolTip(
      "B: bending rigidity as KES-FB2 reads it (the mean slope between 0.5 and 1.5 1/cm); G: "
      "shear rigidity; weight per area; thickness. `drape material show NAME` prints more");
  for (const std::string& name : LibraryMaterialNames(MaterialLibraryDirs(scene_directory))) {
    auto* card = new QListWidgetItem(CardText(name, scene_directory), this);
    card->setData(Qt::UserRole, QString::fromStdString(name));
  }
  if (count() > 0) setCurrentRow(0);
}

QString FabricCards::chosen() const {
  return currentItem() ? currentItem()->data(Qt::UserRole).toString() : QString();
}

bool FabricCards::choose(const QString& name) {
  for (int i = 0; i < count(); ++i)
    if (item(i)->data(Qt::UserRole).toString() == name) {
      setCurrentRow(i);
      return true;
    }
  return false;
}

}  // namespace drape
