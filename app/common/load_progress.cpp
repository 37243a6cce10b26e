#include "common/load_progress.h"

#include <algorithm>
#include <string>

#include "meshtrace/io/memory_budget.h"

namespace meshtrace::app {

namespace {
using Clock = std::chrono::steady_clock;
// Loads of fewer bytes (the files opened so far, summed) show no line: they
// are over in a fraction of a second, where a line drawn and wiped at once
// reads as a flicker, not as progress. A size rather than a time, so that
// whether a mesh shows a line does not depend on how busy the machine is.
constexpr std::uint64_t kQuietBelowBytes = std::uint64_t{8} << 20;
// Redraws are a write to the terminal each: a tenth of a second apart is
// smooth to the eye and costs the load nothing.
constexpr auto kRedrawEvery = std::chrono::milliseconds(100);
constexpr double kEstimateAfterSeconds = 0.1;

double secondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}
}  // namespace

void LoadProgress::bytesRead(const std::filesystem::path& file, std::uint64_t bytes,
                             std::uint64_t fileBytes) {
  if (!progressShown()) return;
  const std::lock_guard<std::mutex> guard(lock_);
  // Timed from the first byte, not from the parse of the scene file or a
  // read that does not report (a bare mesh is read once to frame it).
  if (files_.empty()) start_ = Clock::now();
  FileRead& f = files_[file];
  f.size = fileBytes;
  f.read += bytes;
  drawIfDue(false);
}

void LoadProgress::phase(const std::filesystem::path& file, std::string_view phase) {
  if (!progressShown() || phase != "normals") return;
  const std::lock_guard<std::mutex> guard(lock_);
  if (files_.count(file) == 0) return;  // read by a reader that does not report
  normals_ = true;
  drawIfDue(true);
}

void LoadProgress::drawIfDue(bool phaseChanged) {
  std::uint64_t read = 0, size = 0;
  for (const auto& [file, f] : files_) read += f.read, size += f.size;
  if (size < kQuietBelowBytes) return;
  const Clock::time_point now = Clock::now();
  // A change of phase is always drawn: the line must not stay at "0.0 s
  // left" while the normals are computed.
  if (!phaseChanged && now - lastDraw_ < kRedrawEvery) return;
  lastDraw_ = now;
  std::string line = "loading " +
                     (files_.size() == 1 ? files_.begin()->first.filename().string()
                                         : std::to_string(files_.size()) + " meshes") +
                     ": ";
  if (normals_ && read >= size) {
    line += "computing normals";
  } else {
    const double fraction = static_cast<double>(std::min(read, size)) / static_cast<double>(size);
    const double elapsed = secondsBetween(start_, now);
    line += std::to_string(static_cast<int>(fraction * 100.0)) + "% (" + formatBytes(read) +
            " of " + formatBytes(size) + ")";
    // The first pieces come before any rate can be told from them.
    if (elapsed >= kEstimateAfterSeconds)
      line += ", " + durationText(elapsed / fraction - elapsed) + " left";
  }
  line_.draw(std::move(line));
}

}  // namespace meshtrace::app
