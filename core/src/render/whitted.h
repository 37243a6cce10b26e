#pragma once
// All of the shading: the Whitted recursion (local Phong lighting with hard
// shadows, mirror reflection up to the scene's depth), for one ray and for a
// packet of four. The one-ray recursion is written once for two users: the
// Integrator runs it with NoObserver, whose hooks inline to nothing, and the
// pixel inspector with an observer that records every step, so that what it
// explains is exactly what was rendered. The packet version shares its
// pieces (whittedLocal, mirrorBounce, mirrorMix) and gives the same colours
// to the bit (Render.GivesEachPixelTheColourItHasAlone holds it to that).
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/render/integrator.h"
#include "meshtrace/render/spawn.h"
#include "meshtrace/render/surface.h"

namespace meshtrace {

struct NoObserver {
  void beginBounce(int /*level*/, const Ray&) {}
  void surface(const Hit&, const SurfacePoint&) {}
  void ambient(const Color&) {}
  void lightBehind(std::size_t /*light*/, const Vec3& /*l*/, double /*nl*/) {}
  // The shadow ray from sp toward the light (shadowRayToward) reached
  // something first.
  void lightShadowed(std::size_t, const Vec3&, double, const SurfacePoint& /*sp*/) {}
  void lightLit(std::size_t, const Vec3&, double, const Color& /*diffuse*/,
                const Color& /*specular*/) {}
  void local(const Color&, double /*mirror*/, bool /*reflects*/) {}
  void endBounce(const Color&) {}
};

// The direction l to `light` from sp and its cosine nl with the normal.
// Returns nl > 0: a light behind the surface adds nothing, so its shadow ray
// is left out.
inline bool lightToward(const Light& light, const SurfacePoint& sp, Vec3& l, double& nl) {
  l = glm::normalize(light.position - sp.point);
  nl = glm::dot(sp.normal, l);
  return nl > 0.0;
}

// The shadow ray from sp in the light's direction l (lightToward), and the
// light's distance from that ray's origin: a blocker near the light counts
// as much as one near the point.
inline Ray shadowRayToward(const Light& light, const SurfacePoint& sp, const Vec3& l,
                           double& lightDistance) {
  const Ray shadow{spawnOrigin(sp, l), l};
  lightDistance = glm::length(light.position - shadow.origin);
  return shadow;
}

// Ambient plus, per light, diffuse and specular unless the light is behind
// the surface or shadowed: shadowed(i, l) tells whether the shadow ray
// toward light i, in direction l, is blocked. Always inlined: it is each
// ray's shading in the packet loop, which the compiler would otherwise
// call out of line.
template <typename Observer, typename Shadowed>
[[gnu::always_inline]] inline Color whittedLocal(const SceneIntersector& intersector,
                                                 const Vec3& viewDir, const SurfacePoint& sp,
                                                 Counters& counters, Observer& observer,
                                                 const Shadowed& shadowed) {
  const Scene& scene = intersector.scene();
  const Material& m = *sp.material;
  Color color = scene.ambience * m.ambient;
  observer.ambient(color);
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    Vec3 l;
    double nl;
    if (!lightToward(light, sp, l, nl)) {
      observer.lightBehind(i, l, nl);
      continue;
    }
    ++counters.shadowRays;
    if (shadowed(i, l)) {
      observer.lightShadowed(i, l, nl, sp);
      continue;
    }
    const Color diffuse = light.color * m.diffuse * nl;
    color += diffuse;
    Color specular(0.0);
    const Vec3 r = 2.0 * nl * sp.normal - l;
    const double rv = glm::dot(r, viewDir);
    if (rv > 0.0) {
      specular = light.color * m.specular * std::pow(rv, m.shininess);
      color += specular;
    }
    observer.lightLit(i, l, nl, diffuse, specular);
  }
  return color;
}

template <typename Observer>
Color whittedTrace(const SceneIntersector& intersector, const Ray& ray, int level,
                   Counters& counters, Observer& observer, const PrimitiveRef* start = nullptr,
                   LastBlockers* blockers = nullptr);

// Whether the surface at sp, reached at recursion level `level`, adds a
// mirror reflection. The deepest level keeps its local colour rather than
// mixing with black.
inline bool reflectsAt(const Scene& scene, const SurfacePoint& sp, int level) {
  return sp.material->mirror > 0.0 && level < scene.depth;
}

// The mirror reflection of `ray` at sp, leaving sp.primitive.
inline Ray mirrorBounce(const Ray& ray, const SurfacePoint& sp) {
  const Vec3 d = ray.direction;
  const Vec3 reflected = d - 2.0 * glm::dot(d, sp.normal) * sp.normal;
  return {spawnOrigin(sp, reflected), glm::normalize(reflected)};
}

// A reflecting surface's colour from its local colour and what its mirror
// reflection sees.
inline Color mirrorMix(const Color& local, double mirror, const Color& reflected) {
  return (1.0 - mirror) * local + mirror * reflected;
}

