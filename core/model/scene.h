// The scene: plain data read from a scene file, every quantity in SI units.
//
// This is what users, scripts and the GUI share (docs/format.md is the full
// reference). It holds no mesh and no solver state: `BuildModel`-style steps
// turn it into those. Angles stored under `*_deg` keys stay in degrees.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/model/imperfection.h"
#include "core/model/pattern_piece.h"

namespace drape {

using Vec2 = std::array<double, 2>;
using Vec3 = std::array<double, 3>;

// ---- fabric -----------------------------------------------------------------

struct RectangleOutline {
  Vec2 size{0, 0};    // [m]
  Vec2 center{0, 0};  // [m]
  friend bool operator==(const RectangleOutline&, const RectangleOutline&) = default;
};
struct DiskOutline {
  double radius = 0;  // [m]
  Vec2 center{0, 0};  // [m]
  friend bool operator==(const DiskOutline&, const DiskOutline&) = default;
};
struct PolygonOutline {
  std::vector<Vec2> vertices;  // [m], not closed
  friend bool operator==(const PolygonOutline&, const PolygonOutline&) = default;
};
// A piece from a pattern file (DXF-AAMA, io/dxf_pattern_reader.h): the file
// as the scene names it (relative to the scene's folder) and the piece's
// geometry read from it, in the piece's own coordinates.
struct PatternOutline {
  std::string file;
  std::string piece;
  PiecePlacement placement;
  PatternPiece shape;  // placed
  // Where the reader found the file (absolute); not part of the scene's meaning.
  std::string resolved_path;
  friend bool operator==(const PatternOutline& a, const PatternOutline& b) {
    return a.file == b.file && a.piece == b.piece && a.placement == b.placement &&
           a.shape == b.shape;
  }
};
using Outline = std::variant<RectangleOutline, DiskOutline, PolygonOutline, PatternOutline>;

struct MeshSpec {
  std::optional<std::array<int, 2>> elements;  // [nx, ny], rectangles
  std::optional<double> size;                  // target element edge [m], other outlines
  friend bool operator==(const MeshSpec&, const MeshSpec&) = default;
};

struct ImperfectionSpec {
  double amplitude = 0;  // [m]
  std::uint64_t seed = 0;
  ImperfectionPattern pattern = ImperfectionPattern::kSmooth;
  std::optional<double> wavelength;  // [m]; default: a quarter of the part's longer side
  friend bool operator==(const ImperfectionSpec&, const ImperfectionSpec&) = default;
};

struct Fabric {
  // The part's name when the fabric has several ("fabric" an array): what
  // selections and probes name with "part". Empty for a lone part.
  std::string name;
  Outline outline;
  MeshSpec mesh;
  double elevation = 0;  // [m], z of the flat reference plane
  std::optional<ImperfectionSpec> imperfection;
  friend bool operator==(const Fabric&, const Fabric&) = default;
};

// ---- material -----------------------------------------------------------------

// M per unit width against curvature K. Each law is given in SI: K [1/m], M [N·m/m].
struct LinearBending {
  std::optional<double> rigidity;  // B [N·m²/m]; default: E h³ / 12(1 − ν²)
  friend bool operator==(const LinearBending&, const LinearBending&) = default;
};
struct PolynomialBending {
  std::vector<double> coefficients;  // c₁…cₙ of M = Σ cₖ Kᵏ, SI
  double valid_to = 0;               // |K| [1/m] up to which the fit holds
  friend bool operator==(const PolynomialBending&, const PolynomialBending&) = default;
};
struct CurveBending {
  std::vector<Vec2> points;  // [K, M] pairs, SI; from `file` when one is given
  std::string file;          // a Kawabata CSV/TSV, relative to the scene file
  // Of the file: which branch ("average", "loading", "unloading") and which
  // columns (header names; empty = found by name).
  std::string branch = "average";
  std::string curvature_column, moment_column;
  friend bool operator==(const CurveBending&, const CurveBending&) = default;
};
using BendingLaw = std::variant<LinearBending, PolynomialBending, CurveBending>;

// Bending hysteresis of one law: the width 2HB of its moment–curvature loop
// (KES-FB2), modelled as a frictional moment ±HB (bending_friction.h).
struct Hysteresis {
  double width = 0;       // 2HB [N·m/m]; 0: none
  bool measured = false;  // read from the loop of the law's Kawabata file
  friend bool operator==(const Hysteresis&, const Hysteresis&) = default;
};

struct Bending {
  BendingLaw warp;                 // the law when isotropic
  std::optional<BendingLaw> weft;  // set only for direction-dependent bending
  Hysteresis warp_hysteresis;      // of `warp` (every direction when isotropic)
  Hysteresis weft_hysteresis;      // of `weft`
  friend bool operator==(const Bending&, const Bending&) = default;
};

struct IsotropicMembrane {
  double youngs_modulus = 0;  // [Pa]
  double poisson_ratio = 0;
  friend bool operator==(const IsotropicMembrane&, const IsotropicMembrane&) = default;
};
struct OrthotropicMembrane {
  double e1 = 0, e2 = 0;  // [Pa], 1 = warp
  double nu12 = 0;
  double g12 = 0;  // [Pa]
  friend bool operator==(const OrthotropicMembrane&, const OrthotropicMembrane&) = default;
};
using Membrane = std::variant<IsotropicMembrane, OrthotropicMembrane>;

struct Material {
  double thickness = 0;     // h [m]
  double areal_weight = 0;  // w [N/m²]
  Membrane membrane;
  Bending bending;
  double angle_deg = 0;  // warp direction from the part's x axis [deg]
  // angle_deg was taken from the pattern piece's grain line ("grain").
  bool angle_from_grain = false;
  friend bool operator==(const Material&, const Material&) = default;
};

// ---- selections, supports, grippers, loads ----------------------------------

enum class Side { kLeft, kRight, kBottom, kTop, kBoundary };

struct PointSelection {
  Vec2 at{0, 0};
  friend bool operator==(const PointSelection&, const PointSelection&) = default;
};
struct LineSelection {
  Vec2 from{0, 0}, to{0, 0};
  friend bool operator==(const LineSelection&, const LineSelection&) = default;
};
struct BoxSelection {
  Vec2 min{0, 0}, max{0, 0};
  friend bool operator==(const BoxSelection&, const BoxSelection&) = default;
};
// Every node within `radius` of `center`: the clamped disc of a drape tester.
struct CircleSelection {
  Vec2 center{0, 0};
  double radius = 0;  // [m], > 0
  friend bool operator==(const CircleSelection&, const CircleSelection&) = default;
};
struct CornersSelection {
  friend bool operator==(const CornersSelection&, const CornersSelection&) = default;
};
struct EdgeSelection {
  Side side = Side::kLeft;
  friend bool operator==(const EdgeSelection&, const EdgeSelection&) = default;
};
struct NodesSelection {
  std::vector<int> nodes;
  friend bool operator==(const NodesSelection&, const NodesSelection&) = default;
};
// The node nearest a pattern piece's K-th notch or drill hole, or every node
// on its K-th internal line (fabric.outline.pattern), K counted from 1 in the
// file's order.
enum class PatternMark { kNotch, kDrill, kInternalLine };
struct PatternMarkSelection {
  PatternMark mark = PatternMark::kNotch;
  int index = 1;
  friend bool operator==(const PatternMarkSelection&, const PatternMarkSelection&) = default;
};
using SelectionShape = std::variant<PointSelection,
                                    LineSelection,
                                    BoxSelection,
                                    CircleSelection,
                                    CornersSelection,
                                    EdgeSelection,
                                    NodesSelection,
                                    PatternMarkSelection>;

struct Selection {
  SelectionShape shape;
  std::optional<double> tolerance;  // [m]; default: a millionth of the part's size
  // Of a fabric with several parts: the part's name; none selects in every
  // part (a point or a mark in one part only).
  std::optional<std::string> part = std::nullopt;
  friend bool operator==(const Selection&, const Selection&) = default;
};

enum class Fixity { kPosition, kClamp };

struct Support {
  std::string name;
  Selection select;
  Fixity fix = Fixity::kPosition;
  friend bool operator==(const Support&, const Support&) = default;
};

struct Gripper {
  std::string name;
  Selection select;
  Fixity hold = Fixity::kPosition;
  friend bool operator==(const Gripper&, const Gripper&) = default;
};

struct PointLoad {
  std::string name;
  Selection select;
  Vec3 force{0, 0, 0};   // total [N], shared over the selected nodes
  Vec3 moment{0, 0, 0};  // total [N·m]
  friend bool operator==(const PointLoad&, const PointLoad&) = default;
};

// ---- obstacles --------------------------------------------------------------

struct PlaneShape {
  Vec3 point{0, 0, 0};
  Vec3 normal{0, 0, 1};  // unit
  friend bool operator==(const PlaneShape&, const PlaneShape&) = default;
};
struct BoxShape {
  Vec3 min{0, 0, 0}, max{0, 0, 0};
  double edge_radius = 0;
  friend bool operator==(const BoxShape&, const BoxShape&) = default;
};
struct CylinderShape {
  Vec3 point{0, 0, 0};
  Vec3 axis{1, 0, 0};  // unit
  double radius = 0;
  std::optional<double> length;  // centred on `point`; infinite when absent
  friend bool operator==(const CylinderShape&, const CylinderShape&) = default;
};
struct SphereShape {
  Vec3 center{0, 0, 0};
  double radius = 0;
  friend bool operator==(const SphereShape&, const SphereShape&) = default;
};
struct MeshShape {
  std::string file;  // OBJ or STL, as written in the scene (relative to it)
  // Where the reader found it (absolute); not part of the scene's meaning.
  std::string resolved_path;
  // Its place in the world (core/model/mesh_placement.h): the file's
  // coordinates scaled about its origin (per axis, each > 0), turned about
  // the vertical through the origin, then the origin moved to `at`. A form
  // is sized, turned to face the fabric and stood where it is wanted.
  Vec3 scale{1, 1, 1};
  double rotation_deg = 0;
  Vec3 at{0, 0, 0};
  friend bool operator==(const MeshShape& a, const MeshShape& b) {
    return a.file == b.file && a.scale == b.scale && a.rotation_deg == b.rotation_deg &&
           a.at == b.at;
  }
};
using ObstacleShape = std::variant<PlaneShape, BoxShape, CylinderShape, SphereShape, MeshShape>;

struct Obstacle {
  std::string name;
  ObstacleShape shape;
  friend bool operator==(const Obstacle&, const Obstacle&) = default;
};

// How obstacles push on the fabric (core/contact/node_contact.h): a penalty
// on how far the fabric's surface is inside, or a barrier that keeps it out.
enum class ContactLaw { kPenalty, kBarrier };

struct Contact {
  ContactLaw law = ContactLaw::kPenalty;
  std::optional<double> penalty;  // [N/m³] per unit area; absent = "auto"
  // d̂ of the barrier: it acts while the fabric's surface is nearer than
  // this to an obstacle [m]; absent: half the thickness.
  std::optional<double> barrier_distance;
  double friction = 0;  // Coulomb μ
  // ε: the slip at which friction turns from sticking to sliding [m];
  // absent: DefaultFrictionSlip (core/contact/node_contact.h).
  std::optional<double> friction_slip;
  // Self-contact: the fabric's layers kept `thickness` apart (default the
  // material's) by a barrier (core/contact/self_contact.h).
  bool self = true;
  std::optional<double> thickness;  // [m]
  friend bool operator==(const Contact&, const Contact&) = default;
};

// ---- stages -----------------------------------------------------------------

struct LinePath {
  Vec3 by{0, 0, 0};  // [m]
  friend bool operator==(const LinePath&, const LinePath&) = default;
};
struct ArcPath {
  Vec3 center{0, 0, 0};
  Vec3 axis{0, 0, 1};  // unit; right-handed rotation
  double angle_deg = 0;
  friend bool operator==(const ArcPath&, const ArcPath&) = default;
};
enum class Interpolation { kLinear, kSmooth };
struct KeyframesPath {
  std::vector<Vec3> points;  // offsets from the stage's start, reached at λ = k/n
  Interpolation interpolation = Interpolation::kLinear;
  friend bool operator==(const KeyframesPath&, const KeyframesPath&) = default;
};
using Path = std::variant<LinePath, ArcPath, KeyframesPath>;

// What a move stage carries along a path: a gripper, or (gripper empty) an
// obstacle — a table lowered, a rod lifted.
struct Move {
  std::string gripper;
  Path path;
  std::string obstacle;
  friend bool operator==(const Move&, const Move&) = default;
};

enum class StageKind { kGravity, kLoad, kMove, kHold };
enum class StepControl { kArcLength, kLoad };

struct Stage {
  std::string name;
  StageKind kind = StageKind::kGravity;
  double initial_increment = 0.01;  // Δλ₀
  StepControl control = StepControl::kArcLength;
  std::vector<std::string> release;  // grippers freed from this stage on
  std::vector<Move> moves;
  friend bool operator==(const Stage&, const Stage&) = default;
};

// ---- solver, probes -----------------------------------------------------------

// What the continuation does where the path bifurcates.
enum class Branching {
  kStable,       // switch to the branch a real part takes (stable where one is)
  kFundamental,  // follow the primary path through (the paper's studies)
};

// Named accuracy settings (core/model/solver_preset.h).
enum class SolverPreset { kDraft, kBalanced, kAccurate };

inline constexpr int kAutoSequencing = 0;

struct SolverSettings {
  // The preset the settings were based on; keys given beside it override it.
  std::optional<SolverPreset> preset;
  // The mesh the scene is solved on, in elements per direction relative to
  // fabric.mesh (directions of one or two elements stay): a preset's density.
  double mesh_scale = 1;
  double tolerance = 1e-5;               // ‖R‖/‖R₀‖
  double displacement_tolerance = 1e-8;  // stall: max|Δu| / the part's diagonal
  int target_iterations = 7;             // N_p
  bool acceleration = true;              // γₙ = N_p / N_{n−1}
  int max_steps = 5000;
  int max_iterations = 30;
  int max_step_cuts = 10;
  // Limit points a stage's path may pass (λ turning back) before it fails:
  // under `fundamental` a path can turn back and forth for minutes.
  int max_turns = 20;
  std::optional<double> psi;  // [m]; default: a characteristic length of the part
  Branching branching = Branching::kStable;
  // > 1: follow the path on the mesh this many times coarser in each
  // direction, then solve the scene's mesh from its end (mesh sequencing);
  // 1: off; kAutoSequencing: chosen by AutoSequencing (sequencing_check.h).
  int sequencing = kAutoSequencing;
  // Wall-clock limit of a run [s]: past it the run stops (failed), keeping
  // every converged step. Absent: none.
  std::optional<double> max_wall_s;
  // After a converged run: solve the scene on meshes 2 and 4 times coarser
  // and estimate the error of its probes (core/solve/error_estimate.h).
  bool error_estimate = false;
  friend bool operator==(const SolverSettings&, const SolverSettings&) = default;
};

struct Probe {
  std::string name;
  Vec2 at{0, 0};                                   // reference coordinates [m]
  std::optional<std::string> part = std::nullopt;  // as Selection::part
  friend bool operator==(const Probe&, const Probe&) = default;
};

struct Scene {
  std::string name;
  std::string description;
  Fabric fabric;
  // The fabric's other parts when "fabric" is an array (fabric[1], ...):
  // plies stacked on a table, pieces side by side. Each is meshed on its
  // own; all share `material`.
  std::vector<Fabric> other_parts;
  Material material;
  std::vector<Support> supports;
  std::vector<Gripper> grippers;
  std::vector<PointLoad> loads;
  std::vector<Obstacle> obstacles;
  std::optional<Contact> contact;
  Vec3 gravity_direction{0, 0, -1};  // unit
  std::vector<Stage> stages;
  SolverSettings solver;
  std::vector<Probe> probes;
  friend bool operator==(const Scene&, const Scene&) = default;
};

inline constexpr int kSceneFormatVersion = 1;

// Every part of the fabric, the first (scene.fabric) first.
std::vector<const Fabric*> FabricParts(const Scene& scene);

// Names used in files, reports and messages.
const char* ToString(StageKind kind);
const char* ToString(StepControl control);
const char* ToString(Fixity fixity);
const char* ToString(Side side);
// The selection's key in a scene file ("notch", "drill", "internal_line")
// and its name in messages ("notch", "drill hole", "internal line").
const char* PatternMarkKey(PatternMark mark);
const char* PatternMarkName(PatternMark mark);
const char* ToString(Interpolation interpolation);
const char* ToString(ImperfectionPattern pattern);
const char* ToString(Branching branching);
const char* ToString(SolverPreset preset);  // core/model/solver_preset.cc

}  // namespace drape
