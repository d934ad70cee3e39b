// ROI builders from AprilTag detections.
#include <roiclip/apriltag/roi.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "homography.hpp"

namespace roiclip::apriltag {
namespace {

std::string idList(const std::vector<int>& ids) {
  std::ostringstream out;
  out << '[';
  for (std::size_t i = 0; i < ids.size(); ++i) out << (i ? " " : "") << ids[i];
  out << ']';
  return out.str();
}

// Index detections by id; `needed` decides which ids must be present exactly once.
struct Lookup {
  std::map<int, std::vector<const Detection*>> byId;
  MissingTags status;

  Lookup(const std::vector<Detection>& detections, std::vector<int> needed, int minimumNeeded) {
    for (const Detection& d : detections) byId[d.id].push_back(&d);
    std::sort(needed.begin(), needed.end());
    needed.erase(std::unique(needed.begin(), needed.end()), needed.end());
    status.needed = needed;
    status.minimumNeeded = minimumNeeded;
    for (const auto& [id, list] : byId) status.seen.push_back(id);
    for (int id : needed) {
      auto it = byId.find(id);
      if (it == byId.end()) {
        status.missing.push_back(id);
      } else if (it->second.size() > 1) {
        status.duplicated.push_back(id);
      }
    }
  }
  [[nodiscard]] bool ok() const {
    const int found = static_cast<int>(status.needed.size() - status.missing.size());
    return status.duplicated.empty() && found >= status.minimumNeeded;
  }
  [[nodiscard]] const Detection& get(int id) const { return *byId.at(id).front(); }
};

glm::dvec2 anchorPoint(const Detection& d, TagAnchor anchor) {
  switch (anchor) {
    case TagAnchor::Centre:
      return d.centre;
    case TagAnchor::BottomLeft:
      return d.corner(Corner::BottomLeft);
    case TagAnchor::BottomRight:
      return d.corner(Corner::BottomRight);
    case TagAnchor::TopRight:
      return d.corner(Corner::TopRight);
    case TagAnchor::TopLeft:
      return d.corner(Corner::TopLeft);
  }
  return d.centre;
}

using Json = nlohmann::json;

glm::dvec2 parsePoint(const Json& j, const std::string& where) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) {
    throw InvalidInputError(where + ": expected a point [x, y]");
  }
  const glm::dvec2 p{j[0].get<double>(), j[1].get<double>()};
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InvalidInputError(where + ": not finite");
  return p;
}

const Json& field(const Json& object, const char* name, const std::string& where) {
  auto it = object.find(name);
  if (it == object.end()) throw InvalidInputError(where + ": missing field \"" + name + "\"");
  return *it;
}

}  // namespace

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

TagAnchor parseTagAnchor(const std::string& text) {
  std::string t;
  for (char c : text)
    t += c == '_' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (t == "centre" || t == "center") return TagAnchor::Centre;
  if (t == "bottom-left") return TagAnchor::BottomLeft;
  if (t == "bottom-right") return TagAnchor::BottomRight;
  if (t == "top-right") return TagAnchor::TopRight;
  if (t == "top-left") return TagAnchor::TopLeft;
  throw InvalidInputError("unknown tag anchor '" + text +
                          "' (expected centre, top-left, top-right, bottom-right or bottom-left)");
}

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

