// What the workbench writes of a run: the picture of the step shown, an
// animation of every step, and the VTU series, each through ui/render (the
// same writers as `drape render`, `animate` and `export`), with a progress
// dialog that can cancel the long ones. No window state: the caller hands
// over the run as it stands.
#pragma once

#include <QString>

#include <memory>
#include <vector>

#include "core/fe/shell_model.h"
#include "core/model/scene.h"
#include "core/solve/step_state.h"
#include "ui/render/frame_renderer.h"

class QWidget;

namespace drape {

// The run to export, as the workbench holds it.
struct ExportedRun {
  const Scene* scene = nullptr;
  const ShellModel* model = nullptr;  // null: no scene open
  const std::vector<std::shared_ptr<const StepState>>* steps = nullptr;
  int current_step = 0;  // 0: the reference state
  bool running = false;
};

struct ExportOutcome {
  bool written = false;
  bool cancelled = false;  // by the user: what was written before is kept
  QString message;         // what was written, or why not
};

class ExportController {
 public:
  // `parent` owns the progress dialogs; `view` is the viewport's look and
  // size, which the pictures keep.
  explicit ExportController(QWidget* parent) : parent_(parent) {}

  ExportOutcome Image(const ExportedRun& run, const RenderOptions& view, const QString& file) const;
  ExportOutcome Animation(const ExportedRun& run,
                          const RenderOptions& view,
                          const QString& file,
                          double fps) const;
  ExportOutcome Vtu(const ExportedRun& run, const QString& directory) const;

 private:
  QWidget* parent_;
};

}  // namespace drape
