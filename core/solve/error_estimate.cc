#include "core/solve/error_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/model/solver_preset.h"

namespace drape {
namespace {

// Differences below this [m] are round-off of positions of order a metre,
// and say nothing about convergence.
constexpr double kNoise = 1e-12;

}  // namespace

ErrorEstimate RichardsonEstimate(const std::vector<std::string>& names,
                                 const std::array<std::vector<Eigen::Vector3d>, 3>& positions,
                                 double formal_order) {
  ErrorEstimate out;
  const size_t n = names.size();
  for (const auto& p : positions)
    if (p.size() != n) {
      out.reason = "the three runs report different probes";
      return out;
    }
  if (n == 0) {
    out.reason = "the scene has no probes to estimate the error of";
    return out;
  }
  // The probe that moves most between h and 2h sets the order.
  size_t lead = 0;
  double largest = -1;
  for (size_t i = 0; i < n; ++i) {
    const double d = (positions[0][i] - positions[1][i]).norm();
    if (d > largest) largest = d, lead = i;
  }
  if (largest <= kNoise) {
    out.in_asymptotic_range = true;
    out.reason = "";
    for (size_t i = 0; i < n; ++i) out.probes.push_back({names[i], positions[0][i], 0, 0});
    return out;
  }
  const Eigen::Vector3d e21 = positions[0][lead] - positions[1][lead];
  const Eigen::Vector3d e32 = positions[1][lead] - positions[2][lead];
  out.order = e32.norm() > kNoise ? std::log(e32.norm() / e21.norm()) / std::log(2.0) : 0;
  char text[240];
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d a = positions[0][i] - positions[1][i];
    const Eigen::Vector3d b = positions[1][i] - positions[2][i];
    if (a.norm() <= kNoise && b.norm() <= kNoise) continue;
    const double cosine = a.dot(b) / std::max(a.norm() * b.norm(), 1e-300);
    const double p =
        a.norm() > kNoise && b.norm() > kNoise ? std::log(b.norm() / a.norm()) / std::log(2.0) : 0;
    if (cosine < 0.9) {
      std::snprintf(text,
                    sizeof text,
                    "probe '%s' does not converge monotonically (its changes from 4h to 2h and "
                    "from 2h to h turn by %.0f degrees)",
                    names[i].c_str(),
                    std::acos(std::clamp(cosine, -1.0, 1.0)) * 180 / M_PI);
      out.reason = text;
      return out;
    }
    if (p < formal_order - 0.75 || p > formal_order + 1) {
      std::snprintf(text,
                    sizeof text,
                    "probe '%s' converges at an observed order of %.2f, where these elements give "
                    "%.0f: the meshes are not in the asymptotic range (point supports or loads, "
                    "contact, or a mesh too coarse)",
                    names[i].c_str(),
                    p,
                    formal_order);
      out.reason = text;
      return out;
    }
  }
  out.in_asymptotic_range = true;
  const double denominator = std::pow(2.0, out.order) - 1;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d e = positions[0][i] - positions[1][i];
    ProbeErrorEstimate p;
    p.name = names[i];
    p.extrapolated = positions[0][i] + e / denominator;
    p.error = e.norm() / denominator;
    p.gci = 1.25 * p.error;
    out.probes.push_back(p);
  }
  return out;
}

std::optional<Scene> CoarsenedScene(const Scene& scene, int factor, std::string* why) {
  Scene coarse = scene;
  if (!scene.other_parts.empty()) {
    if (why) *why = "the error estimate coarsens a fabric of one part; this one has several";
    return std::nullopt;
  }
  if (scene.fabric.mesh.elements) {
    auto& e = *coarse.fabric.mesh.elements;
    bool any = false;
    for (int& n : e) {
      if (n < 2 * factor) continue;  // a strip's width stays
      if (n % factor != 0) {
        if (why)
          *why = "fabric.mesh.elements " + std::to_string((*scene.fabric.mesh.elements)[0]) +
                 " x " + std::to_string((*scene.fabric.mesh.elements)[1]) +
                 " cannot be divided by " + std::to_string(factor);
        return std::nullopt;
      }
      n /= factor;
      any = true;
    }
    if (!any) {
      if (why)
        *why = "the mesh is too coarse to make it " + std::to_string(factor) + " times coarser";
      return std::nullopt;
    }
  } else if (scene.fabric.mesh.size) {
    coarse.fabric.mesh.size = *scene.fabric.mesh.size * factor;
  } else {
    if (why) *why = "the mesh has neither elements nor a size";
    return std::nullopt;
  }
  coarse.solver.sequencing = 1;
  return coarse;
}

