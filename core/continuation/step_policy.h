// How long the next step is: the paper's acceleration. A step that took N
// iterations is followed by one γ = N_p / N times as long (N_p the target),
// γ bounded so that no step grows or shrinks too fast. Off, every step keeps
// its length (cut-backs aside).
#pragma once

namespace drape {

struct StepPolicy {
  bool acceleration = true;
  int target_iterations = 7;      // N_p
  double min_step_growth = 0.25;  // bounds on γ
  double max_step_growth = 4.0;

  // The next step's length (or increment) after one of `length` that took
  // `iterations` iterations.
  double Next(double length, int iterations) const;
};

}  // namespace drape
