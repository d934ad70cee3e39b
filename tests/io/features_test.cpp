// SPDX-License-Identifier: MIT
// roiclip::io features: ids and properties kept through reading, the feature-wise operations and
// writing; ring orientation; format detection; the snapping check; warnings for z coordinates.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <roiclip/io/atomic_file.hpp>
#include <roiclip/io/feature.hpp>
#include <roiclip/io/geojson.hpp>

#include "expect_invalid.hpp"

namespace roiclip::io {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kData = std::string(ROICLIP_TEST_DATA) + "/io/";

// Even-odd: the parcels file winds its hole the same way as its outer ring.
double area(const Feature& feature) {
  return simplify(allRings({feature}), FillRule::EvenOdd).area();
}

TEST(ReadFeatures, KeepIdAndEveryPropertyAsJsonText) {
  const std::vector<Feature> features = readFeatures(kData + "parcels.geojson");
  ASSERT_EQ(features.size(), 3u);
  EXPECT_EQ(features[0].id, "\"a\"");
  EXPECT_EQ(features[0].propertiesJson,
            R"({"name":"left","area_m2":12.5,"tags":["x","y"],"owner":null})");
  EXPECT_EQ(features[0].properties.at("name"), "left");  // string values, as before
  EXPECT_EQ(features[0].properties.count("area_m2"), 0u);
  EXPECT_EQ(features[1].id, "7");
  EXPECT_EQ(features[1].propertiesJson,
            R"({"name":"right","n":3,"nested":{"b":1,"a":[true,false]}})");
  EXPECT_EQ(features[2].id, "");
  EXPECT_EQ(features[2].propertiesJson, "null");
  // A bare geometry has no feature, hence no properties at all (not even null).
  EXPECT_EQ(readFeatures(kData + "square.geojson")[0].propertiesJson, "");
}

TEST(ReadFeatures, GeometryCollectionOfPolygonsNestedToo) {
  const std::vector<Feature> features = readFeatures(kData + "parcels.geojson");
  ASSERT_EQ(features[2].polygons.size(), 2u);  // a Polygon and a nested MultiPolygon
  EXPECT_DOUBLE_EQ(area(features[2]), 4.0 + 0.5);
  // parsePaths() takes them too; a line in a polygon collection is still refused.
  EXPECT_EQ(readPaths(kData + "parcels.geojson").size(), 5u);
  EXPECT_THROW(parsePaths(R"({"type":"GeometryCollection","geometries":[
                 {"type":"LineString","coordinates":[[0,0],[1,1]]}]})"),
               InvalidInputError);
}

TEST(FeaturesToGeoJson, IdsAndPropertiesRoundTripInOrder) {
  const std::vector<Feature> features = readFeatures(kData + "parcels.geojson");
  const std::string text = featuresToGeoJson(features);
  const std::vector<Feature> back = parseFeatures(text);
  ASSERT_EQ(back.size(), features.size());
  for (std::size_t f = 0; f < back.size(); ++f) {
    EXPECT_EQ(back[f].id, features[f].id);
    EXPECT_EQ(back[f].propertiesJson, features[f].propertiesJson);  // key order kept
    EXPECT_DOUBLE_EQ(area(back[f]), area(features[f]));
  }
  const json root = json::parse(text);
  EXPECT_FALSE(root.at("features")[2].contains("id"));
  EXPECT_TRUE(root.at("features")[2].at("properties").is_null());
}

TEST(SimplifyFeatures, OneResultPerFeatureWithItsIdAndProperties) {
  const std::vector<Feature> features = readFeatures(kData + "parcels.geojson");
  const std::vector<Feature> result = simplifyFeatures(features, "parcels", FillRule::EvenOdd);
  ASSERT_EQ(result.size(), 3u);
  EXPECT_EQ(result[0].id, "\"a\"");
  EXPECT_EQ(result[1].propertiesJson, features[1].propertiesJson);
  EXPECT_EQ(result[1].properties.at("name"), "right");
  EXPECT_DOUBLE_EQ(area(result[0]), 60.0);
  EXPECT_DOUBLE_EQ(area(result[1]), 60.0 - 4.0);
  // Dissolved: one feature, the summary properties.
  const std::vector<Feature> one = simplifyFeatures({dissolve(features)}, "p", FillRule::EvenOdd);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].id, "");
  EXPECT_EQ(json::parse(one[0].propertiesJson),
            json::parse(R"({"area":120.5,"rings":4})"));  // a and 7 merge
}

