// How far a run's answer is from the converged one, estimated from the run
// itself and the same scene on meshes 2 and 4 times coarser: Richardson's
// extrapolation with the observed order, and Roache's grid convergence
// index (P. J. Roache, "Quantification of uncertainty in computational fluid
// dynamics", Annu. Rev. Fluid Mech. 29, 1997). Where the three answers do
// not converge like h^p with a plausible p (point supports, a mesh too
// coarse, a different branch), it says so instead of giving a number.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/model/scene.h"
#include "core/model/unit_system.h"
#include "core/solve/shell_solver.h"
#include "core/solve/step_state.h"

namespace drape {

struct ProbeErrorEstimate {
  std::string name;
  Eigen::Vector3d extrapolated = Eigen::Vector3d::Zero();  // [m]
  double error = 0;                                        // |f_h − f_extrapolated| [m]
  double gci = 0;  // 1.25 × error: Roache's band with safety factor 1.25 [m]
};

struct ErrorEstimate {
  double order = 0;  // observed p (0 when none could be measured)
  bool in_asymptotic_range = false;
  std::string reason;                      // why not, when not
  std::vector<ProbeErrorEstimate> probes;  // empty when not in range
  std::array<std::string, 3> meshes;       // "80 x 2", "40 x 2", "20 x 2"
};

// The estimate from each probe's final position on the run's mesh (h) and
// on meshes 2h and 4h, same names in the same order. The order comes from
// the probe that moves most between h and 2h; the three answers are in the
// asymptotic range when every probe that moves converges monotonically
// (its two differences point the same way) at an order within
// [formal − 0.75, formal + 1] of the element's (2 for displacements).
ErrorEstimate RichardsonEstimate(const std::vector<std::string>& names,
                                 const std::array<std::vector<Eigen::Vector3d>, 3>& positions,
                                 double formal_order = 2);

// The scene on a mesh `factor` times coarser in each direction that has at
// least 2·factor elements (a strip's width of one or two elements stays),
// or with `mesh.size` times `factor`. Empty (with `why`) when the mesh
// cannot be coarsened so (elements not divisible by it).
std::optional<Scene> CoarsenedScene(const Scene& scene, int factor, std::string* why);

// Solves the scene on meshes 2h and 4h (with `options`, no output) and
// estimates the error of `fine`, the run's own final probe positions. A
// coarse run that does not converge gives no estimate, and says so.
ErrorEstimate EstimateError(const Scene& scene,
                            const SolverOptions& options,
                            const std::vector<NamedVector>& fine,
                            CancellationToken* cancel = nullptr);

// One line: "error estimate (80 x 2, 40 x 2, 20 x 2): order 2.01; tip
// ±0.07 mm, …", or why there is none; the errors in `unit`.
std::string Describe(const ErrorEstimate& estimate, const DisplayUnit& unit = {"mm", 1e-3});

// The unit an error of a position is read in: mm in SI and textile units
// (errors are fractions of a centimetre), in for imperial.
DisplayUnit ErrorUnit(UnitSystem system);

// "80 x 2" or "size 5 mm".
std::string MeshName(const Scene& scene);

}  // namespace drape
