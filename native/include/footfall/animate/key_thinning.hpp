// Footfall — fewer keys for a motion sampled at every frame: the samples
// that Bezier curves between them (cubic Hermite, with slopes from the
// samples) need to pass near every other.
#pragma once

#include <cstddef>
#include <vector>

namespace footfall::animate {

/// How a curve goes from one key to the next.
enum class KeyCurve {
  kLinear,  ///< Straight.
  kCubic,   ///< Cubic Hermite with the keys' slopes (a Bezier segment, handles a third along them).
};

/// Keys for a sampled motion: which samples, and each one's slope per channel.
struct ThinnedKeys {
  std::vector<std::size_t> kept;  ///< Indices of the samples, increasing, the first and last among them.
  std::vector<double> slopes;     ///< Per kept sample, per channel (row-major): d value / d time.
};

/// The samples to key so that the `curve`s between consecutive kept samples
/// (cubic ones with their slopes) pass within `tolerance[c]` of every
/// sample's channel c (times `sample_scale[s]` at sample s, if given: a
/// looser fit where the motion is fast), and through every one that stands still (equal to the
/// sample before or after it), up to rounding. The slopes are the samples' own: three-point, but 0
/// where the motion turns or halts (so a stretch that stands still is
/// exactly still between its ends) and at most three times the smaller
/// secant beside it (Fritsch and Carlson's bound against overshoot).
/// `times` has n increasing entries, `values` n rows of `tolerance.size()`
/// channels (row-major). Throws std::invalid_argument for sizes that
/// differ, no channel, times not finite and increasing, a value not finite,
/// or a tolerance or scale that is not a finite number > 0.
///
/// Bottom up: every other kept sample is dropped at once where the curve over
/// its two kept neighbours fits every sample between them, the odd ones and
/// the even ones by turns, until neither drops any: about 2 log2(n) passes,
/// each over the samples once.
ThinnedKeys keys_to_keep(const std::vector<double>& times, const std::vector<double>& values,
                         const std::vector<double>& tolerance, KeyCurve curve = KeyCurve::kCubic,
                         const std::vector<double>& sample_scale = {});

}  // namespace footfall::animate
