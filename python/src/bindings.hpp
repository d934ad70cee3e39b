// SPDX-License-Identifier: MIT
// roiclip Python bindings: the parts of the module, each defined in its own file.
#pragma once

#include <pybind11/pybind11.h>

namespace roiclip::python {

/// Enums, PolygonSet, simplify/clip/..., clip_lines, from_contours, from_shapely (geometry.cpp).
void bindGeometry(pybind11::module_& m);
/// AprilTag detection, ROI builders, rasterize and the mask checks (vision.cpp).
void bindVision(pybind11::module_& m);
/// process_image: the `roiclip run` pipeline on one image (batch.cpp).
void bindBatch(pybind11::module_& m);

}  // namespace roiclip::python
