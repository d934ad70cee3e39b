// SPDX-License-Identifier: MIT
// libFuzzer target: roiclip::clip on two small path sets, checked against the exact winding
// numbers of both operands combined by the operation (tests/support/oracle.hpp).
//
// Input bytes: [h0: subject rule (bits 0-1), clip rule (bits 2-3), op (bits 4-5),
//               clip is the convex hull of its points (bit 6), subject is (bit 7)]
//              [h1: coordinate mode (bits 0-2), subject path count - 1 (bits 3-4),
//               reverse the hull(s) (bit 5)]
//              then the subject's paths and the clip's paths as in fuzz_simplify.
// A hull is one strictly convex ring, so with Intersection the convex fast path runs; every
// other input goes through the general pipeline.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roiclip;
  if (size < 2) return 0;
  fuzz::ByteReader in(data, size);
  const std::uint8_t h0 = in.next();
  const std::uint8_t h1 = in.next();
  const auto subjectRule = static_cast<FillRule>(h0 & 3);
  const auto clipRule = static_cast<FillRule>((h0 >> 2) & 3);
  const auto op = static_cast<ClipOp>((h0 >> 4) & 3);
  const int mode = h1 & 7;
  const bool reverse = (h1 & 32) != 0;
  Paths subject = fuzz::decodePaths(in, mode, 1 + ((h1 >> 3) & 3), 32);
  Paths clipPaths = fuzz::decodePaths(in, mode, 4, 32);
  if ((h0 & 64) != 0) clipPaths = testing::convexHull(clipPaths, reverse);
  if ((h0 & 128) != 0) subject = testing::convexHull(subject, reverse);
  PolygonSet result;
  fuzz::expectDocumentedErrors(
      "clip", [&] { result = clip(op, subject, clipPaths, subjectRule, clipRule); }, true);
  fuzz::checkAgainstOracle(
      result, {&subject, &clipPaths},
      [&](const std::vector<long long>& w) {
        return testing::combine(op, isFilled(subjectRule, w[0]), isFilled(clipRule, w[1]));
      },
      [&] {
        return std::string("clip ") + toString(op) + ", subject fill rule " +
               toString(subjectRule) + ", clip fill rule " + toString(clipRule) +
               "\nsubject: " + testing::describe(subject) +
               "\nclip: " + testing::describe(clipPaths);
      });
  return 0;
}
