#include "support/spec_renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <vector>

namespace meshtrace::test {

namespace {

// How far a spawned ray starts off its surface, relative to the size of
// the point's coordinates: far above double rounding (1e-16), far below
// any feature of a scene.
constexpr double kOffset = 1e-7;

struct Triangle {
  Vec3 a, b, c;
  std::uint32_t mesh, index;
};

struct Box {
  Vec3 lo{kInfinity}, hi{-kInfinity};
  void add(const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // Whether the ray meets the box at some 0 <= t <= tMax.
  bool met(const Ray& ray, double tMax) const {
    double t0 = 0.0, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
      if (ray.direction[a] == 0.0) {
        if (ray.origin[a] < lo[a] || ray.origin[a] > hi[a]) return false;
        continue;
      }
      double n = (lo[a] - ray.origin[a]) / ray.direction[a];
      double f = (hi[a] - ray.origin[a]) / ray.direction[a];
      if (n > f) std::swap(n, f);
      t0 = std::max(t0, n);
      t1 = std::min(t1, f);
      if (t0 > t1) return false;
    }
    return true;
  }
};

// What a ray met: the distance, the primitive's material, the shading
// normal and the geometric one, and the primitive's place in a plain loop
// over the scene (spheres, planes, cylinders, then each mesh's triangles in
// order), which decides between equal distances.
struct Found {
  double t = kInfinity;
  const Material* material = nullptr;
  Vec3 normal{0.0}, geometric{0.0};
  std::uint64_t place = 0;
};

// Every triangle of every mesh in a median-split BVH: each node's
// triangles are split at the median of their centroids along the axis
// where the centroids spread most, down to four.
class TriangleTree {
 public:
  explicit TriangleTree(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
    if (triangles_.empty()) return;
    nodes_.resize(1);
    build(0, 0, static_cast<std::uint32_t>(triangles_.size()));
  }

  // Calls hit(triangle) for every triangle in a leaf whose box the ray
  // meets before limit() (which may shrink meanwhile).
  template <typename Hit, typename Limit>
  void visit(const Ray& ray, const Hit& hit, const Limit& limit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[64] = {0};  // a median split is ~log2(n) deep
    int size = 1;
    while (size > 0) {
      const Node& node = nodes_[stack[--size]];
      if (!node.box.met(ray, limit())) continue;
      if (node.count > 0) {
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) hit(triangles_[k]);
        continue;
      }
      stack[size++] = node.first;
      stack[size++] = node.first + 1;
    }
  }

 private:
  struct Node {
    Box box;
    std::uint32_t first = 0, count = 0;  // leaf: triangles; else the children's index
  };

  void build(std::uint32_t index, std::uint32_t begin, std::uint32_t end) {
    Box box, centroids;
    for (std::uint32_t k = begin; k < end; ++k) {
      const Triangle& t = triangles_[k];
      box.add(t.a);
      box.add(t.b);
      box.add(t.c);
      centroids.add((t.a + t.b + t.c) / 3.0);
    }
    nodes_[index].box = box;
    if (end - begin <= 4) {
      nodes_[index].first = begin;
      nodes_[index].count = end - begin;
      return;
    }
    const Vec3 spread = centroids.hi - centroids.lo;
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0
                     : spread.y >= spread.z                       ? 1
                                                                  : 2;
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(triangles_.begin() + begin, triangles_.begin() + mid, triangles_.begin() + end,
                     [axis](const Triangle& p, const Triangle& q) {
                       return p.a[axis] + p.b[axis] + p.c[axis] < q.a[axis] + q.b[axis] + q.c[axis];
                     });
    const auto children = static_cast<std::uint32_t>(nodes_.size());
    nodes_.resize(children + 2);
    nodes_[index].first = children;
    build(children, begin, mid);
    build(children + 1, mid, end);
  }

  std::vector<Triangle> triangles_;
  std::vector<Node> nodes_;
};

class SpecRenderer {
 public:
  explicit SpecRenderer(const Scene& scene) : scene_(scene), tree_(triangles(scene)) {
    for (const Mesh& mesh : scene.meshes) {
      faceNormals_.push_back(faceNormals(mesh));
      vertexNormals_.push_back(vertexNormals(mesh, faceNormals_.back()));
    }
  }

  Color trace(const Ray& ray, int level) const {
    const Found hit = closest(ray);
    if (!hit.material) return scene_.background;
    const Material& m = *hit.material;
    const Vec3 p = ray.at(hit.t), n = hit.normal, v = -ray.direction;
    Color local = scene_.ambience * m.ambient;
    for (const Light& light : scene_.lights) {
      const Vec3 l = glm::normalize(light.position - p);
      const double nl = glm::dot(n, l);
      if (nl <= 0.0) continue;
      const Ray shadow{offPoint(p, hit.geometric, l), l};
      if (blocked(shadow, glm::length(light.position - shadow.origin))) continue;
      local += light.color * m.diffuse * nl;
      const Vec3 r = 2.0 * nl * n - l;
      const double rv = glm::dot(r, v);
      if (rv > 0.0) local += light.color * m.specular * std::pow(rv, m.shininess);
    }
    if (m.mirror <= 0.0 || level >= scene_.depth) return local;
    const Vec3 d = ray.direction - 2.0 * glm::dot(ray.direction, n) * n;
    const Color mirrored = trace({offPoint(p, hit.geometric, d), d}, level + 1);
    return (1.0 - m.mirror) * local + m.mirror * mirrored;
  }

