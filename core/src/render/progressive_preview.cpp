#include "render/progressive_preview.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

#include "accel/primitive_query.h"

namespace meshtrace {

namespace {
// A cell per two triangles: on a surface mesh most cells are empty and the
// others hold tens of triangles, few enough for a coarse pass, and the
// tables stay small. Capped for the same reason.
constexpr double kCellsPerTriangle = 0.5;
constexpr double kMaxCells = double(1 << 22);
constexpr int kMaxResolution = 512;
// A triangle whose box overlaps many cells is listed in each: should the
// triangles over several cells need this many entries per triangle (a few
// huge triangles over a fine grid), the grid is made coarser.
constexpr std::size_t kMaxRefsPerTriangle = 16;
constexpr std::size_t kGrain = 4096;
constexpr std::uint32_t kSeveralCells = 0xffffffffu;

template <typename Fn>
void forEachTriangle(const Scene& scene, const Fn& fn) {
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(
                          0, static_cast<std::uint32_t>(mesh.triangles().size()), kGrain),
                      [&](const tbb::blocked_range<std::uint32_t>& r) {
                        for (std::uint32_t t = r.begin(); t < r.end(); ++t) fn(m, t);
                      });
  }
}

Aabb triangleBox(const Mesh& mesh, std::uint32_t t) {
  Aabb box;
  for (std::uint32_t v : mesh.triangles()[t]) box.extend(mesh.vertices()[v]);
  return box;
}
}  // namespace

PreviewGrid::PreviewGrid(const Scene& scene, TriangleKernel kernel)
    : scene_(scene), kernel_(kernel) {
  std::size_t triangles = 0;
  for (const Mesh& m : scene.meshes) {
    if (m.triangles().empty()) continue;
    bounds_.extend(m.bounds());
    triangles += m.triangles().size();
  }
  if (triangles == 0) return;
  const Vec3 extent = bounds_.extent();
  // A flat mesh still gets cells of a sensible shape along its thin axis.
  const double largest = std::max({extent.x, extent.y, extent.z, 1e-300});
  const Vec3 sides = glm::max(extent, Vec3(largest * 1e-3));
  double cells = std::min(kMaxCells, kCellsPerTriangle * double(triangles));
  // Per triangle of each mesh, the one cell it lies in, or kSeveralCells.
  std::vector<std::vector<std::uint32_t>> only(scene.meshes.size());
  for (std::size_t m = 0; m < scene.meshes.size(); ++m)
    only[m].resize(scene.meshes[m].triangles().size());
  for (;;) {
    const double side = std::cbrt(sides.x * sides.y * sides.z / cells);
    std::size_t total = 1;
    for (int a = 0; a < 3; ++a) {
      res_[a] = std::clamp(static_cast<int>(std::ceil(sides[a] / side)), 1, kMaxResolution);
      cellSize_[a] = extent[a] > 0.0 ? extent[a] / res_[a] : 1.0;
      inverseCell_[a] = 1.0 / cellSize_[a];
      total *= static_cast<std::size_t>(res_[a]);
    }
    std::vector<std::atomic<std::uint32_t>> count(total);
    // Most triangles lie in one cell: the first pass notes which, so the
    // second fills those without reading their vertices again.
    std::atomic<std::size_t> spanning{0};
    forEachTriangle(scene, [&](std::uint32_t m, std::uint32_t t) {
      int lo[3], hi[3];
      cellRange(triangleBox(scene.meshes[m], t), lo, hi);
      if (lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2]) {
        const std::size_t c = cellIndex(lo[0], lo[1], lo[2]);
        only[m][t] = static_cast<std::uint32_t>(c);
        count[c].fetch_add(1, std::memory_order_relaxed);
        return;
      }
      only[m][t] = kSeveralCells;
      std::size_t n = 0;
      for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
          for (int x = lo[0]; x <= hi[0]; ++x, ++n)
            count[cellIndex(x, y, z)].fetch_add(1, std::memory_order_relaxed);
      spanning.fetch_add(n, std::memory_order_relaxed);
    });
    if (spanning.load() > kMaxRefsPerTriangle * triangles && cells > 1.0) {
      cells = std::max(1.0, cells / 8.0);
      continue;
    }
    std::size_t refs = 0;
    cellStart_.resize(total + 1);
    for (std::size_t c = 0; c < total; ++c) {
      cellStart_[c] = static_cast<std::uint32_t>(refs);
      refs += count[c].load(std::memory_order_relaxed);
      // The second pass writes each triangle into its cells through a
      // cursor per cell (the order inside a cell does not matter: ties go
      // by primitive, primitive_query.h).
      count[c].store(cellStart_[c], std::memory_order_relaxed);
    }
    cellStart_[total] = static_cast<std::uint32_t>(refs);
    refs_.resize(refs);
    forEachTriangle(scene, [&](std::uint32_t m, std::uint32_t t) {
      if (only[m][t] != kSeveralCells) {
        refs_[count[only[m][t]].fetch_add(1, std::memory_order_relaxed)] = {m, t};
        return;
      }
      int lo[3], hi[3];
      cellRange(triangleBox(scene.meshes[m], t), lo, hi);
      for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
          for (int x = lo[0]; x <= hi[0]; ++x)
            refs_[count[cellIndex(x, y, z)].fetch_add(1, std::memory_order_relaxed)] = {m, t};
    });
    return;
  }
}

