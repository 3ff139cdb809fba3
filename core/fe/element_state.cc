#include "core/fe/element_state.h"

#include "core/mechanics/director.h"

namespace drape {

ShellElementState ElementStateOf(const ShellModel& model, const ShellState& state, int e) {
  ShellElementState element;
  for (int k = 0; k < 4; ++k) {
    const int node = model.mesh.quads(e, k);
    element.positions.col(k) = state.positions.row(node).transpose();
    element.directors.col(k) = state.rotations[node].col(2);
    element.director_tangents[k] = DirectorTangent(state.rotations[node]);
  }
  return element;
}

}  // namespace drape
