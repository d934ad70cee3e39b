// SPDX-License-Identifier: MIT
// roiclip::batch internal: the per-image pipeline with its core calls counted (for the tests
// that pin down how often one image runs the core), and the clock of StageTimes.
#pragma once

#include <chrono>

#include <opencv2/core.hpp>

#include <roiclip/batch/process.hpp>

namespace roiclip::batch::detail {

/// The clock every StageTimes figure is measured with.
using Clock = std::chrono::steady_clock;
inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// How often one image called each core function.
struct CoreCalls {
  int simplify = 0;
  int clip = 0;
  int clipLines = 0;
  [[nodiscard]] int total() const { return simplify + clip + clipLines; }
};

/// Processor(options).process(image), also counting the core calls into `calls`.
ImageResult processCountingCoreCalls(const cv::Mat& image, const RunOptions& options,
                                     CoreCalls& calls);

}  // namespace roiclip::batch::detail
