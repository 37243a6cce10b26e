#pragma once
namespace meshtrace::bench {
// Prints primary-ray throughput for scenes of 100 small meshes of n
// triangles, with all of them in the triangle BVH and with none (each
// tested whole after its top-level box): where a BVH starts to pay.
void printCrossover();
}  // namespace meshtrace::bench
