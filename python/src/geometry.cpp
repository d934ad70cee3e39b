// SPDX-License-Identifier: MIT
// Python bindings of the core (roiclip/roiclip.hpp): enums, PolygonSet, the boolean operations
// and clip_lines, plus cv2 contour conversions (roiclip/opencv/convert.hpp) and from_shapely.
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/opencv/convert.hpp>
#include <roiclip/roiclip.hpp>

#include "arrays.hpp"
#include "bindings.hpp"

namespace roiclip::python {

namespace {

constexpr const char* kRounding =
    "Integer contours are the region snap-rounded to whole pixels (round_to(set, 1)): they never "
    "cross or overlap and holes stay inside, but each boundary point moves by up to 0.71 px and "
    "parts thinner than a pixel may vanish. float32 / float64 keep the sub-pixel vertices.";

py::object indexOrNone(int i) { return i < 0 ? py::object(py::none()) : py::object(py::int_(i)); }

double polygonArea(const Polygon& p) {
  // Outer rings have a negative shoelace sum, holes a positive one.
  double a = -signedArea(p.outer);
  for (const Path& h : p.holes) a -= signedArea(h);
  return a;
}

py::list ringCoordinates(const Path& ring) {
  py::list points;
  for (const Point& q : ring) points.append(py::make_tuple(q.x, q.y));
  if (!ring.empty()) points.append(py::make_tuple(ring.front().x, ring.front().y));
  return points;
}

py::list polygonCoordinates(const Polygon& p) {
  py::list rings;
  rings.append(ringCoordinates(p.outer));
  for (const Path& h : p.holes) rings.append(ringCoordinates(h));
  return rings;
}

template <typename PointT, typename T>
py::tuple contourArrays(const opencv::Contours<PointT>& c) {
  py::tuple contours(c.contours.size());
  for (std::size_t i = 0; i < c.contours.size(); ++i) {
    const auto& in = c.contours[i];
    py::array_t<T> a({static_cast<py::ssize_t>(in.size()), py::ssize_t{1}, py::ssize_t{2}});
    T* d = a.mutable_data();
    for (std::size_t k = 0; k < in.size(); ++k) {
      d[2 * k] = in[k].x;
      d[2 * k + 1] = in[k].y;
    }
    contours[i] = std::move(a);
  }
  if (c.hierarchy.empty()) return py::make_tuple(contours, py::none());
  py::array_t<std::int32_t> h(
      {py::ssize_t{1}, static_cast<py::ssize_t>(c.hierarchy.size()), py::ssize_t{4}});
  std::memcpy(h.mutable_data(), c.hierarchy.data(), c.hierarchy.size() * sizeof(cv::Vec4i));
  return py::make_tuple(contours, h);
}

py::tuple toContours(const PolygonSet& set, const py::object& dtypeArg) {
  const py::dtype dt = py::dtype::from_args(dtypeArg);
  const char kind = dt.kind();
  const auto size = dt.itemsize();
  if (kind == 'i' && size == 4)
    return contourArrays<cv::Point, std::int32_t>(opencv::toContours(set));
  if (kind == 'f' && size == 4) return contourArrays<cv::Point2f, float>(opencv::toContours2f(set));
  if (kind == 'f' && size == 8)
    return contourArrays<cv::Point2d, double>(opencv::toContours2d(set));
  throw InvalidInputError("to_contours: dtype must be int32, float32 or float64, got " +
                          py::str(dt.attr("name")).cast<std::string>());
}

/// cv2.findContours output (a tuple or list of contour arrays, hierarchy (1, M, 4) or None) as
/// cv::Mat headers, then roiclip::opencv::fromContours, which checks and orients them.
Paths fromContours(const py::handle& contours, const py::handle& hierarchy) {
  if (py::isinstance<py::str>(contours) || !PySequence_Check(contours.ptr())) {
    throw InvalidInputError(
        "from_contours: contours must be a sequence of arrays (as "
        "cv2.findContours returns them)");
  }
  const py::sequence seq = py::reinterpret_borrow<py::sequence>(contours);
  std::vector<py::array> keep(seq.size());
  std::vector<cv::Mat> mats(seq.size());
  for (std::size_t i = 0; i < seq.size(); ++i) {
    const std::string name = "contour " + std::to_string(i);
    // (N, 1, 2) becomes an N x 1 two-channel Mat, (N, 2) an N x 2 one; checkVector(2) in
    // fromContours takes both.
    mats[i] = matView(seq[i], "from_contours: " + name, keep[i]);
  }
  py::array hierarchyKeep;
  cv::Mat h;
  if (!hierarchy.is_none()) {
    py::array a =
        py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>::ensure(hierarchy);
    if (!a) throw InvalidInputError("from_contours: hierarchy must be an int32 array or None");
    if (a.size() % 4 != 0) {
      throw InvalidInputError("from_contours: hierarchy must have 4 entries per contour");
    }
    hierarchyKeep = a;
    h = cv::Mat(1, static_cast<int>(a.size() / 4), CV_32SC4, const_cast<void*>(a.data()));
  }
  py::gil_scoped_release release;
  return h.empty() ? opencv::fromContours(mats) : opencv::fromContours(mats, h);
}

}  // namespace

void bindGeometry(py::module_& m) {
  py::enum_<FillRule>(m, "FillRule",
                      "Which points a set of closed paths covers, by their winding number w. "
                      "Functions also accept the names 'evenodd', 'nonzero', 'positive', "
                      "'negative'.")
      .value("EVEN_ODD", FillRule::EvenOdd, "w is odd (what cv2.fillPoly draws)")
      .value("NON_ZERO", FillRule::NonZero, "w != 0")
      .value("POSITIVE", FillRule::Positive, "w > 0")
      .value("NEGATIVE", FillRule::Negative, "w < 0");
  py::enum_<ClipOp>(m, "ClipOp",
                    "Boolean operation between a subject and a clip region. Functions also "
                    "accept the names 'intersection', 'union', 'difference', 'xor'.")
      .value("INTERSECTION", ClipOp::Intersection, "subject AND clip (the ROI case)")
      .value("UNION", ClipOp::Union, "subject OR clip")
      .value("DIFFERENCE", ClipOp::Difference, "subject AND NOT clip")
      .value("XOR", ClipOp::Xor, "subject XOR clip");
  py::enum_<LinePart>(m, "LinePart",
                      "Which parts of open polylines clip_lines() returns ('inside', 'outside').")
      .value("INSIDE", LinePart::Inside,
             "the parts in the region, including parts running along its boundary")
      .value("OUTSIDE", LinePart::Outside, "the parts outside it");

  py::class_<Polygon>(m, "Polygon",
                      "One connected filled region of a PolygonSet: an outer ring and its holes. "
                      "Rings are simple, do not repeat their first point and never cross each "
                      "other (they may touch at isolated vertices). Outer rings have a negative "
                      "shoelace sum, holes a positive one, as cv2.findContours returns them.")
      .def_property_readonly(
          "exterior", [](const Polygon& p) { return toArray(p.outer); },
          "The outer ring as a new (N, 2) float64 array (x, y in pixels, y down).")
      .def_property_readonly(
          "holes", [](const Polygon& p) { return toArrays(p.holes); },
          "The holes as a list of new (N, 2) float64 arrays.")
      .def_property_readonly("area", &polygonArea,
                             "Filled area in square pixels (outer ring minus holes).")
      .def_property_readonly(
          "parent", [](const Polygon& p) { return indexOrNone(p.parent); },
          "Index (in the PolygonSet) of the polygon whose hole this one lies in, or None at "
          "the top level.")
      .def_property_readonly(
          "parent_hole", [](const Polygon& p) { return indexOrNone(p.parentHole); },
          "Index into the parent's holes of the hole this polygon lies in, or None.")
      .def_property_readonly(
          "__geo_interface__",
          [](const Polygon& p) {
            py::dict d;
            d["type"] = "Polygon";
            d["coordinates"] = polygonCoordinates(p);
            return d;
          },
          "GeoJSON-like Polygon mapping (rings closed), for shapely.geometry.shape().")
      .def("__repr__", [](const Polygon& p) {
        return "<roiclip.Polygon " + std::to_string(p.outer.size()) + " vertices, " +
               std::to_string(p.holes.size()) + " holes, area " +
               py::repr(py::float_(polygonArea(p))).cast<std::string>() + ">";
      });

  py::class_<PolygonSet>(
      m, "PolygonSet",
      "A region as a forest of polygons with holes (result of every boolean operation). "
      "len() is the number of polygons; iterating or indexing gives Polygon objects; parents "
      "come before children. A PolygonSet can be passed wherever paths are expected.")
      .def(py::init<>(), "An empty region.")
      .def_property_readonly("area", &PolygonSet::area,
                             "Total filled area in square pixels (outer areas minus holes).")
      .def_property_readonly("ring_count", &PolygonSet::ringCount,
                             "Number of rings (outer rings plus holes).")
      .def("__len__", [](const PolygonSet& s) { return s.polygons.size(); })
      .def(
          "__getitem__",
          [](const PolygonSet& s, py::ssize_t i) -> const Polygon& {
            const auto n = static_cast<py::ssize_t>(s.polygons.size());
            if (i < 0) i += n;
            if (i < 0 || i >= n) throw py::index_error("PolygonSet index out of range");
            return s.polygons[static_cast<std::size_t>(i)];
          },
          py::return_value_policy::reference_internal, py::arg("index"),
          "The polygon at `index` (valid while the PolygonSet lives).")
      .def(
          "__iter__",
          [](const PolygonSet& s) {
            return py::make_iterator(s.polygons.begin(), s.polygons.end());
          },
          py::keep_alive<0, 1>(), "Iterate over the polygons.")
      .def(
          "to_paths", [](const PolygonSet& s) { return toArrays(s.toPaths()); },
          "Every ring (outer rings and holes, with their orientations) as a list of (N, 2) "
          "float64 arrays; filled with 'nonzero' or 'evenodd' they give back this region.")
      .def("to_contours", &toContours, py::arg("dtype") = py::dtype::of<std::int32_t>(),
           (std::string("The region as cv2.findContours(..., cv2.RETR_CCOMP, ...) would return "
                        "it: (contours, hierarchy), contours a tuple of (N, 1, 2) arrays of "
                        "`dtype` (int32, float32 or float64), hierarchy a (1, M, 4) int32 array "
                        "of [next, previous, first_child, parent] (None when empty). Outer rings "
                        "are top-level contours (cv2.contourArea(c, True) < 0), their holes "
                        "their children. ") +
            kRounding)
               .c_str())
      .def_property_readonly(
          "__geo_interface__",
          [](const PolygonSet& s) {
            py::list polygons;
            for (const Polygon& p : s.polygons) polygons.append(polygonCoordinates(p));
            py::dict d;
            d["type"] = "MultiPolygon";
            d["coordinates"] = polygons;
            return d;
          },
          "GeoJSON-like MultiPolygon mapping (each polygon: outer ring, then holes; rings closed; "
          "orientation as in the PolygonSet), so shapely.geometry.shape(result) works.")
      .def("__repr__", [](const PolygonSet& s) {
        return "<roiclip.PolygonSet " + std::to_string(s.polygons.size()) + " polygons, " +
               std::to_string(s.ringCount()) + " rings, area " +
               py::repr(py::float_(s.area())).cast<std::string>() + ">";
      });

  m.def(
      "simplify",
      [](const PathsArg& paths, const FillRuleArg& rule) {
        const Paths p = toPaths(paths.object, "subject");
        py::gil_scoped_release release;
        return roiclip::simplify(p, rule.value);
      },
      py::arg("paths"), py::arg("fill_rule") = "evenodd",
      "Resolve closed paths (self-intersecting, overlapping, touching) into simple outer rings "
      "with holes covering exactly the points the fill rule says they cover. Paths with fewer "
      "than 3 distinct points contribute nothing. Raises InvalidInputError on NaN, infinity or "
      "coordinates outside +-4,194,304 px (the message names the path and vertex).");

  m.def(
      "clip",
      [](const ClipOpArg& op, const PathsArg& subject, const PathsArg& clip,
         const FillRuleArg& subjectRule, const FillRuleArg& clipRule) {
        const Paths s = toPaths(subject.object, "subject");
        const Paths c = toPaths(clip.object, "clip");
        py::gil_scoped_release release;
        return roiclip::clip(op.value, s, c, subjectRule.value, clipRule.value);
      },
      py::arg("op"), py::arg("subject"), py::arg("clip"), py::arg("subject_fill_rule") = "evenodd",
      py::arg("clip_fill_rule") = "evenodd",
      "Boolean operation between two path sets, each read with its own fill rule. Both may "
      "self-intersect, overlap, share edges or contain holes. Returns a PolygonSet. Raises "
      "InvalidInputError as simplify() (naming the 'subject' or 'clip' operand).");

  const auto bindShorthand = [&m](const char* name, ClipOp op, const char* doc) {
    m.def(
        name,
        [op](const PathsArg& subject, const PathsArg& clip, const FillRuleArg& rule) {
          const Paths s = toPaths(subject.object, "subject");
          const Paths c = toPaths(clip.object, "clip");
          py::gil_scoped_release release;
          return roiclip::clip(op, s, c, rule.value, rule.value);
        },
        py::arg("subject"), py::arg("clip"), py::arg("fill_rule") = "evenodd", doc);
  };
  bindShorthand("intersect", ClipOp::Intersection,
                "subject AND clip, both read with `fill_rule`: clip(INTERSECTION, ...).");
  bindShorthand("union", ClipOp::Union, "subject OR clip: clip(UNION, ...).");
  bindShorthand("difference", ClipOp::Difference, "subject AND NOT clip: clip(DIFFERENCE, ...).");
  bindShorthand("xor", ClipOp::Xor, "subject XOR clip: clip(XOR, ...).");

  m.def(
      "clip_lines",
      [](const PathsArg& lines, const PathsArg& region, const FillRuleArg& rule,
         const LinePartArg& part) {
        const Paths l = toPaths(lines.object, "line");
        const Paths r = toPaths(region.object, "clip");
        Paths out;
        {
          py::gil_scoped_release release;
          out = roiclip::clipLines(l, r, rule.value, part.value);
        }
        return toArrays(out);
      },
      py::arg("lines"), py::arg("region"), py::arg("fill_rule") = "evenodd",
      py::arg("part") = "inside",
      "Open polylines (e.g. Canny edges) clipped to a closed region, exactly: the parts inside "
      "(part='inside', boundary included) or outside it, as a list of (N, 2) float64 arrays in "
      "the input's order and direction. A polyline whose last point equals its first is a loop.");

  m.def(
      "from_contours",
      [](const py::object& contours, const py::object& hierarchy) {
        return toArrays(fromContours(contours, hierarchy));
      },
      py::arg("contours"), py::arg("hierarchy") = py::none(),
      "cv2.findContours output (contours, hierarchy) as paths (a list of (N, 2) float64 arrays, "
      "one per contour). Contours may be int32, float32 or float64, (N, 1, 2) or (N, 2). With a "
      "hierarchy (any retrieval mode) outer boundaries are oriented with a negative shoelace sum "
      "and holes with a positive one, so the paths mean the same region under 'nonzero' and "
      "'evenodd'; without one, orientations are kept (read them with 'evenodd').");

  m.def(
      "from_shapely",
      [](const py::object& geometry) { return toArrays(geoInterfacePaths(geometry)); },
      py::arg("geometry"),
      "Rings of a Polygon or MultiPolygon (anything with __geo_interface__: shapely, a "
      "PolygonSet, GeoJSON-like dicts; also inside a GeometryCollection, Feature or "
      "FeatureCollection) as paths: a list of (N, 2) float64 arrays, the repeated closing point "
      "dropped. Read them with 'evenodd' (valid polygons mean the same under any rule).");

  m.def(
      "round_to",
      [](const PolygonSet& set, double step) {
        py::gil_scoped_release release;
        return roundTo(set, step);
      },
      py::arg("region"), py::arg("step"),
      "The region snap-rounded onto multiples of `step` (1: integer pixels, 1/256, 1e-6 for GIS "
      "degrees): every vertex on the grid, no crossings, no overlapping parts, holes inside their "
      "outer ring (valid for shapely/GEOS). Each boundary point moves by at most "
      "step * sqrt(2) / 2; parts thinner than a step may vanish.");

  m.def("release_thread_buffers", &releaseThreadBuffers,
        "Free the working arrays the calling thread keeps between calls (each thread keeps those "
        "of its largest call, up to 64 MiB per array).");
}

}  // namespace roiclip::python
