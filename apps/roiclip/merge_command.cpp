// SPDX-License-Identifier: MIT
// `roiclip merge`: argument parsing and the line of counts. The work is roiclip::batch::merge.
#include "merge_command.hpp"

#include <memory>
#include <string>
#include <vector>

#include <roiclip/batch/merge.hpp>

#include "exit_codes.hpp"

namespace roiclip::app {

namespace {

const char* const kMergeHelp = R"(
Combines the output folders of several `roiclip run`s (shards, e.g. one per machine) into OUT,
as if one run had processed all their images: every shard's NAME.json, NAME.overlay.png and
NAME.mask.png is copied into OUT under the same NAME, and OUT gets summary.csv, summary.json
and report.html over all the images (in image path order). OUT does not depend on the shards
afterwards, a later `roiclip run` into OUT skips the images that are up to date, and merged
folders can be merged again. The shards must have been run with the same options (the
"options" of their summary.json, key by key), and no image may be in two shards.

Examples:
  roiclip merge out out-1 out-2 out-3
  roiclip merge all shards/*

Exit codes:
  0  OUT written, every image in it ok
  1  command-line usage error
  2  invalid input: a shard without a readable summary.json, options that differ between
     shards (the message names the option), an image in two shards, OUT one of the shards
  3  OUT cannot be created or written
  4  internal error (a bug in roiclip: please report the input)
  5  OUT written, but at least one image in it failed, had no ROI or failed its mask
     check, or a shard was interrupted (see summary.csv), as `roiclip run` over all the
     images would have said
)";

}  // namespace

MergeCommand::MergeCommand(CLI::App& app, std::ostream& out) {
  auto options = std::make_shared<batch::MergeOptions>();
  auto noReport = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("merge", "combine the output folders of several runs");
  cmd_ = cmd;
  cmd->footer(kMergeHelp);
  cmd->add_option("OUT", options->output, "merged output folder (created if missing)")->required();
  cmd->add_option("DIR", options->shards, "output folders of `roiclip run` (shards)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_flag("--no-report", *noReport, "do not write report.html");
  cmd->callback([this, options, noReport, &out] {
    options->writeReport = !*noReport;
    const batch::RunSummary s = batch::merge(*options);
    out << "roiclip merge: " << s.images.size() << " of " << s.total << " images from "
        << options->shards.size() << " shards: " << s.ok << " ok, " << s.noRoi << " no-roi, "
        << s.failed << " failed, " << s.mismatched << " mask-mismatch"
        << (s.interrupted ? " (a shard was interrupted)" : "") << "; summary in "
        << (options->output / "summary.csv").string() << "\n";
    exitCode_ = s.allOk() ? kExitOk : kExitImagesFailed;
  });
}

}  // namespace roiclip::app
