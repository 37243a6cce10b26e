// The error-against-time plot of `raytrace --report`, drawn into an Image.
#include "meshtrace/report/plot.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace meshtrace {

namespace {

// A 3x5 pixel font for tick labels: each glyph is five rows of three bits.
const char* const kGlyphChars = "0123456789-e.";
constexpr unsigned char kGlyphs[][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7},
    {0, 0, 7, 0, 0}, {2, 5, 7, 4, 3}, {0, 0, 0, 0, 2}};

struct Canvas {
  Image& image;
  void fill(int x0, int y0, int x1, int y1, const Color& c) {
    for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y)
      for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) image.at(x, y) = c;
  }
  // Scaled by `s`, top-left at (x, y).
  void text(int x, int y, const std::string& s, int scale, const Color& c) {
    for (char ch : s) {
      const char* at = std::strchr(kGlyphChars, ch);
      if (ch && at) {
        const unsigned char* g = kGlyphs[at - kGlyphChars];
        for (int r = 0; r < 5; ++r)
          for (int b = 0; b < 3; ++b)
            if (g[r] & (4 >> b))
              fill(x + b * scale, y + r * scale, x + (b + 1) * scale, y + (r + 1) * scale, c);
      }
      x += 4 * scale;
    }
  }
};

const Color& groupColor(const std::string& group) {
  static const Color colors[] = {{0.85, 0.2, 0.1}, {0.1, 0.5, 0.9}, {0.1, 0.65, 0.2},
                                 {0.6, 0.2, 0.8},  {0.9, 0.6, 0.0}, {0.3, 0.3, 0.3}};
  static const char* groups[] = {"progressive", "samples", "triangle", "precision", "accel"};
  for (int i = 0; i < 5; ++i)
    if (group == groups[i]) return colors[i];
  return colors[5];
}

}  // namespace

Image plotErrorAgainstTime(const SceneReport& report, int width, int height) {
  Image image(width, height, Color(1.0));
  Canvas canvas{image};
  constexpr double kFloor = 0.01;  // RMSE 0 (identical images) is plotted at 0.01
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for (const ReportRow& r : report.rows) {
    x0 = std::min(x0, r.seconds), x1 = std::max(x1, r.seconds);
    y0 = std::min(y0, r.rmse + kFloor), y1 = std::max(y1, r.rmse + kFloor);
  }
  if (report.rows.empty()) return image;
  const int dx0 = int(std::floor(std::log10(x0))),
            dx1 = std::max(dx0 + 1, int(std::ceil(std::log10(x1))));
  const int dy0 = int(std::floor(std::log10(y0))),
            dy1 = std::max(dy0 + 1, int(std::ceil(std::log10(y1))));
  const int left = 70, right = width - 40, top = 20, bottom = height - 50;
  const auto px = [&](double s) {
    return left + (std::log10(s) - dx0) / (dx1 - dx0) * (right - left);
  };
  const auto py = [&](double e) {
    return bottom - (std::log10(e) - dy0) / (dy1 - dy0) * (bottom - top);
  };
  const Color grid(0.85), axis(0.0);
  for (int d = dx0; d <= dx1; ++d) {
    const int x = int(px(std::pow(10.0, d)));
    canvas.fill(x, top, x + 1, bottom, grid);
    canvas.text(x - 8, bottom + 10, "1e" + std::to_string(d), 3, axis);
  }
  for (int d = dy0; d <= dy1; ++d) {
    const int y = int(py(std::pow(10.0, d)));
    canvas.fill(left, y, right, y + 1, grid);
    canvas.text(8, y - 7, "1e" + std::to_string(d), 3, axis);
  }
  canvas.fill(left, top, left + 2, bottom, axis);
  canvas.fill(left, bottom, right, bottom + 2, axis);
  // The JPEG-noise threshold as a dashed line.
  const int yn = int(py(report.jpegNoiseRmse + kFloor));
  for (int x = left; x < right; x += 12) canvas.fill(x, yn, x + 6, yn + 2, Color(0.9, 0.3, 0.3));
  for (const ReportRow& r : report.rows) {
    const int x = int(px(r.seconds)), y = int(py(r.rmse + kFloor));
    canvas.fill(x - 4, y - 4, x + 5, y + 5, axis);
    canvas.fill(x - 3, y - 3, x + 4, y + 4, groupColor(r.config.group));
  }
  return image;
}

}  // namespace meshtrace
