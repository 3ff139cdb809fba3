// Reproducible out-of-plane waviness of the reference surface.
//
// Real fabric is never perfectly flat; a tiny waviness picks one of several
// equilibrium modes where a perfectly flat sheet sits on a bifurcation (the
// paper's block drape, Fig. 9). The same seed gives the same surface on every
// platform: the generator is our own (SplitMix64), not a std:: distribution,
// whose output is implementation-defined.
#pragma once

#include <Eigen/Core>

#include <cstdint>

namespace drape {

enum class ImperfectionPattern {
  kSmooth,  // a sum of random plane waves: a function of (x, y), so the same at any mesh density
  kNodal,   // each node independently uniform in [-amplitude, amplitude] (the paper's study)
};

// Small deterministic PRNG (SplitMix64, Steele, Lea & Flood 2014).
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t Next();
  // Uniform in [0, 1) with 53 random bits.
  double NextUniform();

 private:
  std::uint64_t state_;
};

// Out-of-plane offsets, one per row of `xy` (reference x, y [m]); every offset
// lies in [-amplitude, amplitude]. `wavelength` [m] is the typical wavelength
// of the smooth pattern (ignored for kNodal).
Eigen::VectorXd ImperfectionOffsets(const Eigen::Matrix<double, Eigen::Dynamic, 2>& xy,
                                    double amplitude,
                                    std::uint64_t seed,
                                    ImperfectionPattern pattern,
                                    double wavelength);

}  // namespace drape
