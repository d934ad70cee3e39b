// SPDX-License-Identifier: MIT
// roiclip Python bindings: conversions between Python objects (numpy arrays, cv2 contours,
// strings naming enums) and roiclip's C++ types. Every conversion runs in C++ on numpy buffers;
// no per-point Python code. Functions here need the GIL.
#pragma once

#include <string>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <opencv2/core.hpp>

#include <roiclip/roiclip.hpp>

namespace roiclip::python {

namespace py = pybind11;

/// A geometry operand as Python passes it: a PolygonSet, one path (array-like of shape (N, 2) or
/// cv2's (N, 1, 2), any real dtype), a sequence of paths (a list, cv2.findContours' tuple, a
/// (K, N, 2) array) or a shapely geometry (anything with __geo_interface__, see
/// geoInterfacePaths()). Kept as the Python object until toPaths() converts it, so errors can name
/// the operand ("subject path 2: ...").
struct PathsArg {
  py::object object;
};

/// Enum arguments that also accept their names ("evenodd", "nonzero", "intersection", "inside").
/// An unknown name raises InvalidInputError with the core's message.
struct FillRuleArg {
  FillRule value = FillRule::EvenOdd;
};
struct ClipOpArg {
  ClipOp value = ClipOp::Intersection;
};
struct LinePartArg {
  LinePart value = LinePart::Inside;
};
/// "inside" or "outside" (case-insensitive), the names toString(LinePart) gives.
/// @throws InvalidInputError otherwise.
LinePart parseLinePart(const char* name);

/// Convert an operand (see PathsArg) to paths. `operand` names it in error messages, the way the
/// core names operands ("subject", "clip", "line").
/// @throws InvalidInputError for an array that is not (N, 2) or (N, 1, 2), a non-numeric dtype or
///         an object that is neither a path nor a sequence of paths.
Paths toPaths(const py::handle& object, const std::string& operand);

/// The rings of a Polygon / MultiPolygon (also inside a GeometryCollection, Feature or
/// FeatureCollection) given by an object's __geo_interface__ or a GeoJSON-like dict, each ring
/// one closed path (the repeated closing point dropped).
/// @throws InvalidInputError for other geometry types or malformed coordinates.
Paths geoInterfacePaths(const py::handle& object);

/// One path as a new (N, 2) float64 array.
py::array_t<double> toArray(const Path& path);
/// Paths as a list of new (N, 2) float64 arrays.
py::list toArrays(const Paths& paths);
/// A point as a new (2,) float64 array.
py::array_t<double> toArray(const Point& point);

/// A cv::Mat header over a numpy array's buffer (no copy): 2-D arrays are single-channel, 3-D
/// arrays (H, W, C) have C channels. Dtypes uint8, int8, uint16, int16, int32, float32, float64.
/// The array must stay alive (and unresized) while the Mat is used; a non-contiguous array is
/// copied first into `keep`, which the caller holds as long as the Mat.
/// @throws InvalidInputError naming `name` for other dtypes or dimensions.
cv::Mat matView(const py::handle& object, const std::string& name, py::array& keep);

/// A numpy array that owns `mat` (no copy): (rows, cols) or (rows, cols, channels).
py::array toArray(cv::Mat mat);

/// cv::Size from a numpy-style shape: (height, width) or image.shape (height, width, channels).
/// @throws InvalidInputError for anything else or negative sizes.
cv::Size toSize(const py::handle& shape);

}  // namespace roiclip::python

namespace pybind11::detail {

template <>
struct type_caster<roiclip::python::PathsArg> {
  PYBIND11_TYPE_CASTER(roiclip::python::PathsArg, const_name("Paths"));
  bool load(handle src, bool /*convert*/) {
    value.object = reinterpret_borrow<object>(src);
    return true;
  }
  static handle cast(const roiclip::python::PathsArg& arg, return_value_policy, handle) {
    return arg.object.inc_ref();
  }
};

/// Shared by the three enum arguments: the enum itself, or its name parsed by `parse`.
template <typename Arg, typename Enum, Enum (*parse)(const char*)>
struct enum_name_caster {
  bool load(handle src, bool /*convert*/) {
    if (isinstance<str>(src)) {
      value.value = parse(src.cast<std::string>().c_str());  // throws InvalidInputError
      return true;
    }
    make_caster<Enum> caster;
    if (!caster.load(src, false)) return false;
    value.value = cast_op<Enum>(caster);
    return true;
  }
  static handle cast(const Arg& arg, return_value_policy policy, handle parent) {
    return make_caster<Enum>::cast(arg.value, policy, parent);
  }
  template <typename T>
  using cast_op_type = Arg&;
  explicit operator Arg&() { return value; }
  Arg value;
};

template <>
struct type_caster<roiclip::python::FillRuleArg>
    : enum_name_caster<roiclip::python::FillRuleArg, roiclip::FillRule, roiclip::parseFillRule> {
  static constexpr auto name = const_name("FillRule | str");
};
template <>
struct type_caster<roiclip::python::ClipOpArg>
    : enum_name_caster<roiclip::python::ClipOpArg, roiclip::ClipOp, roiclip::parseClipOp> {
  static constexpr auto name = const_name("ClipOp | str");
};
template <>
struct type_caster<roiclip::python::LinePartArg>
    : enum_name_caster<roiclip::python::LinePartArg, roiclip::LinePart,
                       roiclip::python::parseLinePart> {
  static constexpr auto name = const_name("LinePart | str");
};

}  // namespace pybind11::detail