ErrorEstimate EstimateError(const Scene& written,
                            const SolverOptions& options,
                            const std::vector<NamedVector>& fine,
                            CancellationToken* cancel) {
  // Coarsened from the mesh that was solved, a preset's density applied.
  const Scene scene = SceneOnSolvedMesh(written);
  ErrorEstimate failed;
  failed.meshes[0] = MeshName(scene);
  std::array<std::vector<Eigen::Vector3d>, 3> positions;
  std::vector<std::string> names;
  for (const NamedVector& p : fine) {
    names.push_back(p.name);
    positions[0].push_back(p.value);
  }
  for (int level = 1; level <= 2; ++level) {
    const int factor = level == 1 ? 2 : 4;
    std::string why;
    const std::optional<Scene> coarse = CoarsenedScene(scene, factor, &why);
    if (!coarse) {
      failed.reason = "no mesh " + std::to_string(factor) + " times coarser: " + why;
      if (written.solver.mesh_scale != 1) {
        char scale[96];
        std::snprintf(scale,
                      sizeof scale,
                      " (the mesh solved: fabric.mesh at solver.mesh_scale %g)",
                      written.solver.mesh_scale);
        failed.reason += scale;
      }
      return failed;
    }
    failed.meshes[level] = MeshName(*coarse);
    SolverOptions quiet = options;
    quiet.max_wall_s = 0;
    ShellSolver solver(*coarse, quiet);
    std::vector<NamedVector> last;
    const SolveSummary summary = solver.Solve({[&](const StepState& s) {
                                                last = s.probes;
                                                return StepDecision::kContinue;
                                              }},
                                              cancel);
    if (!summary.IsComplete()) {
      failed.reason = "the run on the mesh " + std::to_string(factor) + " times coarser (" +
                      failed.meshes[level] + ") did not converge: " + summary.message;
      return failed;
    }
    for (const std::string& name : names) {
      const auto it = std::find_if(
          last.begin(), last.end(), [&](const NamedVector& v) { return v.name == name; });
      positions[level].push_back(it == last.end() ? Eigen::Vector3d::Zero() : it->value);
    }
  }
  ErrorEstimate estimate = RichardsonEstimate(names, positions);
  estimate.meshes = failed.meshes;
  return estimate;
}

std::string Describe(const ErrorEstimate& e, const DisplayUnit& unit) {
  std::string meshes = e.meshes[0];
  for (int i = 1; i < 3; ++i)
    if (!e.meshes[i].empty()) meshes += ", " + e.meshes[i];
  if (!e.in_asymptotic_range) return "error estimate (" + meshes + "): none, " + e.reason;
  char text[160];
  std::snprintf(text, sizeof text, "error estimate (%s): order %.2f", meshes.c_str(), e.order);
  std::string line = text;
  for (const ProbeErrorEstimate& p : e.probes) {
    std::snprintf(text,
                  sizeof text,
                  "; %s ±%.3g %s",
                  p.name.c_str(),
                  p.error / unit.si_factor,
                  unit.label.c_str());
    line += text;
  }
  return line;
}

DisplayUnit ErrorUnit(UnitSystem system) {
  return system == UnitSystem::kImperial ? UnitFor(Measure::kLength, system)
                                         : DisplayUnit{"mm", 1e-3};
}

std::string MeshName(const Scene& scene) {
  if (scene.fabric.mesh.elements)
    return std::to_string((*scene.fabric.mesh.elements)[0]) + " x " +
           std::to_string((*scene.fabric.mesh.elements)[1]);
  char text[40];
  std::snprintf(text, sizeof text, "size %.3g mm", 1e3 * scene.fabric.mesh.size.value_or(0));
  return text;
}

}  // namespace drape
