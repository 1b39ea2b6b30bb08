#include "capture/jpeg_decoder.h"

#include <turbojpeg.h>

#include "core/error.h"

namespace octocap::internal {

JpegDecoder::JpegDecoder() : handle_(tjInitDecompress()) {
  if (handle_ == nullptr) throw Error(Errc::out_of_memory, "cannot start a JPEG decoder");
}

JpegDecoder::~JpegDecoder() { tjDestroy(handle_); }

bool JpegDecoder::decode(const std::vector<unsigned char>& jpeg, cv::Mat& bgr) {
  if (jpeg.size() < 4 || jpeg[0] != 0xFF || jpeg[1] != 0xD8) {
    why_ = "a part of " + std::to_string(jpeg.size()) + " bytes is not a JPEG picture";
    return false;
  }
  int width = 0, height = 0, subsampling = 0, colorspace = 0;
  if (tjDecompressHeader3(handle_, jpeg.data(), jpeg.size(), &width, &height, &subsampling, &colorspace) != 0) {
    why_ = std::string("a JPEG picture's header is unreadable: ") + tjGetErrorStr2(handle_);
    return false;
  }
  if (width <= 0 || height <= 0 || static_cast<long>(width) * height > kMaxPixels) {
    why_ = "a JPEG picture of " + std::to_string(width) + "x" + std::to_string(height) + " is larger than any camera's";
    return false;
  }
  bgr.create(height, width, CV_8UC3);
  if (tjDecompress2(handle_, jpeg.data(), jpeg.size(), bgr.data, width, static_cast<int>(bgr.step), height, TJPF_BGR,
                    0) == 0)
    return true;
  const std::string message = tjGetErrorStr2(handle_);
  // Stray bytes between segments are harmless (some cameras always send them); anything else means pixels were
  // lost, and a smeared picture would mislead the detector.
  if (tjGetErrorCode(handle_) == TJERR_WARNING && message.find("extraneous bytes") != std::string::npos) return true;
  why_ = "a corrupt JPEG picture: " + message;
  return false;
}

}  // namespace octocap::internal
