// SPDX-License-Identifier: MIT
// roiclip-make-scenes: render the synthetic AprilTag scenes in images/ with exact ground truth.
//
// A 400 x 300 mm board carries four tag36h11 tags and dark shapes (blobs, a self-crossing
// figure-eight stroke, 1-px lines, a ring, a frame with holes, a self-intersecting pentagram),
// several of them straddling the ROI borders. Each scene views the board through its own
// homography. Rendering is exact point sampling at 8x8 samples per pixel (tags by looking up the
// board point under each sample, shapes with cv::fillPoly on the supersampled grid), averaged to
// the output size, then lit unevenly, blurred and given Gaussian noise. Everything is driven by
// cv::RNG with fixed seeds, so the output is the same on every machine.
//
// Output per scene: scene_NN.png and scene_NN.json (format in images/README.md); plus board.json.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <geos_c.h>
#include <CLI/CLI.hpp>
#include <glm/common.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <roiclip/apriltag/detector.hpp>
#include <roiclip/apriltag/projective.hpp>
#include <roiclip/apriltag/roi.hpp>
#include <roiclip/geometry.hpp>
#include <roiclip/io/atomic_file.hpp>

namespace {

using roiclip::Path;
using roiclip::Paths;
using Json = nlohmann::ordered_json;

constexpr double kPi = 3.14159265358979323846;
constexpr const char* kFamily = "tag36h11";
constexpr double kBoardWidth = 400.0;   // mm
constexpr double kBoardHeight = 300.0;  // mm
constexpr double kTagSide = 64.0;       // black border side, mm
constexpr int kSupersample = 8;         // samples per pixel along each axis
constexpr unsigned char kBoardWhite = 225;
constexpr unsigned char kTagBlack = 20;
constexpr unsigned char kShapeDark = 45;
constexpr unsigned char kTable = 95;

struct BoardTag {
  int id;
  glm::dvec2 centre;
};
// Tag ids in clockwise order on the board, so `tags:0,1,2,3` is a simple quadrilateral.
constexpr BoardTag kBoardTags[] = {{0, {50, 50}}, {1, {350, 50}}, {2, {350, 250}}, {3, {50, 250}}};

struct NamedPaths {
  std::string name;
  Paths paths;
};

std::vector<NamedPaths> boardRois() {
  return {
      {"inspection", {{{120, 40}, {280, 40}, {340, 150}, {280, 260}, {120, 260}, {60, 150}}}},
      {"window", {{{150, 100}, {250, 100}, {250, 200}, {150, 200}}}},
  };
}

struct Shape {
  std::string name;
  std::string kind;
  std::string fillRule;  // how `paths` is read
  Paths paths;           // board frame (mm) until mapped
};

// Corners of a tag in board coordinates, indexed like roiclip::apriltag::Corner
// (bottom-left, bottom-right, top-right, top-left; the board frame is y down).
std::array<glm::dvec2, 4> tagCorners(glm::dvec2 c) {
  const double h = kTagSide / 2;
  return {glm::dvec2{c.x - h, c.y + h}, glm::dvec2{c.x + h, c.y + h}, glm::dvec2{c.x + h, c.y - h},
          glm::dvec2{c.x - h, c.y - h}};
}

// ---- GEOS: buffer centrelines into the exact polygons that get drawn --------------------------

struct GeosContext {
  GEOSContextHandle_t handle = GEOS_init_r();
  GeosContext() {
    GEOSContext_setErrorMessageHandler_r(
        handle, [](const char* message, void*) { std::fprintf(stderr, "GEOS: %s\n", message); },
        nullptr);
  }
  ~GeosContext() { GEOS_finish_r(handle); }
  GeosContext(const GeosContext&) = delete;
  GeosContext& operator=(const GeosContext&) = delete;
};

Path ringToPath(GEOSContextHandle_t ctx, const GEOSGeometry* ring) {
  const GEOSCoordSequence* seq = GEOSGeom_getCoordSeq_r(ctx, ring);
  unsigned int size = 0;
  GEOSCoordSeq_getSize_r(ctx, seq, &size);
  Path path;
  for (unsigned int i = 0; i + 1 < size; ++i) {  // GEOS repeats the first point at the end
    double x = 0, y = 0;
    GEOSCoordSeq_getXY_r(ctx, seq, i, &x, &y);
    path.push_back({x, y});
  }
  return path;
}

// Buffer a polyline by halfWidth (flat caps, mitred joins for lines, round for closed curves).
Paths bufferLine(const GeosContext& geos, const Path& line, double halfWidth, bool closed) {
  GEOSContextHandle_t ctx = geos.handle;
  const unsigned int n = static_cast<unsigned int>(line.size() + (closed ? 1 : 0));
  GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx, n, 2);
  for (unsigned int i = 0; i < n; ++i) {
    const glm::dvec2 p = line[i % line.size()];
    GEOSCoordSeq_setXY_r(ctx, seq, i, p.x, p.y);
  }
  GEOSGeometry* geometry = GEOSGeom_createLineString_r(ctx, seq);
  GEOSGeometry* buffered =
      GEOSBufferWithStyle_r(ctx, geometry, halfWidth, 8, GEOSBUF_CAP_FLAT,
                            closed ? GEOSBUF_JOIN_ROUND : GEOSBUF_JOIN_MITRE, 5.0);
  GEOSGeom_destroy_r(ctx, geometry);
  if (buffered == nullptr) throw std::runtime_error("GEOS buffer failed");
  Paths out;
  const int parts = GEOSGetNumGeometries_r(ctx, buffered);
  for (int p = 0; p < parts; ++p) {
    const GEOSGeometry* polygon = GEOSGetGeometryN_r(ctx, buffered, p);
    out.push_back(ringToPath(ctx, GEOSGetExteriorRing_r(ctx, polygon)));
    const int holes = GEOSGetNumInteriorRings_r(ctx, polygon);
    for (int h = 0; h < holes; ++h) {
      out.push_back(ringToPath(ctx, GEOSGetInteriorRingN_r(ctx, polygon, h)));
    }
  }
  GEOSGeom_destroy_r(ctx, buffered);
  return out;
}

