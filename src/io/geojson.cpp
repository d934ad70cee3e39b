// SPDX-License-Identifier: MIT
// GeoJSON / plain JSON path sets. nlohmann-json does the parsing and printing; this file only
// walks the structure and says precisely where it is wrong.
#include <roiclip/io/geojson.hpp>

#include <cmath>
#include <utility>

#include <nlohmann/json.hpp>

#include <roiclip/io/atomic_file.hpp>

#include "reading.hpp"

namespace roiclip::io {
namespace {

// ordered_json keeps the key order of "properties" when a feature is written back.
using json = nlohmann::ordered_json;
using detail::fail;

std::string typeName(const json& j) { return j.type_name(); }

json parseJson(const std::string& text, const std::string& source) {
  try {
    return json::parse(text);
  } catch (const json::exception& e) {
    // e.what() is "[json.exception.parse_error.101] parse error at line 1, column 2: ..."; number
    // overflow (1e999) is reported as out_of_range.406.
    std::string what = e.what();
    const auto pos = what.find("] ");
    if (pos != std::string::npos) what = what.substr(pos + 2);
    fail(source, "", "not valid JSON (" + what + ")");
  }
}

// Reads rings and polylines and remembers how many paths came before, so a message can also give
// the flat path index the core uses in its own messages.
class PathReader {
 public:
  PathReader(const std::string& source, const ReadOptions& options)
      : source_(source), checker_(source, options) {}

  Path readRing(const json& ring, const std::string& where) {
    const std::string at = checker_.flatName(where);
    Path path = readPoints(ring, at);
    checker_.finishRing(path, at);
    return path;
  }

  Path readLine(const json& line, const std::string& where) {
    const std::string at = checker_.flatName(where);
    Path path = readPoints(line, at);
    checker_.finishLine(path, at);
    return path;
  }

  // One warning for all dropped z values, once the whole input is read.
  void finish() const { checker_.reportWarnings(); }

  // Polygon coordinates: an array of rings, outer first.
  Paths readPolygon(const json& rings, const std::string& where) {
    if (!rings.is_array())
      fail(source_, where, "expected an array of rings, got " + typeName(rings));
    if (rings.empty()) fail(source_, where, "polygon has no rings");
    Paths out;
    out.reserve(rings.size());
    for (std::size_t r = 0; r < rings.size(); ++r) {
      out.push_back(readRing(rings[r], where + ", ring " + std::to_string(r)));
    }
    return out;
  }

  // Polygon coordinates of a Polygon, MultiPolygon or GeometryCollection, appended to `out`.
  void readGeometry(const json& geometry, const std::string& where, std::vector<Paths>& out) {
    readGeometryOf(
        geometry, where, "Polygon", "polygon", out,
        [this](const json& rings, const std::string& at) { return readPolygon(rings, at); });
  }

  // Line coordinates of a LineString, MultiLineString or GeometryCollection, appended to `out`.
  void readLineGeometry(const json& geometry, const std::string& where, Paths& out) {
    readGeometryOf(geometry, where, "LineString", "line", out,
                   [this](const json& line, const std::string& at) { return readLine(line, at); });
  }

  std::vector<Feature> readGeoJson(const json& root) {
    std::vector<Feature> features;
    forEachGeometry(root, [&](const json& geometry, const json* feature, const std::string& where) {
      Feature out;
      readGeometry(geometry, where, out.polygons);
      if (feature != nullptr) {
        const auto id = feature->find("id");
        if (id != feature->end()) out.id = id->dump();
        const auto properties = feature->find("properties");
        out.propertiesJson = properties == feature->end() ? "null" : properties->dump();
        if (properties != feature->end() && properties->is_object()) {
          for (const auto& [key, value] : properties->items()) {
            if (value.is_string()) out.properties[key] = value.get<std::string>();
          }
        }
      }
      features.push_back(std::move(out));
    });
    finish();
    return features;
  }

  Paths readLinesGeoJson(const json& root) {
    Paths lines;
    forEachGeometry(root, [&](const json& geometry, const json*, const std::string& where) {
      readLineGeometry(geometry, where, lines);
    });
    finish();
    return lines;
  }

  // {"paths": [...]}: closed rings (a repeated first point dropped) or open lines (kept).
  Paths readPlain(const json& root, bool lines) {
    const json& list = root.at("paths");
    if (!list.is_array()) fail(source_, "", "\"paths\" must be an array of paths");
    Paths out;
    out.reserve(list.size());
    for (std::size_t p = 0; p < list.size(); ++p) {
      checker_.setPathCount(p);
      const std::string where = "path " + std::to_string(p);
      out.push_back(lines ? readLine(list[p], where) : readRing(list[p], where));
    }
    finish();
    return out;
  }

