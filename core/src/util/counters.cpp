#include "meshtrace/util/counters.h"

#include <sstream>

namespace meshtrace {

Counters& Counters::operator+=(const Counters& o) {
  primaryRays += o.primaryRays;
  shadowRays += o.shadowRays;
  reflectionRays += o.reflectionRays;
  boxTests += o.boxTests;
  triangleTests += o.triangleTests;
  sphereTests += o.sphereTests;
  planeTests += o.planeTests;
  cylinderTests += o.cylinderTests;
  nodeVisits += o.nodeVisits;
  lastBlockerHits += o.lastBlockerHits;
  return *this;
}

std::string Counters::describe() const {
  std::ostringstream s;
  s << "rays: " << primaryRays << " primary, " << shadowRays << " shadow, " << reflectionRays
    << " reflection\n"
    << "tests: " << boxTests << " box, " << triangleTests << " triangle, " << sphereTests
    << " sphere, " << planeTests << " plane, " << cylinderTests << " cylinder\n"
    << "bvh: " << nodeVisits << " node visits\n"
    << "shadow rays answered by the last blocker toward their light: " << lastBlockerHits << "\n";
  return s.str();
}

}  // namespace meshtrace
