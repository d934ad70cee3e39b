// SPDX-License-Identifier: MIT
// report.html's structure: counts, one table row per image with failures first, the grid of
// overlays, no IoU where nothing was clipped, nothing fetched from elsewhere.
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "detail/report.hpp"
#include "detail/report_html.hpp"

namespace rb = roiclip::batch;

namespace {

rb::ImageRecord record(const std::string& image, rb::Status status) {
  rb::ImageRecord r;
  r.image = image;
  r.name = image.substr(0, image.rfind('.'));
  r.status = status;
  r.failure = status == rb::Status::Ok ? rb::FailureKind::None : rb::FailureKind::NoTags;
  r.width = 800;
  r.height = 600;
  r.tagsFound = 4;
  r.roiArea = 1000;
  r.contoursIn = 16;
  r.contoursOut = 11;
  r.clippedArea = 250.5;
  r.iou = 0.987654;
  r.seconds = 0.5;
  return r;
}

// Four images in input order: ok, failed (unreadable: no overlay), no-roi, ok.
rb::RunSummary fourImages() {
  rb::RunSummary s;
  s.images.push_back(record("a.png", rb::Status::Ok));
  s.images.push_back(record("b.png", rb::Status::Failed));
  s.images.back().width = 0;
  s.images.back().height = 0;
  s.images.back().failure = rb::FailureKind::Unreadable;
  s.images.back().reason = "b.png: not an image <&>";
  s.images.push_back(record("c d&e.png", rb::Status::NoRoi));
  s.images.back().reason = "no tag36h11 tags detected";
  s.images.push_back(record("sub/f.png", rb::Status::Ok));
  s.images.back().seconds = 0;
  s.images.back().skipped = true;
  s.total = 4;
  s.ok = 2;
  s.failed = 1;
  s.noRoi = 1;
  s.skipped = 1;
  return s;
}

std::vector<std::string> all(const std::string& text, const std::string& pattern) {
  std::vector<std::string> out;
  const std::regex re(pattern);
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
       ++it) {
    out.push_back(it->size() > 1 ? (*it)[1].str() : it->str());
  }
  return out;
}

std::string html() {
  rb::BatchOptions options;
  options.inputs = {"images"};
  return rb::detail::reportHtml(fourImages(), options);
}

TEST(BatchReport, OrderIsFailuresFirstThenInputOrder) {
  EXPECT_EQ(rb::detail::reportOrder(fourImages()), (std::vector<std::size_t>{1, 2, 0, 3}));
}

TEST(BatchReport, OneTableRowPerImageFailuresFirst) {
  const std::string page = html();
  ASSERT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  // The table comes before the overlays.
  ASSERT_NE(page.find("<table id=\"summary\""), std::string::npos);
  EXPECT_LT(page.find("<table id=\"summary\""), page.find("<div class=\"grid\""));
  const std::vector<std::string> statuses =
      all(page, "<tr id=\"row-\\d+\"[^>]*data-status=\"(\\d)\"");
  EXPECT_EQ(statuses, (std::vector<std::string>{"0", "2", "3", "3"}));  // failed, no-roi, ok, ok
  const std::vector<std::string> images =
      all(page, "<td class=\"text\"><a href=\"#img-\\d+\">([^<]*)</a>");
  EXPECT_EQ(images, (std::vector<std::string>{"b.png", "c d&amp;e.png", "a.png", "sub/f.png"}));
  // The counts at the top, before the table.
  const std::size_t counts = page.find("id=\"counts\"");
  ASSERT_NE(counts, std::string::npos);
  EXPECT_LT(counts, page.find("<table"));
  EXPECT_NE(page.find("<b>4 of 4 images</b>"), std::string::npos);
  EXPECT_NE(page.find(">2 ok<"), std::string::npos);
  EXPECT_NE(page.find(">1 failed<"), std::string::npos);
  EXPECT_NE(page.find(">1 no-roi<"), std::string::npos);
  // Sortable by status, areas, IoU and time.
  EXPECT_EQ(all(page, "<th[^>]*data-key=\"([a-z-]+)\""),
            (std::vector<std::string>{"status", "roi-area", "area", "iou", "time"}));
  EXPECT_NE(page.find("<script>"), std::string::npos);
}

TEST(BatchReport, NoIouWhereNothingWasClipped) {
  const std::string page = html();
  EXPECT_EQ(all(page, "data-iou=\"([^\"]*)\""),
            (std::vector<std::string>{"", "", "0.987654", "0.987654"}));
  // Shown rounded for the clipped images, a dash for the others.
  EXPECT_EQ(all(page, "<td>(0\\.9877)</td>").size(), 2u);
  // The same words as the overlay caption.
  EXPECT_EQ(all(page, "<td>(11 of 16 inside)</td>").size(), 2u);
  EXPECT_NE(page.find("up to date"), std::string::npos);
}

TEST(BatchReport, GridLinksEveryOverlayAndJson) {
  const std::string page = html();
  EXPECT_EQ(all(page, "<figure id=\"img-\\d+\"").size(), 4u);
  // The failed image has no overlay to show: a placeholder with its reason, escaped.
  EXPECT_EQ(
      all(page, "<img [^>]*src=\"([^\"]*)\"[^>]*>"),
      (std::vector<std::string>{"c%20d%26e.overlay.png", "a.overlay.png", "sub/f.overlay.png"}));
  EXPECT_NE(page.find("no overlay: b.png: not an image &lt;&amp;&gt;"), std::string::npos);
  for (const char* json : {"b.json", "c%20d%26e.json", "a.json", "sub/f.json"}) {
    EXPECT_NE(page.find(std::string("href=\"") + json + "\""), std::string::npos) << json;
  }
  // Full-size overlays behind the thumbnails.
  EXPECT_NE(page.find("<a href=\"a.overlay.png\"><img"), std::string::npos);
}

TEST(BatchReport, WorksOffline) {
  const std::string page = html();
  EXPECT_EQ(page.find("http:"), std::string::npos);
  EXPECT_EQ(page.find("https:"), std::string::npos);
  EXPECT_EQ(page.find("\"//"), std::string::npos);  // no protocol-relative URLs either
  EXPECT_EQ(page.find("<link"), std::string::npos);
  EXPECT_EQ(page.find("<script src"), std::string::npos);
}

TEST(BatchReport, SeveralRoisShowTheirOwnFigures) {
  rb::RunSummary s = fourImages();
  s.images[0].rois = {{"inspection", 600, 7, 200}, {"window", 400, 4, 50.5}};
  const std::string page = rb::detail::reportHtml(s, rb::BatchOptions{});
  EXPECT_NE(page.find("<div class=\"sub\">inspection: 7 inside</div>"), std::string::npos);
  EXPECT_NE(page.find("<div class=\"sub\">window: 50.5</div>"), std::string::npos);
}

}  // namespace
