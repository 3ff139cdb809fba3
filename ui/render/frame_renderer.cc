#include "ui/render/frame_renderer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkConeSource.h>
#include <vtkDoubleArray.h>
#include <vtkGlyph3D.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkPolyLine.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "ui/render/colour_map.h"
#include "ui/render/drape_shadow_actors.h"
#include "ui/render/field_units.h"
#include "ui/render/ghost_surface.h"
#include "ui/render/scene_actors.h"
#include "ui/render/window_png.h"

namespace drape {
namespace {

template <typename T>
using Ptr = vtkSmartPointer<T>;

// Colours [0, 1]: the fabric's face (director side) and back, held points.
constexpr double kFront[3] = {0.93, 0.62, 0.33};
constexpr double kBack[3] = {0.47, 0.36, 0.62};
constexpr double kBackground[3] = {0.96, 0.97, 0.98};
constexpr double kFabricOverShadowOpacity = 0.3;
constexpr double kObstacle[3] = {0.62, 0.66, 0.70};
constexpr double kSupport[3] = {0.25, 0.25, 0.28};
constexpr double kGripper[3] = {0.85, 0.15, 0.15};
constexpr double kPath[3] = {0.10, 0.45, 0.25};
constexpr double kGrain[3] = {0.10, 0.20, 0.60};  // the warp: dark blue

// Points as small spheres, `radius` [m].
struct Glyphs {
  Ptr<vtkPoints> points = Ptr<vtkPoints>::New();
  Ptr<vtkPolyData> data = Ptr<vtkPolyData>::New();
  Ptr<vtkActor> actor;

  Glyphs(double radius, const double colour[3]) {
    data->SetPoints(points);
    auto sphere = Ptr<vtkSphereSource>::New();
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(12);
    sphere->SetPhiResolution(8);
    auto glyph = Ptr<vtkGlyph3D>::New();
    glyph->SetInputData(data);
    glyph->SetSourceConnection(sphere->GetOutputPort());
    glyph->ScalingOff();
    auto mapper = Ptr<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(glyph->GetOutputPort());
    mapper->ScalarVisibilityOff();
    actor = Ptr<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  }
  void Place(const std::vector<int>& nodes, const ShellState& state) {
    points->SetNumberOfPoints(static_cast<vtkIdType>(nodes.size()));
    for (size_t i = 0; i < nodes.size(); ++i)
      points->SetPoint(static_cast<vtkIdType>(i),
                       state.positions(nodes[i], 0),
                       state.positions(nodes[i], 1),
                       state.positions(nodes[i], 2));
    points->Modified();
    data->Modified();
  }
};

Eigen::Vector3d ViewDirection(const std::string& view, Eigen::Vector3d* up) {
  *up = Eigen::Vector3d::UnitZ();
  if (view == "front") return {0, -1, 0};
  if (view == "side") return {1, 0, 0};
  if (view == "top") {
    *up = Eigen::Vector3d::UnitY();
    return {0, 0, 1};
  }
  if (view == "iso") return Eigen::Vector3d(1, -1, 0.8).normalized();
  throw std::invalid_argument("unknown camera view '" + view +
                              "' (expected iso, front, top or side)");
}

}  // namespace

struct FrameRenderer::Impl {
  const Scene& scene;
  const ShellModel& model;
  RenderOptions options;
  Eigen::AlignedBox3d bounds;
  std::optional<std::array<double, 2>> field_range;

  Ptr<vtkRenderWindow> window;
  Ptr<vtkRenderer> renderer = Ptr<vtkRenderer>::New();
  std::vector<Ptr<vtkPolyDataMapper>> fabric_mappers;  // one, or two with thickness
  std::vector<Ptr<vtkActor>> fabric_actors;
  Ptr<vtkLookupTable> colours = Ptr<vtkLookupTable>::New();
  Ptr<vtkScalarBarActor> bar = Ptr<vtkScalarBarActor>::New();
  std::vector<Ptr<vtkActor>> obstacle_actors;
  std::unique_ptr<Glyphs> supports, grippers;
  std::vector<int> support_nodes;
  std::vector<Ptr<vtkCaptionActor2D>> probe_labels;
  // The grain line: points along it located on the mesh, drawn a little
  // off both faces so that the surface does not hide it.
  std::vector<ProbePoint> grain_points;
  Ptr<vtkPoints> grain_line = Ptr<vtkPoints>::New();
  double grain_offset = 0;
  Ptr<vtkTextActor> overlay = Ptr<vtkTextActor>::New();
  Ptr<vtkActor> ghost = MakeGhostActor();     // hidden until SetGhost
  std::unique_ptr<DrapeShadowActors> shadow;  // the drapemeter's view only
  std::optional<DrapeMeasurement> drape;      // of the state last shown, in that view

