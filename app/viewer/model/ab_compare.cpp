#include "viewer/model/ab_compare.h"

#include <algorithm>
#include <array>
#include <cstdlib>

#include "meshtrace/util/enum_names.h"

namespace meshtrace::viewer {

namespace {
struct ModeInfo {
  AbMode value;
  const char* name;
  const char* label;
};
constexpr std::array<ModeInfo, kAbModeCount> kModes{
    {{AbMode::A, "a", "A (now)"},
     {AbMode::B, "b", "B (kept)"},
     {AbMode::Wipe, "wipe", "wipe"},
     {AbMode::Difference, "difference", "|A - B|"}}};
}  // namespace

const char* label(AbMode mode) { return kModes[static_cast<int>(mode)].label; }
const char* name(AbMode mode) { return nameIn(kModes, mode); }
std::optional<AbMode> parseAbMode(std::string_view n) { return valueNamed(kModes, n); }

std::vector<std::uint8_t> differenceRgba(const Image8& a, const Image8& b, int gain) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(a.width) * a.height * 4, 255);
  for (std::size_t i = 0; i < out.size() / 4; ++i)
    for (int k = 0; k < 3; ++k) {
      const int d = std::abs(int(a.rgb[i * 3 + k]) - int(b.rgb[i * 3 + k]));
      out[i * 4 + k] = static_cast<std::uint8_t>(std::min(255, d * gain));
    }
  return out;
}

std::vector<std::uint8_t> toRgba(const Image8& image) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(image.width) * image.height * 4, 255);
  for (std::size_t i = 0; i < out.size() / 4; ++i)
    for (int k = 0; k < 3; ++k) out[i * 4 + k] = image.rgb[i * 3 + k];
  return out;
}

AbComparison compareWithB(std::uint64_t job, const Image8& a, const Image8& b) {
  AbComparison c;
  c.job = job;
  c.difference = compareImages(a, b);
  c.differenceRgba = differenceRgba(a, b, kAbDifferenceGain);
  return c;
}

}  // namespace meshtrace::viewer
