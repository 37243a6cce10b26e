#pragma once
// An offscreen OpenGL context through OSMesa (Mesa's software rasteriser),
// for headless snapshots. libOSMesa is opened at run time, so the windowed
// viewer never loads it next to libGL.
#include <cstdint>
#include <string>
#include <vector>

namespace meshtrace::gl {

class OffscreenContext {
 public:
  // Creates a core-profile context drawing into a width x height RGBA
  // buffer, makes it current and loads the GL functions. Throws
  // std::runtime_error saying what failed.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void* library_ = nullptr;
  void* context_ = nullptr;
  int width_, height_;
  std::vector<std::uint8_t> buffer_;
};

// Reads the current framebuffer as RGB, top row first.
std::vector<std::uint8_t> readFramebufferRgb(int width, int height);

}  // namespace meshtrace::gl
