#include "io/temporaries.h"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/random.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <random>

namespace meshtrace::temporaries {

// A temporary's folder and name, readable from a signal handler: `folder`
// is set last when a slot is filled and cleared first when it is emptied.
struct Slot {
  std::atomic<bool> taken{false};
  std::atomic<int> folder{-1};
  char name[NAME_MAX + 1] = {};
};

namespace {

static_assert(std::atomic<int>::is_always_lock_free && std::atomic<void*>::is_always_lock_free,
              "the signal handler reads the slots without locks");

// Slots in blocks that are added as needed and never freed, so the handler
// can walk them at any time.
struct Block {
  std::array<Slot, 64> slots;
  std::atomic<Block*> next{nullptr};
};
Block firstBlock;

// Removes every recorded temporary, then ends the process by the signal
// as its default action would have. Only async-signal-safe calls.
extern "C" void removeTemporariesAndDie(int signal) {
  const int savedErrno = errno;
  for (Block* b = &firstBlock; b; b = b->next.load())
    for (Slot& slot : b->slots) {
      const int folder = slot.folder.load();
      if (folder >= 0) ::unlinkat(folder, slot.name, 0);
    }
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  ::sigemptyset(&dfl.sa_mask);
  ::sigaction(signal, &dfl, nullptr);
  // Delivered with the default action once this handler returns (or at
  // once if the signal is not blocked here).
  ::raise(signal);
  errno = savedErrno;
}

// Handlers only replace defaults: a program that ignores a signal or
// handles it itself keeps doing so.
void installHandlers() {
  for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (::sigaction(signal, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
    struct sigaction mine {};
    mine.sa_handler = removeTemporariesAndDie;
    ::sigfillset(&mine.sa_mask);  // no other handler runs while the files go
    ::sigaction(signal, &mine, nullptr);
  }
  struct sigaction old {};
  if (::sigaction(SIGXFSZ, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    ::sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGXFSZ, &ignore, nullptr);
  }
}

Slot& claimSlot() {
  for (Block* b = &firstBlock;;) {
    for (Slot& slot : b->slots)
      if (!slot.taken.exchange(true)) return slot;
    Block* next = b->next.load();
    if (!next) {
      auto* fresh = new Block;
      if (!b->next.compare_exchange_strong(next, fresh))
        delete fresh;  // another thread added one first: `next` is it
      else
        next = fresh;
    }
    b = next;
  }
}

std::uint64_t randomBits() {
  std::uint64_t bits = 0;
  if (::getrandom(&bits, sizeof bits, 0) == sizeof bits) return bits;
  std::random_device device;
  return (std::uint64_t{device()} << 32) ^ device();
}

}  // namespace

Slot* add(int folder, std::string_view name) {
  static std::once_flag installed;
  std::call_once(installed, installHandlers);
  Slot& slot = claimSlot();
  const std::size_t n = std::min(name.size(), sizeof slot.name - 1);
  std::memcpy(slot.name, name.data(), n);
  slot.name[n] = '\0';
  slot.folder.store(folder);
  return &slot;
}

void remove(Slot* slot) noexcept {
  if (!slot) return;
  slot->folder.store(-1);
  slot->taken.store(false);
}

std::string name(std::string_view target, std::size_t nameMax) {
  // "." + a prefix of the target's name + "." + 12 random characters + ".tmp":
  // 18 bytes besides the prefix, which is cut to fit (at a UTF-8 character
  // boundary) and to at most 64 bytes, enough to tell whose it is.
  constexpr std::size_t kFixed = 18, kMaxPrefix = 64;
  std::size_t keep = std::min({target.size(), kMaxPrefix, nameMax > kFixed ? nameMax - kFixed : 0});
  while (keep > 0 && keep < target.size() &&
         (static_cast<unsigned char>(target[keep]) & 0xC0) == 0x80)
    --keep;
  static constexpr char kDigits[] = "abcdefghijklmnopqrstuvwxyz012345";  // 32: 5 bits each
  std::uint64_t bits = randomBits();
  std::string out;
  out.reserve(keep + kFixed);
  out.append(".").append(target.substr(0, keep)).append(".");
  for (int i = 0; i < 12; ++i, bits >>= 5) out.push_back(kDigits[bits & 31]);
  out.append(".tmp");
  return out;
}

int createExclusive(int folder, const std::string& name) {
  // O_EXCL fails on any existing name, a symlink included, dangling or not.
  return ::openat(folder, name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
}

}  // namespace meshtrace::temporaries
