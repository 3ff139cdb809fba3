// Every error message of the scene reader is checked by a test: it names the
// key, the value in the unit typed and what is expected. Each case below
// starts from a small valid scene, breaks one thing in it and compares the
// whole message the reader gives ("key.path: text") with the one written
// here, so that a change of wording is a change of this table. The cases are
// grouped as the reader reads a scene (core/io/scene_reader*.cc): one case per
// place in the reader that raises an error, one per distinct message shape
// where a generic check of core/io/json_cursor.cc serves many keys, and the
// unit parser's messages (core/model/units.cc) as they reach a quantity key.
// A second test checks that each message starts with the key's path and shows
// the value as the user typed it; a third covers the errors raised before
// there is a JSON document (a key given twice, text that is not JSON, a
// missing file). Errors in files a scene refers to (DXF patterns, Kawabata
// files, meshes, library materials) have their own tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/io/scene_reader.h"
#include "core/model/scene_error.h"
#include "support/minimal_scene.h"
#include "support/temp_dir.h"
#include "support/test_paths.h"

namespace drape {
namespace {

using nlohmann::json;

json Minimal() {
  return test::MinimalSceneJson();
}

// A gripper 'hand' holding the strip's right edge.
void AddGripper(json& doc) {
  doc["grippers"] = json::parse(R"([{"name": "hand", "select": {"edge": "right"}}])");
}

// The gripper, and after the weight a stage 'lift' that raises it by 1 cm.
void AddLift(json& doc) {
  AddGripper(doc);
  doc["stages"].push_back(json::parse(R"({"name": "lift", "kind": "move",
      "moves": [{"gripper": "hand", "path": {"line": {"by": [0, 0, "1 cm"]}}}]})"));
}

// A table under the strip.
void AddTable(json& doc) {
  doc["obstacles"] = json::parse(R"([{"name": "table", "box": {
      "min": ["-20 cm", "-10 cm", "-5 cm"], "max": ["20 cm", "10 cm", "-1 cm"]}}])");
}

// Two plies, 'lower' and 'upper', 1 mm apart.
void MakeTwoParts(json& doc) {
  doc["fabric"] = json::parse(R"([
    {"name": "lower", "outline": {"rectangle": {"size": ["10 cm", "10 cm"]}},
     "mesh": {"elements": [4, 4]}},
    {"name": "upper", "outline": {"rectangle": {"size": ["10 cm", "10 cm"]}},
     "mesh": {"elements": [4, 4]}, "elevation": "1 mm"}])");
}

// A Kawabata file of one loading run and no unloading: no loop to measure
// 2HB on. Written once per test program, removed when it ends.
std::string NoLoopKawabataFile() {
  static const test::TempDir dir("reader-errors");
  const std::filesystem::path file = dir / "no-loop.csv";
  if (!std::filesystem::exists(file))
    std::ofstream(file)
        << "curvature (1/cm),moment (gf*cm/cm)\n0,0\n0.5,0.4\n1,0.6\n1.5,0.7\n2,0.8\n";
  return file.string();
}

struct Case {
  const char* name;
  std::function<void(json&)> edit;
  const char* message;
};

