#include "common/progress.h"

#include <unistd.h>

#include <cstdio>

namespace meshtrace::app {

namespace {
bool& shown() {
  static bool on = ::isatty(STDERR_FILENO) == 1;
  return on;
}

// "12 s", "3 min 5 s", "1 h 2 min".
std::string durationText(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  if (s < 60) return std::to_string(s) + " s";
  if (s < 3600) return std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
  return std::to_string(s / 3600) + " h " + std::to_string(s % 3600 / 60) + " min";
}
}  // namespace

void setProgressShown(bool on) { shown() = on && ::isatty(STDERR_FILENO) == 1; }
bool progressShown() { return shown(); }

Progress::Progress(std::string what, std::size_t total)
    : what_(std::move(what)), total_(total), start_(std::chrono::steady_clock::now()) {}

Progress::~Progress() {
  if (width_ > 0) std::fprintf(stderr, "%*s\r", static_cast<int>(width_), "");
}

void Progress::update(std::size_t done, const std::string& item) {
  if (!shown()) return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string line =
      what_ + " " + std::to_string(done + 1) + "/" + std::to_string(total_) + " (" + item + ")";
  if (done > 0)
    line += ", " +
            durationText(elapsed / static_cast<double>(done) * static_cast<double>(total_ - done)) +
            " left";
  // Spaces over what a longer previous line left.
  const std::size_t width = line.size();
  if (line.size() < width_) line.append(width_ - line.size(), ' ');
  width_ = width;
  std::fprintf(stderr, "%s\r", line.c_str());
  std::fflush(stderr);
}

}  // namespace meshtrace::app
