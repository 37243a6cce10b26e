#include "support/mounts.h"

#include <string_view>

namespace meshtrace::test {

namespace {

// Exit code of the script when a mount fails (the tools never use it).
constexpr int kMountRefused = 77;

std::filesystem::path findUnshare() {
  for (const char* p : {"/usr/bin/unshare", "/bin/unshare"})
    if (std::filesystem::exists(p)) return p;
  return {};
}

// `text` in single quotes for sh.
std::string shellQuoted(std::string_view text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

MountedRun readOnlyFolder(const std::filesystem::path& dir) {
  return {dir, R"(mount --bind "$DIR" "$DIR" && mount -o remount,bind,ro "$DIR")", ""};
}

MountedRun smallTmpfs(const std::filesystem::path& dir, std::size_t bytes,
                      const std::filesystem::path& copyBack) {
  return {dir,
          R"(keep=$(mktemp -d) && cp -a "$DIR/." "$keep/" && )"
          "mount -t tmpfs -o size=" +
              std::to_string(bytes) +
              R"( meshtrace-test "$DIR" && cp -a "$keep/." "$DIR/" && rm -rf "$keep")",
          R"(cp -a "$DIR/." )" + shellQuoted(copyBack.string()) + "/"};
}

std::optional<ToolResult> runToolWithMounts(const std::filesystem::path& tool,
                                            const std::vector<std::string>& args,
                                            const std::filesystem::path& workDir,
                                            const MountedRun& mounts, std::string& refused) {
  const std::filesystem::path unshare = findUnshare();
  if (unshare.empty()) {
    refused = "no unshare command (util-linux)";
    return std::nullopt;
  }
  // "$0" is the tool and "$@" its arguments.
  const std::string script = "DIR=" + shellQuoted(mounts.dir.string()) + "; if ! { " +
                             mounts.setup + "; }; then exit " + std::to_string(kMountRefused) +
                             "; fi; \"$0\" \"$@\"; rc=$?; " +
                             (mounts.after.empty() ? ":" : mounts.after) + "; exit $rc";
  std::vector<std::string> unshareArgs{
      "--user", "--map-root-user", "--mount", "--", "/bin/sh", "-c", script, tool.string()};
  unshareArgs.insert(unshareArgs.end(), args.begin(), args.end());
  ToolResult r = runTool(unshare, unshareArgs, workDir);
  if (r.exited && (r.exitCode == kMountRefused || r.err.rfind("unshare:", 0) == 0)) {
    refused = r.err;
    return std::nullopt;
  }
  return r;
}

}  // namespace meshtrace::test