  Impl(const Scene& s,
       const ShellModel& m,
       const RenderOptions& o,
       const Eigen::AlignedBox3d& b,
       std::optional<std::array<double, 2>> range,
       vtkRenderWindow* external)
      : scene(s), model(m), options(o), bounds(b), field_range(range) {
    if (external) {
      window = external;
    } else {
      window = Ptr<vtkRenderWindow>::New();
      window->SetOffScreenRendering(1);
      window->SetSize(options.width, options.height);
      // No anti-aliasing: in Xvfb's software GL 4× multisampling made a
      // 1280 × 720 frame of a 20 × 20 sheet 3× slower (80 against 25 ms)
      // and FXAA added 45 ms.
      window->SetMultiSamples(0);
    }
    window->AddRenderer(renderer);
    renderer->SetBackground(kBackground[0], kBackground[1], kBackground[2]);
    // Opaque: VTK clears alpha to 0, and a grab of the viewport (a
    // screenshot) would then be transparent where the screen shows the
    // background.
    renderer->SetBackgroundAlpha(1.0);
    renderer->SetTwoSidedLighting(true);
    const double size = bounds.diagonal().norm();
    AddFabric();
    AddObstacles();
    AddHeldPoints(0.006 * size);
    if (options.paths) AddPaths(0.012 * size);
    if (options.grain) AddGrainLine(0.002 * size);
    AddProbes();
    // The drapemeter's shadow lies on its own plane under the hanging part:
    // a grid there would cross it.
    if (options.floor && !HasPlane() && !options.drape_shadow) AddFloor();
    AddOverlay();
    if (options.drape_shadow)
      shadow = std::make_unique<DrapeShadowActors>(renderer, *options.drape_shadow, bounds);
    renderer->AddActor(ghost);
    PlaceCamera();
  }

  // A window that outlives us (the viewport's) must not keep drawing our
  // actors: a new FrameRenderer takes their place.
  ~Impl() { window->RemoveRenderer(renderer); }

  bool HasPlane() const {
    for (const auto& o : scene.obstacles)
      if (std::holds_alternative<PlaneShape>(o.shape)) return true;
    return false;
  }

  void AddFabric() {
    FillColourMap(options.colour_map, colours);
    const int layers = options.thickness ? 2 : 1;
    for (int l = 0; l < layers; ++l) {
      auto mapper = Ptr<vtkPolyDataMapper>::New();
      mapper->SetLookupTable(colours);
      mapper->ScalarVisibilityOff();
      auto actor = Ptr<vtkActor>::New();
      actor->SetMapper(mapper);
      actor->GetProperty()->SetColor(kFront[0], kFront[1], kFront[2]);
      actor->GetProperty()->SetInterpolationToGouraud();
      actor->GetProperty()->SetSpecular(0.1);
      if (options.edges) {
        actor->GetProperty()->EdgeVisibilityOn();
        actor->GetProperty()->SetEdgeColor(0.2, 0.2, 0.2);
      }
      // The shadow under the part shows through it, as the lamp's through
      // the specimen.
      if (options.drape_shadow && options.camera.view == "top")
        actor->GetProperty()->SetOpacity(kFabricOverShadowOpacity);
      auto back = Ptr<vtkProperty>::New();
      back->DeepCopy(actor->GetProperty());
      back->SetColor(kBack[0], kBack[1], kBack[2]);
      actor->SetBackfaceProperty(back);
      renderer->AddActor(actor);
      fabric_mappers.push_back(mapper);
      fabric_actors.push_back(actor);
    }
    if (options.field) {
      bar->SetLookupTable(colours);
      bar->SetTitle(FieldTitle(*options.field, options.units).c_str());
      bar->SetNumberOfLabels(5);
      bar->SetLabelFormat("%-#.3g");
      bar->SetMaximumWidthInPixels(110);
      bar->SetPosition(0.83, 0.1);
      bar->SetPosition2(0.12, 0.8);
      bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
      bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
      bar->GetTitleTextProperty()->SetFontSize(14);
      bar->GetLabelTextProperty()->SetFontSize(12);
      bar->UnconstrainedFontSizeOn();
      renderer->AddViewProp(bar);
    }
  }

