#include "meshtrace/io/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "io/temporaries.h"

namespace meshtrace {

namespace {

// Writes reach the file in pieces of this size: encoders hand over a few
// bytes at a time.
constexpr std::size_t kBufferBytes = std::size_t{1} << 16;
// Tries at fresh random names before giving up on a folder where every
// name is taken (60 random bits each: only a folder someone fills on
// purpose gets there).
constexpr int kNameAttempts = 100;

std::string reason(int error) {
  if (error == EFBIG) return "the file size limit, ulimit -f, is reached";
  if (error == EROFS) return "read-only file system";
  return std::strerror(error);
}

[[noreturn]] void refuse(const std::filesystem::path& target, const std::string& why) {
  throw std::runtime_error(target.string() + ": cannot write the file (" + why + ")");
}

void closeQuietly(int& fd) noexcept {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

// The target's folder, opened (without read or write rights: only as the
// place both names are relative to), after the checks that need no file.
struct TargetFolder {
  int fd = -1;
  std::string name;
  std::size_t nameMax = 255;
};

TargetFolder openTargetFolder(const std::filesystem::path& target) {
  TargetFolder out;
  out.name = target.filename().string();
  if (out.name.empty() || out.name == "." || out.name == "..")
    throw std::runtime_error(target.string() + ": names a folder, not a file");
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  out.fd = ::open(folder.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
  if (out.fd < 0) {
    const int error = errno;
    if (error == ENOENT) refuse(target, "no folder " + folder.string());
    if (error == ENOTDIR) refuse(target, folder.string() + " is not a folder");
    refuse(target, folder.string() + ": " + reason(error));
  }
  try {
    struct stat st {};
    if (::fstatat(out.fd, out.name.c_str(), &st, 0) == 0 && S_ISDIR(st.st_mode))
      throw std::runtime_error(target.string() + ": is a folder, not a file");
    const long nameMax = ::fpathconf(out.fd, _PC_NAME_MAX);
    if (nameMax > 0) out.nameMax = static_cast<std::size_t>(nameMax);
    if (out.name.size() > out.nameMax) {
      refuse(target, "its name is " + std::to_string(out.name.size()) + " bytes, more than the " +
                         std::to_string(out.nameMax) + " its file system allows");
    }
    if (::faccessat(out.fd, ".", W_OK, AT_EACCESS) != 0) {
      const int error = errno;
      if (error == EACCES) refuse(target, "folder " + folder.string() + " is not writable");
      refuse(target, folder.string() + ": " + reason(error));
    }
  } catch (...) {
    closeQuietly(out.fd);
    throw;
  }
  return out;
}

}  // namespace

OutputFile::OutputFile(std::filesystem::path target) : target_(std::move(target)) {
  TargetFolder folder = openTargetFolder(target_);
  folder_ = folder.fd;
  name_ = std::move(folder.name);
  for (int attempt = 0; attempt < kNameAttempts && fd_ < 0; ++attempt) {
    temporary_ = temporaries::name(name_, folder.nameMax);
    // Recorded before it exists: a signal right after its creation must
    // find it.
    slot_ = temporaries::add(folder_, temporary_);
    fd_ = temporaries::createExclusive(folder_, temporary_);
    if (fd_ >= 0) break;
    const int error = errno;
    temporaries::remove(slot_);
    slot_ = nullptr;
    if (error != EEXIST) {
      closeQuietly(folder_);
      refuse(target_, reason(error));
    }
  }
  if (fd_ < 0) {
    closeQuietly(folder_);
    refuse(target_, "no free name for a temporary file in its folder");
  }
  buffer_.reserve(kBufferBytes);
}

OutputFile::OutputFile(OutputFile&& other) noexcept
    : target_(std::move(other.target_)),
      name_(std::move(other.name_)),
      temporary_(std::move(other.temporary_)),
      folder_(std::exchange(other.folder_, -1)),
      fd_(std::exchange(other.fd_, -1)),
      slot_(std::exchange(other.slot_, nullptr)),
      committed_(std::exchange(other.committed_, true)),
      buffer_(std::move(other.buffer_)) {}

OutputFile::~OutputFile() { discard(); }

void OutputFile::discard() noexcept {
  closeQuietly(fd_);
  if (!committed_ && folder_ >= 0 && !temporary_.empty())
    ::unlinkat(folder_, temporary_.c_str(), 0);
  temporaries::remove(slot_);
  slot_ = nullptr;
  closeQuietly(folder_);
}

void OutputFile::fail(int error) {
  discard();
  committed_ = true;  // nothing is left to remove
  refuse(target_, reason(error));
}

void OutputFile::write(const void* data, std::size_t size) {
  if (fd_ < 0) throw std::logic_error(target_.string() + ": written after it was finished");
  const char* bytes = static_cast<const char*>(data);
  if (buffer_.size() + size > kBufferBytes) flushBuffer();
  if (size >= kBufferBytes)
    writeAll(bytes, size);  // large writes go straight through
  else
    buffer_.insert(buffer_.end(), bytes, bytes + size);
}

void OutputFile::writeAll(const char* bytes, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd_, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(n < 0 ? errno : EIO);
    bytes += n;
    size -= static_cast<std::size_t>(n);
  }
}

void OutputFile::flushBuffer() {
  writeAll(buffer_.data(), buffer_.size());
  buffer_.clear();
}

void OutputFile::finish() {
  if (fd_ < 0) return;
  flushBuffer();
  // A file system that cannot sync (EINVAL) keeps the data as well as it can.
  if (::fdatasync(fd_) != 0 && errno != EINVAL) fail(errno);
  const int fd = std::exchange(fd_, -1);
  if (::close(fd) != 0 && errno != EINTR) fail(errno);
  buffer_.shrink_to_fit();
}

void OutputFile::replaceTarget() {
  if (committed_) throw std::logic_error(target_.string() + ": committed twice");
  if (fd_ >= 0) throw std::logic_error(target_.string() + ": renamed before it was finished");
  if (::renameat(folder_, temporary_.c_str(), folder_, name_.c_str()) != 0) fail(errno);
  committed_ = true;
  temporaries::remove(slot_);
  slot_ = nullptr;
  closeQuietly(folder_);
}

void OutputFile::commit() {
  finish();
  replaceTarget();
}

void commitTogether(std::vector<OutputFile>& files) {
  for (OutputFile& f : files) f.finish();
  for (OutputFile& f : files) f.replaceTarget();
}

void writeFileAtomically(const std::filesystem::path& target, std::string_view bytes) {
  OutputFile out(target);
  out.write(bytes);
  out.commit();
}

void checkOutputDestination(const std::filesystem::path& target) {
  TargetFolder folder = openTargetFolder(target);
  closeQuietly(folder.fd);
}

}  // namespace meshtrace
