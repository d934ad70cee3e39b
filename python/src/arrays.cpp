// SPDX-License-Identifier: MIT
#include "arrays.hpp"

#include <cctype>
#include <cstring>
#include <string>
#include <vector>

#include <roiclip/error.hpp>

namespace roiclip::python {

namespace {

std::string shapeText(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    if (i) s += ", ";
    s += std::to_string(a.shape(i));
  }
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string typeName(const py::handle& object) {
  return py::str(py::type::handle_of(object).attr("__name__")).cast<std::string>();
}

std::string dtypeName(const py::dtype& dt) { return py::str(dt.attr("name")).cast<std::string>(); }

/// A numeric array-like as a C-contiguous float64 array (numpy converts, in C).
/// @throws InvalidInputError naming `name` when it is not numeric.
py::array_t<double> numericArray(const py::handle& object, const std::string& name) {
  const py::array a = py::array::ensure(object);
  if (!a) {
    throw InvalidInputError(name + ": expected an array of points, got " + typeName(object));
  }
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f') {
    throw InvalidInputError(name + ": expected numbers (int or float), got an array of dtype " +
                            dtypeName(a.dtype()) + " and shape " + shapeText(a));
  }
  return py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
}

/// (N, 2), (N, 1, 2) or empty; with `allowZ`, also (N, 3) (GeoJSON positions with z).
Path toPath(const py::handle& object, const std::string& name, bool allowZ = false) {
  const py::array_t<double> a = numericArray(object, name);
  const auto nd = a.ndim();
  if (a.size() == 0 && nd <= 2) return {};
  const bool planar =
      (nd == 2 && a.shape(1) == 2) || (nd == 3 && a.shape(1) == 1 && a.shape(2) == 2);
  const bool withZ = allowZ && nd == 2 && a.shape(1) == 3;
  if (!planar && !withZ) {
    throw InvalidInputError(name + ": expected an array of shape (N, 2) or (N, 1, 2), got shape " +
                            shapeText(a));
  }
  const auto n = static_cast<std::size_t>(a.shape(0));
  const std::size_t stride = withZ ? 3 : 2;
  const double* d = a.data();
  Path path(n);
  for (std::size_t i = 0; i < n; ++i) path[i] = Point(d[stride * i], d[stride * i + 1]);
  return path;
}

/// numpy dtype names indexed by OpenCV depth (CV_8U = 0 .. CV_64F = 6).
constexpr const char* kDtypeOfDepth[] = {"uint8", "int8",    "uint16", "int16",
                                         "int32", "float32", "float64"};

/// The OpenCV depth of a numpy dtype, or -1. Bool masks (one byte, 0 or 1) count as CV_8U.
int depthOf(const py::dtype& dt) {
  if (dt.kind() == 'b') return CV_8U;
  if (dt.byteorder() == '>') return -1;  // big-endian data would be misread
  const std::string name = dtypeName(dt);
  for (int depth = CV_8U; depth <= CV_64F; ++depth) {
    if (name == kDtypeOfDepth[depth]) return depth;
  }
  return -1;
}

bool isNumber(const py::handle& h) {
  return !py::isinstance<py::str>(h) && !PySequence_Check(h.ptr()) && PyNumber_Check(h.ptr());
}

/// True when `first` (the first element of a sequence operand) is a point, so the operand is a
/// single path; false when it is itself a path.
bool isPoint(const py::handle& first) {
  if (py::isinstance<py::array>(first)) return py::reinterpret_borrow<py::array>(first).ndim() <= 1;
  if (isNumber(first)) return true;
  if (PySequence_Check(first.ptr()) && !py::isinstance<py::str>(first)) {
    const py::sequence s = py::reinterpret_borrow<py::sequence>(first);
    return s.size() > 0 && isNumber(s[0]);
  }
  return false;
}

}  // namespace

LinePart parseLinePart(const char* name) {
  std::string s = name ? name : "";
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (s == toString(LinePart::Inside)) return LinePart::Inside;
  if (s == toString(LinePart::Outside)) return LinePart::Outside;
  throw InvalidInputError(std::string("unknown line part '") + (name ? name : "") +
                          "' (expected inside or outside)");
}

Paths toPaths(const py::handle& object, const std::string& operand) {
  if (py::isinstance<PolygonSet>(object)) return object.cast<const PolygonSet&>().toPaths();
  if (py::isinstance<py::array>(object)) {
    const auto a = py::reinterpret_borrow<py::array>(object);
    if (a.size() == 0 && a.ndim() <= 1) return {};
    // (N, 2) and cv2's (N, 1, 2) are one path; (K, N, 2) are K paths of N points.
    if (a.ndim() == 3 && a.shape(1) != 1) {
      Paths paths;
      for (py::ssize_t k = 0; k < a.shape(0); ++k) {
        paths.push_back(toPath(a[py::int_(k)], operand + " path " + std::to_string(k)));
      }
      return paths;
    }
    return {toPath(a, operand + " path 0")};
  }
  // shapely geometries (and anything else with __geo_interface__), as from_shapely() reads them.
  if (py::hasattr(object, "__geo_interface__")) return geoInterfacePaths(object);
  if (py::isinstance<py::str>(object) || py::isinstance<py::bytes>(object) ||
      !PySequence_Check(object.ptr())) {
    throw InvalidInputError(operand +
                            ": expected a path (array of shape (N, 2) or (N, 1, 2)), a sequence "
                            "of paths, a PolygonSet or a geometry with __geo_interface__, got " +
                            typeName(object));
  }
  const py::sequence seq = py::reinterpret_borrow<py::sequence>(object);
  if (seq.size() == 0) return {};
  if (isPoint(seq[0])) return {toPath(seq, operand + " path 0")};
  Paths paths;
  paths.reserve(seq.size());
  for (const py::handle item : seq) {
    if (py::isinstance<PolygonSet>(item) || py::hasattr(item, "__geo_interface__")) {
      const Paths rings = toPaths(item, operand);
      paths.insert(paths.end(), rings.begin(), rings.end());
    } else {
      paths.push_back(toPath(item, operand + " path " + std::to_string(paths.size())));
    }
  }
  return paths;
}

