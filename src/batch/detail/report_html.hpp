// SPDX-License-Identifier: MIT
// roiclip::batch internal: report.html, the page a person looks through after a run or a merge.
// detail/report.hpp declares the run's reportHtml(summary, options); this is the general form.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <roiclip/batch/run.hpp>

namespace roiclip::batch::detail {

/// What the page says above its table.
struct ReportPage {
  std::string title;  ///< "roiclip run", "roiclip merge"
  /// Label and value pairs shown in a line under the title ("input", "images"), in this order.
  std::vector<std::pair<std::string, std::string>> facts;
  bool overlays = true;  ///< NAME.overlay.png files exist (false after `--no-overlay`)
};

/// report.html for `summary`: the counts, one table row per image (failures first, then input
/// order; sortable by status, areas, IoU and time with a few lines of inline JavaScript), and a
/// grid of the overlays, each linked to its full-size NAME.overlay.png and its NAME.json. Every
/// link is relative to the folder report.html is written into (ImageRecord::name); no external
/// assets, so the page works offline. Images the pipeline did not clip (no-roi, failed) show no
/// IoU, contours or areas. report.html#sort=KEY opens sorted by KEY (status, roi-area, area,
/// iou, time) ascending, #sort=-KEY descending.
std::string reportHtml(const RunSummary& summary, const ReportPage& page);

/// The order report.html lists the images in: indices into summary.images, failed first, then
/// mask-mismatch, no-roi and ok, each group in input order.
std::vector<std::size_t> reportOrder(const RunSummary& summary);

}  // namespace roiclip::batch::detail
