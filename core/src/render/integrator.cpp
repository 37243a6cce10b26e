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

void Integrator::quad(double x, double y, Color out[4], Counters& counters) const {
  const Camera& camera = intersector_.scene().camera;
  const Ray rays[kPacketSize] = {camera.primaryRay(x, y), camera.primaryRay(x + 1, y),
                                 camera.primaryRay(x, y + 1), camera.primaryRay(x + 1, y + 1)};
  counters.primaryRays += kPacketSize;
  shadePacket(rays, 0xfu, 0, nullptr, out, counters);
}

void Integrator::shadePacket(const Ray* rays, std::uint32_t active, int level,
                             const PrimitiveRef* start, Color* out, Counters& counters) const {
  const Scene& scene = intersector_.scene();
  Hit hits[kPacketSize];
  bool found[kPacketSize];
  intersector_.closestHitPacket(rays, kSpawnTMin, hits, found, counters, start, active);
  NoObserver none;
  if (scene.lights.size() > kMaxPacketLights) {
    for (int r = 0; r < kPacketSize; ++r)
      if (active >> r & 1)
        out[r] = whittedShade(intersector_, rays[r], found[r], hits[r], level, counters, none);
    return;
  }
  SurfacePoint sp[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r)
    if (found[r])
      sp[r] = surfaceAt(scene, rays[r], hits[r], intersector_.options().triangle.precision);
  // Each light's shadow rays from the hits go as one packet; rays not cast
  // (no hit, light behind) keep the incoming ray as a placeholder.
  std::uint32_t blocked[kMaxPacketLights];
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    Ray shadow[kPacketSize] = {rays[0], rays[1], rays[2], rays[3]};
    double lightDistance[kPacketSize] = {0.0, 0.0, 0.0, 0.0};
    PrimitiveRef shadowStart[kPacketSize];
    std::uint32_t cast = 0;
    for (int r = 0; r < kPacketSize; ++r) {
      Vec3 l;
      double nl;
      if (found[r] && lightToward(scene.lights[i], sp[r], l, nl)) {
        shadow[r] = shadowRayToward(scene.lights[i], sp[r], l, lightDistance[r]);
        shadowStart[r] = sp[r].primitive;
        cast |= 1u << r;
      }
    }
    blocked[i] =
        intersector_.occludedPacket(shadow, kSpawnTMin, lightDistance, shadowStart, cast, counters);
  }
  Color local[kPacketSize];
  Ray bounce[kPacketSize];
  PrimitiveRef bounceStart[kPacketSize];
  std::uint32_t reflecting = 0;
  for (int r = 0; r < kPacketSize; ++r) {
    if (!(active >> r & 1)) continue;
    if (!found[r]) {
      out[r] = scene.background;
      continue;
    }
    const auto shadowed = [&](std::size_t i, const Vec3&) { return (blocked[i] >> r & 1) != 0; };
    local[r] = whittedLocal(intersector_, -rays[r].direction, sp[r], counters, none, shadowed);
    if (!reflectsAt(scene, sp[r], level)) {
      out[r] = local[r];
      continue;
    }
    bounce[r] = mirrorBounce(rays[r], sp[r]);
    bounceStart[r] = sp[r].primitive;
    reflecting |= 1u << r;
    ++counters.reflectionRays;
  }
  if (reflecting == 0) return;
  for (int r = 0; r < kPacketSize; ++r)
    if (!(reflecting >> r & 1)) bounce[r] = bounce[__builtin_ctz(reflecting)];
  Color seen[kPacketSize];
  shadePacket(bounce, reflecting, level + 1, bounceStart, seen, counters);
  for (int r = 0; r < kPacketSize; ++r)
    if (reflecting >> r & 1) out[r] = mirrorMix(local[r], sp[r].material->mirror, seen[r]);
}

Color Integrator::pixel(double x, double y, Counters& counters) const {
  return pixel(intersector_.scene().camera, x, y, counters);
}

}  // namespace meshtrace
