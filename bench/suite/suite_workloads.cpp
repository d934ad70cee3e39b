// SPDX-License-Identifier: MIT
#include "suite_workloads.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace roiclip::bench::suite {
namespace {

constexpr double kPi = 3.14159265358979323846;
const cv::Point2d kCentre(960.0, 540.0);

/// Round to integer pixels, dropping consecutive repeats (and a last point equal to the first).
Contour roundPoints(const std::vector<cv::Point2d>& points) {
  Contour out;
  out.reserve(points.size());
  for (const cv::Point2d& p : points) {
    const cv::Point q(int(std::lround(p.x)), int(std::lround(p.y)));
    if (out.empty() || out.back() != q) out.push_back(q);
  }
  while (out.size() > 1 && out.back() == out.front()) out.pop_back();
  return out;
}

/// `samples` points of the star at equal steps of the angle (the shape, before resampling).
std::vector<cv::Point2d> sampleStar(int lobes, std::size_t samples) {
  const double c = kStarSharpness;
  std::vector<cv::Point2d> points(samples);
  for (std::size_t i = 0; i < samples; ++i) {
    const double t = 2.0 * kPi * double(i) / double(samples);
    const double r = 430.0 + 230.0 * std::tanh(c * std::sin(double(lobes) * t)) / std::tanh(c);
    points[i] = kCentre + cv::Point2d(r * std::cos(t), 0.75 * r * std::sin(t));
  }
  return points;
}

/// `count` points at equal arc length along the closed polyline `dense`.
std::vector<cv::Point2d> resampleByArcLength(const std::vector<cv::Point2d>& dense,
                                             std::size_t count) {
  std::vector<double> length(dense.size() + 1, 0.0);
  for (std::size_t i = 0; i < dense.size(); ++i) {
    length[i + 1] = length[i] + cv::norm(dense[(i + 1) % dense.size()] - dense[i]);
  }
  std::vector<cv::Point2d> out(count);
  std::size_t segment = 0;
  for (std::size_t j = 0; j < count; ++j) {
    const double s = length.back() * double(j) / double(count);
    while (length[segment + 1] < s) ++segment;
    const double span = length[segment + 1] - length[segment];
    const double f = span > 0.0 ? (s - length[segment]) / span : 0.0;
    out[j] = dense[segment] + f * (dense[(segment + 1) % dense.size()] - dense[segment]);
  }
  return out;
}

/// Outer contours (parent -1) of a RETR_CCOMP hierarchy, each followed by its holes.
std::vector<std::vector<int>> groupsOf(const std::vector<cv::Vec4i>& hierarchy) {
  std::vector<std::vector<int>> groups;
  for (int i = 0; i < int(hierarchy.size()); ++i) {
    if (hierarchy[std::size_t(i)][3] >= 0) continue;
    std::vector<int> group{i};
    for (int h = hierarchy[std::size_t(i)][2]; h >= 0; h = hierarchy[std::size_t(h)][0]) {
      group.push_back(h);
    }
    groups.push_back(std::move(group));
  }
  return groups;
}

Row singleJob(std::string name, FillRule rule, Contour subject, Contour clip) {
  Row row;
  row.name = std::move(name);
  row.rule = rule;
  row.jobs.push_back(Job{{std::move(subject)}, {std::move(clip)}, {{0}}});
  return row;
}

}  // namespace

const cv::Size kFrame(1920, 1080);

std::size_t Row::vertices() const {
  std::size_t n = 0;
  for (const Job& job : jobs) {
    for (const Contour& c : job.subject) n += c.size();
    for (const Contour& c : job.clip) n += c.size();
  }
  return n;
}

Contour roiQuad() { return {{930, 70}, {1640, 170}, {1560, 1000}, {900, 950}}; }

Contour starContour(int lobes, std::size_t vertices) {
  return roundPoints(resampleByArcLength(sampleStar(lobes, std::size_t(1) << 20), vertices));
}

Contour starPixelChain(int lobes) {
  std::vector<cv::Point> fixedPoint;
  for (const cv::Point2d& p : sampleStar(lobes, std::size_t(1) << 20)) {
    fixedPoint.emplace_back(int(std::lround(p.x * 256.0)), int(std::lround(p.y * 256.0)));
  }
  cv::Mat mask = cv::Mat::zeros(kFrame, CV_8UC1);
  cv::fillPoly(mask, std::vector<Contour>{fixedPoint}, cv::Scalar(255), cv::LINE_8, 8);
  Contours contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  return *std::max_element(contours.begin(), contours.end(),
                           [](const Contour& a, const Contour& b) { return a.size() < b.size(); });
}

Contour epitrochoid(std::size_t vertices) {
  const double m = double(vertices / 16);
  const double spacingPerRadius = 2.0 * kPi / (m - 1.0);
  const double radius = 500.0 / (1.0 + 1.25 * spacingPerRadius);
  const double d = 1.25 * spacingPerRadius * radius;
  std::vector<cv::Point2d> points(vertices);
  for (std::size_t i = 0; i < vertices; ++i) {
    const double t = 2.0 * kPi * double(i) / double(vertices);
    points[i] = kCentre + cv::Point2d(radius * std::cos(t) + d * std::cos(m * t),
                                      radius * std::sin(t) + d * std::sin(m * t));
  }
  return roundPoints(points);
}