Board Board::fromJson(const std::string& text, const std::string& source) {
  Json j;
  try {
    j = Json::parse(text);
  } catch (const Json::exception& e) {  // parse_error, and out_of_range.406 for 1e999
    throw InvalidInputError(source + ": malformed JSON: " + e.what());
  }
  if (!j.is_object()) throw InvalidInputError(source + ": expected a JSON object");
  Board board;
  try {
    if (j.contains("family")) board.family = j.at("family").get<std::string>();
    int size = 0;
    try {
      size = familySize(board.family);
    } catch (const InvalidInputError& e) {
      throw InvalidInputError(source + ": " + e.what());
    }
    const Json& tags = field(j, "tags", source);
    if (!tags.is_array() || tags.empty())
      throw InvalidInputError(source + ": \"tags\" must be a non-empty array");
    for (std::size_t i = 0; i < tags.size(); ++i) {
      const std::string where = source + ": tags[" + std::to_string(i) + "]";
      const Json& t = tags[i];
      const Json& idJson = field(t, "id", where);
      if (!idJson.is_number_integer())
        throw InvalidInputError(where + ": \"id\" must be an integer");
      const int id = idJson.get<int>();
      if (id < 0 || id >= size) {
        throw InvalidInputError(where + ": unknown tag id " + std::to_string(id) + " (family " +
                                board.family + " has ids 0.." + std::to_string(size - 1) + ")");
      }
      if (board.tags.count(id))
        throw InvalidInputError(where + ": tag id " + std::to_string(id) + " listed twice");
      std::array<glm::dvec2, 4> corners{};
      if (t.contains("corners")) {
        const Json& c = t.at("corners");
        if (!c.is_object()) {
          throw InvalidInputError(where +
                                  ": \"corners\" must be an object with top_left, top_right, "
                                  "bottom_right, bottom_left");
        }
        corners[static_cast<int>(Corner::TopLeft)] =
            parsePoint(field(c, "top_left", where), where + ".top_left");
        corners[static_cast<int>(Corner::TopRight)] =
            parsePoint(field(c, "top_right", where), where + ".top_right");
        corners[static_cast<int>(Corner::BottomRight)] =
            parsePoint(field(c, "bottom_right", where), where + ".bottom_right");
        corners[static_cast<int>(Corner::BottomLeft)] =
            parsePoint(field(c, "bottom_left", where), where + ".bottom_left");
      } else {
        // Shorthand: an upright, axis-aligned tag in a y-down board frame.
        const glm::dvec2 c = parsePoint(field(t, "centre", where), where + ".centre");
        const Json& sizeJson = field(t, "size", where);
        if (!sizeJson.is_number() || !(sizeJson.get<double>() > 0)) {
          throw InvalidInputError(where + ": \"size\" must be a positive number");
        }
        const double h = sizeJson.get<double>() / 2;
        for (int k = 0; k < 4; ++k) {
          corners[k] =
              c +
              2 * h * glm::dvec2{detail::kTagFrameCorners[k][0], detail::kTagFrameCorners[k][1]};
        }
      }
      board.tags[id] = corners;
    }
    if (j.contains("rois")) {
      const Json& rois = j.at("rois");
      if (!rois.is_array()) throw InvalidInputError(source + ": \"rois\" must be an array");
      for (std::size_t i = 0; i < rois.size(); ++i) {
        const std::string where = source + ": rois[" + std::to_string(i) + "]";
        BoardRoi roi;
        roi.name = field(rois[i], "name", where).get<std::string>();
        const Json& paths = field(rois[i], "paths", where);
        if (!paths.is_array() || paths.empty())
          throw InvalidInputError(where + ": \"paths\" must be a non-empty array");
        for (std::size_t p = 0; p < paths.size(); ++p) {
          const std::string pathWhere = where + ".paths[" + std::to_string(p) + "]";
          if (!paths[p].is_array())
            throw InvalidInputError(pathWhere + ": expected an array of points");
          Path path;
          for (std::size_t k = 0; k < paths[p].size(); ++k) {
            path.push_back(parsePoint(paths[p][k], pathWhere + "[" + std::to_string(k) + "]"));
          }
          roi.paths.push_back(std::move(path));
        }
        board.rois.push_back(std::move(roi));
      }
    }
  } catch (const Json::exception& e) {
    // Type errors (a string where a number belongs, ...).
    throw InvalidInputError(source + ": " + e.what());
  }
  return board;
}

Board Board::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InvalidInputError("cannot read board file '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return fromJson(text.str(), path);
}

const BoardRoi& Board::roi(const std::string& name) const {
  for (const BoardRoi& r : rois) {
    if (r.name == name) return r;
  }
  std::string names;
  for (const BoardRoi& r : rois) {
    if (!names.empty()) names += ", ";
    names += r.name;
  }
  throw InvalidInputError("board has no ROI named '" + name + "' (it has: " + names + ")");
}

