// SPDX-License-Identifier: MIT
// libFuzzer target: the roiclip::apriltag readers. The first line of the input is a ROI spec
// (parseRoiSpec, and parseTagAnchor on its text), the rest a board file (Board::fromJson). The
// ROI the spec describes is then built from a fixed set of synthetic detections (tags 0-3
// axis-aligned, tag 4 in perspective, tag 5 twice) with the board, and simplified when small.
// Only roiclip::Error may escape.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <roiclip/apriltag/projective.hpp>
#include <roiclip/apriltag/roi.hpp>

#include "fuzz_support.hpp"

namespace {

using roiclip::apriltag::Detection;

Detection syntheticTag(int id, const glm::dmat3& homography) {
  // Tag-frame corners in Corner order: bottom-left, bottom-right, top-right, top-left.
  constexpr double kCorners[4][2] = {{-0.5, 0.5}, {0.5, 0.5}, {0.5, -0.5}, {-0.5, -0.5}};
  Detection d;
  d.id = id;
  d.family = "tag36h11";
  d.decisionMargin = 100;
  d.homography = homography;
  d.centre = roiclip::apriltag::applyHomography(homography, {0, 0});
  for (int k = 0; k < 4; ++k) {
    d.corners[k] = roiclip::apriltag::applyHomography(homography, {kCorners[k][0], kCorners[k][1]});
  }
  return d;
}

const std::vector<Detection>& syntheticDetections() {
  static const std::vector<Detection> detections = [] {
    std::vector<Detection> out;
    for (int id = 0; id < 4; ++id) {
      // Column-major: x' = 40 u + cx, y' = 40 v + cy.
      const double cx = 100 + 300 * (id % 2), cy = 100 + 200 * (id / 2);
      out.push_back(syntheticTag(id, glm::dmat3(40, 0, 0, 0, 40, 0, cx, cy, 1)));
    }
    // A strongly tilted tag: its plane's horizon is close, so tag-frame ROIs can reach it.
    out.push_back(syntheticTag(4, glm::dmat3(40, 5, 0.2, -3, 38, 0.05, 250, 200, 1)));
    out.push_back(syntheticTag(5, glm::dmat3(20, 0, 0, 0, 20, 0, 50, 400, 1)));
    out.push_back(syntheticTag(5, glm::dmat3(20, 0, 0, 0, 20, 0, 450, 400, 1)));
    return out;
  }();
  return detections;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roiclip;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t newline = text.find('\n');
  const std::string specText = text.substr(0, newline);
  const std::string boardText = newline == std::string::npos ? "" : text.substr(newline + 1);

  fuzz::expectDocumentedErrors("parseTagAnchor", [&] { apriltag::parseTagAnchor(specText); });
  std::optional<apriltag::RoiSpec> spec;
  fuzz::expectDocumentedErrors("parseRoiSpec", [&] { spec = apriltag::parseRoiSpec(specText); });
  std::optional<apriltag::Board> board;
  fuzz::expectDocumentedErrors("Board::fromJson", [&] {
    board = apriltag::Board::fromJson(boardText, "<fuzz>");
    for (const apriltag::BoardRoi& roi : board->rois) {
      if (board->roi(roi.name).name != roi.name) fuzz::fail("Board::roi: wrong ROI");
    }
  });
  if (!spec) return 0;
  fuzz::expectDocumentedErrors("buildRoi", [&] {
    const apriltag::RoiResult roi =
        apriltag::buildRoi(*spec, syntheticDetections(), board ? &*board : nullptr);
    if (!roi) {
      if (roi.missing().describe().empty()) fuzz::fail("buildRoi: failure without a reason");
      return;
    }
    std::size_t vertices = 0;
    for (const Path& p : roi.value()) vertices += p.size();
    if (vertices <= 64) simplify(roi.value(), FillRule::NonZero);
  });
  return 0;
}
