// Binned SAH build (see binary_bvh.h). Primitives are handled as 32-byte float
// references (box rounded outward, index in the spare lane) that are
// partitioned in place, so every pass reads memory in order; SSE does the box
// arithmetic. Float boxes are conservative: rounded outward, they still hold
// every primitive exactly.
#include "accel/binary_bvh.h"

#include <emmintrin.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>
#include <xmmintrin.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <utility>
#include <vector>

#include "accel/triangle_copies.h"
#include "accel/triangle_set.h"

namespace meshtrace {

namespace {

constexpr int kMaxBins = 32;
// Below these sizes a node's work is too small to be worth a task.
constexpr std::uint32_t kParallelScan = 32768;
constexpr std::uint32_t kParallelSubtrees = 4096;
// Past this depth nodes are split at the centroid median, which bounds the
// depth by this plus log2(n) <= kMaxBvhDepth.
constexpr int kMedianDepth = 64;
// A node of at least twice this many primitives bins every k-th of them,
// k = n / kBinSample: 4096 to 8191 of them. The top levels' splits are
// chosen about as well from such a sample (the tree's SAH cost rises under
// 1%; an eighth of it, over 1.5%), and their boxes are then gathered in the
// pass after the partition, which reads every primitive anyway.
constexpr std::uint32_t kBinSample = 4096;

float roundDown(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? nextDown(f) : f;
}
float roundUp(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? nextUp(f) : f;
}

// Lanes x, y, z. The w lane of a primitive's box holds its index, whose bit
// pattern is a denormal float: it is masked off before any arithmetic, which
// would otherwise run into the (very slow) denormal assists.
inline __m128 xyz(__m128 v) {
  return _mm_and_ps(v, _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)));
}

// A box rounded outward to float, in SSE lanes x, y, z.
struct FloatBox {
  __m128 lo, hi;
};

FloatBox roundedOutward(const Aabb& b) {
  return {_mm_setr_ps(roundDown(b.min.x), roundDown(b.min.y), roundDown(b.min.z), 0.0f),
          _mm_setr_ps(roundUp(b.max.x), roundUp(b.max.y), roundUp(b.max.z), 0.0f)};
}

// A float box in SSE lanes x, y, z (w: see xyz).
struct Box4 {
  __m128 lo = _mm_set1_ps(std::numeric_limits<float>::infinity());
  __m128 hi = _mm_set1_ps(-std::numeric_limits<float>::infinity());

  void extend(__m128 l, __m128 h) {
    lo = _mm_min_ps(lo, l);
    hi = _mm_max_ps(hi, h);
  }
  void extend(const Box4& b) { extend(b.lo, b.hi); }
  // Half the surface area; SAH costs only compare ratios. Summed as
  // (xy + yz) + zx in registers (w is 0).
  float halfArea() const {
    const __m128 e = _mm_max_ps(_mm_sub_ps(xyz(hi), xyz(lo)), _mm_setzero_ps());
    const __m128 products = _mm_mul_ps(e, _mm_shuffle_ps(e, e, _MM_SHUFFLE(3, 0, 2, 1)));
    const __m128 xyPlusYz = _mm_add_ss(products, _mm_shuffle_ps(products, products, 1));
    return _mm_cvtss_f32(_mm_add_ss(xyPlusYz, _mm_movehl_ps(products, products)));
  }
};

// A primitive: its box, with the primitive index in the w lane of `lo`
// (and 0 in that of `hi`).
struct PrimRef {
  __m128 lo, hi;
  __m128 centroid2() const { return _mm_add_ps(xyz(lo), hi); }  // twice the centroid
  std::uint32_t index() const {
    return static_cast<std::uint32_t>(
        _mm_cvtsi128_si32(_mm_castps_si128(_mm_shuffle_ps(lo, lo, 3))));
  }
};

// Bounds of a range: of the boxes, and of the (doubled) centroids.
struct RangeBounds {
  Box4 box, centroids;
  void add(const PrimRef& p) {
    box.extend(p.lo, p.hi);
    addCentroid(p);
  }
  void addCentroid(const PrimRef& p) {
    const __m128 c = p.centroid2();
    centroids.extend(c, c);
  }
  void add(const RangeBounds& o) {
    box.extend(o.box);
    centroids.extend(o.centroids);
  }
};

