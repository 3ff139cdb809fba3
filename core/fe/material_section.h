// From the scene's material to the shell section law the elements evaluate:
// the membrane (isotropic or orthotropic), the bending law of the plate
// (plate_bending_law.h) built on the strip laws the scene gives, and what a
// user should be warned of (a measured law that softens inside its range).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/mechanics/moment_curvature.h"
#include "core/mechanics/shell_section.h"
#include "core/model/scene.h"

namespace drape {

struct MaterialSection {
  ShellSection section;
  // |K| up to which every bending law is data or fit [1/m]; infinity when
  // all laws are linear.
  double bending_valid_to = 0;
  std::vector<std::string> warnings;  // each names its key
};

// The strip law M(K) of a scene's bending law; `default_rigidity` B [N·m²/m]
// serves a linear law that gives none. Throws SceneError at `where` for a
// law that cannot be built or whose initial stiffness is not positive.
std::shared_ptr<const MomentCurvatureLaw> MakeStripLaw(const BendingLaw& law,
                                                       double default_rigidity,
                                                       const std::string& where);

// Without a weft law, one law bends every direction (MakeIsotropicPlateLaw,
// with the membrane's ν or ν₁₂); with one, warp and weft bend by their own
// (MakeWarpWeftPlateLaw). Linear laws default to E h³/12 (E₁, E₂ for warp and
// weft of an orthotropic membrane). Throws SceneError naming the key.
MaterialSection MakeMaterialSection(const Material& material);

}  // namespace drape
