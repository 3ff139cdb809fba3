// A QOpenGLWidget that hosts a vtkGenericOpenGLRenderWindow: the bridge
// between Qt 6 and Debian's VTK (whose own Qt module is built for Qt 5),
// doing what VTK's QVTKOpenGLNativeWidget and QVTKRenderWindowAdapter do:
// VTK renders with Qt's context (context callbacks, OpenGLInitContext),
// into its own framebuffer, which paintGL blits into the widget's
// defaultFramebufferObject with the GL state saved and restored around it.
// Mouse and wheel events drive a trackball-camera interactor.
#pragma once

#include <vtkSmartPointer.h>
#include <Eigen/Core>
#include <QOpenGLWidget>
#include <QSurfaceFormat>

#include <optional>
#include <vector>

class vtkActor;
class vtkGenericOpenGLRenderWindow;
class vtkGenericRenderWindowInteractor;
class vtkObject;
class vtkPolyData;
class vtkRenderer;
class vtkRenderWindowInteractor;

namespace drape {

class VtkViewport : public QOpenGLWidget {
  Q_OBJECT
 public:
  explicit VtkViewport(QWidget* parent = nullptr);
  ~VtkViewport() override;

  // What VTK's OpenGL2 backend needs of the context (3.2 core, depth and
  // stencil): set it with QSurfaceFormat::setDefaultFormat before the
  // QApplication is made.
  static QSurfaceFormat defaultFormat();

  // The window to add renderers to (FrameRenderer's `window`).
  vtkGenericOpenGLRenderWindow* renderWindow() const;
  // Asks for a VTK render at the next paint (after the scene changed).
  void requestRender();
  // Paints (VTK renders shown) since the viewport was made: for frame rates.
  long long paints() const { return paints_; }
  // For 3-D widgets (path handles) that take mouse events before the camera.
  vtkRenderWindowInteractor* interactor() const;

  // The surface point under a widget position (logical pixels), if any.
  std::optional<Eigen::Vector3d> pickSurface(const QPointF& position) const;
  // In pick mode a left click picks (signal picked) instead of turning the
  // camera.
  void setPickMode(bool on) { pick_mode_ = on; }
  bool pickMode() const { return pick_mode_; }
  // Points drawn over the scene in `renderer` (picked nodes); none: hidden.
  void showMarkers(vtkRenderer* renderer, const std::vector<Eigen::Vector3d>& points);

 signals:
  void picked(const Eigen::Vector3d& point);
  void resized();
  // The user turned, moved or zoomed the camera (mouse or wheel).
  void cameraTouched();

 protected:
  void initializeGL() override;
  void resizeGL(int width, int height) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;

 private:
  void OnWindowEvent(vtkObject* caller, unsigned long event, void* data);
  void ForwardMouse(QMouseEvent* event, unsigned long vtk_event);

  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  std::vector<unsigned long> observers_;
  vtkSmartPointer<vtkPolyData> marker_points_;
  vtkSmartPointer<vtkActor> markers_;
  vtkSmartPointer<vtkRenderer> marker_renderer_;  // kept: renderers are remade on edits
  bool pick_mode_ = false;
  bool in_paint_ = false;
  int framebuffer_retries_ = 0;
  long long paints_ = 0;  // new framebuffers asked of Qt (see paintGL)
};

}  // namespace drape
