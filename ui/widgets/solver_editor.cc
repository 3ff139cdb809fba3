#include "ui/widgets/solver_editor.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QSpinBox>

#include <optional>

#include "core/model/solver_preset.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/quantity_field.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/scene_part_watch.h"

namespace drape {

SolverEditor::SolverEditor(SceneDocument* document, QLabel* message, QWidget* parent)
    : QGroupBox("Solver", parent), document_(document), message_(message) {
  auto* form = new QFormLayout(this);
  MakePreset(form);
  MakeLimits(form);
  MakeChoices(form);
  ConnectNumbers();
  ConnectChoices();
  new ScenePartWatch(
      document_, SceneDocument::Part::kSolver, [this] { refresh(); }, this);
  refresh();
}

void SolverEditor::MakePreset(QFormLayout* form) {
  preset_ = new QComboBox(this);
  for (const PresetDefinition& p : PresetDefinitions())
    preset_->addItem(QString("%1: %2").arg(p.name, p.purpose), p.name);
  preset_->addItem("custom: the fields below, on the scene's mesh", "custom");
  preset_->setToolTip(
      "solver.preset: the mesh density, tolerance and N_p the measured speed–accuracy fronts "
      "showed to be efficient (docs/speed-accuracy.md). A field changed below overrides the "
      "preset's value");
  form->addRow("accuracy", preset_);
  // The preset's numbers, each its own field.
  tolerance_ = new QuantityField(
      dim::kNone,
      "1e-5",
      [](double v) { return v > 0 && v < 1 ? QString() : QString("must lie in (0, 1)"); },
      this);
  target_iterations_ = new QSpinBox(this);
  target_iterations_->setRange(1, 50);
  tolerance_->setToolTip(
      "How closely each step's forces must balance: the out-of-balance force over the first "
      "one, ‖R‖/‖R₀‖ (solver.tolerance). Smaller: more accurate, slower");
  target_iterations_->setToolTip(
      "The step length adapts so that a step takes about this many Newton iterations "
      "(N_p, solver.target_iterations). More: longer steps, fewer of them; fewer: shorter "
      "steps that follow a sharp fold more closely");
  form->addRow("equilibrium tolerance", tolerance_);
  form->addRow("iterations per step", target_iterations_);
}

void SolverEditor::MakeLimits(QFormLayout* form) {
  max_steps_ = new QSpinBox(this);
  max_steps_->setRange(1, 1000000);
  max_steps_->setSingleStep(100);
  max_steps_->setToolTip("The run stops (keeping its steps) after this many (solver.max_steps)");
  form->addRow("at most, steps", max_steps_);
  time_limit_ = new QDoubleSpinBox(this);
  time_limit_->setRange(0, 1e7);
  time_limit_->setDecimals(1);
  time_limit_->setSuffix(" s");
  time_limit_->setSpecialValueText("none");
  time_limit_->setToolTip(
      "Wall-clock limit of a run (solver.max_wall_s), pauses included: past it the run stops "
      "(failed), keeping every converged step. none: no limit");
  form->addRow("time limit", time_limit_);
}

namespace {

// solver.sequencing: 0 reads "auto", 1 "off", a factor its number.
class SequencingSpinBox : public QSpinBox {
 public:
  using QSpinBox::QSpinBox;

