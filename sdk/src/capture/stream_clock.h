// When a live camera's picture was captured. A picture is stamped when it has been decoded, late by however long the
// host took: a busy host decodes some pictures late and in bursts, and their grab times then no longer say when
// they were captured, so frame sets would pair pictures of different instants. Where the stream has timestamps of
// its own (RTP's, for RTSP), capture = stream time + the least (grab - stream) seen: the least-delayed pictures show
// the offset between the two clocks. The stream's clock is trusted once that least offset held still (within 10 ms)
// from one second to the next, so a stream whose timestamps run at another rate than real time (a made-up frame
// count) is never trusted; a jump in it (a reconnect, RTCP taking over) starts again; a few seconds in which every
// picture came late (a busy host) keep it. Untrusted: the grab time.
#pragma once
#include <algorithm>
#include <cstdint>

namespace octocap::internal {

class StreamClock {
 public:
  int64_t capture_us(int64_t grab_us, int64_t stream_us) {
    const int64_t d = grab_us - stream_us;
    if (!started_ || stream_us < last_stream_ || stream_us - last_stream_ > kSecond || grab_us - last_grab_ > kSecond) {
      started_ = true;
      trusted_ = false;
      busy_seconds_ = 0;
      base_ = window_min_ = d;
      window_start_ = grab_us;
      has_previous_window_ = false;
    } else {
      // The least offset may creep up by 1 ms a second: the camera's clock and the host's differ a little in rate.
      base_ = std::min(base_ + (grab_us - last_grab_) / 1000, d);
      window_min_ = std::min(window_min_, d);
      if (grab_us - window_start_ >= kSecond) {
        const bool steady = has_previous_window_ && std::llabs(window_min_ - previous_window_min_) <= kSteady;
        // A trusted clock outlives a few seconds whose pictures all came late (a busy host decoded none promptly):
        // their least offset is higher, but that is the host, not the camera's clock. Dropping the trust there put
        // the camera on grab times for a second or more, paired with the others' pictures of other instants. A rise
        // that lasts longer than kBusySeconds is the clocks disagreeing.
        const bool busy = trusted_ && !steady && window_min_ > previous_window_min_ && busy_seconds_ < kBusySeconds;
        busy_seconds_ = busy ? busy_seconds_ + 1 : 0;
        trusted_ = steady || busy;
        if (has_previous_window_ && !trusted_) base_ = d;  // the clocks do not agree: start the least offset again
        if (!busy) previous_window_min_ = window_min_;  // a busy second is no reference for the next
        has_previous_window_ = true;
        window_min_ = d;
        window_start_ = grab_us;
      }
    }
    last_stream_ = stream_us;
    last_grab_ = grab_us;
    return trusted_ ? std::min(grab_us, stream_us + base_) : grab_us;
  }
  void reset() { started_ = false; }
  bool trusted() const { return trusted_; }

 private:
  static constexpr int64_t kSecond = 1000000, kSteady = 10000;
  static constexpr int kBusySeconds = 3;
  bool started_ = false, trusted_ = false, has_previous_window_ = false;
  int64_t last_stream_ = 0, last_grab_ = 0, base_ = 0;
  int64_t window_start_ = 0, window_min_ = 0, previous_window_min_ = 0;
  int busy_seconds_ = 0;
};

}  // namespace octocap::internal
