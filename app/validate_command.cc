// `drape validate SCENE [--resolved]`: read, check and mesh a scene; print a
// summary, or with --resolved the scene as JSON in SI numbers.
#include <CLI/CLI.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.h"
#include "core/contact/contact_setup.h"
#include "core/fe/fabric_plausibility.h"
#include "core/io/scene_reader.h"
#include "core/io/scene_writer.h"
#include "core/model/fabric_mesh.h"
#include "core/model/node_selection.h"
#include "core/model/obstacle_geometry.h"
#include "core/model/scene_error.h"
#include "core/model/solver_preset.h"

namespace drape::app {
namespace {

struct ValidateArgs {
  std::string scene;
  bool resolved = false;
};

void PrintSummary(const std::string& file,
                  const Scene& scene,
                  const Mesh& mesh,
                  const std::vector<ResolvedSelection>& selections) {
  std::cout << file << ": valid scene";
  if (!scene.name.empty()) std::cout << " \"" << scene.name << "\"";
  std::cout << "\n";
  std::cout << "  mesh        " << mesh.NodeCount() << " nodes, " << mesh.ElementCount()
            << " elements, " << 5 * mesh.NodeCount() << " DOFs (5 per node)";
  if (scene.solver.mesh_scale != 1)
    std::cout << ", fabric.mesh at solver.mesh_scale " << scene.solver.mesh_scale;
  std::cout << "\n";
  if (scene.solver.preset)
    std::cout << "  preset      " << ToString(*scene.solver.preset) << ": "
              << Definition(*scene.solver.preset).purpose << "\n";
  std::cout << "  stages      " << scene.stages.size() << ":";
  for (size_t i = 0; i < scene.stages.size(); ++i)
    std::cout << (i ? ", " : " ") << scene.stages[i].name << " (" << ToString(scene.stages[i].kind)
              << ")";
  std::cout << "\n";
  for (const auto& s : selections)
    std::cout << "  " << std::left << std::setw(26) << s.path << " " << std::setw(12) << s.name
              << " " << s.nodes.size() << (s.nodes.size() == 1 ? " node" : " nodes") << "\n";
  if (!scene.obstacles.empty()) std::cout << "  obstacles   " << scene.obstacles.size() << "\n";
  if (!scene.probes.empty()) std::cout << "  probes      " << scene.probes.size() << "\n";
}

int RunValidate(const ValidateArgs& args) {
  try {
    Scene scene = ReadScene(args.scene);
    Mesh mesh = MeshFabric(SceneOnSolvedMesh(scene).fabric);
    auto selections = ResolveSelections(scene, mesh);
    const double diagonal =
        (mesh.positions.colwise().maxCoeff() - mesh.positions.colwise().minCoeff()).norm();
    CheckFrictionSlip(scene, diagonal);
    CheckBarrierDistance(scene, diagonal);
    // Mesh obstacles are read and checked (closed, readable) here too.
    for (size_t i = 0; i < scene.obstacles.size(); ++i)
      MakeObstacleGeometry(scene.obstacles[i], ".", "obstacles[" + std::to_string(i) + "]");
    // Values no fabric has (most often a unit that slipped) are said, not refused.
    for (const Implausible& value : ImplausibleFabric(scene.material))
      std::cerr << "drape validate: warning: " << Describe(value) << "\n";
    if (args.resolved)
      std::cout << WriteSceneText(scene);
    else
      PrintSummary(args.scene, scene, mesh, selections);
    return 0;
  } catch (const SceneError& e) {
    std::cerr << "drape validate: " << args.scene << ": " << e.what() << "\n";
    return 1;
  }
}

}  // namespace

void AddValidateCommand(CLI::App& app, CommandRunner& runner) {
  auto args = std::make_shared<ValidateArgs>();
  CLI::App* cmd = app.add_subcommand("validate", "Check a scene file and print what it describes");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required();
  cmd->add_flag(
      "--resolved", args->resolved, "Print the scene as JSON with every quantity in SI numbers");
  cmd->callback([args, &runner] { runner = [args] { return RunValidate(*args); }; });
}

}  // namespace drape::app
