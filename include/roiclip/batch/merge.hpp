// SPDX-License-Identifier: MIT
// roiclip::batch: `roiclip merge`, several run output folders (shards) into one, as a library
// function.
//
//   roiclip::batch::MergeOptions m;
//   m.output = "out";
//   m.shards = {"out-1", "out-2"};   // each written by roiclip::batch::run() (`roiclip run`)
//   const roiclip::batch::RunSummary all = roiclip::batch::merge(m);
//
// The merged folder is a run output folder of its own: every shard's NAME.json,
// NAME.overlay.png and NAME.mask.png are copied into it under the same NAME, and its
// summary.csv, summary.json and report.html list every image, so they are the files one run over
// all the shards' images would have written (only the times differ). It does not depend on the
// shards afterwards (they can be moved or deleted), a later `roiclip run` into it skips the
// images that are up to date, and merged folders can be merged again.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <roiclip/batch/run.hpp>
#include <roiclip/error.hpp>

namespace roiclip::batch {

/// Options of merge().
struct MergeOptions {
  std::filesystem::path output;               ///< merged folder (created if missing)
  std::vector<std::filesystem::path> shards;  ///< run output folders, each with its summary.json
  bool writeReport = true;                    ///< write report.html
};

/// merge() refused shards whose runs had different options: `key` of summary.json's "options"
/// (e.g. "min_area") is `firstValue` in `firstShard` and `otherValue` in `otherShard` (values as
/// JSON text; "null" when the key is missing).
class OptionsMismatchError : public InvalidInputError {
 public:
  /// The message is formatted from the fields (every accessor below returns one of them).
  OptionsMismatchError(std::string key, std::filesystem::path firstShard, std::string firstValue,
                       std::filesystem::path otherShard, std::string otherValue);
  /// The option that differs, as named in summary.json ("min_area").
  [[nodiscard]] const std::string& key() const noexcept { return key_; }
  /// The first shard folder given.
  [[nodiscard]] const std::filesystem::path& firstShard() const noexcept { return firstShard_; }
  /// The shard folder whose value differs from the first one's.
  [[nodiscard]] const std::filesystem::path& otherShard() const noexcept { return otherShard_; }
  /// The option's value in firstShard(), as JSON text.
  [[nodiscard]] const std::string& firstValue() const noexcept { return firstValue_; }
  /// The option's value in otherShard(), as JSON text.
  [[nodiscard]] const std::string& otherValue() const noexcept { return otherValue_; }

 private:
  std::string key_;
  std::filesystem::path firstShard_, otherShard_;
  std::string firstValue_, otherValue_;
};

/// Merge the shards into options.output: check that every shard's summary.json has the same
/// "options" (key by key), copy each listed image's files (written atomically; NAME.json last),
/// and write summary.csv, summary.json (the shards' options; "input" is the shards' input folder
/// when they share one, else empty; "merged_from" lists the shards; "total" and "seconds" are the
/// shards' sums) and report.html. Rows are in image path order, as one run lists them.
/// @return the merged rows and totals (RunSummary::interrupted when any shard was).
/// @throws OptionsMismatchError for differing options; InvalidInputError for no shards, a shard
///         without a readable summary.json, a listed NAME.json missing or unreadable, the same
///         NAME in two shards (an image run twice), or options.output being one of the shards;
///         Error if the output folder cannot be created or written.
RunSummary merge(const MergeOptions& options);

}  // namespace roiclip::batch