// Maps doubled centroids to bin indices per axis. An axis whose centroids
// (nearly) coincide gets scale 0: everything in bin 0, no split offered.
struct Binner {
  __m128 origin, scale, last;
  bool usable[3];
  int count;  // bins per axis

  Binner(const Box4& centroids, int bins) : count(bins) {
    alignas(16) float lo[4], hi[4], s[4] = {0, 0, 0, 0};
    _mm_store_ps(lo, centroids.lo);
    _mm_store_ps(hi, centroids.hi);
    for (int a = 0; a < 3; ++a) {
      const float v = static_cast<float>(bins) / (hi[a] - lo[a]);
      usable[a] = v > 0.0f && std::isfinite(v);
      s[a] = usable[a] ? v : 0.0f;
    }
    origin = centroids.lo;
    scale = _mm_load_ps(s);
    last = _mm_set1_ps(static_cast<float>(bins - 1));
  }
  // Bin per axis, in lanes x, y, z.
  __m128i bins(const PrimRef& p) const {
    const __m128 b = _mm_mul_ps(_mm_sub_ps(p.centroid2(), origin), scale);
    return _mm_cvttps_epi32(_mm_max_ps(_mm_min_ps(b, last), _mm_setzero_ps()));
  }
  bool usableAxis() const { return usable[0] || usable[1] || usable[2]; }
};

// Only the first `used` bins of each axis are set up and read: most nodes
// are small, and clearing all kMaxBins of them cost more than binning.
struct Bins {
  struct Bin {
    __m128 lo, hi;
    std::uint32_t count;
  };
  Bin bin[3][kMaxBins];
  int used;

  explicit Bins(int bins = kMaxBins) : used(bins) {
    const __m128 inf = _mm_set1_ps(std::numeric_limits<float>::infinity());
    const __m128 negInf = _mm_set1_ps(-std::numeric_limits<float>::infinity());
    for (auto& axis : bin)
      for (int i = 0; i < used; ++i) axis[i] = {inf, negInf, 0};
  }
  void add(const Bins& o) {
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < used; ++i) {
        bin[a][i].lo = _mm_min_ps(bin[a][i].lo, o.bin[a][i].lo);
        bin[a][i].hi = _mm_max_ps(bin[a][i].hi, o.bin[a][i].hi);
        bin[a][i].count += o.bin[a][i].count;
      }
  }
};

// Runs `scan(begin, end, out)` over [begin, end), in parallel for large
// ranges (each task on a copy of `out` as given, merged with T::add).
template <typename T, typename Scan>
void reduceRange(std::uint32_t begin, std::uint32_t end, const Scan& scan, T& out) {
  if (end - begin < kParallelScan) {
    scan(begin, end, out);
    return;
  }
  out = tbb::parallel_reduce(
      tbb::blocked_range<std::uint32_t>(begin, end, kParallelScan / 4), out,
      [&](const tbb::blocked_range<std::uint32_t>& r, T acc) {
        scan(r.begin(), r.end(), acc);
        return acc;
      },
      [](T a, const T& b) {
        a.add(b);
        return a;
      });
}

struct Split {
  int axis = -1;
  int bin = 0;        // primitives in bins <= bin go left
  float cost = 0.0f;  // sum of area times count over both sides
  Box4 left, right;   // the boxes of the two sides: the unions of their bins
};