TagResult<BoardFit> fitBoard(const Board& board, const std::vector<Detection>& detections,
                             double ransacThreshold) {
  std::vector<Detection> ofFamily;
  for (const Detection& d : detections) {
    if (d.family == board.family) ofFamily.push_back(d);
  }
  std::vector<int> needed;
  for (const auto& [id, corners] : board.tags) needed.push_back(id);
  const Lookup lookup(ofFamily, needed, 1);
  if (!lookup.ok()) return lookup.status;

  BoardFit fit;
  std::vector<cv::Point2d> boardPoints;
  std::vector<cv::Point2d> imagePoints;
  for (const auto& [id, corners] : board.tags) {
    if (!lookup.byId.count(id)) continue;
    fit.tagsUsed.push_back(id);
    const Detection& d = lookup.get(id);
    for (int k = 0; k < 4; ++k) {
      boardPoints.emplace_back(corners[k].x, corners[k].y);
      imagePoints.emplace_back(d.corners[k].x, d.corners[k].y);
    }
  }
  fit.cornersUsed = static_cast<int>(boardPoints.size());
  cv::Mat mask;
  if (fit.tagsUsed.size() == 1) {
    // One tag gives exactly 4 correspondences: solve them exactly, in double precision
    // (findHomography works in float).
    glm::dvec2 from[4];
    glm::dvec2 to[4];
    for (int k = 0; k < 4; ++k) {
      from[k] = {boardPoints[k].x, boardPoints[k].y};
      to[k] = {imagePoints[k].x, imagePoints[k].y};
    }
    fit.imageFromBoard = detail::homographyFrom4(from, to);
  } else {
    cv::Mat h = cv::findHomography(boardPoints, imagePoints, mask, cv::RANSAC, ransacThreshold);
    if (h.empty()) throw Error("board homography fit failed (degenerate tag corners)");
    // RANSAC's mask comes from its best minimal (4-point) model, which extrapolates noise far
    // across a large board and can drop good corners. Re-select the inliers with the refined
    // model and refit them by least squares until the set is stable.
    for (int round = 0; round < 5; ++round) {
      const glm::dmat3 g = detail::toGlm(cv::Matx33d(h));
      cv::Mat inliers(static_cast<int>(boardPoints.size()), 1, CV_8U);
      std::vector<cv::Point2d> from;
      std::vector<cv::Point2d> to;
      for (std::size_t i = 0; i < boardPoints.size(); ++i) {
        const glm::dvec2 p = applyHomography(g, {boardPoints[i].x, boardPoints[i].y});
        const bool in =
            std::hypot(p.x - imagePoints[i].x, p.y - imagePoints[i].y) <= ransacThreshold;
        inliers.at<unsigned char>(static_cast<int>(i)) = in ? 1 : 0;
        if (in) {
          from.push_back(boardPoints[i]);
          to.push_back(imagePoints[i]);
        }
      }
      const bool stable = cv::countNonZero(inliers != mask) == 0;
      mask = inliers;
      if (from.size() < 4) break;
      const cv::Mat refit = cv::findHomography(from, to, 0);
      if (refit.empty()) break;
      h = refit;
      if (stable) break;
    }
    fit.imageFromBoard = detail::toGlm(cv::Matx33d(h));
  }
  double sum = 0;
  for (std::size_t i = 0; i < boardPoints.size(); ++i) {
    if (!mask.empty() && mask.at<unsigned char>(static_cast<int>(i)) == 0) continue;
    const glm::dvec2 p = applyHomography(fit.imageFromBoard, {boardPoints[i].x, boardPoints[i].y});
    const double dx = p.x - imagePoints[i].x, dy = p.y - imagePoints[i].y;
    sum += dx * dx + dy * dy;
    ++fit.inliers;
  }
  fit.rmsError = fit.inliers > 0 ? std::sqrt(sum / fit.inliers) : 0.0;
  return fit;
}

