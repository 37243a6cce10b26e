#include "meshtrace/io/reference_lookup.h"

namespace meshtrace {

std::optional<std::filesystem::path> findReference(const std::filesystem::path& scene) {
  const std::string stem = scene.stem().string();
  // Relative to the scene path as given, so a relative scene gives a relative reference.
  std::filesystem::path dir = scene.parent_path();
  std::error_code ec;
  for (int up = 0; up < 3; ++up, dir /= "..") {
    for (const char* ext : {".png", ".jpg", ".ppm", ".bmp"}) {
      const auto candidate = (dir / "expected_results" / (stem + ext)).lexically_normal();
      if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
    }
  }
  return std::nullopt;
}

}  // namespace meshtrace
