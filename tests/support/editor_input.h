// What the workbench's editor tests (tests/widgets/*editors_test.cc) do as
// a hand would: find where a world point is drawn, press, drag and release
// the mouse there; and the files they open and save.
#pragma once

#include <unistd.h>

#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <QApplication>
#include <QMouseEvent>
#include <QPoint>
#include <QString>
#include <QWidget>

#include <Eigen/Core>

#include <filesystem>
#include <string>

#include "support/test_paths.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape::test {

// Where a world point is drawn in the viewport, in widget coordinates.
inline QPoint OnScreen(VtkViewport* viewport, const Eigen::Vector3d& p) {
  vtkRenderer* r = viewport->renderWindow()->GetRenderers()->GetFirstRenderer();
  r->SetWorldPoint(p.x(), p.y(), p.z(), 1.0);
  r->WorldToDisplay();
  double d[3];
  r->GetDisplayPoint(d);
  const double dpr = viewport->devicePixelRatioF();
  return QPoint(qRound(d[0] / dpr), qRound(viewport->height() - (d[1] + 1) / dpr));
}

inline void Mouse(
    QWidget* w, QEvent::Type type, QPoint at, Qt::MouseButton button, Qt::MouseButtons held) {
  QMouseEvent event(type, QPointF(at), QPointF(w->mapToGlobal(at)), button, held, Qt::NoModifier);
  QApplication::sendEvent(w, &event);
}

// Press, ten moves, release: what a hand does.
inline void Drag(QWidget* w, QPoint from, QPoint to) {
  Mouse(w, QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
  for (int k = 1; k <= 10; ++k)
    Mouse(w, QEvent::MouseMove, from + (to - from) * k / 10, Qt::NoButton, Qt::LeftButton);
  Mouse(w, QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

inline std::string TempFile(const std::string& stem) {
  return (std::filesystem::temp_directory_path() /
          (stem + "-" + std::to_string(getpid()) + ".json"))
      .string();
}

inline QString StripFold() {
  return QString::fromStdString((ScenesDir() / "strip-fold.json").string());
}

}  // namespace drape::test
