#pragma once
// A progress line for long work (raytrace --all, --report): what is being
// done, how far it is and the time left, redrawn in place on stderr. Shown
// only when stderr is a terminal and not turned off (--quiet): logs and
// pipes get the tools' ordinary lines only.
#include <chrono>
#include <cstddef>
#include <string>

namespace meshtrace::app {

// The help text of --quiet, the same in every tool.
inline constexpr const char* kQuietHelp =
    "No progress line for --all, --report or a large mesh loading (shown on a terminal)";

// Turns progress lines off (--quiet) or back on; they are on by default
// where stderr is a terminal.
void setProgressShown(bool shown);
bool progressShown();

// "12 s", "3 min 5 s", "1 h 2 min"; below 10 s to a tenth ("0.3 s").
std::string durationText(double seconds);

// One line of text redrawn in place on stderr (when progress is shown),
// ending in a carriage return so that the tools' next line of output
// writes over it; wiped when cleared or destroyed.
class ProgressLine {
 public:
  ProgressLine() = default;
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void draw(std::string text);
  void clear();

 private:
  std::size_t width_ = 0;  // of the line last drawn
};

class Progress {
 public:
  // `what`: the work, as "rendering" in "rendering 3/10 (scene.sce), 12 s left".
  Progress(std::string what, std::size_t total);
  // `done` items are finished and `item` comes next. The line ends in a
  // carriage return, so the tools' next line of output writes over it.
  void update(std::size_t done, const std::string& item);

 private:
  std::string what_;
  std::size_t total_;
  std::chrono::steady_clock::time_point start_;
  ProgressLine line_;
};

}  // namespace meshtrace::app
