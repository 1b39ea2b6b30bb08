// Picture buffers written again once nobody holds them. A decoder that writes each frame into a fresh buffer pays the
// kernel for new zeroed pages every time: a 1088x1920 BGR picture is 6 MB, and solving four such videos spent about a
// sixth of its CPU in page faults and their clearing. The pool hands out a buffer whose only holder is the pool (the
// decoder writes into it in place) and never one a consumer still holds: that consumer's pixels stay as they were.
#pragma once
#include <opencv2/core.hpp>
#include <vector>

namespace octocap::internal {

class PicturePool {
 public:
  // `slots`: how many pictures may be in flight at once (being decoded, waiting, being read) before the pool
  // allocates; more in flight is still correct, only slower.
  explicit PicturePool(size_t slots = 4) : slots_(slots == 0 ? 1 : slots) {}

  // A picture to decode into: a held-by-nobody buffer of an earlier frame (decoding the same size into it reuses its
  // memory), or an empty one when every buffer is still held.
  cv::Mat& next() {
    for (size_t i = 0; i < slots_.size(); ++i) {
      cv::Mat& m = slots_[(turn_ + i) % slots_.size()];
      if (held_by_pool_only(m)) {
        turn_ = (turn_ + i + 1) % slots_.size();
        return m;
      }
    }
    cv::Mat& m = slots_[turn_];
    m.release();  // the holders keep that buffer; this slot gets a new one
    turn_ = (turn_ + 1) % slots_.size();
    return m;
  }

 private:
  static bool held_by_pool_only(const cv::Mat& m) {
    if (m.u == nullptr) return true;  // empty: nothing to keep
    // Acquire: a consumer's last read of these pixels, on another thread, happens before our next write. OpenCV drops
    // a reference with an atomic decrement; a plain read here would race with it.
    return __atomic_load_n(&m.u->refcount, __ATOMIC_ACQUIRE) == 1;
  }
  std::vector<cv::Mat> slots_;
  size_t turn_ = 0;
};

}  // namespace octocap::internal
