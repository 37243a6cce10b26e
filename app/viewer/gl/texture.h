#pragma once
// An RGBA8 texture the viewer draws images with, updated in rectangles.
#include <cstdint>
#include <memory>
#include <vector>

namespace meshtrace::gl {

class Texture {
 public:
  Texture() = default;
  ~Texture();
  Texture(const Texture&) = delete;
  Texture& operator=(const Texture&) = delete;

  // (Re)allocates when the size changes; contents are then undefined.
  void resize(int width, int height);
  // Uploads rows [y0, y1) and columns [x0, x1) from `rows`: RGBA rows as
  // wide as the texture, stored top row first (rows are drawn top first
  // too), the first of them row y0.
  void upload(const std::uint8_t* rows, int x0, int y0, int x1, int y1);
  void uploadAll(const std::uint8_t* rgba) { upload(rgba, 0, 0, width_, height_); }

  unsigned id() const { return id_; }
  int width() const { return width_; }
  int height() const { return height_; }
  bool valid() const { return id_ != 0 && width_ > 0; }

 private:
  unsigned id_ = 0;
  int width_ = 0, height_ = 0;
};

// A small texture of each kind that decides which shader the software
// rasteriser (llvmpipe) compiles to draw an image: sides a power of two or
// not, across and down. Drawn once before the window is shown, they have
// those shaders compiled there rather than in a frame, where a compile
// (with no shader cache yet) is longer than a frame may take.
std::vector<std::unique_ptr<Texture>> textureKinds();

}  // namespace meshtrace::gl
