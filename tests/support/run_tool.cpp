#include "support/run_tool.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string_view>

#include "support/files.h"

extern char** environ;

namespace meshtrace::test {

namespace {

// Between fork and exec only async-signal-safe calls: everything the child
// needs is prepared before the fork.
[[noreturn]] void execChild(const char* const* argv, const char* outFile, const char* errFile,
                            const ToolRun& run) {
  for (int s = 1; s < NSIG; ++s) ::signal(s, SIG_DFL);
  sigset_t none;
  ::sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  const rlimit as{run.addressSpace, run.addressSpace}, fsize{run.fileSize, run.fileSize};
  if (run.addressSpace != RLIM_INFINITY && ::setrlimit(RLIMIT_AS, &as) != 0) ::_exit(126);
  if (run.fileSize != RLIM_INFINITY && ::setrlimit(RLIMIT_FSIZE, &fsize) != 0) ::_exit(126);
  // Captured through files rather than pipes: no risk of a full pipe
  // blocking the child while we wait for it.
  const int out = ::open(outFile, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int err = ::open(errFile, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0) ::_exit(126);
  ::execve(argv[0], const_cast<char* const*>(argv), environ);
  ::_exit(127);
}

// Whether an inotify event buffer names a newly created "*.tmp" file.
bool createdTemporary(const char* buffer, ssize_t length) {
  for (const char* p = buffer; p < buffer + length;) {
    const auto* event = reinterpret_cast<const inotify_event*>(p);
    const std::string_view name(event->len ? event->name : "");
    if (name.size() > 4 && name.substr(name.size() - 4) == ".tmp") return true;
    p += sizeof(inotify_event) + event->len;
  }
  return false;
}

}  // namespace

ToolResult runTool(const std::filesystem::path& tool, const std::vector<std::string>& args,
                   const std::filesystem::path& workDir, const ToolRun& run) {
  // The names sit outside the folders tests inspect for stray output.
  const auto outFile = workDir / ".tool-stdout";
  const auto errFile = workDir / ".tool-stderr";
  std::vector<std::string> argvStrings{tool.string()};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<const char*> argv;
  for (const std::string& s : argvStrings) argv.push_back(s.c_str());
  argv.push_back(nullptr);

  int watch = -1;
  if (run.signalOnTemporary != 0) {
    watch = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (watch < 0 || ::inotify_add_watch(watch, run.watch.c_str(), IN_CREATE) < 0)
      throw std::runtime_error("cannot watch " + run.watch.string() + ": " + std::strerror(errno));
  }
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0)
    throw std::runtime_error("cannot start " + tool.string() + ": " + std::strerror(errno));
  if (pid == 0) execChild(argv.data(), outFile.c_str(), errFile.c_str(), run);

  ToolResult result;
  int status = 0;
  rusage usage{};
  const auto deadline = start + std::chrono::duration<double>(run.timeoutSeconds);
  while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::wait4(pid, &status, 0, &usage);
      result.timedOut = true;
      break;
    }
    if (watch >= 0 && !result.signalSent) {
      // Wait for the temporary a millisecond at a time, so that the signal
      // lands while the file is being written, not after.
      pollfd p{watch, POLLIN, 0};
      alignas(inotify_event) char buffer[4096];
      if (::poll(&p, 1, 1) > 0) {
        const ssize_t n = ::read(watch, buffer, sizeof buffer);
        if (n > 0 && createdTemporary(buffer, n)) {
          ::kill(pid, run.signalOnTemporary);
          result.signalSent = true;
        }
      }
      continue;
    }
    ::usleep(2000);
  }
  if (watch >= 0) ::close(watch);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.maxResidentBytes = static_cast<std::uint64_t>(usage.ru_maxrss) * 1024;
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
