#include "core/take_timing.h"

#include <algorithm>
#include <cmath>

namespace octocap::internal {

bool times_increase(const std::vector<double>& times_s) {
  for (size_t i = 0; i < times_s.size(); ++i)
    if (!std::isfinite(times_s[i]) || (i > 0 && !(times_s[i] > times_s[i - 1]))) return false;
  return true;
}

double mean_rate(const std::vector<double>& times_s) {
  if (times_s.size() < 2 || !(times_s.back() > times_s.front())) return 0;
  return static_cast<double>(times_s.size() - 1) / (times_s.back() - times_s.front());
}

bool evenly_spaced(const std::vector<double>& times_s, double rate_hz) {
  if (!(rate_hz > 0)) return false;
  const double period = 1.0 / rate_hz;
  for (size_t f = 0; f < times_s.size(); ++f)
    if (std::abs(times_s[f] - times_s.front() - static_cast<double>(f) * period) > 0.25 * period) return false;
  return true;
}

double max_interpolated_gap_s(double rate_hz) { return std::max(0.25, 2.5 / rate_hz); }

std::vector<Resampled> resample_plan(const std::vector<double>& times_s, double rate_hz, double max_gap_s) {
  std::vector<Resampled> plan;
  if (times_s.empty() || !(rate_hz > 0)) return plan;
  const double start = times_s.front(), span = times_s.back() - start;
  // A hair of tolerance: the last frame of a take whose span is a whole number of periods is kept.
  const size_t count = static_cast<size_t>(std::floor(span * rate_hz + 1e-6)) + 1;
  plan.reserve(count);
  size_t i = 0;
  for (size_t k = 0; k < count; ++k) {
    const double t = start + static_cast<double>(k) / rate_hz;
    while (i + 1 < times_s.size() && times_s[i + 1] <= t) ++i;
    Resampled r;
    r.before = i;
    r.after = std::min(i + 1, times_s.size() - 1);
    const double dt = times_s[r.after] - times_s[r.before];
    r.weight = dt > 0 ? std::clamp((t - times_s[r.before]) / dt, 0.0, 1.0) : 0.0;
    // On an input frame (within a microsecond) it is that frame, whatever the gap after it.
    if (t - times_s[r.before] < 1e-6) r.after = r.before, r.weight = 0;
    else if (times_s[r.after] - t < 1e-6) r.before = r.after, r.weight = 0;
    else r.gap = dt > max_gap_s;
    plan.push_back(r);
  }
  return plan;
}

}  // namespace octocap::internal
