#pragma once
// Loading one mesh in each format we read, by our readers and by
// OpenMesh's (through the formats library), timed in the same run.
#include <filesystem>

namespace meshtrace::bench {

// Writes `off`'s mesh beside it as binary PLY (float coordinates), ASCII
// PLY, binary STL and ASCII STL (those missing), loads each in turn
// several times, by our reader and by OpenMesh's, and prints the median of
// each, its rate and its ratio to OFF.
void printMeshLoadTimes(const std::filesystem::path& off);

}  // namespace meshtrace::bench
