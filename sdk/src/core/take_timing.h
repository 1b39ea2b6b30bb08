// When a take's frames happened, and how to put them on a fixed rate: a live take's frame sets come when the cameras
// and the host allow, not every 1/rate seconds, while TRC and BVH readers take row k to be at k / rate.
#pragma once
#include <cstddef>
#include <vector>

namespace octocap::internal {

// Times (seconds) that strictly increase: the only ones that say when frames happened.
bool times_increase(const std::vector<double>& times_s);

// The mean rate of frames at `times_s` (increasing, two or more): (n - 1) / span.
double mean_rate(const std::vector<double>& times_s);

// Whether frame f sits at times_s[0] + f / rate_hz within a quarter of a period, for every f.
bool evenly_spaced(const std::vector<double>& times_s, double rate_hz);

// One frame of a fixed-rate track: (1 - weight) of input frame `before` and `weight` of input frame `after`;
// `gap` when the input has no frame within `max_gap_s` on both sides (nothing there to interpolate: a take that
// stalled, or a person who was away), which the track writes as missing.
struct Resampled {
  size_t before = 0, after = 0;
  double weight = 0;
  bool gap = false;
};

// Frames at times_s[0] + k / rate_hz for every k up to the last input time. `times_s` must increase.
std::vector<Resampled> resample_plan(const std::vector<double>& times_s, double rate_hz, double max_gap_s);

// The longest stretch between two input frames that is interpolated over: a quarter of a second, or two and a half
// output periods at slow rates.
double max_interpolated_gap_s(double rate_hz);

}  // namespace octocap::internal
