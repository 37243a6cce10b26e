#pragma once
// How the image view places the image in its area: fitted, or at a zoom
// (screen pixels per image pixel) about a centre the user moves, apart from
// the scene's camera. Maps screen points to image pixels and back, so that
// at a zoom of 1 or more every pixel can be hovered and clicked.
#include <optional>
#include <utility>

namespace meshtrace::viewer {

struct ScreenRect {
  float x = 0, y = 0, width = 0, height = 0;
};

class ImageViewport {
 public:
  static constexpr double kMinZoom = 1.0 / 16.0, kMaxZoom = 64.0;
  // From this zoom on, lines between the pixels are drawn.
  static constexpr double kGridZoom = 8.0;

  // Places an image of `width` x `height` pixels in `area` (screen pixels);
  // call each frame before the mappings.
  void layout(const ScreenRect& area, int width, int height);

  void fit() { fit_ = true; }
  // One image pixel per screen pixel, about the image's centre.
  void actualSize();
  // `zoom` about image position (col, row) in storage pixels (the first
  // layout keeps it, whatever the image's size was before).
  void zoomTo(double zoom, double col, double row);
  // Multiplies the zoom by `factor`, keeping the image point under the
  // screen point (sx, sy) where it is.
  void zoomAt(double factor, float sx, float sy);
  // Moves the image by (dx, dy) screen pixels.
  void panBy(float dx, float dy);

  bool fitted() const { return fit_; }
  double zoom() const { return zoom_; }
  // Where image pixel (0, 0) (row 0 the top) has its top-left corner.
  float originX() const { return originX_; }
  float originY() const { return originY_; }
  // The image's rectangle on screen (it may reach beyond the area).
  ScreenRect imageRect() const;
  // The storage pixel (col, row; row 0 the top) under a screen point inside
  // both the area and the image.
  std::optional<std::pair<int, int>> pixelAt(float sx, float sy) const;
  // The screen point of image position (col, row) in storage pixels
  // (fractions inside a pixel: its centre is (col + 0.5, row + 0.5)).
  std::pair<float, float> toScreen(double col, double row) const;

 private:
  void place();

  ScreenRect area_;
  int width_ = 0, height_ = 0;
  bool fit_ = true;
  bool keepCenter_ = false;
  double zoom_ = 1.0;
  // The image point at the area's centre, in storage pixels.
  double centerCol_ = 0.0, centerRow_ = 0.0;
  float originX_ = 0, originY_ = 0;
};

}  // namespace meshtrace::viewer