 private:
  static std::vector<Triangle> triangles(const Scene& scene) {
    std::vector<Triangle> all;
    for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
      const auto& v = scene.meshes[m].vertices();
      const auto& t = scene.meshes[m].triangles();
      for (std::uint32_t i = 0; i < t.size(); ++i)
        all.push_back({v[t[i][0]], v[t[i][1]], v[t[i][2]], m, i});
    }
    return all;
  }

  // normalize((B - A) x (C - A)), zero for a degenerate triangle.
  static std::vector<Vec3> faceNormals(const Mesh& mesh) {
    std::vector<Vec3> normals;
    const auto& v = mesh.vertices();
    for (const TriangleIndices& t : mesh.triangles()) {
      const Vec3 n = glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]);
      const double length = glm::length(n);
      normals.push_back(length > 0.0 ? n / length : Vec3(0.0));
    }
    return normals;
  }

  // In one pass over the triangles: each adds its normal, weighted by its
  // opening angle there, to each of its corners.
  static std::vector<Vec3> vertexNormals(const Mesh& mesh, const std::vector<Vec3>& faces) {
    std::vector<Vec3> sums(mesh.vertices().size(), Vec3(0.0));
    const auto& v = mesh.vertices();
    for (std::size_t i = 0; i < mesh.triangles().size(); ++i) {
      const TriangleIndices& t = mesh.triangles()[i];
      for (int k = 0; k < 3; ++k) {
        const Vec3 u = v[t[(k + 1) % 3]] - v[t[k]], w = v[t[(k + 2) % 3]] - v[t[k]];
        const double lengths = glm::length(u) * glm::length(w);
        if (lengths == 0.0) continue;
        sums[t[k]] += std::acos(std::clamp(glm::dot(u, w) / lengths, -1.0, 1.0)) * faces[i];
      }
    }
    for (Vec3& s : sums)
      if (glm::length(s) > 0.0) s = glm::normalize(s);
    return sums;
  }

  // A point just off the surface at p, on the side of its geometric
  // normal that `direction` leaves to.
  static Vec3 offPoint(const Vec3& p, const Vec3& geometric, const Vec3& direction) {
    const double size = std::max({1.0, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    const double side = glm::dot(geometric, direction) < 0.0 ? -1.0 : 1.0;
    return p + side * kOffset * size * geometric;
  }

  // The nearest t > 0, and of equal ones the first in the plain loop.
  Found closest(const Ray& ray) const {
    Found found;
    std::uint64_t place = 0;  // of the shapes, counted as they are offered
    const auto offer = [&](double t, const Material& m, const Vec3& n, const Vec3& g,
                           std::uint64_t at) {
      if (t > 0.0 && (t < found.t || (t == found.t && at < found.place))) found = {t, &m, n, g, at};
    };
    for (const Sphere& s : scene_.spheres) {
      ++place;
      const Vec3 oc = ray.origin - s.center;
      const double b = glm::dot(oc, ray.direction);
      const double disc = b * b - (glm::dot(oc, oc) - s.radius * s.radius);
      if (disc < 0.0) continue;
      for (double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)})
        if (t > 0.0) {
          const Vec3 n = (ray.at(t) - s.center) / s.radius;
          offer(t, s.material, n, n, place);
          break;
        }
    }
    for (const Plane& pl : scene_.planes) {
      ++place;
      const double denom = glm::dot(ray.direction, pl.normal);
      if (denom != 0.0)
        offer(glm::dot(pl.point - ray.origin, pl.normal) / denom, pl.material, pl.normal, pl.normal,
              place);
    }
    for (const Cylinder& c : scene_.cylinders) {
      ++place;
      double t;
      Vec3 n;
      if (cylinder(c, ray, t, n)) offer(t, c.material, n, n, place);
    }
    // Triangles come after every shape: mesh, then index.
    const std::uint64_t firstTriangle = place + 1;
    tree_.visit(
        ray,
        [&](const Triangle& tri) {
          double beta, gamma, t;
          if (!cramer(tri, ray, beta, gamma, t) || t > found.t) return;
          const Mesh& mesh = scene_.meshes[tri.mesh];
          const Vec3& face = faceNormals_[tri.mesh][tri.index];
          Vec3 n = face;
          if (mesh.shading() == Shading::Phong) {
            const TriangleIndices& idx = mesh.triangles()[tri.index];
            const auto& vn = vertexNormals_[tri.mesh];
            n = glm::normalize((1.0 - beta - gamma) * vn[idx[0]] + beta * vn[idx[1]] +
                               gamma * vn[idx[2]]);
          }
          offer(t, mesh.material(), n, face,
                firstTriangle + (std::uint64_t{tri.mesh} << 32 | tri.index));
        },
        [&] { return found.t; });
    return found;
  }

  // Whether anything lies at 0 < t < limit.
  bool blocked(const Ray& ray, double limit) const { return closest(ray).t < limit; }

  // The open tube's nearer wall hit within its height, the normal radial
  // and turned to face the ray.
  static bool cylinder(const Cylinder& c, const Ray& ray, double& hitT, Vec3& normal) {
    const Vec3 w = ray.origin - c.center;
    const Vec3 dp = ray.direction - glm::dot(ray.direction, c.axis) * c.axis;
    const Vec3 wp = w - glm::dot(w, c.axis) * c.axis;
    const double a = glm::dot(dp, dp), b = 2.0 * glm::dot(dp, wp);
    const double disc = b * b - 4.0 * a * (glm::dot(wp, wp) - c.radius * c.radius);
    if (a == 0.0 || disc < 0.0) return false;
    for (double t : {(-b - std::sqrt(disc)) / (2.0 * a), (-b + std::sqrt(disc)) / (2.0 * a)}) {
      if (t <= 0.0) continue;
      const Vec3 q = ray.at(t) - c.center;
      const double along = glm::dot(q, c.axis);
      if (std::abs(along) > 0.5 * c.height) continue;
      normal = glm::normalize(q - along * c.axis);
      if (glm::dot(normal, ray.direction) > 0.0) normal = -normal;
      hitT = t;
      return true;
    }
    return false;
  }

  // o + t d = alpha A + beta B + gamma C by Cramer's rule on
  // [B-A  C-A  -d] (beta, gamma, t) = o - A, each determinant a triple
  // product: det = -(e1 x e2).d, and the numerators e2.(s x d),
  // -e1.(s x d) and (e1 x e2).s. On an edge two triangles share, rounding
  // decides which one a ray meets; in this form it mostly decides as the
  // course's reference images did.
  static bool cramer(const Triangle& tri, const Ray& ray, double& beta, double& gamma, double& t) {
    const Vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a, s = ray.origin - tri.a;
    const Vec3 n = glm::cross(e1, e2), sxd = glm::cross(s, ray.direction);
    const double det = -glm::dot(n, ray.direction);
    if (det == 0.0) return false;
    beta = glm::dot(e2, sxd) / det;
    gamma = -glm::dot(e1, sxd) / det;
    t = glm::dot(n, s) / det;
    return beta >= 0.0 && gamma >= 0.0 && beta + gamma <= 1.0 && t > 0.0;
  }

  const Scene& scene_;
  TriangleTree tree_;
  std::vector<std::vector<Vec3>> faceNormals_, vertexNormals_;
};

