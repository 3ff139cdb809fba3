// Contact's cost (issue 6):
//  - the paper's rod drape (20 × 20, linear bending) and diagonal fold
//    (20 × 20, linear bending) end to end (targets < 0.5 s and < 1 s);
//  - one assembly of the internal force and tangent of an n × n sheet lying
//    on a table: without obstacles (contact code never runs), with the table
//    far below (every node queried, none in contact) and with every node in
//    contact — the price of contact per Newton iteration.
// Results and the machine are in docs/performance.md.
#include <benchmark/benchmark.h>

#include <array>
#include <string>

#include "core/contact/node_contact.h"
#include "core/contact/self_contact.h"
#include "core/contact/self_proximity.h"
#include "core/continuation/equilibrium_system.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_model.h"
#include "core/io/scene_reader.h"
#include "core/solve/shell_solver.h"
#include "scene_solve.h"
#include "support/test_paths.h"

namespace drape {
namespace {

void BM_Scene(benchmark::State& bench, const char* file) {
  SolveSceneForBenchmark(bench, ReadScene(test::ScenesDir() / file));
}
BENCHMARK_CAPTURE(BM_Scene, rod_drape, "rod-drape-linear.json")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Scene, diagonal_fold, "diagonal-fold-linear.json")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->UseRealTime();

enum class Table { kNone, kFarBelow, kTouching };

// Argument (n, table): the sheet's reference state, its nodes h/2 above the
// table when touching (every node in contact with zero gap: the full contact
// tangent is assembled).
void BM_AssembleOnTable(benchmark::State& bench) {
  const int n = static_cast<int>(bench.range(0));
  const auto table = static_cast<Table>(bench.range(1));
  Scene scene = ReadScene(test::ScenesDir() / "block-drape.json");
  scene.fabric.mesh.elements = std::array<int, 2>{n, n};
  const ShellModel model = BuildShellModel(scene);
  std::unique_ptr<NodeContact> contact;
  if (table != Table::kNone) {
    const double below = table == Table::kTouching ? 0.5 * model.thickness : 1.0;
    std::vector<NamedObstacle> obstacles;
    obstacles.push_back(
        {"table",
         MakeObstacleGeometry(Obstacle{"table", PlaneShape{{0, 0, -below}, {0, 0, 1}}}, ".")});
    contact = std::make_unique<NodeContact>(
        model, std::move(obstacles), NormalLaw{AutoPenalty(model)}, 0.0);
  }
  DofMap dofs(model.NodeCount());
  for (const auto& held : model.supports)
    for (int node : held.nodes) dofs.FixNode(node, held.fixity);
  EquilibriumSystem system(model, dofs, contact.get());
  for (auto _ : bench) benchmark::DoNotOptimize(system.Assemble(model.reference, true));
  if (contact) bench.counters["nodes_in_contact"] = contact->Report(model.reference).nodes;
}
BENCHMARK(BM_AssembleOnTable)
    ->ArgNames({"n", "table"})
    ->ArgsProduct({{20, 100}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Self-contact (issue 17) on a 20 × 10 cm sheet of nx × nx/2 elements:
// 100 (5 151 nodes), 140 (10 011), 200 (20 301). Folded flat onto itself
// one thickness (h = 0.5 mm) apart, or lying flat (nothing within reach).
Mesh BenchSheet(int nx) {
  const int ny = nx / 2;
  Mesh mesh;
  mesh.positions.resize((nx + 1) * (ny + 1), 3);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      mesh.positions.row(j * (nx + 1) + i) << 0.2 * i / nx, 0.1 * j / ny, 0;
  mesh.quads.resize(nx * ny, 4);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n = j * (nx + 1) + i;
      mesh.quads.row(j * nx + i) << n, n + 1, n + nx + 2, n + nx + 1;
    }
  return mesh;
}

Positions FoldedFlat(const Mesh& mesh) {
  Positions folded = mesh.positions;
  for (int i = 0; i < folded.rows(); ++i)
    if (folded(i, 0) > 0.1 + 1e-12) folded.row(i) << 0.2 - folded(i, 0), folded(i, 1), 5e-4;
  return folded;
}

// The broad phase alone: every pair within 1.5 h (the barrier's reach: the
// thickness and half of it) and more than 1 cm apart at rest.
void BM_SelfProximity(benchmark::State& bench) {
  const Mesh mesh = BenchSheet(static_cast<int>(bench.range(0)));
  const Positions x = bench.range(1) ? FoldedFlat(mesh) : Positions(mesh.positions);
  const SelfProximity proximity(mesh, 0.01);
  ProximityPairs pairs;
  for (auto _ : bench) pairs = proximity.Candidates(x, 7.5e-4);
  bench.counters["nodes"] = static_cast<double>(x.rows());
  bench.counters["point_triangle"] = static_cast<double>(pairs.point_triangle.size());
  bench.counters["edge_edge"] = static_cast<double>(pairs.edge_edge.size());
}
BENCHMARK(BM_SelfProximity)
    ->ArgNames({"n", "folded"})
    ->ArgsProduct({{100, 140, 200}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// What self-contact adds to one Newton iteration once its list of pairs is
// made (the list is searched again only after the nodes moved): the
// barrier's energy, gradient and 12 × 12 blocks over every pair in reach.
void BM_SelfContactEvaluate(benchmark::State& bench) {
  const Mesh mesh = BenchSheet(static_cast<int>(bench.range(0)));
  const Positions x = bench.range(1) ? FoldedFlat(mesh) : Positions(mesh.positions);
  SelfContactSettings settings;
  settings.offset = 4.5e-4;  // the layers 1.11 h apart, inside the band
  settings.activation = 0.5 * settings.offset;
  settings.stiffness = 1e-3;
  settings.exclusion = 0.01;
  SelfContact contact(mesh, settings);
  contact.Evaluate(x, true);  // makes the list
  int active = 0;
  for (auto _ : bench) active = contact.Evaluate(x, true).active_pairs;
  bench.counters["nodes"] = static_cast<double>(x.rows());
  bench.counters["active_pairs"] = active;
}
BENCHMARK(BM_SelfContactEvaluate)
    ->ArgNames({"n", "folded"})
    ->ArgsProduct({{140}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace drape
