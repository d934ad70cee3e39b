// SPDX-License-Identifier: MIT
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <roiclip/io/geojson.hpp>

#include "expect_invalid.hpp"

namespace roiclip::io {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kData = std::string(ROICLIP_TEST_DATA) + "/io/";

std::string uniqueTempDir(const std::string& name) {
  // The pid keeps concurrent runs of the suite (several builds on one machine) apart.
  const fs::path dir =
      fs::temp_directory_path() / ("roiclip_io_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

TEST(ParsePaths, PolygonDropsClosingPoint) {
  const Paths paths = parsePaths(R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[4,3],[0,0]]]})");
  ASSERT_EQ(paths.size(), 1u);
  ASSERT_EQ(paths[0].size(), 3u);
  EXPECT_EQ(paths[0][1], Point(4, 0));
  EXPECT_EQ(paths[0][2], Point(4, 3));
}

TEST(ParsePaths, PlainJsonNeedsNoClosingPoint) {
  const Paths open = parsePaths(R"({"paths":[[[0,0],[4,0],[4,3]],[[1,1],[2,1],[2,2],[1,1]]]})");
  ASSERT_EQ(open.size(), 2u);
  EXPECT_EQ(open[0].size(), 3u);
  EXPECT_EQ(open[1].size(), 3u);  // a repeated first point is dropped as well
}

TEST(ParsePaths, AcceptsAltitudeAndKeepsDoubles) {
  const Paths paths =
      parsePaths(R"({"type":"Polygon","coordinates":[[[0.125,-7.5,3],[4e-3,0,1],[4,3,2]]]})");
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(paths[0][0], Point(0.125, -7.5));
  EXPECT_EQ(paths[0][1], Point(4e-3, 0));
}

TEST(ReadPaths, EveryRingOfEveryFeatureIsOnePath) {
  const Paths paths = readPaths(kData + "frame.geojson");
  ASSERT_EQ(paths.size(), 3u);  // outer + hole of polygon 0, outer of polygon 1; null geometry
  for (const Path& p : paths) EXPECT_EQ(p.size(), 4u);
  // Rings are taken as-is: even-odd makes the inner square a hole whatever its orientation.
  EXPECT_DOUBLE_EQ(simplify(paths, FillRule::EvenOdd).area(), 100.0 - 36.0 + 100.0);
}

TEST(ReadPaths, FeatureAndPlainFiles) {
  const Paths roi = readPaths(kData + "roi.geojson");
  ASSERT_EQ(roi.size(), 1u);
  EXPECT_EQ(roi[0].size(), 4u);
  const Paths bowtie = readPaths(kData + "bowtie.json");
  ASSERT_EQ(bowtie.size(), 1u);
  EXPECT_EQ(bowtie[0].size(), 4u);
  // Each triangle of the bow-tie keeps the part x in [2, 5] (or [5, 8]): 25 - 16.
  EXPECT_DOUBLE_EQ(intersect(bowtie, roi).area(), 2 * (25.0 - 16.0));
}

TEST(ReadPaths, FillRuleDecidesForRepeatedRings) {
  const Paths twice = readPaths(kData + "twice_wound.json");
  EXPECT_DOUBLE_EQ(simplify(twice, FillRule::NonZero).area(), 100.0);
  EXPECT_DOUBLE_EQ(simplify(twice, FillRule::EvenOdd).area(), 0.0);
}

TEST(ReadFeatures, KeepsPolygonsRingsAndStringProperties) {
  const std::vector<Feature> features = readFeatures(kData + "frame.geojson");
  ASSERT_EQ(features.size(), 2u);
  ASSERT_EQ(features[0].polygons.size(), 2u);
  EXPECT_EQ(features[0].polygons[0].size(), 2u);
  EXPECT_EQ(features[0].polygons[1].size(), 1u);
  EXPECT_EQ(features[0].properties.at("operation"), "frame");
  EXPECT_TRUE(features[1].polygons.empty());
  const std::vector<Feature> lone = readFeatures(kData + "square.geojson");
  ASSERT_EQ(lone.size(), 1u);
  ASSERT_EQ(lone[0].polygons.size(), 1u);
  EXPECT_EQ(lone[0].polygons[0][0].size(), 4u);
}

TEST(ReadFeatures, RejectsPlainPaths) {
  expectInvalid([] { readFeatures(kData + "bowtie.json"); }, {"bowtie.json", "expected GeoJSON"});
}