// The rest of whittedTrace at the ray's hit, whose surface point is sp;
// `shadowed` as in whittedLocal.
template <typename Observer, typename Shadowed>
Color whittedShadeAt(const SceneIntersector& intersector, const Ray& ray, const Hit& hit,
                     const SurfacePoint& sp, int level, Counters& counters, Observer& observer,
                     const Shadowed& shadowed, LastBlockers* blockers) {
  const Scene& scene = intersector.scene();
  observer.surface(hit, sp);
  const Color local = whittedLocal(intersector, -ray.direction, sp, counters, observer, shadowed);
  const double mirror = sp.material->mirror;
  const bool reflects = reflectsAt(scene, sp, level);
  observer.local(local, mirror, reflects);
  if (!reflects) {
    observer.endBounce(local);
    return local;
  }
  ++counters.reflectionRays;
  const Color color = mirrorMix(local, mirror,
                                whittedTrace(intersector, mirrorBounce(ray, sp), level + 1,
                                             counters, observer, &sp.primitive, blockers));
  observer.endBounce(color);
  return color;
}

// The rest of whittedTrace, given the ray's closest hit (`found` false:
// none); shadow rays are traced one by one.
template <typename Observer>
Color whittedShade(const SceneIntersector& intersector, const Ray& ray, bool found, const Hit& hit,
                   int level, Counters& counters, Observer& observer, LastBlockers* blockers) {
  const Scene& scene = intersector.scene();
  if (!found) {
    observer.endBounce(scene.background);
    return scene.background;
  }
  const SurfacePoint sp = surfaceAt(scene, ray, hit, intersector.options().triangle.precision);
  const auto shadowed = [&](std::size_t i, const Vec3& l) {
    double lightDistance;
    const Ray shadow = shadowRayToward(scene.lights[i], sp, l, lightDistance);
    return intersector.occluded(shadow, kSpawnTMin, lightDistance, counters, &sp.primitive,
                                blockers ? blockers->at(level, i) : nullptr);
  };
  return whittedShadeAt(intersector, ray, hit, sp, level, counters, observer, shadowed, blockers);
}

// Colour seen along `ray` at recursion level `level` (0 = primary); `start`
// is the primitive a reflected ray leaves; `blockers`, if given, the shadow
// rays' LastBlockers of the caller's run of pixels.
template <typename Observer>
Color whittedTrace(const SceneIntersector& intersector, const Ray& ray, int level,
                   Counters& counters, Observer& observer, const PrimitiveRef* start,
                   LastBlockers* blockers) {
  observer.beginBounce(level, ray);
  Hit hit;
  const bool found = intersector.closestHit(ray, kSpawnTMin, hit, counters, start);
  return whittedShade(intersector, ray, found, hit, level, counters, observer, blockers);
}

// whittedTrace for the rays of a packet named in `active` (bit r: rays[r],
// leaving start[r] when `start` is given), into out[r]; the other slots are
// left alone. The rays' closest hits are found as one packet, the shadow
// rays toward each light from their hits as another, and their mirror
// reflections as the next level's packet (up to kMaxPacketLights lights;
// with more, each ray's shading goes on alone). Every rays[r] must be a
// valid ray, active or not.
inline void whittedShadePacket(const SceneIntersector& intersector, const Ray* rays,
                               std::uint32_t active, int level, const PrimitiveRef* start,
                               Color* out, Counters& counters, LastBlockers* blockers) {
  const Scene& scene = intersector.scene();
  Hit hits[kPacketSize];
  bool found[kPacketSize];
  intersector.closestHitPacket(rays, kSpawnTMin, hits, found, counters, start, active);
  NoObserver none;
  if (scene.lights.size() > kMaxPacketLights) {
    for (int r = 0; r < kPacketSize; ++r)
      if (active >> r & 1)
        out[r] =
            whittedShade(intersector, rays[r], found[r], hits[r], level, counters, none, blockers);
    return;
  }
  SurfacePoint sp[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r)
    if (found[r])
      sp[r] = surfaceAt(scene, rays[r], hits[r], intersector.options().triangle.precision);
  // Each light's shadow rays from the hits go as one packet; rays not cast
  // (no hit, light behind) keep the incoming ray as a placeholder.
  std::uint32_t blocked[kMaxPacketLights];
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    Ray shadow[kPacketSize];
    std::copy(rays, rays + kPacketSize, shadow);
    double lightDistance[kPacketSize] = {};
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
    blocked[i] = intersector.occludedPacket(shadow, kSpawnTMin, lightDistance, shadowStart, cast,
                                            counters, blockers ? blockers->at(level, i) : nullptr);
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
    local[r] = whittedLocal(intersector, -rays[r].direction, sp[r], counters, none, shadowed);
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
  whittedShadePacket(intersector, bounce, reflecting, level + 1, bounceStart, seen, counters,
                     blockers);
  for (int r = 0; r < kPacketSize; ++r)
    if (reflecting >> r & 1) out[r] = mirrorMix(local[r], sp[r].material->mirror, seen[r]);
}

}  // namespace meshtrace
