// The one picture of a state: the fabric surface (two-sided, an optional
// colour field with its bar and units, optional mesh edges and thickness),
// obstacles where the state put them, supports and grippers as glyphs, the
// grippers' paths, probes with labels, a floor grid and a text overlay. The
// offscreen commands and the workbench's viewport draw with this class, so a
// CI image shows what a user sees.
//
// A FrameRenderer is made once per run: the camera is fitted to the whole
// run (so it does not jump between frames) and a colour field keeps one
// range; each Show() moves the actors to a new state.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/fe/element_fields.h"
#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"
#include "core/measure/drape_coefficient.h"
#include "core/model/scene.h"
#include "core/model/unit_system.h"

class vtkRenderer;
class vtkRenderWindow;

namespace drape {

// "iso", "front", "top", "side", or an explicit camera.
struct CameraSpec {
  std::string view = "iso";
  std::optional<Eigen::Vector3d> position, focal_point, view_up;
};

// How a colour field's values become colours. Viridis (van der Walt,
// Smith & Firing, matplotlib 2015) is perceptually uniform and reads in
// grey; the rainbow is kept for pictures that must match older ones.
enum class ColourMap { kViridis, kRainbow };
const char* ToString(ColourMap map);
std::optional<ColourMap> ColourMapNamed(std::string_view name);

struct RenderOptions {
  int width = 1280, height = 720;
  std::optional<FieldKind> field;  // none: the fabric's own two colours
  ColourMap colour_map = ColourMap::kViridis;
  // The field's values, its bar's labels and title in this system's unit
  // ("curvature [1/cm]"); field_range stays SI.
  UnitSystem units = UnitSystem::kSI;
  bool edges = false;      // mesh lines on the surface
  bool thickness = false;  // both faces, h apart, instead of the midsurface
  bool floor = true;       // a grid under the part (unless a plane obstacle or the shadow is there)
  bool paths = true;       // gripper paths as polylines with an arrow
  bool grain = true;       // a pattern piece's grain line (the warp), drawn on the fabric
  bool overlay = true;     // scene name, stage, step, λ
  // The drapemeter's view (a Cusick test, docs/cusick.md): the state's
  // shadow along gravity filled under the part, the disc's and the flat
  // specimen's rims, and the drape coefficient and node count in the
  // overlay. Seen from the top: the fabric translucent over the shadow, in
  // a parallel projection.
  std::optional<DrapeTestOptions> drape_shadow;
  CameraSpec camera;
};

// What changes from frame to frame.
struct Frame {
  const ShellState* state = nullptr;
  int step = 0;  // 0: the reference state
  // The stage the state ends (−1: unknown, or before the first): grippers
  // released by then are not drawn.
  int stage = -1;
  std::string stage_name;
  double lambda = 0;
  // Per node, for the contact-pressure and friction fields (empty: not
  // available).
  std::vector<double> contact_pressure;
  std::vector<double> friction_state;  // 0 none, 1 sticking, 2 sliding
};

class FrameRenderer {
 public:
  // `bounds`: a box every frame of the run fits in (RunBounds). `field_range`
  // fixes the colour bar's range (default: each frame's own). With `window`
  // (the workbench's viewport) the renderer draws there and the window's
  // owner decides when to render; without, into an offscreen window of
  // options.width × options.height. `scene` and `model` must outlive this.
  FrameRenderer(const Scene& scene,
                const ShellModel& model,
                const RenderOptions& options,
                const Eigen::AlignedBox3d& bounds,
                std::optional<std::array<double, 2>> field_range = std::nullopt,
                vtkRenderWindow* window = nullptr);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // Moves every actor to the frame's state and renders. Throws
  // std::invalid_argument for a field the frame cannot show (contact
  // pressure without pressures).
  void Show(const Frame& frame);
  // The same without rendering (for a viewport that renders when it paints).
  void Update(const Frame& frame);

  // The last rendered picture, RGB, rows from the top.
  std::vector<unsigned char> CaptureRgb();
  // The last rendered picture as a PNG; throws std::runtime_error naming the file.
  void WritePng(const std::filesystem::path& file);

  int width() const;
  int height() const;
  // In the drapemeter's view (options.drape_shadow), the drape coefficient,
  // nodes and shadow of the state last shown; empty otherwise.
  const std::optional<DrapeMeasurement>& drape() const;
  vtkRenderer* renderer();
  // The camera placed again as at the start, fitted to the window's present
  // shape (after the window was resized, or the user turned the view).
  void FitCamera();

  // A preview's ghost (issue 20): `state` on its own `mesh` (a draft's,
  // coarser than the model's), translucent light blue over what Show draws,
  // until ClearGhost or the next SetGhost; both copied. Renders on the next
  // Show (or the viewport's paint). Throws std::invalid_argument when the
  // state's nodes are not the mesh's.
  void SetGhost(const Mesh& mesh, const ShellState& state);
  void ClearGhost();
  bool HasGhost() const;
  // Whether the fabric carries its grain line (options.grain and a pattern
  // piece that has one).
  bool HasGrainLine() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The box the part and the scene's finite obstacles occupy over `states`.
Eigen::AlignedBox3d RunBounds(const Scene& scene, const std::vector<const ShellState*>& states);

// Every point of every gripper path (for a camera that must see them).
std::vector<Eigen::Vector3d> GripperPathPoints(const Scene& scene, const ShellModel& model);

// The value range of a field over several states (for one colour bar across
// an animation).
std::array<double, 2> FieldRange(FieldKind kind,
                                 const ShellModel& model,
                                 const std::vector<const ShellState*>& states,
                                 const std::vector<double>& contact_pressure = {});

}  // namespace drape
