#include "meshtrace/render/integrator.h"

#include "render/whitted.h"

namespace meshtrace {

Color Integrator::trace(const Ray& ray, int level, Counters& counters,
                        LastBlockers* blockers) const {
  NoObserver none;
  return whittedTrace(intersector_, ray, level, counters, none, nullptr, blockers);
}

Color Integrator::pixel(const Camera& camera, double x, double y, Counters& counters,
                        LastBlockers* blockers) const {
  ++counters.primaryRays;
  return trace(camera.primaryRay(x, y), 0, counters, blockers);
}

void Integrator::quad(double x, double y, Color out[kPacketSize], Counters& counters,
                      LastBlockers* blockers) const {
  quad(intersector_.scene().camera, x, y, out, counters, blockers);
}

void Integrator::quad(const Camera& camera, double x, double y, Color out[kPacketSize],
                      Counters& counters, LastBlockers* blockers) const {
  // Lane r is pixel (x + r % 2, y + r / 2).
  Ray rays[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r) rays[r] = camera.primaryRay(x + r % 2, y + r / 2);
  counters.primaryRays += kPacketSize;
  whittedShadePacket(intersector_, rays, 0xfu, 0, nullptr, out, counters, blockers);
}

Color Integrator::pixel(double x, double y, Counters& counters, LastBlockers* blockers) const {
  return pixel(intersector_.scene().camera, x, y, counters, blockers);
}

}  // namespace meshtrace