class Builder {
 public:
  // floatBoxOf(i) is primitive i's box as a FloatBox.
  // With `mesh`, primitive i is its triangle i, and spare copies of a
  // triangle are left out (triangle_copies.h).
  template <typename FloatBoxOf>
  Builder(std::size_t n, const FloatBoxOf& floatBoxOf, const BvhBuildOptions& options, Bvh& out,
          const Mesh* mesh = nullptr)
      : options_(options),
        out_(out),
        mesh_(mesh),
        bins_(std::clamp(options.bins, 2, kMaxBins)),
        refs_(n) {
    // Room for the most nodes a tree can have; the pages of those never
    // used are never touched.
    out_.nodes.resize(2 * n);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16384),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i < r.end(); ++i) {
                          const FloatBox b = floatBoxOf(i);
                          const __m128i id = _mm_setr_epi32(0, 0, 0, static_cast<int>(i));
                          refs_[i].lo = _mm_or_ps(xyz(b.lo), _mm_castsi128_ps(id));
                          refs_[i].hi = xyz(b.hi);
                        }
                      });
  }

  void run(std::uint32_t n) {
    RangeBounds root;
    reduceRange(
        0, n,
        [&](std::uint32_t b, std::uint32_t e, RangeBounds& acc) {
          for (std::uint32_t i = b; i < e; ++i) acc.add(refs_[i]);
        },
        root);
    build(out_.nodes[0], 0, n, root, 1, nullptr, false);
    const std::uint32_t count = nodeCount_.load();
    out_.nodes.resize(count);
    out_.order.resize(n);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, n, kParallelScan),
                      [&](const tbb::blocked_range<std::uint32_t>& r) {
                        for (std::uint32_t i = r.begin(); i < r.end(); ++i)
                          out_.order[i] = refs_[i].index();
                      });
    out_.depth = depth_.load();
    out_.copiesLeftOut = copies_.load();
  }

 private:
  // Primitive tests a leaf of n primitives costs: a shift for the usual
  // power-of-two block, as this runs in the SAH sweep, ~90 times a node.
  float tests(std::uint32_t n) const {
    const auto block = static_cast<std::uint32_t>(options_.leafBlock);
    if (blockShift_ >= 0) return static_cast<float>((n + block - 1) >> blockShift_);
    return static_cast<float>((n + block - 1) / block);
  }

  // Bins for a node of n primitives: four, and one more per twenty
  // primitives (Embree's rule). A node of a few primitives gains little
  // from many boundaries, yet pays a sweep over all of them: more bins
  // build slower and trace no faster.
  int binsFor(std::uint32_t n) const {
    return std::min(bins_, static_cast<int>(4 + std::min<std::uint32_t>(n / 20, kMaxBins)));
  }

  // The cheapest bin boundary over the three axes, or axis -1 if none,
  // binning every stride-th primitive (the split's boxes and cost are then
  // the sample's).
  Split findSplit(std::uint32_t begin, std::uint32_t end, std::uint32_t stride,
                  const Binner& binner) const {
    Bins bins(binner.count);
    const std::uint32_t samples = (end - begin + stride - 1) / stride;
    reduceRange(
        0, samples,
        [&](std::uint32_t b, std::uint32_t e, Bins& acc) {
          // The bins of a batch are found before any is updated. Updated
          // one primitive at a time, each update's address came late (at the
          // end of the bin arithmetic), and the next primitive's loads from
          // the bins, issued before it, were often found to read the same
          // bin and redone: neighbouring primitives share bins. That way was
          // about three times slower per primitive.
          constexpr std::uint32_t kBatch = 32;
          alignas(16) std::int32_t k[kBatch][4];
          for (std::uint32_t first = b; first < e; first += kBatch) {
            const std::uint32_t count = std::min(kBatch, e - first);
            const PrimRef* batch = refs_.data() + begin + std::size_t{first} * stride;
            for (std::uint32_t j = 0; j < count; ++j)
              _mm_store_si128(reinterpret_cast<__m128i*>(k[j]), binner.bins(batch[j * stride]));
            for (std::uint32_t j = 0; j < count; ++j) {
              const PrimRef& p = batch[j * stride];
              for (int a = 0; a < 3; ++a) {
                Bins::Bin& bin = acc.bin[a][k[j][a]];
                bin.lo = _mm_min_ps(bin.lo, p.lo);
                bin.hi = _mm_max_ps(bin.hi, p.hi);
                ++bin.count;
              }
            }
          }
        },
        bins);
    Split best;
    for (int a = 0; a < 3; ++a) {
      if (!binner.usable[a]) continue;
      // Right-to-left sweep of areas times counts, then left to right.
      float rightCost[kMaxBins];
      FloatBox rightBox[kMaxBins];  // rightBox[i]: the union of bins i + 1 and up
      Box4 right;
      std::uint32_t rightCount = 0;
      for (int i = binner.count - 1; i > 0; --i) {
        right.extend(bins.bin[a][i].lo, bins.bin[a][i].hi);
        rightCount += bins.bin[a][i].count;
        rightCost[i - 1] = right.halfArea() * tests(rightCount);
        rightBox[i - 1] = {right.lo, right.hi};
      }
      Box4 left;
      std::uint32_t leftCount = 0;
      for (int i = 0; i < binner.count - 1; ++i) {
        left.extend(bins.bin[a][i].lo, bins.bin[a][i].hi);
        leftCount += bins.bin[a][i].count;
        if (leftCount == 0 || leftCount == samples) continue;
        const float cost = left.halfArea() * tests(leftCount) + rightCost[i];
        if (best.axis < 0 || cost < best.cost)
          best = {a, i, cost, left, Box4{rightBox[i].lo, rightBox[i].hi}};
      }
    }
    return best;
  }

  // Moves the primitives in bins <= split.bin to the front; returns the
  // boundary and the bounds of both sides. Unless the split was found from a
  // sample, the sides' boxes are their bins' (the same primitives, so the
  // same float minima and maxima), and only the centroids' bounds are
  // gathered, in a pass over each side afterwards.
  //
  // Each primitive is swapped to the boundary whatever its side, and the
  // boundary moves by the answer (a branch-free Lomuto partition). On a
  // real mesh the side is a coin toss for the branch predictor, so Hoare's
  // scan from both ends, a branch per primitive, builds the small meshes'
  // trees up to 1.5 times slower. The sides hold the same primitives
  // either way, so every later split and every leaf's set of primitives is
  // the same; only the order within a leaf differs. (Folding the
  // centroids into the swap loop with masks is slower.)
  std::uint32_t partition(std::uint32_t begin, std::uint32_t end, const Binner& binner,
                          const Split& split, bool sampled, RangeBounds& left, RangeBounds& right) {
    // The side test compares all three lanes' bins with the split's and
    // keeps the split axis's answer, in registers throughout.
    const __m128i splitBin = _mm_set1_epi32(split.bin);
    const int axis = split.axis;
    std::uint32_t boundary = begin;
    for (std::uint32_t k = begin; k < end; ++k) {
      const PrimRef p = refs_[k];
      const __m128i beyond = _mm_cmpgt_epi32(binner.bins(p), splitBin);
      const bool goesLeft = (_mm_movemask_ps(_mm_castsi128_ps(beyond)) >> axis & 1) == 0;
      refs_[k] = refs_[boundary];
      refs_[boundary] = p;
      boundary += goesLeft;
    }
    const auto sideBounds = [&](std::uint32_t from, std::uint32_t to, const Box4& binned) {
      RangeBounds side;
      if (sampled) {
        for (std::uint32_t k = from; k < to; ++k) side.add(refs_[k]);
        return side;
      }
      for (std::uint32_t k = from; k < to; ++k) side.addCentroid(refs_[k]);
      side.box = binned;
      return side;
    };
    left = sideBounds(begin, boundary, split.left);
    right = sideBounds(boundary, end, split.right);
    return boundary;
  }

  // Splits at the centroid median of the widest axis (coincident
  // centroids, or too deep for SAH).
  std::uint32_t medianSplit(std::uint32_t begin, std::uint32_t end, const Box4& centroids,
                            RangeBounds& left, RangeBounds& right) {
    alignas(16) float e[4];
    _mm_store_ps(e, _mm_sub_ps(centroids.hi, centroids.lo));
    const int axis = e[0] >= e[1] && e[0] >= e[2] ? 0 : (e[1] >= e[2] ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(refs_.data() + begin, refs_.data() + mid, refs_.data() + end,
                     [&](const PrimRef& p, const PrimRef& q) {
                       alignas(16) float cp[4], cq[4];
                       _mm_store_ps(cp, p.centroid2());
                       _mm_store_ps(cq, q.centroid2());
                       return cp[axis] < cq[axis];
                     });
    for (std::uint32_t i = begin; i < mid; ++i) left.add(refs_[i]);
    for (std::uint32_t i = mid; i < end; ++i) right.add(refs_[i]);
    return mid;
  }

  // A subtree of fewer than kParallelSubtrees primitives is built on one
  // thread, its nodes below its root numbered from 0 in a buffer of that
  // thread's, and moved into the tree in one block when it is done. Taking
  // every node pair from the tree's shared count instead, the two threads
  // fought over that count's cache line (and the depth's beside it) at
  // every node, a fifth of a large build's time. Blocks land in
  // the order subtrees finish, so node numbers can differ from run to run;
  // the tree, and the 8-wide tree collapsed from it, cannot.
  struct Subtree {
    BuildVector<BvhNode> nodes;  // grown to the largest subtree's need
    std::uint32_t used = 0;
    int depth = 0;
  };

  void raiseDepth(int depth) {
    int seen = depth_.load(std::memory_order_relaxed);
    while (seen < depth && !depth_.compare_exchange_weak(seen, depth)) {
    }
  }

  void makeLeaf(BvhNode& node, std::uint32_t begin, std::uint32_t end, int depth,
                Subtree* subtree) {
    node.first = begin;
    node.count = end - begin;
    if (subtree)
      subtree->depth = std::max(subtree->depth, depth);
    else
      raiseDepth(depth);
  }

  void buildSubtree(BvhNode& root, std::uint32_t begin, std::uint32_t end,
                    const RangeBounds& bounds, int depth, bool copiesDropped) {
    Subtree& subtree = subtrees_.local();
    // At most 2n - 2 nodes below the root.
    if (subtree.nodes.size() < 2 * std::size_t{end - begin})
      subtree.nodes.resize(2 * std::size_t{end - begin});
    subtree.used = 0;
    subtree.depth = 0;
    build(root, begin, end, bounds, depth, &subtree, copiesDropped);
    const std::uint32_t base = nodeCount_.fetch_add(subtree.used);
    for (std::uint32_t i = 0; i < subtree.used; ++i) {
      BvhNode node = subtree.nodes[i];
      if (!node.isLeaf()) node.first += base;
      out_.nodes[base + i] = node;
    }
    if (!root.isLeaf()) root.first += base;
    raiseDepth(subtree.depth);
  }

  // Moves the spare copies among the triangles of [begin, end) (copies of
  // two others there, triangle_copies.h) behind the others, which keep
  // their order, and returns how many others there are. The spares' slots
  // stay in the tree's order, but no leaf reaches them.
  std::uint32_t dropSpareCopies(std::uint32_t begin, std::uint32_t end) {
    std::vector<std::uint32_t> triangles(end - begin);
    for (std::uint32_t k = begin; k < end; ++k) triangles[k - begin] = refs_[k].index();
    const std::vector<char> spare = markSpareCopies(*mesh_, triangles);
    std::vector<PrimRef> spares;
    std::uint32_t kept = begin;
    for (std::uint32_t k = begin; k < end; ++k) {
      if (spare[k - begin])
        spares.push_back(refs_[k]);
      else
        refs_[kept++] = refs_[k];
    }
    std::copy(spares.begin(), spares.end(), refs_.data() + kept);
    copies_ += static_cast<std::uint32_t>(spares.size());
    return kept - begin;
  }

  // Builds the subtree of `node`, which is in the tree or, when `subtree`
  // is given, in its buffer. `copiesDropped`: an ancestor has left out the
  // spare copies among its primitives, so none are left among these.
  void build(BvhNode& node, std::uint32_t begin, std::uint32_t end, const RangeBounds& bounds,
             int depth, Subtree* subtree, bool copiesDropped) {
    std::uint32_t n = end - begin;
    if (!subtree && n < kParallelSubtrees)
      return buildSubtree(node, begin, end, bounds, depth, copiesDropped);
    alignas(16) float lo[4], hi[4];
    _mm_store_ps(lo, bounds.box.lo);
    _mm_store_ps(hi, bounds.box.hi);
    std::copy(lo, lo + 3, node.bounds);
    std::copy(hi, hi + 3, node.bounds + 3);
    bool small = n <= static_cast<std::uint32_t>(options_.maxLeafSize);
    if (n == 1) return makeLeaf(node, begin, end, depth, subtree);
    // A small node whose leaf costs no more than a node visit is a leaf
    // whatever split the bins would offer (a split costs that visit plus
    // its children), so it is not binned: with blocks of four, this spares
    // the SAH sweep of every node of two to four triangles.
    if (small && options_.primitiveCost * tests(n) <= options_.nodeCost)
      return makeLeaf(node, begin, end, depth, subtree);

    RangeBounds left, right;
    std::uint32_t mid;
    const Binner binner(bounds.centroids, binsFor(n));
    const std::uint32_t stride = n >= 2 * kBinSample ? n / kBinSample : 1;
    const Split split = depth < kMedianDepth ? findSplit(begin, end, stride, binner) : Split{};
    if (split.axis >= 0) {
      const double area = bounds.box.halfArea();
      const double leafCost = options_.primitiveCost * tests(n) * area;
      const double splitCost = options_.nodeCost * area + options_.primitiveCost * split.cost;
      if (small && leafCost <= splitCost) return makeLeaf(node, begin, end, depth, subtree);
      mid = partition(begin, end, binner, split, stride > 1, left, right);
    } else {
      // Copies have the same box, so only a node whose centroids all
      // coincide can hold a set of them, and only such a node looks for
      // them, the first on its path from the root: no split by bins
      // separates copies, and a median split above it at most leaves a
      // set's two lowest in different nodes, where each keeps them.
      if (!small && mesh_ && !copiesDropped && !binner.usableAxis()) {
        copiesDropped = true;
        end = begin + dropSpareCopies(begin, end);
        n = end - begin;
        small = n <= static_cast<std::uint32_t>(options_.maxLeafSize);
      }
      if (small) return makeLeaf(node, begin, end, depth, subtree);
      mid = medianSplit(begin, end, bounds.centroids, left, right);
    }
    const std::uint32_t child =
        subtree ? std::exchange(subtree->used, subtree->used + 2) : nodeCount_.fetch_add(2);
    BvhNode* children = subtree ? &subtree->nodes[child] : &out_.nodes[child];
    node.first = child;
    node.count = 0;
    const auto buildLeft = [&] {
      build(children[0], begin, mid, left, depth + 1, subtree, copiesDropped);
    };
    const auto buildRight = [&] {
      build(children[1], mid, end, right, depth + 1, subtree, copiesDropped);
    };
    if (n >= kParallelSubtrees) {
      tbb::parallel_invoke(buildLeft, buildRight);
    } else {
      buildLeft();
      buildRight();
    }
  }

  const BvhBuildOptions& options_;
  Bvh& out_;
  const Mesh* mesh_;
  int bins_;
  int blockShift_ = std::has_single_bit(static_cast<unsigned>(std::max(options_.leafBlock, 1)))
                        ? std::countr_zero(static_cast<unsigned>(std::max(options_.leafBlock, 1)))
                        : -1;
  BuildVector<PrimRef> refs_;
  std::atomic<std::uint32_t> nodeCount_{1};
  std::atomic<int> depth_{0};
  std::atomic<std::uint32_t> copies_{0};
  tbb::enumerable_thread_specific<Subtree> subtrees_;
};

}  // namespace

