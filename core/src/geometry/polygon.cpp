#include "meshtrace/geometry/polygon.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <numeric>

namespace meshtrace {

void appendPolygonTriangles(std::span<std::uint32_t> corners, std::vector<TriangleIndices>& out,
                            std::vector<PolygonFace>* polygons) {
  if (polygons && corners.size() > 3) {
    const auto first = static_cast<std::uint32_t>(out.size());
    const std::uint32_t face = polygons->empty() ? first : polygons->back().faceAfter(first);
    polygons->push_back({first, static_cast<std::uint32_t>(corners.size()), face});
  }
  std::size_t left = corners.size();
  while (left > 3) {
    // One round: cut ears (i, i+1, i+2) for even i and keep their first
    // corners, then the one or two corners no ear ended at.
    std::size_t kept = 0, i = 0;
    for (; i + 2 < left; i += 2) {
      out.push_back({corners[i], corners[i + 1], corners[i + 2]});
      corners[kept++] = corners[i];
    }
    for (; i < left; ++i) corners[kept++] = corners[i];
    left = kept;
  }
  out.push_back({corners[0], corners[1], corners[2]});
}

namespace {

using Point = glm::dvec2;

// Twice the signed area of (a, b, c): positive when they turn
// counter-clockwise.
double orient(const Point& a, const Point& b, const Point& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The reflex corners of a polygon by where they lie: a uniform grid over
// the corners' box, about one cell per reflex corner, so that an ear is
// tested only against the reflex corners near it. A corner stays in its
// cell when it stops being reflex (the caller skips it then).
class ReflexGrid {
 public:
  void build(std::span<const Point> points, std::size_t reflexCount) {
    Point hi = points[0];
    lo_ = points[0];
    for (const Point& p : points) {
      lo_ = glm::min(lo_, p);
      hi = glm::max(hi, p);
    }
    const Point size = hi - lo_;
    const double cells = static_cast<double>(std::max<std::size_t>(reflexCount, 1));
    // Square cells where the box allows; a box of no width or height is
    // one cell across it.
    const double side = std::sqrt(size.x * size.y / cells);
    nx_ = side > 0.0 ? std::clamp(static_cast<int>(size.x / side), 1, kMaxCellsAcross) : 1;
    ny_ = side > 0.0 ? std::clamp(static_cast<int>(size.y / side), 1, kMaxCellsAcross) : 1;
    if (side == 0.0)
      (size.x > size.y ? nx_ : ny_) = std::min(static_cast<int>(cells), kMaxCellsAcross);
    scale_ = Point(size.x > 0.0 ? nx_ / size.x : 0.0, size.y > 0.0 ? ny_ / size.y : 0.0);
    cells_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (std::vector<std::uint32_t>& cell : cells_) cell.clear();
  }
  void add(std::uint32_t corner, const Point& p) {
    cells_[static_cast<std::size_t>(row(p.y)) * nx_ + column(p.x)].push_back(corner);
  }
  // Calls visit(corner) for each corner in the cells that the box
  // [from, to] overlaps, until visit returns false; false then.
  template <typename Visit>
  bool forEachNear(const Point& from, const Point& to, Visit&& visit) const {
    const int x0 = column(from.x), x1 = column(to.x), y0 = row(from.y), y1 = row(to.y);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        for (const std::uint32_t corner : cells_[static_cast<std::size_t>(y) * nx_ + x])
          if (!visit(corner)) return false;
    return true;
  }

 private:
  static constexpr int kMaxCellsAcross = 1 << 12;
  // Monotone in the coordinate, so a point inside a box falls in a cell
  // the box's range covers; clamped before the conversion, which a value
  // beyond int's range would make undefined.
  static int cell(double offset, double scale, int cells) {
    return static_cast<int>(std::clamp(std::floor(offset * scale), 0.0, cells - 1.0));
  }
  int column(double x) const { return cell(x - lo_.x, scale_.x, nx_); }
  int row(double y) const { return cell(y - lo_.y, scale_.y, ny_); }

  Point lo_, scale_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
};

// One polygon's work space, reused from polygon to polygon on a thread.
struct PolygonScratch {
  std::vector<std::uint32_t> corners;              // vertex index of each corner, in order
  std::vector<TriangleIndices> positionTriangles;  // the triangles, as corner positions
  std::vector<std::uint32_t> positions;
  std::vector<Point> points;                 // the corners projected
  std::vector<std::uint32_t> prev, next;     // the ring of corners left
  std::vector<char> reflex;                  // a corner left that turns <= zero
  std::vector<std::uint32_t> reflexCorners;  // every corner ever flagged reflex
  ReflexGrid grid;                           // the same, by place, for many of them
  std::vector<TriangleIndices> clipped;
};

// A polygon's corners in order, from the triangles appendPolygonTriangles
// made of them: the same cuts made on the positions 0 .. n-1 say which
// position each triangle's corners hold.
void recoverCorners(std::span<const TriangleIndices> triangles, std::size_t n, PolygonScratch& s) {
  s.positionTriangles.clear();
  if (n == 4) {
    // The common polygon, (0 1 2) (0 2 3), without the general cut's work.
    s.positionTriangles.push_back({0, 1, 2});
    s.positionTriangles.push_back({0, 2, 3});
  } else {
    s.positions.resize(n);
    std::iota(s.positions.begin(), s.positions.end(), 0u);
    appendPolygonTriangles(s.positions, s.positionTriangles);
  }
  s.corners.resize(n);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) s.corners[s.positionTriangles[t][k]] = triangles[t][k];
}

// Projects the corners onto the coordinate plane across the largest
// component of the polygon's Newell normal (the plane it is most nearly
// parallel to), mirrored where needed so that the polygon runs
// counter-clockwise there. Returns the doubled area below which a turn
// counts as none, or 0 when the polygon has no area to tile.
double project(std::span<const Vec3> vertices, PolygonScratch& s) {
  const std::size_t n = s.corners.size();
  // Relative to corner 0, so that a polygon far from the origin keeps the
  // digits of its own size.
  const Vec3 origin = vertices[s.corners[0]];
  Vec3 normal(0.0);
  for (std::size_t i = 0; i < n; ++i)
    normal +=
        glm::cross(vertices[s.corners[i]] - origin, vertices[s.corners[(i + 1) % n]] - origin);
  const Vec3 m = glm::abs(normal);
  const int axis = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
  if (!(m[axis] > 0.0) || !std::isfinite(m[axis])) return 0.0;
  // (x, y) for the z axis, (y, z) for x, (z, x) for y: the component of
  // the normal across each plane is twice the polygon's area in it.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const bool mirror = normal[axis] < 0.0;
  double extent = 0.0;
  s.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = vertices[s.corners[i]] - origin;
    s.points[i] = mirror ? Point(d[v], d[u]) : Point(d[u], d[v]);
    extent = std::max({extent, std::abs(d[u]), std::abs(d[v])});
  }
  // orient() of points within `extent` of the origin rounds by a few units
  // in the last place of extent^2; a turn inside 64 of them is no turn.
  const double zero = 64.0 * std::numeric_limits<double>::epsilon() * extent * extent;
  return std::isfinite(zero) ? zero : 0.0;
}

// Whether any of `triangles` has an area beyond rounding.
bool hasArea(std::span<const Vec3> vertices, std::span<const TriangleIndices> triangles) {
  const Vec3 origin = vertices[triangles[0][0]];
  double extent = 0.0, largest = 0.0;
  for (const TriangleIndices& t : triangles) {
    const Vec3 a = vertices[t[0]] - origin, b = vertices[t[1]] - origin,
               c = vertices[t[2]] - origin;
    extent = std::max({extent, glm::length(a), glm::length(b), glm::length(c)});
    largest = std::max(largest, glm::length(glm::cross(b - a, c - a)));
  }
  return largest > 64.0 * std::numeric_limits<double>::epsilon() * extent * extent;
}

// Whether the polygon's triangles all turn its way (none by less than
// -zero). Then they tile it: the triangles' boundaries add up to the
// polygon's, so the number of triangles over a point, each counted +1 or
// -1 by its turn, is the polygon's winding number there; none turning
// backwards, that is 1 inside and 0 outside.
bool tilesIt(const PolygonScratch& s, double zero) {
  for (const TriangleIndices& t : s.positionTriangles)
    if (orient(s.points[t[0]], s.points[t[1]], s.points[t[2]]) < -zero) return false;
  return true;
}

// Ear clipping: a simple polygon of four corners or more has an ear, a
// convex corner whose triangle with its two neighbours holds no other
// corner (Meisters, 1975). It is cut off, and the rest clipped again. Only
// reflex corners (or flat ones) can lie in such a triangle, so only those
// are tested, and with many of them only those near the ear (ReflexGrid).
// A flat corner, on the line through its neighbours, is cut as a triangle
// of no area when it is met, which leaves the same shape. Fills s.clipped,
// in the polygon's winding; false when no ear is left (the polygon crosses
// itself) or the tests pass the allowance.
bool clipEars(PolygonScratch& s, double zero) {
  const auto n = static_cast<std::uint32_t>(s.points.size());
  const std::vector<Point>& p = s.points;
  s.prev.resize(n);
  s.next.resize(n);
  s.reflex.assign(n, 0);
  s.reflexCorners.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    s.prev[i] = (i + n - 1) % n;
    s.next[i] = (i + 1) % n;
  }
  const auto turn = [&](std::uint32_t i) { return orient(p[s.prev[i]], p[i], p[s.next[i]]); };
  // Below this many reflex corners, an ear is tested against all of them.
  constexpr std::size_t kGridFrom = 64;
  bool gridded = false;
  // A corner's turn changes only when a neighbour is cut; a corner that
  // turns by zero or less is tested against every ear near it.
  const auto flag = [&](std::uint32_t i) {
    const bool reflex = turn(i) <= zero;
    if (reflex && !s.reflex[i]) {
      s.reflexCorners.push_back(i);
      if (gridded) s.grid.add(i, p[i]);
    }
    s.reflex[i] = reflex;
  };
  for (std::uint32_t i = 0; i < n; ++i) flag(i);
  if (s.reflexCorners.size() >= kGridFrom) {
    s.grid.build(p, s.reflexCorners.size());
    for (const std::uint32_t q : s.reflexCorners) s.grid.add(q, p[q]);
    gridded = true;
  }

