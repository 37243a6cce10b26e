#pragma once
// Pieces of valid scene text that tests combine with one broken part.
#include <string>

namespace meshtrace::test {

// A small camera looking down -z at the origin: 8x6 pixels keeps renders quick.
inline const std::string kCameraLine = "camera 0 0 5  0 0 0  0 1 0  45  8 6\n";
// ambient(3) diffuse(3) specular(3) shininess mirror
inline const std::string kMaterial = "0.1 0.1 0.1  0.6 0.6 0.6  0.3 0.3 0.3  20 0";
inline const std::string kSphereLine = "sphere 0 0 0  1  " + kMaterial + "\n";
// One triangle facing +z.
inline const std::string kTriangleOff = "OFF\n3 1 0\n-1 -1 0\n1 -1 0\n0 1 0\n3 0 1 2\n";

}  // namespace meshtrace::test
