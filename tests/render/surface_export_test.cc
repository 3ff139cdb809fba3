// Exported surfaces read back by VTK's own readers: the same points and
// fields; STL solids closed; the PVD collection in step order.
#include "ui/render/surface_export.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFeatureEdges.h>
#include <vtkOBJReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/fe/element_fields.h"
#include "core/mechanics/director.h"
#include "support/strip_scene.h"

namespace drape {
namespace {

namespace fs = std::filesystem;

struct Exported {
  ShellModel model;
  ShellState bent;
  fs::path dir;
};

// A strip and a state bent into a quarter circle of radius 0.1 m.
Exported BentStrip(const std::string& name) {
  test::StripSpec spec;
  Scene scene = test::CantileverStrip(spec);
  Exported e{BuildShellModel(scene), {}, fs::temp_directory_path() / ("drape-export-" + name)};
  fs::remove_all(e.dir);
  e.bent = e.model.reference;
  const double r = 2 * spec.length / M_PI;
  for (int i = 0; i < e.model.NodeCount(); ++i) {
    const double a = e.model.reference.positions(i, 0) / r;
    e.bent.positions(i, 0) = r * std::sin(a);
    e.bent.positions(i, 2) = r * (1 - std::cos(a));
    e.bent.rotations[i] = RotationFromDirector({-std::sin(a), 0, std::cos(a)});
  }
  return e;
}

TEST(SurfaceExport, VtuReopensWithTheSamePointsAndFields) {
  Exported e = BentStrip("vtu");
  const auto files =
      ExportSurfaces(e.model,
                     {{&e.model.reference, 0, -1, 0.0}, {&e.bent, 1, 0, 0.5}, {&e.bent, 2, 0, 1.0}},
                     SurfaceFormat::kVtu,
                     e.dir);
  ASSERT_EQ(files.size(), 4u);  // three steps and the collection
  auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
  reader->SetFileName((e.dir / "step_0001.vtu").string().c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  ASSERT_EQ(grid->GetNumberOfPoints(), e.model.NodeCount());
  ASSERT_EQ(grid->GetNumberOfCells(), e.model.mesh.ElementCount());
  for (int i = 0; i < e.model.NodeCount(); ++i) {
    double p[3];
    grid->GetPoint(i, p);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(p[c], e.bent.positions(i, c));
  }
  vtkDataArray* k = grid->GetCellData()->GetArray("curvature");
  ASSERT_NE(k, nullptr);
  const Eigen::VectorXd expected = EvaluateField(FieldKind::kCurvature, e.model, e.bent);
  for (int c = 0; c < e.model.mesh.ElementCount(); ++c) EXPECT_EQ(k->GetTuple1(c), expected(c));
  ASSERT_NE(grid->GetPointData()->GetArray("displacement"), nullptr);
  // The collection: one entry per step, time = stage + λ increasing.
  std::ifstream pvd(e.dir / "run.pvd");
  std::stringstream text;
  text << pvd.rdbuf();
  const std::string s = text.str();
  EXPECT_NE(s.find("timestep=\"0\" part=\"0\" file=\"step_0000.vtu\""), std::string::npos) << s;
  EXPECT_NE(s.find("timestep=\"0.5\" part=\"0\" file=\"step_0001.vtu\""), std::string::npos) << s;
  EXPECT_NE(s.find("timestep=\"1\" part=\"0\" file=\"step_0002.vtu\""), std::string::npos) << s;
  fs::remove_all(e.dir);
}

// Edges used by one face or by more than two: zero for a closed surface.
vtkIdType OpenEdges(vtkPolyData* surface) {
  auto edges = vtkSmartPointer<vtkFeatureEdges>::New();
  edges->SetInputData(surface);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfCells();
}

TEST(SurfaceExport, StlSolidIsClosedAndTheSheetIsNot) {
  Exported e = BentStrip("stl");
  ExportSurfaces(e.model, {{&e.bent, 1, 0, 1.0}}, SurfaceFormat::kStl, e.dir / "solid", true);
  ExportSurfaces(e.model, {{&e.bent, 1, 0, 1.0}}, SurfaceFormat::kStl, e.dir / "sheet", false);
  auto read = [](const fs::path& file) {
    auto reader = vtkSmartPointer<vtkSTLReader>::New();
    reader->SetFileName(file.string().c_str());
    reader->Update();
    return vtkSmartPointer<vtkPolyData>(reader->GetOutput());
  };
  const auto solid = read(e.dir / "solid" / "step_0001.stl");
  const auto sheet = read(e.dir / "sheet" / "step_0001.stl");
  // Two faces of 2 triangles per element, and 2 per boundary edge segment.
  const int elements = e.model.mesh.ElementCount();
  const int boundary = 2 * (40 + 1);
  EXPECT_EQ(solid->GetNumberOfCells(), 4 * elements + 2 * boundary);
  EXPECT_EQ(OpenEdges(solid), 0);
  EXPECT_EQ(sheet->GetNumberOfCells(), 2 * elements);
  EXPECT_EQ(OpenEdges(sheet), boundary);
  fs::remove_all(e.dir);
}

TEST(SurfaceExport, ObjAndCsvCarryEveryNode) {
  Exported e = BentStrip("obj");
  ExportSurfaces(e.model, {{&e.bent, 3, 0, 1.0}}, SurfaceFormat::kObj, e.dir);
  auto reader = vtkSmartPointer<vtkOBJReader>::New();
  reader->SetFileName((e.dir / "step_0003.obj").string().c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), e.model.NodeCount());
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), e.model.mesh.ElementCount());
  ExportSurfaces(e.model, {{&e.bent, 3, 0, 1.0}}, SurfaceFormat::kCsv, e.dir);
  std::ifstream csv(e.dir / "step_0003.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("node,x_m,y_m,z_m,", 0), 0u);
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, e.model.NodeCount());
  EXPECT_TRUE(fs::exists(e.dir / "step_0003_elements.csv"));
  fs::remove_all(e.dir);
}

TEST(SurfaceExport, UnwritablePlaceIsOneClearError) {
  Exported e = BentStrip("bad");
  try {
    ExportSurfaces(e.model, {{&e.bent, 1, 0, 1.0}}, SurfaceFormat::kVtu, "/proc/no/such/dir");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& err) {
    EXPECT_NE(std::string(err.what()).find("/proc/no/such/dir"), std::string::npos) << err.what();
  }
}

}  // namespace
}  // namespace drape
