#include "core/io/result_writer.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "core/io/scene_writer.h"
#include "core/io/state_file.h"
#include "core/solve/error_estimate.h"

namespace drape {
namespace {

// The scene a result carries must read back without the files it named:
// measured curves keep their points (SI), meshes and patterns their absolute
// paths.
Scene SelfContained(Scene scene) {
  auto embed = [](BendingLaw& law) {
    if (auto* curve = std::get_if<CurveBending>(&law)) curve->file.clear();
  };
  embed(scene.material.bending.warp);
  if (scene.material.bending.weft) embed(*scene.material.bending.weft);
  for (auto& obstacle : scene.obstacles)
    if (auto* mesh = std::get_if<MeshShape>(&obstacle.shape); mesh && !mesh->resolved_path.empty())
      mesh->file = mesh->resolved_path;
  auto absolute = [](Fabric& part) {
    if (auto* pattern = std::get_if<PatternOutline>(&part.outline);
        pattern && !pattern->resolved_path.empty())
      pattern->file = pattern->resolved_path;
  };
  absolute(scene.fabric);
  for (Fabric& part : scene.other_parts) absolute(part);
  return scene;
}

using json = nlohmann::ordered_json;

json Vector(const Eigen::Vector3d& v) {
  return json::array({v.x(), v.y(), v.z()});
}

json Named(const std::vector<NamedVector>& values) {
  json j = json::object();
  for (const auto& v : values) j[v.name] = Vector(v.value);
  return j;
}

}  // namespace

std::string ResultStatus(Termination termination) {
  switch (termination) {
    case Termination::kCompleted:
      return "converged";
    case Termination::kCancelled:
    case Termination::kStoppedByObserver:
      return "cancelled";
    default:
      return "failed";
  }
}

struct ResultWriter::Impl {
  json scene_resolved;
  std::string scene_name;
  int nodes = 0, elements = 0, dofs = 0;
  json parts;  // null for a fabric of one part
  std::unique_ptr<StateFileWriter> states;
  std::ofstream csv;
  json steps = json::array();
  StepState last;
  bool has_last = false;
  bool contact = false;  // the scene has obstacles
  std::vector<std::string> obstacle_names;
  // The provisional result.json kept current while the run goes: when it
  // was last written and how long that took.
  std::chrono::steady_clock::time_point last_written;
  double write_s = 0;
  json error_estimate;  // null until set
};

ResultWriter::ResultWriter(const std::filesystem::path& directory,
                           const Scene& scene,
                           const ShellModel& model)
    : impl_(std::make_unique<Impl>()), directory_(directory) {
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec) throw std::runtime_error("cannot create '" + directory.string() + "': " + ec.message());
  // A result folder reused from an earlier run must not describe two runs at
  // once: the old result goes before the new one starts.
  std::filesystem::remove(directory / kResultFileName, ec);
  impl_->scene_resolved = SceneToJson(SelfContained(scene));
  impl_->scene_name = scene.name;
  impl_->nodes = model.NodeCount();
  impl_->elements = model.mesh.ElementCount();
  impl_->dofs = model.DofCount();
  if (!scene.other_parts.empty()) {
    const auto fabric = FabricParts(scene);
    const auto spans = PartsOf(model.mesh);
    impl_->parts = json::array();
    for (std::size_t p = 0; p < spans.size() && p < fabric.size(); ++p)
      impl_->parts.push_back({{"name", fabric[p]->name},
                              {"first_node", spans[p].first_node},
                              {"nodes", spans[p].nodes},
                              {"first_element", spans[p].first_element},
                              {"elements", spans[p].elements}});
  }
  impl_->states = std::make_unique<StateFileWriter>(directory / kStatesFileName, model.mesh);
  impl_->csv.open(directory / kStepsCsvFileName);
  if (!impl_->csv)
    throw std::runtime_error("cannot create '" + (directory / kStepsCsvFileName).string() + "'");
  impl_->contact = !scene.obstacles.empty();
  for (const auto& o : scene.obstacles) impl_->obstacle_names.push_back(o.name);
  impl_->csv << "stage,stage_name,step,lambda,iterations,arc_length,negative_pivots";
  if (impl_->contact)
    impl_->csv << ",contact_nodes,contact_force_x_N,contact_force_y_N,contact_force_z_N,"
                  "max_penetration_m";
  for (const auto& probe : model.probes)
    for (const char* axis : {"x", "y", "z"}) impl_->csv << "," << probe.name << "_" << axis << "_m";
  impl_->csv << ",event\n";
  impl_->csv.flush();
  // A folder that reads from the start: status "running", no step yet.
  SolveSummary running;
  running.message = "running: no step converged yet";
  Write(Document(running, "running"));
  impl_->last_written = std::chrono::steady_clock::now();
}

ResultWriter::~ResultWriter() = default;

