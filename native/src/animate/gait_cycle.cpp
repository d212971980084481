#include "footfall/animate/gait_cycle.hpp"

#include <cmath>
#include <complex>

#include "footfall/model/geometry.hpp"

namespace footfall::animate {

namespace {

constexpr int kMaxCycles = 4;       // a clip holds at most this many gait cycles
constexpr double kMinSwing = 0.05;  // of the leg's length: feet (or hands) parting by less show no cycle

// The strongest of the first kMaxCycles harmonics of a signal sampled evenly
// over one period: its number, amplitude, and the fraction of a cycle at
// which it peaks.
struct Harmonic {
  int cycles = 1;
  double amplitude = 0;
  double peak = 0;
};

Harmonic dominant(const std::vector<double>& signal) {
  const std::size_t n = signal.size();
  double mean = 0;
  for (double v : signal) mean += v / static_cast<double>(n);
  Harmonic best;
  for (int k = 1; k <= kMaxCycles && static_cast<std::size_t>(2 * k) <= n; ++k) {
    std::complex<double> sum = 0;
    for (std::size_t i = 0; i < n; ++i)
      sum += (signal[i] - mean) * std::polar(1.0, -2 * kPi * k * static_cast<double>(i) / static_cast<double>(n));
    const double amplitude = 2.0 * std::abs(sum) / static_cast<double>(n);
    if (amplitude > best.amplitude) {
      // signal ~ A cos(2 pi k t - theta): peaks at t = theta / (2 pi k).
      double peak = std::fmod(-std::arg(sum) / (2 * kPi), 1.0);
      if (peak < 0) peak += 1.0;
      best = {k, amplitude, peak};
    }
  }
  return best;
}

}  // namespace

GaitCycle find_gait_cycle(const std::vector<double>& feet, const std::vector<double>& hands, double leg_length) {
  for (const auto& [signal, source] : {std::make_pair(&feet, "feet"), std::make_pair(&hands, "hands")}) {
    if (signal->size() < 2) continue;
    const Harmonic h = dominant(*signal);
    if (h.amplitude >= kMinSwing * leg_length) return {h.cycles, h.peak, source};
  }
  return {};
}

}  // namespace footfall::animate