const std::vector<Case>& Cases() {
  static const std::vector<Case> cases = {
      // ---- top level --------------------------------------------------------
      {"unknown key with a suggestion",
       [](json& d) { d["stage"] = d["stages"]; },
       "stage: unknown key; did you mean 'stages'?"},
      {"unknown key without a suggestion",
       [](json& d) { d["gravity"] = json::parse(R"({"direction": [0, 0, -1], "up": 1})"); },
       "gravity.up: unknown key; expected one of 'direction'"},
      {"format version as a string",
       [](json& d) { d["drape_scene"] = "1"; },
       "drape_scene: expected an integer (a whole number), found a string \"1\""},
      {"unsupported format version",
       [](json& d) { d["drape_scene"] = 2; },
       "drape_scene: unsupported scene format version 2; this program reads version 1"},
      {"stages not an array",
       [](json& d) { d["stages"] = "SW"; },
       "stages: expected an array, found a string \"SW\""},
      {"no stage",
       [](json& d) { d["stages"] = json::array(); },
       "stages: a scene needs at least one stage"},
      {"zero gravity direction",
       [](json& d) { d["gravity"] = json::parse(R"({"direction": [0, 0, 0]})"); },
       "gravity.direction: a direction must not be the zero vector"},

      // ---- fabric -----------------------------------------------------------
      {"outline not an object",
       [](json& d) { d["fabric"]["outline"] = "rectangle"; },
       "fabric.outline: expected an object, found a string \"rectangle\""},
      {"fabric part not an object",
       [](json& d) { d["fabric"] = json::array({"lower"}); },
       "fabric[0]: expected an object, found a string \"lower\""},
      {"no fabric part",
       [](json& d) { d["fabric"] = json::array(); },
       "fabric: expected the fabric's parts, at least one"},
      {"two outlines",
       [](json& d) { d["fabric"]["outline"]["disk"] = json::parse(R"({"radius": "5 cm"})"); },
       "fabric.outline: give only one of 'rectangle', 'disk', 'polygon', 'pattern'"},
      {"rectangle size not an array",
       [](json& d) { d["fabric"]["outline"]["rectangle"]["size"] = "20 cm"; },
       "fabric.outline.rectangle.size: expected an array of 2, found a string \"20 cm\""},
      {"rectangle size of a negative bare number",
       [](json& d) { d["fabric"]["outline"]["rectangle"]["size"][0] = -0.2; },
       "fabric.outline.rectangle.size[0]: must be greater than zero, found -0.2"},
      {"polygon of two vertices",
       [](json& d) {
         d["fabric"]["outline"] = json::parse(R"({"polygon": [[0, 0], ["10 cm", 0]]})");
       },
       "fabric.outline.polygon: a polygon needs at least 3 vertices, found 2"},
      {"element counts of three values",
       [](json& d) {
         d["fabric"]["mesh"]["elements"] = json::array({8, 1, 1});
       },
       "fabric.mesh.elements: expected 2 values, found 3"},
      {"fractional element count",
       [](json& d) {
         d["fabric"]["mesh"]["elements"] = json::array({80.5, 2});
       },
       "fabric.mesh.elements[0]: expected an integer (a whole number), found 80.5"},
      {"element count below 1",
       [](json& d) {
         d["fabric"]["mesh"]["elements"] = json::array({1, -3});
       },
       "fabric.mesh.elements[1]: must be at least 1, found -3"},
      {"more than 4 million elements",
       [](json& d) {
         d["fabric"]["mesh"]["elements"] = json::array({3000, 2000});
       },
       "fabric.mesh.elements: 3000 x 2000 = 6000000 elements, more than the 4000000 allowed"},
      {"element counts for a disk",
       [](json& d) { d["fabric"]["outline"] = json::parse(R"({"disk": {"radius": "10 cm"}})"); },
       "fabric.mesh.elements: element counts are for rectangle outlines; this outline is a disk: "
       "give 'size' (a target element edge)"},
      {"negative imperfection amplitude",
       [](json& d) { d["fabric"]["imperfection"] = json::parse(R"({"amplitude": "-1 mm"})"); },
       "fabric.imperfection.amplitude: must not be negative, found \"-1 mm\""},
      {"negative imperfection seed",
       [](json& d) {
         d["fabric"]["imperfection"] = json::parse(R"({"amplitude": "0.1 mm", "seed": -1})");
       },
       "fabric.imperfection.seed: expected a non-negative integer, found -1"},

      // ---- quantities: the unit parser, through any quantity key ------------
      {"unit out of range",
       [](json& d) { d["fabric"]["elevation"] = "1 um^60"; },
       "fabric.elevation: unit 'um^60' is out of range (its factor to SI units must lie between "
       "about 1e-308 and 1e308) in \"1 um^60\""},
      {"unit exponent too large",
       [](json& d) { d["fabric"]["elevation"] = "1 m^50*m^50"; },
       "fabric.elevation: exponent too large: m^100 (at most 99) in \"1 m^50*m^50\""},
      {"unit exponent not an integer",
       [](json& d) { d["material"]["thickness"] = "1 m^x"; },
       "material.thickness: expected an integer exponent after '^', found 'x' in \"1 m^x\""},
      {"unit exponent over 99",
       [](json& d) { d["material"]["thickness"] = "1 m^100"; },
       "material.thickness: exponent '100' is too large (at most 99) in \"1 m^100\""},
      {"unknown unit",
       [](json& d) { d["material"]["thickness"] = "5 furlong"; },
       "material.thickness: unknown unit 'furlong' (known: m, cm, mm, um, in, ft, N, kN, mN, gf, "
       "gmf, kgf, ozf, oz, lbf, lb, kg, g, Pa, kPa, MPa, GPa, psi, deg, rad, s) in \"5 "
       "furlong\""},
      {"number in a unit",
       [](json& d) { d["material"]["thickness"] = "1 2/cm"; },
       "material.thickness: unexpected number '2' in a unit (only 1 may stand for a unit, as in "
       "'1/cm') in \"1 2/cm\""},
      {"unit nested too deep",
       [](json& d) {
         d["fabric"]["elevation"] =
             "1 (((((((((((((((((((((((((((((((((m)))))))))))))))))))))))))))))))))";
       },
       "fabric.elevation: parentheses nested more than 32 deep, at character 33 of the unit in "
       "\"1 (((((((((((((((((((((((((((((((((m)))))))))))))))))))))))))))))))))\""},
      {"unit missing a parenthesis",
       [](json& d) { d["material"]["thickness"] = "1 (mm"; },
       "material.thickness: missing ')' in \"1 (mm\""},
      {"unit ending in an operator",
       [](json& d) { d["material"]["thickness"] = "0.5 mm/"; },
       "material.thickness: expected a unit, found end of text in \"0.5 mm/\""},
      {"two units without an operator",
       [](json& d) { d["material"]["thickness"] = "0.5 mm mm"; },
       "material.thickness: expected '*' or '/' before 'mm' in \"0.5 mm mm\""},
      {"unexpected character in a unit",
       [](json& d) { d["material"]["thickness"] = "0.5 mm)"; },
       "material.thickness: unexpected ')' (expected '*', '/', '^' or the end) in \"0.5 mm)\""},
      {"empty quantity",
       [](json& d) { d["material"]["thickness"] = ""; },
       "material.thickness: empty quantity, expected a number and a unit such as \"0.489 mm\""},
      {"number out of range",
       [](json& d) { d["material"]["thickness"] = "1e400 mm"; },
       "material.thickness: number '1e400' is out of range (its size must lie between about "
       "1e-308 and 1e308) in \"1e400 mm\""},
      {"malformed number",
       [](json& d) { d["material"]["thickness"] = "0.5.1 mm"; },
       "material.thickness: malformed number '0.5.1' (expected a number such as 0.5 or 2e-3) in "
       "\"0.5.1 mm\""},
      {"quantity out of range in SI",
       [](json& d) { d["material"]["youngs_modulus"] = "1e300 GPa"; },
       "material.youngs_modulus: \"1e300 GPa\" is out of range in SI units (at most about "
       "1.8e308)"},
      {"unit of the wrong dimension",
       [](json& d) { d["material"]["youngs_modulus"] = "3 cm"; },
       "material.youngs_modulus: \"3 cm\" is a length, expected a force/area (Pa, kPa, MPa, GPa, "
       "psi, gf/cm^2, oz/in^2)"},
      {"quantity without a unit",
       [](json& d) { d["material"]["thickness"] = "5"; },
       "material.thickness: \"5\" is dimensionless, expected a length (m, cm, mm, in, ft)"},

      // ---- material ---------------------------------------------------------
      {"missing thickness",
       [](json& d) { d["material"].erase("thickness"); },
       "material: missing required key 'thickness'"},
      {"negative thickness",
       [](json& d) { d["material"]["thickness"] = "-0.1 mm"; },
       "material.thickness: must be greater than zero, found \"-0.1 mm\""},
      {"thickness not a quantity",
       [](json& d) { d["material"]["thickness"] = true; },
       "material.thickness: expected a length (m, cm, mm, in, ft) (a number in SI units or a "
       "\"number unit\" string), found true"},
      {"no areal weight",
       [](json& d) { d["material"].erase("areal_weight"); },
       "material: expected one of 'areal_weight', 'areal_density'"},
      {"poisson ratio as a string",
       [](json& d) { d["material"]["poisson_ratio"] = "0.3"; },
       "material.poisson_ratio: expected a number, found a string \"0.3\""},
      {"poisson ratio out of range",
       [](json& d) { d["material"]["poisson_ratio"] = 0.7; },
       "material.poisson_ratio: must lie in [0, 0.5) (an isotropic sheet with ν = 0.5 cannot "
       "change its area), found 0.7"},
      {"membrane beside a modulus",
       [](json& d) {
         d["material"]["membrane"] =
             json::parse(R"({"E1": "10 MPa", "E2": "4 MPa", "nu12": 0.3, "G12": "1 MPa"})");
       },
       "material.youngs_modulus: give either 'youngs_modulus'/'poisson_ratio' or 'membrane', not "
       "both"},
      {"orthotropic nu12 out of range",
       [](json& d) {
         d["material"].erase("youngs_modulus");
         d["material"].erase("poisson_ratio");
         d["material"]["membrane"] =
             json::parse(R"({"E1": "10 MPa", "E2": "4 MPa", "nu12": 1.6, "G12": "1 MPa"})");
       },
       "material.membrane.nu12: must lie in [0, 1.581) for a stable orthotropic law with these E1 "
       "and E2 (the bound is √(E1/E2)), found 1.6"},
      {"angle with a typo of grain",
       [](json& d) { d["material"]["angle_deg"] = "grian"; },
       "material.angle_deg: expected \"grain\" or an angle (a number of degrees, or a \"number "
       "unit\" string such as \"0.5 rad\"), found \"grian\""},
      {"grain of a rectangle",
       [](json& d) { d["material"]["angle_deg"] = "grain"; },
       "material.angle_deg: \"grain\" takes the warp from a pattern piece's grain line; this "
       "fabric's outline is not a pattern piece"},
      {"grain of parts turned apart",
       [](json& d) {
         d["fabric"] = json::parse(R"([
           {"name": "front", "mesh": {"size": "5 cm"}, "outline": {"pattern":
             {"file": "../patterns/garments.dxf", "piece": "SKIRT-FRONT"}}},
           {"name": "turned", "mesh": {"size": "5 cm"}, "outline": {"pattern":
             {"file": "../patterns/garments.dxf", "piece": "SKIRT-FRONT", "rotation_deg": 30}}}])");
         d["material"]["angle_deg"] = "grain";
       },
       "material.angle_deg: the parts' grain lines differ ('front' 90 deg, 'turned' 120 deg) and "
       "the parts share one material: give angle_deg"},
      {"library material with a typo",
       [](json& d) { d["material"] = json::parse(R"({"library": "cotton-twil"})"); },
       "material.library: no library material 'cotton-twil'; did you mean 'cotton-twill'?"},
      {"unknown library material",
       [](json& d) { d["material"] = json::parse(R"({"library": "velvet"})"); },
       "material.library: no library material 'velvet'; the library has: cotton-twill, "
       "cotton-twill-linear, polyester-plain-weave, polyester-plain-weave-block"},
      {"bending law not an object",
       [](json& d) { d["material"]["bending"] = "linear"; },
       "material.bending: expected an object with a 'model', found a string \"linear\""},
      {"empty moment unit",
       [](json& d) {
         d["material"]["bending"] = json::parse(R"({"model": "polynomial", "moment_unit": ""})");
       },
       "material.bending.moment_unit: expected a unit in \"\""},
      {"moment unit of the wrong dimension",
       [](json& d) {
         d["material"]["bending"] = json::parse(R"({"model": "polynomial", "moment_unit": "cm"})");
       },
       "material.bending.moment_unit: expected a unit of moment per width, such as gf*cm/cm or "
       "N*m/m, found \"cm\""},
      {"no polynomial coefficient",
       [](json& d) {
         d["material"]["bending"] =
             json::parse(R"({"model": "polynomial", "coefficients": [], "valid_to": "2.5 1/cm"})");
       },
       "material.bending.coefficients: needs at least one coefficient"},
      {"negative linear coefficient",
       [](json& d) {
         d["material"]["bending"] = json::parse(
             R"({"model": "polynomial", "coefficients": [-1.5], "valid_to": "2.5 1/cm"})");
       },
       "material.bending.coefficients: the linear coefficient c1 (the initial bending rigidity) "
       "must be positive, found -1.5"},
      {"branch of a curve given by points",
       [](json& d) {
         d["material"]["bending"] =
             json::parse(R"({"model": "curve", "points": [[1, 1], [2, 3]], "branch": "loading"})");
       },
       "material.bending.branch: applies only to a Kawabata 'file'"},
      {"curve of one point",
       [](json& d) {
         d["material"]["bending"] = json::parse(R"({"model": "curve", "points": [[1, 1]]})");
       },
       "material.bending.points: a curve needs at least 2 points, found 1"},
      {"curvatures not increasing",
       [](json& d) {
         d["material"]["bending"] =
             json::parse(R"({"model": "curve", "points": [[1, 1], [1, 2]]})");
       },
       "material.bending.points[1]: curvatures must increase from point to point, found 1 after "
       "1"},
      {"measured hysteresis without a file",
       [](json& d) {
         d["material"]["bending"] = json::parse(R"({"model": "linear", "hysteresis": "measured"})");
       },
       "material.bending.hysteresis: \"measured\" takes 2HB from a Kawabata file's loop; this "
       "law has no 'file'"},
      {"measured hysteresis of a file without a loop",
       [](json& d) {
         d["material"]["bending"] = {
             {"model", "curve"}, {"file", NoLoopKawabataFile()}, {"hysteresis", "measured"}};
       },
       "material.bending.hysteresis: the Kawabata file has no loop to measure 2HB on: its "
       "loading and unloading branches do not both reach |K| = 1 1/cm"},
      {"negative hysteresis",
       [](json& d) {
         d["material"]["bending"] =
             json::parse(R"({"model": "linear", "hysteresis": "-0.1 gf*cm/cm"})");
       },
       "material.bending.hysteresis: 2HB, the width of the moment-curvature loop, must not be "
       "negative, found \"-0.1 gf*cm/cm\""},
      {"hysteresis with a typo of measured",
       [](json& d) {
         d["material"]["bending"] = json::parse(R"({"model": "linear", "hysteresis": "mesured"})");
       },
       "material.bending.hysteresis: expected \"measured\" or 2HB, a moment per width (a number "
       "in the law's moment_unit, or a \"number unit\" string such as \"0.1 gf*cm/cm\"), found "
       "\"mesured\""},

      // ---- selections -------------------------------------------------------
      {"line of one point",
       [](json& d) { d["supports"][0]["select"] = json::parse(R"({"line": [[0, 0], [0, 0]]})"); },
       "supports[0].select.line: the two ends of a line must differ, found [0, 0] and [0, 0]"},
      {"box with min above max",
       [](json& d) {
         d["supports"][0]["select"] = json::parse(R"({"box": [["1 cm", 0], [0, "1 cm"]]})");
       },
       "supports[0].select.box: expected [[xmin, ymin], [xmax, ymax]] with min <= max, found xmin "
       "\"1 cm\" > xmax 0"},
      {"corners false",
       [](json& d) { d["supports"][0]["select"] = json::parse(R"({"corners": false})"); },
       "supports[0].select.corners: write \"corners\": true to select corners"},
      {"notch 0",
       [](json& d) { d["supports"][0]["select"] = json::parse(R"({"notch": 0})"); },
       "supports[0].select.notch: counts from 1 (the first in the pattern file), found 0"},
      {"negative node index",
       [](json& d) { d["supports"][0]["select"] = json::parse(R"({"nodes": [-1]})"); },
       "supports[0].select.nodes[0]: node indices start at 0, found -1"},
      {"empty node list",
       [](json& d) { d["supports"][0]["select"] = json::parse(R"({"nodes": []})"); },
       "supports[0].select.nodes: an empty node list selects nothing"},
      {"unknown part",
       [](json& d) {
         MakeTwoParts(d);
         d["supports"][0]["select"] = json::parse(R"({"edge": "left", "part": "top"})");
       },
       "supports[0].select.part: no fabric part is named 'top'; the parts are 'lower', 'upper'"},

      // ---- supports and grippers --------------------------------------------
      {"empty name",
       [](json& d) { d["supports"][0]["name"] = ""; },
       "supports[0].name: a name must not be empty"},
      {"name not a string",
       [](json& d) { d["supports"][0]["name"] = 7; },
       "supports[0].name: expected a string, found the number 7"},
      {"gripper named as a support",
       [](json& d) {
         d["grippers"] = json::parse(R"([{"name": "root", "select": {"edge": "right"}}])");
       },
       "grippers[0].name: 'root' is already the name of supports[0]"},
      {"fixity with a typo",
       [](json& d) { d["supports"][0]["fix"] = "clmp"; },
       "supports[0].fix: 'clmp' is not valid; did you mean 'clamp'?"},

      // ---- loads ------------------------------------------------------------
      {"load without force or moment",
       [](json& d) {
         d["loads"] = json::parse(R"([{"name": "push", "select": {"edge": "right"}}])");
       },
       "loads[0]: a load needs a 'force', a 'moment' or both"},
      {"force given as a moment",
       [](json& d) {
         d["loads"] = json::parse(
             R"([{"name": "push", "select": {"edge": "right"}, "force": [0, 0, "1 N*m"]}])");
       },
       "loads[0].force[2]: \"1 N*m\" is a force·length, expected a force (N, gf, oz, lbf)"},

      // ---- obstacles --------------------------------------------------------
      {"empty mesh file name",
       [](json& d) { d["obstacles"] = json::parse(R"([{"name": "form", "mesh": {"file": ""}}])"); },
       "obstacles[0].mesh.file: a file name must not be empty"},
      {"missing mesh file",
       [](json& d) {
         d["obstacles"] =
             json::parse(R"([{"name": "form", "mesh": {"file": "/nonexistent/form.obj"}}])");
       },
       "obstacles[0].mesh.file: cannot read '/nonexistent/form.obj' (looked for "
       "/nonexistent/form.obj)"},
      {"negative mesh scale",
       [](json& d) {
         d["obstacles"] = json::parse(
             R"([{"name": "form", "mesh": {"file": "../forms/dress-form.obj", "scale": -2}}])");
       },
       "obstacles[0].mesh.scale: a scale factor must be between 1e-6 and 1e6 (a positive number; "
       "a negative one would turn the mesh inside out), found -2"},
      {"box of negative height",
       [](json& d) {
         d["obstacles"] = json::parse(
             R"([{"name": "table", "box": {"min": [0, 0, "1 cm"], "max": ["1 m", "1 m", 0]}}])");
       },
       "obstacles[0].box.max: each coordinate of 'max' must exceed that of 'min', found max[2] = 0 "
       "and min[2] = \"1 cm\""},
      {"box edge radius too large",
       [](json& d) {
         AddTable(d);
         d["obstacles"][0]["box"]["edge_radius"] = "3 cm";
       },
       "obstacles[0].box.edge_radius: must be smaller than half the box's smallest side (2 cm), "
       "found \"3 cm\""},

      // ---- contact ----------------------------------------------------------
      {"penalty of a barrier contact",
       [](json& d) { d["contact"] = json::parse(R"({"law": "barrier", "penalty": "1e6 N/m^3"})"); },
       "contact.penalty: a penalty belongs to contact.law \"penalty\"; this contact is a barrier "
       "(its distance is contact.barrier_distance)"},
      {"penalty with a typo",
       [](json& d) { d["contact"] = json::parse(R"({"penalty": "atuo"})"); },
       "contact.penalty: expected \"auto\" or a force/length^3 (N/m^3, gf/cm^3), found \"atuo\""},
      {"negative friction",
       [](json& d) { d["contact"] = json::parse(R"({"friction": -0.2})"); },
       "contact.friction: a friction coefficient must not be negative, found -0.2"},
      {"barrier distance of a penalty contact",
       [](json& d) { d["contact"] = json::parse(R"({"barrier_distance": "1 mm"})"); },
       "contact.barrier_distance: a barrier distance belongs to contact.law \"barrier\" (this "
       "contact is a penalty)"},
      {"self contact not a boolean",
       [](json& d) { d["contact"] = json::parse(R"({"self": "yes"})"); },
       "contact.self: expected true or false, found a string \"yes\""},

      // ---- stages, moves and paths ------------------------------------------
      {"unknown stage kind",
       [](json& d) { d["stages"][0]["kind"] = "fall"; },
       "stages[0].kind: 'fall' is not valid; expected one of 'gravity', 'load', 'move', 'hold'"},
      {"initial increment above 1",
       [](json& d) { d["stages"][0]["initial_increment"] = 1.5; },
       "stages[0].initial_increment: must lie in (0, 1], found 1.5"},
      {"moves in a gravity stage",
       [](json& d) { d["stages"][0]["moves"] = json::array(); },
       "stages[0].moves: only a stage of kind 'move' has moves; this stage is of kind 'gravity'"},
      {"move stage without moves",
       [](json& d) {
         AddLift(d);
         d["stages"][1].erase("moves");
       },
       "stages[1]: a 'move' stage needs at least one entry in 'moves'"},
      {"arc of zero angle",
       [](json& d) {
         AddLift(d);
         d["stages"][1]["moves"][0]["path"] =
             json::parse(R"({"arc": {"center": [0, 0, 0], "axis": [0, 1, 0], "angle_deg": 0}})");
       },
       "stages[1].moves[0].path.arc.angle_deg: an arc of zero angle does not move"},
      {"angle not a quantity",
       [](json& d) {
         AddLift(d);
         d["stages"][1]["moves"][0]["path"] =
             json::parse(R"({"arc": {"center": [0, 0, 0], "axis": [0, 1, 0], "angle_deg": true}})");
       },
       "stages[1].moves[0].path.arc.angle_deg: expected an angle (a number of degrees, or a "
       "\"number unit\" string such as \"0.5 rad\"), found true"},
      {"keyframes without points",
       [](json& d) {
         AddLift(d);
         d["stages"][1]["moves"][0]["path"] = json::parse(R"({"keyframes": {"points": []}})");
       },
       "stages[1].moves[0].path.keyframes.points: needs at least one point"},
      {"gravity stage of a weightless fabric",
       [](json& d) { d["material"]["areal_weight"] = 0; },
       "stages[0].kind: a gravity stage needs a positive material.areal_weight; "
       "material.areal_weight is 0"},
      {"load stage without loads",
       [](json& d) { d["stages"][0]["kind"] = "load"; },
       "stages[0].kind: a load stage needs at least one entry in 'loads'"},
      {"release of an unknown gripper",
       [](json& d) { d["stages"][0]["release"] = json::array({"lifter"}); },
       "stages[0].release[0]: no gripper is named 'lifter'; this scene has no grippers"},
      {"gripper released twice",
       [](json& d) {
         AddGripper(d);
         d["stages"] = json::parse(R"([{"name": "SW", "kind": "gravity", "release": ["hand"]},
                                       {"name": "rest", "kind": "hold", "release": ["hand"]}])");
       },
       "stages[1].release[0]: gripper 'hand' was already released in stage 'SW'"},
      {"move of an unknown obstacle",
       [](json& d) {
         AddLift(d);
         d["stages"][1]["moves"][0].erase("gripper");
         d["stages"][1]["moves"][0]["obstacle"] = "table";
       },
       "stages[1].moves[0].obstacle: no obstacle is named 'table'; this scene has no obstacles"},
      {"obstacle moved twice",
       [](json& d) {
         AddTable(d);
         AddLift(d);
         d["stages"][1]["moves"] = json::parse(R"([
           {"obstacle": "table", "path": {"line": {"by": [0, 0, "1 cm"]}}},
           {"obstacle": "table", "path": {"line": {"by": [0, 0, "2 cm"]}}}])");
       },
       "stages[1].moves[1].obstacle: obstacle 'table' is moved twice in one stage"},
      {"move of an unknown gripper",
       [](json& d) {
         AddLift(d);
         d["stages"][1]["moves"][0]["gripper"] = "hadn";
       },
       "stages[1].moves[0].gripper: no gripper is named 'hadn'; the only gripper is 'hand'"},
      {"move of a released gripper",
       [](json& d) {
         AddLift(d);
         d["stages"][0]["release"] = json::array({"hand"});
       },
       "stages[1].moves[0].gripper: gripper 'hand' was released in stage 'SW'"},
      {"gripper moved twice",
       [](json& d) {
         AddLift(d);
         const json move = d["stages"][1]["moves"][0];
         d["stages"][1]["moves"].push_back(move);
       },
       "stages[1].moves[1].gripper: gripper 'hand' is moved twice in one stage"},

      // ---- probes -----------------------------------------------------------
      {"part of a fabric of one part",
       [](json& d) {
         d["probes"] = json::parse(R"([{"name": "tip", "at": ["20 cm", 0], "part": "lower"}])");
       },
       "probes[0].part: 'lower' names a part, but this fabric is one part: leave out 'part'"},
      {"two probes of one name",
       [](json& d) {
         d["probes"] = json::parse(
             R"([{"name": "tip", "at": ["10 cm", 0]}, {"name": "tip", "at": ["9 cm", 0]}])");
       },
       "probes[1].name: 'tip' is already the name of probes[0]"},

      // ---- solver -----------------------------------------------------------
      {"unknown preset",
       [](json& d) { d["solver"] = json::parse(R"({"preset": "fast"})"); },
       "solver.preset: 'fast' is not a preset; one of draft, balanced, accurate"},
      {"mesh scale out of range",
       [](json& d) { d["solver"] = json::parse(R"({"mesh_scale": 20})"); },
       "solver.mesh_scale: must lie in [0.1, 10], found 20"},
      {"tolerance out of range",
       [](json& d) { d["solver"] = json::parse(R"({"tolerance": 1.5})"); },
       "solver.tolerance: must lie in (0, 1), found 1.5"},
      {"count below its minimum",
       [](json& d) { d["solver"] = json::parse(R"({"max_steps": -5})"); },
       "solver.max_steps: must be at least 1, found -5"},
      {"integer too large",
       [](json& d) { d["solver"]["max_steps"] = 3000000000u; },
       "solver.max_steps: integer 3000000000 is too large (at most 2147483647)"},
      {"integer too small",
       [](json& d) { d["solver"]["max_iterations"] = -3000000000LL; },
       "solver.max_iterations: integer -3000000000 is too small (at least -2147483648)"},
      {"sequencing word",
       [](json& d) { d["solver"] = json::parse(R"({"sequencing": "often"})"); },
       "solver.sequencing: must be \"auto\" or an integer ≥ 1 (1: off), found \"often\""},
      {"wall-clock limit of zero",
       [](json& d) { d["solver"] = json::parse(R"({"max_wall_s": 0})"); },
       "solver.max_wall_s: must be a number of seconds > 0, found 0"},

      // ---- sequencing (core/model/sequencing_check.cc, checked by the reader)
      {"sequencing two stages",
       [](json& d) {
         d["stages"].push_back(json::parse(R"({"name": "rest", "kind": "hold"})"));
         d["solver"]["sequencing"] = 2;
       },
       "solver.sequencing: sequencing 2 solves one stage of weight or loads; this scene has 2 "
       "stages"},
      {"sequencing a hold stage",
       [](json& d) {
         d["stages"] = json::parse(R"([{"name": "rest", "kind": "hold"}])");
         d["solver"]["sequencing"] = 2;
       },
       "solver.sequencing: sequencing 2 needs a stage that adds weight or loads: stage 'rest' "
       "moves or holds, and its end depends on the path"},
      {"sequencing a release",
       [](json& d) {
         AddGripper(d);
         d["stages"][0]["release"] = json::array({"hand"});
         d["solver"]["sequencing"] = 2;
       },
       "solver.sequencing: sequencing 2 cannot solve stage 'SW': it moves or releases something, "
       "and its end depends on the path"},
      {"sequencing with friction",
       [](json& d) {
         d["contact"] = json::parse(R"({"friction": 0.3})");
         d["solver"]["sequencing"] = 2;
       },
       "solver.sequencing: sequencing 2 needs contact without friction: with friction the drape's "
       "end depends on the path"},
      {"sequencing two parts",
       [](json& d) {
         MakeTwoParts(d);
         d["solver"]["sequencing"] = 2;
       },
       "solver.sequencing: sequencing 2 needs a fabric of one part; this one has 2"},
      {"sequencing a mesh by size",
       [](json& d) {
         d["fabric"]["mesh"] = json::parse(R"({"size": "1 cm"})");
         d["solver"]["sequencing"] = 2;
       },
       "solver.sequencing: sequencing 2 needs a rectangle meshed by element counts"},
      {"sequencing factor not dividing the mesh",
       [](json& d) { d["solver"]["sequencing"] = 4; },
       "solver.sequencing: 4 must divide the mesh's 8 × 1 elements and leave at least 2 each "
       "way"},
      {"sequencing factor not dividing the solved mesh",
       [](json& d) {
         d["fabric"]["mesh"]["elements"] = json::array({8, 4});
         d["solver"] = json::parse(R"({"sequencing": 2, "mesh_scale": 0.5})");
       },
       "solver.sequencing: 2 must divide the mesh's 4 × 2 elements and leave at least 2 each way "
       "(the mesh solved: fabric.mesh at solver.mesh_scale 0.5)"},
  };
  return cases;
}

