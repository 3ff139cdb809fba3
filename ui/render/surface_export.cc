#include "ui/render/surface_export.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <utility>

#include "core/fe/element_fields.h"

namespace drape {
namespace fs = std::filesystem;
namespace {

template <typename T>
using Ptr = vtkSmartPointer<T>;

std::string StepName(int step, const char* extension) {
  char name[64];
  std::snprintf(name, sizeof name, "step_%04d.%s", step, extension);
  return name;
}

void Check(bool written, const fs::path& file) {
  std::error_code ec;
  if (!written || !fs::is_regular_file(file, ec))
    throw std::runtime_error("cannot write " + file.string());
}

Ptr<vtkDoubleArray> Array(const char* name, int components, vtkIdType tuples) {
  auto a = Ptr<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

// Points, quads and every field of a state: displacement and director per
// node, the element fields per cell.
Ptr<vtkUnstructuredGrid> Grid(const ShellModel& model, const ShellState& state) {
  const int n = model.NodeCount();
  auto points = Ptr<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  auto displacement = Array("displacement", 3, n);
  auto director = Array("director", 3, n);
  for (int i = 0; i < n; ++i) {
    points->SetPoint(i, state.positions(i, 0), state.positions(i, 1), state.positions(i, 2));
    const Eigen::Vector3d u =
        (state.positions.row(i) - model.reference.positions.row(i)).transpose();
    const Eigen::Vector3d t = state.Director(i);
    displacement->SetTuple(i, u.data());
    director->SetTuple(i, t.data());
  }
  auto grid = Ptr<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->Allocate(model.mesh.ElementCount());
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    const vtkIdType ids[4] = {model.mesh.quads(e, 0),
                              model.mesh.quads(e, 1),
                              model.mesh.quads(e, 2),
                              model.mesh.quads(e, 3)};
    grid->InsertNextCell(VTK_QUAD, 4, ids);
  }
  grid->GetPointData()->AddArray(displacement);
  grid->GetPointData()->AddArray(director);
  for (const FieldInfo& f : Fields()) {
    if (f.per_node) continue;
    const Eigen::VectorXd v = EvaluateField(f.kind, model, state);
    auto a = Array(f.name, 1, v.size());
    for (Eigen::Index e = 0; e < v.size(); ++e) a->SetValue(e, v(e));
    grid->GetCellData()->AddArray(a);
  }
  return grid;
}

// The surface as poly data; `solid`: a closed shell of thickness h (both
// faces along the nodal directors, and the rim along the boundary edges).
Ptr<vtkPolyData> Surface(const ShellModel& model, const ShellState& state, bool solid) {
  const int n = model.NodeCount();
  const double half = solid ? 0.5 * model.thickness : 0.0;
  auto points = Ptr<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (int side = 0; side < (solid ? 2 : 1); ++side)
    for (int i = 0; i < n; ++i) {
      const Eigen::Vector3d p =
          state.positions.row(i).transpose() + (side == 0 ? half : -half) * state.Director(i);
      points->InsertNextPoint(p.data());
    }
  auto polys = Ptr<vtkCellArray>::New();
  std::map<std::pair<int, int>, int> edge_count;
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    vtkIdType top[4], bottom[4];
    for (int k = 0; k < 4; ++k) {
      top[k] = model.mesh.quads(e, k);
      bottom[k] = model.mesh.quads(e, 3 - k) + n;  // reversed: outward below
      const int a = model.mesh.quads(e, k), b = model.mesh.quads(e, (k + 1) % 4);
      ++edge_count[{std::min(a, b), std::max(a, b)}];
    }
    polys->InsertNextCell(4, top);
    if (solid) polys->InsertNextCell(4, bottom);
  }
  if (solid) {
    // The rim: each boundary edge a → b (counter-clockwise seen from the
    // top face) closed by a quad a, a', b', b facing outward.
    for (int e = 0; e < model.mesh.ElementCount(); ++e)
      for (int k = 0; k < 4; ++k) {
        const int a = model.mesh.quads(e, k), b = model.mesh.quads(e, (k + 1) % 4);
        if (edge_count[{std::min(a, b), std::max(a, b)}] != 1) continue;
        const vtkIdType rim[4] = {b, a, a + n, b + n};
        polys->InsertNextCell(4, rim);
      }
  }
  auto surface = Ptr<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(polys);
  return surface;
}

Ptr<vtkPolyData> Triangles(vtkPolyData* surface) {
  auto filter = Ptr<vtkTriangleFilter>::New();
  filter->SetInputData(surface);
  filter->Update();
  return filter->GetOutput();
}

void WriteCsv(const ShellModel& model, const ShellState& state, const fs::path& file) {
  std::ofstream out(file);
  out.precision(17);
  out << "node,x_m,y_m,z_m,ux_m,uy_m,uz_m,displacement_m,tx,ty,tz\n";
  for (int i = 0; i < model.NodeCount(); ++i) {
    const Eigen::RowVector3d x = state.positions.row(i);
    const Eigen::RowVector3d u = x - model.reference.positions.row(i);
    const Eigen::Vector3d t = state.Director(i);
    out << i << ',' << x(0) << ',' << x(1) << ',' << x(2) << ',' << u(0) << ',' << u(1) << ','
        << u(2) << ',' << u.norm() << ',' << t(0) << ',' << t(1) << ',' << t(2) << '\n';
  }
  Check(static_cast<bool>(out.flush()), file);
}

void WriteElementCsv(const ShellModel& model, const ShellState& state, const fs::path& file) {
  std::ofstream out(file);
  out.precision(17);
  std::vector<Eigen::VectorXd> values;
  out << "element,node0,node1,node2,node3";
  for (const FieldInfo& f : Fields())
    if (!f.per_node) {
      out << ',' << f.title;
      values.push_back(EvaluateField(f.kind, model, state));
    }
  out << '\n';
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    out << e;
    for (int k = 0; k < 4; ++k) out << ',' << model.mesh.quads(e, k);
    for (const auto& v : values) out << ',' << v(e);
    out << '\n';
  }
  Check(static_cast<bool>(out.flush()), file);
}

