#include "core/fe/material_section.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <variant>

#include "core/model/overloaded.h"
#include "core/model/scene_error.h"

namespace drape {
namespace {

bool IsLinear(const BendingLaw& law) {
  return std::holds_alternative<LinearBending>(law);
}

std::string Format(const char* format, double a, double b) {
  char text[128];
  std::snprintf(text, sizeof text, format, a, b);
  return text;
}

// A measured law may turn down inside its range (a fifth-order fit often
// does): the drape is then not unique there. Said, not refused.
void WarnOfSoftening(const MomentCurvatureLaw& law,
                     const std::string& where,
                     std::vector<std::string>& warnings) {
  for (const auto& [from, to] : NegativeStiffnessIntervals(law)) {
    if (to <= 0) continue;  // odd laws: the mirrored interval says it again
    warnings.push_back(where + ": the moment falls with curvature (dM/dK < 0) for K from " +
                       Format("%.4g to %.4g 1/cm", std::max(from, 0.0) / 100, to / 100) +
                       " inside the law's valid range; drapes bent that far may not be unique");
  }
}

struct MembraneParts {
  Eigen::Matrix3d stiffness;  // C [Pa]
  double poisson_ratio = 0;   // ν, or ν₁₂, for an isotropic bending law
  double e_warp = 0, e_weft = 0;
  ShellSection section;  // membrane and transverse shear filled
};

MembraneParts MakeMembrane(const Material& material) {
  const double h = material.thickness;
  return std::visit(Overloaded{
                        [&](const IsotropicMembrane& m) {
                          MembraneParts parts;
                          parts.section = IsotropicSection(m.youngs_modulus, m.poisson_ratio, h);
                          parts.poisson_ratio = m.poisson_ratio;
                          parts.e_warp = parts.e_weft = m.youngs_modulus;
                          return parts;
                        },
                        [&](const OrthotropicMembrane& m) {
                          // Positive definite: 1 − ν₁₂ν₂₁ > 0 with ν₂₁ = ν₁₂E₂/E₁.
                          if (!(m.nu12 * m.nu12 < m.e1 / m.e2))
                            throw SceneError(
                                "material.membrane.nu12",
                                Format("nu12 = %.4g is too large: an orthotropic membrane needs "
                                       "nu12^2 < E1/E2 = %.4g to store energy under every strain",
                                       m.nu12,
                                       m.e1 / m.e2));
                          MembraneParts parts;
                          parts.section = OrthotropicSection(m.e1, m.e2, m.nu12, m.g12, h);
                          parts.poisson_ratio = m.nu12;
                          parts.e_warp = m.e1;
                          parts.e_weft = m.e2;
                          return parts;
                        },
                    },
                    material.membrane);
}

}  // namespace

std::shared_ptr<const MomentCurvatureLaw> MakeStripLaw(const BendingLaw& law,
                                                       double default_rigidity,
                                                       const std::string& where) {
  std::shared_ptr<const MomentCurvatureLaw> strip;
  try {
    strip = std::visit(
        Overloaded{
            [&](const LinearBending& l) {
              return std::shared_ptr<const MomentCurvatureLaw>(
                  MakeLinearLaw(l.rigidity.value_or(default_rigidity)));
            },
            [&](const PolynomialBending& l) {
              return std::shared_ptr<const MomentCurvatureLaw>(
                  MakePolynomialLaw(l.coefficients, l.valid_to));
            },
            [&](const CurveBending& l) {
              std::vector<std::array<double, 2>> points;
              for (const auto& p : l.points) points.push_back({p[0], p[1]});
              return std::shared_ptr<const MomentCurvatureLaw>(MakeCurveLaw(std::move(points)));
            },
        },
        law);
  } catch (const std::invalid_argument& e) {
    throw SceneError(where, e.what());
  }
  if (!(strip->Stiffness(0.0) > 0))
    throw SceneError(where,
                     "the bending law's stiffness dM/dK at K = 0 is not positive: a flat sheet "
                     "would have no bending stiffness");
  return strip;
}

namespace {

// The frictional moment of the laws' hysteresis (2HB), on the norms their
// plate law bends them by; null when no law has one.
std::shared_ptr<const BendingFriction> MakeFriction(const Bending& b, double poisson_ratio) {
  auto friction = std::make_shared<BendingFriction>();
  if (!b.weft) {
    if (b.warp_hysteresis.width > 0)
      friction->families.push_back(
          MakeFrictionFamily(IsotropicCurvatureMetric(poisson_ratio), b.warp_hysteresis.width));
  } else {
    for (int family : {0, 1}) {
      const double width = (family == 0 ? b.warp_hysteresis : b.weft_hysteresis).width;
      if (width > 0)
        friction->families.push_back(MakeFrictionFamily(YarnCurvatureMetric(family), width));
    }
  }
  if (friction->families.empty()) return nullptr;
  return friction;
}

}  // namespace

MaterialSection MakeMaterialSection(const Material& material) {
  const double h = material.thickness;
  MembraneParts membrane = MakeMembrane(material);
  MaterialSection result;
  result.section = membrane.section;
  result.bending_valid_to = std::numeric_limits<double>::infinity();

  const Bending& bending = material.bending;
  const bool linear = IsLinear(bending.warp) && (!bending.weft || IsLinear(*bending.weft));
  const std::string warp_key = bending.weft ? "material.bending.warp" : "material.bending";
  auto warp = MakeStripLaw(bending.warp, membrane.e_warp * h * h * h / 12, warp_key);
  std::shared_ptr<const MomentCurvatureLaw> weft;
  if (bending.weft)
    weft = MakeStripLaw(*bending.weft, membrane.e_weft * h * h * h / 12, "material.bending.weft");

  std::shared_ptr<const PlateBendingLaw> plate;
  if (weft)
    plate = MakeWarpWeftPlateLaw(warp, weft);
  else
    plate = MakeIsotropicPlateLaw(warp, membrane.poisson_ratio);
  result.section.bending = plate->InitialTangent();
  if (!linear) result.section.bending_law = plate;

  result.section.friction = MakeFriction(bending, membrane.poisson_ratio);

  for (const auto& [law, key] :
       {std::pair{warp, warp_key}, std::pair{weft, std::string("material.bending.weft")}}) {
    if (!law) continue;
    result.bending_valid_to = std::min(result.bending_valid_to, law->ValidTo());
    WarnOfSoftening(*law, key, result.warnings);
  }
  return result;
}

}  // namespace drape
