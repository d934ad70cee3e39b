// SPDX-License-Identifier: MIT
// roiclip::batch: `roiclip run` over a folder of images, as a library function.
//
// Output folder layout (every file written atomically: a temporary file in the same folder,
// then a rename, so an interrupted run never leaves a half-written NAME.* file):
//   NAME.json          the image's ImageResult: status, tags, ROI, clipped polygons, figures
//   NAME.overlay.png   renderOverlay() (only when the pipeline got as far as the ROI)
//   NAME.mask.png      renderMask() (only with writeMasks)
//   summary.csv        one row per image (ImageRecord's fields)
//   summary.json       the same rows plus run totals
//   report.html        counts, a sortable table of every image (failures first), the overlays
//   BatchOptions::coco  the run as COCO instance annotations (only when asked; any path)
// docs/outputs.md documents every file and field.
// NAME is the image's relative path without its extension (with it when two images would
// otherwise share a name; "~2", "~3", ... after it when even that is taken), so sub-folders are
// mirrored with `recursive`. The relative path of an image found in a folder input is its path
// relative to that folder; of an image given as a file (directly, by a glob or in a list file),
// its file name. A video's frames are NAME.f000123.* (the 0-based frame index, six digits or
// more), NAME being the video's.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/batch/options.hpp>
#include <roiclip/batch/process.hpp>  // StageTimes

