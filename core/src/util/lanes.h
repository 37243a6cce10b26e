#pragma once
// One value per lane of a packet, made by index: for types without a default
// constructor (a packet's queries, slab rays, box rays), so that the packet
// size is written once (kPacketSize) rather than spelled out as
// {make(0), make(1), make(2), make(3)}.
#include <array>
#include <cstddef>
#include <utility>

namespace meshtrace {

// std::array{make(0), make(1), ..., make(N - 1)}.
template <std::size_t N, typename Make>
[[gnu::always_inline]] inline auto makeLanes(const Make& make) {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<decltype(make(std::size_t{0})), N>{make(I)...};
  }
  (std::make_index_sequence<N>{});
}

}  // namespace meshtrace
