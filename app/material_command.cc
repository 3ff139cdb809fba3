// `drape material fit FILE [--degree N] [--branch B] [--json]`: the paper's
// polynomial bending law fitted to Kawabata data, in the textile units KES
// reports (gf·cm/cm against 1/cm). With --json, a `bending` object ready to
// paste into a scene, plus the fit's RMS error and curvature range.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/commands.h"
#include "core/io/kawabata_reader.h"
#include "core/mechanics/moment_curvature_fit.h"

namespace drape::app {
namespace {

constexpr double kPerCm = 100.0;           // 1/cm in 1/m
constexpr double kGfCmPerCm = 9.80665e-3;  // gf·cm/cm in N·m/m

struct FitArgs {
  std::string file;
  int degree = 5;
  std::string branch = "average";
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
  for (const auto& w : curve.warnings) std::printf("warning: %s\n", w.c_str());
}

int RunFit(const FitArgs& args) {
  const KawabataBranch branch = args.branch == "loading"     ? KawabataBranch::kLoading
                                : args.branch == "unloading" ? KawabataBranch::kUnloading
                                                             : KawabataBranch::kAverage;
  try {
    KawabataOptions options;
    options.branch = branch;
    const KawabataCurve curve = ReadKawabata(args.file, options);
    std::vector<double> k, m;
    for (size_t i = 0; i < curve.curvature.size(); ++i) {
      k.push_back(curve.curvature[i] / kPerCm);
      m.push_back(curve.moment[i] / kGfCmPerCm);
    }
    const PolynomialFit fit = FitOddPolynomial(k, m, args.degree);
    if (!args.json) {
      PrintReport(args, curve, fit, branch);
      return 0;
    }
    char valid_to[64];
    std::snprintf(valid_to, sizeof valid_to, "%.6g 1/cm", fit.valid_to);
    const nlohmann::ordered_json out{{"model", "polynomial"},
                                     {"coefficients", fit.coefficients},
                                     {"moment_unit", "gf*cm/cm"},
                                     {"curvature_unit", "1/cm"},
                                     {"valid_to", valid_to},
                                     {"rms_error", fit.rms_error},
                                     {"range", fit.range}};
    std::cout << out.dump(2) << "\n";
    for (const auto& w : curve.warnings) std::cerr << "warning: " << w << "\n";
    return 0;
  } catch (const KawabataError& e) {
    std::cerr << "drape material fit: " << e.what() << "\n";
  } catch (const std::invalid_argument& e) {
    std::cerr << "drape material fit: " << args.file << ": " << e.what() << "\n";
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
  fit->add_option("--degree", args->degree, "Number of coefficients c_1..c_n (1 to 9)")
      ->check(CLI::Range(1, 9))
      ->capture_default_str();
  fit->add_option("--branch", args->branch, "Which data to fit")
      ->check(CLI::IsMember({"average", "loading", "unloading"}))
      ->capture_default_str();
  fit->add_flag("--json", args->json, "Print a scene-ready `bending` object as JSON");
  fit->callback([args, &runner] { runner = [args] { return RunFit(*args); }; });
}

}  // namespace drape::app
