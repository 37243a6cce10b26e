#pragma once
// Files written whole or not at all: every file the tools write goes
// through an OutputFile. The bytes go to a temporary file created
// exclusively (never through a symlink someone planted) under an
// unpredictable name in the target's folder; only a complete file, every
// write and the close checked and its data synced, is renamed over the
// target. Until then the target is left as it was. The temporary is removed
// when a write fails, when the OutputFile is dropped unfinished, and when
// SIGINT, SIGTERM or SIGHUP ends the process (if the program left those at
// their default); SIGXFSZ is ignored, so that a file size limit (ulimit -f)
// fails the write with an error instead of killing the process.
//
// A target that is a symlink is replaced by the new file; the file the link
// pointed to is not written.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace meshtrace {

namespace temporaries {
struct Slot;
}

class OutputFile {
 public:
  // Creates the temporary beside `target`. Throws std::runtime_error naming
  // `target` if its folder cannot take a new file there.
  explicit OutputFile(std::filesystem::path target);
  OutputFile(OutputFile&& other) noexcept;
  OutputFile& operator=(OutputFile&&) = delete;
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  // Removes the temporary unless the file was committed.
  ~OutputFile();

  const std::filesystem::path& target() const { return target_; }

  // Appends bytes. Throws std::runtime_error naming the target (and removes
  // the temporary) if they cannot be written: a full disk, a file size limit.
  void write(const void* data, std::size_t size);
  void write(std::string_view text) { write(text.data(), text.size()); }

  // finish(), then replaceTarget().
  void commit();
  // Writes out what is buffered, syncs and closes the temporary: after it,
  // every byte is on disk, and no file descriptor stays open. Does nothing
  // the second time.
  void finish();
  // Renames the finished temporary over the target.
  void replaceTarget();

 private:
  void writeAll(const char* bytes, std::size_t size);
  void flushBuffer();
  [[noreturn]] void fail(int error);
  void discard() noexcept;

  std::filesystem::path target_;
  std::string name_;       // the target's file name in its folder
  std::string temporary_;  // the temporary's name in the same folder
  int folder_ = -1;        // the folder, opened once: both names are relative to it
  int fd_ = -1;
  temporaries::Slot* slot_ = nullptr;  // where the signal handlers find the temporary
  bool committed_ = false;
  std::vector<char> buffer_;
};

// Commits files that belong together (a report and its plots): none
// replaces its target unless every one of them was written completely.
void commitTogether(std::vector<OutputFile>& files);

// Writes `bytes` to `target` through an OutputFile.
void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes);

// Throws std::runtime_error naming `target` if an OutputFile could not be
// made there for a reason known before anything is written: its folder is
// missing, not a folder or not writable (permissions or a read-only file
// system), a folder is in the way, or the name is longer than the folder's
// file system allows. Lets a long job refuse its output before it starts.
void checkOutputDestination(const std::filesystem::path& target);

}  // namespace meshtrace
