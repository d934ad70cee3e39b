// SPDX-License-Identifier: MIT
// roiclip::io WKT: reading (Boost.Geometry's read_wkt, collections, z values, errors), writing,
// and the round trip read -> clip -> write -> read.
#include <functional>
#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <roiclip/io/feature.hpp>
#include <roiclip/io/geojson.hpp>
#include <roiclip/io/wkt.hpp>

#include "expect_invalid.hpp"

namespace roiclip::io {
namespace {

const std::string kData = std::string(ROICLIP_TEST_DATA) + "/io/";

std::size_t rings(const std::vector<Feature>& features) { return allRings(features).size(); }

TEST(ParseWkt, MultiPolygonOverSeveralLines) {
  const std::vector<Feature> features = readAnyFeatures(kData + "frame.wkt");
  ASSERT_EQ(features.size(), 1u);
  ASSERT_EQ(features[0].polygons.size(), 2u);
  EXPECT_EQ(features[0].polygons[0].size(), 2u);
  EXPECT_EQ(features[0].polygons[0][0], (Path{{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  EXPECT_EQ(features[0].propertiesJson, "");
  EXPECT_DOUBLE_EQ(simplify(allRings(features), FillRule::EvenOdd).area(), 164.0);
}

TEST(ParseWkt, GeometryCollectionMembersAreFeatures) {
  const std::vector<Feature> features = parseWktFeatures(
      "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1, 0 0)), POLYGON EMPTY,"
      " GEOMETRYCOLLECTION (MULTIPOLYGON (((5 5, 6 5, 6 6, 5 5))), POLYGON ((7 7, 8 7, 8 8))))");
  ASSERT_EQ(features.size(), 3u);
  EXPECT_EQ(features[0].polygons.size(), 1u);
  EXPECT_TRUE(features[1].polygons.empty());
  EXPECT_EQ(features[2].polygons.size(), 2u);
  EXPECT_EQ(features[2].polygons[1][0].size(), 3u);  // not closed: taken as it is
  EXPECT_TRUE(parseWktFeatures("GEOMETRYCOLLECTION EMPTY").empty());
  EXPECT_TRUE(parseWktFeatures("MULTIPOLYGON EMPTY")[0].polygons.empty());
}

TEST(ParseWkt, ZAndMValuesAreDroppedWithAWarning) {
  std::vector<Warning> warnings;
  ReadOptions options;
  options.warnings = &warnings;
  const std::vector<Feature> tagged =
      readAnyFeatures(kData + "square_z.wkt", Format::Auto, options);
  EXPECT_EQ(tagged[0].polygons[0][0], (Path{{0, 0}, {10, 0}, {10, 10}, {0, 10}}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].what(),
            kData + "square_z.wkt: ignored the z coordinate of 5 points (roiclip is 2-D)");
  // Untagged x y z (Boost alone would read "0 0 1, 4 0 1" as the points (0, 0) (1, 4) ...).
  warnings.clear();
  const Paths untagged =
      allRings(parseWktFeatures("POLYGON ((0 0 1, 4 0 1, 4 3 1, 0 0 1))", "u", options));
  EXPECT_EQ(untagged, (Paths{{{0, 0}, {4, 0}, {4, 3}}}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].source, "u");
  warnings.clear();
  parseWktFeatures("POLYGON ZM ((0 0 1 2, 4 0 1 2, 4 3 1 2, 0 0 1 2))", "zm", options);
  EXPECT_EQ(warnings.size(), 1u);
  warnings.clear();
  parseWktFeatures("POLYGON ((0 0, 4 0, 4 3, 0 0))", "flat", options);
  EXPECT_TRUE(warnings.empty());
}

TEST(ParseWkt, Errors) {
  expectInvalid([] { parseWktFeatures("POLYGON ((0 0, 1 0, 1 1, 0 0)", "a.wkt"); },
                {"a.wkt: ", "not valid WKT"});
  expectInvalid([] { parseWktFeatures("POLYGON ((0 0, 1 x, 1 1, 0 0))", "b.wkt"); },
                {"b.wkt: ", "not valid WKT"});
  expectInvalid([] { parseWktFeatures("LINESTRING (0 0, 1 1)", "c.wkt"); },
                {"c.wkt: ", "unsupported geometry type \"LINESTRING\""});
  expectInvalid([] { parseWktFeatures("GEOMETRYCOLLECTION (POINT (1 1))", "d.wkt"); },
                {"d.wkt: member 0: ", "unsupported geometry type \"POINT\""});
  expectInvalid([] { parseWktFeatures("POLYGON ((0 0 0 0 0, 1 0, 1 1))", "e.wkt"); },
                {"e.wkt: ", "a point has 5 values"});
  expectInvalid([] { parseWktFeatures("POLYGON ((0 0, nan 0, 1 1, 0 0))", "f.wkt"); },
                {"f.wkt: polygon 0, ring 0 (path 0), point 1: x is not finite"});
  expectInvalid(
      [] {
        parseWktFeatures("MULTIPOLYGON (((0 0, 1 0, 1 1)), ((0 0, 1 1, 0 0)))", "g.wkt",
                         strictOptions());
      },
      {"g.wkt: polygon 1, ring 0 (path 1): ring has fewer than 3 distinct points"});
  expectInvalid([] { parseWktFeatures("GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1))", "h"); },
                {"h: ", "unbalanced parentheses"});
  expectInvalid([] { parseWktFeatures("", "i"); }, {"i: ", "expected a geometry type"});
}

TEST(ParseWktLines, LineStringsAndCollections) {
  EXPECT_EQ(parseWktLines("LINESTRING (0 0, 4 0, 4 3, 0 0)"),
            (Paths{{{0, 0}, {4, 0}, {4, 3}, {0, 0}}}));  // the repeat kept: a loop
  EXPECT_EQ(parseWktLines("GEOMETRYCOLLECTION (MULTILINESTRING ((0 0, 1 0), (2 2, 3 3)),"
                          " LINESTRING (5 5, 6 6))")
                .size(),
            3u);
  expectInvalid([] { parseWktLines("LINESTRING (0 0)", "l", strictOptions()); },
                {"l: line 0 (path 0)", "fewer than 2"});
  expectInvalid([] { parseWktLines("POLYGON ((0 0, 1 0, 1 1, 0 0))", "p"); },
                {"p: ", "unsupported geometry type \"POLYGON\""});
}

TEST(FeaturesToWkt, OrientationClosedRingsAndCollections) {
  const PolygonSet set =
      simplify(allRings(readAnyFeatures(kData + "frame.wkt")), FillRule::EvenOdd);
  EXPECT_EQ(featuresToWkt({toFeature(set)}),
            "MULTIPOLYGON(((0 10,0 0,10 0,10 10,0 10),(8 8,8 2,2 2,2 8,8 8)),"
            "((20 10,20 0,30 0,30 10,20 10)))\n");
  EXPECT_EQ(featuresToWkt({toFeature(set)}, RingOrientation::OpenCv),
            "MULTIPOLYGON(((0 10,10 10,10 0,0 0,0 10),(8 8,2 8,2 2,8 2,8 8)),"
            "((20 10,30 10,30 0,20 0,20 10)))\n");
  EXPECT_EQ(featuresToWkt({}), "GEOMETRYCOLLECTION EMPTY\n");
  EXPECT_EQ(featuresToWkt({Feature{}}), "MULTIPOLYGON EMPTY\n");
  const std::vector<Feature> two = {toFeature(set), Feature{}};
  EXPECT_EQ(parseWktFeatures(featuresToWkt(two)).size(), 2u);
  EXPECT_EQ(linesToWkt({{{0, 0}, {1.5, 2}}}), "MULTILINESTRING((0 0,1.5 2))\n");
  EXPECT_EQ(linesToWkt({}), "MULTILINESTRING EMPTY\n");
}

// Read WKT -> clip -> write WKT -> read again: the same area and ring count, every digit kept.
TEST(FeaturesToWkt, RoundTripThroughClip) {
  const std::vector<Feature> frame = readAnyFeatures(kData + "frame.wkt");
  const std::vector<Feature> roi =
      parseAnyFeatures("POLYGON ((1 1, 25.5 1, 25.5 9.25, 1 9.25, 1 1))", "roi");
  const std::vector<Feature> clipped = clipFeatures(ClipOp::Intersection, frame, "frame", roi,
                                                    "roi", FillRule::EvenOdd, FillRule::EvenOdd);
  const PolygonSet direct = intersect(allRings(frame), allRings(roi));
  ASSERT_EQ(clipped.size(), 1u);
  for (const RingOrientation orientation : {RingOrientation::Rfc7946, RingOrientation::OpenCv}) {
    const std::string text = featuresToWkt(clipped, orientation);
    const std::vector<Feature> back = parseAnyFeatures(text, "back");
    EXPECT_EQ(rings(back), direct.ringCount()) << text;
    EXPECT_EQ(simplify(allRings(back), FillRule::EvenOdd).area(), direct.area()) << text;
    EXPECT_EQ(simplify(allRings(back), FillRule::NonZero).area(), direct.area()) << text;
  }
  // Crossings with many digits come back as the same doubles.
  const std::vector<Feature> tri = parseWktFeatures("POLYGON ((0 0, 3 0, 0 3, 0 0))");
  const std::vector<Feature> third = clipFeatures(
      ClipOp::Intersection, tri, "t", parseWktFeatures("POLYGON ((0 0, 1 0, 1 1, 0 1))"), "q",
      FillRule::EvenOdd, FillRule::EvenOdd);
  const std::vector<Feature> skew = clipFeatures(
      ClipOp::Intersection, tri, "t", parseWktFeatures("POLYGON ((0.1 0, 2.9 0.7, 0.3 2.2))"), "s",
      FillRule::EvenOdd, FillRule::EvenOdd);
  for (const auto& result : {third, skew}) {
    const std::vector<Feature> back =
        parseWktFeatures(featuresToWkt(result, RingOrientation::OpenCv));
    EXPECT_EQ(allRings(back), allRings(result));
  }
}

}  // namespace
}  // namespace roiclip::io