TEST(ClipFeatures, EachSubjectFeatureByTheUnionOfTheClipFeatures) {
  const std::vector<Feature> parcels = readFeatures(kData + "parcels.geojson");
  const std::vector<Feature> rois = readFeatures(kData + "two_rois.geojson");
  const std::vector<Feature> result = clipFeatures(ClipOp::Intersection, parcels, "p", rois, "r",
                                                   FillRule::EvenOdd, FillRule::EvenOdd);
  ASSERT_EQ(result.size(), 3u);
  // Parcel a = [0,6]x[0,10], ROI A = [2,8]x[-1,11], ROI B = [5,14]x[5,11]: the part of a in
  // A or B is [2,6]x[0,10] (A and B overlap; their union counts the overlap once, where one
  // even-odd path set would cancel it).
  EXPECT_DOUBLE_EQ(area(result[0]), 40.0);
  EXPECT_DOUBLE_EQ(area(result[1]), 20.0 + 20.0);
  EXPECT_TRUE(result[2].polygons.empty());
  EXPECT_EQ(result[1].id, "7");
  EXPECT_EQ(result[2].propertiesJson, "null");
  // Dissolved, as before: every ring of each operand in one path set.
  const std::vector<Feature> one =
      clipFeatures(ClipOp::Intersection, {dissolve(parcels)}, "p", {dissolve(rois)}, "r",
                   FillRule::EvenOdd, FillRule::EvenOdd);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_DOUBLE_EQ(area(one[0]), intersect(allRings(parcels), allRings(rois)).area());
}

TEST(ClipFeatures, CoreErrorsNameTheFileAndTheFlatPathIndex) {
  const std::vector<Feature> parcels = readFeatures(kData + "parcels.geojson");
  std::vector<Feature> far = parcels;
  far[1].polygons[0][0][1].x = 5e6;  // feature 1, ring 0 is path 1 of the file
  try {
    clipFeatures(ClipOp::Intersection, parcels, "p.json", far, "far.json", FillRule::EvenOdd,
                 FillRule::EvenOdd, Grid::fixed(256));  // 5e6 is beyond its range
    ADD_FAILURE() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_EQ(e.location().source, "far.json");
    EXPECT_EQ(e.location().operand, Operand::Clip);
    EXPECT_EQ(e.location().path, 1u);
    EXPECT_EQ(e.location().vertex, 1u);
  }
  try {
    simplifyFeatures(far, "far.json", FillRule::EvenOdd, Grid::fixed(256));
    ADD_FAILURE() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("far.json: path 1, vertex 1: x = ", 0), 0u) << e.what();
  }
}

TEST(OrientRing, Rfc7946ExteriorsPositiveHolesNegativeOpenCvTheOpposite) {
  const Path positive = {{0, 0}, {4, 0}, {4, 3}};  // shoelace > 0
  const Path negative = orientRing(positive, false, RingOrientation::Rfc7946);
  EXPECT_EQ(negative, (Path{{0, 0}, {4, 3}, {4, 0}}));
  EXPECT_EQ(orientRing(positive, true, RingOrientation::Rfc7946), positive);
  EXPECT_EQ(orientRing(positive, true, RingOrientation::OpenCv), negative);
  EXPECT_EQ(orientRing(negative, false, RingOrientation::OpenCv), positive);
  const Path flat = {{0, 0}, {1, 1}, {2, 2}};
  EXPECT_EQ(orientRing(flat, true, RingOrientation::OpenCv), flat);
  EXPECT_EQ(parseRingOrientation("OpenCV"), RingOrientation::OpenCv);
  EXPECT_THROW(parseRingOrientation("clockwise"), InvalidInputError);
}

TEST(ParseAnyFeatures, DetectsTheFormatFromTheText) {
  EXPECT_EQ(parseAnyFeatures("  POLYGON((0 0, 1 0, 1 1, 0 0))").at(0).polygons.size(), 1u);
  EXPECT_EQ(parseAnyFeatures("\n{\"paths\": [[[0,0],[1,0],[1,1]], [[5,5],[6,5],[6,6]]]}")
                .at(0)
                .polygons.size(),
            2u);
  EXPECT_THROW(parseAnyFeatures("POLYGON((0 0, 1 0, 1 1, 0 0))", "x", Format::GeoJson),
               InvalidInputError);
  EXPECT_THROW(parseAnyFeatures("{}", "x", Format::Wkt), InvalidInputError);
  EXPECT_EQ(parseFormat("WKT"), Format::Wkt);
  EXPECT_THROW(parseFormat("shp"), InvalidInputError);
}

