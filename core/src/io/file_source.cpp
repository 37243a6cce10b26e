#include "io/file_source.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "meshtrace/io/input_error.h"
#include "meshtrace/io/load_observer.h"

namespace meshtrace::text {

namespace {

// Why `file` could not be opened, in the words a user looks for.
std::string openFailure(const std::filesystem::path& file, int error) {
  if (error == ELOOP) return "too many levels of symbolic links (a symlink loop?)";
  if (error == ENOENT) {
    struct stat link {};
    if (::lstat(file.c_str(), &link) == 0 && S_ISLNK(link.st_mode))
      return "a symlink to a file that does not exist";
    return "file not found";
  }
  if (error == ENOTDIR) return "file not found (a part of its path is not a folder)";
  if (error == EACCES) return "permission denied";
  if (error == ENAMETOOLONG) return "the path is too long";
  return std::string("cannot open the file (") + std::strerror(error) + ")";
}

}  // namespace

FileSource::FileSource(const std::filesystem::path& file, std::uintmax_t maxBytes,
                       LoadObserver* observer)
    : file_(file), observer_(observer) {
  // Non-blocking: opening a named pipe must not wait for a writer.
  fd_ = ::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
  if (fd_ < 0) throw InputError::inFile(file, openFailure(file, errno));
  struct stat st {};
  const int statError = ::fstat(fd_, &st) == 0 ? 0 : errno;
  const auto fail = [&](const std::string& what) {
    ::close(fd_);
    throw InputError::inFile(file, what);
  };
  if (statError) fail(std::string("cannot read the file (") + std::strerror(statError) + ")");
  if (S_ISDIR(st.st_mode)) fail("is a directory, not a file");
  if (!S_ISREG(st.st_mode))
    fail("is not a regular file (a pipe, device or socket): it may never end");
  size_ = static_cast<std::uintmax_t>(st.st_size);
  if (size_ > maxBytes) {
    fail("file is " + std::to_string(size_) + " bytes, more than the " + std::to_string(maxBytes) +
         " accepted");
  }
}

FileSource::~FileSource() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t FileSource::read(char* out, std::size_t capacity) {
  std::size_t done = 0;
  while (done < capacity) {
    const ssize_t n = ::read(fd_, out + done, capacity - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      throw InputError::inFile(file_,
                               std::string("cannot read the file (") + std::strerror(errno) + ")");
    if (n == 0) break;
    done += static_cast<std::size_t>(n);
  }
  if (observer_ != nullptr && done > 0) observer_->bytesRead(file_, done, size_);
  return done;
}

}  // namespace meshtrace::text