 protected:
  QString textFromValue(int value) const override {
    return value == kAutoSequencing ? "auto" : value == 1 ? "off" : QString::number(value);
  }
  int valueFromText(const QString& text) const override {
    const QString word = text.trimmed();
    if (word == "auto") return kAutoSequencing;
    if (word == "off") return 1;
    return word.toInt();
  }
  QValidator::State validate(QString& text, int& position) const override {
    const QString word = text.trimmed();
    for (const char* name : {"auto", "off"})
      if (QString(name).startsWith(word))
        return word == name ? QValidator::Acceptable : QValidator::Intermediate;
    return QSpinBox::validate(text, position);
  }
};

}  // namespace

void SolverEditor::MakeChoices(QFormLayout* form) {
  sequencing_ = new SequencingSpinBox(this);
  sequencing_->setRange(kAutoSequencing, 20);
  sequencing_->setToolTip(
      "Mesh sequencing for a one-stage drape (solver.sequencing): follow the path on a mesh "
      "this many times coarser in each direction, then solve this mesh from its end in a few "
      "Newton iterations (the result then has one step). Must divide the mesh's element counts. "
      "auto: on for one-stage drapes of 2500 elements or more, with the coarse mesh about 20 "
      "elements across; off: the path on this mesh");
  form->addRow("solve first on a coarser mesh", sequencing_);
  branching_ = new QComboBox(this);
  branching_->addItem("take the stable branch, or snap", "stable");
  branching_->addItem("follow the primary path", "fundamental");
  branching_->setToolTip(
      "solver.branching. Where the part buckles or gives way: switch to the branch a real part "
      "takes, or, where no stable path goes on (a limit point, a bifurcation with no stable "
      "branch), let it snap to the rest state it falls into, as a real part does; or follow the "
      "primary path through limit and bifurcation points (unstable between them; the paper's "
      "load–deflection studies)");
  form->addRow("where it buckles", branching_);
  error_estimate_ = new QCheckBox("on meshes 2 and 4 times coarser", this);
  error_estimate_->setToolTip(
      "solver.error_estimate: after a converged run, solve again on meshes 2 and 4 times coarser "
      "and estimate each probe's error (Richardson); costs about a third more");
  form->addRow("estimate the error", error_estimate_);
}

void SolverEditor::ApplyChecked(const QString& what, const std::function<void(Scene&)>& change) {
  if (refreshing_) return;
  Scene after = document_->scene();
  change(after);
  if (!ApplyOrSay(document_, message_, what, after)) refresh();
}

void SolverEditor::Apply(const QString& what, const std::function<void(Scene&)>& change) {
  if (refreshing_) return;
  Scene after = document_->scene();
  change(after);
  document_->apply(what, after);
}

void SolverEditor::ConnectNumbers() {
  // A preset's number changed by hand: the settings are the user's own now
  // (the menu says custom); the mesh stays as it was.
  connect(tolerance_, &QuantityField::committed, this, [this](double v, const QString& text) {
    ApplyChecked("tolerance " + text, [v](Scene& s) {
      s.solver.tolerance = v;
      s.solver.preset.reset();
    });
  });
  connect(target_iterations_, &QSpinBox::editingFinished, this, [this] {
    const int n = target_iterations_->value();
    ApplyChecked(QString("target iterations %1").arg(n), [n](Scene& s) {
      s.solver.target_iterations = n;
      s.solver.preset.reset();
    });
  });
  connect(max_steps_, &QSpinBox::editingFinished, this, [this] {
    const int n = max_steps_->value();
    ApplyChecked(QString("max steps %1").arg(n), [n](Scene& s) { s.solver.max_steps = n; });
  });
  connect(sequencing_, &QSpinBox::editingFinished, this, [this] {
    const int n = sequencing_->value();
    ApplyChecked(QString("mesh sequencing %1").arg(sequencing_->text()),
                 [n](Scene& s) { s.solver.sequencing = n; });
  });
  connect(time_limit_, &QDoubleSpinBox::editingFinished, this, [this] {
    const double seconds = time_limit_->value();
    Apply(seconds > 0 ? QString("time limit %1 s").arg(seconds) : "no time limit",
          [seconds](Scene& s) {
            s.solver.max_wall_s = seconds > 0 ? std::optional<double>(seconds) : std::nullopt;
          });
  });
}

void SolverEditor::ConnectChoices() {
  connect(error_estimate_, &QCheckBox::toggled, this, [this](bool on) {
    Apply(on ? "estimate the error" : "no error estimate",
          [on](Scene& s) { s.solver.error_estimate = on; });
  });
  connect(branching_, &QComboBox::activated, this, [this](int i) {
    Apply(QString("branching %1").arg(branching_->itemData(i).toString()), [i](Scene& s) {
      s.solver.branching = i == 0 ? Branching::kStable : Branching::kFundamental;
    });
  });
  connect(preset_, &QComboBox::activated, this, [this](int i) {
    Apply(QString("accuracy %1").arg(preset_->itemData(i).toString()), [i](Scene& s) {
      const auto presets = PresetDefinitions();
      if (i < static_cast<int>(presets.size())) {
        s.solver = WithPreset(s.solver, presets[i].preset);
      } else {  // custom: the fields as they are, on the scene's own mesh
        s.solver.preset.reset();
        s.solver.mesh_scale = 1;
      }
    });
  });
}

void SolverEditor::refresh() {
  refreshing_ = true;
  const SolverSettings& solver = document_->scene().solver;
  preset_->setCurrentIndex(solver.preset ? static_cast<int>(*solver.preset)
                                         : static_cast<int>(PresetDefinitions().size()));
  error_estimate_->setChecked(solver.error_estimate);
  tolerance_->setValue(solver.tolerance, QString::number(solver.tolerance));
  target_iterations_->setValue(solver.target_iterations);
  max_steps_->setValue(solver.max_steps);
  time_limit_->setValue(solver.max_wall_s.value_or(0));
  sequencing_->setValue(solver.sequencing);
  branching_->setCurrentIndex(solver.branching == Branching::kStable ? 0 : 1);
  refreshing_ = false;
}

}  // namespace drape
