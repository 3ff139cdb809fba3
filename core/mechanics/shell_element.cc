#include "core/mechanics/shell_element.h"

#include <Eigen/Geometry>
#include <cmath>

#include "core/mechanics/bilinear_quad.h"

namespace drape {
namespace {

using Row8x20 = Eigen::Matrix<double, 8, 20>;
}  // namespace

ShellElementReference MakeShellElementReference(const NodeColumns& positions,
                                                const NodeColumns& directors,
                                                const Eigen::Vector3d& material_x) {
  ShellElementReference ref;
  const double g = 1.0 / std::sqrt(3.0);
  const double gauss_xi[4] = {-g, g, g, -g};
  const double gauss_eta[4] = {-g, -g, g, g};
  for (int p = 0; p < 4; ++p) {
    auto& gp = ref.gauss[p];
    gp.xi = gauss_xi[p];
    gp.eta = gauss_eta[p];
    Eigen::Matrix<double, 4, 2> dn_param;
    BilinearShape(gp.xi, gp.eta, gp.n, &dn_param);
    const Eigen::Matrix<double, 3, 2> a = positions * dn_param;  // covariant base vectors
    const Eigen::Vector3d normal = a.col(0).cross(a.col(1));
    gp.area = normal.norm();  // Gauss weights are 1
    const Eigen::Vector3d nu = normal / gp.area;
    Eigen::Vector3d e1 = material_x - material_x.dot(nu) * nu;
    if (e1.norm() < 1e-8) e1 = a.col(0);
    e1.normalize();
    const Eigen::Vector3d e2 = nu.cross(e1);
    Eigen::Matrix2d j;  // J_αi = A_α·e_i
    j << a.col(0).dot(e1), a.col(0).dot(e2), a.col(1).dot(e1), a.col(1).dot(e2);
    gp.covariant_to_local = j.inverse();
    gp.dn = dn_param * gp.covariant_to_local.transpose();
    const Eigen::Matrix<double, 3, 2> f0 = positions * gp.dn;
    const Eigen::Matrix<double, 3, 2> dt0 = directors * gp.dn;
    gp.metric0 = f0.transpose() * f0;
    gp.curvature0 = 0.5 * (f0.transpose() * dt0 + dt0.transpose() * f0);
  }
  const double tie_xi[4] = {0, 0, -1, 1};
  const double tie_eta[4] = {-1, 1, 0, 0};
  for (int k = 0; k < 4; ++k) {
    auto& tp = ref.tying[k];
    Eigen::Matrix<double, 4, 2> dn_param;
    BilinearShape(tie_xi[k], tie_eta[k], tp.n, &dn_param);
    tp.dn = dn_param.col(k < 2 ? 0 : 1);
    tp.shear0 = (positions * tp.dn).dot(directors * tp.n);
  }
  return ref;
}

void EvaluateShellElement(const ShellElementReference& ref,
                          const ShellSection& section,
                          const ShellElementState& state,
                          ElementOutput output,
                          ElementEnergy& result) {
  const bool want_gradient = output != ElementOutput::kEnergy;
  const bool want_hessian = output == ElementOutput::kHessian;
  const NodeColumns& x = state.positions;
  const NodeColumns& t = state.directors;
  const auto& dt = state.director_tangents;

  // Shear strains at the tying points and their derivatives in the 20 DOFs.
  double tied_strain[4];
  Eigen::Matrix<double, 20, 4> tied_derivative;
  for (int k = 0; k < 4; ++k) {
    const auto& tp = ref.tying[k];
    const Eigen::Vector3d phi_a = x * tp.dn;
    const Eigen::Vector3d t_bar = t * tp.n;
    tied_strain[k] = phi_a.dot(t_bar) - tp.shear0;
    for (int i = 0; i < 4; ++i) {
      tied_derivative.block<3, 1>(5 * i, k) = tp.dn(i) * t_bar;
      tied_derivative.block<2, 1>(5 * i + 3, k) = dt[i].transpose() * (tp.n(i) * phi_a);
    }
  }

  result.value = 0;
  result.gradient.setZero();
  // Geometric stiffness in scalar form: every second derivative of a strain
  // is a scalar times I₃ between a position and a position or director.
  Eigen::Matrix4d g_xx = Eigen::Matrix4d::Zero();
  Eigen::Matrix4d g_xt = Eigen::Matrix4d::Zero();
  Eigen::Vector4d tying_force = Eigen::Vector4d::Zero();  // ∂W/∂γ at each tying point
  // ∂W/∂t_I: its component along t_I enters the Hessian through ∂²t/∂(a,b)² = −t.
  NodeColumns director_force = NodeColumns::Zero();

  Eigen::Matrix<double, 32, 20> b_all, db_all;
  for (int p = 0; p < 4; ++p) {
    const auto& gp = ref.gauss[p];
    const Eigen::Matrix<double, 3, 2> f = x * gp.dn;    // φ,i
    const Eigen::Matrix<double, 3, 2> dtx = t * gp.dn;  // t,i
    const Eigen::Matrix2d eps = 0.5 * (f.transpose() * f - gp.metric0);
    const Eigen::Matrix2d kap = 0.5 * (f.transpose() * dtx + dtx.transpose() * f) - gp.curvature0;
    const double c_a = 0.5 * (1 - gp.eta), c_c = 0.5 * (1 + gp.eta);
    const double c_d = 0.5 * (1 - gp.xi), c_b = 0.5 * (1 + gp.xi);
    const Eigen::Vector2d gamma_cov(c_a * tied_strain[0] + c_c * tied_strain[1],
                                    c_d * tied_strain[2] + c_b * tied_strain[3]);
    const Eigen::Vector2d gamma = gp.covariant_to_local * gamma_cov;
    const Eigen::Vector3d e_m(eps(0, 0), eps(1, 1), 2 * eps(0, 1));
    const Eigen::Vector3d e_b(kap(0, 0), kap(1, 1), 2 * kap(0, 1));
    const Eigen::Vector3d n = section.membrane * e_m;
    const Eigen::Vector3d m = section.bending * e_b;
    const Eigen::Vector2d q = section.shear * gamma;
    result.value += gp.area * 0.5 * (e_m.dot(n) + e_b.dot(m) + gamma.dot(q));
    if (!want_gradient) continue;

    // B = ∂(ε, κ, γ)/∂(20 DOFs), rows: ε11 ε22 2ε12 κ11 κ22 2κ12 γ1 γ2.
    Row8x20 b;
    for (int i = 0; i < 4; ++i) {
      const double d0 = gp.dn(i, 0), d1 = gp.dn(i, 1);
      auto u = b.block<8, 3>(0, 5 * i);
      u.row(0) = d0 * f.col(0).transpose();
      u.row(1) = d1 * f.col(1).transpose();
      u.row(2) = (d0 * f.col(1) + d1 * f.col(0)).transpose();
      u.row(3) = d0 * dtx.col(0).transpose();
      u.row(4) = d1 * dtx.col(1).transpose();
      u.row(5) = (d0 * dtx.col(1) + d1 * dtx.col(0)).transpose();
      auto r = b.block<8, 2>(0, 5 * i + 3);
      r.topRows<3>().setZero();
      r.row(3) = (d0 * f.col(0)).transpose() * dt[i];
      r.row(4) = (d1 * f.col(1)).transpose() * dt[i];
      r.row(5) = (d1 * f.col(0) + d0 * f.col(1)).transpose() * dt[i];
    }
    const Eigen::Matrix<double, 20, 2> shear_cov =
        tied_derivative *
        (Eigen::Matrix<double, 4, 2>() << c_a, 0, c_c, 0, 0, c_d, 0, c_b).finished();
    b.bottomRows<2>() = gp.covariant_to_local * shear_cov.transpose();

    Eigen::Matrix<double, 8, 1> s;
    s.head<3>() = n;
    s.segment<3>(3) = m;
    s.tail<2>() = q;
    result.gradient.noalias() += gp.area * b.transpose() * s;
    if (!want_hessian) continue;

    // Director part of ∂W/∂t_I (for the −t curvature of the exponential map):
    // from κ, ∂κ_ij/∂t_I = ½(N_I,j φ,i + N_I,i φ,j); from γ via the tying points below.
    Eigen::Matrix2d mm;
    mm << m(0), m(2), m(2), m(1);
    Eigen::Matrix2d nn;
    nn << n(0), n(2), n(2), n(1);
    const Eigen::Matrix<double, 3, 2> f_m = f * mm;
    for (int i = 0; i < 4; ++i) director_force.col(i) += gp.area * f_m * gp.dn.row(i).transpose();

    // Material stiffness Bᵀ D B, stacked over the Gauss points and multiplied
    // once after the loop (one 20 × 32 × 20 product vectorises better).
    auto b_rows = b_all.middleRows<8>(8 * p);
    auto db_rows = db_all.middleRows<8>(8 * p);
    b_rows = b;
    db_rows.topRows<3>() = gp.area * section.membrane * b.topRows<3>();
    db_rows.middleRows<3>(3) = gp.area * section.bending * b.middleRows<3>(3);
    db_rows.bottomRows<2>() = gp.area * section.shear * b.bottomRows<2>();

    g_xx.noalias() += gp.area * gp.dn * nn * gp.dn.transpose();
    g_xt.noalias() += gp.area * gp.dn * mm * gp.dn.transpose();
    const Eigen::Vector2d q_cov = gp.covariant_to_local.transpose() * q;  // ∂W/∂γ_α
    tying_force +=
        gp.area * Eigen::Vector4d(q_cov(0) * c_a, q_cov(0) * c_c, q_cov(1) * c_d, q_cov(1) * c_b);
  }
  if (!want_hessian) return;

  result.hessian.noalias() = b_all.transpose() * db_all;
  for (int k = 0; k < 4; ++k) {
    const auto& tp = ref.tying[k];
    g_xt.noalias() += tying_force(k) * tp.dn * tp.n.transpose();
    const Eigen::Vector3d phi_a = x * tp.dn;
    for (int i = 0; i < 4; ++i) director_force.col(i) += tying_force(k) * tp.n(i) * phi_a;
  }
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      result.hessian.block<3, 3>(5 * i, 5 * j).diagonal().array() += g_xx(i, j);
      const Eigen::Matrix<double, 3, 2> xt = g_xt(i, j) * dt[j];
      result.hessian.block<3, 2>(5 * i, 5 * j + 3) += xt;
      result.hessian.block<2, 3>(5 * j + 3, 5 * i) += xt.transpose();
    }
    result.hessian.block<2, 2>(5 * i + 3, 5 * i + 3).diagonal().array() -=
        director_force.col(i).dot(t.col(i));
  }
}

}  // namespace drape
