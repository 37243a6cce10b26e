#include "accel/triangle_copies.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <array>
#include <bit>
#include <tuple>

namespace meshtrace {

namespace {

CornerBits cornerBits(const Mesh& mesh, std::uint32_t t) {
  CornerBits bits;
  const TriangleIndices& idx = mesh.triangles()[t];
  for (int k = 0; k < 3; ++k)
    for (int a = 0; a < 3; ++a)
      bits[3 * k + a] = std::bit_cast<std::uint64_t>(mesh.vertices()[idx[k]][a]);
  return bits;
}

std::uint64_t hashOf(const CornerBits& bits) {
  std::uint64_t h = 0x9e3779b97f4a7c15u;
  for (std::uint64_t w : bits) {
    h = (h ^ w) * 0xbf58476d1ce4e5b9u;
    h ^= h >> 31;
  }
  return h;
}

struct Key {
  std::uint64_t hash;
  std::uint32_t triangle, position;
  bool operator<(const Key& o) const {
    return std::tie(hash, triangle) < std::tie(o.hash, o.triangle);
  }
};

// A run of keys whose hashes are equal, in triangle order: each that
// equals one of the run's earlier distinct corner sets, seen twice already,
// is a spare copy. Runs are almost always one set of copies; a run with
// many distinct sets (colliding hashes) is sorted by the corners themselves
// instead, so no run costs more than n log n.
void markRun(const Mesh& mesh, std::span<Key> run, std::vector<char>& spare) {
  constexpr std::size_t kMaxDistinct = 8;
  struct Set {
    std::uint32_t first;
    int seen;
  };
  std::vector<Set> sets;
  for (const Key& k : run) {
    const auto set = std::find_if(sets.begin(), sets.end(), [&](const Set& s) {
      return sameCorners(mesh, s.first, mesh, k.triangle);
    });
    if (set != sets.end()) {
      spare[k.position] = set->seen++ >= 2;
      continue;
    }
    if (sets.size() == kMaxDistinct) break;
    sets.push_back({k.triangle, 1});
  }
  if (sets.size() < kMaxDistinct) return;
  std::vector<std::pair<CornerBits, Key>> exact;
  exact.reserve(run.size());
  for (const Key& k : run) exact.push_back({cornerBits(mesh, k.triangle), k});
  std::sort(exact.begin(), exact.end(), [](const auto& x, const auto& y) {
    return std::tie(x.first, x.second.triangle) < std::tie(y.first, y.second.triangle);
  });
  for (std::size_t i = 0; i < exact.size(); ++i)
    spare[exact[i].second.position] = i >= 2 && exact[i - 2].first == exact[i].first;
}

}  // namespace

std::vector<char> markSpareCopies(const Mesh& mesh, std::span<const std::uint32_t> triangles) {
  return markSpareCopies(mesh, triangles, hashOf);
}

std::vector<char> markSpareCopies(const Mesh& mesh, std::span<const std::uint32_t> triangles,
                                  CornerHash hash) {
  const std::size_t n = triangles.size();
  std::vector<Key> keys(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 16384), [&](const tbb::blocked_range<
                                                                      std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i)
      keys[i] = {hash(cornerBits(mesh, triangles[i])), triangles[i], static_cast<std::uint32_t>(i)};
  });
  tbb::parallel_sort(keys.begin(), keys.end());
  std::vector<char> spare(n, 0);
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin + 1;
    while (end < n && keys[end].hash == keys[begin].hash) ++end;
    if (end - begin > 2) markRun(mesh, std::span(keys).subspan(begin, end - begin), spare);
    begin = end;
  }
  return spare;
}

}  // namespace meshtrace
