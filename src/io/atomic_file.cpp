// SPDX-License-Identifier: MIT
// Atomic file writes and the cleaner for their temporaries (atomic_file.hpp).
#include <roiclip/io/atomic_file.hpp>

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>

#include <roiclip/error.hpp>

namespace roiclip::io {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kMarker = ".tmp.";

bool allDigits(std::string_view s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
}

[[noreturn]] void fail(const fs::path& file, const std::string& reason) {
  throw Error("cannot write " + file.string() + ": " + reason);
}

}  // namespace

fs::path temporaryPath(const fs::path& file, long pid, unsigned long counter) {
  return file.parent_path() / ("." + file.filename().string() + std::string(kMarker) +
                               std::to_string(pid) + "." + std::to_string(counter));
}

std::optional<long> temporaryOwner(const std::string& filename) {
  const std::size_t marker = filename.rfind(kMarker);
  if (filename.size() < 2 || filename[0] != '.' || marker == std::string::npos || marker == 0) {
    return std::nullopt;
  }
  const std::string_view rest = std::string_view(filename).substr(marker + kMarker.size());
  const std::size_t dot = rest.find('.');
  if (dot == std::string_view::npos) return std::nullopt;
  const std::string_view pid = rest.substr(0, dot);
  // More than 9 digits is no PID (and would not fit a pid_t).
  if (!allDigits(pid) || !allDigits(rest.substr(dot + 1)) || pid.size() > 9) return std::nullopt;
  return std::stol(std::string(pid));
}

void writeFileAtomically(const fs::path& file, std::string_view bytes) {
  // Said before anything is tried: the temporary would go to the folder above, and the rename's
  // error (or the temporary's, in a folder the user cannot write) would hide the real reason.
  std::error_code isDir;
  if (fs::is_directory(file, isDir)) fail(file, "is a directory");
  static std::atomic<unsigned long> counter{0};
  const fs::path tmp = temporaryPath(file, static_cast<long>(::getpid()), counter.fetch_add(1));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) fail(file, std::strerror(errno));
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      fs::remove(tmp, ignored);
      fail(file, "write failed");
    }
  }
  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    fail(file, ec.message());
  }
}

std::size_t removeStaleTemporaries(const fs::path& folder) {
  std::size_t removed = 0;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::optional<long> owner = temporaryOwner(it->path().filename().string());
    if (!owner) continue;
    const auto pid = static_cast<pid_t>(*owner);
    // A live process (another run into the same folder) still owns its temporaries; EPERM also
    // means the process exists.
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code rm;
    if (fs::remove(it->path(), rm)) ++removed;
  }
  return removed;
}

}  // namespace roiclip::io
