#include "meshtrace/report/image_compare.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace meshtrace {

ImageDifference compareImages(const Image8& a, const Image8& b) {
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument("image sizes differ: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " against " + std::to_string(b.width) +
                                "x" + std::to_string(b.height));
  }
  ImageDifference d;
  const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
  if (pixels == 0) return d;
  double sumSq = 0.0;
  std::size_t over32 = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int diff = std::abs(int(a.rgb[i * 3 + c]) - int(b.rgb[i * 3 + c]));
      sumSq += double(diff) * diff;
      worst = std::max(worst, diff);
    }
    if (worst > 32) ++over32;
    d.maxDifference = std::max(d.maxDifference, worst);
  }
  d.rmse = std::sqrt(sumSq / double(pixels * 3));
  d.psnr = d.rmse > 0.0 ? 20.0 * std::log10(255.0 / d.rmse) : kInfinity;
  d.fractionOver32 = double(over32) / double(pixels);
  return d;
}

}  // namespace meshtrace