  const std::size_t allowed = kEarClipTestsPerCorner * n;
  std::size_t tests = 0;
  const auto isEar = [&](std::uint32_t b) {
    ++tests;
    if (s.reflex[b]) return false;
    const std::uint32_t a = s.prev[b], c = s.next[b];
    const Point &pa = p[a], &pb = p[b], &pc = p[c];
    // Whether reflex corner q leaves the ear free.
    const auto outside = [&](std::uint32_t q) {
      if (!s.reflex[q] || q == a || q == c) return true;
      ++tests;
      const Point& pq = p[q];
      // A corner at the same place as one of the ear's (a polygon whose
      // hole is joined to its outline by a cut passes a point twice) does
      // not block it.
      if (pq == pa || pq == pb || pq == pc) return true;
      return !(orient(pa, pb, pq) >= -zero && orient(pb, pc, pq) >= -zero &&
               orient(pc, pa, pq) >= -zero);
    };
    if (!gridded) return std::all_of(s.reflexCorners.begin(), s.reflexCorners.end(), outside);
    // The points the test above counts as inside: barycentric coordinates
    // of at least -e each, e = zero / orient(a, b, c) (under 1: b is
    // convex), a triangle whose corners are a + e (2a - b - c) and so on.
    // Its box, grown by a few units in the last place against rounding,
    // holds every corner the test could find.
    const double e = zero / orient(pa, pb, pc);
    const Point ga = pa + e * ((pa - pb) + (pa - pc)), gb = pb + e * ((pb - pc) + (pb - pa)),
                gc = pc + e * ((pc - pa) + (pc - pb));
    const Point lo = glm::min(glm::min(ga, gb), gc), hi = glm::max(glm::max(ga, gb), gc);
    const Point slack =
        8.0 * std::numeric_limits<double>::epsilon() * (glm::abs(lo) + glm::abs(hi) + (hi - lo));
    return s.grid.forEachNear(lo - slack, hi + slack, outside);
  };
  std::uint32_t left = n;
  const auto cut = [&](std::uint32_t b) {
    const std::uint32_t a = s.prev[b], c = s.next[b];
    s.clipped.push_back({s.corners[a], s.corners[b], s.corners[c]});
    s.next[a] = c;
    s.prev[c] = a;
    s.reflex[b] = 0;
    --left;
    flag(a);
    flag(c);
    return c;
  };
  const auto flat = [&](std::uint32_t i) { return std::abs(turn(i)) <= zero; };

