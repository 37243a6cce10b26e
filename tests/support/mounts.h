#pragma once
// Running a tool where a folder is read-only or its disk is full, for any
// user, root included: in new user and mount namespaces (unshare -U -r -m),
// where mounts made for the run are seen by it alone. File permissions do
// not stop root; a read-only mount and a full file system do.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "support/run_tool.h"

namespace meshtrace::test {

// Shell commands, run in the namespaces before the tool (`setup`: mounts,
// files to put on them) and after it (`after`: copying what a test checks
// out of a mount that ends with the run). "$DIR" in them is `dir`.
struct MountedRun {
  std::filesystem::path dir;
  std::string setup;
  std::string after;
};

// A read-only bind mount of `dir` over itself.
MountedRun readOnlyFolder(const std::filesystem::path& dir);
// A tmpfs of `bytes` bytes on `dir`, holding a copy of what `dir` held
// before; after the run, its contents are copied to `copyBack`.
MountedRun smallTmpfs(const std::filesystem::path& dir, std::size_t bytes,
                      const std::filesystem::path& copyBack);

// Runs `tool args...` in `workDir` inside the namespaces set up by `mounts`.
// Returns nothing, with the reason in `refused`, when the kernel refuses the
// namespaces or the mounts.
std::optional<ToolResult> runToolWithMounts(const std::filesystem::path& tool,
                                            const std::vector<std::string>& args,
                                            const std::filesystem::path& workDir,
                                            const MountedRun& mounts, std::string& refused);

}  // namespace meshtrace::test

// Skips the current test, saying that the kernel refused the namespaces.
#define MESHTRACE_SKIP_IF_MOUNTS_REFUSED(result, refused)                                 \
  do {                                                                                    \
    if (!(result))                                                                        \
      GTEST_SKIP() << "the kernel refused the user and mount namespaces this test needs " \
                      "for a read-only or full file system: "                             \
                   << (refused);                                                          \
  } while (0)