TEST(ReadOptions, ZCoordinatesAreDroppedWithOneWarning) {
  std::vector<Warning> warnings;
  ReadOptions options;
  options.warnings = &warnings;
  const Paths paths = parsePaths(
      R"({"type":"Polygon","coordinates":[[[0,0,1],[4,0,1],[4,3,2],[0,0,1]]]})", "z.json", options);
  EXPECT_EQ(paths, (Paths{{{0, 0}, {4, 0}, {4, 3}}}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0].what(), "z.json: ignored the z coordinate of 4 points (roiclip is 2-D)");
  warnings.clear();
  parseLines(R"({"type":"LineString","coordinates":[[0,0],[4,0]]})", "flat.json", options);
  EXPECT_TRUE(warnings.empty());
}

TEST(SnapWarnings, PixelCoordinatesNoneGisCoordinatesOne) {
  const Grid grid = Grid::fixed(256);  // 1/256 px
  EXPECT_TRUE(snapWarnings(readPaths(kData + "frame.geojson"), "frame", grid).empty());
  EXPECT_TRUE(snapWarnings({{{0.5, 0.25}, {1.0 / 256, 3}, {7, 7}}}, "s", grid).empty());
  // 0.2 px is 51.2 units: moved by 0.2 units, not counted; 0.123456789 px moves by 0.395 units.
  const SnapShift shift = measureSnapShift(readPaths(kData + "gis_square.geojson"), grid);
  EXPECT_EQ(shift.vertices, 4u);
  EXPECT_EQ(shift.moved, 2u);
  EXPECT_NEAR(shift.largest, 0.3950 / 256, 1e-5);
  EXPECT_EQ(shift.vertex, 0u);
  const std::vector<Warning> w = snapWarnings(readPaths(kData + "gis_square.geojson"), "g", grid);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].what().rfind("g: snapping to the 1/256 px grid moved 2 of 4 vertices", 0), 0u)
      << w[0].what();
  // A grid fine enough for the digits there are: no warning.
  EXPECT_TRUE(snapWarnings({{{0.2, 0.2}, {1, 0}, {1, 1}}}, "f", Grid{1024.0 * 1024 * 64}).empty());
  // A fitted grid (the default) moves nothing by a visible amount: never a warning.
  EXPECT_TRUE(snapWarnings(readPaths(kData + "gis_square.geojson"), "g", Grid{}).empty());
}

TEST(WriteFileAtomically, ADirectoryIsSaidToBeOne) {
  const fs::path dir =
      fs::temp_directory_path() / ("roiclip_features_test_dir_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  try {
    writeFileAtomically(dir, "text");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + dir.string() + ": is a directory");
  }
  EXPECT_TRUE(fs::is_directory(dir));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.parent_path())) {
    entries += entry.path().filename().string().rfind("." + dir.filename().string(), 0) == 0;
  }
  EXPECT_EQ(entries, 0u) << "no temporary left next to it";
  try {
    readText(dir.string());
    ADD_FAILURE() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_EQ(std::string(e.what()), dir.string() + ": is a directory");
  }
  fs::remove_all(dir);
}