 private:
  // A `single` geometry (Polygon, LineString), its Multi form, or a GeometryCollection of them
  // (collections may nest): read(coordinates, where) for each part ("polygon 2", "line 0"), the
  // results appended to `out`. A null geometry (a feature without one) adds nothing.
  template <class Out, class Read>
  void readGeometryOf(const json& geometry, const std::string& where, const std::string& single,
                      const char* part, Out& out, Read read) {
    if (geometry.is_null()) return;
    if (!geometry.is_object()) fail(source_, where, "geometry must be an object or null");
    const std::string type = memberType(geometry, where);
    const std::string multi = "Multi" + single;
    if (type == "GeometryCollection") {
      forEachMember(geometry, where, [&](const json& member, const std::string& at) {
        readGeometryOf(member, at, single, part, out, read);
      });
      return;
    }
    if (type != single && type != multi) {
      fail(source_, where,
           "unsupported geometry type \"" + type + "\" (expected " + single + " or " + multi + ")");
    }
    const auto coords = geometry.find("coordinates");
    if (coords == geometry.end()) fail(source_, where, type + " without \"coordinates\"");
    const std::string name = where + ", " + part + " ";
    if (type == single) {
      out.push_back(read(*coords, name + "0"));
      return;
    }
    if (!coords->is_array()) fail(source_, where, multi + " coordinates must be an array");
    for (std::size_t i = 0; i < coords->size(); ++i) {
      out.push_back(read((*coords)[i], name + std::to_string(i)));
    }
  }

  // Calls visit(member, where) for each member of a GeometryCollection.
  template <class Visit>
  void forEachMember(const json& collection, const std::string& where, Visit visit) const {
    const auto members = collection.find("geometries");
    if (members == collection.end() || !members->is_array()) {
      fail(source_, where, "GeometryCollection without a \"geometries\" array");
    }
    for (std::size_t g = 0; g < members->size(); ++g) {
      visit((*members)[g], where + ", member " + std::to_string(g));
    }
  }

  // Calls visit(geometry, feature or nullptr, where) for each feature of a FeatureCollection,
  // for a lone Feature, or for a bare geometry at the top level.
  template <class Visit>
  void forEachGeometry(const json& root, Visit visit) const {
    if (!root.is_object()) {
      fail(source_, "", "expected a JSON object at the top level, got " + typeName(root));
    }
    const std::string type = memberType(root, "");
    const auto visitFeature = [&](const json& feature, const std::string& where) {
      const auto geometry = feature.find("geometry");
      if (geometry == feature.end()) fail(source_, where, "Feature without \"geometry\"");
      visit(*geometry, &feature, where);
    };
    if (type == "FeatureCollection") {
      const auto list = root.find("features");
      if (list == root.end() || !list->is_array()) {
        fail(source_, "", "FeatureCollection without a \"features\" array");
      }
      for (std::size_t f = 0; f < list->size(); ++f) {
        const std::string where = "feature " + std::to_string(f);
        const json& feature = (*list)[f];
        if (!feature.is_object() || memberType(feature, where) != "Feature") {
          fail(source_, where, "expected an object of type \"Feature\"");
        }
        visitFeature(feature, where);
      }
    } else if (type == "Feature") {
      visitFeature(root, "feature");
    } else {
      visit(root, nullptr, "geometry");
    }
  }

  Path readPoints(const json& points, const std::string& at) {
    if (!points.is_array()) {
      fail(source_, at, "expected an array of points, got " + typeName(points));
    }
    Path path;
    path.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      const json& point = points[i];
      const std::string pointAt = at + ", point " + std::to_string(i);
      if (!point.is_array() || point.size() < 2 || point.size() > 3) {
        fail(source_, pointAt,
             "expected [x, y] (or [x, y, z]), got " +
                 (point.is_array() ? "an array of " + std::to_string(point.size()) + " values"
                                   : typeName(point)));
      }
      double xy[2];
      for (int k = 0; k < 2; ++k) {
        const json& value = point[std::size_t(k)];
        const char* axis = k == 0 ? "x" : "y";
        if (!value.is_number()) {
          fail(source_, pointAt, std::string(axis) + " is not a number (" + typeName(value) + ")");
        }
        // JSON has no NaN or infinity and nlohmann rejects 1e999; checked anyway so that no
        // non-finite value can reach the core whatever the parser accepts.
        xy[k] = checker_.coordinate(value.get<double>(), pointAt, axis);
      }
      if (point.size() == 3) checker_.droppedZ();
      path.emplace_back(xy[0], xy[1]);
    }
    return path;
  }

  std::string memberType(const json& object, const std::string& where) const {
    const auto type = object.find("type");
    if (type == object.end() || !type->is_string()) {
      fail(source_, where, "missing GeoJSON \"type\" (or a plain {\"paths\": [...]} object)");
    }
    return type->get<std::string>();
  }

