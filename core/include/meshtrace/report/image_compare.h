#pragma once
// Image differences as the conformance tests and reports measure them.
#include "meshtrace/io/image.h"

namespace meshtrace {

struct ImageDifference {
  double rmse = 0.0;            // over all channels, 8-bit units
  double psnr = 0.0;            // dB; infinite for identical images
  double fractionOver32 = 0.0;  // share of pixels with any channel off by more than 32
  int maxDifference = 0;
};

// Throws std::invalid_argument if the sizes differ.
ImageDifference compareImages(const Image8& a, const Image8& b);

}  // namespace meshtrace
