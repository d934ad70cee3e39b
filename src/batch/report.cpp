// SPDX-License-Identifier: MIT
// The run's summary files: summary.csv and summary.json (report.html: report_html.cpp).
#include "detail/report.hpp"
#include "detail/result_json.hpp"  // kStageTimes

#include <cctype>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

namespace roiclip::batch::detail {

std::string inputList(const BatchOptions& options) {
  std::string out;
  for (const auto& input : options.inputs) out += (out.empty() ? "" : " ") + input.string();
  return out;
}

namespace {

using Json = nlohmann::json;

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

std::string fmt(double v, int precision) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(precision) << v;
  return os.str();
}

}  // namespace

const char* const kSummaryColumns =
    "image,status,failure,reason,skipped,width,height,tags_found,roi_area,contours_in,"
    "contours_out,clipped_area,iou,off_band_mismatches,seconds,roi,tags_rejected,"
    "contours_degenerate";

std::string summaryCsv(const RunSummary& summary) {
  std::ostringstream os;
  os << kSummaryColumns << "\n";
  for (const auto& r : summary.images) {
    // One row per image and ROI: with several ROIs each row has that ROI's figures.
    std::vector<RoiRecord> rows = r.rois;
    if (rows.size() <= 1) {
      rows.assign(1, {rows.empty() ? std::string() : rows[0].name, r.roiArea, r.contoursOut,
                      r.clippedArea});
    }
    for (const RoiRecord& roi : rows) {
      os << csvField(r.image) << ',' << toString(r.status) << ',' << toString(r.failure) << ','
         << csvField(r.reason) << ',' << (r.skipped ? 1 : 0) << ',' << r.width << ',' << r.height
         << ',' << r.tagsFound << ',' << fmt(roi.roiArea, 3) << ',' << r.contoursIn << ','
         << roi.contoursOut << ',' << fmt(roi.clippedArea, 3) << ','
         << (r.iou ? fmt(*r.iou, 6) : std::string()) << ','  // empty: the check did not run
         << r.offBandMismatches << ',' << fmt(r.seconds, 4) << ',' << csvField(roi.name) << ','
         << r.tagsRejected << ',' << r.contoursDegenerate << "\n";
    }
  }
  return os.str();
}

namespace {

Json stageSecondsJson(const StageTimes& s) {
  Json j = Json::object();
  for (const auto& [name, member] : kStageTimes) j[name] = s.*member;
  return j;
}

}  // namespace

std::string summaryJson(const RunSummary& summary, const BatchOptions& options) {
  Json rows = Json::array();
  for (const auto& r : summary.images) {
    Json rois = Json::array();
    for (const RoiRecord& roi : r.rois) {
      rois.push_back({{"name", roi.name},
                      {"roi_area", roi.roiArea},
                      {"contours_out", roi.contoursOut},
                      {"clipped_area", roi.clippedArea}});
    }
    rows.push_back({{"image", r.image},
                    {"name", r.name},
                    {"status", toString(r.status)},
                    {"failure", toString(r.failure)},
                    {"reason", r.reason},
                    {"skipped", r.skipped},
                    {"width", r.width},
                    {"height", r.height},
                    {"tags_found", r.tagsFound},
                    {"tags_rejected", r.tagsRejected},
                    {"rois", std::move(rois)},
                    {"roi_area", r.roiArea},
                    {"contours_in", r.contoursIn},
                    {"contours_degenerate", r.contoursDegenerate},
                    {"contours_out", r.contoursOut},
                    {"clipped_area", r.clippedArea},
                    {"iou", r.iou ? Json(*r.iou) : Json(nullptr)},
                    {"off_band_mismatches", r.offBandMismatches},
                    {"seconds", r.seconds},
                    {"stage_seconds", stageSecondsJson(r.stageSeconds)}});
  }
  const RunOptions& p = options.process;
  Json j = {{"schema_version", kSchemaVersion},
            {"roiclip_version", roiclipVersion()},
            {"input", inputList(options)},
            {"output", options.output.string()},
            {"options",
             {{"roi", p.rois},
              {"keep_tags", p.keepTags},
              {"tag_margin", p.tagMargin},
              {"board", p.boardFile},
              {"family", p.detector.family},
              {"method", toString(p.contours.method)},
              {"polarity", toString(p.contours.polarity)},
              {"approx_epsilon", p.contours.approxEpsilon},
              {"min_area", p.contours.minArea},
              {"fill_rule", toString(p.subjectFillRule)},
              {"roi_fill_rule", toString(p.roiFillRule)}}},
            {"total", summary.total},
            {"processed", summary.images.size()},
            {"ok", summary.ok},
            {"no_roi", summary.noRoi},
            {"failed", summary.failed},
            {"mask_mismatch", summary.mismatched},
            {"skipped", summary.skipped},
            {"interrupted", summary.interrupted},
            {"seconds", summary.seconds},
            {"coco", options.coco.empty() ? Json(nullptr) : Json(options.coco.string())},
            {"images", std::move(rows)}};
  return j.dump(1) + "\n";
}

}  // namespace roiclip::batch::detail