  // SI per unit of the field's values as shown (options.units).
  double FieldScale() const {
    return UnitFor(FieldMeasure(*options.field), options.units).si_factor;
  }

  static FieldInfo FieldInfoOf(FieldKind kind) {
    for (const auto& f : Fields())
      if (f.kind == kind) return f;
    throw std::logic_error("field without a name");
  }

  void AddObstacles() {
    for (const auto& o : scene.obstacles) {
      auto actor = ActorOf(ObstacleSurface(o, bounds));
      actor->GetProperty()->SetColor(kObstacle[0], kObstacle[1], kObstacle[2]);
      if (std::holds_alternative<PlaneShape>(o.shape)) {
        // A table: flat, light, with a grid, so the part stands out on it.
        actor->GetProperty()->LightingOff();
        actor->GetProperty()->EdgeVisibilityOn();
        actor->GetProperty()->SetEdgeColor(0.78, 0.80, 0.83);
        actor->GetProperty()->SetColor(0.90, 0.91, 0.93);
      }
      renderer->AddActor(actor);
      obstacle_actors.push_back(actor);
    }
  }

  void AddHeldPoints(double radius) {
    supports = std::make_unique<Glyphs>(radius, kSupport);
    grippers = std::make_unique<Glyphs>(1.6 * radius, kGripper);
    for (const auto& s : model.supports)
      support_nodes.insert(support_nodes.end(), s.nodes.begin(), s.nodes.end());
    // In the drapemeter's view the disc's rim stands for the nodes it clamps.
    if (!options.drape_shadow) renderer->AddActor(supports->actor);
    renderer->AddActor(grippers->actor);
  }

  // The nodes of the grippers still holding at the end of `stage`.
  std::vector<int> HeldGripperNodes(int stage) const {
    std::vector<int> nodes;
    for (const auto& g : model.grippers) {
      bool released = false;
      for (int k = 0; k <= stage && k < static_cast<int>(scene.stages.size()); ++k)
        for (const auto& name : scene.stages[k].release) released = released || name == g.name;
      if (!released) nodes.insert(nodes.end(), g.nodes.begin(), g.nodes.end());
    }
    return nodes;
  }