// ParaView's collection: one data set per step, at time = stage index + λ
// (λ restarts at 0 in every stage, so this keeps time increasing).
void WritePvd(const std::vector<ExportedStep>& steps,
              const std::vector<fs::path>& files,
              const fs::path& file) {
  std::ofstream out(file);
  out.precision(17);
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <Collection>\n";
  for (size_t i = 0; i < steps.size(); ++i)
    out << "    <DataSet timestep=\"" << std::max(steps[i].stage, 0) + steps[i].lambda
        << "\" part=\"0\" file=\"" << files[i].filename().string() << "\"/>\n";
  out << "  </Collection>\n</VTKFile>\n";
  Check(static_cast<bool>(out.flush()), file);
}

}  // namespace

std::vector<fs::path> ExportSurfaces(const ShellModel& model,
                                     const std::vector<ExportedStep>& steps,
                                     SurfaceFormat format,
                                     const fs::path& directory,
                                     bool solid,
                                     const std::function<bool(int, int)>& progress) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  if (ec) throw std::runtime_error("cannot create " + directory.string() + ": " + ec.message());
  std::vector<fs::path> written;
  size_t done = 0;
  for (const ExportedStep& s : steps) {
    const ShellState& state = *s.state;
    switch (format) {
      case SurfaceFormat::kVtu: {
        const fs::path file = directory / StepName(s.step, "vtu");
        auto writer = Ptr<vtkXMLUnstructuredGridWriter>::New();
        writer->SetFileName(file.string().c_str());
        writer->SetInputData(Grid(model, state));
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        Check(writer->Write() == 1, file);
        written.push_back(file);
        break;
      }
      case SurfaceFormat::kObj: {
        const fs::path file = directory / StepName(s.step, "obj");
        auto writer = Ptr<vtkOBJWriter>::New();
        writer->SetFileName(file.string().c_str());
        writer->SetInputData(Surface(model, state, solid));
        Check(writer->Write() == 1, file);
        written.push_back(file);
        break;
      }
      case SurfaceFormat::kPly: {
        const fs::path file = directory / StepName(s.step, "ply");
        auto writer = Ptr<vtkPLYWriter>::New();
        writer->SetFileName(file.string().c_str());
        writer->SetInputData(Surface(model, state, solid));
        writer->SetFileTypeToBinary();
        Check(writer->Write() == 1, file);
        written.push_back(file);
        break;
      }
      case SurfaceFormat::kStl: {
        const fs::path file = directory / StepName(s.step, "stl");
        auto writer = Ptr<vtkSTLWriter>::New();
        writer->SetFileName(file.string().c_str());
        writer->SetInputData(Triangles(Surface(model, state, solid)));
        writer->SetFileTypeToBinary();
        Check(writer->Write() == 1, file);
        written.push_back(file);
        break;
      }
      case SurfaceFormat::kCsv: {
        const fs::path nodes = directory / StepName(s.step, "csv");
        WriteCsv(model, state, nodes);
        written.push_back(nodes);
        char name[64];
        std::snprintf(name, sizeof name, "step_%04d_elements.csv", s.step);
        WriteElementCsv(model, state, directory / name);
        written.push_back(directory / name);
        break;
      }
    }
    ++done;
    if (progress && !progress(static_cast<int>(done), static_cast<int>(steps.size()))) break;
  }
  if (format == SurfaceFormat::kVtu) {
    const fs::path pvd = directory / "run.pvd";
    WritePvd({steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(done)}, written, pvd);
    written.push_back(pvd);
  }
  return written;
}

}  // namespace drape
