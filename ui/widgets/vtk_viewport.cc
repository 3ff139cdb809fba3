#include "ui/widgets/vtk_viewport.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellPicker.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QTimer>
#include <QWheelEvent>

namespace drape {

VtkViewport::VtkViewport(QWidget* parent) : QOpenGLWidget(parent) {
  window_ = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  interactor_ = vtkSmartPointer<vtkGenericRenderWindowInteractor>::New();
  interactor_->SetRenderWindow(window_);
  auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  interactor_->SetInteractorStyle(style);
  // The interactor asks for renders through the widget: paintGL renders.
  interactor_->EnableRenderOff();
  for (unsigned long event : {vtkCommand::WindowMakeCurrentEvent,
                              vtkCommand::WindowIsCurrentEvent,
                              vtkCommand::WindowFrameEvent})
    observers_.push_back(window_->AddObserver(event, this, &VtkViewport::OnWindowEvent));
  setMouseTracking(false);
  setFocusPolicy(Qt::StrongFocus);
  marker_points_ = vtkSmartPointer<vtkPolyData>::New();
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(marker_points_);
  markers_ = vtkSmartPointer<vtkActor>::New();
  markers_->SetMapper(mapper);
  markers_->GetProperty()->SetColor(0.9, 0.1, 0.6);
  markers_->GetProperty()->SetPointSize(9);
  markers_->GetProperty()->SetRenderPointsAsSpheres(true);
  markers_->PickableOff();
}

vtkRenderWindowInteractor* VtkViewport::interactor() const {
  return interactor_;
}

std::optional<Eigen::Vector3d> VtkViewport::pickSurface(const QPointF& position) const {
  vtkRenderer* renderer = window_->GetRenderers()->GetFirstRenderer();
  if (!renderer) return std::nullopt;
  const double dpr = devicePixelRatioF();
  auto picker = vtkSmartPointer<vtkCellPicker>::New();
  picker->SetTolerance(0.002);
  // VTK's display y runs up.
  if (!picker->Pick(position.x() * dpr, (height() - position.y()) * dpr - 1, 0, renderer))
    return std::nullopt;
  const double* p = picker->GetPickPosition();
  return Eigen::Vector3d(p[0], p[1], p[2]);
}

void VtkViewport::showMarkers(vtkRenderer* renderer, const std::vector<Eigen::Vector3d>& points) {
  if (marker_renderer_ && marker_renderer_ != renderer) marker_renderer_->RemoveActor(markers_);
  marker_renderer_ = renderer;
  auto xyz = vtkSmartPointer<vtkPoints>::New();
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  for (const Eigen::Vector3d& p : points) {
    const vtkIdType id = xyz->InsertNextPoint(p.x(), p.y(), p.z());
    vertices->InsertNextCell(1, &id);
  }
  marker_points_->SetPoints(xyz);
  marker_points_->SetVerts(vertices);
  marker_points_->Modified();
  if (renderer && !renderer->HasViewProp(markers_)) renderer->AddActor(markers_);
  update();
}

VtkViewport::~VtkViewport() {
  makeCurrent();
  for (unsigned long id : observers_) window_->RemoveObserver(id);
  window_->Finalize();
  window_->SetReadyForRendering(false);
  doneCurrent();
}

QSurfaceFormat VtkViewport::defaultFormat() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 2);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setSwapBehavior(QSurfaceFormat::DoubleBuffer);
  format.setRedBufferSize(8);
  format.setGreenBufferSize(8);
  format.setBlueBufferSize(8);
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(8);
  format.setAlphaBufferSize(8);
  format.setSamples(0);
  return format;
}

vtkGenericOpenGLRenderWindow* VtkViewport::renderWindow() const {
  return window_;
}

void VtkViewport::requestRender() {
  update();
}

void VtkViewport::OnWindowEvent(vtkObject*, unsigned long event, void* data) {
  switch (event) {
    case vtkCommand::WindowMakeCurrentEvent:
      makeCurrent();
      break;
    case vtkCommand::WindowIsCurrentEvent:
      *static_cast<bool*>(data) = QOpenGLContext::currentContext() == context();
      break;
    case vtkCommand::WindowFrameEvent:
      // A render VTK started itself (an interaction): show it.
      if (!in_paint_) update();
      break;
  }
}

void VtkViewport::initializeGL() {
  // VTK caches GL state: start it from what Qt set up (Qt's framebuffer is
  // bound now), with the depth test VTK expects (Qt's default is GL_LESS).
  vtkOpenGLState* state = window_->GetState();
  state->Reset();
  state->vtkglDepthFunc(GL_LEQUAL);
  // VTK uses Qt's context: it must neither create nor swap one.
  window_->SetOwnContext(0);
  window_->SetFrameBlitMode(vtkOpenGLRenderWindow::NoBlit);
  window_->SetForceMaximumHardwareLineWidth(1);
  window_->SetReadyForRendering(true);
  // VTK's framebuffers start at the widget's size.
  window_->SetSize(static_cast<int>(width() * devicePixelRatioF()),
                   static_cast<int>(height() * devicePixelRatioF()));
  window_->OpenGLInitContext();
  interactor_->Initialize();
}