Bvh buildBvh(std::span<const Aabb> boxes, const BvhBuildOptions& options) {
  Bvh bvh;
  if (boxes.empty()) return bvh;
  const auto boxOf = [&](std::size_t i) { return roundedOutward(boxes[i]); };
  Builder(boxes.size(), boxOf, options, bvh).run(static_cast<std::uint32_t>(boxes.size()));
  return bvh;
}

namespace {

Bvh buildOneMesh(const Mesh& mesh, const BvhBuildOptions& options) {
  Bvh bvh;
  const auto& triangles = mesh.triangles();
  if (triangles.empty()) return bvh;
  // Each vertex is rounded outward once, not once per triangle using it:
  // rounding is monotone, so the triangle's float box, the lows' minimum
  // and the highs' maximum, is the same as its double box rounded outward.
  const auto& vertices = mesh.vertices();
  BuildVector<FloatBox> vertexBoxes(vertices.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, vertices.size(), 16384),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t v = r.begin(); v < r.end(); ++v)
                        vertexBoxes[v] = roundedOutward(Aabb{vertices[v], vertices[v]});
                    });
  const auto boxOf = [&](std::size_t i) {
    const TriangleIndices& t = triangles[i];
    const FloatBox &a = vertexBoxes[t[0]], &b = vertexBoxes[t[1]], &c = vertexBoxes[t[2]];
    return FloatBox{_mm_min_ps(_mm_min_ps(a.lo, b.lo), c.lo),
                    _mm_max_ps(_mm_max_ps(a.hi, b.hi), c.hi)};
  };
  Builder(triangles.size(), boxOf, options, bvh, &mesh)
      .run(static_cast<std::uint32_t>(triangles.size()));
  return bvh;
}