RoiResult boardRoi(const Board& board, const std::vector<Detection>& detections,
                   const std::string& roiName, double ransacThreshold) {
  Paths boardPaths;
  if (roiName.empty()) {
    if (board.rois.empty()) throw InvalidInputError("board has no ROIs");
    for (const BoardRoi& r : board.rois)
      boardPaths.insert(boardPaths.end(), r.paths.begin(), r.paths.end());
  } else {
    boardPaths = board.roi(roiName).paths;
  }
  const TagResult<BoardFit> fit = fitBoard(board, detections, ransacThreshold);
  if (!fit) return fit.missing();
  return mapPaths(fit.value().imageFromBoard, boardPaths);
}

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string::npos) return parts;
    start = end + 1;
  }
}

// Whole-string number parsing: "12x" or "" is an error, not 12 or 0.
int parseId(const std::string& text, const std::string& spec) {
  std::size_t used = 0;
  int value = 0;
  try {
    value = std::stoi(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || value < 0) {
    throw InvalidInputError("ROI '" + spec + "': '" + text + "' is not a tag id");
  }
  return value;
}

double parseNumber(const std::string& text, const std::string& spec) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (text.empty() || used != text.size() || !std::isfinite(value)) {
    throw InvalidInputError("ROI '" + spec + "': '" + text + "' is not a number");
  }
  return value;
}

std::vector<int> parseIds(const std::string& text, const std::string& spec) {
  std::vector<int> ids;
  for (const std::string& part : split(text, ',')) ids.push_back(parseId(part, spec));
  return ids;
}

}  // namespace

RoiSpec parseRoiSpec(const std::string& text) {
  const std::size_t colon = text.find(':');
  const std::string kind = text.substr(0, colon);
  const std::string rest = colon == std::string::npos ? std::string() : text.substr(colon + 1);
  const bool hasArgument = colon != std::string::npos;
  RoiSpec spec;
  if (kind == "tags") {
    spec.kind = RoiSpec::Kind::Tags;
    if (!hasArgument)
      throw InvalidInputError("ROI '" + text + "': expected tags:ID,ID,ID[@anchor]");
    const std::size_t at = rest.find('@');
    spec.ids = parseIds(rest.substr(0, at), text);
    if (at != std::string::npos) spec.anchor = parseTagAnchor(rest.substr(at + 1));
    if (spec.ids.size() < 3)
      throw InvalidInputError("ROI '" + text + "': a tag polygon needs at least 3 ids");
  } else if (kind == "hull") {
    spec.kind = RoiSpec::Kind::Hull;
    if (hasArgument) spec.ids = parseIds(rest, text);
  } else if (kind == "board") {
    spec.kind = RoiSpec::Kind::Board;
    spec.roiName = rest;
  } else if (kind == "tag") {
    spec.kind = RoiSpec::Kind::TagFrame;
    const std::size_t second = rest.find(':');
    if (!hasArgument || second == std::string::npos) {
      throw InvalidInputError("ROI '" + text + "': expected tag:ID:x,y;x,y;x,y");
    }
    spec.ids = {parseId(rest.substr(0, second), text)};
    for (const std::string& pathText : split(rest.substr(second + 1), '|')) {
      Path path;
      for (const std::string& vertex : split(pathText, ';')) {
        const std::vector<std::string> xy = split(vertex, ',');
        if (xy.size() != 2)
          throw InvalidInputError("ROI '" + text + "': vertex '" + vertex + "' is not x,y");
        path.push_back({parseNumber(xy[0], text), parseNumber(xy[1], text)});
      }
      if (path.size() < 3)
        throw InvalidInputError("ROI '" + text + "': a path needs at least 3 vertices");
      spec.tagFramePaths.push_back(std::move(path));
    }
  } else {
    throw InvalidInputError("ROI '" + text + "': unknown kind '" + kind +
                            "' (expected tags:, hull, board or tag:)");
  }
  return spec;
}

RoiResult buildRoi(const RoiSpec& spec, const std::vector<Detection>& detections,
                   const Board* board) {
  switch (spec.kind) {
    case RoiSpec::Kind::Tags:
      return polygonThroughTags(detections, spec.ids, spec.anchor);
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
