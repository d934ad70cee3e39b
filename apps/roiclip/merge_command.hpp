// SPDX-License-Identifier: MIT
// `roiclip merge OUT DIR...`: shard output folders of `roiclip run` into one
// (roiclip::batch::merge).
#pragma once

#include <iostream>

#include <CLI/CLI.hpp>

namespace roiclip::app {

/// Add the `merge` subcommand to `app`. It does its work from its CLI11 callback, when parsing
/// reaches it, and prints one line of counts to `out`. Errors leave app.parse() as roiclip
/// exceptions, for main() to map to exit codes like every command's: InvalidInputError (options
/// differ between shards, a shard without summary.json, an image in two shards) -> 2, Error
/// (output folder not writable) -> 3.
/// @return the subcommand.
CLI::App* addMergeCommand(CLI::App& app, std::ostream& out = std::cout);

}  // namespace roiclip::app
