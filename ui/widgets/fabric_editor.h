// The fabric's group of the property panel: its outline (a rectangle, a
// disk or a polygon, with its centre), how it is meshed (element counts for
// rectangles, an element size for the others), its imperfection, the count
// of the mesh the engine made, and why an edit of them was refused.
#pragma once

#include <QGroupBox>

#include <nlohmann/json_fwd.hpp>

#include "core/model/unit_system.h"

class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace drape {

class ImperfectionEditor;
class MeshSummary;
class SceneDocument;

class FabricEditor : public QGroupBox {
  Q_OBJECT
 public:
  explicit FabricEditor(SceneDocument* document, QWidget* parent = nullptr);

  QComboBox* outlineShape() const { return shape_; }
  QLineEdit* outlineExtent() const { return extent_; }
  QLineEdit* outlineCenter() const { return center_; }
  QLineEdit* elementSize() const { return element_size_; }
  QSpinBox* elementsX() const { return nx_; }
  QSpinBox* elementsY() const { return ny_; }
  ImperfectionEditor* imperfection() const { return imperfection_; }
  MeshSummary* meshInfo() const { return mesh_info_; }
  QString message() const;

  // The outline: shape "rectangle" (extent "width, height"), "disk" (extent
  // the radius) or "polygon" (extent "x, y; x, y; …"), with its centre
  // ("x, y"; not for polygons); units allowed. Read by the scene reader;
  // false with its message when wrong.
  bool setOutline(const QString& shape, const QString& extent, const QString& center = "0, 0");
  // The target element edge of outlines meshed by size.
  bool setElementSize(const QString& size);

 public slots:
  void refresh();  // from the document's scene
  void setUnitSystem(UnitSystem system);

 private:
  void ConnectFields();
  void EditMesh();
  void ShowOutline();
  bool ApplyFabric(const QString& what, const nlohmann::json& fabric);

  SceneDocument* document_;
  QFormLayout* form_;
  QComboBox* shape_;
  QLineEdit *extent_, *center_, *element_size_;
  QSpinBox *nx_, *ny_;
  ImperfectionEditor* imperfection_;
  MeshSummary* mesh_info_;
  QLabel* message_;
  UnitSystem units_ = UnitSystem::kSI;
  bool refreshing_ = false;
};

}  // namespace drape