TEST(ToGeoJson, FeatureCollectionWithClosedRingsAreaAndRingCount) {
  const Paths frame = readPaths(kData + "frame.geojson");
  const PolygonSet set = simplify(frame, FillRule::EvenOdd);
  const json root = json::parse(toGeoJson(set, -1, RingOrientation::OpenCv));
  EXPECT_EQ(root.at("type"), "FeatureCollection");
  ASSERT_EQ(root.at("features").size(), 1u);
  const json& feature = root.at("features")[0];
  EXPECT_EQ(feature.at("type"), "Feature");
  EXPECT_DOUBLE_EQ(feature.at("properties").at("area").get<double>(), set.area());
  EXPECT_EQ(feature.at("properties").at("rings").get<std::size_t>(), set.ringCount());
  const json& geometry = feature.at("geometry");
  EXPECT_EQ(geometry.at("type"), "MultiPolygon");
  const json& polygons = geometry.at("coordinates");
  ASSERT_EQ(polygons.size(), set.polygons.size());
  for (std::size_t p = 0; p < set.polygons.size(); ++p) {
    ASSERT_EQ(polygons[p].size(), 1 + set.polygons[p].holes.size());
    for (std::size_t r = 0; r < polygons[p].size(); ++r) {
      const json& ring = polygons[p][r];
      const Path& expected = r == 0 ? set.polygons[p].outer : set.polygons[p].holes[r - 1];
      ASSERT_EQ(ring.size(), expected.size() + 1);
      EXPECT_EQ(ring.front(), ring.back()) << "GeoJSON rings repeat their first point";
      EXPECT_EQ(ring[1][0].get<double>(), expected[1].x);
      EXPECT_EQ(ring[1][1].get<double>(), expected[1].y);
    }
  }
  // Reading the output back gives the same region, with the same orientations.
  const Paths back = parsePaths(toGeoJson(set, 2, RingOrientation::OpenCv));
  EXPECT_EQ(back, set.toPaths());
}

TEST(ToGeoJson, Rfc7946OrderByDefault) {
  const PolygonSet set = simplify(readPaths(kData + "frame.geojson"), FillRule::EvenOdd);
  const Paths back = parsePaths(toGeoJson(set));
  const Paths native = set.toPaths();
  ASSERT_EQ(back.size(), native.size());
  for (std::size_t r = 0; r < back.size(); ++r) {
    // The same ring, reversed: exterior rings positive, holes negative.
    EXPECT_DOUBLE_EQ(signedArea(back[r]), -signedArea(native[r]));
    EXPECT_EQ(back[r].front(), native[r].front()) << "the first point stays first";
  }
  EXPECT_GT(signedArea(back[0]), 0.0);  // polygon 0's exterior
  EXPECT_LT(signedArea(back[1]), 0.0);  // its hole
  EXPECT_DOUBLE_EQ(simplify(back, FillRule::NonZero).area(), set.area());
}

TEST(ToGeoJson, EmptySetIsAnEmptyMultiPolygon) {
  const json root = json::parse(toGeoJson(PolygonSet{}));
  const json& feature = root.at("features")[0];
  EXPECT_TRUE(feature.at("geometry").at("coordinates").empty());
  EXPECT_EQ(feature.at("properties").at("rings"), 0);
  EXPECT_EQ(feature.at("properties").at("area"), 0.0);
}

TEST(WriteGeoJson, WritesFileAndLeavesNoTemporary) {
  const std::string dir = uniqueTempDir("write");
  const std::string file = dir + "/out.geojson";
  const PolygonSet set = simplify(readPaths(kData + "square.geojson"), FillRule::NonZero);
  writeGeoJson(set, file);
  EXPECT_DOUBLE_EQ(simplify(readPaths(file), FillRule::NonZero).area(), 100.0);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u);
  fs::remove_all(dir);
}

TEST(WriteGeoJson, UnwritableFolderThrowsAndWritesNothing) {
  const std::string dir = uniqueTempDir("nowrite");
  const std::string file = dir + "/missing/out.geojson";
  EXPECT_THROW(writeGeoJson(PolygonSet{}, file), Error);
  EXPECT_FALSE(fs::exists(file));
  fs::remove_all(dir);
}

// --- errors: every one names the input and the problem ---

TEST(ReadErrors, MissingFile) {
  expectInvalid([] { readPaths(kData + "no_such_file.json"); },
                {"no_such_file.json", "cannot open"});
}

