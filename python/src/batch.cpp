// SPDX-License-Identifier: MIT
// Python binding of roiclip::batch: process_image(), the `roiclip run` pipeline on one image,
// returning the NAME.json record (batch::resultToJson) as a dict.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <roiclip/batch/options.hpp>
#include <roiclip/batch/process.hpp>

#include <pybind11/stl.h>  // the roi list, the optional name

#include "arrays.hpp"
#include "bindings.hpp"

namespace roiclip::python {

namespace {

using batch::RunOptions;

std::vector<std::string> roiSpecs(const py::handle& roi) {
  if (py::isinstance<py::str>(roi)) return {roi.cast<std::string>()};
  std::vector<std::string> out;
  for (const py::handle spec : py::reinterpret_borrow<py::iterable>(roi)) {
    if (!py::isinstance<py::str>(spec)) {
      throw InvalidInputError("roi: expected a spec string or a list of them");
    }
    out.push_back(spec.cast<std::string>());
  }
  return out;
}

bool isPath(const py::handle& image) {
  return py::isinstance<py::str>(image) ||
         py::isinstance(image, py::module_::import("os").attr("PathLike"));
}

}  // namespace

void bindBatch(py::module_& m) {
  const RunOptions defaults;  // the one set of defaults (batch/options.hpp)
  m.def(
      "process_image",
      [](const py::object& image, const py::object& roi, const std::string& board,
         const std::string& family, double tagMargin, bool keepTags, const std::string& method,
         const std::string& polarity, double approxEpsilon, double minArea,
         const FillRuleArg& fillRule, const FillRuleArg& roiFillRule, float quadDecimate,
         int maxHamming, double minMargin, bool edges, std::int64_t maxPixels,
         const std::optional<std::string>& name) {
        RunOptions o;
        o.rois = roiSpecs(roi);
        o.boardFile = board;
        o.detector.family = family;
        o.tagMargin = tagMargin;
        o.keepTags = keepTags;
        batch::parseContourMethod(method, o.contours);
        o.contours.polarity = batch::parsePolarity(polarity);
        o.contours.approxEpsilon = approxEpsilon;
        o.contours.minArea = minArea;
        o.subjectFillRule = fillRule.value;
        o.roiFillRule = roiFillRule.value;
        o.detector.quadDecimate = quadDecimate;
        o.detector.maxHamming = maxHamming;
        o.detector.minDecisionMargin = minMargin;
        o.contours.openEdges = edges;
        o.maxPixels = maxPixels;

        std::string text;
        if (isPath(image)) {
          const std::string file = py::str(py::module_::import("os").attr("fspath")(image));
          py::gil_scoped_release release;
          const batch::Processor processor(o);
          text = batch::resultToJson(processor.processFile(file), name.value_or(file),
                                     batch::optionsKey(o));
        } else {
          py::array keep;
          const cv::Mat mat = matView(image, "image", keep);
          py::gil_scoped_release release;
          const batch::Processor processor(o);
          text =
              batch::resultToJson(processor.process(mat), name.value_or(""), batch::optionsKey(o));
        }
        return py::module_::import("json").attr("loads")(text);
      },
      py::arg("image"), py::kw_only(), py::arg("roi") = defaults.rois, py::arg("board") = "",
      py::arg("family") = defaults.detector.family, py::arg("tag_margin") = defaults.tagMargin,
      py::arg("keep_tags") = defaults.keepTags,
      py::arg("method") = batch::toString(defaults.contours.method),
      py::arg("polarity") = batch::toString(defaults.contours.polarity),
      py::arg("approx_epsilon") = defaults.contours.approxEpsilon,
      py::arg("min_area") = defaults.contours.minArea,
      py::arg("fill_rule") = toString(defaults.subjectFillRule),
      py::arg("roi_fill_rule") = toString(defaults.roiFillRule),
      py::arg("quad_decimate") = defaults.detector.quadDecimate,
      py::arg("max_hamming") = defaults.detector.maxHamming,
      py::arg("min_margin") = defaults.detector.minDecisionMargin,
      py::arg("edges") = defaults.contours.openEdges, py::arg("max_pixels") = defaults.maxPixels,
      py::arg("name") = py::none(),
      "Run `roiclip run`'s pipeline on one image and return its record: the same dict as the "
      "NAME.json file `roiclip run` writes (docs/outputs.md): status, failure, reason, tags, "
      "ROIs, 'clipped' (a GeoJSON FeatureCollection in pixel coordinates, y down), the "
      "figures, 'mask_check' (None when it did not run) and 'seconds'.\n\n"
      "`image` is a numpy array (uint8/uint16/float32, gray, BGR or BGRA, as cv2.imread "
      "gives) or a file path (str or os.PathLike), read as `roiclip run` reads it (header "
      "checked against max_pixels before decoding). Per-image problems are in the record "
      "(status 'no-roi' or 'failed' with a reason), as in `roiclip run`; bad options raise "
      "InvalidInputError. Options are the `roiclip run` flags: roi (a spec or a list of "
      "specs: 'hull', 'hull:0,2,5', 'tags:0,1,2,3[@anchor]', 'board[:NAME]', 'tag:ID:x,y;...'), "
      "board (board JSON file), family, tag_margin, keep_tags, method ('otsu', 'adaptive', "
      "'canny', 'threshold:T'), polarity ('dark', 'light'), approx_epsilon, min_area, "
      "fill_rule, roi_fill_rule, quad_decimate (0: automatic), max_hamming, min_margin, edges "
      "(also clip the Canny edges), max_pixels (<= 0: no limit); name is stored as 'image' "
      "(default: the path, or '' for an array). Releases the GIL while it works.");
}

}  // namespace roiclip::python
