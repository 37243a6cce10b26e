#pragma once
// The error of each pass of a progressive render against a reference image,
// for the compare panel's plot, and the current difference image. Each
// level pass's image is rebuilt from the render's colours, exactly: pass k
// traces every pixel at a multiple of its step, and later level passes
// never change those, so its image is each block filled with its corner's
// colour (from the exact colours once anti-aliasing has changed the
// others). So every level pass gets its point however short the render;
// an anti-aliasing pass gets one when the viewer sees it completed.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "meshtrace/io/image.h"
#include "meshtrace/render/progressive.h"
#include "meshtrace/report/image_compare.h"

namespace meshtrace::viewer {

struct PassError {
  int pass = 0;
  double ms = 0.0;    // when the pass was complete, since the render started
  double rmse = 0.0;  // 8-bit units
  bool antiAliasing = false;
};

// The render as the viewer has it, copied for a comparison off the UI thread.
struct FrameCopy {
  std::uint64_t job = 0;
  ProgressiveFrame frame;  // colours, the tiles' steps and the job's exact colours
  ProgressiveStatus status;
};

class PassErrors {
 public:
  struct Comparison {
    std::uint64_t job = 0;
    int passesDone = 0;  // passes the points cover
    std::vector<PassError> points;
    ImageDifference current;
    std::vector<std::uint8_t> differenceRgba;  // |render - reference| x kDifferenceGain
  };
  static constexpr int kDifferenceGain = 4;

  // Whether a comparison of the render in this state would bring anything
  // new: a new job, a pass completed since the last one, or a finished
  // render not compared since.
  bool due(const ProgressiveStatus& status) const;
  // Marks the comparison of this state as asked for.
  void asked(const ProgressiveStatus& status);
  // Takes a comparison's points in (dropped if of an older job).
  void merge(const Comparison& c);
  void clear();

  const std::vector<PassError>& points() const { return points_; }
  std::uint64_t job() const { return job_; }

  // Compares `copy` with `reference` (the same size): the passes from
  // `firstPass` on that are complete, and the current image.
  static Comparison compare(const FrameCopy& copy, const Image8& reference, int firstPass);
  int nextPass() const { return covered_; }

 private:
  std::uint64_t job_ = 0;
  int covered_ = 0;        // passes with a point (or asked for)
  bool finished_ = false;  // the finished render was asked for
  std::vector<PassError> points_;
};

// The image pass `pass` (a level pass) showed: each block of its step
// filled with its corner's colour. RGB, top row first.
Image8 levelPassImage(const ProgressiveFrame& frame, int pass);
// The colours now (RGB, top row first), each traced pixel filling its block.
Image8 currentImage(const ProgressiveFrame& frame);

}  // namespace meshtrace::viewer
