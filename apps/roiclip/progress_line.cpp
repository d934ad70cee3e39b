// SPDX-License-Identifier: MIT
// The progress bar of `roiclip run`, and the pipe that keeps other stderr output off it.
#include "progress_line.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace roiclip::app {

namespace {

constexpr const char* kClearLine = "\r\x1b[K";

}  // namespace

ProgressLine::ProgressLine(bool terminal) : terminal_(terminal) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return;
  std::cerr.flush();
  std::fflush(stderr);
  stderr_ = ::fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 0);
  if (stderr_ < 0 || ::dup2(fds[1], STDERR_FILENO) < 0) {
    if (stderr_ >= 0) ::close(stderr_);
    stderr_ = -1;
    ::close(fds[0]);
    ::close(fds[1]);
    return;
  }
  ::close(fds[1]);  // fd 2 is now the pipe's only write end: restoring it ends the reader
  captured_ = fds[0];
  reader_ = std::thread([this] { forwardCapturedLines(); });
}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::finish() {
  if (reader_.joinable()) {
    std::cerr.flush();
    std::fflush(stderr);
    ::dup2(stderr_, STDERR_FILENO);  // closes the pipe's write end
    reader_.join();
    ::close(captured_);
    ::close(stderr_);
    stderr_ = captured_ = -1;
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  if (!bar_.empty()) writeToStderr("\n");
  bar_.clear();
}

void ProgressLine::show(const batch::Progress& s) {
  const double rate = s.elapsed > 0 ? static_cast<double>(s.done) / s.elapsed : 0.0;
  const double eta = rate > 0 ? static_cast<double>(s.total - s.done) / rate : 0.0;
  std::ostringstream line;
  line << std::fixed << std::setprecision(1);
  if (terminal_) {
    constexpr int kWidth = 28;
    const int filled = static_cast<int>(kWidth * s.done / std::max<std::size_t>(s.total, 1));
    line << kClearLine << "[" << std::string(static_cast<std::size_t>(filled), '#')
         << std::string(static_cast<std::size_t>(kWidth - filled), '.') << "] " << s.done << "/"
         << s.total << "  " << rate << " img/s  ETA " << eta << " s  failed " << s.failed;
  } else {
    line << "[" << s.done << "/" << s.total << "] " << s.last->image << " "
         << (s.last->skipped ? "skipped (up to date)" : batch::toString(s.last->status));
    if (!s.last->reason.empty()) line << " (" << s.last->reason << ")";
    line << "  " << rate << " img/s, ETA " << eta << " s\n";
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  const bool done = s.done == s.total;
  bar_ = terminal_ && !done ? line.str() : std::string();
  writeToStderr(terminal_ && done ? line.str() + "\n" : line.str());
}

void ProgressLine::forwardCapturedLines() {
  std::string pending;
  char buffer[4096];
  const auto forward = [this](const std::string& text) {
    const std::lock_guard<std::mutex> lock(mutex_);
    writeToStderr(bar_.empty() ? text : kClearLine + text + bar_);
  };
  while (true) {
    const ssize_t n = ::read(captured_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    pending.append(buffer, static_cast<std::size_t>(n));
    const std::size_t end = pending.rfind('\n');
    if (end == std::string::npos) continue;
    forward(pending.substr(0, end + 1));
    pending.erase(0, end + 1);
  }
  if (!pending.empty()) forward(pending + "\n");
}

void ProgressLine::writeToStderr(const std::string& text) const {
  const int fd = stderr_ >= 0 ? stderr_ : STDERR_FILENO;
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    written += static_cast<std::size_t>(n);
  }
}

}  // namespace roiclip::app
