#include "capture/frame_set.h"

#include <algorithm>

namespace octocap {

FrameSetDecision decide_frame_set(const std::vector<Candidate>& cameras, int64_t now_us, const FrameSetOptions& o) {
  const size_t n = cameras.size();
  FrameSetDecision d;
  d.take.assign(n, false);
  d.discard.assign(n, false);
  auto corrected = [&](size_t c) {
    return cameras[c].time_us - (c < o.offsets_us.size() ? o.offsets_us[c] : 0);
  };
  bool any = false;
  int64_t newest = 0;
  for (size_t c = 0; c < n; ++c)
    if (cameras[c].present) newest = any ? std::max(newest, corrected(c)) : corrected(c), any = true;
  if (!any) return d;
  // The set is anchored on the newest picture: anything older than the tolerance can never join a set again.
  size_t in_set = 0;
  int64_t sum = 0;
  for (size_t c = 0; c < n; ++c) {
    if (!cameras[c].present) continue;
    const int64_t t = corrected(c);
    if (newest - t > o.tolerance_us) {
      d.discard[c] = true;
      continue;
    }
    d.take[c] = true;
    ++in_set;
    sum += t;
  }
  // Waiting is measured on the raw grab clock: offsets shift which pictures match, not how long one has waited.
  bool awaited = false;
  for (size_t c = 0; c < n; ++c)
    if (!d.take[c] && cameras[c].last_us > 0 && now_us - cameras[c].last_us <= o.max_wait_us) awaited = true;
  d.emit = !awaited;
  d.time_us = in_set ? sum / static_cast<int64_t>(in_set) : newest;
  if (!d.emit) std::fill(d.take.begin(), d.take.end(), false);
  return d;
}

}  // namespace octocap
