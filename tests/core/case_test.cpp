// SPDX-License-Identifier: MIT
// The hand-worked core cases, as data (tests/data/core/cases/<behaviour>.json), run by one
// parameterised test. A case file holds the operands and the expected results of one or more
// operations:
//   {"note": "...", "subject": paths, "clip": paths (absent: simplify only),
//    "expect": [{"op": "simplify" | "intersection" | "union" | "difference" | "xor",
//                "fillRule": rule (both operands) | "subjectFillRule", "clipFillRule"
//                (default "evenodd"),
//                "area": px^2, "areaTolerance": (default 1e-9),
//                "rings", "polygons": counts,
//                "outerVertices": [vertex count of each polygon's outer ring],
//                "holes": [hole count of each polygon],
//                "parents": [[parent, parentHole] of each polygon],
//                "covers", "notCovers": [[x, y], ...] points inside / outside the result}, ...]}
// Every expectation also checks the ring structure and the independent oracles (exact winding
// numbers at sample points, slab-integrated area); a binary intersection, union or xor must
// give the same area with the operands swapped.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <roiclip/roiclip.hpp>

#include "data_files.hpp"
#include "support/geos_validity.hpp"
#include "support/oracle.hpp"

namespace roiclip {
namespace {

std::vector<std::string> caseFiles() { return testing::jsonFiles({"core/cases"}); }

bool covers(const PolygonSet& r, Point p) {
  int w = 0;
  for (const Path& ring : r.toPaths()) w -= testing::ringWinding(ring, p);
  return w == 1;
}

// One expected result of a case.
void checkExpectation(const Paths& subject, const Paths* clipPaths, const nlohmann::json& e) {
  const std::string opName = e.at("op").get<std::string>();
  const std::string rule = e.value("fillRule", "evenodd");
  const FillRule rs = parseFillRule(e.value("subjectFillRule", rule).c_str());
  const FillRule rc = parseFillRule(e.value("clipFillRule", rule).c_str());
  const bool binary = opName != "simplify";
  ASSERT_EQ(binary, clipPaths != nullptr) << "\"simplify\" takes no clip, every other op does";
  const ClipOp op = binary ? parseClipOp(opName.c_str()) : ClipOp::Union;
  const PolygonSet r = binary ? clip(op, subject, *clipPaths, rs, rc) : simplify(subject, rs);

  EXPECT_NEAR(r.area(), e.at("area").get<double>(), e.value("areaTolerance", 1e-9));
  EXPECT_EQ(testing::structureProblems(r), "");
  EXPECT_EQ(testing::geosValidityProblem(r), "");
  EXPECT_EQ(testing::geosValidityProblem(roundTo(r, 1.0)), "");
  if (e.contains("rings")) {
    EXPECT_EQ(r.ringCount(), e.at("rings").get<std::size_t>());
  }
  if (e.contains("polygons")) {
    EXPECT_EQ(r.polygons.size(), e.at("polygons").get<std::size_t>());
  }
  if (e.contains("outerVertices")) {
    const auto want = e.at("outerVertices").get<std::vector<std::size_t>>();
    ASSERT_EQ(r.polygons.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(r.polygons[i].outer.size(), want[i]) << "polygon " << i;
    }
  }
  if (e.contains("holes")) {
    const auto want = e.at("holes").get<std::vector<std::size_t>>();
    ASSERT_EQ(r.polygons.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(r.polygons[i].holes.size(), want[i]) << "polygon " << i;
    }
  }
  if (e.contains("parents")) {
    const auto want = e.at("parents").get<std::vector<std::vector<int>>>();
    ASSERT_EQ(r.polygons.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
      EXPECT_EQ(r.polygons[i].parent, want[i].at(0)) << "polygon " << i;
      EXPECT_EQ(r.polygons[i].parentHole, want[i].at(1)) << "polygon " << i;
    }
  }
  for (const char* key : {"covers", "notCovers"}) {
    if (!e.contains(key)) continue;
    for (const auto& q : e.at(key)) {
      const Point p(q.at(0).get<double>(), q.at(1).get<double>());
      EXPECT_EQ(covers(r, p), std::string(key) == "covers")
          << key << " (" << p.x << ", " << p.y << ")";
    }
  }

  // The independent oracles agree with the hand-worked answer's result.
  std::vector<const Paths*> inputs = {&subject};
  if (binary) inputs.push_back(clipPaths);
  const auto expected = [&](const std::vector<long long>& w) {
    const bool s = isFilled(rs, w[0]);
    return binary ? testing::combine(op, s, isFilled(rc, w[1])) : s;
  };
  const auto report = testing::sampleRegion(r, inputs, expected, -1, 31, 1000, 11u);
  EXPECT_EQ(report.mismatches, 0) << report.firstMismatch;
  const double truth = testing::slabArea(inputs, expected);
  EXPECT_NEAR(r.area(), truth, 1e-9 * (truth + 1));

  if (binary && op != ClipOp::Difference) {
    EXPECT_NEAR(clip(op, *clipPaths, subject, rc, rs).area(), r.area(), 1e-9) << "operands swapped";
  }
}

class Case : public ::testing::TestWithParam<std::string> {};

TEST_P(Case, MatchesHandWorkedAnswer) {
  std::ifstream in(GetParam());
  const nlohmann::json j = nlohmann::json::parse(in);
  const Paths subject = testing::readPaths(j.at("subject"));
  const bool binary = j.contains("clip");
  const Paths clipPaths = binary ? testing::readPaths(j.at("clip")) : Paths{};
  ASSERT_FALSE(j.at("expect").empty());
  for (const auto& e : j.at("expect")) {
    SCOPED_TRACE(j.value("note", "") + ": " + e.dump());
    checkExpectation(subject, binary ? &clipPaths : nullptr, e);
  }
}

INSTANTIATE_TEST_SUITE_P(HandWorked, Case, ::testing::ValuesIn(caseFiles()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return testing::testNameOf(param.param);
                         });

TEST(Case, FolderHoldsEveryHandWorkedCase) { EXPECT_GE(caseFiles().size(), 24u); }

}  // namespace
}  // namespace roiclip
