// roiclip::batch internal: NAME.json, written for every image and read back when a run resumes.
// Both directions spell Status and FailureKind with the tables of options.hpp.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <roiclip/batch/process.hpp>
#include <roiclip/batch/run.hpp>

namespace roiclip::batch::detail {

/// NAME.json text for one image: status, reason, size, tags, ROI, every clipped polygon with
/// holes (image coordinates), areas, mask-check figures, stage times. `imageName` is stored
/// as "image", `optionsKey` (when not empty) as "options" (see optionsKey()), `frame` (a
/// video's frame index, when >= 0) as "frame".
std::string resultToJson(const ImageResult& result, const std::string& imageName,
                         const std::string& optionsKey = {}, int frame = -1);

/// The summary row of one processed image (image and name left empty, skipped false).
ImageRecord recordOf(const ImageResult& result);

/// The summary row back from resultToJson() text: every field recordOf() fills (seconds from
/// the stage times' total) plus `image` and `frame`; nothing when the text is not such a file.
std::optional<ImageRecord> parseRecord(const std::string& jsonText);

/// What a resumed run reuses of an existing NAME.json: its row (skipped, seconds 0) when the
/// file was made with options key `key` and its status is final (ok or no-roi; failed images,
/// perhaps a file still being copied, and mask mismatches are tried again).
std::optional<ImageRecord> readRecord(const std::filesystem::path& jsonFile,
                                      const std::string& key);

}  // namespace roiclip::batch::detail
