#include "core/fe/bending_slip.h"

namespace drape {

void CommitBendingSlip(const ShellModel& model, ShellState& state) {
  if (!model.section.friction) return;
  const int elements = model.mesh.ElementCount();
  if (state.bending_slip.empty()) state.bending_slip.assign(elements, ElementSlip::Zero());
#pragma omp parallel for schedule(static) if (elements >= 256)
  for (int e = 0; e < elements; ++e) {
    const auto curvatures = ElementBendingStrains(model, state, e);
    for (int p = 0; p < 4; ++p)
      UpdateSlip(*model.section.friction, curvatures[p], p, state.bending_slip[e]);
  }
}

}  // namespace drape
