// SPDX-License-Identifier: MIT
// roiclip::batch internal: NAME.json (batch::resultToJson() writes it for every image), read
// back when a run resumes and when the COCO file is made. Both directions spell Status and
// FailureKind with the tables of options.hpp; docs/outputs.md documents every member.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/batch/process.hpp>
#include <roiclip/batch/run.hpp>

namespace roiclip::batch::detail {

/// The name of every StageTimes figure in output files ("seconds" of NAME.json, "stage_seconds"
/// of summary.json), in pipeline order; writing and reading both go through this table.
inline constexpr std::pair<const char*, double StageTimes::*> kStageTimes[] = {
    {"read", &StageTimes::read},       {"detect", &StageTimes::detect},
    {"roi", &StageTimes::roi},         {"contours", &StageTimes::contours},
    {"clip", &StageTimes::clip},       {"check", &StageTimes::check},
    {"overlay", &StageTimes::overlay}, {"write", &StageTimes::write},
    {"total", &StageTimes::total},
};

/// The "coordinates" member of every output JSON: the one statement of the pixel convention.
extern const char* const kPixelCoordinates;

/// The summary row of one processed image (image and name left empty, skipped false).
ImageRecord recordOf(const ImageResult& result);

/// The summary row back from resultToJson() text: every field recordOf() fills plus `image` and
/// `frame`; nothing when the text is not such a file or has another schema_version (a file of an
/// older roiclip is made again rather than read in a layout it does not have).
std::optional<ImageRecord> parseRecord(const std::string& jsonText);

/// What a resumed run reuses of an existing NAME.json: its row (skipped, times 0) when the
/// file was made with options key `key` and its status is final (ok or no-roi; failed images,
/// perhaps a file still being copied, and mask mismatches are tried again).
std::optional<ImageRecord> readRecord(const std::filesystem::path& jsonFile,
                                      const std::string& key);

/// One Feature of NAME.json's "clipped" FeatureCollection, read back.
struct ClippedFeature {
  Polygon polygon;        ///< rings without GeoJSON's repeated closing point; no parent links
  int contourIndex = -1;  ///< the source contour (cv::findContours index), -1 when null
  std::vector<std::string> rois;  ///< names of the ROIs the source contour has a part inside
  double area = 0;                ///< px^2
};

/// The "clipped" features of a NAME.json file, in file order; nothing when the file cannot be
/// read or is not a NAME.json of this schema_version.
std::optional<std::vector<ClippedFeature>> readClipped(const std::filesystem::path& jsonFile);

}  // namespace roiclip::batch::detail