  const std::string& source_;
  detail::RingChecker checker_;
};

bool isPlain(const json& root) {
  return root.is_object() && root.contains("paths") && !root.contains("type");
}

json ringJson(const Path& ring) {
  json out = json::array();
  for (const Point& p : ring) out.push_back({p.x, p.y});
  if (!ring.empty()) out.push_back({ring.front().x, ring.front().y});
  return out;
}

// JSON text kept by the reader (an id, a properties object) back as JSON; empty text is null.
json kept(const std::string& text) { return text.empty() ? json() : json::parse(text); }

std::string oneFeatureCollection(json geometry, json properties, int indent) {
  json feature = {{"type", "Feature"},
                  {"properties", std::move(properties)},
                  {"geometry", std::move(geometry)}};
  const json root = {{"type", "FeatureCollection"},
                     {"features", json::array({std::move(feature)})}};
  return root.dump(indent) + "\n";
}

}  // namespace

Paths parsePaths(const std::string& text, const std::string& source, const ReadOptions& options) {
  const json root = parseJson(text, source);
  PathReader reader(source, options);
  if (isPlain(root)) return reader.readPlain(root, false);
  Paths out;
  for (Feature& feature : reader.readGeoJson(root)) {
    for (Paths& polygon : feature.polygons) {
      for (Path& ring : polygon) out.push_back(std::move(ring));
    }
  }
  return out;
}

Paths readPaths(const std::string& file, const ReadOptions& options) {
  return parsePaths(readText(file), sourceName(file), options);
}

Paths parseLines(const std::string& text, const std::string& source, const ReadOptions& options) {
  const json root = parseJson(text, source);
  PathReader reader(source, options);
  return isPlain(root) ? reader.readPlain(root, true) : reader.readLinesGeoJson(root);
}

Paths readLines(const std::string& file, const ReadOptions& options) {
  return parseLines(readText(file), sourceName(file), options);
}

std::vector<Feature> detail::parseGeoJsonFeatures(const std::string& text,
                                                  const std::string& source,
                                                  const ReadOptions& options, bool acceptPlain) {
  const json root = parseJson(text, source);
  PathReader reader(source, options);
  if (!isPlain(root)) return reader.readGeoJson(root);
  if (!acceptPlain) fail(source, "", "expected GeoJSON, got a plain {\"paths\": ...} object");
  Feature feature;
  for (Path& path : reader.readPlain(root, false)) feature.polygons.push_back({std::move(path)});
  return {std::move(feature)};
}

std::vector<Feature> parseFeatures(const std::string& text, const std::string& source,
                                   const ReadOptions& options) {
  return detail::parseGeoJsonFeatures(text, source, options, false);
}

std::vector<Feature> readFeatures(const std::string& file, const ReadOptions& options) {
  return parseFeatures(readText(file), sourceName(file), options);
}

std::string featuresToGeoJson(const std::vector<Feature>& features, const WriteOptions& options) {
  json list = json::array();
  for (const Feature& feature : features) {
    json polygons = json::array();
    for (const Paths& polygon : feature.polygons) {
      json rings = json::array();
      for (std::size_t r = 0; r < polygon.size(); ++r) {
        rings.push_back(ringJson(orientRing(polygon[r], r == 0, options.orientation)));
      }
      polygons.push_back(std::move(rings));
    }
    json out = {{"type", "Feature"}};
    if (!feature.id.empty()) out["id"] = kept(feature.id);
    out["properties"] = kept(feature.propertiesJson);
    out["geometry"] = {{"type", "MultiPolygon"}, {"coordinates", std::move(polygons)}};
    list.push_back(std::move(out));
  }
  const json root = {{"type", "FeatureCollection"}, {"features", std::move(list)}};
  return root.dump(options.indent) + "\n";
}

std::string toGeoJson(const PolygonSet& set, int indent, RingOrientation orientation) {
  return featuresToGeoJson({toFeature(set)}, {orientation, indent});
}

void writeGeoJson(const PolygonSet& set, const std::string& file, int indent,
                  RingOrientation orientation) {
  writeFileAtomically(file, toGeoJson(set, indent, orientation));
}

std::string linesToGeoJson(const Paths& lines, int indent, std::size_t ignoredClipRings) {
  json coordinates = json::array();
  double length = 0.0;
  for (const Path& line : lines) {
    json points = json::array();
    for (std::size_t i = 0; i < line.size(); ++i) {
      points.push_back({line[i].x, line[i].y});
      if (i > 0) length += std::hypot(line[i].x - line[i - 1].x, line[i].y - line[i - 1].y);
    }
    coordinates.push_back(std::move(points));
  }
  json properties = {{"length", length}, {"lines", lines.size()}};
  if (ignoredClipRings > 0) properties["ignoredClipRings"] = ignoredClipRings;
  return oneFeatureCollection(
      {{"type", "MultiLineString"}, {"coordinates", std::move(coordinates)}}, std::move(properties),
      indent);
}

void writeLinesGeoJson(const Paths& lines, const std::string& file, int indent) {
  writeFileAtomically(file, linesToGeoJson(lines, indent));
}

}  // namespace roiclip::io
