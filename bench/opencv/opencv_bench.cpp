// SPDX-License-Identifier: MIT
// Vector vs raster ROI clipping of every contour of an image, in the same run.
//
// Both routes start from the contours cv::findContours found in the image and end with the
// contours of the part inside the ROI quad:
//   vector: fromContours -> roiclip::intersect(contours, quad, EvenOdd) -> toContours
//   raster: fillPoly(contours) -> fillPoly(quad) -> bitwise_and -> findContours
// The raster route is what an OpenCV user would otherwise write; it is approximate (pixel
// grid, fillPoly's edge lines), the vector route is exact.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <roiclip/opencv/opencv.hpp>

#include "scenes.hpp"

namespace roiclip::opencv {
namespace {

struct Workload {
  cv::Size size;
  std::vector<std::vector<cv::Point>> contours;
  std::vector<cv::Vec4i> hierarchy;
  Paths quad;
  std::size_t vertices = 0;
};

Workload fromMask(const cv::Mat& mask) {
  Workload w;
  w.size = mask.size();
  cv::findContours(mask, w.contours, w.hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
  for (const auto& c : w.contours) w.vertices += c.size();
  const double x = w.size.width, y = w.size.height;
  // A perspective view of a rectangle, as four AprilTag centres would give it.
  w.quad = {{{0.12 * x + 0.3, 0.18 * y},
             {0.22 * x, 0.91 * y + 0.6},
             {0.86 * x + 0.25, 0.79 * y},
             {0.74 * x, 0.08 * y + 0.45}}};
  return w;
}

// 1920x1080: blobs with holes, text strokes and 1-px lines drawn over each other.
const Workload& fullHd() {
  static const Workload w = [] {
    const cv::Size size(1920, 1080);
    cv::Mat mask = testing::drawScene(testing::SceneKind::Blobs, size, 1);
    mask |= testing::drawScene(testing::SceneKind::Text, size, 2);
    mask |= testing::drawScene(testing::SceneKind::ThinLines, size, 3);
    return fromMask(mask);
  }();
  return w;
}

// images/scene_01.png (800x600, dark shapes and AprilTags on paper) if it exists.
const Workload* sceneImage() {
  static const Workload w = [] {
    const cv::Mat gray =
        cv::imread(std::string(ROICLIP_IMAGES) + "/scene_01.png", cv::IMREAD_GRAYSCALE);
    if (gray.empty()) return Workload{};
    cv::Mat mask;
    cv::threshold(gray, mask, 0, 255, cv::THRESH_BINARY_INV | cv::THRESH_OTSU);
    return fromMask(mask);
  }();
  return w.contours.empty() ? nullptr : &w;
}

void setCounters(benchmark::State& state, const Workload& w, std::size_t outputContours) {
  state.counters["contours"] = double(w.contours.size());
  state.counters["vertices"] = double(w.vertices);
  state.counters["out_contours"] = double(outputContours);
  state.counters["pixels"] = double(w.size.area());
}

void vectorRoute(benchmark::State& state, const Workload& w) {
  std::size_t out = 0;
  for (auto _ : state) {
    const PolygonSet inside = intersect(fromContours(w.contours), w.quad, FillRule::EvenOdd);
    const Contours<cv::Point2d> result = toContours2d(inside);
    out = result.contours.size();
    benchmark::DoNotOptimize(result.contours.data());
  }
  setCounters(state, w, out);
}

void vectorRoutePerContour(benchmark::State& state, const Workload& w) {
  // One clip per contour: keeps each contour's identity (holes are separate contours here).
  std::size_t out = 0;
  for (auto _ : state) {
    out = 0;
    for (const auto& c : w.contours) {
      const PolygonSet inside = intersect(Paths{fromContour(c)}, w.quad, FillRule::EvenOdd);
      out += inside.ringCount();
      benchmark::DoNotOptimize(inside.polygons.data());
    }
  }
  setCounters(state, w, out);
}

void rasterRoute(benchmark::State& state, const Workload& w) {
  const std::vector<std::vector<cv::Point>> quad = toFixedPointContours(w.quad).contours.contours;
  std::size_t out = 0;
  for (auto _ : state) {
    cv::Mat subject(w.size, CV_8UC1, cv::Scalar(0));
    cv::fillPoly(subject, w.contours, cv::Scalar(255));
    cv::Mat roi(w.size, CV_8UC1, cv::Scalar(0));
    cv::fillPoly(roi, quad, cv::Scalar(255), cv::LINE_8, kDefaultShift);
    cv::Mat inside;
    cv::bitwise_and(subject, roi, inside);
    std::vector<std::vector<cv::Point>> contours;
    std::vector<cv::Vec4i> hierarchy;
    cv::findContours(inside, contours, hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE);
    out = contours.size();
    benchmark::DoNotOptimize(contours.data());
  }
  setCounters(state, w, out);
}

}  // namespace
}  // namespace roiclip::opencv

int main(int argc, char** argv) {
  using namespace roiclip::opencv;
  benchmark::RegisterBenchmark("Vector/FullHd", [](benchmark::State& s) {
    vectorRoute(s, fullHd());
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("VectorPerContour/FullHd", [](benchmark::State& s) {
    vectorRoutePerContour(s, fullHd());
  })->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("Raster/FullHd", [](benchmark::State& s) {
    rasterRoute(s, fullHd());
  })->Unit(benchmark::kMillisecond);
  // images/scene_01.png is written by the scene generator; skip its rows until it exists.
  if (sceneImage() != nullptr) {
    benchmark::RegisterBenchmark("Vector/Scene01", [](benchmark::State& s) {
      vectorRoute(s, *sceneImage());
    })->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark("Raster/Scene01", [](benchmark::State& s) {
      rasterRoute(s, *sceneImage());
    })->Unit(benchmark::kMillisecond);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
