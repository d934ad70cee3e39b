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
// NAME is the image's path relative to the input folder without its extension (with it when
// two images would otherwise share a name), so sub-folders are mirrored with `recursive`.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/batch/options.hpp>

namespace roiclip::batch {

/// Options of a run.
struct BatchOptions {
  std::filesystem::path input;   ///< folder of images
  std::filesystem::path output;  ///< output folder (created if missing)
  RunOptions process;            ///< per-image pipeline
  int jobs = 0;                  ///< parallel workers; 0 = all hardware threads
  bool recursive = false;        ///< descend into sub-folders (symlinked folders are not followed)
  bool force = false;            ///< reprocess images whose outputs are complete and up to date
  bool writeMasks = false;       ///< also write NAME.mask.png
  bool writeReport = true;       ///< write report.html
};

/// The figures of one named ROI of an image (RoiRegion).
struct RoiRecord {
  std::string name;
  double roiArea = 0;
  int contoursOut = 0;
  double clippedArea = 0;
};

/// One image of the summary (summary.csv has one row per image and ROI).
struct ImageRecord {
  std::string image;  ///< path relative to the input folder ('/' separated)
  std::string name;   ///< output NAME (relative to the output folder)
  Status status = Status::Failed;
  FailureKind failure = FailureKind::Internal;
  std::string reason;
  bool skipped = false;  ///< outputs were up to date; figures read back from NAME.json
  int width = 0, height = 0;
  int tagsFound = 0;
  int tagsRejected = 0;         ///< doubtful detections dropped (DetectorOptions::maxHamming, ...)
  std::vector<RoiRecord> rois;  ///< per named ROI; the figures below are for their union
  double roiArea = 0;
  int contoursIn = 0, contoursOut = 0;
  double clippedArea = 0;
  double iou = 1.0;                    ///< exact raster route
  std::int64_t offBandMismatches = 0;  ///< over all comparisons
  double seconds = 0;                  ///< processing time (0 when skipped)
};

/// Progress, reported after every image (from worker threads, one call at a time).
struct Progress {
  std::size_t done = 0;  ///< images finished (processed, skipped or failed)
  std::size_t total = 0;
  std::size_t skipped = 0;
  std::size_t failed = 0;             ///< status other than Ok
  double elapsed = 0;                 ///< seconds since the run started
  const ImageRecord* last = nullptr;  ///< the image just finished
};
using ProgressCallback = std::function<void(const Progress&)>;

/// What run() did.
struct RunSummary {
  std::vector<ImageRecord> images;  ///< in input order; only images finished when interrupted
  std::size_t total = 0;            ///< images found
  std::size_t ok = 0, noRoi = 0, failed = 0, mismatched = 0, skipped = 0;
  bool interrupted = false;
  double seconds = 0;
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

/// Process every image of options.input into options.output, `jobs` at a time, each worker
/// holding one image at a time (memory is bounded by jobs x one image). Per-image failures are
/// recorded and the run carries on. Temporaries of dead runs in options.output are removed first
/// (io::removeStaleTemporaries). Images whose NAME.json (status ok or no-roi, made with the
/// same optionsKey()) and NAME.overlay.png (and NAME.mask.png when asked) are newer than the
/// image are skipped unless options.force; failed and mask-mismatch images are always redone.
/// When `cancel` becomes true, no new image is started; images in flight finish (their files
/// are complete or absent), then the summary of what was done is written and
/// RunSummary::interrupted is set.
/// @throws InvalidInputError if the input folder cannot be read or the pipeline options are bad
///         (ROI spec, board file); Error if the output folder cannot be created or written.
RunSummary run(const BatchOptions& options, const ProgressCallback& progress = {},
               const std::atomic<bool>* cancel = nullptr);

/// Turn a JSON config object into command-line arguments: {"jobs": 2, "force": true,
/// "roi": "hull"} -> ["--jobs", "2", "--force", "--roi", "hull"]. Booleans become a flag when
/// true and are left out when false; arrays repeat the option. Keys are long option names
/// without the dashes. The app puts these before its own arguments so the command line wins.
/// @throws InvalidInputError naming `source` for malformed JSON or a non-object.
std::vector<std::string> configToArguments(const std::string& jsonText,
                                           const std::string& source = "config");

}  // namespace roiclip::batch
