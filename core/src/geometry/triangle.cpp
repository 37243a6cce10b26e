#include "meshtrace/geometry/triangle.h"

#include <stdexcept>
#include <string>

namespace meshtrace {

namespace {
template <typename E>
struct Named {
  E value;
  const char* name;
};
constexpr Named<TriangleTest> kTests[] = {{TriangleTest::Cramer, "cramer"},
                                          {TriangleTest::MollerTrumbore, "mt"},
                                          {TriangleTest::Watertight, "watertight"}};
constexpr Named<Precision> kPrecisions[] = {{Precision::Double, "double"},
                                            {Precision::Single, "single"}};

template <typename E, std::size_t N>
const char* nameOf(const Named<E> (&table)[N], E value) {
  for (const Named<E>& n : table)
    if (n.value == value) return n.name;
  return "?";
}

// Throws std::invalid_argument listing the known names.
template <typename E, std::size_t N>
E parseNamed(const Named<E> (&table)[N], std::string_view name, const char* what) {
  std::string known;
  for (const Named<E>& n : table) {
    if (name == n.name) return n.value;
    known += (known.empty() ? "" : ", ") + std::string(n.name);
  }
  throw std::invalid_argument("unknown " + std::string(what) + " '" + std::string(name) +
                              "' (use " + known + ")");
}
}  // namespace

const char* toString(TriangleTest test) { return nameOf(kTests, test); }
const char* toString(Precision precision) { return nameOf(kPrecisions, precision); }
TriangleTest parseTriangleTest(std::string_view name) {
  return parseNamed(kTests, name, "triangle test");
}
Precision parsePrecision(std::string_view name) {
  return parseNamed(kPrecisions, name, "precision");
}

bool intersectTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray,
                       double tMin, double tMax, TriangleHit& out) {
  return TriangleRay(ray, TriangleKernel{}).intersect(a, b, c, tMin, tMax, out);
}

Vec3 triangleNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  return len > 0.0 && std::isfinite(len) ? n / len : Vec3(0.0);
}

Vec3 cornerAngles(const Vec3& a, const Vec3& b, const Vec3& c) {
  // The angle between two edges as atan2(|u x v|, u . v): accurate for angles
  // near 0 and pi, where acos of a normalised dot product loses digits.
  const auto angle = [](const Vec3& u, const Vec3& v) {
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
  };
  return {angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)};
}

}  // namespace meshtrace
