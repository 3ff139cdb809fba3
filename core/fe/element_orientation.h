// Physical states only: an element turned inside out — its surface folded
// through itself, (φ,₁ × φ,₂)·t ≤ 0 at a Gauss point — is no state a part
// can be in, although its strains and energy look ordinary. The Newton
// corrector refuses to converge there (newton_corrector.h), so a step that
// would end inverted is cut back.
#pragma once

#include <optional>
#include <string>

#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"

namespace drape {

struct InvertedElement {
  int element = -1;
  int gauss_point = -1;
  double ratio = 0;  // (φ,₁ × φ,₂)·t over its reference value there (≤ 0)
};

// The first element, in mesh order, with a Gauss point at or below zero
// oriented area (OrientedAreaRatios); nullopt when none is.
std::optional<InvertedElement> FindInvertedElement(const ShellModel& model,
                                                   const ShellState& state);

// "element 12 (nodes 3, 4, 15, 14) is turned inside out (oriented area
// −0.31 of its reference at Gauss point 2)".
std::string Describe(const InvertedElement& inverted, const ShellModel& model);

}  // namespace drape
