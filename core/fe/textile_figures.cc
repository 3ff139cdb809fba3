#include "core/fe/textile_figures.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

#include "core/fe/material_section.h"
#include "core/model/overloaded.h"
#include "core/model/string_format.h"

namespace drape {
namespace {

constexpr double kPerCm = 100.0;                    // 1/cm in 1/m
constexpr double kGfCmPerCm = 9.80665e-3;           // gf·cm/cm in N·m/m
constexpr double kGfCm2PerCm = 9.80665e-5;          // gf·cm²/cm in N·m²/m
constexpr double kGfPerCm = 0.980665;               // gf/cm in N/m
constexpr double kStandardGravity = 9.80665;        // m/s², weight to mass
constexpr double kDegree = std::numbers::pi / 180;  // rad
constexpr double kKesTensileLoad = 500;             // gf/cm, where KES-FB1 reads EMT

const char* LawName(const BendingLaw& law) {
  return std::visit(Overloaded{[](const LinearBending&) { return "linear"; },
                               [](const PolynomialBending&) { return "polynomial"; },
                               [](const CurveBending&) { return "curve"; }},
                    law);
}

// Membrane moduli [Pa]: warp, weft, in-plane shear, and ν (ν₁₂).
struct Moduli {
  double warp, weft, shear, poisson;
};
Moduli MembraneModuli(const Membrane& membrane) {
  return std::visit(
      Overloaded{[](const IsotropicMembrane& m) {
                   const double g = m.youngs_modulus / (2 * (1 + m.poisson_ratio));
                   return Moduli{m.youngs_modulus, m.youngs_modulus, g, m.poisson_ratio};
                 },
                 [](const OrthotropicMembrane& m) {
                   return Moduli{m.e1, m.e2, m.g12, m.nu12};
                 }},
      membrane);
}

}  // namespace

double KawabataB(const MomentCurvatureLaw& strip) {
  return (strip.Moment(1.5 * kPerCm) - strip.Moment(0.5 * kPerCm)) / kPerCm / kGfCm2PerCm;
}

double EmtPercent(double tensile_gf_per_cm) {
  return kKesTensileLoad / tensile_gf_per_cm * 100;
}

TextileFigures FiguresOf(const Material& m) {
  const double h = m.thickness;
  const Moduli e = MembraneModuli(m.membrane);
  TextileFigures f;
  f.thickness_mm = h * 1e3;
  f.weight_g_per_m2 = m.areal_weight / kStandardGravity * 1e3;
  f.membrane = std::holds_alternative<IsotropicMembrane>(m.membrane) ? "isotropic" : "orthotropic";
  f.tensile_warp = e.warp * h / kGfPerCm;
  f.tensile_weft = e.weft * h / kGfPerCm;
  f.shear = e.shear * h * kDegree / kGfPerCm;
  f.poisson_ratio = e.poisson;
  // The strip laws as the engine builds them (MakeMaterialSection): without a
  // weft law the warp law bends every direction.
  const BendingLaw& weft_law = m.bending.weft ? *m.bending.weft : m.bending.warp;
  const auto warp = MakeStripLaw(m.bending.warp, e.warp * h * h * h / 12, "material.bending");
  const auto weft = m.bending.weft
                        ? MakeStripLaw(weft_law, e.weft * h * h * h / 12, "material.bending.weft")
                        : warp;
  f.bending_warp = KawabataB(*warp);
  f.bending_weft = KawabataB(*weft);
  f.hysteresis_warp = m.bending.warp_hysteresis.width / kGfCmPerCm;
  f.hysteresis_weft =
      (m.bending.weft ? m.bending.weft_hysteresis : m.bending.warp_hysteresis).width / kGfCmPerCm;
  f.bending_warp_law = LawName(m.bending.warp);
  f.bending_weft_law = LawName(weft_law);
  return f;
}

Material MaterialFromSummary(const FabricSummary& s) {
  const std::pair<double, const char*> figures[] = {
      {s.thickness_mm, "the thickness T"},
      {s.weight_g_per_m2, "the weight W"},
      {s.bending_warp, "the warp's B"},
      {s.bending_weft, "the weft's B"},
      {s.shear, "the shear rigidity G"},
      {s.tensile_warp, "the warp's stretch stiffness"},
      {s.tensile_weft, "the weft's stretch stiffness"}};
  for (const auto& [value, name] : figures)
    if (!(value > 0) || !std::isfinite(value))
      throw std::invalid_argument(std::string(name) + " must be greater than zero, found " +
                                  Format("%g", value));
  Material m;
  m.thickness = s.thickness_mm * 1e-3;
  m.areal_weight = s.weight_g_per_m2 * 1e-3 * kStandardGravity;
  const double h = m.thickness;
  m.membrane = OrthotropicMembrane{s.tensile_warp * kGfPerCm / h,
                                   s.tensile_weft * kGfPerCm / h,
                                   s.poisson_ratio,
                                   s.shear * kGfPerCm / (h * kDegree)};
  m.bending.warp = LinearBending{s.bending_warp * kGfCm2PerCm};
  if (s.bending_weft != s.bending_warp)
    m.bending.weft = LinearBending{s.bending_weft * kGfCm2PerCm};
  return m;
}

}  // namespace drape
