#pragma once
// The names of an enum's values, written once per enum as a table of entries
// that have a `value` and a `name` (EnumName, or a richer struct with both,
// such as the viewer's views with their labels). Every toString and parse
// of the library and the tools goes through these, so a name is spelled in
// one place and every "unknown name" message lists the same choices.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "meshtrace/util/quoted.h"

namespace meshtrace {

template <typename E>
struct EnumName {
  E value;
  const char* name;
};

// The name of `value`, or "?" for a value the table lacks.
template <typename Table, typename E>
constexpr const char* nameIn(const Table& table, E value) {
  for (const auto& entry : table)
    if (entry.value == value) return entry.name;
  return "?";
}

// The value named `name`, if the table has it.
template <typename Table>
constexpr auto valueNamed(const Table& table, std::string_view name)
    -> std::optional<decltype(std::begin(table)->value)> {
  for (const auto& entry : table)
    if (name == entry.name) return entry.value;
  return std::nullopt;
}

// The table's names as "a, b or c".
template <typename Table>
std::string namesIn(const Table& table) {
  std::string out;
  const auto count = static_cast<std::size_t>(std::end(table) - std::begin(table));
  std::size_t k = 0;
  for (const auto& entry : table) {
    if (k > 0) out += k + 1 == count ? " or " : ", ";
    out += entry.name;
    ++k;
  }
  return out;
}

// The value named `name`; throws std::invalid_argument "unknown <what>
// 'name' (use a, b or c)" if the table lacks it (the name shown as
// quoted() shows input).
template <typename Table>
auto parseNamed(const Table& table, std::string_view name, const char* what) {
  if (const auto value = valueNamed(table, name)) return *value;
  throw std::invalid_argument("unknown " + std::string(what) + " " + quoted(name) + " (use " +
                              namesIn(table) + ")");
}

}  // namespace meshtrace