// Degenerate rings (fewer than 3 distinct points, or all points on a line) through every reader:
// kept by default, contributing nothing, and counted as ignoredRings; refused when strict.
TEST(DegenerateRings, EveryReaderKeepsThemAndTheOperationsCountThem) {
  const std::vector<std::pair<std::string, Format>> inputs = {
      {R"({"type":"MultiPolygon","coordinates":[[[[0,0],[10,0],[10,10],[0,10],[0,0]]],
          [[[20,20],[21,21],[20,20]]], [[[30,30],[31,31],[32,32],[30,30]]]]})",
       Format::GeoJson},
      {R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":null,
          "geometry":{"type":"MultiPolygon","coordinates":[[[[0,0],[10,0],[10,10],[0,10]]],
          [[[20,20],[21,21]]], [[[30,30],[31,31],[32,32]]]]}}]})",
       Format::GeoJson},
      {R"({"paths": [[[0,0],[10,0],[10,10],[0,10]], [[20,20],[21,21]], [[30,30],[31,31],[32,32]]]})",
       Format::GeoJson},
      {"MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0)), ((20 20, 21 21, 20 20)), "
       "((30 30, 31 31, 32 32, 30 30)))",
       Format::Wkt},
      {"GEOMETRYCOLLECTION (POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0)), POLYGON ((20 20, 20 20, 20 "
       "20)), POLYGON ((30 30, 31 31, 32 32, 30 30)))",
       Format::Wkt},
  };
  for (const auto& [text, format] : inputs) {
    SCOPED_TRACE(text);
    const std::vector<Feature> features = parseAnyFeatures(text, "in", format);
    ASSERT_EQ(allRings(features).size(), 3u);
    const std::vector<Feature> simple = simplifyFeatures(features, "in", FillRule::EvenOdd);
    ASSERT_EQ(simple.size(), features.size());
    std::size_t ignored = 0;
    double area = 0;
    for (const Feature& f : simple) {
      ignored += f.ignoredRings;
      for (const Paths& polygon : f.polygons) area -= signedArea(polygon[0]);
    }
    EXPECT_EQ(ignored, 2u);
    EXPECT_NEAR(std::fabs(area), 100.0, 0);
    const std::vector<Feature> clipped =
        clipFeatures(ClipOp::Intersection, features, "in",
                     {toFeature(simplify({{{0, 0}, {5, 0}, {5, 5}}}, FillRule::NonZero))}, "clip",
                     FillRule::EvenOdd, FillRule::NonZero);
    ignored = 0;
    for (const Feature& f : clipped) {
      ignored += f.ignoredRings;
      EXPECT_EQ(f.ignoredClipRings, 0u);
    }
    EXPECT_EQ(ignored, 2u);
    // The same rings as the clip operand: counted as the clip's, in every result (two subject
    // features without properties, so they get the summary properties).
    std::vector<Feature> subjects(2);
    subjects[0].polygons = {{{{0, 0}, {5, 0}, {5, 5}}}};
    subjects[1].polygons = {{{{1, 0}, {6, 0}, {6, 5}}}};
    const std::vector<Feature> byDegenerate =
        clipFeatures(ClipOp::Intersection, subjects, "subject", features, "in", FillRule::NonZero,
                     FillRule::EvenOdd);
    ASSERT_EQ(byDegenerate.size(), 2u);
    for (const Feature& f : byDegenerate) {
      EXPECT_EQ(f.ignoredRings, 0u);
      EXPECT_EQ(f.ignoredClipRings, 2u);
      EXPECT_NE(f.propertiesJson.find("\"ignoredClipRings\":2"), std::string::npos)
          << f.propertiesJson;
      EXPECT_EQ(f.propertiesJson.find("\"ignoredRings\""), std::string::npos) << f.propertiesJson;
    }
    // The summary properties name the count (features with their own properties keep them).
    for (std::size_t i = 0; i < simple.size(); ++i) {
      if (features[i].propertiesJson.empty() && simple[i].ignoredRings > 0) {
        EXPECT_NE(simple[i].propertiesJson.find("\"ignoredRings\":" +
                                                std::to_string(simple[i].ignoredRings)),
                  std::string::npos)
            << simple[i].propertiesJson;
      }
    }
    // Strict (the CLI's --strict): the reader refuses the file, naming the ring.
    expectInvalid([&] { parseAnyFeatures(text, "in", format, strictOptions()); },
                  {"in: ", "path 1", "fewer than 3 distinct points"});
  }
}

