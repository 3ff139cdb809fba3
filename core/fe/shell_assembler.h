// Assembly of the shell's energy, internal force and tangent stiffness
// (MFEM's NonlinearForm: GetEnergy, Mult, GetGradient in one pass).
//
// The sparse pattern of the tangent (upper triangle over the free DOFs) and
// each element's slots in it are built once per model. Elements are coloured
// so that no two of one colour share a node; each colour is assembled in
// parallel with no locks.
#pragma once

#include <Eigen/SparseCore>

#include <utility>
#include <vector>

#include "core/fe/dof_map.h"
#include "core/fe/shell_model.h"
#include "core/fe/shell_state.h"

namespace drape {

class ShellAssembler {
 public:
  // `coupled`: node pairs beyond the elements' whose translations the
  // tangent's pattern couples too (self-contact between layers).
  ShellAssembler(const ShellModel& model,
                 const DofMap& dofs,
                 const std::vector<std::pair<int, int>>& coupled = {});

  // Energy [J]; `internal` (5 per node, all DOFs) receives ∂E/∂q; when
  // `tangent` is given (it must have Pattern()'s structure) its values are
  // replaced by the upper triangle of ∂²E/∂q² over the free DOFs.
  //
  // With `velocity` (5 per node: how fast the prescribed DOFs move with λ,
  // zero elsewhere) and a tangent, `rate` receives ∂F_int/∂λ = K v over all
  // DOFs: the paper's ∂P/∂λ for prescribed motion, exact (from the element
  // Hessians) rather than by differencing.
  double Assemble(const ShellState& state,
                  Eigen::VectorXd& internal,
                  Eigen::SparseMatrix<double>* tangent,
                  const Eigen::VectorXd* velocity = nullptr,
                  Eigen::VectorXd* rate = nullptr) const;

  // The tangent's structure, values zero.
  const Eigen::SparseMatrix<double>& Pattern() const { return pattern_; }
  int ColorCount() const { return static_cast<int>(colors_.size()); }

 private:
  static constexpr int kUpperPairs = 20 * 21 / 2;

  const ShellModel& model_;
  const DofMap& dofs_;
  Eigen::SparseMatrix<double> pattern_;
  std::vector<std::vector<int>> colors_;  // element indices per colour
  std::vector<int> slots_;                // per element, kUpperPairs value indices or −1
};

}  // namespace drape
