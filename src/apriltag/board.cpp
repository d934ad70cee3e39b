// SPDX-License-Identifier: MIT
// Boards: tag corners and ROI polygons in one board frame, read from and written to JSON, fitted
// to the detections by a homography.
#include <roiclip/apriltag/roi.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>

#include "homography.hpp"
#include "tag_lookup.hpp"

namespace roiclip::apriltag {
namespace {

using detail::Lookup;
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
    if (j.contains("units")) board.units = j.at("units").get<std::string>();
    if (j.contains("size")) board.size = parsePoint(j.at("size"), source + ": size");
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

std::string Board::toJson(int indent) const {
  // Keys in the order a person reads the file, as images/board.json has them.
  using Ordered = nlohmann::ordered_json;
  const auto point = [](const glm::dvec2& p) { return Ordered::array({p.x, p.y}); };
  Ordered j;
  j["family"] = family;
  if (!units.empty()) j["units"] = units;
  if (size) j["size"] = point(*size);
  Ordered tagsJson = Ordered::array();
  for (const auto& [id, c] : tags) {
    Ordered corners;
    corners["top_left"] = point(c[static_cast<int>(Corner::TopLeft)]);
    corners["top_right"] = point(c[static_cast<int>(Corner::TopRight)]);
    corners["bottom_right"] = point(c[static_cast<int>(Corner::BottomRight)]);
    corners["bottom_left"] = point(c[static_cast<int>(Corner::BottomLeft)]);
    tagsJson.push_back({{"id", id}, {"corners", std::move(corners)}});
  }
  j["tags"] = std::move(tagsJson);
  Ordered roisJson = Ordered::array();
  for (const BoardRoi& roi : rois) {
    Ordered paths = Ordered::array();
    for (const Path& path : roi.paths) {
      Ordered points = Ordered::array();
      for (const Point& p : path) points.push_back(point(p));
      paths.push_back(std::move(points));
    }
    roisJson.push_back({{"name", roi.name}, {"paths", std::move(paths)}});
  }
  j["rois"] = std::move(roisJson);
  return j.dump(indent) + "\n";
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

}  // namespace roiclip::apriltag
