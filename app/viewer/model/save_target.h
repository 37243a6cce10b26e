#pragma once
// Where the viewer proposes to save, and saving that never replaces a file
// unless told to: a path proposed is absolute, new, and in a folder the
// user may write to that is not the course's data.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshtrace::viewer {

// What to do when the target exists: refuse (the UI then asks), or replace it.
enum class Existing { Refuse, Replace };

// Thrown when a save would replace a file it was not told to replace.
struct FileExists : std::runtime_error {
  explicit FileExists(const std::filesystem::path& path);
  std::filesystem::path path;
};

// Throws FileExists if `target` exists and `existing` is Refuse.
void refuseExisting(const std::filesystem::path& target, Existing existing);

// The course's data (a folder below shared/seed), shared by everyone who
// takes the course: never a place to save.
bool isCourseData(const std::filesystem::path& path);

// A folder that exists and whose permissions let files be made in it. For
// the super-user, whom the system lets write anywhere, a folder with no
// write permission bit still counts as read-only: its owner meant it so.
bool isWritableFolder(const std::filesystem::path& dir);

// The first of `candidates` that is a writable folder outside the course's
// data, made absolute; `fallback` if none is.
std::filesystem::path chooseSaveFolder(const std::vector<std::filesystem::path>& candidates,
                                       const std::filesystem::path& fallback);

// `folder`/`stem``extension`, or with -2, -3 ... before the extension: the
// first that does not exist.
std::filesystem::path freeName(const std::filesystem::path& folder, const std::string& stem,
                               const std::string& extension);

// Where a save is proposed when the user's own folder is not usable: the
// working folder, then the home folder ($HOME), then the temporary folder.
std::vector<std::filesystem::path> userFolders();

}  // namespace meshtrace::viewer
