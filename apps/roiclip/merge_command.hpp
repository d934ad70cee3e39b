// SPDX-License-Identifier: MIT
// `roiclip merge OUT DIR...`: shard output folders of `roiclip run` into one
// (roiclip::batch::merge).
#pragma once

#include <iostream>

#include <CLI/CLI.hpp>

namespace roiclip::app {

/// The `merge` subcommand of `app`. It does its work from its CLI11 callback, when parsing
/// reaches it, and prints one line of counts to `out`. Errors leave app.parse() as roiclip
/// exceptions, for main() to map to exit codes like every command's: InvalidInputError (options
/// differ between shards, a shard without summary.json, an image in two shards) -> 2, Error
/// (output folder not writable) -> 3.
class MergeCommand {
 public:
  explicit MergeCommand(CLI::App& app, std::ostream& out = std::cout);
  MergeCommand(const MergeCommand&) = delete;  // the callback holds `this`
  MergeCommand& operator=(const MergeCommand&) = delete;
  [[nodiscard]] CLI::App* subcommand() const { return cmd_; }
  /// After parsing ran the merge: kExitOk when every merged image is ok, as `run` would have
  /// said over all the images, else kExitImagesFailed (OUT is written all the same).
  [[nodiscard]] int exitCode() const { return exitCode_; }

 private:
  CLI::App* cmd_ = nullptr;
  int exitCode_ = 0;
};

}  // namespace roiclip::app
