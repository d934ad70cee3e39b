// SPDX-License-Identifier: MIT
// Open polylines: Canny edges traced into chains (the core's clipLines clips them to the ROI).
#include <roiclip/opencv/edges.hpp>

#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace roiclip::opencv {

namespace {

// 4-neighbours first, so chains follow straight steps before diagonal ones.
constexpr std::array<std::array<int, 2>, 8> kSteps = {
    {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}}};

}  // namespace

Paths traceEdges(cv::InputArray input) {
  const cv::Mat edges = input.getMat();
  if (edges.empty()) return {};
  if (edges.type() != CV_8UC1) throw InvalidInputError("traceEdges: need a CV_8UC1 edge image");
  const int w = edges.cols;
  const int h = edges.rows;
  cv::Mat visited = cv::Mat::zeros(edges.size(), CV_8U);
  const auto free = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && edges.at<uchar>(y, x) != 0 &&
           visited.at<uchar>(y, x) == 0;
  };
  const auto isEdge = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h && edges.at<uchar>(y, x) != 0;
  };
  // Follow unvisited neighbours from (x, y) (already in `path`) until none is left.
  const auto follow = [&](int x, int y, Path& path) {
    for (;;) {
      bool moved = false;
      for (const auto& s : kSteps) {
        if (free(x + s[0], y + s[1])) {
          x += s[0];
          y += s[1];
          visited.at<uchar>(y, x) = 1;
          path.emplace_back(x, y);
          moved = true;
          break;
        }
      }
      if (!moved) return;
    }
  };
  Paths out;
  const auto traceFrom = [&](int x, int y) {
    visited.at<uchar>(y, x) = 1;
    Path forward{{x, y}};
    follow(x, y, forward);
    Path backward{{x, y}};
    follow(x, y, backward);  // a start in the middle of a chain: the other direction
    Path path(backward.rbegin(), backward.rend());
    path.insert(path.end(), forward.begin() + 1, forward.end());
    // A closed loop comes back next to its start: close it.
    const Point first = path.front();
    const Point last = path.back();
    if (path.size() > 3 && std::abs(first.x - last.x) <= 1 && std::abs(first.y - last.y) <= 1) {
      path.push_back(first);
    }
    out.push_back(std::move(path));
  };
  // Chain ends first (exactly one edge neighbour), then whatever is left (loops, branches).
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!free(x, y)) continue;
      int neighbours = 0;
      for (const auto& s : kSteps) neighbours += isEdge(x + s[0], y + s[1]) ? 1 : 0;
      if (neighbours == 1) traceFrom(x, y);
    }
  }
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (free(x, y)) traceFrom(x, y);
    }
  }
  return out;
}

void approximatePolylines(Paths& polylines, double epsilon) {
  for (Path& line : polylines) {
    // cv::approxPolyDP takes int or float points only; float is exact for the pixel centres
    // traceEdges() gives (up to 2^24 px).
    std::vector<cv::Point2f> in;
    std::vector<cv::Point2f> approx;
    for (const Point& p : line) in.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
    cv::approxPolyDP(in, approx, epsilon, false);
    line.clear();
    for (const auto& p : approx) line.emplace_back(p.x, p.y);
  }
}

double polylineLength(const Paths& polylines) {
  double total = 0;
  for (const Path& line : polylines) {
    for (std::size_t i = 1; i < line.size(); ++i) {
      total += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
    }
  }
  return total;
}

}  // namespace roiclip::opencv
