// The parts of an MJPEG camera's multipart/x-mixed-replace HTTP body, cut as the bytes arrive. Only the newest whole
// part is kept: a reader that falls behind the camera skips the parts in between (counted) instead of letting them
// queue, so latency and memory stay bounded. A part is bounded too: one announcing, or growing past, more bytes than
// any picture has is refused at once.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace octocap::internal {

class MultipartReader {
 public:
  static constexpr size_t kMaxPartBytes = 64u << 20;  // 64 MB: an 8K JPEG at top quality is a fraction of that

  // `boundary` as the Content-Type header's boundary= gives it (quotes and a leading "--" are tolerated, as cameras
  // send either); empty: the first line starting with "--" gives it.
  explicit MultipartReader(std::string boundary);

  // Takes the next bytes of the body. Throws Error(io) for a part larger than kMaxPartBytes.
  void feed(const char* data, size_t size);
  // The newest whole part not yet taken, if any (swapped into `body`).
  bool take(std::vector<unsigned char>& body);
  // Whole parts a newer one replaced before they were taken.
  uint64_t skipped() const { return skipped_; }

 private:
  void parse();
  bool delimiter_at(size_t line_start, size_t line_end) const;
  void finish_part(size_t begin, size_t end);

  std::string boundary_;  // without the leading "--"
  std::string buffer_;    // bytes not yet cut into parts
  enum class State { seeking_delimiter, headers, body } state_ = State::seeking_delimiter;
  size_t content_length_ = 0;  // of the part being read; 0: unknown, it ends at the next delimiter
  bool has_length_ = false;
  std::vector<unsigned char> newest_;
  bool has_newest_ = false;
  uint64_t skipped_ = 0;
};

}  // namespace octocap::internal