// ---- shapes ----------------------------------------------------------------------------------

Path blob(cv::RNG& rng, glm::dvec2 centre, double radius) {
  double amp[4];
  double phase[4];
  for (int k = 0; k < 4; ++k) {
    amp[k] = rng.uniform(0.0, 0.12);
    phase[k] = rng.uniform(0.0, 2 * kPi);
  }
  Path path;
  constexpr int kVertices = 96;
  for (int i = 0; i < kVertices; ++i) {
    const double t = 2 * kPi * i / kVertices;
    double r = 1.0;
    for (int k = 0; k < 4; ++k) r += amp[k] * std::cos((k + 2) * t + phase[k]);
    path.push_back(centre + radius * r * glm::dvec2{std::cos(t), std::sin(t)});
  }
  return path;
}

Path circle(glm::dvec2 centre, double radius, bool reversed) {
  Path path;
  constexpr int kVertices = 72;
  for (int i = 0; i < kVertices; ++i) {
    const double t = (reversed ? -2 : 2) * kPi * i / kVertices;
    path.push_back(centre + radius * glm::dvec2{std::cos(t), std::sin(t)});
  }
  return path;
}

Path rotatedRect(glm::dvec2 centre, double w, double h, double angle) {
  const glm::dvec2 u{std::cos(angle), std::sin(angle)};
  const glm::dvec2 v{-u.y, u.x};
  return {centre - u * (w / 2) - v * (h / 2), centre + u * (w / 2) - v * (h / 2),
          centre + u * (w / 2) + v * (h / 2), centre - u * (w / 2) + v * (h / 2)};
}