namespace {

// One row of steps.csv (header: ResultWriter's constructor).
std::string StepsCsvRow(const StepState& step, bool with_contact) {
  std::ostringstream csv;
  csv.precision(17);
  // Stage names are user text: quote them for CSV.
  std::string name = step.stage_name;
  for (size_t at = 0; (at = name.find('"', at)) != std::string::npos; at += 2)
    name.insert(at, 1, '"');
  csv << step.stage << ",\"" << name << "\"," << step.step << "," << step.lambda << ","
      << step.iterations << "," << step.arc_length << "," << step.negative_pivots;
  if (with_contact) {
    const ContactReport c = step.contact.value_or(ContactReport{});
    csv << "," << c.nodes << "," << c.force.x() << "," << c.force.y() << "," << c.force.z() << ","
        << c.max_penetration;
  }
  for (const auto& p : step.probes)
    csv << "," << p.value.x() << "," << p.value.y() << "," << p.value.z();
  // The stability event the step ends (a limit or bifurcation passed, a snap
  // landed), blank for none.
  csv << "," << (step.stability_event ? ToString(step.stability_event->kind) : "") << "\n";
  return csv.str();
}

}  // namespace

void ResultWriter::AddStep(const StepState& step) {
  impl_->states->Append(
      {step.stage, step.step, step.lambda, step.state.positions, step.state.Directors()});
  json s{{"stage", step.stage},
         {"step", step.step},
         {"lambda", step.lambda},
         {"iterations", step.iterations},
         {"residuals", step.residuals},
         {"residual_ratio", step.residuals.empty() ? 0.0 : step.residuals.back()},
         {"converged_by", ToString(step.convergence)},
         {"arc_length", step.arc_length},
         {"negative_pivots", step.negative_pivots},
         {"max_curvature", step.max_curvature},
         {"law_curvature", step.law_curvature},
         {"reactions", Named(step.reactions)},
         {"probes", Named(step.probes)}};
  if (step.layer_distance) {
    s["layers"] = {{"min_distance", *step.layer_distance}};
    if (step.layer_force) s["layers"]["force"] = *step.layer_force;
  }
  if (step.contact) {
    s["contact"] = {{"nodes", step.contact->nodes},
                    {"force", Vector(step.contact->force)},
                    {"max_penetration", step.contact->max_penetration}};
    if (step.contact->with_friction)
      s["contact"]["friction"] = {{"sticking", step.contact->sticking},
                                  {"sliding", step.contact->sliding},
                                  {"force", Vector(step.contact->friction_force)}};
    if (step.contact->max_stabilization_force > 0)
      s["contact"]["max_stabilization_force"] = step.contact->max_stabilization_force;
    if (step.contact->penetration_target > 0) {
      s["contact"]["penetration_target"] = step.contact->penetration_target;
      s["contact"]["augmentation_passes"] = step.contact->augmentation_passes;
      if (!step.contact->augmentation_shortfall.empty())
        s["contact"]["penetration_target_missed"] = step.contact->augmentation_shortfall;
    }
  }
  // Obstacles a stage moved: where each one is (world = R x_scene + t).
  for (size_t o = 0; o < step.state.obstacles.size() && o < impl_->obstacle_names.size(); ++o) {
    const ObstaclePlacement& p = step.state.obstacles[o];
    if (p.IsIdentity()) continue;
    json rotation = json::array();
    for (int r = 0; r < 3; ++r)
      rotation.push_back({p.rotation(r, 0), p.rotation(r, 1), p.rotation(r, 2)});
    s["obstacles"][impl_->obstacle_names[o]] = {{"rotation", rotation},
                                                {"translation", Vector(p.translation)}};
  }
  impl_->steps.push_back(std::move(s));
  // One line, written whole: a process killed at any moment leaves no half
  // line behind.
  impl_->csv << StepsCsvRow(step, impl_->contact);
  impl_->csv.flush();
  impl_->last = step;
  impl_->has_last = true;
  // Kept current as steps converge, at most as often as writing it takes
  // 5 % of the time (it grows with the steps), and after the first step.
  const auto now = std::chrono::steady_clock::now();
  if (impl_->steps.size() == 1 ||
      std::chrono::duration<double>(now - impl_->last_written).count() >=
          std::max(1.0, 20 * impl_->write_s)) {
    SolveSummary running;
    running.message = "running: " + std::to_string(impl_->steps.size()) + " steps converged so far";
    Write(Document(running, "running"));
    impl_->write_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - now).count();
    impl_->last_written = now;
  }
}

void ResultWriter::Finish(const SolveSummary& summary) {
  Write(Document(summary, ResultStatus(summary.termination)));
}