// The camera of the page: pixel (x, y), y = 0 the bottom row, looks along
// lower_left + x x_dir + y y_dir - eye.
class SpecCamera {
 public:
  explicit SpecCamera(const CameraSpec& c) : eye_(c.eye) {
    const Vec3 view = glm::normalize(c.center - c.eye);
    const double dist = glm::length(c.center - c.eye);
    const double imageHeight = 2.0 * dist * std::tan(glm::radians(c.fovyDegrees) / 2.0);
    const double imageWidth = double(c.width) / c.height * imageHeight;
    xDir_ = glm::normalize(glm::cross(view, c.up)) * imageWidth / double(c.width);
    yDir_ = glm::normalize(glm::cross(xDir_, view)) * imageHeight / double(c.height);
    lowerLeft_ = c.center - 0.5 * c.width * xDir_ - 0.5 * c.height * yDir_;
  }
  Ray ray(int x, int y) const {
    return {eye_, glm::normalize(lowerLeft_ + double(x) * xDir_ + double(y) * yDir_ - eye_)};
  }

 private:
  Vec3 eye_, xDir_, yDir_, lowerLeft_;
};

std::uint8_t byte(double c) {
  return static_cast<std::uint8_t>(std::floor(255.0 * std::clamp(c, 0.0, 1.0)));
}

}  // namespace

Image8 renderBySpec(const Scene& scene) {
  const CameraSpec& spec = scene.camera.spec();
  const SpecCamera camera(spec);
  const SpecRenderer renderer(scene);
  Image8 image{spec.width, spec.height,
               std::vector<std::uint8_t>(std::size_t{3} * spec.width * spec.height)};
  tbb::parallel_for(tbb::blocked_range<int>(0, spec.height), [&](const tbb::blocked_range<int>& r) {
    for (int row = r.begin(); row < r.end(); ++row)
      for (int x = 0; x < spec.width; ++x) {
        const Color c = renderer.trace(camera.ray(x, spec.height - 1 - row), 0);
        for (int k = 0; k < 3; ++k)
          image.rgb[(std::size_t(row) * spec.width + x) * 3 + k] = byte(c[k]);
      }
  });
  return image;
}

}  // namespace meshtrace::test
