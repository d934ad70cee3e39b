// A run's input: the image files of a folder and the output NAME of each.
#include "detail/folder.hpp"

#include <algorithm>
#include <cctype>
#include <map>

#include <roiclip/error.hpp>

namespace roiclip::batch::detail {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool isImageFile(const fs::path& p) {
  const std::string ext = lower(p.extension().string());
  const auto& all = imageExtensions();
  return std::find(all.begin(), all.end(), ext) != all.end();
}

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

}  // namespace

const std::vector<std::string>& imageExtensions() {
  static const std::vector<std::string> kExtensions = {
      ".png", ".jpg", ".jpeg", ".jpe", ".tif",  ".tiff", ".bmp", ".dib",
      ".pgm", ".ppm", ".pnm",  ".pbm", ".webp", ".jp2",  ".exr", ".hdr"};
  return kExtensions;
}

std::vector<fs::path> findImages(const fs::path& input, bool recursive) {
  std::error_code ec;
  if (!fs::is_directory(input, ec)) {
    throw InvalidInputError(input.string() + ": not a folder (or not readable)");
  }
  std::vector<fs::path> found;
  const auto consider = [&](const fs::directory_entry& e) {
    const std::string fname = e.path().filename().string();
    if (!fname.empty() && fname[0] == '.') return;  // hidden files and our own temp files
    std::error_code fe;
    if (e.is_regular_file(fe) && isImageFile(e.path())) found.push_back(e.path());
  };
  try {
    if (recursive) {
      for (const auto& e :
           fs::recursive_directory_iterator(input, fs::directory_options::skip_permission_denied)) {
        consider(e);
      }
    } else {
      for (const auto& e : fs::directory_iterator(input)) consider(e);
    }
  } catch (const fs::filesystem_error& e) {
    throw InvalidInputError(input.string() + ": cannot list folder: " + e.what());
  }
  std::sort(found.begin(), found.end());
  return found;
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

std::vector<Job> listJobs(const fs::path& input, const fs::path& output, bool recursive) {
  std::vector<fs::path> images = findImages(input, recursive);
  // An output folder inside the input folder must not feed our own overlays back in.
  const fs::path outCanon = fs::weakly_canonical(output);
  const fs::path inCanon = fs::weakly_canonical(input);
  const auto isOurOutput = [&](const fs::path& p) {
    if (outCanon != inCanon) {
      // Only an output folder inside the input folder can hold outputs we would list.
      return isUnder(outCanon, inCanon) && isUnder(fs::weakly_canonical(p), outCanon);
    }
    const std::string f = lower(p.filename().string());
    const auto endsWith = [&f](const std::string& s) {
      return f.size() >= s.size() && f.compare(f.size() - s.size(), s.size(), s) == 0;
    };
    return endsWith(".overlay.png") || endsWith(".mask.png");
  };
  images.erase(std::remove_if(images.begin(), images.end(), isOurOutput), images.end());

  std::vector<Job> jobs;
  std::map<std::string, int> stems;
  for (const auto& p : images) {
    Job j;
    j.image = p;
    // Relative to the folder as listed, symlinks not resolved: a link to a file elsewhere still
    // gets its name inside the output folder.
    const fs::path rel = p.lexically_relative(input);
    j.rel = rel.generic_string();
    j.name = outputName(rel, false);
    ++stems[j.name];
    jobs.push_back(std::move(j));
  }
  for (auto& j : jobs) {
    if (stems[j.name] > 1) j.name = outputName(fs::path(j.rel), true);
  }
  return jobs;
}

}  // namespace roiclip::batch::detail
