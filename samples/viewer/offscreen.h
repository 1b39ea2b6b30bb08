// A headless OpenGL 3.3 core context (OSMesa, software llvmpipe): no display needed.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl_api.h"

class OffscreenContext {
 public:
  // Throws std::runtime_error when OSMesa cannot make a 3.3 core context.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  const GlApi& gl() const { return gl_; }
  int width() const { return width_; }
  int height() const { return height_; }
  // The frame as RGB rows, top row first.
  std::vector<uint8_t> read_rgb() const;
  std::string renderer_name() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  GlApi gl_{};
  int width_, height_;
};

// Writes RGB rows (top first) as PNG; throws std::runtime_error on failure.
void write_png(const std::string& path, const std::vector<uint8_t>& rgb, int width, int height);
