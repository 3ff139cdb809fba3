// The discrete equilibrium equations R(q) = F_int(q) − F_ext = 0 over the free
// DOFs, with the tangent K = ∂R/∂q factorised for Newton and continuation
// steps. Owns the assembly buffers and the factorisation (analysed once).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <utility>
#include <vector>

#include "core/contact/node_contact.h"
#include "core/contact/self_contact.h"
#include "core/fe/dof_map.h"
#include "core/fe/shell_assembler.h"
#include "core/fe/shell_model.h"
#include "core/linalg/critical_modes.h"
#include "core/linalg/sparse_cholesky.h"

namespace drape {

struct SystemTimers {
  double assembly_s = 0;
  double factorization_s = 0;
  double solve_s = 0;
  int factorizations = 0;
  int indefinite_factorizations = 0;
  int reused_factorizations = 0;  // asked for a matrix already factorised

  SystemTimers& operator+=(const SystemTimers& o) {
    assembly_s += o.assembly_s;
    factorization_s += o.factorization_s;
    solve_s += o.solve_s;
    factorizations += o.factorizations;
    indefinite_factorizations += o.indefinite_factorizations;
    reused_factorizations += o.reused_factorizations;
    return *this;
  }
};

class EquilibriumSystem {
 public:
  // `contact` (may be null: no obstacles, no contact code runs) must
  // outlive the system.
  EquilibriumSystem(const ShellModel& model,
                    const DofMap& dofs,
                    const NodeContact* contact = nullptr);

  // Self-contact between the fabric's layers (may be null; must outlive the
  // system): its barrier joins the energy, force and tangent, whose pattern
  // grows (and is analysed again) when layers come within reach of parts it
  // does not couple yet.
  void SetSelfContact(SelfContact* self_contact) { self_contact_ = self_contact; }

  // The largest fraction of a full increment (5 per node) that keeps the
  // layers apart and the fabric out of the obstacles (1 without
  // self-contact or a barrier).
  double StepBound(const ShellState& state, const Eigen::VectorXd& increment) const;
  // The same for the nodes moving from `state` by `motion` (one row per
  // node, held nodes' prescribed motion included).
  double StepBound(const ShellState& state, const Positions& motion) const;
  // Whether StepBound may cut a step: self-contact or a barrier contact.
  bool BoundsSteps() const {
    return self_contact_ != nullptr || (contact_ && contact_->HasBarrier());
  }

  // Assembles the internal force (and the tangent) at `state`; returns the
  // energy. With `velocity` (prescribed DOF rates, 5 per node) and the
  // tangent, also ∂F_int/∂λ = K v (InternalForceRate).
  double Assemble(const ShellState& state,
                  bool with_tangent,
                  const Eigen::VectorXd* velocity = nullptr);
  // The total potential energy at `state` under the loads `external` (full, 5
  // per node) [J]: strain energy, self-contact barrier and obstacle contact
  // (NodeContact::Energy), less the forces' work from the reference
  // positions, and the moments about loaded edges (their potential −M θ, θ
  // in (−π, π]); other moments act on the nodal bases and have none here.
  // Assembles the force (not the tangent) there.
  double PotentialEnergy(const ShellState& state, const Eigen::VectorXd& external);

  // The full internal force of the last assembly (5 per node).
  const Eigen::VectorXd& InternalForce() const { return internal_; }
  const Eigen::VectorXd& InternalForceRate() const { return rate_; }
  // ∂F_int/∂λ from obstacles moving along their paths (full, 5 per node).
  Eigen::VectorXd ObstacleForceRate(const ShellState& state,
                                    const std::vector<ObstacleMotion>& motions) const;
  // R = F_int − F_ext over the free DOFs, from the last assembly.
  Eigen::VectorXd Residual(const Eigen::VectorXd& external) const;

  // The force level of the last assembly: ‖F_ext‖ over the free DOFs plus
  // ‖F_int − F_ext‖ over the fixed ones (the reactions) [N]. What a residual
  // is small against when a step adds no load (grippers move, a hold).
  double ForceLevel(const Eigen::VectorXd& external) const;

  // The residual's round-off level at `state` [N]: ‖K δ‖ for the state's
  // coordinates each off by one rounding (δ = ε·max|x| on translations, ε on
  // rotations), from the last assembled tangent; root-sum-square over the
  // free DOFs. No Newton iteration can bring ‖R‖ reliably below it.
  double RoundOffLevel(const ShellState& state) const;

  // The diagonal of the last assembled tangent (free DOFs).
  Eigen::VectorXd TangentDiagonal() const;

  // Adds `shift` (free DOFs) to the diagonal of the last assembled tangent:
  // K + μD for the energy minimiser. The next assembly starts afresh.
  void ShiftTangentDiagonal(const Eigen::VectorXd& shift);

  // Factorises the last assembled tangent.
  FactorizationInfo Factorize();
  // K⁻¹ b with the last factorisation (free DOFs).
  Eigen::VectorXd Solve(const Eigen::VectorXd& b);

  const ShellModel& model() const { return model_; }
  const DofMap& dofs() const { return dofs_; }
  const SystemTimers& timers() const { return timers_; }
  int ColorCount() const { return assembler_->ColorCount(); }

 private:
  void AddContact(const ShellState& state, bool with_tangent, const Eigen::VectorXd* velocity);
  // Adds the moments about loaded edges at the state's load factor (their
  // work, force and load stiffness); returns their energy.
  double AddEdgeMoments(const ShellState& state, bool with_tangent);
  // The pattern-dependent parts: assembler, tangent, analysis, slots.
  void BuildPattern();
  // Adds the self-contact barrier; false (nothing added to the tangent) when
  // the pattern lacks a pair it needs, which it then grows.
  bool AddSelfContact(const ShellState& state, bool with_tangent, double& energy);

  const ShellModel& model_;
  const DofMap& dofs_;
  const NodeContact* contact_;
  SelfContact* self_contact_ = nullptr;
  std::vector<std::pair<int, int>> coupled_;  // node pairs the pattern couples beyond elements
  // Where the self-contact was last evaluated and the smallest distance it
  // found there (+∞ beyond its reach): a step too short to close that gap
  // needs no collision test.
  Positions self_contact_positions_;
  double self_contact_smallest_ = 0;
  std::unique_ptr<ShellAssembler> assembler_;
  // Per node, the tangent's slots of the upper triangle of its 3×3
  // translational block (row-major pairs a ≤ b; −1 where a DOF is fixed).
  std::vector<std::array<int, 6>> block_slots_;
  std::vector<Eigen::Matrix3d> contact_blocks_;
  Eigen::SparseMatrix<double> tangent_;
  Eigen::VectorXd internal_;
  Eigen::VectorXd rate_;
  SparseCholesky cholesky_;
  // The values of the matrix the factor holds, to skip refactorising it.
  Eigen::VectorXd factorized_values_;
  FactorizationInfo factorized_info_;
  bool factorized_valid_ = false;
  SystemTimers timers_;
  // Per tangent entry: its translational and rotational DOF counts.
  Eigen::ArrayX2d round_off_weights_;
};

// The system's last factorised tangent as CriticalModes takes it (the
// system must outlive it).
FactorizedTangent LastFactorizedTangent(EquilibriumSystem& system);

}  // namespace drape
