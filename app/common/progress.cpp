#include "common/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>
#include <mutex>

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

namespace {
// The terminal line is one for every ProgressLine, drawn from the main
// thread and from loading workers.
std::mutex& terminalLock() {
  static std::mutex lock;
  return lock;
}
ProgressLine*& innermostLine() {
  static ProgressLine* line = nullptr;
  return line;
}
std::size_t& widthOnTerminal() {  // of what was drawn last, to cover it
  static std::size_t width = 0;
  return width;
}

std::size_t terminalColumns() {
  winsize size{};
  return ::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 ? size.ws_col : 0;
}

// With terminalLock held.
void drawOnTerminal(std::string text) {
  // One column short of the width: a character in the last column leaves
  // some terminals' cursor past it, on the next line.
  const std::size_t columns = terminalColumns();
  if (columns > 1 && text.size() > columns - 1) text.resize(columns - 1);
  const std::size_t width = text.size();
  if (width < widthOnTerminal()) text.append(widthOnTerminal() - width, ' ');
  widthOnTerminal() = width;
  std::fprintf(stderr, "%s\r", text.c_str());
  std::fflush(stderr);
}
}  // namespace

std::string ProgressLine::nestedText() const {
  return outer_ ? outer_->nestedText() + " | " + text_ : text_;
}

void ProgressLine::draw(std::string text) {
  if (!shown()) return;
  const std::lock_guard<std::mutex> guard(terminalLock());
  if (!drawn_) {
    outer_ = innermostLine();
    innermostLine() = this;
    drawn_ = true;
  }
  text_ = std::move(text);
  drawOnTerminal(nestedText());
}

// Wipes the whole terminal line, the outer lines' text too: the tools'
// next output starts at its beginning, and an outer line shows again at
// its next update.
void ProgressLine::clear() {
  const std::lock_guard<std::mutex> guard(terminalLock());
  if (!drawn_) return;
  drawn_ = false;
  // Out of the chain of lines, wherever it stands in it (an outer line
  // may be cleared first).
  for (ProgressLine** link = &innermostLine(); *link; link = &(*link)->outer_)
    if (*link == this) {
      *link = outer_;
      break;
    }
  outer_ = nullptr;
  std::fprintf(stderr, "%*s\r", static_cast<int>(widthOnTerminal()), "");
  std::fflush(stderr);
  widthOnTerminal() = 0;
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