nlohmann::json ResultWriter::Document(const SolveSummary& summary,
                                      const std::string& status) const {
  json r;
  r["drape_result"] = kResultFormatVersion;
  r["scene"] = impl_->scene_name;
  r["status"] = status;
  r["message"] = summary.message;
  r["mesh"] = {{"nodes", impl_->nodes}, {"elements", impl_->elements}, {"dofs", impl_->dofs}};
  if (!impl_->parts.is_null()) r["mesh"]["parts"] = impl_->parts;
  r["stages"] = json::array();
  for (const auto& st : summary.stages)
    r["stages"].push_back({{"name", st.name},
                           {"steps", st.steps},
                           {"iterations", st.iterations},
                           {"step_cuts", st.step_cuts},
                           {"control", ToString(st.control_used)},
                           {"final_lambda", st.final_lambda}});
  r["stability_events"] = json::array();
  for (const auto& e : summary.stability_events) {
    json event{{"stage", e.stage},
               {"step", e.step},
               {"kind", ToString(e.kind)},
               {"lambda", e.lambda},
               {"negative_pivots_before", e.negative_pivots_before},
               {"negative_pivots_after", e.negative_pivots_after},
               {"branch", ToString(e.branch)}};
    if (e.branch == Branch::kStable) {
      event["negative_pivots_fundamental"] = e.negative_pivots_fundamental;
      event["modes"] = e.modes;
      event["mode_max_displacement"] = e.mode_max_displacement;
      event["switch_iterations"] = e.switch_iterations;
      event["switch_s"] = e.switch_s;
    }
    if (e.kind == StabilityKind::kSnap) {
      event["trigger"] = ToString(e.trigger);
      event["negative_pivots_fundamental"] = e.negative_pivots_fundamental;
      event["energy_released"] = e.energy_released;
      event["max_displacement"] = e.mode_max_displacement;
      event["iterations"] = e.switch_iterations;
      event["time_s"] = e.switch_s;
    }
    r["stability_events"].push_back(std::move(event));
  }
  r["notes"] = summary.notes;
  r["warnings"] = summary.warnings;
  // JSON has no infinity: a linear law's unlimited range is null.
  r["bending"] = {
      {"max_curvature", summary.max_curvature},
      {"max_law_curvature", summary.max_law_curvature},
      {"valid_to",
       std::isfinite(summary.bending_valid_to) ? json(summary.bending_valid_to) : json(nullptr)}};
  if (summary.contact_penalty > 0)
    r["contact"] = {{"penalty", summary.contact_penalty},
                    {"max_penetration", summary.max_penetration},
                    {"max_stabilization_force", summary.max_stabilization_force}};
  r["steps"] = impl_->steps;
  json final_state = json::object();
  if (impl_->has_last) {
    json positions = json::array();
    const auto& x = impl_->last.state.positions;
    for (int i = 0; i < x.rows(); ++i) positions.push_back({x(i, 0), x(i, 1), x(i, 2)});
    final_state["step"] = impl_->last.step;
    final_state["positions"] = std::move(positions);
    final_state["probes"] = Named(impl_->last.probes);
    if (impl_->last.contact) {
      final_state["contact_pressure"] = impl_->last.contact->pressure;
      if (impl_->last.contact->with_friction) {
        json slip = json::array();
        for (SlipState s : impl_->last.contact->friction) slip.push_back(static_cast<int>(s));
        final_state["friction_state"] = std::move(slip);
      }
    }
  }
  r["final"] = std::move(final_state);
  r["timing"] = {{"total_s", summary.total_s},
                 {"assembly_s", summary.assembly_s},
                 {"factorization_s", summary.factorization_s},
                 {"solve_s", summary.solve_s},
                 {"peak_memory_bytes", summary.peak_memory_bytes}};
  r["counts"] = {{"steps", summary.steps},
                 {"iterations", summary.iterations},
                 {"factorizations", summary.factorizations}};
  if (!impl_->error_estimate.is_null()) r["error_estimate"] = impl_->error_estimate;
  r["states_file"] = kStatesFileName;
  r["scene_resolved"] = impl_->scene_resolved;
  return r;
}

void ResultWriter::SetErrorEstimate(const ErrorEstimate& e) {
  json j = {
      {"order", e.order}, {"in_asymptotic_range", e.in_asymptotic_range}, {"meshes", e.meshes}};
  if (!e.in_asymptotic_range) j["reason"] = e.reason;
  json probes = json::object();
  for (const ProbeErrorEstimate& p : e.probes)
    probes[p.name] = {
        {"error", p.error},
        {"gci", p.gci},
        {"extrapolated", {p.extrapolated.x(), p.extrapolated.y(), p.extrapolated.z()}}};
  j["probes"] = std::move(probes);
  impl_->error_estimate = std::move(j);
}

void ResultWriter::Write(const nlohmann::json& r) const {
  const auto path = directory_ / kResultFileName;
  const auto temporary = directory_ / (std::string(kResultFileName) + ".part");
  {
    std::ofstream out(temporary, std::ios::binary);
    out << FormatJson(r);
    if (!out) throw std::runtime_error("cannot write '" + temporary.string() + "'");
  }
  // Rename so a reader never sees half a file.
  std::filesystem::rename(temporary, path);
}

}  // namespace drape
