#include "core/fe/bending_slip.h"

namespace drape {

void CommitBendingSlip(const ShellModel& model, ShellState& state) {
  if (!model.section.friction) return;
  const int elements = model.mesh.ElementCount();
  if (state.bending_slip.empty()) state.bending_slip.assign(elements, ElementSlip::Zero());
#pragma omp parallel for schedule(static) if (elements >= 256)
  for (int e = 0; e < elements; ++e) {
    NodeColumns x, t;
    for (int k = 0; k < 4; ++k) {
      const int node = model.mesh.quads(e, k);
      x.col(k) = state.positions.row(node).transpose();
      t.col(k) = state.Director(node);
    }
    const auto curvatures = BendingStrains(model.elements[e], x, t);
    for (int p = 0; p < 4; ++p)
      UpdateSlip(*model.section.friction, curvatures[p], p, state.bending_slip[e]);
  }
}

}  // namespace drape
