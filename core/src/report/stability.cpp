// The numerical robustness measurements of stability.h.
#include "meshtrace/report/stability.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/geometry/scene_meshes.h"
#include "meshtrace/render/spawn.h"
#include "meshtrace/render/surface.h"
#include "meshtrace/util/enum_names.h"

namespace meshtrace {

namespace {

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Vec3 randomUnit(Rng& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  for (;;) {
    const Vec3 v(n(rng), n(rng), n(rng));
    const double len = glm::length(v);
    if (len > 1e-6) return v / len;
  }
}

// A unit vector w with dot(w, n) >= minCos (n unit).
Vec3 randomInHemisphere(Rng& rng, const Vec3& n, double minCos = 0.05) {
  for (;;) {
    const Vec3 w = randomUnit(rng);
    const double c = glm::dot(w, n);
    if (c >= minCos) return w;
    if (-c >= minCos) return -w;
  }
}

// Two unit vectors completing n (unit) to an orthonormal basis.
void basis(const Vec3& n, Vec3& u, Vec3& v) {
  u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
  v = glm::cross(n, u);
}

Scene sceneWith(ObjectKind kind) {
  Scene scene;
  scene.file = std::string("stability-") + toString(kind) + ".sce";
  return scene;
}

}  // namespace

std::vector<TriangleKernel> allTriangleKernels() {
  std::vector<TriangleKernel> out{TriangleKernel{}};
  for (Precision p : {Precision::Double, Precision::Single})
    for (TriangleTest t :
         {TriangleTest::Cramer, TriangleTest::MollerTrumbore, TriangleTest::Watertight})
      if (!(t == out[0].test && p == out[0].precision)) out.push_back({t, p});
  return out;
}

MeshData makeClosedGridBox(int n) {
  MeshData mesh;
  std::map<std::array<int, 3>, std::uint32_t> index;  // lattice point -> vertex
  const auto vertex = [&](std::array<int, 3> l) {
    auto [it, added] = index.try_emplace(l, static_cast<std::uint32_t>(mesh.vertices.size()));
    if (added) {
      // One expression for every coordinate, so shared vertices are bit-identical.
      const auto coord = [n](int i) { return -1.0 + 2.0 * i / n; };
      mesh.vertices.emplace_back(coord(l[0]), coord(l[1]), coord(l[2]));
    }
    return it->second;
  };
  for (int k = 0; k < 3; ++k) {
    const int ku = (k + 1) % 3, kv = (k + 2) % 3;  // e_ku x e_kv = e_k
    for (int side : {0, n}) {
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          std::uint32_t c[4];
          const int corner[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
          for (int q = 0; q < 4; ++q) {
            std::array<int, 3> l{};
            l[k] = side;
            l[ku] = corner[q][0];
            l[kv] = corner[q][1];
            c[q] = vertex(l);
          }
          if (side == n) {  // +k face: counter-clockwise seen from +k
            mesh.triangles.push_back({c[0], c[1], c[2]});
            mesh.triangles.push_back({c[0], c[2], c[3]});
          } else {
            mesh.triangles.push_back({c[0], c[2], c[1]});
            mesh.triangles.push_back({c[0], c[3], c[2]});
          }
        }
      }
    }
  }
  return mesh;
}