Paths geoInterfacePaths(const py::handle& object) {
  const py::object geo = py::hasattr(object, "__geo_interface__")
                             ? py::object(object.attr("__geo_interface__"))
                             : py::reinterpret_borrow<py::object>(object);
  if (!py::isinstance<py::dict>(geo) || !geo.contains("type")) {
    throw InvalidInputError(
        "from_shapely: expected a geometry with __geo_interface__ or a GeoJSON "
        "mapping, got " +
        typeName(object));
  }
  const auto type = py::str(geo["type"]).cast<std::string>();
  Paths paths;
  const auto addPolygon = [&](const py::handle& rings) {
    for (const py::handle ring : rings) {
      Path p = toPath(ring, "from_shapely: ring " + std::to_string(paths.size()), true);
      if (p.size() > 1 && p.front() == p.back()) p.pop_back();  // GeoJSON closes its rings
      paths.push_back(std::move(p));
    }
  };
  const auto addAll = [&](const py::handle& items) {
    for (const py::handle item : items) {
      Paths more = geoInterfacePaths(item);
      paths.insert(paths.end(), more.begin(), more.end());
    }
  };
  if (type == "Polygon") {
    addPolygon(geo["coordinates"]);
  } else if (type == "MultiPolygon") {
    for (const py::handle polygon : geo["coordinates"]) addPolygon(polygon);
  } else if (type == "GeometryCollection") {
    addAll(geo["geometries"]);
  } else if (type == "Feature") {
    if (!geo["geometry"].is_none()) paths = geoInterfacePaths(geo["geometry"]);
  } else if (type == "FeatureCollection") {
    addAll(geo["features"]);
  } else {
    throw InvalidInputError("from_shapely: a " + type +
                            " has no area (expected Polygon or MultiPolygon)");
  }
  return paths;
}

py::array_t<double> toArray(const Path& path) {
  py::array_t<double> a({static_cast<py::ssize_t>(path.size()), py::ssize_t{2}});
  double* d = a.mutable_data();
  for (std::size_t i = 0; i < path.size(); ++i) {
    d[2 * i] = path[i].x;
    d[2 * i + 1] = path[i].y;
  }
  return a;
}

py::list toArrays(const Paths& paths) {
  py::list list;
  for (const Path& p : paths) list.append(toArray(p));
  return list;
}

py::array_t<double> toArray(const Point& point) {
  py::array_t<double> a(2);
  a.mutable_data()[0] = point.x;
  a.mutable_data()[1] = point.y;
  return a;
}

cv::Mat matView(const py::handle& object, const std::string& name, py::array& keep) {
  keep = py::array::ensure(object, py::array::c_style);
  if (!keep) throw InvalidInputError(name + ": expected a numpy array, got " + typeName(object));
  const int depth = depthOf(keep.dtype());
  if (depth < 0) {
    throw InvalidInputError(name + ": unsupported dtype " + dtypeName(keep.dtype()) +
                            " (expected uint8, int8, uint16, int16, int32, float32 or float64)");
  }
  if (keep.ndim() != 2 && !(keep.ndim() == 3 && keep.shape(2) >= 1 && keep.shape(2) <= CV_CN_MAX)) {
    throw InvalidInputError(name + ": expected an image of shape (H, W) or (H, W, C), got " +
                            shapeText(keep));
  }
  const int channels = keep.ndim() == 3 ? static_cast<int>(keep.shape(2)) : 1;
  return cv::Mat(static_cast<int>(keep.shape(0)), static_cast<int>(keep.shape(1)),
                 CV_MAKETYPE(depth, channels), const_cast<void*>(keep.data()));
}

py::array toArray(cv::Mat mat) {
  if (!mat.isContinuous()) mat = mat.clone();
  const py::dtype dt(kDtypeOfDepth[mat.depth()]);
  std::vector<py::ssize_t> shape = {mat.rows, mat.cols};
  if (mat.channels() > 1) shape.push_back(mat.channels());
  auto* owner = new cv::Mat(mat);
  const py::capsule base(owner, [](void* p) { delete static_cast<cv::Mat*>(p); });
  return py::array(dt, shape, {}, owner->data, base);
}

cv::Size toSize(const py::handle& shape) {
  const auto bad = [&]() {
    return InvalidInputError("shape: expected (height, width) or an image's shape, got " +
                             py::repr(shape).cast<std::string>());
  };
  if (!PySequence_Check(shape.ptr()) || py::isinstance<py::str>(shape)) throw bad();
  const py::sequence s = py::reinterpret_borrow<py::sequence>(shape);
  if (s.size() != 2 && s.size() != 3) throw bad();
  const auto height = s[0].cast<long long>();
  const auto width = s[1].cast<long long>();
  if (height < 0 || width < 0 || height > (1 << 30) || width > (1 << 30)) throw bad();
  return {static_cast<int>(width), static_cast<int>(height)};
}

}  // namespace roiclip::python
