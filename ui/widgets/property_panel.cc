#include "ui/widgets/property_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QVBoxLayout>

#include <cmath>
#include <optional>

#include <nlohmann/json.hpp>

#include "core/model/overloaded.h"
#include "core/model/solver_preset.h"
#include "ui/widgets/edit_feedback.h"
#include "ui/widgets/scene_document.h"
#include "ui/widgets/typed_json.h"

namespace drape {

namespace {

QString Positive(double v) {
  return v > 0 && std::isfinite(v) ? QString() : "must be > 0";
}
QString NonNegative(double v) {
  return v >= 0 && std::isfinite(v) ? QString() : "must be ≥ 0";
}

}  // namespace

PropertyPanel::PropertyPanel(SceneDocument* document, QWidget* parent)
    : QWidget(parent), document_(document) {
  auto* layout = new QVBoxLayout(this);

  auto* fabric = new QGroupBox("Fabric", this);
  auto* fabric_form = new QFormLayout(fabric);
  shape_ = new QComboBox(fabric);
  shape_->addItems({"rectangle", "disk", "polygon"});
  extent_ = new QLineEdit(fabric);
  center_ = new QLineEdit(fabric);
  element_size_ = new QLineEdit(fabric);
  element_size_->setToolTip("target element edge, e.g. 1 cm");
  nx_ = new QSpinBox(fabric);
  ny_ = new QSpinBox(fabric);
  for (QSpinBox* s : {nx_, ny_}) s->setRange(1, 400);
  mesh_info_ = new QLabel(fabric);
  mesh_info_->setWordWrap(true);  // the solved mesh of a preset makes it long
  fabric_message_ = MakeMessageLabel(fabric);
  fabric_form->addRow("outline", shape_);
  fabric_form->addRow("size", extent_);
  fabric_form->addRow("centre", center_);
  fabric_form->addRow("elements along x", nx_);
  fabric_form->addRow("elements along y", ny_);
  fabric_form->addRow("element size", element_size_);
  imperfection_ = new QLineEdit(fabric);
  imperfection_->setToolTip("largest out-of-plane offset, e.g. 0.05 mm; 0 for a flat part");
  seed_ = new QSpinBox(fabric);
  seed_->setRange(0, 1000000);
  pattern_ = new QComboBox(fabric);
  pattern_->addItems({"smooth", "nodal"});
  pattern_->setToolTip("smooth: random plane waves (the same at any mesh); nodal: each node");
  auto* imperfection_row = new QHBoxLayout;
  imperfection_row->addWidget(imperfection_, 1);
  imperfection_row->addWidget(new QLabel("seed", fabric));
  imperfection_row->addWidget(seed_);
  imperfection_row->addWidget(pattern_);
  fabric_form->addRow("imperfection", imperfection_row);
  fabric_form->addRow(mesh_info_);
  connect(imperfection_, &QLineEdit::editingFinished, this, [this] {
    if (!refreshing_)
      setImperfection(imperfection_->text(), seed_->value(), pattern_->currentText());
  });
  connect(seed_, &QSpinBox::editingFinished, this, [this] {
    if (!refreshing_)
      setImperfection(imperfection_->text(), seed_->value(), pattern_->currentText());
  });
  connect(pattern_, &QComboBox::activated, this, [this] {
    if (!refreshing_)
      setImperfection(imperfection_->text(), seed_->value(), pattern_->currentText());
  });
  fabric_form->addRow(fabric_message_);
  fabric_form_ = fabric_form;
  layout->addWidget(fabric);
  for (QSpinBox* s : {nx_, ny_})
    connect(s, &QSpinBox::editingFinished, this, &PropertyPanel::EditMesh);
  connect(shape_, &QComboBox::activated, this, [this] {
    // Another shape starts from a part of about the same size.
    const QString shape = shape_->currentText();
    if (shape == "rectangle")
      setOutline(shape, "20 cm, 20 cm");
    else if (shape == "disk")
      setOutline(shape, "10 cm");
    else
      setOutline(shape, "-10 cm, -10 cm; 10 cm, -10 cm; 0, 10 cm");
  });
  for (QLineEdit* e : {extent_, center_})
    connect(e, &QLineEdit::editingFinished, this, [this] {
      if (!refreshing_) setOutline(shape_->currentText(), extent_->text(), center_->text());
    });
  connect(element_size_, &QLineEdit::editingFinished, this, [this] {
    if (!refreshing_) setElementSize(element_size_->text());
  });

  auto* material = new QGroupBox("Material", this);
  auto* form = new QFormLayout(material);
  thickness_ = new QuantityField(Measure::kThickness, "0.5 mm", Positive, material);
  // A weight per area, or a mass per area (g/m²) as the reader's areal_density.
  weight_ = new QuantityField(Measure::kArealWeight, "180 g/m^2", NonNegative, material);
  modulus_ = new QuantityField(dim::kPressure, "60450 gf/cm^2", Positive, material);
  poisson_ = new QuantityField(
      dim::kNone,
      "0.3",
      [](double v) { return v >= 0 && v < 0.5 ? QString() : QString("must lie in [0, 0.5)"); },
      material);
  angle_ = new QuantityField(dim::kAngle, "45 deg", nullptr, material);
  membrane_ = new QComboBox(material);
  membrane_->addItems({"isotropic", "orthotropic (warp 1, weft 2)"});
  e1_ = new QuantityField(dim::kPressure, "60450 gf/cm^2", Positive, material);
  e2_ = new QuantityField(dim::kPressure, "30000 gf/cm^2", Positive, material);
  nu12_ = new QuantityField(dim::kNone, "0.2", NonNegative, material);
  g12_ = new QuantityField(dim::kPressure, "5000 gf/cm^2", Positive, material);
  material_message_ = MakeMessageLabel(material);
  form->addRow("thickness h", thickness_);
  form->addRow("areal weight w", weight_);
  form->addRow("membrane", membrane_);
  form->addRow("Young's modulus E", modulus_);
  form->addRow("Poisson's ratio ν", poisson_);
  form->addRow("E₁ (warp)", e1_);
  form->addRow("E₂ (weft)", e2_);
  form->addRow("ν₁₂", nu12_);
  form->addRow("G₁₂", g12_);
  form->addRow("warp angle", angle_);
  form->addRow(material_message_);
  material_form_ = form;
  layout->addWidget(material);

  // Checked by the reader's and the engine's rules (an orthotropic ν₁₂ must
  // keep the law stable); a refused value goes back to the scene's.
  auto edit = [this](const QString& what, auto change) {
    return [this, what, change](double si, const QString& text) {
      if (refreshing_) return;
      Scene after = document_->scene();
      change(after, si);
      if (!ApplyOrSay(document_, material_message_, what + " " + text, after)) refresh();
    };
  };
  auto ortho = [](auto set) {
    return [set](Scene& s, double v) {
      if (auto* m = std::get_if<OrthotropicMembrane>(&s.material.membrane)) set(*m, v);
    };
  };
  connect(e1_,
          &QuantityField::committed,
          this,
          edit("E₁", ortho([](OrthotropicMembrane& m, double v) { m.e1 = v; })));
  connect(e2_,
          &QuantityField::committed,
          this,
          edit("E₂", ortho([](OrthotropicMembrane& m, double v) { m.e2 = v; })));
  connect(nu12_,
          &QuantityField::committed,
          this,
          edit("ν₁₂", ortho([](OrthotropicMembrane& m, double v) { m.nu12 = v; })));
  connect(g12_,
          &QuantityField::committed,
          this,
          edit("G₁₂", ortho([](OrthotropicMembrane& m, double v) { m.g12 = v; })));
  connect(membrane_, &QComboBox::activated, this, [this](int i) { setOrthotropic(i == 1); });
  connect(thickness_, &QuantityField::committed, this, edit("thickness", [](Scene& s, double v) {
            s.material.thickness = v;
          }));
  connect(weight_, &QuantityField::committed, this, edit("areal weight", [](Scene& s, double v) {
            s.material.areal_weight = v;
          }));
  connect(
      modulus_, &QuantityField::committed, this, edit("Young's modulus", [](Scene& s, double v) {
        if (auto* m = std::get_if<IsotropicMembrane>(&s.material.membrane)) m->youngs_modulus = v;
      }));
  connect(
      poisson_, &QuantityField::committed, this, edit("Poisson's ratio", [](Scene& s, double v) {
        if (auto* m = std::get_if<IsotropicMembrane>(&s.material.membrane)) m->poisson_ratio = v;
      }));
  connect(angle_, &QuantityField::committed, this, edit("warp angle", [](Scene& s, double v) {
            s.material.angle_deg = v * 180.0 / M_PI;
          }));

  auto* solver = new QGroupBox("Solver", this);
  auto* solver_form = new QFormLayout(solver);
  preset_ = new QComboBox(solver);
  for (const PresetDefinition& p : PresetDefinitions())
    preset_->addItem(QString("%1: %2").arg(p.name, p.purpose), p.name);
  preset_->addItem("custom: the fields below, on the scene's mesh", "custom");
  preset_->setToolTip(
      "solver.preset: the mesh density, tolerance and N_p the measured speed–accuracy fronts "
      "showed to be efficient (docs/speed-accuracy.md). A field changed below overrides the "
      "preset's value");
  solver_form->addRow("accuracy", preset_);
  // The preset's numbers, and the run's limits, each its own field.
  tolerance_ = new QuantityField(
      dim::kNone,
      "1e-5",
      [](double v) { return v > 0 && v < 1 ? QString() : QString("must lie in (0, 1)"); },
      solver);
  target_iterations_ = new QSpinBox(solver);
  target_iterations_->setRange(1, 50);
  max_steps_ = new QSpinBox(solver);
  max_steps_->setRange(1, 1000000);
  max_steps_->setSingleStep(100);
  solver_form->addRow("tolerance ‖R‖/‖R₀‖", tolerance_);
  solver_form->addRow("target iterations N_p", target_iterations_);
  solver_form->addRow("max steps", max_steps_);
  time_limit_ = new QDoubleSpinBox(solver);
  time_limit_->setRange(0, 1e7);
  time_limit_->setDecimals(1);
  time_limit_->setSuffix(" s");
  time_limit_->setSpecialValueText("none");
  time_limit_->setToolTip(
      "Wall-clock limit of a run (solver.max_wall_s), pauses included: past it the run stops "
      "(failed), keeping every converged step. none: no limit");
  solver_form->addRow("time limit", time_limit_);
  sequencing_ = new QSpinBox(solver);
  sequencing_->setRange(1, 20);
  sequencing_->setSpecialValueText("off");
  sequencing_->setToolTip(
      "Mesh sequencing for a one-stage drape: follow the path on a mesh this many times coarser "
      "in each direction, then solve this mesh from its end in a few Newton iterations (the "
      "result then has one step). Must divide the mesh's element counts");
  solver_form->addRow("coarse path, factor", sequencing_);
  branching_ = new QComboBox(solver);
  branching_->addItem("take the stable branch", "stable");
  branching_->addItem("follow the primary path", "fundamental");
  branching_->setToolTip(
      "At a bifurcation (the tangent turns indefinite while λ goes on): switch to the branch a "
      "real part takes, or follow the primary path through it (unstable past it; the paper's "
      "studies)");
  solver_form->addRow("at bifurcations", branching_);
  error_estimate_ = new QCheckBox("on meshes 2 and 4 times coarser", solver);
  error_estimate_->setToolTip(
      "solver.error_estimate: after a converged run, solve again on meshes 2 and 4 times coarser "
      "and estimate each probe's error (Richardson); costs about a third more");
  solver_form->addRow("estimate the error", error_estimate_);
  layout->addWidget(solver);
  connect(error_estimate_, &QCheckBox::toggled, this, [this](bool on) {
    if (refreshing_ || on == document_->scene().solver.error_estimate) return;
    Scene after = document_->scene();
    after.solver.error_estimate = on;
    document_->apply(on ? "estimate the error" : "no error estimate", after);
  });
  // A preset's number changed by hand: the settings are the user's own now
  // (the menu says custom); the mesh stays as it was.
  connect(tolerance_, &QuantityField::committed, this, edit("tolerance", [](Scene& s, double v) {
            s.solver.tolerance = v;
            s.solver.preset.reset();
          }));
  connect(target_iterations_, &QSpinBox::editingFinished, this, [this, edit] {
    edit("target iterations", [](Scene& s, double v) {
      s.solver.target_iterations = static_cast<int>(v);
      s.solver.preset.reset();
    })(target_iterations_->value(), QString::number(target_iterations_->value()));
  });
  connect(max_steps_, &QSpinBox::editingFinished, this, [this, edit] {
    edit("max steps", [](Scene& s, double v) { s.solver.max_steps = static_cast<int>(v); })(
        max_steps_->value(), QString::number(max_steps_->value()));
  });
  connect(time_limit_, &QDoubleSpinBox::editingFinished, this, [this] {
    if (refreshing_) return;
    Scene after = document_->scene();
    const double seconds = time_limit_->value();
    after.solver.max_wall_s = seconds > 0 ? std::optional<double>(seconds) : std::nullopt;
    if (after.solver.max_wall_s == document_->scene().solver.max_wall_s) return;
    document_->apply(seconds > 0 ? QString("time limit %1 s").arg(seconds) : "no time limit",
                     after);
  });
  connect(sequencing_, &QSpinBox::editingFinished, this, [this, edit] {
    edit("mesh sequencing", [](Scene& s, double v) { s.solver.sequencing = static_cast<int>(v); })(
        sequencing_->value(), QString::number(sequencing_->value()));
  });
  connect(branching_, &QComboBox::activated, this, [this](int i) {
    if (refreshing_) return;
    Scene after = document_->scene();
    after.solver.branching = i == 0 ? Branching::kStable : Branching::kFundamental;
    if (after.solver.branching == document_->scene().solver.branching) return;
    document_->apply(QString("branching %1").arg(branching_->itemData(i).toString()), after);
  });
  connect(preset_, &QComboBox::activated, this, [this](int i) {
    if (refreshing_) return;
    Scene after = document_->scene();
    const auto presets = PresetDefinitions();
    if (i < static_cast<int>(presets.size())) {
      after.solver = WithPreset(after.solver, presets[i].preset);
    } else {  // custom: the fields as they are, on the scene's own mesh
      after.solver.preset.reset();
      after.solver.mesh_scale = 1;
    }
    if (after.solver == document_->scene().solver) return;
    document_->apply(QString("accuracy %1").arg(preset_->itemData(i).toString()), after);
  });
  layout->addStretch(1);
  connect(document_, &SceneDocument::changed, this, &PropertyPanel::refresh);
  refresh();
}

void PropertyPanel::setUnitSystem(UnitSystem system) {
  if (system == units_) return;
  units_ = system;
  refresh();
}

QString PropertyPanel::materialMessage() const {
  return material_message_->text();
}

bool PropertyPanel::setOrthotropic(bool on) {
  Scene after = document_->scene();
  Membrane& m = after.material.membrane;
  if (on == std::holds_alternative<OrthotropicMembrane>(m)) return true;
  if (const auto* iso = std::get_if<IsotropicMembrane>(&m)) {
    // The same material, described by its directions: E₁ = E₂ = E, ν₁₂ = ν,
    // G₁₂ = E / 2(1 + ν); then each can be changed.
    const double e = iso->youngs_modulus, nu = iso->poisson_ratio;
    m = OrthotropicMembrane{e, e, nu, e / (2 * (1 + nu))};
  } else {
    const auto& o = std::get<OrthotropicMembrane>(m);
    m = IsotropicMembrane{o.e1, o.nu12};
  }
  const bool done = ApplyOrSay(
      document_, material_message_, on ? "orthotropic membrane" : "isotropic membrane", after);
  if (!done) refresh();
  return done;
}

QString PropertyPanel::fabricMessage() const {
  return fabric_message_->text();
}

bool PropertyPanel::ApplyFabric(const QString& what, const nlohmann::json& fabric) {
  // The scene reader reads the fabric, so wrong text gets its message.
  nlohmann::json document = document_->json();
  document["fabric"] = fabric;
  const bool done = ApplyOrSay(document_, fabric_message_, what, document);
  if (!done) refresh();  // the fields show the scene's fabric again
  return done;
}

bool PropertyPanel::setOutline(const QString& shape, const QString& extent, const QString& center) {
  nlohmann::json fabric = document_->json()["fabric"];
  nlohmann::json outline;
  if (shape == "rectangle") {
    outline["rectangle"] = {{"size", TypedList(extent)}, {"center", TypedList(center)}};
  } else if (shape == "disk") {
    outline["disk"] = {{"radius", TypedQuantity(extent)}, {"center", TypedList(center)}};
  } else if (shape == "polygon") {
    outline["polygon"] = TypedLists(extent);
  } else {
    return false;
  }
  const bool was_rectangle = fabric["outline"].contains("rectangle");
  fabric["outline"] = outline;
  // Element counts are for rectangles; other shapes are meshed by size.
  if (shape != "rectangle" && fabric["mesh"].contains("elements")) {
    fabric["mesh"].erase("elements");
    if (!fabric["mesh"].contains("size")) fabric["mesh"]["size"] = 0.01;
  }
  if (shape == "rectangle" && !was_rectangle && !fabric["mesh"].contains("elements"))
    fabric["mesh"] = {{"elements", {20, 20}}};
  return ApplyFabric(QString("%1 outline %2").arg(shape, extent), fabric);
}

bool PropertyPanel::setImperfection(const QString& amplitude, int seed, const QString& pattern) {
  nlohmann::json fabric = document_->json()["fabric"];
  const nlohmann::json a = TypedQuantity(amplitude);
  if (amplitude.trimmed().isEmpty() || (a.is_number() && a.get<double>() == 0.0)) {
    fabric.erase("imperfection");
  } else {
    nlohmann::json spec = fabric.value("imperfection", nlohmann::json::object());
    spec["amplitude"] = a;
    spec["seed"] = static_cast<std::uint64_t>(seed);
    spec["pattern"] = pattern.toStdString();
    fabric["imperfection"] = spec;
  }
  return ApplyFabric("imperfection " + amplitude, fabric);
}

bool PropertyPanel::setElementSize(const QString& size) {
  nlohmann::json fabric = document_->json()["fabric"];
  fabric["mesh"] = {{"size", TypedQuantity(size)}};
  return ApplyFabric("element size " + size, fabric);
}

void PropertyPanel::EditMesh() {
  if (refreshing_) return;
  Scene after = document_->scene();
  after.fabric.mesh.elements = std::array<int, 2>{nx_->value(), ny_->value()};
  document_->apply(QString("mesh %1 × %2").arg(nx_->value()).arg(ny_->value()), after);
}

void PropertyPanel::refresh() {
  refreshing_ = true;
  const Scene& s = document_->scene();
  const bool rectangle = std::holds_alternative<RectangleOutline>(s.fabric.outline);
  const bool by_count = rectangle && s.fabric.mesh.elements.has_value();
  std::visit(Overloaded{[&](const RectangleOutline& r) {
                          shape_->setCurrentText("rectangle");
                          extent_->setText(ListText(r.size, units_));
                          center_->setText(ListText(r.center, units_));
                        },
                        [&](const DiskOutline& d) {
                          shape_->setCurrentText("disk");
                          extent_->setText(QuantityText(d.radius, Measure::kLength, units_));
                          center_->setText(ListText(d.center, units_));
                        },
                        [&](const PolygonOutline& p) {
                          shape_->setCurrentText("polygon");
                          QStringList vertices;
                          for (const Vec2& v : p.vertices) vertices << ListText(v, units_);
                          extent_->setText(vertices.join("; "));
                        }},
             s.fabric.outline);
  auto label = [&](QWidget* field, const QString& text) {
    if (auto* l = qobject_cast<QLabel*>(fabric_form_->labelForField(field))) l->setText(text);
  };
  label(extent_,
        rectangle                                               ? "size"
        : std::holds_alternative<DiskOutline>(s.fabric.outline) ? "radius"
                                                                : "vertices");
  fabric_form_->setRowVisible(center_, !std::holds_alternative<PolygonOutline>(s.fabric.outline));
  fabric_form_->setRowVisible(nx_, by_count);
  fabric_form_->setRowVisible(ny_, by_count);
  fabric_form_->setRowVisible(element_size_, !by_count);
  if (s.fabric.mesh.elements) {
    nx_->setValue((*s.fabric.mesh.elements)[0]);
    ny_->setValue((*s.fabric.mesh.elements)[1]);
  }
  element_size_->setText(
      s.fabric.mesh.size ? QuantityText(*s.fabric.mesh.size, Measure::kLength, units_) : QString());
  if (s.fabric.imperfection) {
    imperfection_->setText(
        QuantityText(s.fabric.imperfection->amplitude, Measure::kThickness, units_));
    seed_->setValue(static_cast<int>(s.fabric.imperfection->seed));
    pattern_->setCurrentIndex(s.fabric.imperfection->pattern == ImperfectionPattern::kSmooth ? 0
                                                                                             : 1);
  } else {
    imperfection_->setText("0");
  }
  // The count of the mesh the engine made (Gmsh's for curved outlines): the
  // document's model's, not meshed again.
  model_ = document_->model();
  if (model_) {
    const Mesh& mesh = model_->mesh;
    QString info = QString("%1 nodes, %2 elements, %3 DOFs")
                       .arg(mesh.NodeCount())
                       .arg(mesh.ElementCount())
                       .arg(5 * mesh.NodeCount());
    if (s.solver.mesh_scale != 1)
      info = QString("solved on %1: %2 × the element counts above (%3)")
                 .arg(info)
                 .arg(s.solver.mesh_scale)
                 .arg(s.solver.preset ? QString("accuracy ") + ToString(*s.solver.preset)
                                      : QString("solver.mesh_scale"));
    mesh_info_->setText(info);
  } else {
    mesh_info_->setText(document_->modelProblem());
  }
  thickness_->setValue(s.material.thickness, units_);
  weight_->setValue(s.material.areal_weight, units_);
  const auto* iso = std::get_if<IsotropicMembrane>(&s.material.membrane);
  const auto* orthotropic = std::get_if<OrthotropicMembrane>(&s.material.membrane);
  membrane_->setCurrentIndex(iso ? 0 : 1);
  for (QWidget* f : std::initializer_list<QWidget*>{modulus_, poisson_})
    material_form_->setRowVisible(f, iso != nullptr);
  for (QWidget* f : std::initializer_list<QWidget*>{e1_, e2_, nu12_, g12_})
    material_form_->setRowVisible(f, orthotropic != nullptr);
  if (iso) {
    modulus_->setValue(iso->youngs_modulus, units_);
    poisson_->setValue(iso->poisson_ratio, QString::number(iso->poisson_ratio));
  }
  if (orthotropic) {
    e1_->setValue(orthotropic->e1, units_);
    e2_->setValue(orthotropic->e2, units_);
    nu12_->setValue(orthotropic->nu12, QString::number(orthotropic->nu12));
    g12_->setValue(orthotropic->g12, units_);
  }
  angle_->setValue(s.material.angle_deg * M_PI / 180, QString("%1 deg").arg(s.material.angle_deg));
  preset_->setCurrentIndex(s.solver.preset ? static_cast<int>(*s.solver.preset)
                                           : static_cast<int>(PresetDefinitions().size()));
  error_estimate_->setChecked(s.solver.error_estimate);
  tolerance_->setValue(s.solver.tolerance, QString::number(s.solver.tolerance));
  target_iterations_->setValue(s.solver.target_iterations);
  max_steps_->setValue(s.solver.max_steps);
  time_limit_->setValue(s.solver.max_wall_s.value_or(0));
  sequencing_->setValue(s.solver.sequencing);
  branching_->setCurrentIndex(s.solver.branching == Branching::kStable ? 0 : 1);
  refreshing_ = false;
}

}  // namespace drape
