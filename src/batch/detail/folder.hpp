// SPDX-License-Identifier: MIT
// roiclip::batch internal: which files a run processes (BatchOptions::inputs: folders, image and
// video files, globs, list files), and the output NAME of each.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace roiclip::batch::detail {

/// Image file extensions a run picks up in folders (lower case, compared case-insensitively).
const std::vector<std::string>& imageExtensions();
/// Video file extensions (read with cv::VideoCapture): .mp4, .avi, .mkv, .mov, ...
const std::vector<std::string>& videoExtensions();
/// Extensions of list files (.txt, .lst, .list).
const std::vector<std::string>& listExtensions();

/// True when `file`'s extension is one of videoExtensions().
bool isVideoFile(const std::filesystem::path& file);

/// The image and video files under `folder` (sorted by path), recursively when asked. Hidden
/// files (names starting with '.', among them io's temporaries) are skipped.
/// @throws InvalidInputError if `folder` is not a readable folder.
std::vector<std::filesystem::path> findMediaFiles(const std::filesystem::path& folder,
                                                  bool recursive);

/// The paths matching `pattern` (POSIX glob(3): '*', '?', '[...]'; a leading '.' only matched
/// explicitly), sorted by path so the order does not depend on the locale.
/// @throws InvalidInputError if a folder on the way cannot be read.
std::vector<std::filesystem::path> expandGlob(const std::string& pattern);

/// The entries of a list file: one path per line (surrounding white space trimmed), relative
/// ones taken relative to the list file's folder; empty lines and lines starting with '#' are
/// skipped. The entries are not checked.
/// @throws InvalidInputError if the file cannot be read.
std::vector<std::filesystem::path> readListFile(const std::filesystem::path& list);

/// Output NAME for `relative` (an image path relative to the input folder): the path without
/// its extension, or with the extension kept (`keepExtension`). Only plain names are allowed:
/// absolute paths, "..", "." and empty components are rejected, so the result can never point
/// outside the output folder.
/// @throws InvalidInputError for such a path.
std::string outputName(const std::filesystem::path& relative, bool keepExtension = false);

/// One input of a run: an image, or a video (all its frames).
struct Job {
  std::filesystem::path image;  ///< the file (may be missing: an entry of a list file)
  std::string rel;              ///< relative path, '/' separated (ImageRecord::image)
  std::string name;             ///< output NAME (a video's frames add ".f000123")
  bool video = false;           ///< read with cv::VideoCapture
};

/// The inputs of a run from `inputs` into `output` (which need not exist yet), in the order
/// given, each folder's files in path order (see BatchOptions::inputs): the run's own outputs
/// (when `output` lies in a folder input, or overlays and masks in the output folder) are left
/// out, and a file reached twice is listed once. Each gets its output NAME: the relative path
/// without extension, with it where two would share a name, then "~2", "~3", ... as needed.
/// @throws InvalidInputError for an input that is missing, a glob that matches nothing, an
///         unreadable folder or list file.
std::vector<Job> listJobs(const std::vector<std::filesystem::path>& inputs,
                          const std::filesystem::path& output, bool recursive);

/// Create the output folder (and its parents) and remove the hidden temporaries a run killed
/// hard (second Ctrl-C, SIGKILL) left there; never final files.
/// @throws Error naming the folder when it cannot be created.
void prepareOutputFolder(const std::filesystem::path& output);

}  // namespace roiclip::batch::detail