void PreviewGrid::cellRange(const Aabb& box, int lo[3], int hi[3]) const {
  // A little slack: a triangle on a cell boundary is listed on both sides.
  // The positions are >= -slack, so truncation is the floor after the max.
  constexpr double kSlack = 1e-9;
  for (int a = 0; a < 3; ++a) {
    const double l = std::max(0.0, (box.min[a] - bounds_.min[a]) * inverseCell_[a] - kSlack);
    const double h = std::max(0.0, (box.max[a] - bounds_.min[a]) * inverseCell_[a] + kSlack);
    lo[a] = std::min(static_cast<int>(l), res_[a] - 1);
    hi[a] = std::min(static_cast<int>(h), res_[a] - 1);
  }
}

template <typename Search>
bool PreviewGrid::trace(Search& search, Counters& counters) const {
  for (std::uint32_t i = 0; i < scene_.spheres.size(); ++i)
    if (search.shape(ObjectKind::Sphere, i)) return true;
  for (std::uint32_t i = 0; i < scene_.planes.size(); ++i)
    if (search.shape(ObjectKind::Plane, i)) return true;
  for (std::uint32_t i = 0; i < scene_.cylinders.size(); ++i)
    if (search.shape(ObjectKind::Cylinder, i)) return true;
  if (refs_.empty()) return false;
  const Ray& ray = search.query().ray();
  double tEnter, tExit;
  if (!intersectSlabs(bounds_, RayInverse(ray), search.query().tMin(), search.limit(), tEnter,
                      tExit))
    return false;
  // The cell the ray enters, and per axis the step, the distance to the
  // next cell boundary and between boundaries.
  int cell[3], step[3];
  double next[3], delta[3];
  for (int a = 0; a < 3; ++a) {
    const double p = ray.origin[a] + tEnter * ray.direction[a];
    cell[a] = std::clamp(static_cast<int>(std::floor((p - bounds_.min[a]) / cellSize_[a])), 0,
                         res_[a] - 1);
    const double d = ray.direction[a];
    if (d == 0.0) {
      step[a] = 0;
      next[a] = delta[a] = kInfinity;
      continue;
    }
    step[a] = d > 0.0 ? 1 : -1;
    const double boundary = bounds_.min[a] + (cell[a] + (d > 0.0 ? 1 : 0)) * cellSize_[a];
    next[a] = (boundary - ray.origin[a]) / d;
    delta[a] = cellSize_[a] / std::abs(d);
  }
  for (;;) {
    ++counters.nodeVisits;
    const std::size_t c = cellIndex(cell[0], cell[1], cell[2]);
    for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k)
      if (search.triangle(refs_[k].mesh, refs_[k].triangle)) return true;
    const int a = next[0] < next[1] ? (next[0] < next[2] ? 0 : 2) : (next[1] < next[2] ? 1 : 2);
    // Every hit nearer than the cell's far side lies in a cell walked so far.
    if (search.limit() <= next[a] || next[a] > tExit) return false;
    cell[a] += step[a];
    if (cell[a] < 0 || cell[a] >= res_[a]) return false;
    next[a] += delta[a];
  }
}

bool PreviewGrid::closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters) const {
  ClosestHitSearch search(hit, scene_, ray, kernel_, tMin, counters);
  trace(search, counters);
  return search.found();
}

bool PreviewGrid::occluded(const Ray& ray, double tMin, double tMax, Counters& counters) const {
  AnyHitSearch search(tMax, scene_, ray, kernel_, tMin, counters);
  return trace(search, counters);
}

}  // namespace meshtrace
