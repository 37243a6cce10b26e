#pragma once
// Runs a built command-line tool as a separate process, as a user would, and
// reports how it ended and what it printed.
#include <filesystem>
#include <string>
#include <vector>

namespace meshtrace::test {

struct ToolResult {
  bool exited = false;  // ended by exit(), not by a signal or the time limit
  int exitCode = -1;    // valid when `exited`
  int signal = 0;       // the signal that ended it, if any
  bool timedOut = false;
  std::string out, err;  // stdout and stderr
  double seconds = 0.0;
};

// Runs `tool args...`, with stdout and stderr captured through files in
// `workDir` (which must exist). A tool still running after `timeoutSeconds`
// is killed and reported as timed out.
ToolResult runTool(const std::filesystem::path& tool, const std::vector<std::string>& args,
                   const std::filesystem::path& workDir, double timeoutSeconds = 60.0);

// Prints a ToolResult in failure messages.
std::string describe(const ToolResult& r);

}  // namespace meshtrace::test
