#include "core/solve/equilibrium_system.h"

#include <chrono>
#include <cmath>

namespace drape {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

EquilibriumSystem::EquilibriumSystem(const ShellModel& model, const DofMap& dofs)
    : dofs_(dofs), assembler_(model, dofs), tangent_(assembler_.Pattern()) {
  internal_.setZero(model.DofCount());
  if (dofs.FreeCount() > 0) cholesky_.Analyze(tangent_);
}

double EquilibriumSystem::Assemble(const ShellState& state,
                                   bool with_tangent,
                                   const Eigen::VectorXd* velocity) {
  const auto start = std::chrono::steady_clock::now();
  const double energy = assembler_.Assemble(
      state, internal_, with_tangent ? &tangent_ : nullptr, velocity, velocity ? &rate_ : nullptr);
  timers_.assembly_s += SecondsSince(start);
  return energy;
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

FactorizationInfo EquilibriumSystem::Factorize() {
  const auto start = std::chrono::steady_clock::now();
  FactorizationInfo info = cholesky_.Factorize(tangent_);
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

}  // namespace drape
