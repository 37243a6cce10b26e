#pragma once
// raytrace --report-merge OUTDIR SHAREDIR...: the report of a run whose
// scenes were measured in shares (--report --shard I/N), made from the
// shares' data files (report.csv, scenes.csv, share.txt) as one run would
// have written it; the stability table is share 0's.
#include <filesystem>
#include <vector>

namespace meshtrace {

// Writes the merged report into `outDir` (writeReport). Throws
// std::runtime_error, leaving `outDir` as it was, when the shares do not
// make exactly one run: a folder without a share's files (InputError naming
// the file and line of anything malformed), shares of different runs, two
// folders holding the same share or scene (overlap), or a share missing
// (incomplete, naming the share and its scenes).
void mergeReports(const std::filesystem::path& outDir,
                  const std::vector<std::filesystem::path>& shareDirs);

}  // namespace meshtrace
