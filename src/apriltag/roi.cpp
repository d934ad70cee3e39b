// SPDX-License-Identifier: MIT
// ROI builders from AprilTag detections: polygons through tags, hulls of tags, polygons in a tag's
// frame, and buildRoi() dispatching a parsed spec.
#include <roiclip/apriltag/roi.hpp>

#include <algorithm>
#include <set>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "tag_lookup.hpp"

namespace roiclip::apriltag {

using detail::anchorPoint;
using detail::idList;
using detail::Lookup;

std::string MissingTags::describe() const {
  std::ostringstream out;
  if (needed.empty()) {
    out << "needed at least " << minimumNeeded << " detected tag, seen " << idList(seen);
    return out.str();
  }
  out << "needed ";
  if (minimumNeeded < static_cast<int>(needed.size()))
    out << "at least " << minimumNeeded << " of ";
  out << "tags " << idList(needed) << ", seen " << idList(seen);
  if (!missing.empty()) out << ": missing " << idList(missing);
  if (!duplicated.empty())
    out << (missing.empty() ? ": " : "; ") << "seen more than once " << idList(duplicated);
  return out.str();
}

MissingTagsError::MissingTagsError(MissingTags info)
    : Error("AprilTag ROI unavailable: " + info.describe()), info_(std::move(info)) {}

RoiResult polygonThroughTags(const std::vector<Detection>& detections, const std::vector<int>& ids,
                             TagAnchor anchor) {
  if (ids.size() < 3) {
    throw InvalidInputError("tag polygon: needs at least 3 tag ids, got " +
                            std::to_string(ids.size()));
  }
  if (std::set<int>(ids.begin(), ids.end()).size() != ids.size()) {
    throw InvalidInputError("tag polygon: an id is listed twice in " + idList(ids));
  }
  const Lookup lookup(detections, ids, static_cast<int>(ids.size()));
  if (!lookup.ok()) return lookup.status;
  Path path;
  for (int id : ids) path.push_back(anchorPoint(lookup.get(id), anchor));
  return Paths{std::move(path)};
}

RoiResult polygonThroughTags(const std::vector<Detection>& detections, const std::vector<int>& ids,
                             const std::vector<TagAnchor>& anchors) {
  if (anchors.size() != ids.size()) {
    throw InvalidInputError("tag polygon: " + std::to_string(anchors.size()) + " anchors for " +
                            std::to_string(ids.size()) + " tag ids");
  }
  const RoiResult through = polygonThroughTags(detections, ids, TagAnchor::Centre);
  if (!through) return through;
  const Lookup lookup(detections, ids, static_cast<int>(ids.size()));
  Path path;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    path.push_back(anchorPoint(lookup.get(ids[i]), anchors[i]));
  }
  return Paths{std::move(path)};
}

RoiResult convexHullOfTags(const std::vector<Detection>& detections, const std::vector<int>& ids) {
  std::vector<cv::Point2d> points;
  if (ids.empty()) {
    if (detections.empty()) {
      MissingTags none;
      none.minimumNeeded = 1;
      return none;  // nothing detected at all
    }
    for (const Detection& d : detections) {
      for (const glm::dvec2& c : d.corners) points.emplace_back(c.x, c.y);
    }
  } else {
    const Lookup lookup(detections, ids,
                        static_cast<int>(std::set<int>(ids.begin(), ids.end()).size()));
    if (!lookup.ok()) return lookup.status;
    for (int id : lookup.status.needed) {
      for (const glm::dvec2& c : lookup.get(id).corners) points.emplace_back(c.x, c.y);
    }
  }
  // convexHull takes float or int points; hull by index, then keep the double coordinates.
  std::vector<cv::Point2f> asFloat(points.begin(), points.end());
  std::vector<int> hull;
  cv::convexHull(asFloat, hull, false, false);
  Path path;
  for (int i : hull) path.push_back({points[i].x, points[i].y});
  if (signedArea(path) > 0) std::reverse(path.begin(), path.end());
  return Paths{std::move(path)};
}

RoiResult tagFrameRoi(const std::vector<Detection>& detections, int id,
                      const Paths& tagFramePaths) {
  const Lookup lookup(detections, {id}, 1);
  if (!lookup.ok()) return lookup.status;
  return mapPaths(lookup.get(id).homography, tagFramePaths);
}

RoiResult buildRoi(const RoiSpec& spec, const std::vector<Detection>& detections,
                   const Board* board) {
  switch (spec.kind) {
    case RoiSpec::Kind::Tags:
      return polygonThroughTags(detections, spec.ids, spec.anchors);
    case RoiSpec::Kind::Hull:
      return convexHullOfTags(detections, spec.ids);
    case RoiSpec::Kind::Board:
      if (board == nullptr) throw InvalidInputError("a board ROI needs a board file");
      return boardRoi(*board, detections, spec.roiName);
    case RoiSpec::Kind::TagFrame:
      return tagFrameRoi(detections, spec.ids.at(0), spec.tagFramePaths);
  }
  throw InternalError("buildRoi: unknown RoiSpec kind");
}

}  // namespace roiclip::apriltag
