// How a Newton iteration stands against the convergence test.
#pragma once

namespace drape {

// How an iteration stands against the convergence test.
enum class Convergence {
  kNotYet,     // iterate on
  kTolerance,  // ‖R‖/‖R₀‖ ≤ tolerance
  kRoundOff,   // ‖R‖ at the round-off floor: as converged as the arithmetic allows
  kStalled,    // the corrections stopped with the residual above both: not converged
};

// "tolerance", "round_off", "stalled", "not_converged" (result.json's words).
const char* ToString(Convergence convergence);

}  // namespace drape
