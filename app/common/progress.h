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
//
// Lines nest: one first drawn while another is shown (a large mesh
// loading during raytrace --all) is drawn after it, as "scene 2/9
// (knot1m.sce), 4 s left | loading knot1m.off: 38% (19 of 49 MB)", so
// that the outer line's news stays in sight. A line longer than the
// terminal is cut to its width: a wrapped line cannot be redrawn in place.
class ProgressLine {
 public:
  ProgressLine() = default;
  ~ProgressLine() { clear(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void draw(std::string text);
  void clear();

 private:
  // This line's text after those of the lines it is drawn in.
  std::string nestedText() const;

  std::string text_;                 // as last drawn
  ProgressLine* outer_ = nullptr;    // the line shown when this one was first drawn
  bool drawn_ = false;               // shown and not yet cleared
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
