// roiclip::batch internal: which files of the input folder a run processes, and the output NAME
// of each.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace roiclip::batch::detail {

/// Image file extensions a run picks up (lower case, compared case-insensitively).
const std::vector<std::string>& imageExtensions();

/// The image files under `input` (sorted by path), recursively when asked. Hidden files (names
/// starting with '.', among them io's temporaries) are skipped.
/// @throws InvalidInputError if `input` is not a readable folder.
std::vector<std::filesystem::path> findImages(const std::filesystem::path& input, bool recursive);

/// Output NAME for `relative` (an image path relative to the input folder): the path without
/// its extension, or with the extension kept (`keepExtension`). Only plain names are allowed:
/// absolute paths, "..", "." and empty components are rejected, so the result can never point
/// outside the output folder.
/// @throws InvalidInputError for such a path.
std::string outputName(const std::filesystem::path& relative, bool keepExtension = false);

/// One image of a run.
struct Job {
  std::filesystem::path image;  ///< as listed under the input folder
  std::string rel;              ///< relative to the input folder, '/' separated
  std::string name;             ///< output NAME
};

/// The images of a run from `input` into `output` (which need not exist yet), in path order:
/// every
/// image findImages() lists except the run's own outputs (when `output` lies in `input`), each
/// with its output NAME, which keeps the extension where two images would share a name.
/// @throws InvalidInputError as findImages() and outputName().
std::vector<Job> listJobs(const std::filesystem::path& input, const std::filesystem::path& output,
                          bool recursive);

}  // namespace roiclip::batch::detail
