// SPDX-License-Identifier: MIT
// WKT regions and polylines (wkt.hpp). Boost.Geometry parses and prints each geometry; this file
// splits GEOMETRYCOLLECTIONs (Boost 1.74's read_wkt has none), counts the values per point
// (Boost would read "x y z" into a 2-D point as two points) and checks rings as the GeoJSON
// reader does.
#include <roiclip/io/wkt.hpp>

#include <cctype>
#include <exception>
#include <functional>
#include <limits>
#include <sstream>
#include <utility>

#include <boost/geometry/geometries/linestring.hpp>
#include <boost/geometry/geometries/multi_linestring.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/io/wkt/read.hpp>
#include <boost/geometry/io/wkt/write.hpp>

#include "reading.hpp"

namespace roiclip::io {
namespace {

namespace bg = boost::geometry;

// Read with room for x y z m, so that tagged Z / M / ZM geometries parse; z and m are dropped.
using ReadPoint = bg::model::point<double, 4, bg::cs::cartesian>;
using ReadPolygon = bg::model::polygon<ReadPoint>;
using ReadMultiPolygon = bg::model::multi_polygon<ReadPolygon>;
using ReadLine = bg::model::linestring<ReadPoint>;
using ReadMultiLine = bg::model::multi_linestring<ReadLine>;

using WritePoint = bg::model::d2::point_xy<double>;
using WritePolygon = bg::model::polygon<WritePoint>;
using WriteMultiPolygon = bg::model::multi_polygon<WritePolygon>;
using WriteLine = bg::model::linestring<WritePoint>;
using WriteMultiLine = bg::model::multi_linestring<WriteLine>;

using detail::fail;

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool isBlank(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

// One geometry's text split into its type keyword and the rest.
struct Tagged {
  std::string type;  // upper case
  std::string text;  // the whole geometry, blanks normalised to ' '
};

// Walks the text of one WKT input: geometry collections are split here, every other geometry goes
// to Boost.Geometry whole.
class WktReader {
 public:
  WktReader(const std::string& source, const ReadOptions& options) : checker_(source, options) {}

  std::vector<Feature> features(const std::string& text) {
    std::vector<Feature> out;
    const Tagged top = tagged(text, "");
    if (top.type == "GEOMETRYCOLLECTION") {
      const std::vector<std::string> members = collectionMembers(top.text, "");
      for (std::size_t m = 0; m < members.size(); ++m) {
        Feature feature;
        readRegion(members[m], "member " + std::to_string(m), feature.polygons);
        out.push_back(std::move(feature));
      }
    } else {
      Feature feature;
      readRegion(top.text, "", feature.polygons);
      out.push_back(std::move(feature));
    }
    checker_.reportWarnings();
    return out;
  }

  Paths lines(const std::string& text) {
    Paths out;
    readLines(text, "", out);
    checker_.reportWarnings();
    return out;
  }

 private:
  static std::string join(const std::string& where, const std::string& what) {
    return where.empty() ? what : where + ", " + what;
  }

  Tagged tagged(const std::string& text, const std::string& where) const {
    std::string normal = text;
    for (char& c : normal) {
      if (isBlank(c)) c = ' ';
    }
    std::size_t begin = 0;
    while (begin < normal.size() && normal[begin] == ' ') ++begin;
    std::size_t end = begin;
    while (end < normal.size() && std::isalpha(static_cast<unsigned char>(normal[end]))) ++end;
    if (end == begin) fail(checker_.source(), where, "not valid WKT (expected a geometry type)");
    return {upper(normal.substr(begin, end - begin)), normal.substr(begin)};
  }

  // The members of "GEOMETRYCOLLECTION [Z|M|ZM] (A, B, ...)" (none for EMPTY), split at the
  // commas outside parentheses.
  std::vector<std::string> collectionMembers(const std::string& text,
                                             const std::string& where) const {
    std::size_t i = std::string("GEOMETRYCOLLECTION").size();
    const auto skipBlanks = [&] {
      while (i < text.size() && text[i] == ' ') ++i;
    };
    const auto word = [&] {
      skipBlanks();
      std::size_t end = i;
      while (end < text.size() && std::isalpha(static_cast<unsigned char>(text[end]))) ++end;
      return upper(text.substr(i, end - i));
    };
    std::string tag = word();
    if (tag == "Z" || tag == "M" || tag == "ZM") {
      i += tag.size();
      tag = word();
    }
    std::vector<std::string> members;
    if (tag == "EMPTY") {
      i += tag.size();
      skipBlanks();
      if (i != text.size()) fail(checker_.source(), where, "not valid WKT (text after EMPTY)");
      return members;
    }
    skipBlanks();
    if (i == text.size() || text[i] != '(') {
      fail(checker_.source(), where, "not valid WKT (expected '(' after GEOMETRYCOLLECTION)");
    }
    int depth = 0;
    std::size_t start = i + 1;
    for (; i < text.size(); ++i) {
      if (text[i] == '(') {
        ++depth;
      } else if (text[i] == ')' || (text[i] == ',' && depth == 1)) {
        if (text[i] == ')' && --depth > 0) continue;
        members.push_back(text.substr(start, i - start));
        start = i + 1;
        if (depth == 0) break;
      }
    }
    if (depth != 0) fail(checker_.source(), where, "not valid WKT (unbalanced parentheses)");
    for (++i; i < text.size(); ++i) {
      if (text[i] != ' ') fail(checker_.source(), where, "not valid WKT (text after ')')");
    }
    return members;
  }

  // Boost.Geometry's read_wkt() with its exception as an InvalidInputError. Before that, the
  // number of values of each point: 2, or 3 to 4 (z and m, dropped); Boost itself would take a
  // third value of an untagged 2-D geometry for the next point's x.
  template <class Geometry>
  Geometry parse(const std::string& text, const std::string& where) {
    std::size_t values = 0;
    bool letters = false;
    bool inToken = false;
    for (const char c : text + ",") {
      if (c == '(' || c == ')' || c == ',') {
        if (!letters && values > 4) {
          fail(checker_.source(), where,
               "a point has " + std::to_string(values) + " values (expected x y [z [m]])");
        }
        if (!letters && values > 2) checker_.droppedZ();
        values = 0;
        letters = false;
        inToken = false;
      } else if (c == ' ') {
        inToken = false;
      } else {
        if (!inToken) ++values;
        inToken = true;
        // Keywords (POLYGON, Z, EMPTY) are no values; "nan", "inf" and "1e5" are.
        if (std::isalpha(static_cast<unsigned char>(c)) && c != 'e' && c != 'E' && values == 1 &&
            !(c == 'n' || c == 'N' || c == 'i' || c == 'I')) {
          letters = true;
        }
      }
    }
    Geometry geometry;
    try {
      bg::read_wkt(text, geometry);
    } catch (const std::exception& e) {
      // Boost's message ends with " in '<the whole text>'": the text can be long, so it goes.
      std::string what = e.what();
      const std::size_t in = what.find(" in '");
      if (in != std::string::npos) what = what.substr(0, in);
      fail(checker_.source(), where, "not valid WKT (" + what + ")");
    }
    return geometry;
  }

  Path points(const std::vector<ReadPoint>& in, const std::string& at) const {
    Path path;
    path.reserve(in.size());
    for (std::size_t i = 0; i < in.size(); ++i) {
      const std::string pointAt = at + ", point " + std::to_string(i);
      path.emplace_back(checker_.coordinate(bg::get<0>(in[i]), pointAt, "x"),
                        checker_.coordinate(bg::get<1>(in[i]), pointAt, "y"));
    }
    return path;
  }

  Paths polygon(const ReadPolygon& in, const std::string& where) {
    Paths rings;
    const auto ring = [&](const auto& inRing, std::size_t r) {
      const std::string at = checker_.flatName(join(where, "ring " + std::to_string(r)));
      Path path = points({inRing.begin(), inRing.end()}, at);
      checker_.finishRing(path, at);
      rings.push_back(std::move(path));
    };
    ring(in.outer(), 0);
    for (std::size_t h = 0; h < in.inners().size(); ++h) ring(in.inners()[h], h + 1);
    return rings;
  }

  void readRegion(const std::string& text, const std::string& where, std::vector<Paths>& polygons) {
    readGeometryOf<ReadPolygon, ReadMultiPolygon>(text, where, "POLYGON", "polygon",
                                                  [&](const ReadPolygon& p, const std::string& at) {
                                                    // POLYGON EMPTY reads as a polygon without
                                                    // points.
                                                    if (!p.outer().empty())
                                                      polygons.push_back(polygon(p, at));
                                                  });
  }

  void readLines(const std::string& text, const std::string& where, Paths& out) {
    readGeometryOf<ReadLine, ReadMultiLine>(text, where, "LINESTRING", "line",
                                            [&](const ReadLine& l, const std::string& at) {
                                              if (l.empty()) return;  // LINESTRING EMPTY
                                              const std::string name = checker_.flatName(at);
                                              Path path = points({l.begin(), l.end()}, name);
                                              checker_.finishLine(path, name);
                                              out.push_back(std::move(path));
                                            });
  }

  // A `single` geometry (POLYGON, LINESTRING), its MULTI form, or a GEOMETRYCOLLECTION of them
  // (collections may nest): take(part, where) for each part ("polygon 2", "line 0").
  template <class Single, class Multi, class Take>
  void readGeometryOf(const std::string& text, const std::string& where, const std::string& single,
                      const char* part, Take take) {
    const Tagged g = tagged(text, where);
    const std::string multi = "MULTI" + single;
    const std::string name = join(where, std::string(part) + " ");
    if (g.type == single) {
      take(parse<Single>(g.text, where), name + "0");
    } else if (g.type == multi) {
      const auto m = parse<Multi>(g.text, where);
      for (std::size_t i = 0; i < m.size(); ++i) take(m[i], name + std::to_string(i));
    } else if (g.type == "GEOMETRYCOLLECTION") {
      const std::vector<std::string> members = collectionMembers(g.text, where);
      for (std::size_t m = 0; m < members.size(); ++m) {
        readGeometryOf<Single, Multi>(members[m], join(where, "member " + std::to_string(m)),
                                      single, part, take);
      }
    } else {
      fail(checker_.source(), where,
           "unsupported geometry type \"" + g.type + "\" (expected " + single + " or " + multi +
               ")");
    }
  }

  detail::RingChecker checker_;
};

WritePolygon writePolygon(const Paths& rings, RingOrientation orientation) {
  WritePolygon out;
  const auto fill = [&](const Path& ring, bool outer, auto& target) {
    const Path oriented = orientRing(ring, outer, orientation);
    for (const Point& p : oriented) target.push_back({p.x, p.y});
    if (!oriented.empty()) target.push_back({oriented.front().x, oriented.front().y});
  };
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (r == 0) {
      fill(rings[r], true, out.outer());
    } else {
      out.inners().emplace_back();
      fill(rings[r], false, out.inners().back());
    }
  }
  return out;
}

template <class Geometry>
std::string print(const Geometry& geometry, const char* empty) {
  if (geometry.empty()) return empty;
  std::ostringstream out;
  out.precision(std::numeric_limits<double>::max_digits10);
  out << bg::wkt(geometry);
  return out.str();
}

std::string multiPolygonWkt(const Feature& feature, RingOrientation orientation) {
  WriteMultiPolygon m;
  for (const Paths& polygon : feature.polygons) m.push_back(writePolygon(polygon, orientation));
  return print(m, "MULTIPOLYGON EMPTY");
}

}  // namespace

std::vector<Feature> parseWktFeatures(const std::string& text, const std::string& source,
                                      const ReadOptions& options) {
  return WktReader(source, options).features(text);
}

Paths parseWktLines(const std::string& text, const std::string& source,
                    const ReadOptions& options) {
  return WktReader(source, options).lines(text);
}

std::string featuresToWkt(const std::vector<Feature>& features, RingOrientation orientation) {
  if (features.size() == 1) return multiPolygonWkt(features[0], orientation) + "\n";
  if (features.empty()) return "GEOMETRYCOLLECTION EMPTY\n";
  std::string out = "GEOMETRYCOLLECTION(";
  for (std::size_t f = 0; f < features.size(); ++f) {
    out += (f == 0 ? "" : ",") + multiPolygonWkt(features[f], orientation);
  }
  return out + ")\n";
}

std::string linesToWkt(const Paths& lines) {
  WriteMultiLine m;
  for (const Path& line : lines) {
    m.emplace_back();
    for (const Point& p : line) m.back().push_back({p.x, p.y});
  }
  return print(m, "MULTILINESTRING EMPTY") + "\n";
}

}  // namespace roiclip::io