std::vector<Shape> makeShapes(cv::RNG& rng, const GeosContext& geos, double mmPerPixel) {
  auto jitter = [&](glm::dvec2 p, double r) {
    return p + glm::dvec2{rng.uniform(-r, r), rng.uniform(-r, r)};
  };
  std::vector<Shape> shapes;
  // Blob across the inspection ROI's top edge (y = 40).
  shapes.push_back({"blob_top_edge",
                    "blob",
                    "evenodd",
                    {blob(rng, jitter({200, 40}, 6), rng.uniform(14.0, 18.0))}});
  // Blob well inside the inspection ROI.
  shapes.push_back({"blob_inside",
                    "blob",
                    "evenodd",
                    {blob(rng, jitter({115, 150}, 3), rng.uniform(10.0, 13.0))}});
  // Blob entirely outside both ROIs.
  shapes.push_back({"blob_outside",
                    "blob",
                    "evenodd",
                    {blob(rng, jitter({200, 285}, 2), rng.uniform(6.0, 8.0))}});
  // Figure-eight stroke (lemniscate of Gerono) crossing the window's left and right edges; its
  // buffer is an outer ring with the two lobes as holes.
  {
    const glm::dvec2 c = jitter({200, 150}, 3);
    const double a = rng.uniform(52.0, 58.0);
    const double b = rng.uniform(24.0, 28.0);
    const double angle = rng.uniform(-0.15, 0.15);
    Path centreline;
    constexpr int kSamples = 160;
    for (int i = 0; i < kSamples; ++i) {
      const double t = 2 * kPi * i / kSamples;
      const glm::dvec2 q{a * std::sin(t), b * std::sin(t) * std::cos(t) * 2};
      centreline.push_back(c + glm::dvec2{q.x * std::cos(angle) - q.y * std::sin(angle),
                                          q.x * std::sin(angle) + q.y * std::cos(angle)});
    }
    shapes.push_back({"figure_eight_stroke", "stroke", "evenodd",
                      bufferLine(geos, centreline, rng.uniform(1.8, 2.4), true)});
  }
  // Two 1-px lines: one crossing the inspection ROI's bottom edge, one its upper-right edge.
  shapes.push_back(
      {"thin_line_bottom", "line", "evenodd",
       bufferLine(geos, {jitter({150, 238}, 3), jitter({252, 282}, 3)}, 0.5 * mmPerPixel, false)});
  shapes.push_back(
      {"thin_line_right", "line", "evenodd",
       bufferLine(geos, {jitter({250, 70}, 3), jitter({332, 112}, 2)}, 0.5 * mmPerPixel, false)});
  // A ring (disc with a hole) across the inspection ROI's lower-right edge.
  {
    const glm::dvec2 c = jitter({322, 183}, 2);
    const double r = rng.uniform(13.0, 16.0);
    shapes.push_back(
        {"ring_right_edge", "ring", "evenodd", {circle(c, r, false), circle(c, r * 0.55, true)}});
  }
  // A frame with two square holes across the window's bottom edge.
  {
    const glm::dvec2 c = jitter({228, 212}, 2);
    const double angle = rng.uniform(-0.3, 0.3);
    const glm::dvec2 u{std::cos(angle), std::sin(angle)};
    Paths frame = {rotatedRect(c, 40, 26, angle), rotatedRect(c - u * 9.0, 12, 12, angle),
                   rotatedRect(c + u * 9.0, 12, 12, angle)};
    shapes.push_back({"frame_two_holes", "frame", "evenodd", std::move(frame)});
  }
  // A self-intersecting pentagram over the inspection ROI's left vertex; under even-odd its
  // central pentagon stays white.
  {
    const glm::dvec2 c = jitter({60, 150}, 2);
    const double r = rng.uniform(17.0, 20.0);
    const double rot = rng.uniform(0.0, 2 * kPi);
    Path star;
    for (int i = 0; i < 5; ++i) {
      const double t = rot + 2 * kPi * ((2 * i) % 5) / 5.0;
      star.push_back(c + r * glm::dvec2{std::cos(t), std::sin(t)});
    }
    shapes.push_back({"pentagram_left_vertex", "pentagram", "evenodd", {star}});
  }
  return shapes;
}

// ---- scenes ----------------------------------------------------------------------------------

struct SceneSpec {
  int width;
  int height;
  std::uint64_t seed;
  double fill;        // fraction of the image the board's bounding box fills
  double rotation;    // radians, in the image plane
  glm::dvec2 tilt;    // perspective terms (per mm)
  double blurSigma;   // px
  double noiseSigma;  // grey levels
};

