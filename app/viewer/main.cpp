// viewer: the interactive scene viewer and pixel debugger.
#include <cstdlib>

#include "formats/openmesh_reader.h"
#include "viewer/model/background_priority.h"
#include "viewer/model/options.h"
#include "viewer/platform/run.h"

int main(int argc, char** argv) {
  // Mesa's software rasteriser (llvmpipe, all there is without a GPU) then
  // draws on the UI thread instead of handing each frame to its own threads,
  // which compete with the render workers for the cores. Ignored by GPUs.
  setenv("LP_NUM_THREADS", "0", /*overwrite=*/0);
  meshtrace::viewer::runTbbWorkersInBackground();
  // Scenes' mesh lines may name PLY, OBJ and STL files, read through OpenMesh.
  meshtrace::formats::registerOpenMeshFormats();
  int exitCode = 0;
  const auto options = meshtrace::viewer::parseOptions(argc, argv, exitCode);
  if (!options) return exitCode;
  return options->headless ? meshtrace::viewer::runHeadless(*options, argv[0])
                           : meshtrace::viewer::runWindow(*options, argv[0]);
}
