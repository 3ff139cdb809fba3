// Values no real fabric has. They are most often a unit that slipped — a
// thickness typed "0.5" is read as 0.5 m — so each is named with its key,
// the value as read, the range fabrics have, and the value the likely slip
// meant. Not errors: a scene may model something that is not a fabric.
#pragma once

#include <string>
#include <vector>

#include "core/model/scene.h"

namespace drape {

struct Implausible {
  std::string key;           // "material.thickness"
  std::string quantity;      // "thickness"
  std::string read_as;       // the value as read, in the unit its range is given in: "0.5 m"
  std::string why;           // "thicker than any fabric (0.05–5 mm)"
  std::string did_you_mean;  // "0.5 mm", or "" when no single slip explains it
};

// Ranges (woven, knitted and nonwoven apparel fabrics, KES-FB and FAST
// data): thickness 0.05–5 mm; weight 20–1 000 g/m²; bending length
// c = (B/w)^⅓ 0.3–15 cm (B the warp's initial bending rigidity, w the
// weight per area; the cantilever's bending length of BS 3356 / ASTM D1388).
std::vector<Implausible> ImplausibleFabric(const Material& material);

// "material.thickness: 0.5 m is thicker than any fabric (0.05–5 mm); did you mean 0.5 mm?"
std::string Describe(const Implausible& implausible);

}  // namespace drape