// Scene 5 is upside down and scene 8 turned by about 90 degrees, so corner order is exercised.
const SceneSpec kScenes[] = {
    {800, 600, 1001, 0.92, 0.00, {0.0, 0.0}, 0.6, 2.0},
    {800, 600, 1002, 0.95, 0.12, {0.0012, 0.0}, 0.8, 3.0},
    {800, 600, 1003, 0.90, -0.20, {-0.0010, 0.0014}, 0.9, 4.0},
    {800, 600, 1004, 0.97, 0.35, {0.0, -0.0018}, 1.0, 3.0},
    {800, 600, 1005, 0.88, kPi - 0.1, {0.0014, 0.0008}, 0.7, 5.0},
    {800, 600, 1006, 0.96, -0.05, {-0.0020, -0.0006}, 1.1, 4.0},
    {640, 480, 1007, 0.93, 0.08, {0.0008, 0.0012}, 0.8, 3.0},
    {640, 480, 1008, 0.95, -kPi / 2 + 0.15, {-0.0012, 0.0}, 0.7, 4.0},
};

// image_from_board: centre the board, apply perspective and rotation, then scale and move it so
// the board's bounding box fills `fill` of the image.
glm::dmat3 sceneHomography(const SceneSpec& s) {
  const glm::dmat3 toCentre(1, 0, 0, 0, 1, 0, -kBoardWidth / 2, -kBoardHeight / 2, 1);
  const glm::dmat3 perspective(1, 0, s.tilt.x, 0, 1, s.tilt.y, 0, 0, 1);
  const double c = std::cos(s.rotation), n = std::sin(s.rotation);
  const glm::dmat3 rotation(c, n, 0, -n, c, 0, 0, 0, 1);
  const glm::dmat3 h = rotation * perspective * toCentre;
  glm::dvec2 lo{1e300, 1e300};
  glm::dvec2 hi{-1e300, -1e300};
  for (const glm::dvec2 corner :
       {glm::dvec2{0, 0}, glm::dvec2{kBoardWidth, 0}, glm::dvec2{kBoardWidth, kBoardHeight},
        glm::dvec2{0, kBoardHeight}}) {
    const glm::dvec2 p = roiclip::apriltag::applyHomography(h, corner);
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double scale = s.fill * std::min(s.width / (hi.x - lo.x), s.height / (hi.y - lo.y));
  const glm::dvec2 mid = (lo + hi) * 0.5;
  const glm::dmat3 toImage(scale, 0, 0, 0, scale, 0, (s.width - 1) / 2.0 - scale * mid.x,
                           (s.height - 1) / 2.0 - scale * mid.y, 1);
  return toImage * h;
}

// Local scale (px per mm) of a homography at a board point: sqrt of its Jacobian determinant.
double pixelsPerMm(const glm::dmat3& h, glm::dvec2 p) {
  const double d = 1e-3;
  const glm::dvec2 o = roiclip::apriltag::applyHomography(h, p);
  const glm::dvec2 ex = roiclip::apriltag::applyHomography(h, p + glm::dvec2{d, 0}) - o;
  const glm::dvec2 ey = roiclip::apriltag::applyHomography(h, p + glm::dvec2{0, d}) - o;
  return std::sqrt(std::abs(ex.x * ey.y - ex.y * ey.x)) / d;
}

Json pointsJson(const Path& path) {
  Json out = Json::array();
  for (const glm::dvec2& p : path) out.push_back({p.x, p.y});
  return out;
}

Json pathsJson(const Paths& paths) {
  Json out = Json::array();
  for (const Path& path : paths) out.push_back(pointsJson(path));
  return out;
}

// The board file, in the format roiclip::apriltag::Board reads.
std::string boardFile() {
  roiclip::apriltag::Board board;
  board.family = kFamily;
  board.units = "mm";
  board.size = glm::dvec2{kBoardWidth, kBoardHeight};
  for (const BoardTag& tag : kBoardTags) {
    const auto c = tagCorners(tag.centre);
    board.tags[tag.id] = c;
  }
  for (const NamedPaths& roi : boardRois()) board.rois.push_back({roi.name, roi.paths});
  return board.toJson(1);
}

// The board's appearance at a board point (mm): white board, tag cells, or the table.
class BoardTexture {
 public:
  BoardTexture() {
    for (const BoardTag& tag : kBoardTags) {
      int border = 0;
      tags_.push_back(roiclip::apriltag::renderTag(kFamily, tag.id, &border));
      borderCells_ = border;
    }
  }
  [[nodiscard]] unsigned char at(glm::dvec2 p) const {
    if (p.x < 0 || p.y < 0 || p.x >= kBoardWidth || p.y >= kBoardHeight) return kTable;
    const double cell = kTagSide / borderCells_;
    for (std::size_t i = 0; i < tags_.size(); ++i) {
      const cv::Mat& tag = tags_[i];
      const double half = cell * tag.cols / 2;
      const glm::dvec2 q = p - kBoardTags[i].centre + glm::dvec2{half, half};
      if (q.x >= 0 && q.y >= 0 && q.x < 2 * half && q.y < 2 * half) {
        const int col = static_cast<int>(q.x / cell);
        const int row = static_cast<int>(q.y / cell);
        return tag.at<unsigned char>(row, col) < 128 ? kTagBlack : kBoardWhite;
      }
    }
    return kBoardWhite;
  }

 private:
  std::vector<cv::Mat> tags_;
  int borderCells_ = 8;
};

Paths mapToSuper(const glm::dmat3& imageFromBoard, const Paths& boardPaths) {
  Paths out = roiclip::apriltag::mapPaths(imageFromBoard, boardPaths);
  for (Path& path : out) {
    for (glm::dvec2& p : path) p = (p + 0.5) * static_cast<double>(kSupersample) - 0.5;
  }
  return out;
}

void fillEvenOdd(cv::Mat& image, const Paths& superPaths, unsigned char value) {
  constexpr int kShift = 8;
  std::vector<std::vector<cv::Point>> contours;
  for (const Path& path : superPaths) {
    std::vector<cv::Point> contour;
    for (const glm::dvec2& p : path) {
      contour.emplace_back(static_cast<int>(std::lround(p.x * (1 << kShift))),
                           static_cast<int>(std::lround(p.y * (1 << kShift))));
    }
    contours.push_back(std::move(contour));
  }
  cv::fillPoly(image, contours, cv::Scalar(value), cv::LINE_8, kShift);
}

void writeScene(const std::filesystem::path& dir, int index, const SceneSpec& spec,
                const BoardTexture& texture, const GeosContext& geos) {
  cv::RNG rng(spec.seed);
  const glm::dmat3 imageFromBoard = sceneHomography(spec);
  const glm::dmat3 boardFromImage = glm::inverse(imageFromBoard);
  // Every tag (with its white margin) must be fully inside the image for the detection tests.
  for (const BoardTag& tag : kBoardTags) {
    for (double dx : {-40.0, 40.0}) {
      for (double dy : {-40.0, 40.0}) {
        const glm::dvec2 p =
            roiclip::apriltag::applyHomography(imageFromBoard, tag.centre + glm::dvec2{dx, dy});
        if (p.x < 2 || p.y < 2 || p.x > spec.width - 3 || p.y > spec.height - 3) {
          throw std::runtime_error("scene " + std::to_string(index) + ": tag " +
                                   std::to_string(tag.id) + " leaves the image");
        }
      }
    }
  }

  // Supersampled, exactly point-sampled board.
  const int sw = spec.width * kSupersample, sh = spec.height * kSupersample;
  cv::Mat super(sh, sw, CV_8UC1);
  super.forEach<unsigned char>([&](unsigned char& value, const int* pos) {
    const glm::dvec2 image{(pos[1] + 0.5) / kSupersample - 0.5,
                           (pos[0] + 0.5) / kSupersample - 0.5};
    const glm::dvec3 q = boardFromImage * glm::dvec3(image, 1.0);
    value = texture.at({q.x / q.z, q.y / q.z});
  });

  const double mmPerPixel = 1.0 / pixelsPerMm(imageFromBoard, {kBoardWidth / 2, kBoardHeight / 2});
  std::vector<Shape> shapes = makeShapes(rng, geos, mmPerPixel);
  for (const Shape& shape : shapes) {
    fillEvenOdd(super, mapToSuper(imageFromBoard, shape.paths), kShapeDark);
  }

  cv::Mat small;
  cv::resize(super, small, cv::Size(spec.width, spec.height), 0, 0, cv::INTER_AREA);
  cv::Mat image;
  small.convertTo(image, CV_32F);
  // Uneven lighting: a smooth multiplicative gradient.
  const double gx = rng.uniform(-0.25, 0.25) / spec.width,
               gy = rng.uniform(-0.25, 0.25) / spec.height;
  image.forEach<float>([&](float& v, const int* pos) {
    v *= static_cast<float>(1.0 + gx * (pos[1] - spec.width / 2.0) +
                            gy * (pos[0] - spec.height / 2.0));
  });
  cv::GaussianBlur(image, image, cv::Size(0, 0), spec.blurSigma);
  cv::Mat noise(image.size(), CV_32F);
  rng.fill(noise, cv::RNG::NORMAL, 0.0, spec.noiseSigma);
  image += noise;
  cv::Mat out;
  image.convertTo(out, CV_8U);  // saturating, rounding

  char stem[32];
  std::snprintf(stem, sizeof stem, "scene_%02d", index);
  const std::filesystem::path png = dir / (std::string(stem) + ".png");
  if (!cv::imwrite(png.string(), out, {cv::IMWRITE_PNG_COMPRESSION, 9})) {
    throw std::runtime_error("cannot write " + png.string());
  }

  Json gt;
  gt["image"] = png.filename().string();
  gt["width"] = spec.width;
  gt["height"] = spec.height;
  gt["board"] = "board.json";
  gt["family"] = kFamily;
  Json h = Json::array();
  for (int r = 0; r < 3; ++r)
    h.push_back({imageFromBoard[0][r], imageFromBoard[1][r], imageFromBoard[2][r]});
  gt["image_from_board"] = h;
  Json tags = Json::array();
  for (const BoardTag& tag : kBoardTags) {
    const auto c = tagCorners(tag.centre);
    Path corners(c.begin(), c.end());
    Json t;
    t["id"] = tag.id;
    t["corners"] = pointsJson(roiclip::apriltag::mapPaths(imageFromBoard, {corners})[0]);
    const glm::dvec2 centre = roiclip::apriltag::applyHomography(imageFromBoard, tag.centre);
    t["centre"] = {centre.x, centre.y};
    tags.push_back(t);
  }
  gt["tags"] = tags;
  Json rois = Json::array();
  for (const NamedPaths& roi : boardRois()) {
    rois.push_back({{"name", roi.name},
                    {"paths", pathsJson(roiclip::apriltag::mapPaths(imageFromBoard, roi.paths))}});
  }
  gt["rois"] = rois;
  Json shapesJson = Json::array();
  for (const Shape& shape : shapes) {
    shapesJson.push_back(
        {{"name", shape.name},
         {"kind", shape.kind},
         {"fill_rule", shape.fillRule},
         {"paths", pathsJson(roiclip::apriltag::mapPaths(imageFromBoard, shape.paths))}});
  }
  gt["shapes"] = shapesJson;
  gt["render"] = {{"seed", spec.seed},
                  {"supersample", kSupersample},
                  {"blur_sigma", spec.blurSigma},
                  {"noise_sigma", spec.noiseSigma},
                  {"board_grey", kBoardWhite},
                  {"shape_grey", kShapeDark},
                  {"tag_black_grey", kTagBlack},
                  {"table_grey", kTable}};
  roiclip::io::writeFileAtomically(dir / (std::string(stem) + ".json"), gt.dump(1) + '\n');
  std::cout << png.string() << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Render the synthetic AprilTag scenes (PNG + ground-truth JSON) into a directory."};
  std::string outDir = "images";
  app.add_option("-o,--out", outDir, "output directory (created if missing)");
  CLI11_PARSE(app, argc, argv);
  try {
    std::filesystem::create_directories(outDir);
    std::ofstream(std::filesystem::path(outDir) / "board.json") << boardFile();
    const BoardTexture texture;
    const GeosContext geos;
    int index = 1;
    for (const SceneSpec& spec : kScenes) writeScene(outDir, index++, spec, texture, geos);
  } catch (const std::exception& e) {
    std::cerr << "roiclip-make-scenes: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
