#include "viewer/model/image_viewport.h"

#include <algorithm>
#include <cmath>

namespace meshtrace::viewer {

void ImageViewport::layout(const ScreenRect& area, int width, int height) {
  if ((width != width_ || height != height_) && !keepCenter_) {
    centerCol_ = width / 2.0;
    centerRow_ = height / 2.0;
  }
  keepCenter_ = false;
  area_ = area;
  width_ = width;
  height_ = height;
  if (fit_ && width > 0 && height > 0) {
    zoom_ = std::max(kMinZoom, std::min(double(area.width) / width, double(area.height) / height));
    centerCol_ = width / 2.0;
    centerRow_ = height / 2.0;
  }
  place();
}

void ImageViewport::place() {
  // Whole screen pixels: image pixels then map onto screen pixels the same
  // way everywhere, and a grid line falls between two of them.
  originX_ = std::round(area_.x + area_.width / 2.0 - centerCol_ * zoom_);
  originY_ = std::round(area_.y + area_.height / 2.0 - centerRow_ * zoom_);
}

void ImageViewport::actualSize() {
  fit_ = false;
  zoom_ = 1.0;
  centerCol_ = width_ / 2.0;
  centerRow_ = height_ / 2.0;
  place();
}

void ImageViewport::zoomTo(double zoom, double col, double row) {
  fit_ = false;
  keepCenter_ = true;
  zoom_ = std::clamp(zoom, kMinZoom, kMaxZoom);
  centerCol_ = col;
  centerRow_ = row;
  place();
}

void ImageViewport::zoomAt(double factor, float sx, float sy) {
  const double col = (sx - originX_) / zoom_, row = (sy - originY_) / zoom_;
  fit_ = false;
  zoom_ = std::clamp(zoom_ * factor, kMinZoom, kMaxZoom);
  // The centre moves so that (col, row) stays under (sx, sy).
  centerCol_ = col - (sx - (area_.x + area_.width / 2.0)) / zoom_;
  centerRow_ = row - (sy - (area_.y + area_.height / 2.0)) / zoom_;
  place();
}

void ImageViewport::panBy(float dx, float dy) {
  fit_ = false;
  centerCol_ -= dx / zoom_;
  centerRow_ -= dy / zoom_;
  // Some of the image stays in view.
  centerCol_ = std::clamp(centerCol_, 0.0, double(width_));
  centerRow_ = std::clamp(centerRow_, 0.0, double(height_));
  place();
}

ScreenRect ImageViewport::imageRect() const {
  return {originX_, originY_, float(width_ * zoom_), float(height_ * zoom_)};
}

std::optional<std::pair<int, int>> ImageViewport::pixelAt(float sx, float sy) const {
  if (sx < area_.x || sy < area_.y || sx >= area_.x + area_.width || sy >= area_.y + area_.height)
    return std::nullopt;
  const double col = std::floor((sx - originX_) / zoom_), row = std::floor((sy - originY_) / zoom_);
  if (col < 0 || row < 0 || col >= width_ || row >= height_) return std::nullopt;
  return std::make_pair(static_cast<int>(col), static_cast<int>(row));
}

std::pair<float, float> ImageViewport::toScreen(double col, double row) const {
  return {float(originX_ + col * zoom_), float(originY_ + row * zoom_)};
}

}  // namespace meshtrace::viewer