// The cases whose message shows the value the edit typed, as the message
// shows it: a quantity or a word in the quotes the message puts around it, a
// bare number as JSON writes it.
struct TypedValue {
  const char* name;
  const char* shown;
};

constexpr TypedValue kTypedValues[] = {
    {"format version as a string", "\"1\""},
    {"unsupported format version", "version 2;"},
    {"stages not an array", "\"SW\""},
    {"outline not an object", "\"rectangle\""},
    {"fabric part not an object", "\"lower\""},
    {"rectangle size not an array", "\"20 cm\""},
    {"rectangle size of a negative bare number", "-0.2"},
    {"fractional element count", "80.5"},
    {"element count below 1", "-3"},
    {"more than 4 million elements", "3000"},
    {"negative imperfection amplitude", "\"-1 mm\""},
    {"negative imperfection seed", "found -1"},
    {"unit out of range", "\"1 um^60\""},
    {"unit exponent too large", "\"1 m^50*m^50\""},
    {"unit exponent not an integer", "\"1 m^x\""},
    {"unit exponent over 99", "\"1 m^100\""},
    {"unknown unit", "\"5 furlong\""},
    {"number in a unit", "\"1 2/cm\""},
    {"unit nested too deep",
     "\"1 (((((((((((((((((((((((((((((((((m)))))))))))))))))))))))))))))))))\""},
    {"unit missing a parenthesis", "\"1 (mm\""},
    {"unit ending in an operator", "\"0.5 mm/\""},
    {"two units without an operator", "\"0.5 mm mm\""},
    {"unexpected character in a unit", "\"0.5 mm)\""},
    {"number out of range", "\"1e400 mm\""},
    {"malformed number", "\"0.5.1 mm\""},
    {"quantity out of range in SI", "\"1e300 GPa\""},
    {"unit of the wrong dimension", "\"3 cm\""},
    {"quantity without a unit", "\"5\""},
    {"negative thickness", "\"-0.1 mm\""},
    {"thickness not a quantity", "found true"},
    {"poisson ratio as a string", "\"0.3\""},
    {"poisson ratio out of range", "found 0.7"},
    {"orthotropic nu12 out of range", "found 1.6"},
    {"angle with a typo of grain", "\"grian\""},
    {"grain of a rectangle", "\"grain\""},
    {"library material with a typo", "'cotton-twil'"},
    {"unknown library material", "'velvet'"},
    {"bending law not an object", "\"linear\""},
    {"moment unit of the wrong dimension", "\"cm\""},
    {"negative linear coefficient", "found -1.5"},
    {"curvatures not increasing", "found 1 after 1"},
    {"measured hysteresis without a file", "\"measured\""},
    {"negative hysteresis", "\"-0.1 gf*cm/cm\""},
    {"hysteresis with a typo of measured", "\"mesured\""},
    {"line of one point", "[0, 0]"},
    {"box with min above max", "\"1 cm\""},
    {"notch 0", "found 0"},
    {"negative node index", "found -1"},
    {"unknown part", "'top'"},
    {"name not a string", "number 7"},
    {"gripper named as a support", "'root'"},
    {"fixity with a typo", "'clmp'"},
    {"force given as a moment", "\"1 N*m\""},
    {"missing mesh file", "'/nonexistent/form.obj'"},
    {"negative mesh scale", "found -2"},
    {"box of negative height", "\"1 cm\""},
    {"box edge radius too large", "\"3 cm\""},
    {"penalty with a typo", "\"atuo\""},
    {"negative friction", "found -0.2"},
    {"self contact not a boolean", "\"yes\""},
    {"unknown stage kind", "'fall'"},
    {"initial increment above 1", "found 1.5"},
    {"moves in a gravity stage", "'gravity'"},
    {"angle not a quantity", "found true"},
    {"gravity stage of a weightless fabric", "is 0"},
    {"release of an unknown gripper", "'lifter'"},
    {"gripper released twice", "'hand'"},
    {"move of an unknown obstacle", "'table'"},
    {"obstacle moved twice", "'table'"},
    {"move of an unknown gripper", "'hadn'"},
    {"move of a released gripper", "'hand'"},
    {"gripper moved twice", "'hand'"},
    {"part of a fabric of one part", "'lower'"},
    {"two probes of one name", "'tip'"},
    {"unknown preset", "'fast'"},
    {"mesh scale out of range", "found 20"},
    {"tolerance out of range", "found 1.5"},
    {"count below its minimum", "found -5"},
    {"integer too large", "3000000000"},
    {"integer too small", "-3000000000"},
    {"sequencing word", "\"often\""},
    {"wall-clock limit of zero", "found 0"},
    {"sequencing two stages", "sequencing 2"},
    {"sequencing a hold stage", "sequencing 2"},
    {"sequencing a release", "sequencing 2"},
    {"sequencing with friction", "sequencing 2"},
    {"sequencing two parts", "sequencing 2"},
    {"sequencing a mesh by size", "sequencing 2"},
    {"sequencing factor not dividing the mesh", "4 must divide"},
    {"sequencing factor not dividing the solved mesh", "mesh_scale 0.5"},
};