WatertightResult measureWatertightBox(TriangleKernel kernel, int n, const Vec3& eye) {
  const MeshData box = makeClosedGridBox(n);

  // Targets: every point of the half-step lattice on each face, i.e. the
  // vertices, edge midpoints and diagonal midpoints.
  std::vector<Ray> rays;
  for (int k = 0; k < 3; ++k)
    for (double side : {-1.0, 1.0})
      for (int i = 0; i <= 2 * n; ++i)
        for (int j = 0; j <= 2 * n; ++j) {
          Vec3 target;
          target[k] = side;
          target[(k + 1) % 3] = -1.0 + double(i) / n;
          target[(k + 2) % 3] = -1.0 + double(j) / n;
          rays.push_back({eye, glm::normalize(target - eye)});
        }

  // Every ray against every triangle, as brute force does: one scan counts
  // both a leak (no triangle hit) and a multiple hit (more than one).
  WatertightResult r;
  r.rays = rays.size();
  const auto start = std::chrono::steady_clock::now();
  for (const Ray& ray : rays) {
    const TriangleRay tr(ray, kernel);
    int hits = 0;
    for (const TriangleIndices& t : box.triangles) {
      TriangleHit th;
      hits += tr.intersect(box.vertices[t[0]], box.vertices[t[1]], box.vertices[t[2]], 0.0,
                           kInfinity, th);
    }
    r.leaks += hits == 0;
    r.multipleHits += hits > 1;
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

SelfHitResult measureSelfIntersection(ObjectKind kind, TriangleKernel kernel, double scale,
                                      double offset, int samples, std::uint64_t seed) {
  Rng rng(seed);
  SelfHitResult r;
  const Vec3 shift(offset);
  for (int s = 0; s < samples; ++s) {
    Scene scene = sceneWith(kind);
    Vec3 target, outward;  // a point on the surface and the side the ray comes from
    bool flat = false;
    switch (kind) {
      case ObjectKind::Mesh: {
        MeshData m;
        for (int k = 0; k < 3; ++k)
          m.vertices.push_back(
              shift + scale * Vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)));
        m.triangles.push_back({0, 1, 2});
        const double b = uniform(rng, 0.05, 0.9), g = uniform(rng, 0.05, 0.95 - b);
        target = (1 - b - g) * m.vertices[0] + b * m.vertices[1] + g * m.vertices[2];
        scene.meshes.emplace_back("triangle.off", std::move(m), Shading::Flat, Material{});
        outward = randomUnit(rng);
        flat = true;
        break;
      }
      case ObjectKind::Sphere: {
        const Sphere sphere{shift, scale, {}};
        outward = randomUnit(rng);
        target = sphere.center + sphere.radius * outward;
        scene.spheres.push_back(sphere);
        break;
      }
      case ObjectKind::Plane: {
        const Plane plane{shift, randomUnit(rng), {}};
        Vec3 u, v;
        basis(plane.normal, u, v);
        target = plane.point + scale * (uniform(rng, -1, 1) * u + uniform(rng, -1, 1) * v);
        scene.planes.push_back(plane);
        outward = randomUnit(rng);
        flat = true;
        break;
      }
      case ObjectKind::Cylinder: {
        const Cylinder cyl{shift, scale, randomUnit(rng), 4.0 * scale, {}};
        Vec3 u, v;
        basis(cyl.axis, u, v);
        const double phi = uniform(rng, 0.0, 6.283185307179586);
        outward = std::cos(phi) * u + std::sin(phi) * v;
        target = cyl.center + uniform(rng, -1.5, 1.5) * scale * cyl.axis + cyl.radius * outward;
        scene.cylinders.push_back(cyl);
        break;
      }
    }
    // The origin lies in the open half-space in front of the tangent plane,
    // so the first hit is near `target` and, for convex shapes, from outside.
    const Vec3 origin =
        target + scale * uniform(rng, 1.0, 4.0) * randomInHemisphere(rng, outward, 0.2);
    const Ray ray{origin, glm::normalize(target - origin)};
    TraceOptions options;
    options.triangle = kernel;
    const SceneIntersector intersector(scene, options);
    Counters counters;
    Hit hit;
    if (!intersector.closestHit(ray, kSpawnTMin, hit, counters)) continue;
    ++r.primaryHits;
    const SurfacePoint sp = surfaceAt(scene, ray, hit, kernel.precision);
    const Vec3 ng =
        glm::dot(sp.geometricNormal, ray.direction) < 0 ? sp.geometricNormal : -sp.geometricNormal;
    std::vector<Vec3> directions{
        ray.direction - 2.0 * glm::dot(ray.direction, sp.normal) * sp.normal,
        randomInHemisphere(rng, ng)};
    if (flat) directions.push_back(randomInHemisphere(rng, -ng));
    for (Vec3 d : directions) {
      d = glm::normalize(d);
      ++r.spawned;
      r.reHits += intersector.occluded({spawnOrigin(sp, d), d}, kSpawnTMin, kInfinity, counters);
    }
  }
  return r;
}

const char* toString(IllConditioned family) {
  static constexpr EnumName<IllConditioned> kFamilies[] = {{IllConditioned::Grazing, "grazing"},
                                                           {IllConditioned::Sliver, "sliver"},
                                                           {IllConditioned::Huge, "huge"},
                                                           {IllConditioned::Tiny, "tiny"}};
  return nameIn(kFamilies, family);
}