void VtkViewport::resizeGL(int width, int height) {
  const double dpr = devicePixelRatioF();
  const int w = static_cast<int>(width * dpr), h = static_cast<int>(height * dpr);
  window_->SetSize(w, h);
  interactor_->UpdateSize(w, h);
  emit resized();
}

void VtkViewport::paintGL() {
  QOpenGLExtraFunctions* gl = context()->extraFunctions();
  // Under Xvfb (Mesa) the first framebuffer Qt makes for a widget has been
  // seen incomplete (GL_FRAMEBUFFER_UNSUPPORTED): nothing drawn into it
  // shows. Qt makes a new one on a resize; ask for one.
  gl->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
  if (gl->glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE &&
      framebuffer_retries_ < 3) {
    ++framebuffer_retries_;
    QTimer::singleShot(0, this, [this] {
      const QSize size = this->size();
      resize(size.width() + 1, size.height());
      resize(size);
    });
    return;
  }
  in_paint_ = true;
  vtkOpenGLState* state = window_->GetState();
  // Qt changed GL state behind VTK's cache since the last paint.
  state->Reset();
  state->Push();
  state->vtkglDepthFunc(GL_LEQUAL);
  window_->Render();
  makeCurrent();  // a render may have made another widget's context current
  // VTK drew into its own (display) framebuffer: copy it into the widget's.
  const bool scissor = gl->glIsEnabled(GL_SCISSOR_TEST);
  if (scissor) gl->glDisable(GL_SCISSOR_TEST);  // the scissor box clips a blit
  vtkOpenGLFramebufferObject* display = window_->GetDisplayFramebuffer();
  const int* source = display->GetLastSize();
  const int w = static_cast<int>(width() * devicePixelRatioF());
  const int h = static_cast<int>(height() * devicePixelRatioF());
  gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, display->GetFBOIndex());
  gl->glReadBuffer(GL_COLOR_ATTACHMENT0);
  gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  const GLenum attachment = GL_COLOR_ATTACHMENT0;
  gl->glDrawBuffers(1, &attachment);
  gl->glBlitFramebuffer(0, 0, source[0], source[1], 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  if (scissor) gl->glEnable(GL_SCISSOR_TEST);
  state->Pop();
  ++paints_;
  in_paint_ = false;
}

void VtkViewport::ForwardMouse(QMouseEvent* event, unsigned long vtk_event) {
  const double dpr = devicePixelRatioF();
  const QPointF p = event->position();
  interactor_->SetEventInformationFlipY(static_cast<int>(p.x() * dpr),
                                        static_cast<int>(p.y() * dpr),
                                        (event->modifiers() & Qt::ControlModifier) ? 1 : 0,
                                        (event->modifiers() & Qt::ShiftModifier) ? 1 : 0);
  interactor_->InvokeEvent(vtk_event, event);
  update();
}

void VtkViewport::mousePressEvent(QMouseEvent* event) {
  if (pick_mode_ && event->button() == Qt::LeftButton) {
    if (const auto p = pickSurface(event->position())) emit picked(*p);
    return;
  }
  emit cameraTouched();  // (or a handle dragged: the view keeps its camera either way)
  switch (event->button()) {
    case Qt::LeftButton:
      ForwardMouse(event, vtkCommand::LeftButtonPressEvent);
      break;
    case Qt::MiddleButton:
      ForwardMouse(event, vtkCommand::MiddleButtonPressEvent);
      break;
    case Qt::RightButton:
      ForwardMouse(event, vtkCommand::RightButtonPressEvent);
      break;
    default:
      break;
  }
}

void VtkViewport::mouseReleaseEvent(QMouseEvent* event) {
  if (pick_mode_ && event->button() == Qt::LeftButton) return;
  switch (event->button()) {
    case Qt::LeftButton:
      ForwardMouse(event, vtkCommand::LeftButtonReleaseEvent);
      break;
    case Qt::MiddleButton:
      ForwardMouse(event, vtkCommand::MiddleButtonReleaseEvent);
      break;
    case Qt::RightButton:
      ForwardMouse(event, vtkCommand::RightButtonReleaseEvent);
      break;
    default:
      break;
  }
}

void VtkViewport::mouseMoveEvent(QMouseEvent* event) {
  ForwardMouse(event, vtkCommand::MouseMoveEvent);
}

void VtkViewport::wheelEvent(QWheelEvent* event) {
  emit cameraTouched();
  const double dpr = devicePixelRatioF();
  const QPointF p = event->position();
  interactor_->SetEventInformationFlipY(static_cast<int>(p.x() * dpr),
                                        static_cast<int>(p.y() * dpr));
  interactor_->InvokeEvent(event->angleDelta().y() > 0 ? vtkCommand::MouseWheelForwardEvent
                                                       : vtkCommand::MouseWheelBackwardEvent,
                           event);
  update();
}

}  // namespace drape
