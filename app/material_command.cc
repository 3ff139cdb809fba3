// `drape material fit FILE [--model polynomial|spline] [--degree N]
// [--knots N] [--branch B] [--json]`: the paper's polynomial bending law, or
// a monotone spline, fitted to Kawabata data in the textile units KES
// reports (gf·cm/cm against 1/cm). With --json, a `bending` object ready to
// paste into a scene, plus the fit's RMS error and curvature range. A fit
// that softens (dM/dK < 0) inside its range is warned of.
//
// `drape material list [--json]`: the library materials a scene can name.
//
// `drape material show NAME [--json]`: a library entry as the engine would
// take it, in the textile units KES and FAST report: the entry is read through
// the scene reader (a scene naming it as its material) and its SI numbers are
// converted back, so that the printed figures can be held against the table
// the entry cites.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "app/commands.h"
#include "core/fe/material_section.h"
#include "core/fe/textile_figures.h"
#include "core/io/kawabata_reader.h"
#include "core/io/library_fabric.h"
#include "core/io/material_library.h"
#include "core/io/scene_reader.h"
#include "core/mechanics/moment_curvature.h"
#include "core/mechanics/moment_curvature_fit.h"
#include "core/model/overloaded.h"
#include "core/model/scene_error.h"

namespace drape::app {
namespace {

constexpr double kPerCm = 100.0;           // 1/cm in 1/m
constexpr double kGfCmPerCm = 9.80665e-3;  // gf·cm/cm in N·m/m

struct FitArgs {
  std::string file;
  std::string model = "polynomial";
  int degree = 5;
  int knots = 20;
  std::string branch = "average";
  std::string curvature_column, moment_column;
  bool json = false;
};

const char* BranchName(KawabataBranch b) {
  switch (b) {
    case KawabataBranch::kLoading:
      return "loading branch";
    case KawabataBranch::kUnloading:
      return "unloading branch";
    default:
      return "average of loading and unloading";
  }
}

void PrintReport(const FitArgs& args,
                 const KawabataCurve& curve,
                 const PolynomialFit& fit,
                 KawabataBranch branch) {
  std::printf("%s: %zu points, K from %.4g to %.4g 1/cm (%s)\n",
              args.file.c_str(),
              curve.curvature.size(),
              fit.range[0],
              fit.range[1],
              BranchName(branch));
  std::printf("M = sign(K) * sum c_k |K|^k   [M in gf*cm/cm, K in 1/cm], degree %d\n", args.degree);
  for (size_t k = 0; k < fit.coefficients.size(); ++k)
    std::printf("  c%zu = %.6g\n", k + 1, fit.coefficients[k]);
  std::printf("rms error %.3g gf*cm/cm; valid to %.4g 1/cm\n", fit.rms_error, fit.valid_to);
}

void PrintSplineReport(const FitArgs& args,
                       const KawabataCurve& curve,
                       const CurveFit& fit,
                       KawabataBranch branch) {
  std::printf("%s: %zu points, K from %.4g to %.4g 1/cm (%s)\n",
              args.file.c_str(),
              curve.curvature.size(),
              fit.range[0],
              fit.range[1],
              BranchName(branch));
  std::printf("monotone spline through %zu knots [K in 1/cm, M in gf*cm/cm]:\n", fit.points.size());
  for (const auto& p : fit.points) std::printf("  %8.4f  %10.6f\n", p[0], p[1]);
  std::printf("rms error %.3g gf*cm/cm; valid to %.4g 1/cm\n", fit.rms_error, fit.valid_to);
}

// Where the fitted law's moment falls with curvature inside its range.
std::vector<std::string> SofteningWarnings(const MomentCurvatureLaw& law) {
  std::vector<std::string> warnings;
  for (const auto& [from, to] : NegativeStiffnessIntervals(law)) {
    if (to <= 0) continue;  // the mirrored interval of an odd law
    char text[160];
    std::snprintf(text,
                  sizeof text,
                  "the fitted moment falls with curvature (dM/dK < 0) for K from %.4g to %.4g "
                  "1/cm; try a lower degree or the spline",
                  std::max(from, 0.0),
                  to);
    warnings.push_back(text);
  }
  return warnings;
}

int RunFit(const FitArgs& args) {
  const KawabataBranch branch = args.branch == "loading"     ? KawabataBranch::kLoading
                                : args.branch == "unloading" ? KawabataBranch::kUnloading
                                                             : KawabataBranch::kAverage;
  try {
    KawabataOptions options;
    options.branch = branch;
    options.curvature_column = args.curvature_column;
    options.moment_column = args.moment_column;
    const KawabataCurve curve = ReadKawabata(args.file, options);
    std::vector<double> k, m;
    for (size_t i = 0; i < curve.curvature.size(); ++i) {
      k.push_back(curve.curvature[i] / kPerCm);
      m.push_back(curve.moment[i] / kGfCmPerCm);
    }
    std::vector<std::string> warnings = curve.warnings;
    nlohmann::ordered_json out;
    if (args.model == "spline") {
      const CurveFit fit = FitMonotoneCurve(k, m, args.knots);
      if (!args.json) PrintSplineReport(args, curve, fit, branch);
      out = {{"model", "curve"},
             {"points", fit.points},
             {"moment_unit", "gf*cm/cm"},
             {"curvature_unit", "1/cm"},
             {"rms_error", fit.rms_error},
             {"range", fit.range}};
    } else {
      const PolynomialFit fit = FitOddPolynomial(k, m, args.degree);
      for (auto& w : SofteningWarnings(*MakePolynomialLaw(fit.coefficients, fit.valid_to)))
        warnings.push_back(std::move(w));
      if (!args.json) PrintReport(args, curve, fit, branch);
      char valid_to[64];
      std::snprintf(valid_to, sizeof valid_to, "%.6g 1/cm", fit.valid_to);
      out = {{"model", "polynomial"},
             {"coefficients", fit.coefficients},
             {"moment_unit", "gf*cm/cm"},
             {"curvature_unit", "1/cm"},
             {"valid_to", valid_to},
             {"rms_error", fit.rms_error},
             {"range", fit.range}};
    }
    if (args.json) std::cout << out.dump(2) << "\n";
    if (!args.json)
      std::printf("read %s and %s\n", curve.curvature_read.c_str(), curve.moment_read.c_str());
    // Warnings go to stderr with --json, so that stdout stays one document.
    for (const auto& w : warnings) (args.json ? std::cerr : std::cout) << "warning: " << w << "\n";
    return 0;
  } catch (const KawabataError& e) {
    std::cerr << "drape material fit: " << e.what() << "\n";
  } catch (const std::invalid_argument& e) {
    std::cerr << "drape material fit: " << args.file << ": " << e.what() << "\n";
  }
  return 1;
}

// The library as a scene in the working directory would see it.
int RunList(bool json) {
  const auto dirs = MaterialLibraryDirs(std::filesystem::current_path());
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  int status = 0;
  for (const auto& name : LibraryMaterialNames(dirs)) {
    try {
      const LibraryMaterial entry = ReadLibraryMaterial(*FindLibraryMaterial(name, dirs));
      if (json) {
        out.push_back({{"library", name},
                       {"name", entry.name},
                       {"source", entry.source},
                       {"file", entry.file.string()}});
      } else {
        std::printf("%-28s %s\n%-28s   source: %s\n",
                    name.c_str(),
                    entry.name.c_str(),
                    "",
                    entry.source.c_str());
      }
    } catch (const SceneError& e) {
      std::cerr << "drape material list: " << e.what() << "\n";
      status = 1;
    }
  }
  if (json) std::cout << out.dump(2) << "\n";
  return status;
}

// ---- material show --------------------------------------------------------

// A finite number, or JSON null (never NaN in the output).
nlohmann::ordered_json Finite(double value) {
  return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json FiguresJson(const std::string& library,
                                   const LibraryMaterial& entry,
                                   const TextileFigures& f) {
  return {{"library", library},
          {"name", entry.name},
          {"source", entry.source},
          {"file", entry.file.string()},
          {"thickness_mm", Finite(f.thickness_mm)},
          {"weight_g_per_m2", Finite(f.weight_g_per_m2)},
          {"bending_law_warp", f.bending_warp_law},
          {"bending_law_weft", f.bending_weft_law},
          {"bending_rigidity_warp_gf_cm2_per_cm", Finite(f.bending_warp)},
          {"bending_rigidity_weft_gf_cm2_per_cm", Finite(f.bending_weft)},
          {"bending_hysteresis_warp_gf_cm_per_cm", Finite(f.hysteresis_warp)},
          {"bending_hysteresis_weft_gf_cm_per_cm", Finite(f.hysteresis_weft)},
          {"membrane", f.membrane},
          {"shear_rigidity_gf_per_cm_deg", Finite(f.shear)},
          {"tensile_stiffness_warp_gf_per_cm", Finite(f.tensile_warp)},
          {"tensile_stiffness_weft_gf_per_cm", Finite(f.tensile_weft)},
          {"emt_warp_percent_at_500_gf_per_cm", Finite(EmtPercent(f.tensile_warp))},
          {"emt_weft_percent_at_500_gf_per_cm", Finite(EmtPercent(f.tensile_weft))},
          {"poisson_ratio", Finite(f.poisson_ratio)}};
}

void PrintFigures(const std::string& library,
                  const LibraryMaterial& entry,
                  const TextileFigures& f) {
  std::printf("%s: %s\n  source: %s\n  file: %s\n",
              library.c_str(),
              entry.name.c_str(),
              entry.source.c_str(),
              entry.file.string().c_str());
  std::printf("  thickness T                %.4g mm\n", f.thickness_mm);
  std::printf("  weight W                   %.4g g/m^2\n", f.weight_g_per_m2);
  const std::string laws = f.bending_warp_law == f.bending_weft_law
                               ? f.bending_warp_law + " law"
                               : "warp " + f.bending_warp_law + ", weft " + f.bending_weft_law;
  std::printf("  bending rigidity B         warp %.4g, weft %.4g gf*cm^2/cm (%s)\n",
              f.bending_warp,
              f.bending_weft,
              laws.c_str());
  std::printf("  bending hysteresis 2HB     warp %.4g, weft %.4g gf*cm/cm%s\n",
              f.hysteresis_warp,
              f.hysteresis_weft,
              f.hysteresis_warp > 0 || f.hysteresis_weft > 0 ? "" : " (none)");
  std::printf(
      "  shear rigidity G           %.4g gf/(cm*deg) (%s membrane)\n", f.shear, f.membrane.c_str());
  std::printf(
      "  tensile stiffness E*h      warp %.4g, weft %.4g gf/cm\n", f.tensile_warp, f.tensile_weft);
  std::printf("  EMT at 500 gf/cm (linear)  warp %.4g, weft %.4g %%\n",
              EmtPercent(f.tensile_warp),
              EmtPercent(f.tensile_weft));
  std::printf("  Poisson ratio              %.4g\n", f.poisson_ratio);
  std::printf(
      "B: the strip law's mean slope between K = 0.5 and 1.5 1/cm, as KES-FB2 reads it.\n"
      "2HB: the loop's width, modelled as a frictional moment +-HB (docs/bending.md).\n"
      "Not modelled: shear hysteresis (2HG) and the tensile curve's nonlinearity (LT).\n");
}

// The names a scene could use, for an unknown one.
std::string KnownNames(const std::vector<std::filesystem::path>& dirs) {
  std::string known;
  for (const auto& n : LibraryMaterialNames(dirs)) known += (known.empty() ? "" : ", ") + n;
  return known.empty() ? "none (no library found in " + dirs.front().string() + " …)" : known;
}

int RunShow(const std::string& name, bool json) {
  const auto dirs = MaterialLibraryDirs(std::filesystem::current_path());
  const std::optional<std::filesystem::path> file = FindLibraryMaterial(name, dirs);
  if (!file) {
    std::cerr << "drape material show: no library material '" << name
              << "'; the library has: " << KnownNames(dirs) << "\n";
    return 1;
  }
  try {
    const LibraryMaterial entry = ReadLibraryMaterial(*file);
    const TextileFigures figures = FiguresOf(LibraryFabric(name, std::filesystem::current_path()));
    if (json)
      std::cout << FiguresJson(name, entry, figures).dump(2) << "\n";
    else
      PrintFigures(name, entry, figures);
    return 0;
  } catch (const SceneError& e) {
    std::cerr << "drape material show: " << e.what() << "\n";
  }
  return 1;
}

}  // namespace

void AddMaterialCommand(CLI::App& app, CommandRunner& runner) {
  CLI::App* material = app.add_subcommand("material", "Work with fabric material data");
  material->require_subcommand(1);
  auto args = std::make_shared<FitArgs>();
  CLI::App* fit = material->add_subcommand(
      "fit", "Fit the bending law M = sign(K) sum c_k |K|^k to Kawabata (KES-FB2) data");
  fit->add_option("file", args->file, "Kawabata CSV/TSV file")->required();
  fit->add_option("--model", args->model, "The law to fit")
      ->check(CLI::IsMember({"polynomial", "spline"}))
      ->capture_default_str();
  fit->add_option("--degree", args->degree, "Polynomial: number of coefficients c_1..c_n (1 to 9)")
      ->check(CLI::Range(1, 9))
      ->capture_default_str();
  fit->add_option("--knots", args->knots, "Spline: number of knots (2 to 50)")
      ->check(CLI::Range(2, 50))
      ->capture_default_str();
  fit->add_option("--branch", args->branch, "Which data to fit")
      ->check(CLI::IsMember({"average", "loading", "unloading"}))
      ->capture_default_str();
  fit->add_option("--curvature-column",
                  args->curvature_column,
                  "Header name of the curvature column (default: found by name)");
  fit->add_option("--moment-column",
                  args->moment_column,
                  "Header name of the moment column (default: found by name)");
  fit->add_flag("--json", args->json, "Print a scene-ready `bending` object as JSON");
  fit->callback([args, &runner] { runner = [args] { return RunFit(*args); }; });

  auto list_json = std::make_shared<bool>(false);
  CLI::App* list = material->add_subcommand(
      "list", "List the library materials a scene can use as \"material\": {\"library\": NAME}");
  list->add_flag("--json", *list_json, "Print the list as JSON");
  list->callback([list_json, &runner] { runner = [list_json] { return RunList(*list_json); }; });

  auto show_name = std::make_shared<std::string>();
  auto show_json = std::make_shared<bool>(false);
  CLI::App* show = material->add_subcommand(
      "show", "Show a library material's figures in textile units (KES/FAST), as a scene reads it");
  show->add_option("name", *show_name, "Library material name (see `drape material list`)")
      ->required();
  show->add_flag("--json", *show_json, "Print the figures as JSON");
  show->callback([show_name, show_json, &runner] {
    runner = [show_name, show_json] { return RunShow(*show_name, *show_json); };
  });
}

}  // namespace drape::app
