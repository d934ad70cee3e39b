// GeoJSON / plain JSON path sets. nlohmann-json does the parsing and printing; this file only
// walks the structure and says precisely where it is wrong.
#include <roiclip/io/geojson.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include <roiclip/io/atomic_file.hpp>

namespace roiclip::io {
namespace {

using nlohmann::json;

// The source is a field of the error; `where` (feature, polygon, ring, point) stays in the text.
[[noreturn]] void fail(const std::string& source, const std::string& where,
                       const std::string& problem) {
  InputLocation location;
  location.source = source;
  throw InvalidInputError(location, (where.empty() ? "" : where + ": ") + problem);
}

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

std::string readFile(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) fail(file, "", "cannot open file for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) fail(file, "", "read error");
  return buffer.str();
}

// Reads rings and polylines and remembers how many paths came before, so a message can also give
// the flat path index the core uses in its own messages.
class PathReader {
 public:
  PathReader(const std::string& source, const ReadOptions& options)
      : source_(source), options_(options) {}

  Path readRing(const json& ring, const std::string& where, bool dropClosingPoint) {
    const std::string at = flatName(where);
    Path path = readPoints(ring, at);
    if (dropClosingPoint && path.size() > 1 && path.front() == path.back()) path.pop_back();
    if (!options_.allowDegenerateRings && distinctPoints(path) < 3) {
      fail(source_, at, "ring has fewer than 3 distinct points");
    }
    ++pathCount_;
    return path;
  }

  // An open polyline: every point kept, a repeated first point included (the core reads it as a
  // loop). Equal points are not counted away: a zero-length line is valid and clips to nothing.
  Path readLine(const json& line, const std::string& where) {
    const std::string at = flatName(where);
    Path path = readPoints(line, at);
    if (!options_.allowDegenerateRings && path.size() < 2) {
      fail(source_, at, "line has fewer than 2 points");
    }
    ++pathCount_;
    return path;
  }

  // Polygon coordinates: an array of rings, outer first.
  Paths readPolygon(const json& rings, const std::string& where) {
    if (!rings.is_array())
      fail(source_, where, "expected an array of rings, got " + typeName(rings));
    if (rings.empty()) fail(source_, where, "polygon has no rings");
    Paths out;
    out.reserve(rings.size());
    for (std::size_t r = 0; r < rings.size(); ++r) {
      out.push_back(readRing(rings[r], where + ", ring " + std::to_string(r), true));
    }
    return out;
  }

  std::vector<Paths> readGeometry(const json& geometry, const std::string& where) {
    std::vector<Paths> polygons;
    if (geometry.is_null()) return polygons;  // GeoJSON allows features without geometry
    if (!geometry.is_object()) fail(source_, where, "geometry must be an object or null");
    const std::string type = memberType(geometry, where);
    const auto coords = geometry.find("coordinates");
    if (type == "Polygon" || type == "MultiPolygon") {
      if (coords == geometry.end()) fail(source_, where, type + " without \"coordinates\"");
    }
    if (type == "Polygon") {
      polygons.push_back(readPolygon(*coords, where + ", polygon 0"));
    } else if (type == "MultiPolygon") {
      if (!coords->is_array()) fail(source_, where, "MultiPolygon coordinates must be an array");
      for (std::size_t p = 0; p < coords->size(); ++p) {
        polygons.push_back(readPolygon((*coords)[p], where + ", polygon " + std::to_string(p)));
      }
    } else {
      fail(source_, where,
           "unsupported geometry type \"" + type + "\" (expected Polygon or MultiPolygon)");
    }
    return polygons;
  }

  // Line coordinates of a LineString, MultiLineString or GeometryCollection, appended to `out`.
  void readLineGeometry(const json& geometry, const std::string& where, Paths& out) {
    if (geometry.is_null()) return;
    if (!geometry.is_object()) fail(source_, where, "geometry must be an object or null");
    const std::string type = memberType(geometry, where);
    if (type == "GeometryCollection") {
      const auto members = geometry.find("geometries");
      if (members == geometry.end() || !members->is_array()) {
        fail(source_, where, "GeometryCollection without a \"geometries\" array");
      }
      for (std::size_t g = 0; g < members->size(); ++g) {
        readLineGeometry((*members)[g], where + ", member " + std::to_string(g), out);
      }
      return;
    }
    if (type != "LineString" && type != "MultiLineString") {
      fail(source_, where,
           "unsupported geometry type \"" + type + "\" (expected LineString or MultiLineString)");
    }
    const auto coords = geometry.find("coordinates");
    if (coords == geometry.end()) fail(source_, where, type + " without \"coordinates\"");
    if (type == "LineString") {
      out.push_back(readLine(*coords, where + ", line 0"));
      return;
    }
    if (!coords->is_array()) fail(source_, where, "MultiLineString coordinates must be an array");
    for (std::size_t l = 0; l < coords->size(); ++l) {
      out.push_back(readLine((*coords)[l], where + ", line " + std::to_string(l)));
    }
  }

