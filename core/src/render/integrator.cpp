#include "meshtrace/render/integrator.h"

#include "render/whitted.h"

namespace meshtrace {

Color Integrator::trace(const Ray& ray, int level, Counters& counters) const {
  NoObserver none;
  return whittedTrace(intersector_, ray, level, counters, none);
}

Color Integrator::pixel(const Camera& camera, double x, double y, Counters& counters) const {
  ++counters.primaryRays;
  return trace(camera.primaryRay(x, y), 0, counters);
}

void Integrator::quad(double x, double y, Color out[kPacketSize], Counters& counters) const {
  quad(intersector_.scene().camera, x, y, out, counters);
}

void Integrator::quad(const Camera& camera, double x, double y, Color out[kPacketSize],
                      Counters& counters) const {
  // Lane r is pixel (x + r % 2, y + r / 2).
  Ray rays[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r) rays[r] = camera.primaryRay(x + r % 2, y + r / 2);
  counters.primaryRays += kPacketSize;
  whittedShadePacket(intersector_, rays, 0xfu, 0, nullptr, out, counters);
}

Color Integrator::pixel(double x, double y, Counters& counters) const {
  return pixel(intersector_.scene().camera, x, y, counters);
}

}  // namespace meshtrace
