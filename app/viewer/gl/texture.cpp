#include "viewer/gl/texture.h"

#include "viewer/gl/gl_api.h"

namespace meshtrace::gl {

Texture::~Texture() {
  if (id_) glDeleteTextures(1, &id_);
}

void Texture::resize(int width, int height) {
  if (id_ && width == width_ && height == height_) return;
  if (!id_) glGenTextures(1, &id_);
  width_ = width;
  height_ = height;
  glBindTexture(GL_TEXTURE_2D, id_);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  // Magnified pixels stay sharp squares: the inspector points at pixels.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
}

void Texture::upload(const std::uint8_t* rows, int x0, int y0, int x1, int y1) {
  if (!id_ || x1 <= x0 || y1 <= y0) return;
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, width_);
  glTexSubImage2D(GL_TEXTURE_2D, 0, x0, y0, x1 - x0, y1 - y0, GL_RGBA, GL_UNSIGNED_BYTE,
                  rows + static_cast<std::size_t>(x0) * 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
}

std::vector<std::unique_ptr<Texture>> textureKinds() {
  std::vector<std::unique_ptr<Texture>> kinds;
  const std::uint8_t white[4 * 9] = {255, 255, 255, 255};
  for (const int width : {1, 3})
    for (const int height : {1, 3}) {
      auto t = std::make_unique<Texture>();
      t->resize(width, height);
      t->uploadAll(white);
      kinds.push_back(std::move(t));
    }
  return kinds;
}

}  // namespace meshtrace::gl
