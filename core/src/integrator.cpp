#include "meshtrace/integrator.h"

#include "whitted.h"

namespace meshtrace {

Color Integrator::trace(const Ray& ray, int level, Counters& counters) const {
  NoObserver none;
  return whittedTrace(intersector_, ray, level, counters, none);
}

Color Integrator::pixel(const Camera& camera, double x, double y, Counters& counters) const {
  ++counters.primaryRays;
  return trace(camera.primaryRay(x, y), 0, counters);
}

void Integrator::quad(double x, double y, Color out[4], Counters& counters) const {
  const Camera& camera = intersector_.scene().camera;
  const Ray rays[kPacketSize] = {camera.primaryRay(x, y), camera.primaryRay(x + 1, y),
                                 camera.primaryRay(x, y + 1), camera.primaryRay(x + 1, y + 1)};
  Hit hits[kPacketSize];
  bool found[kPacketSize];
  intersector_.closestHitPacket(rays, kSpawnTMin, hits, found, counters);
  NoObserver none;
  for (int r = 0; r < kPacketSize; ++r) {
    ++counters.primaryRays;
    out[r] = whittedShade(intersector_, rays[r], found[r], hits[r], 0, counters, none);
  }
}

Color Integrator::pixel(double x, double y, Counters& counters) const {
  return pixel(intersector_.scene().camera, x, y, counters);
}

}  // namespace meshtrace
