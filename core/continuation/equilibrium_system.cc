#include "core/continuation/equilibrium_system.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "core/fe/edge_moments.h"

namespace drape {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

EquilibriumSystem::EquilibriumSystem(const ShellModel& model,
                                     const DofMap& dofs,
                                     const NodeContact* contact)
    : model_(model), dofs_(dofs), contact_(contact) {
  internal_.setZero(model.DofCount());
  BuildPattern();
}

void EquilibriumSystem::BuildPattern() {
  const ShellModel& model = model_;
  const DofMap& dofs = dofs_;
  assembler_ = std::make_unique<ShellAssembler>(model, dofs, coupled_);
  tangent_ = assembler_->Pattern();
  factorized_valid_ = false;
  if (dofs.FreeCount() > 0) cholesky_.Analyze(tangent_);
  // Per stored entry (row r, column c of the upper triangle), how many of
  // its two DOFs (one on the diagonal) are translations and how many
  // rotations: the weights of X² and 1 in RoundOffLevel.
  std::vector<bool> rotation(dofs.FreeCount(), false);
  for (int d = 0; d < dofs.DofCount(); ++d)
    if (const int f = dofs.Free(d); f >= 0) rotation[f] = d % kDofsPerNode >= 3;
  round_off_weights_.setZero(tangent_.nonZeros(), 2);
  for (int c = 0; c < tangent_.outerSize(); ++c)
    for (int k = tangent_.outerIndexPtr()[c]; k < tangent_.outerIndexPtr()[c + 1]; ++k) {
      const int r = tangent_.innerIndexPtr()[k];
      round_off_weights_(k, rotation[c] ? 1 : 0) += 1;
      if (r != c) round_off_weights_(k, rotation[r] ? 1 : 0) += 1;
    }
  if (!contact_) return;
  // Every node's translational block is in the element pattern already.
  const int* outer = tangent_.outerIndexPtr();
  const int* inner = tangent_.innerIndexPtr();
  block_slots_.resize(model.NodeCount());
  for (int i = 0; i < model.NodeCount(); ++i) {
    int pair = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b, ++pair) {
        const int fa = dofs.Free(kDofsPerNode * i + a), fb = dofs.Free(kDofsPerNode * i + b);
        int& slot = block_slots_[i][pair];
        slot = -1;
        if (fa < 0 || fb < 0) continue;
        const int row = std::min(fa, fb), col = std::max(fa, fb);
        const int* at = std::lower_bound(inner + outer[col], inner + outer[col + 1], row);
        slot = static_cast<int>(at - inner);
      }
  }
}

void EquilibriumSystem::AddContact(const ShellState& state,
                                   bool with_tangent,
                                   const Eigen::VectorXd* velocity) {
  contact_->Add(state,
                internal_,
                with_tangent ? &contact_blocks_ : nullptr,
                with_tangent ? velocity : nullptr,
                with_tangent && velocity ? &rate_ : nullptr);
  if (!with_tangent) return;
  double* values = tangent_.valuePtr();
  for (size_t i = 0; i < block_slots_.size(); ++i) {
    const Eigen::Matrix3d& k = contact_blocks_[i];
    if (k.isZero(0.0)) continue;
    int pair = 0;
    for (int a = 0; a < 3; ++a)
      for (int b = a; b < 3; ++b, ++pair)
        if (block_slots_[i][pair] >= 0) values[block_slots_[i][pair]] += k(a, b);
  }
}

double EquilibriumSystem::Assemble(const ShellState& state,
                                   bool with_tangent,
                                   const Eigen::VectorXd* velocity) {
  const auto start = std::chrono::steady_clock::now();
  double energy = 0;
  // At most twice: once more when the self-contact grew the pattern.
  for (int pass = 0; pass < 2; ++pass) {
    energy = assembler_->Assemble(state,
                                  internal_,
                                  with_tangent ? &tangent_ : nullptr,
                                  velocity,
                                  velocity ? &rate_ : nullptr);
    if (contact_) AddContact(state, with_tangent, velocity);
    if (state.load_factor != 0 && HasEdgeMoments(model_))
      energy += AddEdgeMoments(state, with_tangent);
    if (!self_contact_ || AddSelfContact(state, with_tangent, energy)) break;
  }
  timers_.assembly_s += SecondsSince(start);
  return energy;
}

double EquilibriumSystem::PotentialEnergy(const ShellState& state,
                                          const Eigen::VectorXd& external) {
  double energy = Assemble(state, /*with_tangent=*/false);
  if (contact_) energy += contact_->Energy(state);
  const Positions& reference = model_.reference.positions;
  for (int i = 0; i < model_.NodeCount(); ++i)
    energy -= external.segment<3>(kDofsPerNode * i)
                  .dot((state.positions.row(i) - reference.row(i)).transpose());
  return energy;
}