  void AddPaths(double arrow) {
    for (const auto& line : GripperPaths(scene, model)) {
      if (line.size() < 2) continue;
      auto points = Ptr<vtkPoints>::New();
      auto polyline = Ptr<vtkPolyLine>::New();
      polyline->GetPointIds()->SetNumberOfIds(static_cast<vtkIdType>(line.size()));
      for (size_t i = 0; i < line.size(); ++i) {
        points->InsertNextPoint(line[i].data());
        polyline->GetPointIds()->SetId(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
      }
      auto cells = Ptr<vtkCellArray>::New();
      cells->InsertNextCell(polyline);
      auto data = Ptr<vtkPolyData>::New();
      data->SetPoints(points);
      data->SetLines(cells);
      auto actor = ActorOf(data);
      actor->GetProperty()->SetColor(kPath[0], kPath[1], kPath[2]);
      actor->GetProperty()->SetLineWidth(2.5);
      renderer->AddActor(actor);
      // An arrow head at the end, along the last segment: the direction of travel.
      const Eigen::Vector3d end = line.back();
      const Eigen::Vector3d dir = (line.back() - line[line.size() - 2]).normalized();
      auto cone = Ptr<vtkConeSource>::New();
      cone->SetHeight(arrow);
      cone->SetRadius(0.4 * arrow);
      cone->SetResolution(16);
      const Eigen::Vector3d centre = end - 0.5 * arrow * dir;
      cone->SetCenter(centre.data());
      cone->SetDirection(dir.data());
      cone->Update();
      auto head = ActorOf(cone->GetOutput());
      head->GetProperty()->SetColor(kPath[0], kPath[1], kPath[2]);
      renderer->AddActor(head);
    }
  }

  void AddGrainLine(double offset) {
    const auto* pattern = std::get_if<PatternOutline>(&scene.fabric.outline);
    if (!pattern || !pattern->shape.grain) return;
    const auto& [from, to] = *pattern->shape.grain;
    constexpr int kPoints = 24;
    for (int i = 0; i < kPoints; ++i) {
      const double t = static_cast<double>(i) / (kPoints - 1);
      grain_points.push_back(LocateProbe(
          model.mesh,
          Probe{"grain", {from[0] + t * (to[0] - from[0]), from[1] + t * (to[1] - from[1])}}));
    }
    grain_offset = std::max(offset, model.thickness);
    auto cells = Ptr<vtkCellArray>::New();
    for (int side = 0; side < 2; ++side) {
      auto line = Ptr<vtkPolyLine>::New();
      line->GetPointIds()->SetNumberOfIds(kPoints);
      for (int i = 0; i < kPoints; ++i) {
        grain_line->InsertNextPoint(0, 0, 0);
        line->GetPointIds()->SetId(i, side * kPoints + i);
      }
      cells->InsertNextCell(line);
    }
    auto data = Ptr<vtkPolyData>::New();
    data->SetPoints(grain_line);
    data->SetLines(cells);
    auto actor = ActorOf(data);
    actor->GetProperty()->SetColor(kGrain[0], kGrain[1], kGrain[2]);
    actor->GetProperty()->SetLineWidth(3.0);
    renderer->AddActor(actor);
  }

  // The grain line on `state`'s surface, off each face along the director
  // of the element's first node.
  void PlaceGrainLine(const ShellState& state) {
    const int n = static_cast<int>(grain_points.size());
    for (int i = 0; i < n; ++i) {
      const ProbePoint& p = grain_points[i];
      const Eigen::Vector3d at = ProbePosition(model, p, state);
      const Eigen::Vector3d normal = state.Director(model.mesh.quads(p.element, 0));
      const Eigen::Vector3d up = at + grain_offset * normal, down = at - grain_offset * normal;
      grain_line->SetPoint(i, up.data());
      grain_line->SetPoint(n + i, down.data());
    }
    grain_line->Modified();
  }

  void AddProbes() {
    for (const auto& probe : model.probes) {
      auto label = Ptr<vtkCaptionActor2D>::New();
      label->SetCaption(probe.name.c_str());
      label->BorderOff();
      label->LeaderOn();
      label->ThreeDimensionalLeaderOff();
      label->SetWidth(0.06);
      label->SetHeight(0.04);
      label->GetCaptionTextProperty()->SetColor(0.1, 0.1, 0.1);
      label->GetCaptionTextProperty()->BoldOff();
      label->GetCaptionTextProperty()->ItalicOff();
      label->GetCaptionTextProperty()->ShadowOff();
      label->GetProperty()->SetColor(0.1, 0.1, 0.1);
      renderer->AddViewProp(label);
      probe_labels.push_back(label);
    }
  }

  // Below the part and every finite obstacle (a dress form reaches lower
  // than the scarf on it).
  void AddFloor() {
    const Eigen::Vector3d lo = bounds.min(), hi = bounds.max();
    const double margin = 0.15 * bounds.diagonal().norm();
    double bottom = lo.z();
    for (size_t o = 0; o < obstacle_actors.size(); ++o) {
      const auto& shape = scene.obstacles[o].shape;
      const auto* cylinder = std::get_if<CylinderShape>(&shape);
      if (std::holds_alternative<PlaneShape>(shape) || (cylinder && !cylinder->length)) continue;
      bottom = std::min(bottom, obstacle_actors[o]->GetBounds()[4]);
    }
    const double z = bottom - 0.02 * bounds.diagonal().norm();
    Obstacle floor{"floor", PlaneShape{{0, 0, z}, {0, 0, 1}}};
    Eigen::AlignedBox3d around(Eigen::Vector3d(lo.x() - margin, lo.y() - margin, z),
                               Eigen::Vector3d(hi.x() + margin, hi.y() + margin, z));
    auto actor = ActorOf(ObstacleSurface(floor, around));
    actor->GetProperty()->SetRepresentationToWireframe();
    actor->GetProperty()->SetColor(0.80, 0.82, 0.85);
    actor->GetProperty()->LightingOff();
    renderer->AddActor(actor);
  }

  void AddOverlay() {
    overlay->GetTextProperty()->SetFontSize(16);
    overlay->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
    overlay->SetDisplayPosition(12, 12);
    overlay->SetVisibility(options.overlay);
    renderer->AddViewProp(overlay);
  }

  void PlaceCamera() {
    vtkCamera* camera = renderer->GetActiveCamera();
    const Eigen::Vector3d centre = bounds.center();
    if (options.camera.position || options.camera.focal_point || options.camera.view_up) {
      const Eigen::Vector3d focal = options.camera.focal_point.value_or(centre);
      const Eigen::Vector3d position = options.camera.position.value_or(
          focal + bounds.diagonal().norm() * Eigen::Vector3d(1, -1, 1));
      const Eigen::Vector3d up = options.camera.view_up.value_or(Eigen::Vector3d::UnitZ());
      camera->SetFocalPoint(focal.data());
      camera->SetPosition(position.data());
      camera->SetViewUp(up.data());
      renderer->ResetCameraClippingRange();
      return;
    }
    Eigen::Vector3d up;
    const Eigen::Vector3d direction = ViewDirection(options.camera.view, &up);
    const Eigen::Vector3d position = centre + direction;
    camera->SetFocalPoint(centre.data());
    camera->SetPosition(position.data());
    camera->SetViewUp(up.data());
    // The drapemeter's shadow is a parallel projection: seen so, the
    // fabric's rim lies on the shadow's, at any height.
    camera->SetParallelProjection(options.drape_shadow && options.camera.view == "top");
    double b[6] = {bounds.min().x(),
                   bounds.max().x(),
                   bounds.min().y(),
                   bounds.max().y(),
                   bounds.min().z(),
                   bounds.max().z()};
    renderer->ResetCamera(b);  // keeps the direction, fits the run's box
  }

  void ShowFabric(const Frame& frame) {
    const ShellState& state = *frame.state;
    const Eigen::Matrix<double, Eigen::Dynamic, 3> directors = state.Directors();
    Eigen::VectorXd values;
    bool per_node = true;
    if (options.field) {
      const FieldInfo info = FieldInfoOf(*options.field);
      per_node = info.per_node;
      if (*options.field == FieldKind::kContactPressure) {
        if (static_cast<int>(frame.contact_pressure.size()) != model.NodeCount())
          throw std::invalid_argument(
              "the contact pressure is stored for the last step of a run with obstacles only");
        values =
            Eigen::Map<const Eigen::VectorXd>(frame.contact_pressure.data(), model.NodeCount());
      } else if (*options.field == FieldKind::kFrictionState) {
        if (static_cast<int>(frame.friction_state.size()) != model.NodeCount())
          throw std::invalid_argument(
              "which nodes stick and slide is stored for the last step of a run with friction "
              "only");
        values = Eigen::Map<const Eigen::VectorXd>(frame.friction_state.data(), model.NodeCount());
      } else {
        values = EvaluateField(*options.field, model, state);
      }
      values /= FieldScale();
    }
    for (size_t l = 0; l < fabric_mappers.size(); ++l) {
      const double offset =
          fabric_mappers.size() == 1 ? 0.0 : (l == 0 ? 0.5 : -0.5) * model.thickness;
      auto surface = FabricSurface(model.mesh, state.positions, &directors, offset);
      if (options.field) {
        auto scalars = Ptr<vtkDoubleArray>::New();
        scalars->SetName(FieldInfoOf(*options.field).name);
        scalars->SetNumberOfValues(values.size());
        for (Eigen::Index i = 0; i < values.size(); ++i) scalars->SetValue(i, values(i));
        if (per_node)
          surface->GetPointData()->SetScalars(scalars);
        else
          surface->GetCellData()->SetScalars(scalars);
      }
      auto normals = Ptr<vtkPolyDataNormals>::New();
      normals->SetInputData(surface);
      normals->SplittingOff();
      normals->ConsistencyOff();
      normals->AutoOrientNormalsOff();
      normals->Update();
      vtkPolyDataMapper* mapper = fabric_mappers[l];
      mapper->SetInputData(normals->GetOutput());
      if (options.field) {
        std::array<double, 2> range =
            field_range ? std::array<double, 2>{(*field_range)[0] / FieldScale(),
                                                (*field_range)[1] / FieldScale()}
                        : std::array<double, 2>{values.size() ? values.minCoeff() : 0.0,
                                                values.size() ? values.maxCoeff() : 1.0};
        // Friction's three states keep their colours from frame to frame.
        if (*options.field == FieldKind::kFrictionState) range = {0.0, 2.0};
        if (!(range[1] > range[0]))
          range[1] = range[0] + std::max(1e-12, std::abs(range[0]) * 1e-6);
        mapper->ScalarVisibilityOn();
        mapper->SetScalarModeToDefault();
        mapper->SetScalarRange(range[0], range[1]);
        colours->SetRange(range[0], range[1]);
      }
    }
  }

  void Update(const Frame& frame) {
    if (!frame.state) throw std::invalid_argument("a frame without a state");
    const ShellState& state = *frame.state;
    ShowFabric(frame);
    for (size_t o = 0; o < obstacle_actors.size(); ++o) {
      auto matrix = Ptr<vtkMatrix4x4>::New();
      if (o < state.obstacles.size()) {
        const ObstaclePlacement& p = state.obstacles[o];
        for (int r = 0; r < 3; ++r) {
          for (int c = 0; c < 3; ++c) matrix->SetElement(r, c, p.rotation(r, c));
          matrix->SetElement(r, 3, p.translation(r));
        }
      }
      obstacle_actors[o]->SetUserMatrix(matrix);
    }
    supports->Place(support_nodes, state);
    grippers->Place(HeldGripperNodes(frame.stage), state);
    for (size_t p = 0; p < probe_labels.size(); ++p) {
      Eigen::Vector3d at = ProbePosition(model, model.probes[p], state);
      probe_labels[p]->SetAttachmentPoint(at.data());
    }
    if (!grain_points.empty()) PlaceGrainLine(state);
    char text[512];
    if (frame.step == 0)
      std::snprintf(text, sizeof text, "%s\nreference state", scene.name.c_str());
    else
      std::snprintf(text,
                    sizeof text,
                    "%s\nstage %s   step %d   lambda = %.4f",
                    scene.name.c_str(),
                    frame.stage_name.c_str(),
                    frame.step,
                    frame.lambda);
    std::string shown = text;
    if (shadow) {
      drape = shadow->Place(model.mesh, state);
      shown += "\n" + DrapeSummary(*drape);
    }
    overlay->SetInput(shown.c_str());
    renderer->ResetCameraClippingRange();
  }
};

FrameRenderer::FrameRenderer(const Scene& scene,
                             const ShellModel& model,
                             const RenderOptions& options,
                             const Eigen::AlignedBox3d& bounds,
                             std::optional<std::array<double, 2>> field_range,
                             vtkRenderWindow* window)
    : impl_(std::make_unique<Impl>(scene, model, options, bounds, field_range, window)) {}

FrameRenderer::~FrameRenderer() = default;

void FrameRenderer::Show(const Frame& frame) {
  impl_->Update(frame);
  impl_->window->Render();
}

void FrameRenderer::Update(const Frame& frame) {
  impl_->Update(frame);
}

std::vector<unsigned char> FrameRenderer::CaptureRgb() {
  auto grab = Ptr<vtkWindowToImageFilter>::New();
  grab->SetInput(impl_->window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* image = grab->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  auto* data = static_cast<unsigned char*>(image->GetScalarPointer());
  const size_t row = static_cast<size_t>(dims[0]) * 3;
  std::vector<unsigned char> rgb(row * dims[1]);
  for (int y = 0; y < dims[1]; ++y)  // VTK's first row is the bottom one
    std::copy(data + row * (dims[1] - 1 - y), data + row * (dims[1] - y), rgb.data() + row * y);
  return rgb;
}

void FrameRenderer::WritePng(const std::filesystem::path& file) {
  WriteWindowPng(impl_->window, file);
}

int FrameRenderer::width() const {
  return impl_->options.width;
}
int FrameRenderer::height() const {
  return impl_->options.height;
}
void FrameRenderer::FitCamera() {
  impl_->PlaceCamera();
}

void FrameRenderer::SetGhost(const Mesh& mesh, const ShellState& state) {
  PlaceGhost(impl_->ghost, mesh, state);
  impl_->renderer->ResetCameraClippingRange();  // the ghost may reach beyond the shown state
}
void FrameRenderer::ClearGhost() {
  impl_->ghost->VisibilityOff();
}
bool FrameRenderer::HasGhost() const {
  return impl_->ghost->GetVisibility();
}

bool FrameRenderer::HasGrainLine() const {
  return !impl_->grain_points.empty();
}

const std::optional<DrapeMeasurement>& FrameRenderer::drape() const {
  return impl_->drape;
}

vtkRenderer* FrameRenderer::renderer() {
  return impl_->renderer;
}

}  // namespace drape
