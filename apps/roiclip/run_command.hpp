// SPDX-License-Identifier: MIT
// `roiclip run`: its options, bound to the fields of roiclip::batch::BatchOptions (so the
// library's defaults are the command's, and --help shows them), and its execution. The work is
// roiclip::batch.
#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include <roiclip/batch/run.hpp>

namespace roiclip::app {

class RunCommand {
 public:
  /// Adds `run` to `app` with its options bound to this object (which must outlive the parse).
  /// `run --config FILE` hands FILE to app's config option: CLI11 reads config files on the main
  /// app only; ConfigJson reads it into run's options, which the command line overrides.
  explicit RunCommand(CLI::App& app);
  RunCommand(const RunCommand&) = delete;
  RunCommand& operator=(const RunCommand&) = delete;

  [[nodiscard]] CLI::App* subcommand() const { return cmd_; }

  /// The options as parsed: the library's defaults where none was given.
  [[nodiscard]] const batch::BatchOptions& options() const { return options_; }

  /// The exit code for a parse error that is bad input rather than bad usage: an option value
  /// the library refuses, a config file that cannot be read or says something wrong. Prints one
  /// line naming the option (and the file). Nothing for other errors (usage errors).
  [[nodiscard]] std::optional<int> badInputExit(const CLI::ParseError& error) const;

  /// Check everything before anything is created (bad options, an input folder without images:
  /// exit 2, no output folder), run, print the summary; returns the exit code (see --help).
  [[nodiscard]] int execute() const;

 private:
  CLI::App* cmd_ = nullptr;
  CLI::Option* config_ = nullptr;  // the main app's config option
  batch::BatchOptions options_;
  bool quiet_ = false;
};

}  // namespace roiclip::app
