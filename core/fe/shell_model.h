// Everything about a scene that stays fixed during a run: the mesh and its
// reference geometry, the section law, the loads at λ = 1, which nodes the
// supports, grippers and loads hold, and where the probes are.
#pragma once

#include <Eigen/Core>

#include <array>
#include <limits>
#include <string>
#include <vector>

#include "core/fe/shell_state.h"
#include "core/mechanics/edge_twist.h"
#include "core/mechanics/shell_element.h"
#include "core/mechanics/shell_section.h"
#include "core/model/mesh.h"
#include "core/model/scene.h"

namespace drape {

struct HeldNodes {
  std::string name;
  std::vector<int> nodes;
  Fixity fixity = Fixity::kPosition;
};

// One segment of a loaded edge and its share of the moment about the edge's
// axis, which does work through the segment's twist (edge_twist.h).
struct EdgeMomentSegment {
  int nodes[2] = {0, 0};
  EdgeTwistReference reference;
  double moment = 0;  // about reference.axis [N·m]
};

struct NodalLoad {
  std::string name;
  std::vector<int> nodes;
  Eigen::Vector3d force_per_node = Eigen::Vector3d::Zero();  // [N]
  // The part of the moment a fixed vector on each node's rotation (all of it
  // unless the nodes are a line of element edges) [N·m].
  Eigen::Vector3d moment_per_node = Eigen::Vector3d::Zero();
  // On a line of element edges, the moment's part about that line.
  std::vector<EdgeMomentSegment> edge_segments;
};

// A material point given in reference coordinates: element and (ξ, η).
struct ProbePoint {
  std::string name;
  int element = 0;
  double xi = 0, eta = 0;
};

struct ShellModel {
  Mesh mesh;
  ShellSection section;
  std::vector<ShellElementReference> elements;
  ShellState reference;         // stress-free state
  Eigen::VectorXd weight_load;  // nodal self-weight at λ = 1, 5 per node [N]
  Eigen::Vector3d total_weight = Eigen::Vector3d::Zero();  // Σ weight [N]
  std::vector<HeldNodes> supports;
  std::vector<HeldNodes> grippers;
  std::vector<NodalLoad> loads;
  std::vector<ProbePoint> probes;
  double characteristic_length = 0;  // diagonal of the part [m]
  double thickness = 0;              // h [m]
  // |K| up to which the bending laws are data or fit [1/m]; ∞ when linear.
  double bending_valid_to = std::numeric_limits<double>::infinity();
  std::vector<std::string> warnings;  // about the scene's material, each naming its key

  int NodeCount() const { return mesh.NodeCount(); }
  int DofCount() const { return kDofsPerNode * mesh.NodeCount(); }
};

// Builds the model of a scene. Throws SceneError naming the key of anything
// the engine cannot model (it never silently ignores one).
ShellModel BuildShellModel(const Scene& scene);
// The same on a given reference mesh instead of meshing the scene's outline
// (patch tests, imported meshes). Selections still use the outline.
ShellModel BuildShellModel(const Scene& scene, Mesh mesh);

// (ξ, η) of the reference point `p` (x, y) in element `e`, by Newton on the
// bilinear map; false when it lies outside the element (beyond round-off).
bool LocateInElement(const Mesh& mesh, int e, const Vec2& p, double& xi, double& eta);

// A probe of a fabric of several parts located in its part.
ProbePoint LocateProbeInParts(const Scene& scene, const Mesh& mesh, const Probe& probe);

// Where a reference point lies: its element and (ξ, η) in it; a point off
// the mesh (a curved outline's meshed polygon lies slightly inside) goes to
// the nearest node.
ProbePoint LocateProbe(const Mesh& mesh, const Probe& probe);

// The bending strains of element `e` in `state` at its four Gauss points,
// in the material frame (BendingStrains on the element's nodes).
std::array<Eigen::Vector3d, 4> ElementBendingStrains(const ShellModel& model,
                                                     const ShellState& state,
                                                     int e);

// Position of a probe in a state: Σ N_I(ξ, η) φ_I over its element.
Eigen::Vector3d ProbePosition(const ShellModel& model,
                              const ProbePoint& probe,
                              const ShellState& state);

}  // namespace drape
