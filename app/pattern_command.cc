// `drape pattern list FILE [--json]`: the pieces of a pattern file (DXF in
// the AAMA layout, ASTM D6673) as a scene would cut them — each piece's
// name, area, size, notches, drill holes, cut-outs, internal lines and
// grain line — so that a scene can name the piece and its marks. With
// --json, the same in SI (m, m², degrees).
//
// `drape pattern write SPEC.json -o FILE.dxf`: pieces described in JSON
// (lengths with units) written as DXF-AAMA, for pattern CAD to read.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "app/commands.h"
#include "core/io/dxf_pattern_reader.h"
#include "core/io/dxf_pattern_writer.h"
#include "core/io/pattern_spec.h"
#include "core/model/outline_geometry.h"
#include "core/model/scene_error.h"

namespace drape::app {
namespace {

struct PatternArgs {
  std::string file;
  bool json = false;
  std::string output;
};

Bounds2 Extent(const PatternPiece& piece) {
  return OutlineBounds(PolygonOutline{piece.boundary});
}

nlohmann::json AsJson(const DxfPattern& pattern) {
  nlohmann::json pieces = nlohmann::json::array();
  for (const PatternPiece& p : pattern.pieces) {
    const Bounds2 b = Extent(p);
    nlohmann::json piece{{"name", p.name},
                         {"area_m2", PieceArea(p)},
                         {"size_m", {b.max[0] - b.min[0], b.max[1] - b.min[1]}},
                         {"notches_m", p.notches},
                         {"drill_holes_m", p.drills},
                         {"cut_outs", p.holes.size()},
                         {"internal_lines", p.internal_lines.size()}};
    piece["grain_deg"] = p.grain ? nlohmann::json(GrainAngleDeg(p)) : nlohmann::json(nullptr);
    pieces.push_back(piece);
  }
  return {{"unit_m", pattern.unit}, {"unit_from", pattern.unit_source}, {"pieces", pieces}};
}

void PrintTable(const DxfPattern& pattern, const std::string& file) {
  std::printf("%s: %zu pieces (lengths from %s, 1 unit = %g mm)\n",
              file.c_str(),
              pattern.pieces.size(),
              pattern.unit_source.c_str(),
              pattern.unit * 1e3);
  std::printf("  %-16s %10s %16s %7s %6s %8s %10s  %s\n",
              "piece",
              "area",
              "size",
              "notches",
              "drills",
              "cut-outs",
              "int. lines",
              "grain");
  for (const PatternPiece& p : pattern.pieces) {
    const Bounds2 b = Extent(p);
    char size[32], grain[32] = "none";
    std::snprintf(size,
                  sizeof size,
                  "%.1f x %.1f cm",
                  (b.max[0] - b.min[0]) * 100,
                  (b.max[1] - b.min[1]) * 100);
    if (p.grain) std::snprintf(grain, sizeof grain, "%.2f deg", GrainAngleDeg(p));
    std::printf("  %-16s %7.1f cm² %16s %7zu %6zu %8zu %10zu  %s\n",
                p.name.c_str(),
                PieceArea(p) * 1e4,
                size,
                p.notches.size(),
                p.drills.size(),
                p.holes.size(),
                p.internal_lines.size(),
                grain);
  }
}

int RunList(const PatternArgs& args) {
  try {
    const DxfPattern pattern = ReadDxfPattern(args.file);
    if (args.json)
      std::cout << AsJson(pattern).dump(2) << "\n";
    else
      PrintTable(pattern, args.file);
    return 0;
  } catch (const DxfPatternError& e) {
    std::cerr << "drape pattern list: " << e.what() << "\n";
  }
  return 1;
}

int RunWrite(const PatternArgs& args) {
  try {
    const std::vector<PatternPiece> pieces = ReadPatternSpec(args.file);
    WriteDxfPattern(args.output, pieces);
    std::printf(
        "%s: %zu pieces written (DXF-AAMA, millimetres)\n", args.output.c_str(), pieces.size());
    return 0;
  } catch (const SceneError& e) {
    std::cerr << "drape pattern write: " << args.file << ": " << e.what() << "\n";
  } catch (const std::runtime_error& e) {
    std::cerr << "drape pattern write: " << e.what() << "\n";
  }
  return 1;
}

}  // namespace

void AddPatternCommand(CLI::App& app, CommandRunner& runner) {
  CLI::App* pattern = app.add_subcommand("pattern", "Work with pattern files (DXF-AAMA)");
  pattern->require_subcommand(1);
  auto args = std::make_shared<PatternArgs>();
  CLI::App* list = pattern->add_subcommand(
      "list", "The pieces of a pattern file: names, areas, notches, drill holes, grain lines");
  list->add_option("file", args->file, "A DXF in the AAMA layout (ASTM D6673)")->required();
  list->add_flag("--json", args->json, "The same in SI, as JSON");
  list->callback([args, &runner] { runner = [args] { return RunList(*args); }; });
  CLI::App* write = pattern->add_subcommand(
      "write", "Write pieces described in JSON (a drape_pattern file) as DXF-AAMA");
  write->add_option("spec", args->file, "The pieces, in JSON (docs/format.md §9)")->required();
  write->add_option("-o,--output", args->output, "The DXF file to write")->required();
  write->callback([args, &runner] { runner = [args] { return RunWrite(*args); }; });
}

}  // namespace drape::app