Contour randomIntegerPolygon(std::size_t vertices, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coord(0, 999);
  Contour ring(vertices);
  for (cv::Point& p : ring) {
    p.x = coord(rng);
    p.y = coord(rng);
  }
  return ring;
}

Contours ellipseContours() {
  cv::Mat mask = cv::Mat::zeros(kFrame, CV_8UC1);
  cv::RNG rng(4);
  constexpr int kShift = 4;  // centres and axes to 1/16 px
  for (int gy = 0; gy < 80; ++gy) {
    for (int gx = 0; gx < 125; ++gx) {
      const cv::Point2d centre((gx + 0.5) * 1920.0 / 125.0, (gy + 0.5) * 1080.0 / 80.0);
      const cv::Size axes(int(rng.uniform(2.5, 4.5) * 16), int(rng.uniform(2.5, 4.5) * 16));
      cv::ellipse(mask, cv::Point(int(centre.x * 16), int(centre.y * 16)), axes,
                  rng.uniform(0.0, 180.0), 0, 360, cv::Scalar(255), cv::FILLED, cv::LINE_8, kShift);
    }
  }
  Contours contours;
  cv::findContours(mask, contours, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  if (contours.size() != 10000) throw std::runtime_error("W4: ellipses merged or vanished");
  return contours;
}

ImageContours imageContours(const std::string& pngFile, int method) {
  const cv::Mat gray = cv::imread(pngFile, cv::IMREAD_GRAYSCALE);
  if (gray.empty()) throw std::runtime_error("cannot read " + pngFile);
  cv::Mat mask;
  cv::threshold(gray, mask, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
  ImageContours out;
  std::vector<cv::Vec4i> hierarchy;
  cv::findContours(mask, out.contours, hierarchy, cv::RETR_CCOMP, method);
  out.groups = groupsOf(hierarchy);
  return out;
}

Contour tagHull(const std::string& jsonFile) {
  std::ifstream in(jsonFile);
  if (!in) throw std::runtime_error("cannot read " + jsonFile);
  const nlohmann::json doc = nlohmann::json::parse(in);
  Contour corners;
  for (const auto& tag : doc.at("tags")) {
    for (const auto& c : tag.at("corners")) {
      corners.emplace_back(int(std::lround(c.at(0).get<double>())),
                           int(std::lround(c.at(1).get<double>())));
    }
  }
  Contour hull;
  cv::convexHull(corners, hull);
  return hull;
}

std::vector<RowRecipe> rowRecipes(const std::string& imagesDir) {
  std::vector<RowRecipe> recipes;
  const auto add = [&](std::string name, std::function<Row()> make) {
    recipes.push_back(RowRecipe{std::move(name), std::move(make)});
  };
  add("W1-1k",
      [] { return singleJob("W1-1k", FillRule::EvenOdd, starContour(5, 1000), roiQuad()); });
  add("W1-10k",
      [] { return singleJob("W1-10k", FillRule::EvenOdd, starContour(14, 10000), roiQuad()); });
  add("W1-100k",
      [] { return singleJob("W1-100k", FillRule::EvenOdd, starPixelChain(140), roiQuad()); });
  for (const std::size_t n : {1000, 10000}) {
    for (const FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
      const std::string name = "W2-" + std::to_string(n / 1000) + "k-" +
                               (rule == FillRule::EvenOdd ? "evenodd" : "nonzero");
      add(name, [=] { return singleJob(name, rule, epitrochoid(n), roiQuad()); });
    }
  }
  for (const FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
    const std::string name =
        std::string("W3-1k-") + (rule == FillRule::EvenOdd ? "evenodd" : "nonzero");
    add(name, [=] {
      return singleJob(name, rule, randomIntegerPolygon(1000, 31), randomIntegerPolygon(1000, 32));
    });
  }
  add("W4-10000", [] {
    Row row;
    row.name = "W4-10000";
    for (Contour& c : ellipseContours())
      row.jobs.push_back(Job{{std::move(c)}, {roiQuad()}, {{0}}});
    return row;
  });
  std::vector<std::string> scenes;
  for (const auto& entry : std::filesystem::directory_iterator(imagesDir)) {
    if (entry.path().extension() == ".png") scenes.push_back(entry.path().stem().string());
  }
  std::sort(scenes.begin(), scenes.end());
  for (const std::string& scene : scenes) {
    for (const int method : {int(cv::CHAIN_APPROX_SIMPLE), int(cv::CHAIN_APPROX_NONE)}) {
      const std::string name =
          "W5-" + scene + (method == cv::CHAIN_APPROX_SIMPLE ? "-simple" : "-none");
      add(name, [=] {
        ImageContours image = imageContours(imagesDir + "/" + scene + ".png", method);
        Row row;
        row.name = name;
        row.jobs.push_back(Job{std::move(image.contours),
                               {tagHull(imagesDir + "/" + scene + ".json")},
                               std::move(image.groups)});
        return row;
      });
    }
  }
  return recipes;
}

}  // namespace roiclip::bench::suite
