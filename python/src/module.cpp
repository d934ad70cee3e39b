// SPDX-License-Identifier: MIT
// The compiled part of the Python package roiclip (imported and re-exported by
// roiclip/__init__.py). Exceptions: roiclip.Error (root), roiclip.InvalidInputError (also a
// ValueError), roiclip.InternalError, roiclip.MissingTagsError, carrying the C++ library's
// messages.
#include <exception>
#include <vector>

#include <roiclip/apriltag/roi.hpp>
#include <roiclip/batch/process.hpp>  // roiclipVersion()
#include <roiclip/error.hpp>

#include "bindings.hpp"

namespace py = pybind11;

namespace {

py::object newException(py::module_& m, const char* name, const char* doc, py::handle bases) {
  const std::string qualified = std::string("roiclip.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (!type) throw py::error_already_set();
  auto object = py::reinterpret_steal<py::object>(type);
  m.attr(name) = object;
  return object;
}

py::list intList(const std::vector<int>& v) {
  py::list l;
  for (int i : v) l.append(i);
  return l;
}

}  // namespace

PYBIND11_MODULE(_roiclip, m) {
  m.doc() =
      "Exact clipping of self-intersecting polygons for vision pipelines (C++ core; see the "
      "roiclip package docstring).";
  m.attr("__version__") = roiclip::batch::roiclipVersion();

  // Kept for the life of the interpreter (the translator below uses them).
  static py::handle error, invalidInput, internal, missingTags;
  error = newException(m, "Error", "Root of all roiclip exceptions.", PyExc_Exception).release();
  invalidInput =
      newException(m, "InvalidInputError",
                   "Input roiclip cannot process: NaN or infinite coordinates, coordinates outside "
                   "the supported range, malformed arrays or files, wrong image types. The "
                   "message names the input (e.g. 'subject path 0, vertex 3: x is not a finite "
                   "number'). Also a ValueError.",
                   py::make_tuple(error, py::handle(PyExc_ValueError)))
          .release();
  internal = newException(m, "InternalError",
                          "An internal consistency check failed: a bug in roiclip; please report "
                          "the input.",
                          error)
                 .release();
  missingTags = newException(m, "MissingTagsError",
                             "An ROI builder did not find the tags it needs. Attributes: needed, "
                             "seen, missing, duplicated (lists of ids), minimum_needed.",
                             error)
                    .release();

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const roiclip::apriltag::MissingTagsError& e) {
      const auto& info = e.info();
      py::object exc = py::reinterpret_borrow<py::object>(missingTags)(e.what());
      exc.attr("needed") = intList(info.needed);
      exc.attr("seen") = intList(info.seen);
      exc.attr("missing") = intList(info.missing);
      exc.attr("duplicated") = intList(info.duplicated);
      exc.attr("minimum_needed") = info.minimumNeeded;
      PyErr_SetObject(missingTags.ptr(), exc.ptr());
    } catch (const roiclip::InvalidInputError& e) {
      PyErr_SetString(invalidInput.ptr(), e.what());
    } catch (const roiclip::InternalError& e) {
      PyErr_SetString(internal.ptr(), e.what());
    } catch (const roiclip::Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });

  roiclip::python::bindGeometry(m);
  roiclip::python::bindVision(m);
  roiclip::python::bindBatch(m);
}
