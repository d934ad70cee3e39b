// SPDX-License-Identifier: MIT
// A run's inputs: folders, files, globs and list files, expanded into the files to process and
// the output NAME of each.
#include "detail/folder.hpp"

#include <glob.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <set>

#include <roiclip/error.hpp>
#include <roiclip/io/atomic_file.hpp>

namespace roiclip::batch::detail {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool hasExtension(const fs::path& p, const std::vector<std::string>& extensions) {
  const std::string ext = lower(p.extension().string());
  return std::find(extensions.begin(), extensions.end(), ext) != extensions.end();
}

bool isMediaFile(const fs::path& p) {
  return hasExtension(p, imageExtensions()) || hasExtension(p, videoExtensions());
}

bool isOverlayOrMask(const fs::path& p) {
  const std::string f = lower(p.filename().string());
  const auto endsWith = [&f](const std::string& s) {
    return f.size() >= s.size() && f.compare(f.size() - s.size(), s.size(), s) == 0;
  };
  return endsWith(".overlay.png") || endsWith(".mask.png");
}

bool hasGlobCharacters(const std::string& s) { return s.find_first_of("*?[") != std::string::npos; }

// True when `p` lies in folder `dir` (both weakly canonical).
bool isUnder(const fs::path& p, const fs::path& dir) {
  auto d = dir.begin();
  auto q = p.begin();
  for (; d != dir.end(); ++d, ++q) {
    if (d->empty()) continue;  // trailing separator
    if (q == p.end() || *q != *d) return false;
  }
  return true;
}

// "in/" lists "in/x.png", which is not relative to "in/" element by element: drop the slash.
fs::path withoutTrailingSeparator(fs::path p) {
  while (!p.has_filename() && p.has_relative_path()) p = p.parent_path();
  return p;
}

// One file found, before naming.
struct Found {
  fs::path file;
  fs::path rel;
};

class Lister {
 public:
  Lister(const fs::path& output, bool recursive)
      : outCanon_(fs::weakly_canonical(output)), recursive_(recursive) {}

  // A command-line input: folder, file, list file or glob.
  void addInput(const fs::path& given) {
    const fs::path input = withoutTrailingSeparator(given);
    std::error_code ec;
    const fs::file_status status = fs::status(input, ec);
    if (fs::is_directory(status)) {
      addFolder(input);
    } else if (fs::exists(status)) {
      if (hasExtension(input, listExtensions())) {
        for (const fs::path& entry : readListFile(input)) addEntry(entry);
      } else {
        addFile(input);
      }
    } else if (hasGlobCharacters(input.string())) {
      const std::vector<fs::path> matches = expandGlob(input.string());
      if (matches.empty()) throw InvalidInputError(input.string() + ": matches no file or folder");
      for (const fs::path& m : matches) {
        if (fs::is_directory(m, ec)) {
          addFolder(m);
        } else if (isMediaFile(m)) {
          addFile(m);
        }
      }
    } else {
      throw InvalidInputError(input.string() + ": no such file or folder");
    }
  }

  std::vector<Found> found() && { return std::move(found_); }

 private:
  // A list file's entry: a folder or a file, which may be missing (a failed row then).
  void addEntry(const fs::path& entry) {
    const fs::path p = withoutTrailingSeparator(entry);
    std::error_code ec;
    if (fs::is_directory(p, ec)) {
      addFolder(p);
    } else {
      addFile(p);
    }
  }

  void addFolder(const fs::path& folder) {
    // An output folder inside the input folder must not feed our own overlays back in.
    const fs::path inCanon = fs::weakly_canonical(folder);
    const auto isOurOutput = [&](const fs::path& p) {
      if (outCanon_ != inCanon) {
        // Only an output folder inside the input folder can hold outputs we would list.
        return isUnder(outCanon_, inCanon) && isUnder(fs::weakly_canonical(p), outCanon_);
      }
      return isOverlayOrMask(p);
    };
    for (const fs::path& p : findMediaFiles(folder, recursive_)) {
      // Relative to the folder as listed, symlinks not resolved: a link to a file elsewhere
      // still gets its name inside the output folder.
      if (!isOurOutput(p)) add(p, p.lexically_relative(folder));
    }
  }

  void addFile(const fs::path& file) {
    if (isOverlayOrMask(file) && isUnder(fs::weakly_canonical(file), outCanon_)) return;
    add(file, file.filename());
  }

  void add(const fs::path& file, const fs::path& rel) {
    if (seen_.insert(fs::absolute(file).lexically_normal()).second) found_.push_back({file, rel});
  }

  fs::path outCanon_;
  bool recursive_;
  std::vector<Found> found_;
  std::set<fs::path> seen_;
};

}  // namespace

const std::vector<std::string>& imageExtensions() {
  static const std::vector<std::string> kExtensions = {
      ".png", ".jpg", ".jpeg", ".jpe", ".tif",  ".tiff", ".bmp", ".dib",
      ".pgm", ".ppm", ".pnm",  ".pbm", ".webp", ".jp2",  ".exr", ".hdr"};
  return kExtensions;
}

