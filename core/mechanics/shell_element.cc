#include "core/mechanics/shell_element.h"

#include <Eigen/Geometry>
#include <array>
#include <cmath>

#include "core/mechanics/bilinear_quad.h"

namespace drape {
namespace {

// The Hessian is built with the 20 DOFs ordered by component, then by node:
// (Δu_x of nodes 0–3, Δu_y …, Δu_z …, a …, b …). A derivative in them is then
// a 4 × 5 matrix (row: node, column: component) whose columns are single SIMD
// packets: strain derivatives are built for the four nodes at once, the
// membrane terms (no rotations) fill the leading 12 × 12 block alone, and the
// stiffness products run over whole packets. The result is permuted to the
// public per-node order (Δu, a, b) once, at the end.
constexpr int kTranslations = 12;
using InternalMatrix = Eigen::Matrix<double, 20, 20>;
using NodeRows3 = Eigen::Matrix<double, 4, 3>;  // row I: a vector of node I
using NodeRows2 = Eigen::Matrix<double, 4, 2>;  // row I: (a, b) of node I
using DirectorTangents = std::array<Eigen::Matrix<double, 3, 2>, 4>;
// ∂t_I/∂(a, b) by rotation component: tangents[a].row(I) = (∂t_I/∂a)ᵀ.
using Tangents = std::array<NodeRows3, 2>;

// Sums start from −0.0, the exact additive identity (−0 + x = x for every x).
// Unlike +0.0 it is not all-zero bits, so it is stored with a few vector moves
// instead of a memset, which GCC expands to a `rep stos` that costs tens of
// cycles per matrix, a measurable share of this kernel.
template <typename Matrix>
Matrix ZeroSum() {
  return Matrix::Constant(-0.0);
}

// The translation and rotation parts of an internal 20-column.
template <typename Column>
Eigen::Map<NodeRows3> TranslationPart(Column&& column) {
  return Eigen::Map<NodeRows3>(column.data());
}
template <typename Column>
Eigen::Map<NodeRows2> RotationPart(Column&& column) {
  return Eigen::Map<NodeRows2>(column.data() + kTranslations);
}

Tangents TangentsByComponent(const DirectorTangents& dt) {
  Tangents tangents;
  for (int a = 0; a < 2; ++a)
    for (int i = 0; i < 4; ++i) tangents[a].row(i) = dt[i].col(a).transpose();
  return tangents;
}

// A derivative in the directors (row I: ∂/∂t_I) as one in the rotation
// increments: ∂/∂(a, b)_I = (∂t_I/∂(a, b))ᵀ ∂/∂t_I.
NodeRows2 ToRotations(const Tangents& tangents, const NodeRows3& d_director) {
  NodeRows2 r;
  for (int a = 0; a < 2; ++a) r.col(a) = d_director.cwiseProduct(tangents[a]).rowwise().sum();
  return r;
}

// For s_ij = ½(g_i·y,j + g_j·y,i) with y = Σ_I y_I N_I and g fixed, the
// derivatives of the Voigt components (s11, s22, 2 s12) in the nodal y_I (row
// I). With g = φ,i these are ∂ε/∂φ_I and ∂κ/∂t_I; with g = t,i, ∂κ/∂φ_I.
std::array<NodeRows3, 3> VoigtDerivative(const Eigen::Matrix<double, 3, 2>& g,
                                         const Eigen::Matrix<double, 4, 2>& dn) {
  return {dn.col(0) * g.col(0).transpose(),
          dn.col(1) * g.col(1).transpose(),
          dn.col(0) * g.col(1).transpose() + dn.col(1) * g.col(0).transpose()};
}

// Symmetric 2 × 2 tensor of a Voigt vector (11, 22, 12).
Eigen::Matrix2d Tensor(const Eigen::Vector3d& v) {
  return (Eigen::Matrix2d() << v(0), v(2), v(2), v(1)).finished();
}

// ∂γ/∂(γ_A, γ_C, γ_D, γ_B): the MITC4 interpolation of the tied covariant
// strains to the Gauss point, then the map to the local frame.
Eigen::Matrix<double, 2, 4> ShearInterpolation(const ShellElementReference::GaussPoint& gp) {
  const double c_a = 0.5 * (1 - gp.eta), c_c = 0.5 * (1 + gp.eta);
  const double c_d = 0.5 * (1 - gp.xi), c_b = 0.5 * (1 + gp.xi);
  const Eigen::Matrix2d& l = gp.covariant_to_local;
  Eigen::Matrix<double, 2, 4> s;
  s << c_a * l.col(0), c_c * l.col(0), c_d * l.col(1), c_b * l.col(1);
  return s;
}

// The shear strains at the tying points: γ_k = φ,α·t̄ − (reference).
struct TiedShear {
  NodeColumns phi;  // column k: φ,α at tying point k
  NodeColumns t;    // column k: t̄ there
  Eigen::Vector4d strain;
};

TiedShear TiedShearStrains(const ShellElementReference& ref,
                           const NodeColumns& x,
                           const NodeColumns& t) {
  TiedShear tied;
  for (int k = 0; k < 4; ++k) {
    tied.phi.col(k) = x * ref.tying[k].dn;
    tied.t.col(k) = t * ref.tying[k].n;
    tied.strain(k) = tied.phi.col(k).dot(tied.t.col(k)) - ref.tying[k].shear0;
  }
  return tied;
}

// What the Hessian gathers over the Gauss points, in the internal DOF order.
struct StiffnessTerms {
  Tangents tangents;
  // Geometric stiffness in scalar form: every second derivative of a strain
  // is a scalar times I₃ between a position and a position or director.
  Eigen::Matrix4d g_xx = ZeroSum<Eigen::Matrix4d>();
  Eigen::Matrix4d g_xt = ZeroSum<Eigen::Matrix4d>();
  // Material stiffness Σ b (D b)ᵀ: strain derivatives (columns) and D dA
  // times them, stacked over the Gauss points. Bending at Gauss point p in
  // columns 3p … 3p + 2, then the four tied shear strains (the shear energy
  // is a quadratic form in them, ∂²W/∂γ_k∂γ_l = tied_stiffness, so 4 columns
  // serve all Gauss points); the membrane, free of rotations, apart.
  Eigen::Matrix<double, 20, 16> b_bend_shear, db_bend_shear;
  Eigen::Matrix<double, kTranslations, 12> b_membrane, db_membrane;
  Eigen::Matrix4d tied_stiffness = ZeroSum<Eigen::Matrix4d>();
};

// The stiffness-weighted strain derivatives: column c of db is Σ_e D_ce b_e,
// i.e. db = b Dᵀ, summed column by column over whole packets.
template <typename Columns, typename Stiffness, typename Weighted>
void Weight(const Columns& b, const Stiffness& d, Weighted&& db) {
  for (int c = 0; c < Stiffness::RowsAtCompileTime; ++c) {
    db.col(c) = d(c, 0) * b.col(0);
    for (int e = 1; e < Stiffness::ColsAtCompileTime; ++e) db.col(c) += d(c, e) * b.col(e);
  }
}

// Gauss point p's share of the stiffness, from φ,i (f), t,i (dtx) and the
// force and moment tensors times dA.
void AddGaussPointStiffness(int p,
                            const ShellElementReference::GaussPoint& gp,
                            const ShellSection& section,
                            const Eigen::Matrix3d& bending_tangent,
                            const Eigen::Matrix<double, 3, 2>& f,
                            const Eigen::Matrix<double, 3, 2>& dtx,
                            const Eigen::Matrix2d& n_da,
                            const Eigen::Matrix2d& m_da,
                            const Eigen::Matrix<double, 2, 4>& shear_interpolation,
                            StiffnessTerms& s) {
  s.g_xx.noalias() += gp.dn * n_da * gp.dn.transpose();
  s.g_xt.noalias() += gp.dn * m_da * gp.dn.transpose();
  s.tied_stiffness.noalias() +=
      shear_interpolation.transpose() * (gp.area * section.shear) * shear_interpolation;
  const std::array<NodeRows3, 3> d_membrane = VoigtDerivative(f, gp.dn);  // also ∂κ/∂t
  const std::array<NodeRows3, 3> d_bending = VoigtDerivative(dtx, gp.dn);
  for (int c = 0; c < 3; ++c) {
    TranslationPart(s.b_bend_shear.col(3 * p + c)) = d_bending[c];
    RotationPart(s.b_bend_shear.col(3 * p + c)) = ToRotations(s.tangents, d_membrane[c]);
    TranslationPart(s.b_membrane.col(3 * p + c)) = d_membrane[c];
  }
  Weight(s.b_bend_shear.middleCols<3>(3 * p),
         gp.area * bending_tangent,
         s.db_bend_shear.middleCols<3>(3 * p));
  Weight(s.b_membrane.middleCols<3>(3 * p),
         gp.area * section.membrane,
         s.db_membrane.middleCols<3>(3 * p));
}

// The tied shear strains' share: their derivatives ∂γ_k/∂φ_I = N_I,α(k) t̄_k
// and ∂γ_k/∂t_I = N_I(k) φ,α(k), and the geometric term of ∂W/∂γ_k.
void AddTiedShearStiffness(const ShellElementReference& ref,
                           const TiedShear& tied,
                           const Eigen::Vector4d& tying_force,
                           StiffnessTerms& s) {
  for (int k = 0; k < 4; ++k) {
    const auto& tp = ref.tying[k];
    TranslationPart(s.b_bend_shear.col(12 + k)) = tp.dn * tied.t.col(k).transpose();
    RotationPart(s.b_bend_shear.col(12 + k)) =
        ToRotations(s.tangents, tp.n * tied.phi.col(k).transpose());
    s.g_xt.noalias() += tying_force(k) * tp.dn * tp.n.transpose();
  }
  Weight(s.b_bend_shear.rightCols<4>(), s.tied_stiffness, s.db_bend_shear.rightCols<4>());
}

// Columns j and j + 1 of the upper triangle of Σ_s b_s db_sᵀ (the sum over the
// columns s of the stacks), over rows 0 … kRows − 1, kRows a whole number of
// packets ≥ j + 2. The two sums stay in registers.
template <int kRows, typename Stack>
void AddColumnPair(const Stack& b, const Stack& db, int j, bool accumulate, InternalMatrix& k) {
  using Column = Eigen::Matrix<double, kRows, 1>;
  Column sum0 = accumulate ? Column(k.col(j).template head<kRows>()) : Column::Zero();
  Column sum1 = accumulate ? Column(k.col(j + 1).template head<kRows>()) : Column::Zero();
  for (int s = 0; s < Stack::ColsAtCompileTime; ++s) {
    sum0 += db(j, s) * b.col(s).template head<kRows>();
    sum1 += db(j + 1, s) * b.col(s).template head<kRows>();
  }
  k.col(j).template head<kRows>() = sum0;
  k.col(j + 1).template head<kRows>() = sum1;
}

// Sets (or with `accumulate` adds) the upper triangle of b dbᵀ in the leading
// kColumns columns of k, in blocks of 4 columns: columns 4q … 4q + 3 need
// rows 0 … 4q + 3. Only the upper triangle is needed: the permutation to the
// public order mirrors it.
template <int kColumns, typename Stack>
void UpperProduct(const Stack& b, const Stack& db, bool accumulate, InternalMatrix& k) {
  if constexpr (kColumns > 4) UpperProduct<kColumns - 4>(b, db, accumulate, k);
  AddColumnPair<kColumns>(b, db, kColumns - 4, accumulate, k);
  AddColumnPair<kColumns>(b, db, kColumns - 2, accumulate, k);
}

// h(5I + c, 5J + d) = h(5J + d, 5I + c) = k(4c + I, 4d + J), from the upper
// triangle of k: each 4 × 4 component block of k is a strided 4 × 4 block of h.
void ToPublicOrder(const InternalMatrix& k, ElementMatrix& h) {
  using Strided = Eigen::Map<Eigen::Matrix4d, Eigen::Unaligned, Eigen::Stride<5 * 20, 5>>;
  for (int d = 0; d < 5; ++d) {
    Strided(h.data() + d + 20 * d) = k.block<4, 4>(4 * d, 4 * d).selfadjointView<Eigen::Upper>();
    for (int c = 0; c < d; ++c) {
      Strided(h.data() + c + 20 * d) = k.block<4, 4>(4 * c, 4 * d);
      Strided(h.data() + d + 20 * c) = k.block<4, 4>(4 * c, 4 * d).transpose();
    }
  }
}

// The Hessian from the gathered terms; `director_force` is ∂W/∂t_I (column I).
void AssembleHessian(const StiffnessTerms& s,
                     const NodeColumns& director_force,
                     const NodeColumns& t,
                     ElementMatrix& h) {
  // Upper triangle, internal order: material, then geometric terms.
  InternalMatrix k;
  UpperProduct<20>(s.b_bend_shear, s.db_bend_shear, /*accumulate=*/false, k);
  UpperProduct<kTranslations>(s.b_membrane, s.db_membrane, /*accumulate=*/true, k);
  for (int r = 0; r < 3; ++r) {
    k.block<4, 4>(4 * r, 4 * r) += s.g_xx;
    // ∂²/∂φ_I,r∂a_J = g_xt(I, J) ∂t_J,r/∂a.
    for (int a = 0; a < 2; ++a)
      k.block<4, 4>(4 * r, kTranslations + 4 * a) += s.g_xt * s.tangents[a].col(r).asDiagonal();
  }
  // ∂²t_I/∂(a, b)² = −t_I I₂ at zero increment.
  const Eigen::Vector4d director_force_along_t =
      director_force.cwiseProduct(t).colwise().sum().transpose();
  for (int a = 0; a < 2; ++a)
    k.block<4, 4>(kTranslations + 4 * a, kTranslations + 4 * a).diagonal() -=
        director_force_along_t;
  ToPublicOrder(k, h);
}

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
    gp.orientation0 = f0.col(0).cross(f0.col(1)).dot(directors * gp.n);
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

std::array<Eigen::Vector3d, 4> BendingStrains(const ShellElementReference& ref,
                                              const NodeColumns& x,
                                              const NodeColumns& t) {
  std::array<Eigen::Vector3d, 4> strains;
  for (int p = 0; p < 4; ++p) {
    const auto& gp = ref.gauss[p];
    const Eigen::Matrix<double, 3, 2> f = x * gp.dn;
    const Eigen::Matrix<double, 3, 2> dtx = t * gp.dn;
    const Eigen::Matrix2d kap = 0.5 * (f.transpose() * dtx + dtx.transpose() * f) - gp.curvature0;
    strains[p] = Eigen::Vector3d(kap(0, 0), kap(1, 1), 2 * kap(0, 1));
  }
  return strains;
}

std::array<Eigen::Vector3d, 4> MembraneStrains(const ShellElementReference& ref,
                                               const NodeColumns& x) {
  std::array<Eigen::Vector3d, 4> strains;
  for (int p = 0; p < 4; ++p) {
    const auto& gp = ref.gauss[p];
    const Eigen::Matrix<double, 3, 2> f = x * gp.dn;
    const Eigen::Matrix2d eps = 0.5 * (f.transpose() * f - gp.metric0);
    strains[p] = Eigen::Vector3d(eps(0, 0), eps(1, 1), 2 * eps(0, 1));
  }
  return strains;
}

void EvaluateShellElement(const ShellElementReference& ref,
                          const ShellSection& section,
                          const ShellElementState& state,
                          ElementOutput output,
                          ElementEnergy& result,
                          const ElementSlip* slip) {
  static const ElementSlip kNoSlip = ElementSlip::Zero();
  if (!slip) slip = &kNoSlip;
  const bool want_gradient = output != ElementOutput::kEnergy;
  const NodeColumns& x = state.positions;
  const NodeColumns& t = state.directors;
  const DirectorTangents& dt = state.director_tangents;
  const TiedShear tied = TiedShearStrains(ref, x, t);

  // The gradient in tensor form: ∂W/∂φ_I and ∂W/∂t_I (column I), ∂W/∂γ_k.
  NodeColumns position_force = ZeroSum<NodeColumns>();
  NodeColumns director_force = ZeroSum<NodeColumns>();
  Eigen::Vector4d tying_force = ZeroSum<Eigen::Vector4d>();
  const bool want_hessian = output == ElementOutput::kHessian;
  StiffnessTerms stiffness;
  if (want_hessian) stiffness.tangents = TangentsByComponent(dt);

  result.value = 0;
  for (int p = 0; p < 4; ++p) {
    const auto& gp = ref.gauss[p];
    const Eigen::Matrix<double, 3, 2> f = x * gp.dn;    // φ,i
    const Eigen::Matrix<double, 3, 2> dtx = t * gp.dn;  // t,i
    const Eigen::Matrix2d eps = 0.5 * (f.transpose() * f - gp.metric0);
    const Eigen::Matrix2d kap = 0.5 * (f.transpose() * dtx + dtx.transpose() * f) - gp.curvature0;
    const Eigen::Matrix<double, 2, 4> shear_interpolation = ShearInterpolation(gp);
    const Eigen::Vector2d gamma = shear_interpolation * tied.strain;
    const Eigen::Vector3d e_m(eps(0, 0), eps(1, 1), 2 * eps(0, 1));
    const Eigen::Vector3d e_b(kap(0, 0), kap(1, 1), 2 * kap(0, 1));
    const Eigen::Vector3d n = section.membrane * e_m;
    const Eigen::Vector2d q = section.shear * gamma;
    Eigen::Vector3d m;
    double bending_energy;
    const Eigen::Matrix3d* bending_tangent = &section.bending;
    PlateBendingResponse law;
    if (section.bending_law) {
      section.bending_law->Evaluate(e_b, want_hessian, law);
      m = law.moment;
      bending_energy = law.energy;
      bending_tangent = &law.tangent;
    } else {
      m = section.bending * e_b;
      bending_energy = 0.5 * e_b.dot(m);
    }
    if (section.friction) {
      PlateBendingResponse friction;
      AddBendingFriction(*section.friction, e_b, *slip, p, want_hessian, friction);
      m += friction.moment;
      bending_energy += friction.energy;
      if (want_hessian) {
        law.tangent = *bending_tangent + friction.tangent;
        bending_tangent = &law.tangent;
      }
    }
    result.value += gp.area * (0.5 * (e_m.dot(n) + gamma.dot(q)) + bending_energy);
    if (!want_gradient) continue;

    // ∂W/∂φ_I = dA (φ,i n_ij + t,i m_ij) N_I,j and ∂W/∂t_I = dA φ,i m_ij N_I,j
    // (the B-matrix rows of ε and κ contracted with n and m).
    const Eigen::Matrix2d n_da = gp.area * Tensor(n);
    const Eigen::Matrix2d m_da = gp.area * Tensor(m);
    position_force.noalias() += (f * n_da + dtx * m_da) * gp.dn.transpose();
    director_force.noalias() += (f * m_da) * gp.dn.transpose();
    tying_force.noalias() += shear_interpolation.transpose() * (gp.area * q);
    if (want_hessian) {
      AddGaussPointStiffness(
          p, gp, section, *bending_tangent, f, dtx, n_da, m_da, shear_interpolation, stiffness);
    }
  }
  if (!want_gradient) {
    result.gradient.setZero();  // as it always was
    return;
  }

  // Tied shear: ∂γ_k/∂φ_I = N_I,α(k) t̄_k, ∂γ_k/∂t_I = N_I(k) φ,α(k).
  for (int k = 0; k < 4; ++k) {
    const auto& tp = ref.tying[k];
    position_force.noalias() += tying_force(k) * tied.t.col(k) * tp.dn.transpose();
    director_force.noalias() += tying_force(k) * tied.phi.col(k) * tp.n.transpose();
  }
  for (int i = 0; i < 4; ++i) {
    result.gradient.segment<3>(5 * i) = position_force.col(i);
    result.gradient.segment<2>(5 * i + 3) = dt[i].transpose() * director_force.col(i);
  }
  if (!want_hessian) return;

  AddTiedShearStiffness(ref, tied, tying_force, stiffness);
  AssembleHessian(stiffness, director_force, t, result.hessian);
}

std::array<double, 4> OrientedAreaRatios(const ShellElementReference& ref,
                                         const NodeColumns& x,
                                         const NodeColumns& t) {
  std::array<double, 4> ratios;
  for (int p = 0; p < 4; ++p) {
    const auto& gp = ref.gauss[p];
    const Eigen::Matrix<double, 3, 2> f = x * gp.dn;
    ratios[p] = f.col(0).cross(f.col(1)).dot(t * gp.n) / gp.orientation0;
  }
  return ratios;
}

}  // namespace drape
