#pragma once
// Where a scene's reference image is: an expected_results/ folder beside one
// of the scene's enclosing folders holding <stem>.png, .jpg, .ppm or .bmp
// (the seed's layout, scenes/<name>/<name>.sce with expected_results/<name>.jpg,
// and ours, with expected_results/<name>.png at the checkout's root), the
// nearest folder first. The viewer compares against it, and
// `raytrace --report` scores a scene against it.
#include <filesystem>
#include <optional>

namespace meshtrace {

std::optional<std::filesystem::path> findReference(const std::filesystem::path& scene);

}  // namespace meshtrace