const std::vector<std::string>& videoExtensions() {
  static const std::vector<std::string> kExtensions = {".mp4",  ".m4v", ".mov",  ".avi", ".mkv",
                                                       ".webm", ".mpg", ".mpeg", ".ts",  ".mts",
                                                       ".m2ts", ".wmv", ".flv",  ".ogv", ".3gp"};
  return kExtensions;
}

const std::vector<std::string>& listExtensions() {
  static const std::vector<std::string> kExtensions = {".txt", ".lst", ".list"};
  return kExtensions;
}

bool isVideoFile(const fs::path& file) { return hasExtension(file, videoExtensions()); }

std::vector<fs::path> findMediaFiles(const fs::path& folder, bool recursive) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) {
    throw InvalidInputError(folder.string() + ": not a folder (or not readable)");
  }
  std::vector<fs::path> found;
  const auto consider = [&](const fs::directory_entry& e) {
    const std::string fname = e.path().filename().string();
    if (!fname.empty() && fname[0] == '.') return;  // hidden files and our own temp files
    std::error_code fe;
    if (e.is_regular_file(fe) && isMediaFile(e.path())) found.push_back(e.path());
  };
  try {
    if (recursive) {
      for (const auto& e : fs::recursive_directory_iterator(
               folder, fs::directory_options::skip_permission_denied)) {
        consider(e);
      }
    } else {
      for (const auto& e : fs::directory_iterator(folder)) consider(e);
    }
  } catch (const fs::filesystem_error& e) {
    throw InvalidInputError(folder.string() + ": cannot list folder: " + e.what());
  }
  std::sort(found.begin(), found.end());
  return found;
}

std::vector<fs::path> expandGlob(const std::string& pattern) {
  glob_t g{};
  const int rc = ::glob(pattern.c_str(), GLOB_NOSORT, nullptr, &g);
  std::vector<fs::path> out;
  if (rc == 0) {
    for (std::size_t i = 0; i < g.gl_pathc; ++i) out.emplace_back(g.gl_pathv[i]);
  }
  ::globfree(&g);
  if (rc != 0 && rc != GLOB_NOMATCH) {
    throw InvalidInputError(pattern + ": cannot expand the pattern (a folder on the way cannot " +
                            "be read)");
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<fs::path> readListFile(const fs::path& list) {
  std::ifstream in(list, std::ios::binary);
  if (!in) throw InvalidInputError(list.string() + ": cannot read list file");
  const fs::path base = list.parent_path();
  std::vector<fs::path> entries;
  for (std::string line; std::getline(in, line);) {
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::size_t last = line.find_last_not_of(" \t\r");
    const fs::path entry = line.substr(first, last - first + 1);
    entries.push_back(entry.is_absolute() ? entry : base / entry);
  }
  return entries;
}

std::string outputName(const fs::path& relative, bool keepExtension) {
  if (relative.empty() || relative.is_absolute() || relative.has_root_name()) {
    throw InvalidInputError("'" + relative.string() + "': not a relative path");
  }
  std::string out;
  for (auto it = relative.begin(); it != relative.end(); ++it) {
    const std::string part = it->string();
    if (part.empty() || part == "." || part == "..") {
      throw InvalidInputError("'" + relative.string() + "': path leaves or names its folder");
    }
    if (!out.empty()) out += '/';
    out += (std::next(it) == relative.end() && !keepExtension) ? it->stem().string() : part;
  }
  if (out.empty() || out.back() == '/') {
    throw InvalidInputError("'" + relative.string() + "': empty file name");
  }
  return out;
}

std::vector<Job> listJobs(const std::vector<fs::path>& inputs, const fs::path& output,
                          bool recursive) {
  Lister lister(output, recursive);
  for (const fs::path& input : inputs) lister.addInput(input);
  std::vector<Found> found = std::move(lister).found();

  std::vector<Job> jobs;
  std::map<std::string, int> stems;
  for (Found& f : found) {
    Job j;
    j.rel = f.rel.generic_string();
    j.name = outputName(f.rel, false);
    j.video = isVideoFile(f.file);
    j.image = std::move(f.file);
    ++stems[j.name];
    jobs.push_back(std::move(j));
  }
  // Same stem: keep the extensions; the same file name from two places: number the later ones.
  std::set<std::string> taken;
  for (auto& j : jobs) {
    if (stems[j.name] > 1) j.name = outputName(fs::path(j.rel), true);
  }
  for (auto& j : jobs) {
    const std::string base = j.name;
    for (int k = 2; !taken.insert(j.name).second; ++k) j.name = base + "~" + std::to_string(k);
  }
  return jobs;
}

void prepareOutputFolder(const fs::path& output) {
  std::error_code ec;
  fs::create_directories(output, ec);
  if (ec || !fs::is_directory(output)) {
    throw Error("cannot create output folder " + output.string() + (ec ? ": " + ec.message() : ""));
  }
  io::removeStaleTemporaries(output);
}

}  // namespace roiclip::batch::detail
