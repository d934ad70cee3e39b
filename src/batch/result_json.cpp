// NAME.json: one image's result as JSON, and its summary row read back for resuming.
#include "detail/result_json.hpp"

#include <fstream>

#include <nlohmann/json.hpp>

namespace roiclip::batch::detail {

namespace {

using Json = nlohmann::json;

Json pathJson(const Path& path) {
  Json a = Json::array();
  for (const Point& p : path) a.push_back({p.x, p.y});
  return a;
}

Json pathsJson(const Paths& paths) {
  Json a = Json::array();
  for (const Path& p : paths) a.push_back(pathJson(p));
  return a;
}

Json polygonSetJson(const PolygonSet& set) {
  Json a = Json::array();
  for (const Polygon& poly : set.polygons) {
    Json holes = Json::array();
    for (const Path& h : poly.holes) holes.push_back(pathJson(h));
    a.push_back({{"outer", pathJson(poly.outer)},
                 {"holes", std::move(holes)},
                 {"parent", poly.parent},
                 {"parent_hole", poly.parentHole}});
  }
  return a;
}

Json comparisonJson(const opencv::MaskComparison& c) {
  return {{"iou", c.iou},
          {"only_expected", c.onlyExpected},
          {"only_actual", c.onlyActual},
          {"both", c.both},
          {"band_px", c.boundaryBand},
          {"band_pixels", c.bandPixels},
          {"off_band_only_expected", c.offBandOnlyExpected},
          {"off_band_only_actual", c.offBandOnlyActual},
          {"off_band_iou", c.offBandIou},
          {"agrees_off_band", c.agreesOffBand()}};
}

Json tagsJson(const std::vector<apriltag::Detection>& tags) {
  Json out = Json::array();
  for (const auto& t : tags) {
    Json corners = Json::array();
    for (const auto& c : t.corners) corners.push_back({c.x, c.y});
    out.push_back({{"id", t.id},
                   {"family", t.family},
                   {"hamming", t.hamming},
                   {"decision_margin", t.decisionMargin},
                   {"centre", {t.centre.x, t.centre.y}},
                   {"corners", std::move(corners)}});
  }
  return out;
}

Json contoursJson(const std::vector<ContourResult>& contours) {
  Json out = Json::array();
  for (const auto& c : contours) {
    if (c.clipped.empty()) continue;  // only what lies inside the ROI; counts say the rest
    out.push_back({{"contour_index", c.contourIndex},
                   {"holes", static_cast<int>(c.input.size()) - 1},
                   {"input_area", c.inputArea},
                   {"clipped_area", c.clippedArea},
                   {"polygons", polygonSetJson(c.clipped)}});
  }
  return out;
}

Json roisJson(const std::vector<RoiRegion>& rois) {
  Json out = Json::array();
  for (const RoiRegion& roi : rois) {
    out.push_back({{"name", roi.name},
                   {"paths", pathsJson(roi.paths)},
                   {"region", pathsJson(roi.region)},
                   {"area", roi.area},
                   {"contours_out", roi.contoursOut},
                   {"clipped_area", roi.clippedArea}});
  }
  return out;
}

std::optional<ImageRecord> recordFromJson(const Json& j) {
  if (j.is_discarded() || !j.is_object()) return std::nullopt;
  try {
    const std::optional<Status> status = parseStatus(j.at("status").get<std::string>());
    const std::optional<FailureKind> failure = parseFailureKind(j.at("failure").get<std::string>());
    if (!status || !failure) return std::nullopt;
    ImageRecord r;
    r.image = j.at("image").get<std::string>();
    r.frame = j.value("frame", -1);
    r.status = *status;
    r.failure = *failure;
    r.reason = j.at("reason").get<std::string>();
    r.width = j.at("width").get<int>();
    r.height = j.at("height").get<int>();
    r.tagsFound = static_cast<int>(j.at("tags").size());
    r.tagsRejected = static_cast<int>(j.at("rejected_tags").size());
    for (const Json& roi : j.at("rois")) {
      r.rois.push_back({roi.at("name").get<std::string>(), roi.at("area").get<double>(),
                        roi.at("contours_out").get<int>(), roi.at("clipped_area").get<double>()});
    }
    r.roiArea = j.at("roi").at("area").get<double>();
    r.contoursIn = j.at("contours_in").get<int>();
    r.contoursOut = j.at("contours_out").get<int>();
    r.clippedArea = j.at("clipped_area").get<double>();
    r.iou = j.at("mask_check").at("exact").at("iou").get<double>();
    r.offBandMismatches = j.at("mask_check").at("off_band_mismatches").get<std::int64_t>();
    r.seconds = j.at("seconds").at("total").get<double>();
    return r;
  } catch (const Json::exception&) {
    return std::nullopt;
  }
}

}  // namespace

std::string resultToJson(const ImageResult& r, const std::string& imageName,
                         const std::string& optionsKey, int frame) {
  Json j;
  j["image"] = imageName;
  if (frame >= 0) j["frame"] = frame;
  if (!optionsKey.empty()) j["options"] = optionsKey;
  j["status"] = toString(r.status);
  j["failure"] = toString(r.failure);
  j["reason"] = r.reason;
  j["width"] = r.width;
  j["height"] = r.height;
  j["tags"] = tagsJson(r.tags);
  j["rejected_tags"] = tagsJson(r.rejectedTags);
  j["quad_decimate"] = r.quadDecimate;
  if (r.missingTags) {
    j["missing_tags"] = {{"needed", r.missingTags->needed},
                         {"seen", r.missingTags->seen},
                         {"missing", r.missingTags->missing},
                         {"duplicated", r.missingTags->duplicated}};
  }
  j["rois"] = roisJson(r.rois);
  j["excluded_tags"] = pathsJson(r.excludedTags);
  j["roi"] = {{"paths", pathsJson(r.roi)}, {"area", r.roiArea}};
  j["contours_in"] = r.contoursIn;
  j["contours_out"] = r.contoursOut;
  j["holes_in"] = r.holesIn;
  j["clipped_area"] = r.clippedArea;
  j["contour_clipped_area_sum"] = r.contourClippedAreaSum;
  j["clipped"] = polygonSetJson(r.clipped);
  j["contours"] = contoursJson(r.contours);
  if (!r.edges.empty() || r.edgesIn > 0) {
    j["edges"] = {{"traced", r.edgesIn},
                  {"clipped", r.edges.size()},
                  {"length", r.edgeLength},
                  {"polylines", pathsJson(r.edges)}};
  }
  Json check = {{"exact", comparisonJson(r.vectorVsRaster)},
                {"off_band_mismatches", r.offBandMismatches()}};
  if (r.vectorVsOpenCv) check["opencv"] = comparisonJson(*r.vectorVsOpenCv);
  j["mask_check"] = std::move(check);
  j["seconds"] = {{"detect", r.seconds.detect},     {"roi", r.seconds.roi},
                  {"contours", r.seconds.contours}, {"clip", r.seconds.clip},
                  {"check", r.seconds.check},       {"total", r.seconds.total}};
  return j.dump() + "\n";  // compact: polygons with thousands of vertices
}

ImageRecord recordOf(const ImageResult& r) {
  ImageRecord rec;
  rec.status = r.status;
  rec.failure = r.failure;
  rec.reason = r.reason;
  rec.width = r.width;
  rec.height = r.height;
  rec.tagsFound = static_cast<int>(r.tags.size());
  rec.tagsRejected = static_cast<int>(r.rejectedTags.size());
  for (const RoiRegion& roi : r.rois) {
    rec.rois.push_back({roi.name, roi.area, roi.contoursOut, roi.clippedArea});
  }
  rec.roiArea = r.roiArea;
  rec.contoursIn = r.contoursIn;
  rec.contoursOut = r.contoursOut;
  rec.clippedArea = r.clippedArea;
  rec.iou = r.vectorVsRaster.iou;
  rec.offBandMismatches = r.offBandMismatches();
  rec.seconds = r.seconds.total;
  return rec;
}

std::optional<ImageRecord> parseRecord(const std::string& jsonText) {
  return recordFromJson(Json::parse(jsonText, nullptr, false));
}

std::optional<ImageRecord> readRecord(const std::filesystem::path& jsonFile,
                                      const std::string& key) {
  std::ifstream in(jsonFile, std::ios::binary);
  if (!in) return std::nullopt;
  const Json j = Json::parse(in, nullptr, false);
  if (!j.is_object() || j.value("options", std::string()) != key) return std::nullopt;
  std::optional<ImageRecord> r = recordFromJson(j);
  if (!r || (r->status != Status::Ok && r->status != Status::NoRoi)) return std::nullopt;
  r->skipped = true;
  r->seconds = 0;
  return r;
}

}  // namespace roiclip::batch::detail