namespace roiclip::batch {

/// A deterministic share of a run's inputs: shard `index` of `count` (0 <= index < count).
/// Every input (an image, or a video with all its frames) belongs to exactly one shard, chosen by
/// FNV-1a 64 of its relative path (UTF-8, '/' separated, as ImageRecord::image) modulo `count`.
/// The choice depends on nothing else (not on the machine, the order or the other inputs), so N
/// processes started with the same inputs and index 0..N-1 (a Slurm array, a Kubernetes indexed
/// Job, GNU parallel) process every input once between them.
struct Shard {
  int index = 0;  ///< this process's share, 0 .. count - 1
  int count = 1;  ///< number of shares; 1 processes every input
};

/// Parse "I/N" (0 <= I < N, e.g. "0/4" .. "3/4").
/// @throws InvalidInputError quoting the text.
Shard parseShard(const std::string& text);

/// FNV-1a 64-bit hash of `text`'s bytes (offset basis 14695981039346656037, prime
/// 1099511628211): the stable hash Shard uses.
std::uint64_t fnv1a64(const std::string& text);

/// Options of a run.
struct BatchOptions {
  /// What to process, in this order (a file reached twice, e.g. through a folder and a glob,
  /// is processed once, under its first name):
  ///   - a folder: its image and video files (sub-folders with `recursive`);
  ///   - an image file (PNG, JPEG, TIFF, ...) or a video file (anything cv::VideoCapture opens,
  ///     recognised by extension: .mp4, .avi, .mkv, .mov, .webm, ...);
  ///   - a glob (a path with '*', '?' or '[' that names no file): the files and folders it
  ///     matches (POSIX glob(3), sorted; hidden names only when the pattern says so);
  ///   - a list file (.txt, .lst, .list): one path per line, relative to the list file's folder;
  ///     empty lines and lines starting with '#' are skipped; entries that are missing or
  ///     unreadable become failed rows (not a failed run).
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path output;  ///< output folder (created if missing)
  RunOptions process;            ///< per-image pipeline
  int jobs = 0;                  ///< parallel workers; 0 = all hardware threads
  bool recursive = false;        ///< descend into sub-folders (symlinked folders are not followed)
  bool force = false;            ///< reprocess images whose outputs are complete and up to date
  bool writeMasks = false;       ///< also write NAME.mask.png
  bool writeOverlays = true;     ///< write NAME.overlay.png (false: the JSON and summaries only)
  bool writeReport = true;       ///< write report.html
  /// When not empty: also write the whole run as one COCO instance-annotation file here
  /// (docs/outputs.md), atomically, after the summary.
  std::filesystem::path coco;
  int every = 1;  ///< videos: process frames 0, every, 2 x every, ... (>= 1)
  Shard shard;    ///< process only this share of the inputs
};

/// The figures of one named ROI of an image (RoiRegion).
struct RoiRecord {
  std::string name;        ///< RoiRegion::name
  double roiArea = 0;      ///< area of the ROI minus the excluded tags, px^2
  int contoursOut = 0;     ///< contours with a part inside it
  double clippedArea = 0;  ///< area of the contours' parts inside it, px^2
};

/// One image of the summary (summary.csv has one row per image and ROI).
struct ImageRecord {
  std::string image;  ///< relative path ('/' separated; see above); for a frame, the video's
  std::string name;   ///< output NAME (relative to the output folder)
  int frame = -1;     ///< a video's frame index (0-based); -1 for an image
  Status status = Status::Failed;               ///< the image's outcome
  FailureKind failure = FailureKind::Internal;  ///< why it is not Ok (None when it is)
  std::string reason;                           ///< one line when not Ok; empty otherwise
  bool skipped = false;         ///< outputs were up to date; figures read back from NAME.json
  int width = 0;                ///< image width, px (0 when it could not be read)
  int height = 0;               ///< image height, px
  int tagsFound = 0;            ///< accepted tag detections
  int tagsRejected = 0;         ///< doubtful detections dropped (DetectorOptions::maxHamming, ...)
  std::vector<RoiRecord> rois;  ///< per named ROI; the figures below are for their union
  double roiArea = 0;           ///< area of the region (all ROIs minus the tags), px^2
  int contoursIn = 0;           ///< outer contours detected and kept (with an area)
  int contoursDegenerate = 0;   ///< outer contours without an area (ImageResult)
  int contoursOut = 0;          ///< of those, how many have a part inside the region
  double clippedArea = 0;       ///< area of the contours' parts inside the region, px^2
  /// Exact raster route; nothing when the mask check did not run (failed and no-roi images).
  std::optional<double> iou;
  std::int64_t offBandMismatches = 0;  ///< over all comparisons
  double seconds = 0;                  ///< stageSeconds.total (0 when skipped)
  /// Per stage; in a run, `write` includes writing NAME.json (which NAME.json's own "seconds"
  /// cannot). All 0 when skipped.
  StageTimes stageSeconds;
};

/// Progress, reported after every image (from worker threads, one call at a time). A video's
/// frames count as images: `total` counts a video not opened yet as one, an open one by the
/// frame count its container states (CAP_PROP_FRAME_COUNT, divided by BatchOptions::every),
/// and a finished one by the frames it had.
struct Progress {
  std::size_t done = 0;               ///< images finished (processed, skipped or failed)
  std::size_t total = 0;              ///< images expected (see above)
  std::size_t skipped = 0;            ///< of `done`, how many were up to date
  std::size_t failed = 0;             ///< status other than Ok
  double elapsed = 0;                 ///< seconds since the run started
  const ImageRecord* last = nullptr;  ///< the image just finished
};
using ProgressCallback = std::function<void(const Progress&)>;

/// What run() did.
struct RunSummary {
  std::vector<ImageRecord> images;  ///< in input order; only images finished when interrupted
  std::size_t total = 0;            ///< images found (in this shard; a video's frames each)
  std::size_t ok = 0;               ///< images with Status::Ok
  std::size_t noRoi = 0;            ///< images with Status::NoRoi
  std::size_t failed = 0;           ///< images with Status::Failed
  std::size_t mismatched = 0;       ///< images with Status::MaskMismatch
  std::size_t skipped = 0;          ///< images whose outputs were up to date
  bool interrupted = false;         ///< the run was cancelled before every image was done
  double seconds = 0;               ///< wall time of the run
  /// True when every finished image is Ok and the run was not interrupted.
  [[nodiscard]] bool allOk() const {
    return !interrupted && ok == images.size() && images.size() == total;
  }
  /// Append a finished image's row to `images` and count it (ok ... mismatched, skipped).
  void add(ImageRecord record) {
    switch (record.status) {
      case Status::Ok:
        ++ok;
        break;
      case Status::NoRoi:
        ++noRoi;
        break;
      case Status::Failed:
        ++failed;
        break;
      case Status::MaskMismatch:
        ++mismatched;
        break;
    }
    if (record.skipped) ++skipped;
    images.push_back(std::move(record));
  }
};

/// Process every image of options.inputs (of options.shard) into options.output, `jobs` at a
/// time, each worker holding one image at a time (memory is bounded by jobs x one image; a video
/// is read by one worker, frame after frame). Images are read as their EXIF orientation says
/// (JPEG APP1, PNG eXIf; as cv::imread does without IMREAD_IGNORE_ORIENTATION), keeping 16-bit
/// and alpha. Per-image failures are
/// recorded and the run carries on. Temporaries of dead runs in options.output are removed first
/// (io::removeStaleTemporaries). Images whose NAME.json (status ok or no-roi, made with the
/// same optionsKey()) and NAME.overlay.png (and NAME.mask.png when asked) are newer than the
/// image are skipped unless options.force; failed and mask-mismatch images are always redone.
/// When `cancel` becomes true, no new image is started; images in flight finish (their files
/// are complete or absent), then the summary of what was done is written and
/// RunSummary::interrupted is set.
/// Frames of a video are resumed one by one (each frame's NAME.f000123.json against the video's
/// modification time).
/// @throws InvalidInputError if an input folder, file, glob or list file given in
///         options.inputs cannot be read or matches nothing, options.every or options.shard are
///         out of range, or the pipeline options are bad (ROI spec, board file); Error if the
///         output folder cannot be created or written.
RunSummary run(const BatchOptions& options, const ProgressCallback& progress = {},
               const std::atomic<bool>* cancel = nullptr);

/// What run() refuses before it creates anything, checked without touching the output folder:
/// the input folder is listed and the pipeline options make a Processor (ROI specs, board file,
/// detector options). Call it first so that bad options leave no output folder behind.
/// @return the number of images run() would process (0: none found).
/// @throws InvalidInputError as run() does for those.
std::size_t checkRun(const BatchOptions& options);

}  // namespace roiclip::batch
