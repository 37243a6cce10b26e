#pragma once
// Runs a built command-line tool as a separate process, as a user would, and
// reports how it ended and what it printed.
#include <sys/resource.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "support/sanitizers.h"

namespace meshtrace::test {

struct ToolResult {
  bool exited = false;  // ended by exit(), not by a signal or the time limit
  int exitCode = -1;    // valid when `exited`
  int signal = 0;       // the signal that ended it, if any
  bool timedOut = false;
  bool signalSent = false;  // ToolRun::signalOnTemporary was sent
  std::string out, err;     // stdout and stderr
  double seconds = 0.0;
  std::uint64_t maxResidentBytes = 0;  // the tool's peak resident memory
};

// How a tool runs, besides its arguments. The child starts with every
// signal at its default action and none blocked, whatever the test process
// does with them.
struct ToolRun {
  double timeoutSeconds = 60.0;         // then the tool is killed and reported as timed out
  rlim_t addressSpace = RLIM_INFINITY;  // RLIMIT_AS of the child, bytes
  rlim_t fileSize = RLIM_INFINITY;      // RLIMIT_FSIZE of the child, bytes
  // If not 0: sent to the tool the moment a file whose name ends in ".tmp"
  // is created in `watch` (an output's temporary, while it is written).
  int signalOnTemporary = 0;
  std::filesystem::path watch;
};

// Runs `tool args...`, with stdout and stderr captured through files in
// `workDir` (which must exist).
ToolResult runTool(const std::filesystem::path& tool, const std::vector<std::string>& args,
                   const std::filesystem::path& workDir, const ToolRun& run);
inline ToolResult runTool(const std::filesystem::path& tool, const std::vector<std::string>& args,
                          const std::filesystem::path& workDir, double timeoutSeconds = 60.0) {
  return runTool(tool, args, workDir, ToolRun{.timeoutSeconds = timeoutSeconds});
}

// Prints a ToolResult in failure messages.
std::string describe(const ToolResult& r);

}  // namespace meshtrace::test

// Skips a test that limits address space when the build uses
// AddressSanitizer (scripts/sanitize.sh); the ordinary build runs it.
#define MESHTRACE_SKIP_ADDRESS_LIMITS_UNDER_ASAN()                                           \
  do {                                                                                       \
    if (::meshtrace::test::kBuiltWithAsan)                                                   \
      GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space for its shadow " \
                      "memory: address-space limits are tested in the build without it";     \
  } while (0)
