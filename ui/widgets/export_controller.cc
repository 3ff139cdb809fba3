#include "ui/widgets/export_controller.h"

#include <QCoreApplication>
#include <QProgressDialog>

#include <atomic>
#include <exception>

#include "core/fe/path_handles.h"
#include "ui/render/animation.h"
#include "ui/render/surface_export.h"

namespace drape {
namespace {

ShellState ReferenceOf(const ExportedRun& run) {
  ShellState reference = run.model->reference;
  reference.obstacles.assign(run.scene->obstacles.size(), ObstaclePlacement{});
  return reference;
}

bool HasSteps(const ExportedRun& run) {
  return run.model && run.steps && !run.steps->empty() && !run.running;
}

QString Failure(const std::exception& e) {
  return QString::fromStdString(e.what());
}

}  // namespace

ExportOutcome ExportController::Image(const ExportedRun& run,
                                      const RenderOptions& view,
                                      const QString& file) const {
  if (!run.model) return {false, false, "nothing to draw: open a scene first"};
  try {
    Eigen::AlignedBox3d bounds = RunBounds(*run.scene, {&run.model->reference});
    for (const auto& p : GripperPathPoints(*run.scene, *run.model)) bounds.extend(p);
    FrameRenderer offscreen(*run.scene, *run.model, view, bounds);
    const ShellState reference = ReferenceOf(run);
    Frame frame;
    frame.state = &reference;
    if (run.current_step > 0 && run.steps) {
      const StepState& s = *run.steps->at(run.current_step - 1);
      frame.state = &s.state;
      frame.step = s.step;
      frame.stage = s.stage;
      frame.stage_name = s.stage_name;
      frame.lambda = s.lambda;
    }
    offscreen.Show(frame);
    offscreen.WritePng(file.toStdString());
    return {true, false, "wrote " + file};
  } catch (const std::exception& e) {
    return {false, false, Failure(e)};
  }
}

ExportOutcome ExportController::Animation(const ExportedRun& run,
                                          const RenderOptions& view,
                                          const QString& file,
                                          double fps) const {
  if (!HasSteps(run)) return {false, false, "nothing to animate: run the scene first"};
  const ShellState reference = ReferenceOf(run);
  AnimationInput input{run.scene, run.model, {&reference}, {""}, {0.0}, {-1}};
  for (const auto& s : *run.steps) {
    input.states.push_back(&s->state);
    input.stages.push_back(s->stage);
    input.stage_names.push_back(s->stage_name);
    input.lambdas.push_back(s->lambda);
  }
  AnimationOptions options;
  options.view = view;
  options.fps = fps;
  QProgressDialog dialog(
      "Writing " + file, "Cancel", 0, static_cast<int>(input.states.size()), parent_);
  dialog.setWindowModality(Qt::WindowModal);
  dialog.setMinimumDuration(500);
  std::atomic<bool> cancel{false};
  try {
    const int frames = WriteAnimation(
        input,
        options,
        file.toStdString(),
        [&](int done, int all) {
          dialog.setMaximum(all);
          dialog.setValue(done);
          QCoreApplication::processEvents();
          if (dialog.wasCanceled()) cancel = true;
        },
        &cancel);
    if (frames < 0) return {false, true, "export cancelled; no file written"};
    return {true, false, QString("wrote %1 frames to %2").arg(frames).arg(file)};
  } catch (const std::exception& e) {
    return {false, false, Failure(e)};
  }
}

ExportOutcome ExportController::Vtu(const ExportedRun& run, const QString& directory) const {
  if (!HasSteps(run)) return {false, false, "nothing to export: run the scene first"};
  const ShellState reference = run.model->reference;
  std::vector<ExportedStep> steps{{&reference, 0, -1, 0.0}};
  for (const auto& s : *run.steps) steps.push_back({&s->state, s->step, s->stage, s->lambda});
  QProgressDialog dialog(
      "Writing VTU to " + directory, "Cancel", 0, static_cast<int>(steps.size()), parent_);
  dialog.setWindowModality(Qt::WindowModal);
  dialog.setMinimumDuration(500);
  try {
    const auto files = ExportSurfaces(
        *run.model, steps, SurfaceFormat::kVtu, directory.toStdString(), false, [&](int done, int) {
          dialog.setValue(done);
          QCoreApplication::processEvents();
          return !dialog.wasCanceled();
        });
    const bool cancelled = dialog.wasCanceled();
    return {!cancelled,
            cancelled,
            QString("wrote %1 files to %2%3")
                .arg(files.size())
                .arg(directory)
                .arg(cancelled ? " (cancelled: the steps before are kept)" : "")};
  } catch (const std::exception& e) {
    return {false, false, Failure(e)};
  }
}

}  // namespace drape