  s.clipped.clear();
  std::uint32_t at = 0, misses = 0;  // corners looked at since the last cut
  while (left > 3) {
    if (tests > allowed) return false;
    if (flat(at) || isEar(at)) {
      at = cut(at);
      // A corner the cut left flat goes next, so that a row of them (a
      // comb's valleys once its teeth are cut) is cut into triangles of no
      // area, not into a fan of slivers from a corner beside the row.
      // Otherwise the corner after the cut's is tried next, not the
      // cut's: an ear there would share the cut's first corner, and a run
      // of such ears (along a row of many corners) makes a fan whose long
      // slivers' boxes all hold the points near its apex. Skipping one
      // cuts a run in rounds of every other corner, as
      // appendPolygonTriangles does, and the slivers stay short.
      at = flat(s.prev[at]) ? s.prev[at] : s.next[at];
      misses = 0;
      continue;
    }
    at = s.next[at];
    // No ear and no flat corner: every corner left is reflex or holds
    // another in its triangle, so the polygon crosses itself.
    if (++misses >= left) return false;
  }
  if (turn(at) < -zero) return false;
  s.clipped.push_back({s.corners[s.prev[at]], s.corners[at], s.corners[s.next[at]]});
  return true;
}

}  // namespace

PolygonTiling tileNonConvexPolygons(std::span<const Vec3> vertices,
                                    std::span<const PolygonFace> polygons,
                                    std::span<TriangleIndices> triangles) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, polygons.size(), 1024), PolygonTiling{},
      [&](const tbb::blocked_range<std::size_t>& r, PolygonTiling acc) {
        PolygonScratch s;
        for (std::size_t k = r.begin(); k < r.end(); ++k) {
          const PolygonFace& face = polygons[k];
          if (face.corners < 4) continue;  // a face left out: no triangles to tile
          const std::span<TriangleIndices> own =
              triangles.subspan(face.firstTriangle, face.corners - 2);
          recoverCorners(own, face.corners, s);
          const double zero = project(vertices, s);
          if (zero == 0.0) {
            // No area, yet triangles with some: it winds both ways alike
            // (a bow tie).
            acc.untiled += hasArea(vertices, own);
            continue;
          }
          if (tilesIt(s, zero)) continue;
          if (!clipEars(s, zero)) {
            ++acc.untiled;
            continue;
          }
          std::copy(s.clipped.begin(), s.clipped.end(), own.begin());
          ++acc.recut;
        }
        return acc;
      },
      [](PolygonTiling a, const PolygonTiling& b) {
        a.recut += b.recut;
        a.untiled += b.untiled;
        return a;
      });
}

}  // namespace meshtrace
