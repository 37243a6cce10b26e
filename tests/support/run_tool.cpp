#include "support/run_tool.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "support/files.h"

extern char** environ;

namespace meshtrace::test {

ToolResult runTool(const std::filesystem::path& tool, const std::vector<std::string>& args,
                   const std::filesystem::path& workDir, double timeoutSeconds) {
  // Captured through files rather than pipes: no risk of a full pipe
  // blocking the child while we wait for it. The names sit outside the
  // folders tests inspect for stray output.
  const auto outFile = workDir / ".tool-stdout";
  const auto errFile = workDir / ".tool-stderr";
  std::vector<std::string> argvStrings{tool.string()};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argvStrings) argv.push_back(s.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, outFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, 2, errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  pid_t pid = 0;
  const auto start = std::chrono::steady_clock::now();
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + tool.string() + ": " + std::strerror(rc));

  ToolResult result;
  int status = 0;
  const auto deadline = start + std::chrono::duration<double>(timeoutSeconds);
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      result.timedOut = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!result.timedOut && WIFEXITED(status)) {
    result.exited = true;
    result.exitCode = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  }
  result.out = readFileBytes(outFile);
  result.err = readFileBytes(errFile);
  std::filesystem::remove(outFile);
  std::filesystem::remove(errFile);
  return result;
}

std::string describe(const ToolResult& r) {
  std::string s = r.timedOut ? "timed out"
                  : r.exited ? "exit code " + std::to_string(r.exitCode)
                             : "killed by signal " + std::to_string(r.signal);
  return s + "\n--- stdout:\n" + r.out + "--- stderr:\n" + r.err;
}

}  // namespace meshtrace::test
