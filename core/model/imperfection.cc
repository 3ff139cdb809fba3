#include "core/model/imperfection.h"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

namespace drape {
namespace {

constexpr double kTwoPi = 6.28318530717958647692;

// Plane waves in the smooth pattern: enough that the surface shows no single
// dominant direction, few enough to evaluate cheaply.
constexpr int kWaveCount = 16;

// Shortest text that reads back as `value` (0.1, not 0.10000000000000001).
std::string Format(double value) {
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string Violation(const char* name, double value, const char* constraint) {
  return std::string("ImperfectionOffsets: ") + name + " = " + Format(value) +
         ". Violated constraint: " + constraint;
}

struct PlaneWave {
  double kx = 0, ky = 0;  // wave vector [1/m]
  double phase = 0;       // [rad]
  double weight = 0;      // > 0
};

}  // namespace

std::uint64_t SplitMix64::Next() {
  state_ += 0x9E3779B97F4A7C15ULL;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double SplitMix64::NextUniform() {
  return static_cast<double>(Next() >> 11) * 0x1.0p-53;
}

Eigen::VectorXd ImperfectionOffsets(const Eigen::Matrix<double, Eigen::Dynamic, 2>& xy,
                                    double amplitude,
                                    std::uint64_t seed,
                                    ImperfectionPattern pattern,
                                    double wavelength) {
  if (!(std::isfinite(amplitude) && amplitude >= 0))
    throw std::invalid_argument(Violation("amplitude", amplitude, "finite and >= 0"));
  const Eigen::Index n = xy.rows();
  Eigen::VectorXd offsets(n);
  SplitMix64 random(seed);
  if (pattern == ImperfectionPattern::kNodal) {
    for (Eigen::Index i = 0; i < n; ++i)
      offsets[i] = amplitude * (2.0 * random.NextUniform() - 1.0);
    return offsets;
  }

  if (!(std::isfinite(wavelength) && wavelength > 0))
    throw std::invalid_argument(Violation("wavelength", wavelength, "finite and > 0"));
  // z(x) = amplitude / Σ w_k · Σ w_k cos(k_k · x + φ_k): |z| <= amplitude
  // everywhere, and z depends on (x, y) only, never on the mesh.
  std::array<PlaneWave, kWaveCount> waves;
  double weight_sum = 0;
  for (PlaneWave& wave : waves) {
    const double direction = kTwoPi * random.NextUniform();
    const double length = (0.5 + random.NextUniform()) * wavelength;  // in [0.5, 1.5) λ
    wave.kx = kTwoPi / length * std::cos(direction);
    wave.ky = kTwoPi / length * std::sin(direction);
    wave.phase = kTwoPi * random.NextUniform();
    wave.weight = 0.5 + 0.5 * random.NextUniform();  // in [0.5, 1): no wave vanishes
    weight_sum += wave.weight;
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    double sum = 0;
    for (const PlaneWave& wave : waves)
      sum += wave.weight * std::cos(wave.kx * xy(i, 0) + wave.ky * xy(i, 1) + wave.phase);
    // sum / weight_sum rounds to at most 1 in magnitude, so the bound holds
    // in floating point too.
    offsets[i] = amplitude * (sum / weight_sum);
  }
  return offsets;
}

}  // namespace drape