namespace {

__extension__ typedef __float128 Quad;

struct Q3 {
  Quad x, y, z;
  explicit Q3(const Vec3& v) : x(v.x), y(v.y), z(v.z) {}
  Q3(Quad a, Quad b, Quad c) : x(a), y(b), z(c) {}
  Q3 operator-(const Q3& o) const { return {x - o.x, y - o.y, z - o.z}; }
};
Quad dot(const Q3& a, const Q3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Q3 cross(const Q3& a, const Q3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Cramer's rule in quad precision on the exact double inputs: differences and
// products of doubles carry ~113 bits, far below any double error measured.
bool referenceHit(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray, TriangleHit& out) {
  const Q3 qa(a), e1 = Q3(b) - qa, e2 = Q3(c) - qa, s = Q3(ray.origin) - qa, d(ray.direction);
  const Q3 n = cross(e1, e2);
  const Quad det = -dot(n, d);
  if (det == 0) return false;
  const Q3 sxd = cross(s, d);
  const Quad beta = dot(e2, sxd) / det, gamma = -dot(e1, sxd) / det, t = dot(n, s) / det;
  out = {double(t), double(beta), double(gamma)};
  return beta >= 0 && gamma >= 0 && beta + gamma <= 1 && t > 0;
}

// A random rotation (from a random unit quaternion).
glm::dmat3 randomRotation(Rng& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  double q[4], len = 0;
  for (double& x : q) {
    x = n(rng);
    len += x * x;
  }
  len = std::sqrt(len);
  const double w = q[0] / len, x = q[1] / len, y = q[2] / len, z = q[3] / len;
  return glm::dmat3(1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y),
                    2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x),
                    2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y));
}

}  // namespace

AccuracyResult measureAccuracy(IllConditioned family, TriangleKernel kernel, int samples,
                               std::uint64_t seed) {
  Rng rng(seed);
  AccuracyResult r;
  const double u =
      kernel.precision == Precision::Double ? std::ldexp(1.0, -53) : std::ldexp(1.0, -24);
  for (int s = 0; s < samples; ++s) {
    // A canonical triangle in the z = 0 plane and a ray from above, then a
    // random rotation (the rotated values, rounded, are the exact inputs).
    double size = 1.0, elevation = uniform(rng, 0.2, 1.5);  // radians above the plane
    Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    switch (family) {
      case IllConditioned::Grazing: elevation = std::pow(10.0, -uniform(rng, 1.0, 8.0)); break;
      case IllConditioned::Sliver: c = {0.5, std::pow(10.0, -uniform(rng, 4.0, 10.0)), 0}; break;
      case IllConditioned::Huge: size = std::pow(10.0, uniform(rng, 6.0, 12.0)); break;
      case IllConditioned::Tiny: size = std::pow(10.0, -uniform(rng, 6.0, 12.0)); break;
    }
    const double beta = uniform(rng, 0.1, 0.8), gamma = uniform(rng, 0.05, 0.9 - beta);
    const Vec3 target = size * ((1 - beta - gamma) * a + beta * b + gamma * c);
    const double phi = uniform(rng, 0.0, 6.283185307179586);
    const Vec3 d(std::cos(elevation) * std::cos(phi), std::cos(elevation) * std::sin(phi),
                 -std::sin(elevation));
    const glm::dmat3 rot = randomRotation(rng);
    const Vec3 A = rot * (size * a), B = rot * (size * b), C = rot * (size * c);
    const Vec3 o = rot * (target - size * uniform(rng, 1.0, 10.0) * d);
    const Ray ray{o, glm::normalize(rot * d)};

    TriangleHit ref{}, got{};
    const bool refHit = referenceHit(A, B, C, ray, ref);
    const bool gotHit = TriangleRay(ray, kernel).intersect(A, B, C, 0.0, kInfinity, got);
    ++r.cases;
    if (refHit != gotHit) ++r.wrongDecisions;
    if (!refHit || !gotHit) continue;
    const double L = std::max({glm::length(B - A), glm::length(C - A), glm::length(o - A)});
    const double kappa = L * L / std::abs(glm::dot(glm::cross(B - A, C - A), ray.direction));
    const double tErr = std::abs(got.t - ref.t) / ref.t;
    const double baryErr = std::max(std::abs(got.beta - ref.beta), std::abs(got.gamma - ref.gamma));
    r.maxTError = std::max(r.maxTError, tErr);
    r.maxBaryError = std::max(r.maxBaryError, baryErr);
    r.maxTErrorOverBound = std::max(r.maxTErrorOverBound, tErr / (u * kappa * (2 + L / ref.t)));
    r.maxBaryErrorOverBound = std::max(r.maxBaryErrorOverBound, baryErr / (u * kappa));
  }
  return r;
}

namespace {
// Passes until this much time has gone by, and at least kThroughputPasses.
constexpr double kThroughputSeconds = 0.2;
constexpr int kThroughputPasses = 5;
}  // namespace

