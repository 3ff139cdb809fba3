// The materials library as cards, one per fabric, in the figures a textile
// lab reports: its name, the warp's and weft's bending rigidity B
// (gf·cm²/cm), shear rigidity G (gf/(cm·deg)), weight (g/m²) and thickness
// (mm), each as the engine builds the fabric (core/fe/textile_figures.h).
#pragma once

#include <QListWidget>

#include <filesystem>

namespace drape {

class FabricCards : public QListWidget {
  Q_OBJECT
 public:
  // The library as a scene in `scene_directory` finds it.
  explicit FabricCards(const std::filesystem::path& scene_directory, QWidget* parent = nullptr);

  // The library name of the chosen card ("" when none).
  QString chosen() const;
  // Chooses the card of `name`; false when the library has none.
  bool choose(const QString& name);
};

}  // namespace drape
