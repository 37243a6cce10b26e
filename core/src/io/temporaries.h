#pragma once
// The temporary files that OutputFile is writing, where the signal handlers
// can find and remove them, and how they are named and created.
#include <cstddef>
#include <string>
#include <string_view>

namespace meshtrace::temporaries {

struct Slot;

// Records `name`, in the folder open as `folder`, as a temporary to remove
// if SIGINT, SIGTERM or SIGHUP ends the process. The first call installs
// the handlers of those signals that are at their default, and ignores
// SIGXFSZ if it is at its default (a write beyond the file size limit then
// fails with EFBIG). Safe to call from several threads.
Slot* add(int folder, std::string_view name);
// Forgets the temporary (it was renamed or removed).
void remove(Slot* slot) noexcept;

// A fresh name for a temporary beside the file `target`: hidden, at most
// `nameMax` bytes whatever the length of `target`, with 60 random bits.
std::string name(std::string_view target, std::size_t nameMax);

// Creates `name` in `folder` for writing, only if nothing (not even a
// dangling symlink) has that name. Returns the descriptor, or -1 with errno
// set (EEXIST if the name is taken).
int createExclusive(int folder, const std::string& name);

}  // namespace meshtrace::temporaries
