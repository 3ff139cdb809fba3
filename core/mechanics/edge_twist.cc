#include "core/mechanics/edge_twist.h"

#include <Eigen/Geometry>
#include <unsupported/Eigen/AutoDiff>

#include <cmath>

namespace drape {
namespace {

// Forward mode over forward mode: values carry the gradient, their
// derivatives the Hessian's rows (exact, no differencing).
using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<double, 10, 1>>;
using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, 10, 1>>;
using Vec = Eigen::Matrix<Outer, 3, 1>;

Outer Variable(double value, int index) {
  Outer v;
  v.value() = Inner(value, 10, index);
  v.derivatives() = Eigen::Matrix<Inner, 10, 1>::Unit(10, index);
  for (int k = 0; k < 10; ++k) v.derivatives()(k).derivatives().setZero();
  return v;
}

Outer Constant(double v) {
  return Outer(Inner(v));
}

Vec Constant(const Eigen::Vector3d& v) {
  return {Constant(v(0)), Constant(v(1)), Constant(v(2))};
}

// The node's position φ + Δu with Δu the variables first..first+2.
Vec Position(const Eigen::Vector3d& x, int first) {
  Vec out;
  for (int i = 0; i < 3; ++i) out(i) = Variable(x(i), first + i);
  return out;
}

// The director exp(ŵ) t to second order in w = a g₁ + b g₂ (exact in value,
// gradient and Hessian at w = 0): t − a g₂ + b g₁ − ½(a² + b²) t.
Vec Director(const Eigen::Matrix3d& rotation, int first) {
  const Outer a = Variable(0.0, first), b = Variable(0.0, first + 1);
  Vec out;
  for (int i = 0; i < 3; ++i)
    out(i) = rotation(i, 2) - a * rotation(i, 1) + b * rotation(i, 0) -
             0.5 * (a * a + b * b) * rotation(i, 2);
  return out;
}

// The angle about `axis` (unit) from `from` to `to`, both taken normal to it.
Outer AngleAbout(const Vec& axis, const Vec& from, const Vec& to) {
  using std::atan2;
  return atan2(axis.dot(from.cross(to)), from.dot(to) - from.dot(axis) * to.dot(axis));
}

}  // namespace

EdgeTwist EvaluateEdgeTwist(const EdgeTwistReference& reference,
                            const Eigen::Vector3d& x0,
                            const Eigen::Vector3d& x1,
                            const Eigen::Matrix3d& rotation0,
                            const Eigen::Matrix3d& rotation1) {
  using std::sqrt;
  const Vec chord = Position(x1, 5) - Position(x0, 0);
  const Vec axis = chord / sqrt(chord.squaredNorm());
  const Vec axis0 = Constant(reference.axis);
  // S v = v + c × v + c × (c × v)/(1 + a₀·a), c = a₀ × a: a₀ to a.
  const Vec c = axis0.cross(axis);
  const Outer scale = 1.0 / (1.0 + axis0.dot(axis));
  const Vec directors[2] = {Director(rotation0, 3), Director(rotation1, 8)};
  Outer twist = Constant(0.0);
  for (int n = 0; n < 2; ++n) {
    Eigen::Vector3d t0 = reference.directors[n];
    t0 -= t0.dot(reference.axis) * reference.axis;
    const Vec from0 = Constant(t0);
    const Vec from = from0 + c.cross(from0) + scale * c.cross(c.cross(from0));
    twist += 0.5 * AngleAbout(axis, from, directors[n]);
  }
  EdgeTwist out;
  out.angle = twist.value().value();
  for (int k = 0; k < 10; ++k) {
    out.gradient(k) = twist.derivatives()(k).value();
    out.hessian.row(k) = twist.derivatives()(k).derivatives().transpose();
  }
  return out;
}

}  // namespace drape
