#include "capture/frame_set.h"

#include <algorithm>
#include <cstdlib>

namespace octocap::internal {

FrameSetDecision decide_frame_set(const std::vector<Candidate>& cameras, int64_t now_us, const FrameSetOptions& o) {
  const size_t n = cameras.size();
  FrameSetDecision d;
  d.take.assign(n, 0);
  auto offset = [&](size_t c) { return c < o.offsets_us.size() ? o.offsets_us[c] : 0; };
  auto fresh = [&](size_t c) {
    return cameras[c].newest.sequence != 0 && now_us - cameras[c].newest.arrived() <= o.max_wait_us;
  };
  bool any = false;
  int64_t set_time = 0;
  for (size_t c = 0; c < n; ++c) {
    if (!fresh(c)) continue;
    const int64_t t = cameras[c].newest.time_us - offset(c);
    set_time = any ? std::min(set_time, t) : t;
    any = true;
  }
  if (!any) return d;
  size_t in_set = 0;
  for (size_t c = 0; c < n; ++c) {
    if (!fresh(c)) continue;
    const Candidate& k = cameras[c];
    Picture best = k.newest;
    if (k.previous.sequence != 0 &&
        std::llabs(k.previous.time_us - offset(c) - set_time) < std::llabs(k.newest.time_us - offset(c) - set_time))
      best = k.previous;
    if (std::llabs(best.time_us - offset(c) - set_time) > o.tolerance_us) continue;
    d.take[c] = best.sequence;
    ++in_set;
  }
  // A camera left out is awaited when it delivered within max_wait: its next picture is about to come.
  bool awaited = false;
  for (size_t c = 0; c < n; ++c)
    if (d.take[c] == 0 && cameras[c].last_us > 0 && now_us - cameras[c].last_arrived() <= o.max_wait_us) awaited = true;
  d.emit = in_set > 0 && (in_set == n || !awaited);
  d.time_us = set_time;
  if (!d.emit) std::fill(d.take.begin(), d.take.end(), 0);
  return d;
}

}  // namespace octocap::internal