TEST(ReadErrors, UnparsableJson) {
  expectInvalid([] { readPaths(kData + "bad_syntax.json"); },
                {"bad_syntax.json", "not valid JSON", "line 1"});
  expectInvalid([] { parsePaths("", "empty.json"); }, {"empty.json", "not valid JSON"});
}

TEST(ReadErrors, WrongStructure) {
  expectInvalid([] { readPaths(kData + "bad_structure.json"); },
                {"bad_structure.json", "unsupported geometry type \"LineString\""});
  expectInvalid([] { parsePaths("[1, 2]", "a.json"); }, {"a.json", "expected a JSON object"});
  expectInvalid([] { parsePaths(R"({"foo": 1})", "b.json"); }, {"b.json", "\"type\""});
  expectInvalid([] { parsePaths(R"({"type":"Polygon"})", "c.json"); },
                {"c.json", "without \"coordinates\""});
  expectInvalid([] { parsePaths(R"({"type":"FeatureCollection"})", "d.json"); },
                {"d.json", "\"features\""});
  expectInvalid([] { parsePaths(R"({"type":"Feature","properties":{}})", "e.json"); },
                {"e.json", "without \"geometry\""});
  expectInvalid([] { parsePaths(R"({"paths": {"a": 1}})", "f.json"); },
                {"f.json", "\"paths\" must be an array"});
  expectInvalid([] { parsePaths(R"({"paths": [[[0,0],[1],[1,1]]]})", "g.json"); },
                {"g.json", "path 0, point 1", "expected [x, y]"});
  expectInvalid([] { parsePaths(R"({"type":"Polygon","coordinates":[]})", "h.json"); },
                {"h.json", "polygon has no rings"});
  expectInvalid([] { parsePaths(R"({"type":"Polygon","coordinates":[5]})", "i.json"); },
                {"i.json", "ring 0", "expected an array of points"});
}

TEST(ReadErrors, StringOrNullWhereANumberBelongs) {
  expectInvalid([] { readPaths(kData + "string_coordinate.json"); },
                {"string_coordinate.json", "path 0, point 2", "y is not a number"});
  expectInvalid([] { readPaths(kData + "null_coordinate.geojson"); },
                {"null_coordinate.geojson", "polygon 0, ring 1", "point 1", "x is not a number"});
}

TEST(ReadErrors, InfiniteLiteral) {
  expectInvalid([] { parsePaths(R"({"paths": [[[0,0],[1e999,0],[1,1]]]})", "inf.json"); },
                {"inf.json", "not valid JSON", "1e999"});
}

TEST(ReadErrors, RingWithFewerThanThreeDistinctPoints) {
  // Refused only when strict (the CLI's --strict); by default kept, and the core ignores them.
  expectInvalid([] { readPaths(kData + "degenerate_ring.geojson", strictOptions()); },
                {"degenerate_ring.geojson", "polygon 1, ring 0", "(path 1)", "fewer than 3"});
  expectInvalid(
      [] {
        parsePaths(R"({"paths": [[[0,0],[1,0],[1,1]], [[2,2],[3,3]]]})", "p.json", strictOptions());
      },
      {"p.json", "path 1", "fewer than 3"});
  const Paths kept = readPaths(kData + "degenerate_ring.geojson");
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[1].size(), 4u);
  EXPECT_DOUBLE_EQ(simplify(kept, FillRule::EvenOdd).area(), 50.0);
}

// --- open polylines (clipLines input and output) ---

TEST(ParseLines, LineStringKeepsEveryPointAndAltitudeIsIgnored) {
  const Paths lines =
      parseLines(R"({"type":"LineString","coordinates":[[0,0,9],[4,0],[4,3.5],[0,0]]})");
  ASSERT_EQ(lines.size(), 1u);
  // The repeated first point stays: the core reads such a polyline as a loop.
  EXPECT_EQ(lines[0], (Path{{0, 0}, {4, 0}, {4, 3.5}, {0, 0}}));
}

TEST(ParseLines, MultiLineStringFeature) {
  const Paths lines = readLines(kData + "lines_cross.geojson");
  EXPECT_EQ(lines, (Paths{{{-5, 5}, {5, 5}, {5, 15}}, {{2, 2}, {8, 2}}, {{-2, 10}, {12, 10}}}));
}

