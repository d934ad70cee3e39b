// SPDX-License-Identifier: MIT
// `roiclip run`'s progress on stderr: a bar redrawn in place on a terminal, one line per image
// otherwise.
#pragma once

#include <mutex>
#include <string>
#include <thread>

#include <roiclip/batch/run.hpp>

namespace roiclip::app {

/// Prints batch::Progress to stderr. While it exists, whatever else the process writes to stderr
/// goes through a pipe and is printed line by line above the bar, so it never lands in the middle
/// of it: libpng prints its warnings ("libpng warning: iCCP: ...") to stderr from inside
/// cv::imread, where OpenCV's log level does not reach and no handler can be set. If the pipe
/// cannot be made, stderr is left alone.
class ProgressLine {
 public:
  /// @param terminal redraw one bar in place (stderr is a terminal) rather than print lines
  explicit ProgressLine(bool terminal);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// Show the progress after an image (from any thread).
  void show(const batch::Progress& progress);

  /// Give stderr back and print what is left in the pipe; the destructor does it too. A bar left
  /// unfinished (an interrupted run) is ended with a newline.
  void finish();

 private:
  void forwardCapturedLines();                        // the reader thread
  void writeToStderr(const std::string& text) const;  // to the real stderr

  bool terminal_;
  int stderr_ = -1;    // the real stderr while captured (a duplicate), else -1
  int captured_ = -1;  // the pipe's read end
  std::thread reader_;
  std::mutex mutex_;
  std::string bar_;  // the bar as last drawn, redrawn under a forwarded line; empty when done
};

}  // namespace roiclip::app
