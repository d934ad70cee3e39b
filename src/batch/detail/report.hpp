// SPDX-License-Identifier: MIT
// roiclip::batch internal: the run's summary files (summary.csv, summary.json, report.html).
#pragma once

#include <string>

#include <roiclip/batch/run.hpp>

namespace roiclip::batch::detail {

/// BatchOptions::inputs as one line (separated by spaces).
std::string inputList(const BatchOptions& options);

/// CSV header of summary.csv.
extern const char* const kSummaryColumns;

/// summary.csv text for `summary`.
std::string summaryCsv(const RunSummary& summary);
/// summary.json text for `summary`.
std::string summaryJson(const RunSummary& summary, const BatchOptions& options);
/// report.html text: every overlay (linked relative to the output folder) with its figures.
std::string reportHtml(const RunSummary& summary, const BatchOptions& options);

}  // namespace roiclip::batch::detail
