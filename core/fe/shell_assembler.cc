#include "core/fe/shell_assembler.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "core/fe/element_state.h"

namespace drape {
namespace {

// Greedy colouring: an element takes the smallest colour not used by any
// element sharing one of its nodes. Structured meshes need 4 colours.
std::vector<std::vector<int>> ColorElements(const Mesh& mesh) {
  std::vector<std::uint64_t> used(mesh.NodeCount(), 0);  // colours seen at each node
  std::vector<std::vector<int>> colors;
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    std::uint64_t taken = 0;
    for (int k = 0; k < 4; ++k) taken |= used[mesh.quads(e, k)];
    int c = 0;
    while (c < 64 && (taken >> c) & 1u) ++c;
    if (c == 64) throw std::runtime_error("element colouring needs more than 64 colours");
    if (c >= static_cast<int>(colors.size())) colors.resize(c + 1);
    colors[c].push_back(e);
    for (int k = 0; k < 4; ++k) used[mesh.quads(e, k)] |= std::uint64_t{1} << c;
  }
  return colors;
}

int GlobalDof(const Mesh& mesh, int element, int local) {
  return kDofsPerNode * mesh.quads(element, local / kDofsPerNode) + local % kDofsPerNode;
}

}  // namespace

ShellAssembler::ShellAssembler(const ShellModel& model,
                               const DofMap& dofs,
                               const std::vector<std::pair<int, int>>& coupled)
    : model_(model), dofs_(dofs) {
  const Mesh& mesh = model.mesh;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(mesh.ElementCount()) * kUpperPairs);
  for (int e = 0; e < mesh.ElementCount(); ++e)
    for (int a = 0; a < 20; ++a)
      for (int b = a; b < 20; ++b) {
        int fa = dofs.Free(GlobalDof(mesh, e, a)), fb = dofs.Free(GlobalDof(mesh, e, b));
        if (fa >= 0 && fb >= 0) entries.emplace_back(std::min(fa, fb), std::max(fa, fb), 0.0);
      }
  for (const auto& [i, j] : coupled)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const int fa = dofs.Free(kDofsPerNode * i + a), fb = dofs.Free(kDofsPerNode * j + b);
        if (fa >= 0 && fb >= 0) entries.emplace_back(std::min(fa, fb), std::max(fa, fb), 0.0);
      }
  pattern_.resize(dofs.FreeCount(), dofs.FreeCount());
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();

  slots_.assign(static_cast<size_t>(mesh.ElementCount()) * kUpperPairs, -1);
  const int* outer = pattern_.outerIndexPtr();
  const int* inner = pattern_.innerIndexPtr();
  for (int e = 0; e < mesh.ElementCount(); ++e) {
    int pair = 0;
    for (int a = 0; a < 20; ++a)
      for (int b = a; b < 20; ++b, ++pair) {
        int fa = dofs.Free(GlobalDof(mesh, e, a)), fb = dofs.Free(GlobalDof(mesh, e, b));
        if (fa < 0 || fb < 0) continue;
        const int row = std::min(fa, fb), col = std::max(fa, fb);
        const int* at = std::lower_bound(inner + outer[col], inner + outer[col + 1], row);
        slots_[static_cast<size_t>(e) * kUpperPairs + pair] = static_cast<int>(at - inner);
      }
  }
  colors_ = ColorElements(mesh);
}

double ShellAssembler::Assemble(const ShellState& state,
                                Eigen::VectorXd& internal,
                                Eigen::SparseMatrix<double>* tangent,
                                const Eigen::VectorXd* velocity,
                                Eigen::VectorXd* rate) const {
  const Mesh& mesh = model_.mesh;
  internal.setZero(model_.DofCount());
  const bool want_rate = tangent && velocity && rate;
  if (want_rate) rate->setZero(model_.DofCount());
  double* values = nullptr;
  if (tangent) {
    tangent->coeffs().setZero();
    values = tangent->valuePtr();
  }
  const ElementOutput output = tangent ? ElementOutput::kHessian : ElementOutput::kGradient;
  if (!state.bending_slip.empty() &&
      state.bending_slip.size() != static_cast<size_t>(mesh.ElementCount()))
    throw std::invalid_argument("ShellAssembler: the state's bending slip is of another mesh");
  double energy = 0;
  for (const auto& color : colors_) {
    const int count = static_cast<int>(color.size());
    // Threads only pay off with enough elements per colour; on a loaded
    // machine a parallel region over a handful of elements stalls.
#pragma omp parallel for schedule(static) reduction(+ : energy) if (count >= 64)
    for (int c = 0; c < count; ++c) {
      const int e = color[c];
      const ShellElementState element = ElementStateOf(model_, state, e);
      ElementEnergy result;
      const ElementSlip* slip = state.bending_slip.empty() ? nullptr : &state.bending_slip[e];
      EvaluateShellElement(model_.elements[e], model_.section, element, output, result, slip);
      energy += result.value;
      for (int k = 0; k < 4; ++k)
        internal.segment<kDofsPerNode>(kDofsPerNode * mesh.quads(e, k)) +=
            result.gradient.segment<kDofsPerNode>(kDofsPerNode * k);
      if (want_rate) {
        ElementVector v;
        for (int k = 0; k < 4; ++k)
          v.segment<kDofsPerNode>(kDofsPerNode * k) =
              velocity->segment<kDofsPerNode>(kDofsPerNode * mesh.quads(e, k));
        if (!v.isZero(0.0)) {
          const ElementVector kv = result.hessian * v;
          for (int k = 0; k < 4; ++k)
            rate->segment<kDofsPerNode>(kDofsPerNode * mesh.quads(e, k)) +=
                kv.segment<kDofsPerNode>(kDofsPerNode * k);
        }
      }
      if (!values) continue;
      const int* slot = slots_.data() + static_cast<size_t>(e) * kUpperPairs;
      for (int a = 0; a < 20; ++a)
        for (int b = a; b < 20; ++b, ++slot)
          if (*slot >= 0) values[*slot] += result.hessian(a, b);
    }
  }
  return energy;
}

}  // namespace drape
