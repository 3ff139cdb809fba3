// What the machine gives a run: memory, and the threads the element assembly
// (OpenMP) runs on.
#pragma once

namespace drape {

// The memory available to a new allocation [bytes] (Linux MemAvailable);
// +∞ where that cannot be read.
double AvailableMemoryBytes();
// The most memory this process has held resident so far [bytes].
double PeakMemoryBytes();

// Sets the assembly's threads to `requested` (0: leave OpenMP's choice) and
// returns how many it will use.
int UseAssemblyThreads(int requested);

}  // namespace drape
