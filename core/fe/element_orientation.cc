#include "core/fe/element_orientation.h"

#include "core/mechanics/shell_element.h"
#include "core/model/string_format.h"

namespace drape {

std::optional<InvertedElement> FindInvertedElement(const ShellModel& model,
                                                   const ShellState& state) {
  NodeColumns x, t;
  for (int e = 0; e < model.mesh.ElementCount(); ++e) {
    for (int k = 0; k < 4; ++k) {
      const int node = model.mesh.quads(e, k);
      x.col(k) = state.positions.row(node).transpose();
      t.col(k) = state.Director(node);
    }
    const std::array<double, 4> ratios = OrientedAreaRatios(model.elements[e], x, t);
    for (int p = 0; p < 4; ++p)
      // Not `<= 0`: a NaN is no orientation either.
      if (!(ratios[p] > 0)) return InvertedElement{e, p, ratios[p]};
  }
  return std::nullopt;
}

std::string Describe(const InvertedElement& inverted, const ShellModel& model) {
  const auto quad = model.mesh.quads.row(inverted.element);
  return Format(
      "element %d (nodes %d, %d, %d, %d) is turned inside out (oriented area %.3g of "
      "its reference at Gauss point %d)",
      inverted.element,
      quad(0),
      quad(1),
      quad(2),
      quad(3),
      inverted.ratio,
      inverted.gauss_point + 1);
}

}  // namespace drape