TEST(ParseLines, FeatureCollectionAndNestedGeometryCollections) {
  // Feature 0: a GeometryCollection of a LineString and a GeometryCollection holding a
  // MultiLineString; feature 1: null geometry; feature 2: a closed LineString (a loop).
  const Paths lines = readLines(kData + "lines_collection.geojson");
  EXPECT_EQ(lines, (Paths{{{0, 0}, {1, 0}},
                          {{0, 1}, {1, 1}, {1, 2}},
                          {{0, 2}, {1, 3}},
                          {{5, 5}, {6, 5}, {6, 6}, {5, 5}}}));
}

TEST(ParseLines, PlainJsonKeepsTheClosingPoint) {
  const Paths lines = readLines(kData + "lines_loop.json");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].size(), 4u);  // parsePaths() would drop the repeat and give 3
  EXPECT_EQ(lines[0].front(), lines[0].back());
  ReadOptions lenient;  // path 1 is no ring
  lenient.allowDegenerateRings = true;
  EXPECT_EQ(readPaths(kData + "lines_loop.json", lenient)[0].size(), 3u);
  EXPECT_EQ(lines[1], (Path{{-4, 4}, {4, 4}}));
}

TEST(ParseLines, EmptyInputsAndZeroLengthLinesAreValid) {
  EXPECT_TRUE(parseLines(R"({"type":"MultiLineString","coordinates":[]})").empty());
  EXPECT_TRUE(parseLines(R"({"type":"FeatureCollection","features":[]})").empty());
  EXPECT_TRUE(parseLines(R"({"type":"GeometryCollection","geometries":[]})").empty());
  EXPECT_TRUE(parseLines(R"({"paths":[]})").empty());
  // Two equal points: valid (GeoJSON asks only for 2 positions); the core gives nothing for it.
  const Paths dot = parseLines(R"({"type":"LineString","coordinates":[[3,3],[3,3]]})");
  ASSERT_EQ(dot.size(), 1u);
  const Paths square = readPaths(kData + "square.geojson");
  EXPECT_TRUE(clipLines(dot, square, FillRule::EvenOdd, LinePart::Inside).empty());
  EXPECT_TRUE(clipLines(dot, square, FillRule::EvenOdd, LinePart::Outside).empty());
}

TEST(LineErrors, WrongStructure) {
  expectInvalid([] { readLines(kData + "square.geojson"); },
                {"square.geojson", "unsupported geometry type \"Polygon\"", "LineString"});
  const struct {
    const char* text;
    const char* where;
    const char* problem;
  } cases[] = {
      {"[1, 2]", "", "expected a JSON object"},
      {R"({"type":"LineString"})", "geometry", "LineString without \"coordinates\""},
      {R"({"type":"MultiLineString","coordinates":{}})", "geometry",
       "MultiLineString coordinates must be an array"},
      {R"({"type":"GeometryCollection"})", "geometry", "without a \"geometries\" array"},
      {R"({"type":"GeometryCollection","geometries":[
           {"type":"LineString","coordinates":[[0,0],[1,1]]},
           {"type":"MultiPolygon","coordinates":[]}]})",
       "geometry, member 1", "unsupported geometry type \"MultiPolygon\""},
      {R"({"type":"Feature","properties":{}})", "feature", "without \"geometry\""},
      {R"({"paths": [[[0,0],[1,1]], 7]})", "path 1", "expected an array of points"},
      {R"({"paths": [[[0,0],[1,1,1,1]]]})", "path 0, point 1", "expected [x, y]"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.text);
    expectInvalid([&] { parseLines(c.text, "bad.json"); }, {"bad.json: ", c.where, c.problem});
  }
}

TEST(LineErrors, NaNAndNonNumbersNameTheLine) {
  // Python's json.dumps writes NaN as a bare NaN, which is not JSON.
  expectInvalid([] { readLines(kData + "lines_nan.json"); },
                {"lines_nan.json", "not valid JSON", "line 1"});
  expectInvalid(
      [] {
        parseLines(R"({"type":"FeatureCollection","features":[
          {"type":"Feature","geometry":{"type":"LineString","coordinates":[[0,0],[1,1]]}},
          {"type":"Feature","geometry":{"type":"MultiLineString",
                                        "coordinates":[[[0,0],[1,1]],[["NaN",0],[1,1]]]}}]})",
                   "s.json");
      },
      {"s.json", "feature 1, line 1 (path 2), point 0", "x is not a number (string)"});
  expectInvalid([] { parseLines(R"({"paths": [[[0,0],[1,null]]]})", "n.json"); },
                {"n.json", "path 0, point 1", "y is not a number (null)"});
  expectInvalid([] { readLines(kData + "no_such_file.json"); },
                {"no_such_file.json", "cannot open"});
  expectInvalid([] { readLines(kData + "bad_syntax.json"); },
                {"bad_syntax.json", "not valid JSON"});
}