  std::vector<Feature> readGeoJson(const json& root) {
    std::vector<Feature> features;
    forEachGeometry(root,
                    [&](const json& geometry, const json* properties, const std::string& where) {
                      Feature out;
                      out.polygons = readGeometry(geometry, where);
                      if (properties != nullptr && properties->is_object()) {
                        for (const auto& [key, value] : properties->items()) {
                          if (value.is_string()) out.properties[key] = value.get<std::string>();
                        }
                      }
                      features.push_back(std::move(out));
                    });
    return features;
  }

  Paths readLinesGeoJson(const json& root) {
    Paths lines;
    forEachGeometry(root, [&](const json& geometry, const json*, const std::string& where) {
      readLineGeometry(geometry, where, lines);
    });
    return lines;
  }

  // {"paths": [...]}: closed rings (a repeated first point dropped) or open lines (kept).
  Paths readPlain(const json& root, bool lines) {
    const json& list = root.at("paths");
    if (!list.is_array()) fail(source_, "", "\"paths\" must be an array of paths");
    Paths out;
    out.reserve(list.size());
    for (std::size_t p = 0; p < list.size(); ++p) {
      pathCount_ = p;
      const std::string where = "path " + std::to_string(p);
      out.push_back(lines ? readLine(list[p], where) : readRing(list[p], where, true));
    }
    return out;
  }

 private:
  // Calls visit(geometry, properties or nullptr, where) for each feature of a FeatureCollection,
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
      const auto properties = feature.find("properties");
      visit(*geometry, properties == feature.end() ? nullptr : &*properties, where);
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

  // Nested GeoJSON rings and lines also get their flat index: the core's messages use it.
  std::string flatName(const std::string& where) const {
    return where.rfind("path ", 0) == 0 ? where
                                        : where + " (path " + std::to_string(pathCount_) + ")";
  }

  Path readPoints(const json& points, const std::string& at) const {
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
        xy[k] = value.get<double>();
        // JSON has no NaN or infinity and nlohmann rejects 1e999; checked anyway so that no
        // non-finite value can reach the core whatever the parser accepts.
        if (!std::isfinite(xy[k])) fail(source_, pointAt, std::string(axis) + " is not finite");
      }
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

  static std::size_t distinctPoints(const Path& path) {
    // Rings are short in practice and this runs once per ring: a quadratic count is fine and
    // keeps the original order untouched.
    std::size_t count = 0;
    for (std::size_t i = 0; i < path.size() && count < 3; ++i) {
      bool seen = false;
      for (std::size_t j = 0; j < i && !seen; ++j) seen = path[j] == path[i];
      if (!seen) ++count;
    }
    return count;
  }

  const std::string& source_;
  const ReadOptions& options_;
  std::size_t pathCount_ = 0;
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

void writeTextAtomically(const std::string& text, const std::string& file) {
  writeFileAtomically(file, text);
}

json featureCollection(json geometry, json properties) {
  json feature = {{"type", "Feature"},
                  {"properties", std::move(properties)},
                  {"geometry", std::move(geometry)}};
  return {{"type", "FeatureCollection"}, {"features", json::array({std::move(feature)})}};
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
  return parsePaths(readFile(file), file, options);
}

Paths parseLines(const std::string& text, const std::string& source, const ReadOptions& options) {
  const json root = parseJson(text, source);
  PathReader reader(source, options);
  return isPlain(root) ? reader.readPlain(root, true) : reader.readLinesGeoJson(root);
}

Paths readLines(const std::string& file, const ReadOptions& options) {
  return parseLines(readFile(file), file, options);
}

std::vector<Feature> parseFeatures(const std::string& text, const std::string& source,
                                   const ReadOptions& options) {
  const json root = parseJson(text, source);
  if (isPlain(root)) fail(source, "", "expected GeoJSON, got a plain {\"paths\": ...} object");
  PathReader reader(source, options);
  return reader.readGeoJson(root);
}

std::vector<Feature> readFeatures(const std::string& file, const ReadOptions& options) {
  return parseFeatures(readFile(file), file, options);
}

std::string toGeoJson(const PolygonSet& set, int indent) {
  json polygons = json::array();
  for (const Polygon& polygon : set.polygons) {
    json rings = json::array();
    rings.push_back(ringJson(polygon.outer));
    for (const Path& hole : polygon.holes) rings.push_back(ringJson(hole));
    polygons.push_back(std::move(rings));
  }
  return featureCollection({{"type", "MultiPolygon"}, {"coordinates", std::move(polygons)}},
                           {{"area", set.area()}, {"rings", set.ringCount()}})
             .dump(indent) +
         "\n";
}

void writeGeoJson(const PolygonSet& set, const std::string& file, int indent) {
  writeTextAtomically(toGeoJson(set, indent), file);
}

std::string linesToGeoJson(const Paths& lines, int indent) {
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
  return featureCollection({{"type", "MultiLineString"}, {"coordinates", std::move(coordinates)}},
                           {{"length", length}, {"lines", lines.size()}})
             .dump(indent) +
         "\n";
}

void writeLinesGeoJson(const Paths& lines, const std::string& file, int indent) {
  writeTextAtomically(linesToGeoJson(lines, indent), file);
}

}  // namespace roiclip::io
