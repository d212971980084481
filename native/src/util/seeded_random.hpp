// Footfall — a small portable random generator (splitmix64): seeded scenes
// and SteerSuite's random placements are the same on every machine.
#pragma once

#include <cstdint>

namespace footfall {

/// Uniform numbers from a seed, the same sequence everywhere.
class SeededRandom {
 public:
  /// Starts the sequence at `seed`.
  explicit SeededRandom(std::uint64_t seed) : state_(seed) {}
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    state_ += 0x9E3779B97F4A7C15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return lo + (hi - lo) * static_cast<double>(z >> 11) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

}  // namespace footfall
