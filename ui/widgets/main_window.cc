#include "ui/widgets/main_window.h"

#include <vtkGenericOpenGLRenderWindow.h>
#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QSlider>
#include <QStatusBar>
#include <QThread>
#include <QToolBar>
#include <QVBoxLayout>

#include "core/io/scene_reader.h"
#include "core/model/outline_geometry.h"
#include "ui/render/frame_renderer.h"
#include "ui/widgets/solver_worker.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {
namespace {

// Errors are shown without blocking: a run started by a script must not
// wait for someone to click OK.
void ShowError(QWidget* parent, const QString& title, const QString& message) {
  auto* box = new QMessageBox(QMessageBox::Critical, title, message, QMessageBox::Ok, parent);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->show();
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  qRegisterMetaType<drape::Scene>();
  qRegisterMetaType<drape::SolveSummary>();
  qRegisterMetaType<std::shared_ptr<const drape::StepState>>();
  setWindowTitle("Drape Studio");
  auto* central = new QWidget(this);
  auto* layout = new QVBoxLayout(central);
  viewport_ = new VtkViewport(central);
  viewport_->setMinimumSize(640, 400);
  layout->addWidget(viewport_, 1);
  auto* timeline = new QHBoxLayout;
  timeline_ = new QSlider(Qt::Horizontal, central);
  timeline_->setRange(0, 0);
  step_label_ = new QLabel("no scene", central);
  step_label_->setMinimumWidth(260);
  timeline->addWidget(timeline_, 1);
  timeline->addWidget(step_label_);
  layout->addLayout(timeline);
  setCentralWidget(central);
  connect(timeline_, &QSlider::valueChanged, this, [this](int i) {
    follow_ = i == stepCount();
    showStep(i);
  });
  buildActions();
  updateControls();
  resize(1100, 760);
}

MainWindow::~MainWindow() {
  stop();
  if (thread_) {
    thread_->quit();
    thread_->wait();
  }
  // The renderer's actors live in the viewport's window: release them while
  // the GL context exists.
  viewport_->makeCurrent();
  renderer_.reset();
  viewport_->doneCurrent();
}

void MainWindow::buildActions() {
  QToolBar* bar = addToolBar("Run");
  open_ = bar->addAction("Open…", this, [this] {
    const QString file = QFileDialog::getOpenFileName(this, "Open scene", {}, "Scenes (*.json)");
    if (!file.isEmpty()) openScene(file);
  });
  open_->setShortcut(QKeySequence::Open);
  run_ = bar->addAction("Run", this, &MainWindow::run);
  run_->setShortcut(Qt::Key_F5);
  pause_ = bar->addAction("Pause", this, &MainWindow::pauseOrResume);
  step_ = bar->addAction("Step", this, &MainWindow::stepOnce);
  stop_ = bar->addAction("Stop", this, &MainWindow::stop);
  stop_->setShortcut(Qt::Key_Escape);
}

void MainWindow::updateControls() {
  const bool loaded = model_ != nullptr;
  open_->setEnabled(!running_);
  run_->setEnabled(loaded && !running_);
  pause_->setEnabled(running_);
  pause_->setText(paused_ ? "Resume" : "Pause");
  step_->setEnabled(running_ && paused_);
  stop_->setEnabled(running_);
}

bool MainWindow::openScene(const QString& file) {
  if (running_) return false;
  try {
    Scene scene = ReadScene(file.toStdString());
    auto model = std::make_unique<ShellModel>(BuildShellModel(scene));
    viewport_->makeCurrent();
    renderer_.reset();
    viewport_->doneCurrent();
    scene_ = std::move(scene);
    model_ = std::move(model);
  } catch (const std::exception& e) {
    ShowError(this, "Cannot open the scene", QString::fromStdString(e.what()));
    statusBar()->showMessage(QString::fromStdString(e.what()));
    return false;
  }
  steps_.clear();
  setWindowTitle(QFileInfo(file).fileName() + " — Drape Studio");
  rebuildRenderer();
  timeline_->setRange(0, 0);
  showStep(0);
  statusBar()->showMessage(QString("%1: %2 nodes, %3 elements")
                               .arg(QString::fromStdString(scene_.name))
                               .arg(model_->NodeCount())
                               .arg(model_->mesh.ElementCount()));
  updateControls();
  return true;
}

void MainWindow::rebuildRenderer() {
  // The camera sees the part and where its grippers will take it.
  Eigen::AlignedBox3d bounds = RunBounds(scene_, {&model_->reference});
  for (const auto& p : GripperPathPoints(scene_, *model_)) bounds.extend(p);
  RenderOptions options;
  viewport_->makeCurrent();
  renderer_ = std::make_unique<FrameRenderer>(
      scene_, *model_, options, bounds, std::nullopt, viewport_->renderWindow());
  viewport_->doneCurrent();
}

void MainWindow::showStep(int index) {
  if (!renderer_) return;
  index = std::clamp(index, 0, stepCount());
  Frame frame;
  ShellState reference = model_->reference;
  reference.obstacles.assign(scene_.obstacles.size(), ObstaclePlacement{});
  if (index == 0) {
    frame.state = &reference;
    step_label_->setText("reference state");
  } else {
    const StepState& s = *steps_[index - 1];
    frame.state = &s.state;
    frame.step = s.step;
    frame.stage_name = s.stage_name;
    frame.lambda = s.lambda;
    step_label_->setText(QString("step %1 of %2 — stage %3, λ = %4")
                             .arg(s.step)
                             .arg(stepCount())
                             .arg(QString::fromStdString(s.stage_name))
                             .arg(s.lambda, 0, 'f', 4));
  }
  renderer_->Update(frame);
  viewport_->requestRender();
}

void MainWindow::run() {
  if (!model_ || running_) return;
  steps_.clear();
  timeline_->setRange(0, 0);
  follow_ = true;
  thread_ = new QThread(this);
  worker_ = new SolverWorker;
  worker_->moveToThread(thread_);
  connect(thread_, &QThread::finished, worker_, &QObject::deleteLater);
  connect(worker_, &SolverWorker::stepConverged, this, &MainWindow::onStep, Qt::QueuedConnection);
  connect(worker_, &SolverWorker::finished, this, &MainWindow::onFinished, Qt::QueuedConnection);
  connect(worker_, &SolverWorker::failed, this, &MainWindow::onFailed, Qt::QueuedConnection);
  thread_->start();
  running_ = true;
  paused_ = false;
  updateControls();
  statusBar()->showMessage("running…");
  const Scene scene = scene_;
  QMetaObject::invokeMethod(
      worker_, [w = worker_, scene] { w->run(scene); }, Qt::QueuedConnection);
}

void MainWindow::pauseOrResume() {
  if (!running_) return;
  paused_ = !paused_;
  paused_ ? worker_->pause() : worker_->resume();
  updateControls();
}

void MainWindow::stepOnce() {
  if (running_ && paused_) worker_->step();
}

void MainWindow::stop() {
  if (running_ && worker_) worker_->stop();
}

void MainWindow::onStep(std::shared_ptr<const StepState> step) {
  steps_.push_back(std::move(step));
  const QSignalBlocker block(timeline_);
  timeline_->setRange(0, stepCount());
  if (follow_) {
    timeline_->setValue(stepCount());
    showStep(stepCount());
  }
}

void MainWindow::onFinished(const SolveSummary& summary) {
  running_ = false;
  paused_ = false;
  thread_->quit();
  thread_->wait();
  thread_->deleteLater();
  thread_ = nullptr;
  worker_ = nullptr;
  statusBar()->showMessage(QString::fromStdString(summary.BriefReport()));
  updateControls();
  emit runFinished(summary);
}

void MainWindow::onFailed(const QString& message) {
  SolveSummary summary;
  summary.termination = Termination::kInvalidInput;
  summary.message = message.toStdString();
  ShowError(this, "The run could not start", message);
  onFinished(summary);
}

}  // namespace drape