double EquilibriumSystem::AddEdgeMoments(const ShellState& state, bool with_tangent) {
  const double factor = state.load_factor;
  double energy = 0;
  for (const auto& t : EdgeMomentTerms(model_, state)) {
    energy += factor * t.energy;
    int dof[10];
    for (int k = 0; k < 10; ++k) dof[k] = kDofsPerNode * t.nodes[k / 5] + k % 5;
    for (int k = 0; k < 10; ++k) internal_(dof[k]) += factor * t.force(k);
    if (!with_tangent) continue;
    for (int k = 0; k < 10; ++k)
      for (int l = 0; l < 10; ++l) {
        const int r = dofs_.Free(dof[k]), c = dofs_.Free(dof[l]);
        if (r >= 0 && c >= r) tangent_.coeffRef(r, c) += factor * t.stiffness(k, l);
      }
  }
  return energy;
}

bool EquilibriumSystem::AddSelfContact(const ShellState& state, bool with_tangent, double& energy) {
  const SelfContactEvaluation e = self_contact_->Evaluate(state.positions, with_tangent);
  self_contact_positions_ = state.positions;
  self_contact_smallest_ = e.smallest_distance;
  energy += e.energy;
  for (int i = 0; i < model_.NodeCount(); ++i)
    internal_.segment<3>(kDofsPerNode * i) += e.gradient.segment<3>(3 * i);
  if (!with_tangent) return true;
  const int* outer = tangent_.outerIndexPtr();
  const int* inner = tangent_.innerIndexPtr();
  // The slot of each upper-triangle entry (r ≤ c) of each 12 × 12 block, by
  // free DOF; −1 where a DOF is fixed or the entry is in the lower triangle.
  std::vector<int> slots(e.blocks.size() * 144, -1);
  std::vector<std::pair<int, int>> missing;
  for (size_t b = 0; b < e.blocks.size(); ++b) {
    const auto& nodes = e.block_nodes[b];
    for (int k = 0; k < 4; ++k)
      for (int l = 0; l < 4; ++l)
        for (int q = 0; q < 3; ++q) {
          const int c = dofs_.Free(kDofsPerNode * nodes[l] + q);
          if (c < 0) continue;
          const int* at = inner + outer[c];
          for (int p = 0; p < 3; ++p) {
            const int r = dofs_.Free(kDofsPerNode * nodes[k] + p);
            if (r < 0 || r > c) continue;
            at = std::lower_bound(at, inner + outer[c + 1], r);
            if (at == inner + outer[c + 1] || *at != r) {
              missing.emplace_back(std::min(nodes[k], nodes[l]), std::max(nodes[k], nodes[l]));
              at = inner + outer[c];
              continue;
            }
            slots[144 * b + 12 * (3 * k + p) + 3 * l + q] = static_cast<int>(at - inner);
          }
        }
  }
  if (!missing.empty()) {
    // Couple every pair within three times the barrier's reach, so that the
    // pattern (and its analysis) lasts while the layers move.
    const SelfContactSettings& s = self_contact_->settings();
    for (const auto& pair :
         self_contact_->NodePairs(state.positions, 3 * (s.offset + s.activation)))
      missing.push_back(pair);
    coupled_.insert(coupled_.end(), missing.begin(), missing.end());
    std::sort(coupled_.begin(), coupled_.end());
    coupled_.erase(std::unique(coupled_.begin(), coupled_.end()), coupled_.end());
    BuildPattern();
    return false;
  }
  double* values = tangent_.valuePtr();
  for (size_t b = 0; b < e.blocks.size(); ++b) {
    const double* block = e.blocks[b].data();  // column-major: (i, j) at 12 j + i
    const int* slot = &slots[144 * b];
    for (int i = 0; i < 12; ++i)
      for (int j = 0; j < 12; ++j)
        if (slot[12 * i + j] >= 0) values[slot[12 * i + j]] += block[12 * j + i];
  }
  return true;
}

double EquilibriumSystem::StepBound(const ShellState& state,
                                    const Eigen::VectorXd& increment) const {
  if (!self_contact_ && !(contact_ && contact_->HasBarrier())) return 1.0;
  Positions dx(model_.NodeCount(), 3);
  for (int i = 0; i < model_.NodeCount(); ++i)
    dx.row(i) = increment.segment<3>(kDofsPerNode * i).transpose();
  return StepBound(state, dx);
}

