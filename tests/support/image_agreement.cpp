#include "support/image_agreement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "meshtrace/report/image_compare.h"

namespace meshtrace::test {

std::size_t pixelsDiffering(const Image8& a, const Image8& b, int by) {
  std::size_t n = 0;
  for (std::size_t p = 0; p + 2 < std::min(a.rgb.size(), b.rgb.size()); p += 3) {
    int most = 0;
    for (int c = 0; c < 3; ++c)
      most = std::max(most, std::abs(int(a.rgb[p + c]) - int(b.rgb[p + c])));
    n += most > by;
  }
  return n;
}

void expectWithinJpegNoise(const Image8& render, const std::filesystem::path& reference,
                           const std::string& label) {
  // The page: "RMSE <= 0.2 once the render itself is encoded the same way".
  constexpr double kMaxRmse = 0.2;
  const Image8 ours = jpegRoundTrip(render, 95);
  const Image8 theirs = readImage(reference);
  const ImageDifference d = compareImages(ours, theirs);
  const std::size_t over32 = pixelsDiffering(ours, theirs, 32);
  std::printf("[ figures  ] %-26s RMSE %.3f  PSNR %.1f dB  pixels off >32: %zu  max %d\n",
              label.c_str(), d.rmse, d.psnr, over32, d.maxDifference);
  EXPECT_LE(d.rmse, kMaxRmse) << label;
  EXPECT_LE(over32, kHandfulOfPixels) << label;
}

}  // namespace meshtrace::test
