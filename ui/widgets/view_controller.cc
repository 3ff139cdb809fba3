#include "ui/widgets/view_controller.h"

#include <vtkGenericOpenGLRenderWindow.h>
#include <QAction>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QTimer>
#include <QToolButton>

#include <algorithm>
#include <cmath>

#include "ui/render/drape_shadow_actors.h"
#include "ui/widgets/typed_json.h"
#include "ui/widgets/vtk_viewport.h"

namespace drape {
namespace {

// The menu shows the choice made by a call, without calling back.
void ShowChoice(QComboBox* box, const QString& data) {
  const int index = box->findData(data);
  if (index < 0 || index == box->currentIndex()) return;
  const QSignalBlocker block(box);
  box->setCurrentIndex(index);
}

// The per-node fields a step's contact report carries.
void SetContactFields(const ContactReport& contact, Frame& frame) {
  frame.contact_pressure = contact.pressure;
  if (!contact.with_friction) return;
  frame.friction_state.clear();
  for (SlipState s : contact.friction) frame.friction_state.push_back(static_cast<double>(s));
}

}  // namespace

ViewController::ViewController(VtkViewport* viewport, QWidget* bar_parent, QObject* parent)
    : QObject(parent), viewport_(viewport) {
  bar_ = new QWidget(bar_parent);
  auto* row = new QHBoxLayout(bar_);
  row->setContentsMargins(0, 0, 0, 0);
  timeline_ = new QSlider(Qt::Horizontal, bar_);
  timeline_->setRange(0, 0);
  step_label_ = new QLabel("no scene", bar_);
  step_label_->setMinimumWidth(260);
  drape_label_ = new QLabel(bar_);
  drape_label_->setVisible(false);
  field_ = new QComboBox(bar_);
  field_->addItem("fabric colours", "");
  for (const auto& f : Fields()) field_->addItem(f.title, f.name);
  colour_map_ = new QComboBox(bar_);
  for (ColourMap m : {ColourMap::kViridis, ColourMap::kRainbow})
    colour_map_->addItem(ToString(m), ToString(m));
  colour_map_->setToolTip(
      "Colours of the field: viridis (perceptually uniform, reads in grey) or the rainbow");
  auto* play = new QAction("Play", bar_);
  connect(play, &QAction::triggered, this, &ViewController::play);
  auto* play_button = new QToolButton(bar_);
  play_button->setDefaultAction(play);
  row->addWidget(play_button);
  row->addWidget(timeline_, 1);
  row->addWidget(step_label_);
  row->addWidget(drape_label_);
  row->addWidget(field_);
  row->addWidget(colour_map_);
  player_ = new QTimer(this);
  player_->setInterval(40);
  connect(player_, &QTimer::timeout, this, [this] {
    if (currentStep() >= stepCount()) return player_->stop();
    timeline_->setValue(currentStep() + 1);
  });
  connect(field_, &QComboBox::currentIndexChanged, this, [this](int) {
    setField(field_->currentData().toString());
  });
  connect(colour_map_, &QComboBox::currentIndexChanged, this, [this](int) {
    setColourMap(colour_map_->currentData().toString());
  });
  connect(timeline_, &QSlider::valueChanged, this, [this](int i) {
    follow_ = i == stepCount();
    showStep(i);
  });
  // Until the user turns the view, it keeps the whole run framed as the
  // window's layout settles or is resized.
  connect(viewport_, &VtkViewport::cameraTouched, this, [this] { camera_touched_ = true; });
  connect(viewport_, &VtkViewport::resized, this, [this] {
    if (!renderer_ || camera_touched_) return;
    renderer_->FitCamera();
    viewport_->requestRender();
  });
}

void ViewController::setScene(const Scene& scene,
                              std::shared_ptr<const ShellModel> model,
                              bool keep_result) {
  releaseRenderer();  // it holds the scene and the model it was made for
  // The last run's end stays in view over an edit that keeps its nodes and
  // obstacles (the new scene's ghost is drawn over it).
  std::shared_ptr<const StepState> kept = !keep_result || !model ? nullptr
                                          : !steps_.empty()      ? steps_.back()
                                                                 : stale_;
  if (kept && (kept->state.positions.rows() != model->NodeCount() ||
               kept->state.obstacles.size() != scene.obstacles.size()))
    kept.reset();
  stale_ = std::move(kept);
  scene_ = scene;
  model_ = std::move(model);
  steps_.clear();
  clearGhost();
  RebuildRenderer();
  timeline_->setRange(0, 0);
  showStep(0);
}

void ViewController::releaseRenderer() {
  if (!renderer_) return;
  emit rendererChanging();
  viewport_->makeCurrent();
  renderer_.reset();  // its actors leave the window before new ones come
  viewport_->doneCurrent();
}

void ViewController::RebuildRenderer() {
  releaseRenderer();
  if (!model_) return;
  // The camera sees the part and where its grippers will take it.
  Eigen::AlignedBox3d bounds = RunBounds(scene_, {&model_->reference});
  for (const auto& p : GripperPathPoints(scene_, *model_)) bounds.extend(p);
  viewport_->makeCurrent();
  renderer_ = std::make_unique<FrameRenderer>(
      scene_, *model_, look(), bounds, std::nullopt, viewport_->renderWindow());
  viewport_->doneCurrent();
  camera_touched_ = false;
  drawn_generation_ = -1;
  DrawGhost();  // the preview's ghost on the new renderer too
  emit rendererChanged();
}

// The view's look changed: a renderer built with it, on the step shown.
void ViewController::Redraw() {
  if (!model_) return;
  RebuildRenderer();
  showStep(currentStep());
}

void ViewController::clearSteps() {
  steps_.clear();
  timeline_->setRange(0, 0);
  follow_ = true;
  if (stale_) {
    stale_.reset();
    showStep(0);
  }
}

void ViewController::setGhost(int generation,
                              std::shared_ptr<const ShellModel> model,
                              std::shared_ptr<const StepState> step) {
  ghost_generation_ = generation;
  ghost_model_ = std::move(model);
  ghost_step_ = std::move(step);
  if (drawn_generation_ != generation) {
    // A new preview's first step: on the renderer at once, so the paint
    // already due (the edit's new renderer) shows it.
    DrawGhost();
    viewport_->requestRender();
    return;
  }
  if (ghost_pending_) return;
  ghost_pending_ = true;
  QTimer::singleShot(0, this, [this] {
    ghost_pending_ = false;
    DrawGhost();
    viewport_->requestRender();
  });
}

void ViewController::DrawGhost() {
  if (!renderer_ || !ghost_step_) return;
  try {
    renderer_->SetGhost(ghost_model_->mesh, ghost_step_->state);
    drawn_generation_ = ghost_generation_;
  } catch (const std::invalid_argument& e) {
    emit message(QString::fromStdString(e.what()));
  }
}

void ViewController::clearGhost() {
  ghost_model_.reset();
  ghost_step_.reset();
  ghost_generation_ = drawn_generation_ = -1;
  if (!renderer_ || !renderer_->HasGhost()) return;
  renderer_->ClearGhost();
  viewport_->requestRender();
}

int ViewController::ghostGeneration() const {
  return renderer_ && renderer_->HasGhost() ? drawn_generation_ : -1;
}

// The view draws only the newest of the steps that arrived together (one
// draw after the queued ones are taken).
void ViewController::addStep(std::shared_ptr<const StepState> step) {
  steps_.push_back(std::move(step));
  const QSignalBlocker block(timeline_);
  timeline_->setRange(0, stepCount());
  if (!follow_ || draw_pending_) return;
  draw_pending_ = true;
  QTimer::singleShot(0, this, [this] {
    draw_pending_ = false;
    if (!follow_) return;
    const QSignalBlocker block(timeline_);
    timeline_->setValue(stepCount());
    showStep(stepCount());
  });
}

int ViewController::currentStep() const {
  return timeline_->value();
}

const Eigen::MatrixX3d& ViewController::shownPositions() const {
  const int i = currentStep();
  if (i > 0) return steps_[i - 1]->state.positions;
  return stale_ ? stale_->state.positions : model_->reference.positions;
}

ExportedRun ViewController::exportedRun(bool running) const {
  return {&scene_, model_.get(), &steps_, currentStep(), running};
}

RenderOptions ViewController::look() const {
  RenderOptions look = view_;
  look.width = viewport_->width();
  look.height = viewport_->height();
  // A Cusick test shows its shadow and drape coefficient, as `drape render` does.
  if (model_) look.drape_shadow = DrapemeterTestOf(scene_, model_->mesh);
  return look;
}

void ViewController::showStep(int index) {
  if (!renderer_) return;
  index = std::clamp(index, 0, stepCount());
  if (timeline_->value() != index) {
    const QSignalBlocker block(timeline_);
    timeline_->setValue(index);
  }
  Frame frame;
  ShellState reference = model_->reference;
  reference.obstacles.assign(scene_.obstacles.size(), ObstaclePlacement{});
  if (index == 0 && stale_) {
    // The last run's end over an edit: what the ghost is to be compared with.
    frame.state = &stale_->state;
    frame.step = stale_->step;
    frame.stage = stale_->stage;
    frame.stage_name = stale_->stage_name + " (before the edit)";
    frame.lambda = stale_->lambda;
    if (stale_->contact) SetContactFields(*stale_->contact, frame);
    step_label_->setText(
        QString("step %1 of the last run — stale: edited since").arg(stale_->step));
  } else if (index == 0) {
    frame.state = &reference;
    step_label_->setText("reference state");
  } else {
    const StepState& s = *steps_[index - 1];
    frame.state = &s.state;
    frame.step = s.step;
    frame.stage = s.stage;
    frame.stage_name = s.stage_name;
    frame.lambda = s.lambda;
    if (s.contact) SetContactFields(*s.contact, frame);
    // λ in the user's words: how far through its stage; and whether the
    // state is one a real part could rest in (no negative pivot).
    step_label_->setText(QString("step %1 of %2, stable rest state: %3 — %4 %5 %")
                             .arg(s.step)
                             .arg(stepCount())
                             .arg(s.negative_pivots == 0 ? "yes" : "no")
                             .arg(QString::fromStdString(s.stage_name))
                             .arg(100 * s.lambda, 0, 'f', 0));
    step_label_->setToolTip(
        QString("λ = %1 of the stage's load or motion. Stable rest state: the tangent stiffness "
                "has %2 negative pivots (0: a state a real part can rest in; more: it would move "
                "off on its own)")
            .arg(s.lambda, 0, 'f', 4)
            .arg(s.negative_pivots));
  }
  emit stepShown(index);
  try {
    renderer_->Update(frame);
  } catch (const std::invalid_argument& e) {
    // A field this state has no values of (contact pressure of the
    // reference state): say so and keep the picture.
    emit message(QString::fromStdString(e.what()));
    return;
  }
  ShowDrape();
  viewport_->requestRender();
}

namespace {
// An area as a drape tester quotes it: cm², or in² for imperial units.
QString AreaText(double m2, UnitSystem units) {
  if (units == UnitSystem::kImperial)
    return QString("%1 in²").arg(m2 / (0.0254 * 0.0254), 0, 'f', 2);
  return QString("%1 cm²").arg(m2 * 1e4, 0, 'f', 1);
}
}  // namespace

void ViewController::ShowDrape() {
  const auto& m = renderer_->drape();
  drape_label_->setVisible(m.has_value());
  if (!m) return;
  drape_label_->setText(QString::fromStdString(DrapeSummary(*m)));
  QStringList nodes;
  for (const DrapeNode& n : m->nodes)
    nodes << QString("%1° (%2)")
                 .arg(n.angle * 180 / M_PI, 0, 'f', 1)
                 .arg(QuantityText(n.amplitude, Measure::kLength, view_.units));
  drape_label_->setToolTip(
      QString("The Cusick drape test of the step shown: shadow %1, disc %2, specimen %3.\n"
              "Nodes (angle from x, amplitude): %4")
          .arg(AreaText(m->shadow_area, view_.units),
               AreaText(m->disc_area, view_.units),
               AreaText(m->specimen_area, view_.units),
               nodes.isEmpty() ? "none" : nodes.join(", ")));
}

void ViewController::play() {
  if (stepCount() == 0) return;
  if (currentStep() >= stepCount()) timeline_->setValue(0);
  player_->start();
}

bool ViewController::setCamera(const QString& view) {
  if (!QStringList{"iso", "front", "top", "side"}.contains(view)) return false;
  view_.camera = CameraSpec{};
  view_.camera.view = view.toStdString();
  Redraw();
  return true;
}

bool ViewController::setField(const QString& name) {
  std::optional<FieldKind> kind;
  if (!name.isEmpty()) {
    const auto f = FindField(name.toStdString());
    if (!f) return false;
    kind = f->kind;
  }
  view_.field = kind;
  ShowChoice(field_, name);
  Redraw();
  return true;
}

void ViewController::setUnitSystem(UnitSystem system) {
  if (view_.units == system) return;
  view_.units = system;
  Redraw();
}

bool ViewController::setColourMap(const QString& name) {
  const auto map = ColourMapNamed(name.toStdString());
  if (!map) return false;
  view_.colour_map = *map;
  ShowChoice(colour_map_, name);
  Redraw();
  return true;
}

}  // namespace drape