double EquilibriumSystem::StepBound(const ShellState& state, const Positions& dx) const {
  const double obstacles = contact_ ? contact_->StepBound(state, dx) : 1.0;
  if (!self_contact_) return obstacles;
  // No pair's distance changes by more than twice the motions' spread: a
  // step that closes at most 90 % of the smallest gap beyond the offset is
  // whole (as the filter would find), without testing pairs.
  if (self_contact_positions_.rows() == state.positions.rows() &&
      self_contact_positions_ == state.positions) {
    const SelfContactSettings& s = self_contact_->settings();
    const double gap = std::min(self_contact_smallest_, s.offset + s.activation) - s.offset;
    if (2 * MotionSpread(dx) < 0.9 * gap) return obstacles;
  }
  return std::min(obstacles, self_contact_->StepBound(state.positions, dx));
}

Eigen::VectorXd EquilibriumSystem::ObstacleForceRate(
    const ShellState& state, const std::vector<ObstacleMotion>& motions) const {
  Eigen::VectorXd rate = Eigen::VectorXd::Zero(internal_.size());
  if (contact_) contact_->AddObstacleRate(state, motions, rate);
  return rate;
}

Eigen::VectorXd EquilibriumSystem::Residual(const Eigen::VectorXd& external) const {
  return dofs_.Restrict(internal_ - external);
}

double EquilibriumSystem::ForceLevel(const Eigen::VectorXd& external) const {
  double free = 0, fixed = 0;
  for (int d = 0; d < dofs_.DofCount(); ++d) {
    if (dofs_.IsFixed(d)) {
      const double r = internal_(d) - external(d);
      fixed += r * r;
    } else {
      free += external(d) * external(d);
    }
  }
  return std::sqrt(free) + std::sqrt(fixed);
}

double EquilibriumSystem::RoundOffLevel(const ShellState& state) const {
  // Σ_ij K_ij² δ_j² over the symmetric matrix from its upper triangle, with
  // δ = ε·X on translations and ε on rotations: each stored entry adds
  // K²(δ_r² + δ_c²) (once on the diagonal), i.e. ε²K²(X² a + b) with the
  // pattern's own counts a, b (round_off_weights_).
  const double eps = std::numeric_limits<double>::epsilon();
  const double coordinate = state.positions.cwiseAbs().maxCoeff();
  const Eigen::Map<const Eigen::ArrayXd> values(tangent_.valuePtr(), tangent_.nonZeros());
  const double translational = (values.square() * round_off_weights_.col(0)).sum();
  const double rotational = (values.square() * round_off_weights_.col(1)).sum();
  return eps * std::sqrt(coordinate * coordinate * translational + rotational);
}

Eigen::VectorXd EquilibriumSystem::TangentDiagonal() const {
  return tangent_.diagonal();
}

void EquilibriumSystem::ShiftTangentDiagonal(const Eigen::VectorXd& shift) {
  // The upper triangle is stored by columns: each column's last entry is its
  // diagonal.
  const int* outer = tangent_.outerIndexPtr();
  double* values = tangent_.valuePtr();
  for (int c = 0; c < tangent_.outerSize(); ++c) values[outer[c + 1] - 1] += shift(c);
}

FactorizationInfo EquilibriumSystem::Factorize() {
  const auto start = std::chrono::steady_clock::now();
  // A step's predictor starts from the state the last corrector converged
  // at, whose tangent was factorised for its stability indicator: the same
  // matrix need not be factorised twice.
  const Eigen::Map<const Eigen::VectorXd> values(tangent_.valuePtr(), tangent_.nonZeros());
  if (factorized_valid_ && factorized_values_.size() == values.size() &&
      std::equal(values.begin(), values.end(), factorized_values_.begin())) {
    ++timers_.reused_factorizations;
    return factorized_info_;
  }
  FactorizationInfo info = cholesky_.Factorize(tangent_);
  factorized_values_ = values;
  factorized_info_ = info;
  factorized_valid_ = true;
  timers_.factorization_s += SecondsSince(start);
  ++timers_.factorizations;
  if (!info.positive_definite) ++timers_.indefinite_factorizations;
  return info;
}

Eigen::VectorXd EquilibriumSystem::Solve(const Eigen::VectorXd& b) {
  const auto start = std::chrono::steady_clock::now();
  Eigen::VectorXd x = cholesky_.Solve(b);
  timers_.solve_s += SecondsSince(start);
  return x;
}

FactorizedTangent LastFactorizedTangent(EquilibriumSystem& system) {
  return {system.TangentDiagonal(),
          [&system](const Eigen::VectorXd& b) { return system.Solve(b); }};
}

}  // namespace drape
