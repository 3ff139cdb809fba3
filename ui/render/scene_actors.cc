#include "ui/render/scene_actors.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkOBJReader.h>
#include <vtkPlaneSource.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkSTLReader.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "core/fe/path_handles.h"
#include "core/model/mesh_placement.h"
#include "core/model/overloaded.h"
#include "core/model/vec3_eigen.h"

namespace drape {
namespace {

// A transform taking VTK's canonical sources (axis y, centred at 0) to `axis`
// through `center`.
vtkSmartPointer<vtkTransform> AlongAxis(const Eigen::Vector3d& center,
                                        const Eigen::Vector3d& axis) {
  auto t = vtkSmartPointer<vtkTransform>::New();
  t->Translate(center.data());
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d a = axis.normalized();
  const Eigen::Vector3d turn = y.cross(a);
  const double angle = std::atan2(turn.norm(), y.dot(a)) * 180.0 / M_PI;
  if (turn.norm() > 1e-12)
    t->RotateWXYZ(angle, turn.x(), turn.y(), turn.z());
  else if (y.dot(a) < 0)
    t->RotateWXYZ(180.0, 1, 0, 0);
  return t;
}

vtkSmartPointer<vtkPolyData> Transformed(vtkPolyDataAlgorithm* source, vtkTransform* transform) {
  auto filter = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  filter->SetInputConnection(source->GetOutputPort());
  filter->SetTransform(transform);
  filter->Update();
  return filter->GetOutput();
}

Eigen::AlignedBox3d Grown(const Eigen::AlignedBox3d& bounds) {
  const double margin = 0.25 * bounds.diagonal().norm() + 1e-3;
  return {bounds.min().array() - margin, bounds.max().array() + margin};
}

}  // namespace

vtkSmartPointer<vtkPolyData> FabricSurface(const Mesh& mesh,
                                           const Eigen::Matrix<double, Eigen::Dynamic, 3>& x,
                                           const Eigen::Matrix<double, Eigen::Dynamic, 3>* t,
                                           double offset) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(x.rows());
  for (int i = 0; i < x.rows(); ++i) {
    Eigen::Vector3d p = x.row(i).transpose();
    if (t && offset != 0) p += offset * t->row(i).transpose();
    points->SetPoint(i, p.data());
  }
  auto quads = vtkSmartPointer<vtkCellArray>::New();
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    const vtkIdType ids[4] = {
        mesh.quads(e, 0), mesh.quads(e, 1), mesh.quads(e, 2), mesh.quads(e, 3)};
    quads->InsertNextCell(4, ids);
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(quads);
  return surface;
}

vtkSmartPointer<vtkPolyData> ObstacleSurface(const Obstacle& obstacle,
                                             const Eigen::AlignedBox3d& bounds) {
  const Eigen::AlignedBox3d around = Grown(bounds);
  return std::visit(
      Overloaded{
          [&](const PlaneShape& s) {
            // A square on the plane, centred under the part, as wide as the scene.
            const Eigen::Vector3d n = ToEigen(s.normal).normalized();
            const Eigen::Vector3d p = ToEigen(s.point);
            const Eigen::Vector3d c = around.center() - (around.center() - p).dot(n) * n;
            Eigen::Vector3d u = n.unitOrthogonal();
            const Eigen::Vector3d v = n.cross(u);
            const double half = 0.5 * around.diagonal().norm();
            auto plane = vtkSmartPointer<vtkPlaneSource>::New();
            Eigen::Vector3d o = c - half * u - half * v, p1 = c + half * u - half * v,
                            p2 = c - half * u + half * v;
            plane->SetOrigin(o.data());
            plane->SetPoint1(p1.data());
            plane->SetPoint2(p2.data());
            plane->SetResolution(20, 20);
            plane->Update();
            return vtkSmartPointer<vtkPolyData>(plane->GetOutput());
          },
          [&](const BoxShape& s) {
            auto box = vtkSmartPointer<vtkCubeSource>::New();
            box->SetBounds(s.min[0], s.max[0], s.min[1], s.max[1], s.min[2], s.max[2]);
            box->Update();
            return vtkSmartPointer<vtkPolyData>(box->GetOutput());
          },
          [&](const CylinderShape& s) {
            const double length = s.length ? *s.length : around.diagonal().norm() * 1.5;
            auto cylinder = vtkSmartPointer<vtkCylinderSource>::New();
            cylinder->SetRadius(s.radius);
            cylinder->SetHeight(length);
            cylinder->SetResolution(48);
            cylinder->SetCapping(s.length.has_value());
            // An infinite rod: centred where the part is, along its axis.
            const Eigen::Vector3d a = ToEigen(s.axis).normalized();
            Eigen::Vector3d c = ToEigen(s.point);
            if (!s.length) c += (around.center() - c).dot(a) * a;
            return Transformed(cylinder, AlongAxis(c, a));
          },
          [&](const SphereShape& s) {
            auto sphere = vtkSmartPointer<vtkSphereSource>::New();
            sphere->SetCenter(s.center.data());
            sphere->SetRadius(s.radius);
            sphere->SetThetaResolution(48);
            sphere->SetPhiResolution(24);
            sphere->Update();
            return vtkSmartPointer<vtkPolyData>(sphere->GetOutput());
          },
          [&](const MeshShape& s) {
            const std::filesystem::path file = s.resolved_path.empty() ? s.file : s.resolved_path;
            vtkSmartPointer<vtkPolyDataAlgorithm> reader;
            if (file.extension() == ".obj" || file.extension() == ".OBJ") {
              auto obj = vtkSmartPointer<vtkOBJReader>::New();
              obj->SetFileName(file.string().c_str());
              reader = obj;
            } else {
              auto stl = vtkSmartPointer<vtkSTLReader>::New();
              stl->SetFileName(file.string().c_str());
              reader = stl;
            }
            auto placement = vtkSmartPointer<vtkTransform>::New();
            const Eigen::Matrix<double, 4, 4, Eigen::RowMajor> rows = MeshPlacement(s).matrix();
            placement->SetMatrix(rows.data());  // VTK reads the elements by rows
            const vtkSmartPointer<vtkPolyData> out = Transformed(reader, placement);
            if (!out || out->GetNumberOfCells() == 0)
              throw std::runtime_error("cannot draw obstacle '" + obstacle.name + "' from " +
                                       file.string());
            return out;
          },
      },
      obstacle.shape);
}

std::vector<std::vector<Eigen::Vector3d>> GripperPaths(const Scene& scene,
                                                       const ShellModel& model) {
  std::vector<std::vector<Eigen::Vector3d>> paths;
  for (const CarriedMove& m : GripperMoves(scene, model))
    paths.push_back(SamplePath(scene.stages[m.stage].moves[m.move].path, m.start));
  return paths;
}

vtkSmartPointer<vtkActor> ActorOf(vtkPolyData* data) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

}  // namespace drape