// One tree from `top`, a tree with one part per leaf, and the parts' own
// trees: each leaf of `top` becomes its part's root. Part k's node indices
// move past those before it, its leaves' ranges past the earlier parts'
// primitives, and its primitive indices up by idOffset[k].
Bvh join(const Bvh& top, std::span<const Bvh> parts, std::span<const std::uint32_t> idOffset) {
  Bvh out;
  std::size_t nodes = top.nodes.size(), primitives = 0;
  for (const Bvh& part : parts) nodes += part.nodes.size(), primitives += part.order.size();
  out.nodes.reserve(nodes);
  out.order.reserve(primitives);
  out.nodes = top.nodes;
  std::vector<std::uint32_t> root(parts.size());
  int partDepth = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const auto nodeOffset = static_cast<std::uint32_t>(out.nodes.size());
    const auto orderOffset = static_cast<std::uint32_t>(out.order.size());
    root[k] = nodeOffset;
    for (BvhNode node : parts[k].nodes) {
      node.first += node.isLeaf() ? orderOffset : nodeOffset;
      out.nodes.push_back(node);
    }
    for (std::uint32_t i : parts[k].order) out.order.push_back(i + idOffset[k]);
    partDepth = std::max(partDepth, parts[k].depth);
    out.copiesLeftOut += parts[k].copiesLeftOut;
  }
  // The parts' roots are copied into the leaves (their old slots stay
  // unreachable).
  for (std::size_t i = 0; i < top.nodes.size(); ++i)
    if (top.nodes[i].isLeaf()) out.nodes[i] = out.nodes[root[top.order[top.nodes[i].first]]];
  out.depth = top.depth - 1 + partDepth;
  return out;
}

}  // namespace

