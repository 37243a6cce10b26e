#include "render/progressive_preview.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>

#include "accel/primitive_query.h"

namespace meshtrace {

namespace {
// Triangles per chunk; a mesh in no order of its surface gets 1.
constexpr std::uint32_t kChunkTriangles = 16;
// About a cell per chunk: most cells of a surface's grid are empty, the
// others hold a few chunks.
constexpr double kCellsPerChunk = 1.0;
constexpr double kMaxCells = double(1 << 22);
constexpr int kMaxResolution = 512;
// Chunks over more cells than this on average are spread out: their
// triangles are not in surface order (chunks of one follow), or huge (a
// coarser grid follows).
constexpr double kMaxEntriesPerChunk = 8.0;
constexpr std::size_t kGrain = 1024;

// The float just below (or above) a double: a box rounded outward.
float down(double v) {
  const float f = static_cast<float>(v);
  return double(f) <= v ? f : std::nextafter(f, -INFINITY);
}
float up(double v) {
  const float f = static_cast<float>(v);
  return double(f) >= v ? f : std::nextafter(f, INFINITY);
}
}  // namespace

PreviewGrid::PreviewGrid(const Scene& scene, TriangleKernel kernel)
    : scene_(scene), kernel_(kernel) {
  std::size_t triangles = 0;
  for (const Mesh& m : scene.meshes) {
    if (!m.triangles().empty()) bounds_.extend(m.bounds());
    triangles += m.triangles().size();
  }
  if (triangles == 0) return;
  if (build(kChunkTriangles, kCellsPerChunk * double(triangles) / kChunkTriangles)) return;
  // Single triangles, on a coarser grid while some span too many cells.
  for (double cells = kCellsPerChunk * double(triangles); !build(1, cells); cells /= 8.0) {
  }
}

bool PreviewGrid::build(std::uint32_t size, double cellsWanted) {
  // The chunks, mesh by mesh, and their boxes (one pass over the triangles).
  std::size_t chunkCount = 0;
  for (const Mesh& mesh : scene_.meshes) chunkCount += (mesh.triangles().size() + size - 1) / size;
  BuildVector<Chunk> chunks(chunkCount);
  std::size_t next = 0;
  for (std::uint32_t m = 0; m < scene_.meshes.size(); ++m) {
    const auto n = static_cast<std::uint32_t>(scene_.meshes[m].triangles().size());
    for (std::uint32_t first = 0; first < n; first += size)
      chunks[next++] = {m, first, std::min(size, n - first), {}, {}};
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i) {
                        Chunk& c = chunks[i];
                        const Mesh& mesh = scene_.meshes[c.mesh];
                        Aabb box;
                        for (std::uint32_t t = c.first; t < c.first + c.count; ++t)
                          for (std::uint32_t v : mesh.triangles()[t])
                            box.extend(mesh.vertices()[v]);
                        for (int a = 0; a < 3; ++a) {
                          c.lo[a] = down(box.min[a]);
                          c.hi[a] = up(box.max[a]);
                        }
                      }
                    });
  const auto boxOf = [](const Chunk& c) {
    return Aabb{Vec3(c.lo[0], c.lo[1], c.lo[2]), Vec3(c.hi[0], c.hi[1], c.hi[2])};
  };
  const Vec3 extent = bounds_.extent();
  // A flat mesh still gets cells of a sensible shape along its thin axis.
  const double largest = std::max({extent.x, extent.y, extent.z, 1e-300});
  const Vec3 sides = glm::max(extent, Vec3(largest * 1e-3));
  const double cells = std::clamp(cellsWanted, 1.0, kMaxCells);
  const double side = std::cbrt(sides.x * sides.y * sides.z / cells);
  std::size_t total = 1;
  for (int a = 0; a < 3; ++a) {
    res_[a] = std::clamp(static_cast<int>(std::ceil(sides[a] / side)), 1, kMaxResolution);
    cellSize_[a] = extent[a] > 0.0 ? extent[a] / res_[a] : 1.0;
    inverseCell_[a] = 1.0 / cellSize_[a];
    total *= static_cast<std::size_t>(res_[a]);
  }
  // Count, then fill each cell through a cursor of its own (the order in a
  // cell does not matter: ties go by primitive, primitive_query.h).
  std::vector<std::atomic<std::uint32_t>> count(total);
  std::atomic<std::size_t> entries{0};
  const auto forEachCell = [&](const Chunk& c, const auto& fn) {
    int lo[3], hi[3];
    cellRange(boxOf(c), lo, hi);
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) fn(cellIndex(x, y, z));
  };
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      std::size_t n = 0;
                      for (std::size_t i = r.begin(); i < r.end(); ++i)
                        forEachCell(chunks[i], [&](std::size_t cell) {
                          count[cell].fetch_add(1, std::memory_order_relaxed);
                          ++n;
                        });
                      entries.fetch_add(n, std::memory_order_relaxed);
                    });
  if (cells > 1.0 && double(entries.load()) > kMaxEntriesPerChunk * double(chunks.size()))
    return false;
  cellStart_.resize(total + 1);
  std::uint32_t at = 0;
  for (std::size_t c = 0; c < total; ++c) {
    cellStart_[c] = at;
    at += count[c].load(std::memory_order_relaxed);
    count[c].store(cellStart_[c], std::memory_order_relaxed);
  }
  cellStart_[total] = at;
  refs_.resize(at);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks.size(), kGrain),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i)
                        forEachCell(chunks[i], [&](std::size_t cell) {
                          refs_[count[cell].fetch_add(1, std::memory_order_relaxed)] =
                              static_cast<std::uint32_t>(i);
                        });
                    });
  chunks_ = std::move(chunks);
  chunkSize_ = size;
  return true;
}

void PreviewGrid::cellRange(const Aabb& box, int lo[3], int hi[3]) const {
  // A little slack: a box on a cell boundary is listed on both sides. The
  // positions are >= -slack, so truncation is the floor after the max.
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
  const RayInverse inverse(ray);
  double tEnter, tExit;
  if (!intersectSlabs(bounds_, inverse, search.query().tMin(), search.limit(), tEnter, tExit))
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
    for (std::uint32_t k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
      const Chunk& chunk = chunks_[refs_[k]];
      if (chunkSize_ > 1) {
        const Aabb box{Vec3(chunk.lo[0], chunk.lo[1], chunk.lo[2]),
                       Vec3(chunk.hi[0], chunk.hi[1], chunk.hi[2])};
        double t0, t1;
        if (!intersectSlabs(box, inverse, search.query().tMin(), search.limit(), t0, t1)) continue;
      }
      for (std::uint32_t t = chunk.first; t < chunk.first + chunk.count; ++t)
        if (search.triangle(chunk.mesh, t)) return true;
    }
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
