#include "ui/render/drape_shadow_actors.h"

#include "core/measure/drape_test_setup.h"
#include "ui/render/scene_actors.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkContourTriangulator.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace drape {
namespace {

template <typename T>
using Ptr = vtkSmartPointer<T>;

// The drapemeter's shadow on its paper ring: dark grey-blue, and the rims
// in the colours of the glyphs that hold the part (the disc) and of the
// floor grid (the flat specimen).
constexpr double kShadowColour[3] = {0.22, 0.24, 0.32};
constexpr double kDiscColour[3] = {0.85, 0.15, 0.1};
constexpr double kSpecimenColour[3] = {0.45, 0.47, 0.5};
constexpr int kRimPoints = 360;

void AddRing(vtkPoints* points, vtkCellArray* lines, const std::vector<Eigen::Vector3d>& ring) {
  const vtkIdType first = points->GetNumberOfPoints();
  for (const auto& p : ring) points->InsertNextPoint(p.data());
  lines->InsertNextCell(static_cast<vtkIdType>(ring.size() + 1));
  for (size_t i = 0; i < ring.size(); ++i)
    lines->InsertCellPoint(first + static_cast<vtkIdType>(i));
  lines->InsertCellPoint(first);
}

Ptr<vtkActor> RimActor(const std::vector<Eigen::Vector3d>& ring,
                       const double colour[3],
                       double width) {
  auto points = Ptr<vtkPoints>::New();
  auto lines = Ptr<vtkCellArray>::New();
  AddRing(points, lines, ring);
  auto rim = Ptr<vtkPolyData>::New();
  rim->SetPoints(points);
  rim->SetLines(lines);
  auto actor = ActorOf(rim);
  actor->GetProperty()->SetLineWidth(width);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->LightingOff();
  return actor;
}

}  // namespace

std::optional<DrapeTestOptions> DrapemeterTestOf(const Scene& scene, const Mesh& mesh) {
  try {
    return DrapeTestFor(scene, mesh, std::nullopt, std::nullopt);
  } catch (const DrapeTestError&) {
    return std::nullopt;
  }
}

std::vector<Eigen::Vector3d> DrapeShadowActors::Rim(double radius, double depth) const {
  std::vector<Eigen::Vector3d> ring;
  for (int k = 0; k < kRimPoints; ++k) {
    const double a = 2 * M_PI * k / kRimPoints;
    ring.push_back(OnPlane({radius * std::cos(a), radius * std::sin(a)}, depth));
  }
  return ring;
}

DrapeShadowActors::DrapeShadowActors(vtkRenderer* renderer,
                                     const DrapeTestOptions& test,
                                     const Eigen::AlignedBox3d& bounds)
    : test_(test), plane_(ShadowPlane::Across(test.down, test.centre)) {
  const Eigen::Vector3d down = test.down.normalized();
  double lowest = 0;
  for (int k = 0; k < 8; ++k)
    lowest = std::max(
        lowest,
        (bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)) - test.centre).dot(down));
  // Nothing held by the disc hangs lower than the specimen's reach beyond
  // it: the plane stays under every state when `bounds` holds only the
  // flat reference (the workbench, before a run).
  const double hanging = std::sqrt(test.specimen_area / M_PI) - test.disc_radius;
  shadow_depth_ = std::max(lowest, hanging) + 0.01 * bounds.diagonal().norm();

  // The rims, just above the disc (over the fabric seen from above).
  const double specimen_radius = std::sqrt(test.specimen_area / M_PI);
  const double lift = -0.002 * bounds.diagonal().norm();
  disc_rim_ = RimActor(Rim(test.disc_radius, lift), kDiscColour, 2.5);
  specimen_rim_ = RimActor(Rim(specimen_radius, lift), kSpecimenColour, 1.5);
  renderer->AddActor(disc_rim_);
  renderer->AddActor(specimen_rim_);

  shadow_ = ActorOf(Ptr<vtkPolyData>::New());
  // The triangulator's output carries no colours of its own to map.
  shadow_->GetMapper()->ScalarVisibilityOff();
  shadow_->GetProperty()->SetColor(kShadowColour[0], kShadowColour[1], kShadowColour[2]);
  shadow_->GetProperty()->LightingOff();
  renderer->AddActor(shadow_);
}

Eigen::Vector3d DrapeShadowActors::OnPlane(const Eigen::Vector2d& p, double depth) const {
  return plane_.origin + p.x() * plane_.u + p.y() * plane_.v + depth * test_.down.normalized();
}

DrapeMeasurement DrapeShadowActors::Place(const Mesh& mesh, const ShellState& state) {
  const DrapeMeasurement m = MeasureDrape(state.positions, mesh.quads, test_);
  // The rings as closed lines; the triangulator fills them, holes as holes.
  auto points = Ptr<vtkPoints>::New();
  auto lines = Ptr<vtkCellArray>::New();
  for (const auto& ring : m.shadow.rings) {
    std::vector<Eigen::Vector3d> placed;
    for (const auto& p : ring) placed.push_back(OnPlane(p, shadow_depth_));
    AddRing(points, lines, placed);
  }
  auto outline = Ptr<vtkPolyData>::New();
  outline->SetPoints(points);
  outline->SetLines(lines);
  auto fill = Ptr<vtkContourTriangulator>::New();
  fill->SetInputData(outline);
  fill->Update();
  auto filled = Ptr<vtkPolyData>::New();
  filled->DeepCopy(fill->GetOutput());
  vtkPolyDataMapper::SafeDownCast(shadow_->GetMapper())->SetInputData(filled);
  return m;
}

}  // namespace drape
