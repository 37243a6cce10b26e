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

Color Integrator::pixel(double x, double y, Counters& counters) const {
  return pixel(intersector_.scene().camera, x, y, counters);
}

}  // namespace meshtrace
