#include "footfall/animate/key_thinning.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace footfall::animate {
namespace {

// Each sample's slope per channel (row-major): three-point, flat where the
// motion turns or halts, bounded as Fritsch and Carlson bound it.
std::vector<double> sample_slopes(const std::vector<double>& times, const std::vector<double>& values,
                                  std::size_t channels) {
  const std::size_t count = times.size();
  std::vector<double> slopes(values.size(), 0.0);
  if (count < 2) return slopes;
  auto secant = [&](std::size_t k, std::size_t c) {
    return (values[(k + 1) * channels + c] - values[k * channels + c]) / (times[k + 1] - times[k]);
  };
  for (std::size_t c = 0; c < channels; ++c) {
    slopes[c] = secant(0, c);
    slopes[(count - 1) * channels + c] = secant(count - 2, c);
    for (std::size_t k = 1; k + 1 < count; ++k) {
      const double before = secant(k - 1, c), after = secant(k, c);
      if (before * after <= 0.0) continue;  // a turn or a halt: flat
      // The three-point slope, held to three times the smaller secant (so
      // that the curve between samples keeps to their side of a halt).
      const double h0 = times[k] - times[k - 1], h1 = times[k + 1] - times[k];
      const double central = (h1 * before + h0 * after) / (h0 + h1);
      const double limit = 3 * std::min(std::fabs(before), std::fabs(after));
      slopes[k * channels + c] = std::copysign(std::min(std::fabs(central), limit), central);
    }
  }
  return slopes;
}

// A channel of a sample is still where it equals the sample before or after:
// the curve must keep it (up to rounding), not merely pass near it.
constexpr double kStill = 1e-12;

bool is_still(const std::vector<double>& values, std::size_t channels, std::size_t s, std::size_t c,
              std::size_t count) {
  const double here = values[s * channels + c];
  return (s > 0 && values[(s - 1) * channels + c] == here) ||
         (s + 1 < count && values[(s + 1) * channels + c] == here);
}

// True if the curve from sample a to sample b (cubic Hermite with the
// slopes, or straight) passes within the tolerance of every sample between
// them (and keeps every still one).
bool curve_fits(const std::vector<double>& times, const std::vector<double>& values,
                const std::vector<double>& slopes, const std::vector<double>& tolerance,
                const std::vector<double>& sample_scale, KeyCurve kind, std::size_t a, std::size_t b) {
  const std::size_t channels = tolerance.size(), count = times.size();
  const double span = times[b] - times[a];
  for (std::size_t s = a + 1; s < b; ++s) {
    const double u = (times[s] - times[a]) / span, u2 = u * u, u3 = u2 * u;
    const bool cubic = kind == KeyCurve::kCubic;
    const double from = cubic ? 2 * u3 - 3 * u2 + 1 : 1 - u, to = cubic ? 3 * u2 - 2 * u3 : u;
    const double leave = cubic ? (u3 - 2 * u2 + u) * span : 0.0, arrive = cubic ? (u3 - u2) * span : 0.0;
    for (std::size_t c = 0; c < channels; ++c) {
      const double curve = from * values[a * channels + c] + leave * slopes[a * channels + c] +
                           to * values[b * channels + c] + arrive * slopes[b * channels + c];
      const double off = std::fabs(values[s * channels + c] - curve);
      if (off > tolerance[c] * (sample_scale.empty() ? 1.0 : sample_scale[s])) return false;
      if (off > kStill * (1 + std::fabs(curve)) && is_still(values, channels, s, c, count)) return false;
    }
  }
  return true;
}

}  // namespace

ThinnedKeys keys_to_keep(const std::vector<double>& times, const std::vector<double>& values,
                         const std::vector<double>& tolerance, KeyCurve curve,
                         const std::vector<double>& sample_scale) {
  const std::size_t count = times.size(), channels = tolerance.size();
  if (channels == 0) throw std::invalid_argument("keys_to_keep: needs at least one channel");
  if (values.size() != count * channels)
    throw std::invalid_argument("keys_to_keep: values must have one row of every channel per time");
  for (const double t : tolerance)
    if (!(std::isfinite(t) && t > 0.0)) throw std::invalid_argument("keys_to_keep: tolerances must be > 0");
  for (std::size_t i = 0; i < count; ++i)
    if (!std::isfinite(times[i]) || (i > 0 && !(times[i] > times[i - 1])))
      throw std::invalid_argument("keys_to_keep: times must be finite and increasing");
  for (const double v : values)
    if (!std::isfinite(v)) throw std::invalid_argument("keys_to_keep: values must be finite");
  if (!sample_scale.empty() && sample_scale.size() != count)
    throw std::invalid_argument("keys_to_keep: one scale per sample, or none");
  for (const double k : sample_scale)
    if (!(std::isfinite(k) && k > 0.0)) throw std::invalid_argument("keys_to_keep: scales must be > 0");
  const std::vector<double> slopes = sample_slopes(times, values, channels);
  std::vector<std::size_t> kept(count);
  for (std::size_t i = 0; i < count; ++i) kept[i] = i;
  std::size_t first = 1;
  for (int idle = 0; idle < 2 && kept.size() > 2;) {
    std::vector<std::size_t> next;
    next.reserve(kept.size());
    bool dropped = false;
    for (std::size_t m = 0; m < kept.size(); ++m) {
      const bool may_go = m >= first && (m - first) % 2 == 0 && m + 1 < kept.size();
      if (may_go && curve_fits(times, values, slopes, tolerance, sample_scale, curve, kept[m - 1], kept[m + 1])) {
        dropped = true;
        continue;
      }
      next.push_back(kept[m]);
    }
    kept.swap(next);
    first = 3 - first;
    idle = dropped ? 0 : idle + 1;
  }
  ThinnedKeys keys{kept, {}};
  keys.slopes.reserve(kept.size() * channels);
  for (const std::size_t k : kept)
    keys.slopes.insert(keys.slopes.end(), slopes.begin() + k * channels, slopes.begin() + (k + 1) * channels);
  return keys;
}

}  // namespace footfall::animate
