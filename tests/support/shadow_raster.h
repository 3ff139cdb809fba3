// An area of a surface's shadow computed without the polygon library: its
// triangles (each quad split along 0–2, as CastShadow splits it) projected
// on the x–y plane and rasterised, every cell whose centre lies in some
// triangle counted once.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

namespace drape::test {

inline double RasterShadowArea(const Eigen::MatrixX3d& positions,
                               const Eigen::Matrix<int, Eigen::Dynamic, 4>& quads,
                               double cell) {
  const Eigen::Vector2d low = positions.leftCols<2>().colwise().minCoeff().transpose();
  const Eigen::Vector2d high = positions.leftCols<2>().colwise().maxCoeff().transpose();
  const int nx = static_cast<int>(std::ceil((high.x() - low.x()) / cell)) + 1;
  const int ny = static_cast<int>(std::ceil((high.y() - low.y()) / cell)) + 1;
  std::vector<char> covered(static_cast<size_t>(nx) * ny, 0);
  auto cover = [&](Eigen::Vector2d a, Eigen::Vector2d b, Eigen::Vector2d c) {
    const double twice = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (twice == 0) return;
    const Eigen::Vector2d lo = a.cwiseMin(b).cwiseMin(c) - low,
                          hi = a.cwiseMax(b).cwiseMax(c) - low;
    const int i0 = std::max(0, static_cast<int>(lo.x() / cell) - 1);
    const int i1 = std::min(nx - 1, static_cast<int>(hi.x() / cell) + 1);
    const int j0 = std::max(0, static_cast<int>(lo.y() / cell) - 1);
    const int j1 = std::min(ny - 1, static_cast<int>(hi.y() / cell) + 1);
    for (int i = i0; i <= i1; ++i)
      for (int j = j0; j <= j1; ++j) {
        const Eigen::Vector2d p = low + Eigen::Vector2d((i + 0.5) * cell, (j + 0.5) * cell);
        auto side = [&](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
          return ((v - u).x() * (p - u).y() - (v - u).y() * (p - u).x()) * twice;
        };
        if (side(a, b) >= 0 && side(b, c) >= 0 && side(c, a) >= 0)
          covered[static_cast<size_t>(i) * ny + j] = 1;
      }
  };
  for (int e = 0; e < quads.rows(); ++e) {
    auto xy = [&](int k) { return Eigen::Vector2d(positions.row(quads(e, k)).head<2>()); };
    cover(xy(0), xy(1), xy(2));
    cover(xy(0), xy(2), xy(3));
  }
  double count = 0;
  for (char c : covered) count += c;
  return count * cell * cell;
}

}  // namespace drape::test
