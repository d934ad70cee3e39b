// SPDX-License-Identifier: MIT
// NAME.json: one image's result as JSON (layout in docs/outputs.md), and what a run reads back
// of it: the summary row for resuming, the clipped polygons for the COCO file.
#include "detail/result_json.hpp"

#include <fstream>
#include <map>
#include <utility>

#include <nlohmann/json.hpp>

#ifndef ROICLIP_VERSION
#error "ROICLIP_VERSION must be defined (src/batch/CMakeLists.txt)"
#endif

namespace roiclip::batch {

const char* roiclipVersion() { return ROICLIP_VERSION; }

namespace detail {

const char* const kPixelCoordinates =
    "pixel, x right, y down, origin at the centre of the top-left pixel";

namespace {

using Json = nlohmann::ordered_json;  // members in the order written: schema_version first

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

// A GeoJSON linear ring: closed by repeating its first point (RFC 7946, 3.1.6).
Json ringJson(const Path& ring) {
  Json a = pathJson(ring);
  if (!ring.empty()) a.push_back({ring.front().x, ring.front().y});
  return a;
}

Json indexOrNull(int index) { return index < 0 ? Json(nullptr) : Json(index); }

// The contour each polygon of ImageResult::clipped comes from. The polygons of the one clip of
// all contours are those of the per-contour clips (contours do not overlap), so a vertex of a
// polygon's outer ring is a vertex of its contour's clipped outer ring, bit for bit: both clips
// compute it from the same edges on the same grid. -1 where no vertex is found (contours that
// touch, whose parts the one clip may join).
std::vector<const ContourResult*> sourceContours(const ImageResult& r) {
  std::map<std::pair<double, double>, const ContourResult*> owner;
  for (const ContourResult& c : r.contours) {
    for (const Polygon& poly : c.clipped.polygons) {
      for (const Point& p : poly.outer) owner.emplace(std::make_pair(p.x, p.y), &c);
    }
  }
  std::vector<const ContourResult*> out;
  for (const Polygon& poly : r.clipped.polygons) {
    const ContourResult* found = nullptr;
    for (const Point& p : poly.outer) {
      const auto it = owner.find({p.x, p.y});
      if (it != owner.end()) {
        found = it->second;
        break;
      }
    }
    out.push_back(found);
  }
  return out;
}

Json roiNames(const ContourResult* c, const std::vector<RoiRegion>& rois) {
  Json names = Json::array();
  if (c) {
    for (int i : c->rois) names.push_back(rois[static_cast<std::size_t>(i)].name);
  }
  return names;
}

// ImageResult::clipped as a GeoJSON FeatureCollection, one Polygon Feature per polygon.
Json clippedJson(const ImageResult& r, const std::vector<const ContourResult*>& sources) {
  Json features = Json::array();
  for (std::size_t i = 0; i < r.clipped.polygons.size(); ++i) {
    const Polygon& poly = r.clipped.polygons[i];
    Json rings = Json::array({ringJson(poly.outer)});
    double area = -signedArea(poly.outer);
    for (const Path& h : poly.holes) {
      rings.push_back(ringJson(h));
      area -= signedArea(h);
    }
    features.push_back(
        {{"type", "Feature"},
         {"geometry", {{"type", "Polygon"}, {"coordinates", std::move(rings)}}},
         {"properties",
          {{"contour_index", sources[i] ? Json(sources[i]->contourIndex) : Json(nullptr)},
           {"rois", roiNames(sources[i], r.rois)},
           {"area", area},
           {"holes", poly.holes.size()},
           {"parent", indexOrNull(poly.parent)},
           {"parent_hole", indexOrNull(poly.parentHole)}}}});
  }
  return {{"type", "FeatureCollection"}, {"features", std::move(features)}};
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

// Per contour with a part inside the region: its figures and the features it gave.
Json contoursJson(const ImageResult& r, const std::vector<const ContourResult*>& sources) {
  Json out = Json::array();
  for (const auto& c : r.contours) {
    if (c.clipped.empty()) continue;  // only what lies inside the ROI; counts say the rest
    Json features = Json::array();
    for (std::size_t i = 0; i < sources.size(); ++i) {
      if (sources[i] == &c) features.push_back(i);
    }
    out.push_back({{"contour_index", c.contourIndex},
                   {"holes", static_cast<int>(c.input.size()) - 1},
                   {"input_area", c.inputArea},
                   {"clipped_area", c.clippedArea},
                   {"rois", roiNames(&c, r.rois)},
                   {"features", std::move(features)}});
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

// The mask check runs as the last stage and decides between these two.
bool checked(Status status) { return status == Status::Ok || status == Status::MaskMismatch; }

Json stageTimesJson(const StageTimes& s) {
  Json j = Json::object();
  for (const auto& [name, member] : kStageTimes) j[name] = s.*member;
  return j;
}

StageTimes stageTimesFrom(const Json& j) {
  StageTimes s;
  for (const auto& [name, member] : kStageTimes) s.*member = j.at(name).get<double>();
  return s;
}

bool isCurrentResult(const Json& j) {
  if (!j.is_object()) return false;
  const auto version = j.find("schema_version");
  return version != j.end() && version->is_number_integer() && *version == kSchemaVersion;
}

std::optional<ImageRecord> recordFromJson(const Json& j) {
  if (!isCurrentResult(j)) return std::nullopt;
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
    r.contoursDegenerate = j.value("contours_degenerate", 0);  // absent before 0.3
    r.contoursOut = j.at("contours_out").get<int>();
    r.clippedArea = j.at("clipped_area").get<double>();
    const Json& check = j.at("mask_check");
    if (!check.is_null()) {
      r.iou = check.at("exact").at("iou").get<double>();
      r.offBandMismatches = check.at("off_band_mismatches").get<std::int64_t>();
    }
    r.stageSeconds = stageTimesFrom(j.at("seconds"));
    r.seconds = r.stageSeconds.total;
    return r;
  } catch (const Json::exception&) {
    return std::nullopt;
  }
}

Json readJson(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return Json(Json::value_t::discarded);
  return Json::parse(in, nullptr, false);
}

Path ringFrom(const Json& ring) {
  Path out;
  for (const Json& p : ring) out.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();
  return out;
}

}  // namespace

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
  rec.contoursDegenerate = r.contoursDegenerate;
  rec.contoursOut = r.contoursOut;
  rec.clippedArea = r.clippedArea;
  if (checked(r.status)) {
    rec.iou = r.vectorVsRaster.iou;
    rec.offBandMismatches = r.offBandMismatches();
  }
  rec.stageSeconds = r.seconds;
  rec.seconds = r.seconds.total;
  return rec;
}

std::optional<ImageRecord> parseRecord(const std::string& jsonText) {
  return recordFromJson(Json::parse(jsonText, nullptr, false));
}

std::optional<ImageRecord> readRecord(const std::filesystem::path& jsonFile,
                                      const std::string& key) {
  const Json j = readJson(jsonFile);
  if (!j.is_object() || j.value("options", std::string()) != key) return std::nullopt;
  std::optional<ImageRecord> r = recordFromJson(j);
  if (!r || (r->status != Status::Ok && r->status != Status::NoRoi)) return std::nullopt;
  r->skipped = true;
  r->seconds = 0;
  r->stageSeconds = {};
  return r;
}

std::optional<std::vector<ClippedFeature>> readClipped(const std::filesystem::path& jsonFile) {
  const Json j = readJson(jsonFile);
  if (!isCurrentResult(j)) return std::nullopt;
  try {
    std::vector<ClippedFeature> out;
    for (const Json& f : j.at("clipped").at("features")) {
      ClippedFeature c;
      const Json& rings = f.at("geometry").at("coordinates");
      c.polygon.outer = ringFrom(rings.at(0));
      for (std::size_t i = 1; i < rings.size(); ++i) c.polygon.holes.push_back(ringFrom(rings[i]));
      const Json& p = f.at("properties");
      c.contourIndex = p.at("contour_index").is_null() ? -1 : p.at("contour_index").get<int>();
      c.rois = p.at("rois").get<std::vector<std::string>>();
      c.area = p.at("area").get<double>();
      out.push_back(std::move(c));
    }
    return out;
  } catch (const Json::exception&) {
    return std::nullopt;
  }
}

}  // namespace detail

std::string resultToJson(const ImageResult& r, const std::string& imageName,
                         const std::string& optionsKey, int frame) {
  using detail::Json;
  const std::vector<const ContourResult*> sources = detail::sourceContours(r);
  Json j;
  j["schema_version"] = kSchemaVersion;
  j["roiclip_version"] = roiclipVersion();
  j["coordinates"] = detail::kPixelCoordinates;
  j["image"] = imageName;
  if (frame >= 0) j["frame"] = frame;
  if (!optionsKey.empty()) j["options"] = optionsKey;
  j["status"] = toString(r.status);
  j["failure"] = toString(r.failure);
  j["reason"] = r.reason;
  j["width"] = r.width;
  j["height"] = r.height;
  j["tags"] = detail::tagsJson(r.tags);
  j["rejected_tags"] = detail::tagsJson(r.rejectedTags);
  j["quad_decimate"] = r.quadDecimate;
  j["detect_passes"] = r.detectPasses;
  if (r.missingTags) {
    j["missing_tags"] = {{"needed", r.missingTags->needed},
                         {"seen", r.missingTags->seen},
                         {"missing", r.missingTags->missing},
                         {"duplicated", r.missingTags->duplicated}};
  }
  j["rois"] = detail::roisJson(r.rois);
  j["excluded_tags"] = detail::pathsJson(r.excludedTags);
  j["roi"] = {{"paths", detail::pathsJson(r.roi)}, {"area", r.roiArea}};
  j["contours_in"] = r.contoursIn;
  j["contours_degenerate"] = r.contoursDegenerate;
  j["contours_out"] = r.contoursOut;
  j["holes_in"] = r.holesIn;
  j["clipped_area"] = r.clippedArea;
  j["contour_clipped_area_sum"] = r.contourClippedAreaSum;
  j["clipped"] = detail::clippedJson(r, sources);
  j["contours"] = detail::contoursJson(r, sources);
  if (!r.edges.empty() || r.edgesIn > 0) {
    j["edges"] = {{"traced", r.edgesIn},
                  {"clipped", r.edges.size()},
                  {"length", r.edgeLength},
                  {"polylines", detail::pathsJson(r.edges)}};
  }
  if (detail::checked(r.status)) {
    Json check = {{"exact", detail::comparisonJson(r.vectorVsRaster)},
                  {"off_band_mismatches", r.offBandMismatches()}};
    if (r.vectorVsOpenCv) check["opencv"] = detail::comparisonJson(*r.vectorVsOpenCv);
    j["mask_check"] = std::move(check);
  } else {
    j["mask_check"] = nullptr;  // the check did not run
  }
  j["seconds"] = detail::stageTimesJson(r.seconds);
  return j.dump() + "\n";  // compact: polygons with thousands of vertices
}

}  // namespace roiclip::batch