Scene knotThroughputScene() {
  Scene scene;
  scene.file = "knot.sce";
  scene.meshes.emplace_back("knot.off", makeOurSceneMesh("knot/knot.off"), Shading::Flat,
                            Material{});
  // From scenes/knot/knot.sce's eye, the knot's bounding sphere just fills
  // the view: the rays meet the mesh's BVH rather than miss its root box.
  const Aabb& box = scene.meshes[0].bounds();
  const Vec3 eye(0.0, 2.4, 7.0), center = box.center();
  const double radius = 0.5 * glm::length(box.extent());
  const double fovy = 2.0 * glm::degrees(std::asin(radius / glm::length(center - eye)));
  scene.camera = Camera(CameraSpec{eye, center, {0.0, 1.0, 0.0}, fovy, 256, 256});
  return scene;
}

ThroughputResult measureThroughput(const Scene& knot, TriangleKernel kernel) {
  TraceOptions options;
  options.triangle = kernel;
  const SceneIntersector intersector(knot, options);
  const int w = knot.camera.width(), h = knot.camera.height();
  std::vector<Ray> rays;
  rays.reserve(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) rays.push_back(knot.camera.primaryRay(x, y));
  ThroughputResult r, best;
  r.rays = rays.size();
  r.triangles = knot.triangleCount();
  // The fastest of several passes: other work on the machine only ever
  // slows a pass down, so the fastest is closest to the test's own speed.
  const auto first = std::chrono::steady_clock::now();
  for (int pass = 0;
       pass < kThroughputPasses ||
       std::chrono::duration<double>(std::chrono::steady_clock::now() - first).count() <
           kThroughputSeconds;
       ++pass) {
    ThroughputResult p = r;
    const auto start = std::chrono::steady_clock::now();
    for (const Ray& ray : rays) {
      Hit hit;
      p.hits += intersector.closestHit(ray, 0.0, hit, p.counters);
    }
    p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (pass == 0 || p.seconds < best.seconds) best = p;
  }
  return best;
}

std::vector<StabilityRow> measureStabilityTable(int samplesPerCase) {
  std::vector<StabilityRow> rows;
  const Scene knot = knotThroughputScene();
  for (const TriangleKernel& k : allTriangleKernels()) {
    StabilityRow row{k,
                     measureWatertightBox(k, 16, Vec3(0.1234, -0.0567, 0.0891)),
                     {},
                     {},
                     measureThroughput(knot, k)};
    std::uint64_t seed = 1;
    for (double scale : {1e-4, 1.0, 1e4})
      for (double offset : {0.0, 1e4, 1e6}) {
        const SelfHitResult s =
            measureSelfIntersection(ObjectKind::Mesh, k, scale, offset, samplesPerCase, seed++);
        row.selfHits.primaryHits += s.primaryHits;
        row.selfHits.spawned += s.spawned;
        row.selfHits.reHits += s.reHits;
      }
    for (IllConditioned f : {IllConditioned::Grazing, IllConditioned::Sliver, IllConditioned::Huge,
                             IllConditioned::Tiny}) {
      const AccuracyResult a = measureAccuracy(f, k, samplesPerCase, seed++);
      AccuracyResult& t = row.accuracy;
      t.cases += a.cases;
      t.wrongDecisions += a.wrongDecisions;
      t.maxTError = std::max(t.maxTError, a.maxTError);
      t.maxBaryError = std::max(t.maxBaryError, a.maxBaryError);
      t.maxTErrorOverBound = std::max(t.maxTErrorOverBound, a.maxTErrorOverBound);
      t.maxBaryErrorOverBound = std::max(t.maxBaryErrorOverBound, a.maxBaryErrorOverBound);
    }
    rows.push_back(row);
  }
  return rows;
}

std::string stabilityMarkdown(const std::vector<StabilityRow>& rows) {
  std::string out =
      "| triangle test | precision | leaks (box) | multiple hits | self re-hits | wrong "
      "hit/miss | max t error | max barycentric error | Mrays/s (knot, BVH, 1 core) |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  char line[512];
  for (const StabilityRow& r : rows) {
    std::snprintf(line, sizeof line,
                  "| %s | %s | %zu / %zu | %zu | %zu / %zu | %zu / %zu | %.2g | %.2g | %.2f |\n",
                  toString(r.kernel.test), toString(r.kernel.precision), r.watertight.leaks,
                  r.watertight.rays, r.watertight.multipleHits, r.selfHits.reHits,
                  r.selfHits.spawned, r.accuracy.wrongDecisions, r.accuracy.cases,
                  r.accuracy.maxTError, r.accuracy.maxBaryError, r.throughput.mraysPerSecond());
    out += line;
  }
  return out;
}

}  // namespace meshtrace
