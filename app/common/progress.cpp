#include "common/progress.h"

#include <unistd.h>

#include <cstdio>

namespace meshtrace::app {

namespace {
bool& shown() {
  static bool on = ::isatty(STDERR_FILENO) == 1;
  return on;
}
}  // namespace

void setProgressShown(bool on) { shown() = on && ::isatty(STDERR_FILENO) == 1; }
bool progressShown() { return shown(); }

std::string durationText(double seconds) {
  if (seconds < 9.95) {
    char text[16];
    std::snprintf(text, sizeof text, "%.1f s", seconds < 0.0 ? 0.0 : seconds);
    return text;
  }
  const long s = static_cast<long>(seconds + 0.5);
  if (s < 60) return std::to_string(s) + " s";
  if (s < 3600) return std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s";
  return std::to_string(s / 3600) + " h " + std::to_string(s % 3600 / 60) + " min";
}

void ProgressLine::draw(std::string text) {
  if (!shown()) return;
  // Spaces over what a longer previous line left.
  const std::size_t width = text.size();
  if (text.size() < width_) text.append(width_ - text.size(), ' ');
  width_ = width;
  std::fprintf(stderr, "%s\r", text.c_str());
  std::fflush(stderr);
}

void ProgressLine::clear() {
  if (width_ == 0) return;
  std::fprintf(stderr, "%*s\r", static_cast<int>(width_), "");
  std::fflush(stderr);
  width_ = 0;
}

Progress::Progress(std::string what, std::size_t total)
    : what_(std::move(what)), total_(total), start_(std::chrono::steady_clock::now()) {}

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
  line_.draw(std::move(line));
}

}  // namespace meshtrace::app