TEST(LineErrors, LineWithFewerThanTwoPoints) {
  expectInvalid(
      [] { parseLines(R"({"paths": [[[0,0],[1,1]], [[2,2]]]})", "p.json", strictOptions()); },
      {"p.json", "path 1", "line has fewer than 2 points"});
  expectInvalid(
      [] { parseLines(R"({"type":"LineString","coordinates":[]})", "q.json", strictOptions()); },
      {"q.json", "geometry, line 0 (path 0)", "fewer than 2 points"});
  const Paths kept = parseLines(R"({"paths": [[[0,0],[4,0]], [[2,2]], []]})", "p.json");
  ASSERT_EQ(kept.size(), 3u);
  // The core gives nothing for them, as the header promises.
  const Paths square = readPaths(kData + "square.geojson");
  EXPECT_EQ(clipLines(kept, square, FillRule::EvenOdd), (Paths{{{0, 0}, {4, 0}}}));
}

TEST(LinesToGeoJson, MultiLineStringWithLengthAndCountRoundTrips) {
  const Paths lines = {
      {{0, 0}, {3, 4}, {3, 10}}, {{1.5, -2.25}, {1.5, 0}}, {{5, 5}, {6, 5}, {5, 5}}};
  const json root = json::parse(linesToGeoJson(lines));
  EXPECT_EQ(root.at("type"), "FeatureCollection");
  ASSERT_EQ(root.at("features").size(), 1u);
  const json& feature = root.at("features")[0];
  EXPECT_EQ(feature.at("type"), "Feature");
  EXPECT_EQ(feature.at("geometry").at("type"), "MultiLineString");
  EXPECT_EQ(feature.at("geometry").at("coordinates").size(), 3u);
  EXPECT_EQ(feature.at("geometry").at("coordinates")[2].size(), 3u);  // no point added or dropped
  EXPECT_DOUBLE_EQ(feature.at("properties").at("length").get<double>(), (5 + 6) + 2.25 + 2);
  EXPECT_EQ(feature.at("properties").at("lines").get<int>(), 3);
  EXPECT_FALSE(feature.at("properties").contains("ignoredClipRings"));
  EXPECT_EQ(parseLines(linesToGeoJson(lines)), lines);
  EXPECT_EQ(parseLines(linesToGeoJson(lines, 2)), lines);
  // The region's degenerate rings, when there are any, after the two.
  const json counted = json::parse(linesToGeoJson(lines, -1, 2)).at("features")[0];
  EXPECT_EQ(counted.at("properties").dump(),
            json({{"length", (5 + 6) + 2.25 + 2}, {"lines", 3}, {"ignoredClipRings", 2}}).dump());
  EXPECT_EQ(formatLines(lines, Format::GeoJson, -1, 2), linesToGeoJson(lines, -1, 2));
  EXPECT_EQ(formatLines(lines, Format::Wkt, -1, 2), formatLines(lines, Format::Wkt));  // no props
}

TEST(LinesToGeoJson, NoLinesIsAnEmptyMultiLineString) {
  const json feature = json::parse(linesToGeoJson({})).at("features")[0];
  EXPECT_EQ(feature.at("geometry").at("type"), "MultiLineString");
  EXPECT_TRUE(feature.at("geometry").at("coordinates").empty());
  EXPECT_EQ(feature.at("properties").at("length"), 0.0);
  EXPECT_EQ(feature.at("properties").at("lines"), 0);
  EXPECT_TRUE(parseLines(linesToGeoJson({})).empty());
}

TEST(WriteLinesGeoJson, WritesFileAndLeavesNoTemporary) {
  const std::string dir = uniqueTempDir("write_lines");
  const std::string file = dir + "/lines.geojson";
  const Paths lines = readLines(kData + "lines_cross.geojson");
  writeLinesGeoJson(lines, file);
  EXPECT_EQ(readLines(file), lines);
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u);
  EXPECT_THROW(writeLinesGeoJson(lines, dir + "/missing/lines.geojson"), Error);
  EXPECT_FALSE(fs::exists(dir + "/missing"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace roiclip::io
