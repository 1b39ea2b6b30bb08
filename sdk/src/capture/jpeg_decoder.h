// JPEG pictures from a camera's bytes, through libjpeg-turbo's TurboJPEG API: a picture whose data is corrupt (bits
// lost on the wire, a truncated part) is reported as such rather than decoded into a smeared one, and nothing is
// printed (libjpeg's own warnings go to stderr through OpenCV's imdecode).
#pragma once
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace octocap::internal {

class JpegDecoder {
 public:
  static constexpr long kMaxPixels = 8192L * 8192L;

  JpegDecoder();
  ~JpegDecoder();
  JpegDecoder(const JpegDecoder&) = delete;
  JpegDecoder& operator=(const JpegDecoder&) = delete;

  // Decodes `jpeg` into `bgr` (its buffer reused when the size matches). False, with why() set, for bytes that are
  // not a JPEG, a picture larger than kMaxPixels, or data the decoder found corrupt.
  bool decode(const std::vector<unsigned char>& jpeg, cv::Mat& bgr);
  const std::string& why() const { return why_; }

 private:
  void* handle_;
  std::string why_;
};

}  // namespace octocap::internal
