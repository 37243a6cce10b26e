#pragma once
// Everything the viewer's pixel inspector shows about one pixel, recorded
// while the renderer's own shading routine (whitted.h) traces it: the hit, its normals, the shading
// per light (and what blocks a shadowed light), each reflection bounce and the mesh boxes the ray
// entered. Its colour is the Integrator's, to the bit (a test holds it to
// that), so what it explains is what was rendered.
#include <cstdint>
#include <optional>
#include <vector>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/geometry/mesh.h"
#include "meshtrace/util/counters.h"

namespace meshtrace {

struct LightRecord {
  std::size_t light = 0;
  Vec3 toLight{0.0};  // unit direction l from the hit point to the light
  double nDotL = 0.0;
  bool facing = false;                  // n.l > 0; a light behind the surface casts no shadow ray
  bool shadowed = false;                // a shadow ray was cast and something blocked it
  std::optional<PrimitiveRef> blocker;  // the nearest thing in the way, when shadowed
  double blockerT = 0.0;
  Color diffuse{0.0};
  Color specular{0.0};
};

struct SurfaceRecord {
  PrimitiveRef ref;
  FaceOfTriangle face;  // meshes only: the face of the file the triangle was cut from
  double t = 0.0;
  Vec3 point{0.0};
  double alpha = 0.0, beta = 0.0, gamma = 0.0;  // triangles only
  Vec3 geometricNormal{0.0};                    // the triangle's flat normal, or the shape's normal
  bool phong = false;  // a PHONG mesh: the shading normal interpolates the vertex normals
  bool hasVertexNormals = false;  // the mesh holds vertex normals (PHONG, or once PHONG)
  Vec3 vertexNormals[3] = {Vec3(0.0), Vec3(0.0), Vec3(0.0)};
  Vec3 shadingNormal{0.0};          // the normal shading used
  double normalAngleDegrees = 0.0;  // between the geometric and the shading normal
};

// A mesh box the ray enters (t >= 0), nearest first.
struct BoxRecord {
  std::uint32_t mesh = 0;
  double tEnter = 0.0, tExit = 0.0;
};

// The two levels of the scene's BVH (--accel bvh): the objects' tree
// (spheres, cylinders, small meshes and the triangle BVH as one object),
// and the triangle BVH over the larger meshes.
enum class BvhLevel : std::uint8_t { Objects, Triangles };
const char* toString(BvhLevel level);

// A node of the scene's BVH, for drawing: its box (its children's, as the
// traversal tests them), its depth in its level (the root at 0), whether
// it is a leaf.
struct BvhNodeBox {
  Aabb box;
  int depth = 0;
  BvhLevel level = BvhLevel::Triangles;
  bool leaf = false;
};

struct BounceRecord {
  int level = 0;
  Ray ray;
  bool hit = false;
  SurfaceRecord surface;
  std::vector<BoxRecord> boxes;
  // The BVH nodes of both levels whose box the ray meets before its hit:
  // those every closest-hit traversal enters (one that meets a farther hit
  // first enters more). Empty without a BVH.
  std::vector<BvhNodeBox> nodes;
  Color ambient{0.0};
  std::vector<LightRecord> lights;
  Color local{0.0};       // ambient plus every light
  double mirror = 0.0;    // the material's reflectivity
  bool reflects = false;  // a reflected ray follows (mirror > 0 and level < depth)
  double weight = 1.0;    // share of the pixel this level's colour carries
  Color color{0.0};       // what this level returns, reflections included
};

struct PixelInspection {
  double x = 0.0, y = 0.0;            // y = 0 is the bottom row
  std::vector<BounceRecord> bounces;  // [0] is the primary ray
  Color color{0.0};
  Counters counters;
};

// Through `camera`, which need not be the scene's own.
PixelInspection inspectPixel(const SceneIntersector& intersector, const Camera& camera, double x,
                             double y);

// The nodes of one level of the scene's BVH at `depth`, with the leaves
// that end above it: together they cover everything the level holds.
struct BvhCut {
  std::vector<BvhNodeBox> boxes;  // at most the limit asked for, in the tree's order
  bool truncated = false;         // more nodes lie at that depth
  int levelDepth = 0;             // the deepest node of the level
};
// Empty without a BVH (--accel bvh) or a level that holds nothing.
BvhCut bvhCut(const SceneIntersector& intersector, BvhLevel level, int depth, std::size_t limit);

// What the false-colour views need from a primary ray, cheaply.
struct PixelProbe {
  float depth = -1.0f;                   // t of the primary hit; negative for a miss
  float normal[3] = {0.0f, 0.0f, 0.0f};  // shading normal
  std::int32_t object = -1;              // global object index, see objectIndex(); -1 for a miss
  ObjectKind kind = ObjectKind::Sphere;
  std::uint32_t index = 0;     // index within its kind
  std::uint32_t triangle = 0;  // meshes only
  float beta = 0.0f, gamma = 0.0f;
  std::uint16_t boxHits = 0;  // mesh boxes met at t >= 0, as debug_aabb counts them
  std::uint32_t cost = 0;     // traversal cost of the closest-hit query

  bool hit() const { return object >= 0; }
};

PixelProbe probePixel(const SceneIntersector& intersector, const Camera& camera, double x,
                      double y);

// Spheres, then planes, cylinders and meshes, in scene order.
std::int32_t objectIndex(const Scene& scene, const PrimitiveRef& ref);

// The traversal cost of a query: the BVH nodes it entered, the mesh boxes it
// tested and the primitives (triangles, spheres, planes, cylinders) it tested.
std::uint64_t traversalCost(const Counters& counters);

}  // namespace meshtrace
