#include "meshtrace/render/inspect_colors.h"

#include <array>

namespace meshtrace {

Color heatColor(double t) {
  // Stops of a perceptual "inferno"-like ramp.
  static constexpr std::array<std::array<double, 3>, 6> stops{{{0.02, 0.02, 0.12},
                                                               {0.26, 0.04, 0.41},
                                                               {0.58, 0.15, 0.40},
                                                               {0.87, 0.32, 0.23},
                                                               {0.98, 0.62, 0.04},
                                                               {0.99, 0.99, 0.65}}};
  if (!(t > 0.0)) t = 0.0;
  if (t > 1.0) t = 1.0;
  const double f = t * (stops.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(f), stops.size() - 2);
  const double u = f - double(i);
  const auto& a = stops[i];
  const auto& b = stops[i + 1];
  return {a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2])};
}

Color idColor(std::uint32_t id) {
  const double h = std::fmod(0.11 + id * 0.6180339887498949, 1.0) * 6.0;
  const double v = (id % 3 == 0) ? 0.95 : (id % 3 == 1 ? 0.75 : 0.55);
  const double x = 1.0 - std::abs(std::fmod(h, 2.0) - 1.0);
  Color c;
  switch (static_cast<int>(h)) {
    case 0: c = {1, x, 0}; break;
    case 1: c = {x, 1, 0}; break;
    case 2: c = {0, 1, x}; break;
    case 3: c = {0, x, 1}; break;
    case 4: c = {x, 0, 1}; break;
    default: c = {1, 0, x}; break;
  }
  return c * v;
}

Color normalColor(const Vec3& n) { return 0.5 * (n + Vec3(1.0)); }

Color depthColor(double t, double nearT, double farT) {
  const double span = farT - nearT;
  double u = span > 0.0 ? (t - nearT) / span : 0.0;
  u = std::clamp(u, 0.0, 1.0);
  return Color(1.0 - 0.85 * u);
}

}  // namespace meshtrace
