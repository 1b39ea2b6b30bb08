#include "offscreen.h"

#include <GL/osmesa.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

struct OffscreenContext::Impl {
  OSMesaContext context = nullptr;
  std::vector<uint8_t> buffer;  // RGBA, bottom row first (OSMesa's default)
};

namespace {
void* osmesa_proc(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }
}  // namespace

OffscreenContext::OffscreenContext(int width, int height)
    : impl_(std::make_unique<Impl>()), width_(width), height_(height) {
  if (width <= 0 || height <= 0 || width > 8192 || height > 8192)
    throw std::runtime_error("render size must be 1..8192 pixels a side");
  const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  impl_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (!impl_->context) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context");
  impl_->buffer.assign(static_cast<size_t>(width) * height * 4, 0);
  if (!OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, width, height))
    throw std::runtime_error("OSMesaMakeCurrent failed");
  load_gl(gl_, osmesa_proc);
}

OffscreenContext::~OffscreenContext() {
  if (impl_->context) OSMesaDestroyContext(impl_->context);
}

std::vector<uint8_t> OffscreenContext::read_rgb() const {
  gl_.Finish();
  std::vector<uint8_t> rgb(static_cast<size_t>(width_) * height_ * 3);
  for (int y = 0; y < height_; ++y) {
    const uint8_t* src = &impl_->buffer[static_cast<size_t>(height_ - 1 - y) * width_ * 4];
    uint8_t* dst = &rgb[static_cast<size_t>(y) * width_ * 3];
    for (int x = 0; x < width_; ++x) dst[3 * x] = src[4 * x], dst[3 * x + 1] = src[4 * x + 1], dst[3 * x + 2] = src[4 * x + 2];
  }
  return rgb;
}

std::string OffscreenContext::renderer_name() const {
  const auto* s = gl_.GetString(GL_RENDERER);
  const auto* v = gl_.GetString(GL_VERSION);
  return std::string(s ? reinterpret_cast<const char*>(s) : "?") + ", OpenGL " + (v ? reinterpret_cast<const char*>(v) : "?");
}

void write_png(const std::string& path, const std::vector<uint8_t>& rgb, int width, int height) {
  cv::Mat image(height, width, CV_8UC3, const_cast<uint8_t*>(rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(image, bgr, cv::COLOR_RGB2BGR);
  if (!cv::imwrite(path, bgr)) throw std::runtime_error("cannot write " + path);
}
