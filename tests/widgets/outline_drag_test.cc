// A polygon outline's vertices dragged in the view: the vertex lands under
// the mouse in the part's plane, the mesh is remade for the new outline
// (its area the polygon's), a drag that would make the outline cross
// itself is refused, and undo restores the outline and the mesh.
#include <gtest/gtest.h>

#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "core/model/polygon_checks.h"
#include "support/editor_input.h"
#include "support/mesh_area.h"
#include "support/temp_dir.h"
#include "ui/widgets/main_window.h"
#include "ui/widgets/model_tree.h"
#include "ui/widgets/outline_handles.h"
#include "ui/widgets/scene_document.h"
#include "widgets/gui_test.h"

namespace drape {
namespace {

using test::Drag;
using test::MeshArea;
using test::OnScreen;

double PolygonArea(const PolygonOutline& outline) {
  std::vector<Eigen::Vector2d> points;
  for (const Vec2& v : outline.vertices) points.emplace_back(v[0], v[1]);
  return std::abs(ShoelaceArea(points));
}

TEST_F(Widgets, AnOutlineVertexIsDraggedInTheViewAndUndone) {
  test::TempDir dir("outline-drag");
  // A 20 cm square 1 cm above the table plane, hung by its corners.
  std::ofstream(dir / "square.json") << R"({"drape_scene": 1,
    "fabric": {"outline": {"polygon": [["-10 cm", "-10 cm"], ["10 cm", "-10 cm"],
                                       ["10 cm", "10 cm"], ["-10 cm", "10 cm"]]},
               "mesh": {"size": "2 cm"}, "elevation": "1 cm"},
    "material": {"library": "cotton-twill"},
    "supports": [{"name": "corners", "select": {"corners": true}}],
    "stages": [{"name": "weight", "kind": "gravity"}]})";
  MainWindow window;
  window.show();
  ASSERT_TRUE(window.openScene(QString::fromStdString((dir / "square.json").string())));
  SceneDocument* doc = window.document();
  const Scene before = doc->scene();
  const Mesh mesh_before = doc->model()->mesh;
  window.tree()->setCurrentItem(window.tree()->item(ModelTree::Part::kFabric));
  QTest::qWait(200);

  OutlineHandles* handles = window.outlineHandles();
  ASSERT_EQ(handles->count(), 4);
  EXPECT_LT((handles->position(2) - Eigen::Vector3d(0.10, 0.10, 0.01)).norm(), 1e-15);

  // Vertex 3 (10, 10) cm dragged out towards (16, 14) cm.
  const QPoint from = OnScreen(window.viewport(), handles->position(2));
  const QPoint to = OnScreen(window.viewport(), {0.16, 0.14, 0.01});
  Drag(window.viewport(), from, to);
  QTest::qWait(100);
  const auto& moved = std::get<PolygonOutline>(doc->scene().fabric.outline);
  const Vec2 v = moved.vertices[2];
  EXPECT_GT(std::hypot(v[0] - 0.10, v[1] - 0.10), 0.03) << "the drag did not move the vertex";
  // It lies in the part's plane under the mouse, where the mouse was let
  // go (a pixel is about 1 mm there).
  EXPECT_LT(std::hypot(v[0] - 0.16, v[1] - 0.14), 2e-3) << v[0] << ", " << v[1];
  EXPECT_EQ(moved.vertices[0], (Vec2{-0.10, -0.10}));
  EXPECT_DOUBLE_EQ(doc->scene().fabric.elevation, 0.01);
  // The mesh is the new outline's.
  EXPECT_NEAR(MeshArea(*doc->model()) / PolygonArea(moved), 1.0, 1e-12);
  EXPECT_GT(MeshArea(*doc->model()), 0.04 + 1e-3);  // dragged outwards
  EXPECT_EQ(doc->undoStack()->undoText(), "move outline vertex 3");
  if (const char* shot = getenv("DRAPE_OUTLINE_DRAG_SHOT")) window.grab().save(shot);

  // Across the opposite side, the outline would cross itself: refused, and
  // the handle goes back to the vertex.
  const Scene dragged = doc->scene();
  QTest::qWait(100);
  ASSERT_EQ(handles->count(), 4);
  Drag(window.viewport(),
       OnScreen(window.viewport(), handles->position(2)),
       OnScreen(window.viewport(), {-0.20, 0.0, 0.01}));
  QTest::qWait(100);
  EXPECT_EQ(doc->scene(), dragged);
  ASSERT_EQ(handles->count(), 4);
  EXPECT_LT((handles->position(2) - Eigen::Vector3d(v[0], v[1], 0.01)).norm(), 1e-12);

  // Undo: the square and its mesh, node for node.
  doc->undoStack()->undo();
  QTest::qWait(50);
  EXPECT_EQ(doc->scene(), before);
  EXPECT_EQ(doc->model()->mesh.positions, mesh_before.positions);
  EXPECT_EQ(doc->model()->mesh.quads, mesh_before.quads);
  EXPECT_NEAR(MeshArea(*doc->model()), 0.04, 1e-12);
  ASSERT_EQ(handles->count(), 4);
  EXPECT_LT((handles->position(2) - Eigen::Vector3d(0.10, 0.10, 0.01)).norm(), 1e-15);
}

}  // namespace
}  // namespace drape