// The value itself, as it stands in the scene: `shown` without the text
// around it in the message ("found 0.7" → 0.7) and without its quotes.
std::string BareValue(std::string shown) {
  for (const char* prefix : {"found ", "number ", "version ", "mesh_scale ", "is ", "sequencing "})
    if (shown.rfind(prefix, 0) == 0) shown.erase(0, std::string(prefix).size());
  if (auto space = shown.find(' '); space != std::string::npos && shown.front() != '"')
    shown.erase(space);  // "4 must divide" → 4
  if (!shown.empty() && shown.back() == ';') shown.pop_back();
  if (shown.size() >= 2 && (shown.front() == '"' || shown.front() == '\'') &&
      shown.back() == shown.front())
    shown = shown.substr(1, shown.size() - 2);
  return shown;
}

json Edited(const Case& c) {
  json doc = Minimal();
  c.edit(doc);
  return doc;
}

// The whole message ("key.path: text") of the SceneError reading `c` throws.
std::string MessageOf(const Case& c) {
  try {
    SceneFromJson(Edited(c), test::ScenesDir());
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SceneReaderErrors, TheStartingSceneIsValid) {
  EXPECT_NO_THROW(SceneFromJson(Minimal(), test::ScenesDir()));
  json doc = Minimal();
  AddLift(doc);
  AddTable(doc);
  EXPECT_NO_THROW(SceneFromJson(doc, test::ScenesDir()));
  doc = Minimal();
  MakeTwoParts(doc);
  EXPECT_NO_THROW(SceneFromJson(doc, test::ScenesDir()));
}

TEST(SceneReaderErrors, EachMistakeGivesItsWholeMessage) {
  for (const Case& c : Cases()) {
    SCOPED_TRACE(c.name);
    EXPECT_EQ(MessageOf(c), c.message);
  }
}

TEST(SceneReaderErrors, EachMessageNamesTheKeyAndTheValueAsTyped) {
  for (const Case& c : Cases()) {
    SCOPED_TRACE(c.name);
    const std::string message = MessageOf(c);
    // "key.path: text": a path, which has no space, before the first ": ".
    const auto colon = message.find(": ");
    ASSERT_NE(colon, std::string::npos) << message;
    EXPECT_GT(colon, 0u) << message;
    EXPECT_EQ(message.substr(0, colon).find(' '), std::string::npos) << message;
  }
  for (const TypedValue& typed : kTypedValues) {
    SCOPED_TRACE(typed.name);
    const auto c = std::find_if(Cases().begin(), Cases().end(), [&](const Case& c) {
      return std::string(c.name) == typed.name;
    });
    ASSERT_NE(c, Cases().end()) << "no case of this name";
    // The value is one the edit typed, and the message shows it.
    EXPECT_NE(Edited(*c).dump().find(BareValue(typed.shown)), std::string::npos)
        << BareValue(typed.shown);
    EXPECT_NE(MessageOf(*c).find(typed.shown), std::string::npos) << MessageOf(*c);
  }
}

// Mistakes found before there is a JSON document to walk: a key given twice
// (which nlohmann/json would silently drop), text that is not JSON, a number
// JSON cannot hold, a scene file that cannot be opened.
TEST(SceneReaderErrors, TextThatIsNotAValidDocumentIsNamedByKeyOrPosition) {
  struct TextCase {
    const char* name;
    const char* text;
    const char* message;
  };
  const TextCase cases[] = {
      {"a key twice",
       R"({"drape_scene": 1, "stages": [{"name": "a", "name": "b"}]})",
       "stages[0].name: key appears twice in the same object"},
      {"a trailing comma",
       R"({"drape_scene": 1,})",
       "line 1, column 19: not valid JSON: syntax error while parsing object key - unexpected "
       "'}'; expected string literal"},
      {"a number too large for a double",
       R"({"drape_scene": 1e999})",
       "not valid JSON: number overflow parsing '1e999'"},
  };
  for (const TextCase& c : cases) {
    SCOPED_TRACE(c.name);
    std::string message = "(no error)";
    try {
      ParseScene(c.text, test::ScenesDir());
    } catch (const SceneError& e) {
      message = e.what();
    }
    EXPECT_EQ(message, c.message);
  }
  std::string message = "(no error)";
  try {
    ReadScene("/nonexistent/scene.json");
  } catch (const SceneError& e) {
    message = e.what();
  }
  EXPECT_EQ(message, "cannot open scene file '/nonexistent/scene.json'");
}

}  // namespace
}  // namespace drape