// Degenerate means "all points on one line on the call's grid" (countDegeneratePaths()), so
// counting and refusing take the same rings: fewer than 3 distinct points, 3 or more on one
// line, and a ring that only snapping puts on one line.
TEST(DegenerateRings, RefuseTakesExactlyTheRingsCountCounts) {
  const Path square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Path twoPoints = {{20, 20}, {21, 21}, {20, 20}};
  const Path onALine = {{30, 30}, {31, 31}, {32, 32}};
  const Path thin = {{0, 0}, {10, 0}, {5, 0.1}};  // area 0.5, but on one line at 1 unit per px
  const Grid fine = resolveGrid(Grid::fitted(), {square, thin});
  EXPECT_EQ(checkDegenerateRings({square, thin}, fine, Operand::Subject), 0u);
  EXPECT_EQ(checkDegenerateRings({square, thin}, fine, Operand::Subject, DegenerateRings::Refuse),
            0u);
  EXPECT_EQ(
      checkDegenerateRings({square, twoPoints, onALine, thin}, Grid::fixed(1), Operand::Subject),
      3u);
  struct Case {
    Paths rings;
    std::size_t path;
    const char* problem;
  };
  for (const Case& c :
       {Case{{square, twoPoints, onALine}, 1, "ring has fewer than 3 distinct points"},
        Case{{square, onALine, twoPoints}, 1, "ring has no area (all its points on one line)"},
        Case{{square, square, thin}, 2, "ring has no area (all its points on one line)"}}) {
    try {
      checkDegenerateRings(c.rings, Grid::fixed(1), Operand::Clip, DegenerateRings::Refuse);
      ADD_FAILURE() << "not refused: path " << c.path;
    } catch (const InvalidInputError& e) {
      EXPECT_EQ(e.location().operand, Operand::Clip);
      EXPECT_EQ(e.location().path, c.path);
      EXPECT_EQ(e.problem(), c.problem);
      EXPECT_EQ(std::string(e.what()), "clip path " + std::to_string(c.path) + ": " + c.problem);
    }
  }
}

// The feature-wise operations refuse with the file and the flat path index, in either operand,
// and the clip operand's are refused (and counted) also without any subject feature.
TEST(DegenerateRings, FeatureWiseOperationsRefuseThemNamingFileAndFlatPath) {
  const std::string text =
      R"({"type":"FeatureCollection","features":[
          {"type":"Feature","properties":{"n":1},"geometry":{"type":"Polygon","coordinates":
           [[[0,0],[10,0],[10,10],[0,10],[0,0]]]}},
          {"type":"Feature","properties":{"n":2},"geometry":{"type":"MultiPolygon","coordinates":
           [[[[20,0],[30,0],[30,10],[20,0]]], [[[40,0],[41,1],[42,2],[40,0]]]]}}]})";
  const std::vector<Feature> features = parseAnyFeatures(text, "in");
  ASSERT_EQ(features.size(), 2u);
  // The strict reader keeps the flat ring (3 distinct points): the operations decide on the grid.
  EXPECT_EQ(allRings(parseAnyFeatures(text, "in", Format::Auto, strictOptions())).size(), 3u);
  const std::vector<Feature> simple = simplifyFeatures(features, "in", FillRule::EvenOdd);
  EXPECT_EQ(simple[0].ignoredRings + simple[1].ignoredRings, 1u);
  EXPECT_EQ(countDegenerateRings(features, {}), 1u);
  const std::initializer_list<std::string> flat = {"in: path 2: ring has no area"};
  expectInvalid(
      [&] { simplifyFeatures(features, "in", FillRule::EvenOdd, {}, DegenerateRings::Refuse); },
      flat);
  const std::vector<Feature> square = {features[0]};
  expectInvalid(
      [&] {
        clipFeatures(ClipOp::Intersection, features, "in", square, "clip", FillRule::EvenOdd,
                     FillRule::EvenOdd, {}, DegenerateRings::Refuse);
      },
      flat);
  EXPECT_NO_THROW(clipFeatures(ClipOp::Intersection, square, "subject", square, "clip",
                               FillRule::EvenOdd, FillRule::EvenOdd, {}, DegenerateRings::Refuse));
  // As the clip operand, with no subject feature at all: no result carries the count, which
  // countDegenerateRings() gives; Refuse still refuses.
  EXPECT_TRUE(clipFeatures(ClipOp::Intersection, {}, "subject", features, "in", FillRule::EvenOdd,
                           FillRule::EvenOdd)
                  .empty());
  expectInvalid(
      [&] {
        clipFeatures(ClipOp::Intersection, {}, "subject", features, "in", FillRule::EvenOdd,
                     FillRule::EvenOdd, {}, DegenerateRings::Refuse);
      },
      flat);
  const std::vector<Feature> clipped =
      clipFeatures(ClipOp::Intersection, square, "subject", features, "in", FillRule::EvenOdd,
                   FillRule::EvenOdd);
  ASSERT_EQ(clipped.size(), 1u);
  EXPECT_EQ(clipped[0].ignoredClipRings, countDegenerateRings(features, {}));
}

}  // namespace
}  // namespace roiclip::io
