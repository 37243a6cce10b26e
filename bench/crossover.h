#pragma once
namespace meshtrace::bench {
// Prints primary-ray throughput for scenes of 100 small meshes of n
// triangles, with and without per-mesh BVHs: where a BVH starts to pay.
void printCrossover();
}  // namespace meshtrace::bench