// Several meshes: each mesh's tree is built on its own, in parallel, and
// the trees joined under one over the meshes' boxes (whose leaves hold one
// mesh each: with maxLeafSize 1, only single primitives become leaves). One
// SAH build over all the triangles gives the same ray speed on the seed
// scenes but takes longer, its first levels binning the whole set on two
// cores.
Bvh buildBvh(const TriangleSet& triangles, const BvhBuildOptions& options) {
  const std::size_t meshes = triangles.meshCount();
  if (meshes == 0) return {};
  if (meshes == 1) return buildOneMesh(triangles.mesh(0), options);
  std::vector<Bvh> parts(meshes);
  std::vector<Aabb> boxes(meshes);
  std::vector<std::uint32_t> idOffset(meshes);
  tbb::parallel_for(std::size_t(0), meshes, [&](std::size_t k) {
    parts[k] = buildOneMesh(triangles.mesh(k), options);
    boxes[k] = triangles.mesh(k).bounds();
    idOffset[k] = triangles.firstId(k);
  });
  const Bvh top = buildBvh(
      boxes,
      {.bins = options.bins, .maxLeafSize = 1, .nodeCost = options.nodeCost, .primitiveCost = 1.0});
  return join(top, parts, idOffset);
}

}  // namespace meshtrace
