// SPDX-License-Identifier: MIT
// Synthetic binary scenes for the OpenCV mask tests, drawn with OpenCV so the contours are real
// cv::findContours output: blobs with holes, text strokes, 1-px lines, self-touching shapes.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include <roiclip/roiclip.hpp>

namespace roiclip::testing {

enum class SceneKind { Blobs, Text, ThinLines, SelfTouching };

inline const char* sceneName(SceneKind k) {
  switch (k) {
    case SceneKind::Blobs:
      return "blobs";
    case SceneKind::Text:
      return "text";
    case SceneKind::ThinLines:
      return "thinlines";
    case SceneKind::SelfTouching:
      return "selftouching";
  }
  return "?";
}

/// A CV_8U mask (0 / 255) of the given kind; the same seed always gives the same scene.
inline cv::Mat drawScene(SceneKind kind, cv::Size size, unsigned seed) {
  std::mt19937 rng(seed);
  auto uniform = [&rng](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  auto anyPoint = [&](double margin) {
    return cv::Point(int(uniform(-margin, size.width + margin)),
                     int(uniform(-margin, size.height + margin)));
  };
  cv::Mat m(size, CV_8UC1, cv::Scalar(0));
  const int scale = std::max(1, std::min(size.width, size.height) / 40);
  switch (kind) {
    case SceneKind::Blobs:
      for (int i = 0; i < 14; ++i) {
        const cv::Point c = anyPoint(10);
        const cv::Size axes(int(uniform(2, 8) * scale), int(uniform(2, 8) * scale));
        const double angle = uniform(0, 180);
        cv::ellipse(m, c, axes, angle, 0, 360, cv::Scalar(255), cv::FILLED);
        if (i % 3 == 0) {  // a hole, sometimes with an island in it
          cv::ellipse(m, c, axes / 2, angle, 0, 360, cv::Scalar(0), cv::FILLED);
          if (i % 2 == 0) cv::circle(m, c, std::max(1, axes.width / 6), cv::Scalar(255), -1);
        }
      }
      break;
    case SceneKind::Text: {
      const int fonts[] = {cv::FONT_HERSHEY_SIMPLEX, cv::FONT_HERSHEY_PLAIN,
                           cv::FONT_HERSHEY_SCRIPT_SIMPLEX, cv::FONT_HERSHEY_COMPLEX};
      const std::string words[] = {"ROI clip 8&B", "gQ@%#0", "AprilTag 36h11", "wxyz WM"};
      for (int i = 0; i < 6; ++i) {
        cv::putText(m, words[i % 4], anyPoint(-20), fonts[i % 4], uniform(0.4, 1.2) * scale / 3.0,
                    cv::Scalar(255), 1 + i % 3, i % 2 ? cv::LINE_8 : cv::LINE_4);
      }
      break;
    }
    case SceneKind::ThinLines:
      for (int i = 0; i < 20; ++i) {
        cv::line(m, anyPoint(5), anyPoint(5), cv::Scalar(255), 1, i % 2 ? cv::LINE_8 : cv::LINE_4);
      }
      for (int i = 0; i < 6; ++i) {
        cv::circle(m, anyPoint(0), int(uniform(2, 10) * scale), cv::Scalar(255), 1, cv::LINE_8);
      }
      break;
    case SceneKind::SelfTouching: {
      // Squares touching diagonally (8-connected through one corner pixel) and rings whose
      // inner boundary touches itself: findContours returns contours that revisit pixels.
      const int cell = 2 * scale + 1;
      for (int y = 0; y + cell < size.height; y += 2 * cell) {
        for (int x = (y / (2 * cell)) % 2 * cell; x + cell < size.width; x += 2 * cell) {
          if (uniform(0, 1) < 0.6) cv::rectangle(m, cv::Rect(x, y, cell, cell), 255, cv::FILLED);
        }
      }
      for (int i = 0; i < 4; ++i) {
        const cv::Point c = anyPoint(-10);
        const int r = int(uniform(3, 8) * scale);
        cv::rectangle(m, cv::Rect(c.x - r, c.y - r, 2 * r, 2 * r), 255, 1);
        cv::line(m, c - cv::Point(r, r), c + cv::Point(r - 1, r - 1), 255, 1);
      }
      break;
    }
  }
  return m;
}

/// Convex and non-convex quads and self-intersecting ROIs for an image of the given size.
struct NamedRoi {
  std::string name;
  Paths paths;
};

inline std::vector<NamedRoi> makeRois(cv::Size size) {
  const double w = size.width, h = size.height;
  const double cx = w / 2, cy = h / 2;
  std::vector<NamedRoi> rois;
  rois.push_back({"axis-quad",
                  {{{0.2 * w + 0.5, 0.15 * h},
                    {0.2 * w + 0.5, 0.85 * h},
                    {0.8 * w, 0.85 * h},
                    {0.8 * w, 0.15 * h}}}});
  rois.push_back({"perspective-quad",
                  {{{0.13 * w, 0.21 * h},
                    {0.31 * w, 0.93 * h},
                    {0.87 * w + 0.37, 0.77 * h},
                    {0.71 * w, 0.07 * h}}}});
  {
    Path rotated;
    for (int i = 0; i < 4; ++i) {
      const double a = 0.3 + i * M_PI / 2;
      rotated.push_back({cx + 0.4 * w * std::cos(a), cy + 0.4 * h * std::sin(a)});
    }
    rois.push_back({"rotated-quad", {rotated}});
  }
  rois.push_back(
      {"bowtie",
       {{{0.1 * w, 0.1 * h}, {0.9 * w, 0.9 * h}, {0.9 * w, 0.1 * h}, {0.1 * w, 0.9 * h}}}});
  {
    Path star;  // pentagram: the centre has winding number 2
    for (int i = 0; i < 5; ++i) {
      const double a = -M_PI / 2 + i * 4 * M_PI / 5;
      star.push_back({cx + 0.45 * w * std::cos(a), cy + 0.45 * h * std::sin(a)});
    }
    rois.push_back({"pentagram", {star}});
  }
  // Two overlapping quads wound in opposite directions: winding -1, 0 and +1 regions.
  rois.push_back(
      {"opposed-quads",
       {{{0.1 * w, 0.2 * h}, {0.6 * w, 0.2 * h}, {0.6 * w, 0.8 * h}, {0.1 * w, 0.8 * h}},
        {{0.4 * w, 0.1 * h}, {0.4 * w, 0.7 * h}, {0.9 * w, 0.7 * h}, {0.9 * w, 0.1 * h}}}});
  return rois;
}

}  // namespace roiclip::testing
