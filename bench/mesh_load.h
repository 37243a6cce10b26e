#pragma once
// Loading one mesh as OFF (our reader) and as binary PLY (OpenMesh's,
// through the formats library), timed in the same run.
#include <filesystem>

namespace meshtrace::bench {

// Writes `off`'s mesh as binary little-endian PLY beside it (if missing),
// loads both in turn several times and prints the median of each and
// their ratio.
void printMeshLoadTimes(const std::filesystem::path& off);

}  // namespace meshtrace::bench
