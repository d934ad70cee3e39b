// SPDX-License-Identifier: MIT
// Python bindings of roiclip::apriltag (detection, ROI builders, boards) and of roiclip::opencv's
// rasteriser and mask checks. Images are numpy arrays viewed as cv::Mat without a copy.
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <roiclip/apriltag/detector.hpp>
#include <roiclip/apriltag/roi.hpp>
#include <roiclip/opencv/mask_check.hpp>
#include <roiclip/opencv/rasterize.hpp>

#include <pybind11/stl.h>  // vector<int>, vector<string> (ids, family names)

#include "arrays.hpp"
#include "bindings.hpp"

namespace roiclip::python {

namespace {

using apriltag::Detection;
using apriltag::Detector;
using apriltag::DetectorOptions;

constexpr const char* kPixels =
    "Coordinates are pixels in OpenCV's convention: (0, 0) is the centre of the top-left pixel, "
    "x right, y down.";

std::vector<Detection> toDetections(const py::handle& tags) {
  if (py::isinstance<py::str>(tags) || !PySequence_Check(tags.ptr())) {
    throw InvalidInputError("tags: expected a list of roiclip.Tag (detect_tags() output)");
  }
  std::vector<Detection> out;
  for (const py::handle t : py::reinterpret_borrow<py::sequence>(tags)) {
    if (!py::isinstance<Detection>(t)) {
      throw InvalidInputError("tags: expected roiclip.Tag objects, got " +
                              py::str(py::type::handle_of(t).attr("__name__")).cast<std::string>());
    }
    out.push_back(t.cast<const Detection&>());
  }
  return out;
}

py::list toList(std::vector<Detection> detections) {
  py::list l;
  for (Detection& d : detections) l.append(py::cast(std::move(d)));
  return l;
}

std::vector<int> toIds(const py::handle& ids) {
  std::vector<int> out;
  if (ids.is_none()) return out;
  for (const py::handle i : py::reinterpret_borrow<py::iterable>(ids)) out.push_back(i.cast<int>());
  return out;
}

/// The ROI paths, or MissingTagsError (translated to roiclip.MissingTagsError).
py::list roiPaths(const apriltag::RoiResult& roi) { return toArrays(roi.value()); }

DetectorOptions detectorOptions(std::string family, float quadDecimate, float quadSigma,
                                bool refineEdges, int threads, double decodeSharpening,
                                int maxBitsCorrected) {
  DetectorOptions o;
  o.family = std::move(family);
  o.quadDecimate = quadDecimate;
  o.quadSigma = quadSigma;
  o.refineEdges = refineEdges;
  o.threads = threads;
  o.decodeSharpening = decodeSharpening;
  o.maxBitsCorrected = maxBitsCorrected;
  return o;
}

py::list detect(const Detector& detector, const py::handle& image) {
  py::array keep;
  const cv::Mat mat = matView(image, "image", keep);
  std::vector<Detection> found;
  {
    py::gil_scoped_release release;
    found = detector.detect(mat);
  }
  return toList(std::move(found));
}

// Detector options as keyword arguments, shared by Detector() and detect_tags().
#define ROICLIP_DETECTOR_ARGS                                                                    \
  py::arg("family") = "tag36h11", py::arg("quad_decimate") = 0.0f, py::arg("quad_sigma") = 0.0f, \
  py::arg("refine_edges") = true, py::arg("threads") = 1, py::arg("decode_sharpening") = 0.25,   \
  py::arg("max_bits_corrected") = 2

constexpr const char* kDetectorArgs =
    "family: tag family (see available_families()); quad_decimate: detect quads on an image "
    "decimated by this factor (>= 1), or 0 (the default) for automatic decimation, coarse to "
    "fine as in roiclip run; quad_sigma: Gaussian blur of the quad image (0 off); "
    "refine_edges: snap quad edges to strong gradients; threads: libapriltag worker threads "
    "(one runs with libapriltag before 3.4.3, whose worker pool can crash with more); "
    "decode_sharpening: payload sharpening; max_bits_corrected: bit errors the decoder may "
    "correct (0..3). Raises InvalidInputError for an unknown family or out-of-range options.";

py::object maskComparisonRepr(const opencv::MaskComparison& c) {
  std::ostringstream os;
  os << c;
  return py::str("<roiclip.MaskComparison " + os.str() + ">");
}

}  // namespace

void bindVision(py::module_& m) {
  // --- AprilTag detection -----------------------------------------------------------------------
  py::class_<Detection>(m, "Tag", (std::string("One decoded AprilTag. ") + kPixels).c_str())
      .def_readonly("id", &Detection::id, "Tag id within its family.")
      .def_readonly("family", &Detection::family, "Tag family, e.g. 'tag36h11'.")
      .def_readonly("hamming", &Detection::hamming, "Number of corrected bit errors.")
      .def_readonly("decision_margin", &Detection::decisionMargin,
                    "libapriltag's decode quality (higher is better).")
      .def_property_readonly(
          "center", [](const Detection& d) { return toArray(Point(d.centre)); },
          "Image of the tag centre as a (2,) float64 array.")
      .def_property_readonly(
          "corners",
          [](const Detection& d) { return toArray(Path(d.corners.begin(), d.corners.end())); },
          "Outer corners of the black border, (4, 2) float64, libapriltag's order: bottom-left, "
          "bottom-right, top-right, top-left of the upright tag (counter-clockwise on screen).")
      .def_property_readonly(
          "homography",
          [](const Detection& d) {
            py::array_t<double> h({3, 3});
            auto r = h.mutable_unchecked<2>();
            for (int row = 0; row < 3; ++row) {
              for (int col = 0; col < 3; ++col) r(row, col) = d.homography[col][row];  // GLM: [col]
            }
            return h;
          },
          "Image-from-tag homography as a (3, 3) float64 array acting on column vectors "
          "(x, y, 1): H @ (u, v, 1). Tag frame: origin at the centre, unit = black-border side, "
          "corners at (+-0.5, +-0.5).")
      .def(
          "tag_to_image",
          [](const Detection& d, double u, double v) {
            return toArray(Point(d.tagToImage({u, v})));
          },
          py::arg("u"), py::arg("v"), "Map a point of the tag frame into the image.")
      .def("__repr__", [](const Detection& d) {
        return "<roiclip.Tag " + d.family + " id " + std::to_string(d.id) + " at (" +
               py::repr(py::float_(d.centre.x)).cast<std::string>() + ", " +
               py::repr(py::float_(d.centre.y)).cast<std::string>() + ")>";
      });

  py::class_<Detector>(m, "Detector",
                       "An AprilTag detector for one family; reuse it across frames (creating "
                       "one builds the family's decode table). detect() releases the GIL; calls "
                       "on one Detector from several threads are serialised, so give each thread "
                       "its own Detector for parallel detection.")
      .def(py::init([](std::string family, float quadDecimate, float quadSigma, bool refineEdges,
                       int threads, double decodeSharpening, int maxBitsCorrected) {
             const DetectorOptions o =
                 detectorOptions(std::move(family), quadDecimate, quadSigma, refineEdges, threads,
                                 decodeSharpening, maxBitsCorrected);
             py::gil_scoped_release release;
             return Detector(o);
           }),
           ROICLIP_DETECTOR_ARGS, kDetectorArgs)
      .def("detect", &detect, py::arg("image"),
           (std::string("Detect all tags in `image`: a uint8 numpy array, gray (H, W), BGR "
                        "(H, W, 3) or BGRA (H, W, 4); never modified. Returns a list of Tag "
                        "sorted by id. ") +
            kPixels)
               .c_str())
      .def_property_readonly(
          "family", [](const Detector& d) { return d.options().family; }, "The tag family.");

  m.def(
      "detect_tags",
      [](const py::object& image, std::string family, float quadDecimate, float quadSigma,
         bool refineEdges, int threads, double decodeSharpening, int maxBitsCorrected) {
        const DetectorOptions o =
            detectorOptions(std::move(family), quadDecimate, quadSigma, refineEdges, threads,
                            decodeSharpening, maxBitsCorrected);
        std::optional<Detector> detector;
        {
          py::gil_scoped_release release;
          detector.emplace(o);
        }
        return detect(*detector, image);
      },
      py::arg("image"), ROICLIP_DETECTOR_ARGS,
      (std::string("Detect AprilTags in a uint8 image (gray, BGR or BGRA numpy array) with a "
                   "new Detector; returns a list of Tag (id, corners (4, 2), center, hamming, "
                   "decision_margin), sorted by id. For many frames keep a Detector. ") +
       kDetectorArgs)
          .c_str());

  m.def("available_families", &apriltag::availableFamilies,
        "Tag family names this build supports.");
  m.def("family_size", &apriltag::familySize, py::arg("family"),
        "Number of ids in a family (valid ids 0 .. size-1).");
  m.def(
      "render_tag",
      [](const std::string& family, int id) {
        int border = 0;
        cv::Mat image = apriltag::renderTag(family, id, &border);
        return py::make_tuple(toArray(std::move(image)), border);
      },
      py::arg("family"), py::arg("id"),
      "Tag `id` of `family` as libapriltag draws it: (image, black_border_cells), the image a "
      "uint8 array of one pixel per cell (0 black, 255 white) including the white border.");

  // --- ROI builders -----------------------------------------------------------------------------
  m.def(
      "convex_hull_of_tags",
      [](const py::object& tags, const py::object& ids) {
        return roiPaths(apriltag::convexHullOfTags(toDetections(tags), toIds(ids)));
      },
      py::arg("tags"), py::arg("ids") = py::none(),
      "ROI: convex hull of the 4 corners of every tag in `ids` (all tags when None), as paths "
      "(a list with one (N, 2) float64 array, negative shoelace sum). Raises MissingTagsError "
      "when a listed id is missing or detected twice, or nothing was detected.");
  m.def(
      "polygon_through_tags",
      [](const py::object& tags, const py::object& ids, const std::string& anchor) {
        return roiPaths(apriltag::polygonThroughTags(toDetections(tags), toIds(ids),
                                                     apriltag::parseTagAnchor(anchor)));
      },
      py::arg("tags"), py::arg("ids"), py::arg("anchor") = "centre",
      "ROI: one closed path through the anchor point ('centre', 'bottom-left', 'bottom-right', "
      "'top-right', 'top-left') of each listed tag (at least 3 ids), in the order given. "
      "Raises MissingTagsError when a listed id is missing or detected twice.");
  m.def(
      "tag_frame_roi",
      [](const py::object& tags, int id, const PathsArg& paths) {
        return roiPaths(
            apriltag::tagFrameRoi(toDetections(tags), id, toPaths(paths.object, "tag frame")));
      },
      py::arg("tags"), py::arg("id"), py::arg("paths"),
      "ROI: paths given in tag `id`'s own frame (origin at its centre, unit = black-border "
      "side, x right and y down for an upright tag) mapped into the image.");

  py::class_<apriltag::Board>(m, "Board",
                              "A planar board: tag corners and named ROI polygons in one board "
                              "frame (format in images/README.md).")
      .def_static("load", &apriltag::Board::load, py::arg("path"),
                  "Read and parse a board JSON file. Raises InvalidInputError.")
      .def_static("from_json", &apriltag::Board::fromJson, py::arg("text"),
                  py::arg("source") = "board", "Parse a board from JSON text.")
      .def("to_json", &apriltag::Board::toJson, py::arg("indent") = 1,
           "The board as JSON text (-1: one line).")
      .def_readonly("family", &apriltag::Board::family, "Tag family.")
      .def_readonly("units", &apriltag::Board::units, "Board frame unit (informative).")
      .def_property_readonly(
          "tag_ids",
          [](const apriltag::Board& b) {
            py::list ids;
            for (const auto& entry : b.tags) ids.append(entry.first);
            return ids;
          },
          "Ids of the board's tags.")
      .def_property_readonly(
          "roi_names",
          [](const apriltag::Board& b) {
            py::list names;
            for (const auto& r : b.rois) names.append(r.name);
            return names;
          },
          "Names of the board's ROIs.")
      .def(
          "roi",
          [](const apriltag::Board& b, const std::string& name) {
            return toArrays(b.roi(name).paths);
          },
          py::arg("name"), "The ROI `name` in board units (InvalidInputError if unknown).");

  m.def(
      "board_roi",
      [](const apriltag::Board& board, const py::object& tags, const std::string& roiName,
         double ransacThreshold) {
        const std::vector<Detection> d = toDetections(tags);
        apriltag::RoiResult roi = std::vector<Path>{};
        {
          py::gil_scoped_release release;
          roi = apriltag::boardRoi(board, d, roiName, ransacThreshold);
        }
        return roiPaths(roi);
      },
      py::arg("board"), py::arg("tags"), py::arg("roi_name") = "",
      py::arg("ransac_threshold") = 2.0,
      "ROI: the board ROI `roi_name` (all ROIs when empty) mapped into the image through the "
      "image-from-board homography fitted to the detected board tags (RANSAC, then least "
      "squares). Raises MissingTagsError when no board tag was detected.");

  py::class_<apriltag::RoiSpec> spec(m, "RoiSpec",
                                     "A parsed ROI description (parse_roi_spec), as "
                                     "`roiclip run --roi` takes it.");
  spec.def_property_readonly(
          "kind",
          [](const apriltag::RoiSpec& s) {
            switch (s.kind) {
              case apriltag::RoiSpec::Kind::Tags:
                return "tags";
              case apriltag::RoiSpec::Kind::Hull:
                return "hull";
              case apriltag::RoiSpec::Kind::Board:
                return "board";
              case apriltag::RoiSpec::Kind::TagFrame:
                return "tag";
            }
            return "?";
          },
          "'tags', 'hull', 'board' or 'tag' (tag frame).")
      .def_readonly("ids", &apriltag::RoiSpec::ids, "Tag ids (order for 'tags', set for 'hull').")
      .def_readonly("roi_name", &apriltag::RoiSpec::roiName, "Board ROI name ('board' only).")
      .def_property_readonly(
          "tag_frame_paths", [](const apriltag::RoiSpec& s) { return toArrays(s.tagFramePaths); },
          "Paths in the tag frame ('tag' only).");

  m.def("parse_roi_spec", &apriltag::parseRoiSpec, py::arg("text"),
        "Parse 'tags:0,1,2,3[@anchor]', 'hull', 'hull:0,2,5', 'board', 'board:NAME' or "
        "'tag:ID:x,y;x,y;...' into a RoiSpec. Raises InvalidInputError quoting the text.");
  m.def(
      "build_roi",
      [](const py::object& specArg, const py::object& tags, const apriltag::Board* board) {
        const apriltag::RoiSpec s = py::isinstance<py::str>(specArg)
                                        ? apriltag::parseRoiSpec(specArg.cast<std::string>())
                                        : specArg.cast<apriltag::RoiSpec>();
        const std::vector<Detection> d = toDetections(tags);
        apriltag::RoiResult roi = std::vector<Path>{};
        {
          py::gil_scoped_release release;
          roi = apriltag::buildRoi(s, d, board);
        }
        return roiPaths(roi);
      },
      py::arg("spec"), py::arg("tags"), py::arg("board") = nullptr,
      "ROI a spec (RoiSpec or its text) describes, from one image's tags, as paths. `board` is "
      "required for 'board' specs. Raises MissingTagsError when tags are missing.");

  // --- Rasterising and mask checks --------------------------------------------------------------
  m.def(
      "rasterize",
      [](const PathsArg& region, const py::object& shape, const FillRuleArg& rule) {
        const cv::Size size = toSize(shape);
        cv::Mat mask;
        if (py::isinstance<PolygonSet>(region.object)) {
          const auto& set = region.object.cast<const PolygonSet&>();
          py::gil_scoped_release release;
          mask = opencv::rasterize(set, size);
        } else {
          const Paths paths = toPaths(region.object, "subject");
          py::gil_scoped_release release;
          mask = opencv::rasterize(paths, rule.value, size);
        }
        return toArray(std::move(mask));
      },
      py::arg("region"), py::arg("shape"), py::arg("fill_rule") = "evenodd",
      "Exact rasterisation: a (H, W) uint8 mask (255 inside, 0 outside) of `region` (a "
      "PolygonSet, or paths read with `fill_rule`) for an image of `shape` ((H, W) or "
      "image.shape). Pixel (col, row) is set when its centre is inside (a centre on an edge "
      "belongs to the region to its right, then below); no edge lines as cv2.fillPoly draws.");

  py::class_<opencv::MaskComparison>(m, "MaskComparison",
                                     "Result of compare_masks(); 'on' means non-zero.")
      .def_readonly("only_expected", &opencv::MaskComparison::onlyExpected,
                    "Pixels on in expected, off in actual.")
      .def_readonly("only_actual", &opencv::MaskComparison::onlyActual,
                    "Pixels on in actual, off in expected.")
      .def_readonly("both", &opencv::MaskComparison::both, "Pixels on in both.")
      .def_readonly("iou", &opencv::MaskComparison::iou, "Intersection over union (1 if all off).")
      .def_readonly("boundary_band", &opencv::MaskComparison::boundaryBand, "The band used (px).")
      .def_readonly("band_pixels", &opencv::MaskComparison::bandPixels,
                    "Pixels ignored because they lie within the band.")
      .def_readonly("off_band_only_expected", &opencv::MaskComparison::offBandOnlyExpected,
                    "only_expected outside the band.")
      .def_readonly("off_band_only_actual", &opencv::MaskComparison::offBandOnlyActual,
                    "only_actual outside the band.")
      .def_readonly("off_band_iou", &opencv::MaskComparison::offBandIou, "IoU outside the band.")
      .def_property_readonly("agrees_off_band", &opencv::MaskComparison::agreesOffBand,
                             "True when the masks agree on every pixel outside the band.")
      .def("__bool__", &opencv::MaskComparison::agreesOffBand, "agrees_off_band.")
      .def("__repr__", &maskComparisonRepr);

  m.attr("EXACT_BAND") = opencv::kExactBand;
  m.attr("OPENCV_BAND") = opencv::kOpenCvBand;

  m.def(
      "compare_masks",
      [](const py::object& expected, const py::object& actual, double band, const PathsArg& edges) {
        py::array keepExpected;
        py::array keepActual;
        const cv::Mat e = matView(expected, "expected", keepExpected);
        const cv::Mat a = matView(actual, "actual", keepActual);
        const Paths edgePaths = toPaths(edges.object, "edges");
        py::gil_scoped_release release;
        return opencv::compareMasks(e, a, band, edgePaths);
      },
      py::arg("expected"), py::arg("actual"), py::arg("band"), py::arg("edges"),
      "Compare two single-channel uint8 masks of the same size pixel by pixel, ignoring pixels "
      "whose centre is within `band` px of an edge of `edges` (normally every path of both "
      "operands). Returns a MaskComparison. Raises InvalidInputError on a type or size "
      "mismatch or a negative band.");
  m.def(
      "boundary_band_mask",
      [](const PathsArg& paths, double band, const py::object& shape) {
        const Paths p = toPaths(paths.object, "subject");
        const cv::Size size = toSize(shape);
        cv::Mat mask;
        {
          py::gil_scoped_release release;
          mask = opencv::boundaryBandMask(p, band, size);
        }
        return toArray(std::move(mask));
      },
      py::arg("paths"), py::arg("band"), py::arg("shape"),
      "uint8 mask (255) of the pixels whose centre lies within `band` px of an edge of `paths`.");

  py::class_<opencv::MaskCheck>(m, "MaskCheck", "Everything check_roi_clip() computed.")
      .def_readonly("vector_vs_raster", &opencv::MaskCheck::vectorVsRaster,
                    "rasterize(clipped) against the raster route (rasterize(subject) op "
                    "rasterize(roi)), band exact_band.")
      .def_property_readonly(
          "vector_vs_opencv",
          [](const opencv::MaskCheck& c) -> py::object {
            if (!c.vectorVsOpenCv) return py::none();
            return py::cast(*c.vectorVsOpenCv);
          },
          "rasterize(clipped) against cv2.fillPoly(subject) op cv2.fillPoly(roi), band "
          "opencv_band; None unless both fill rules are even-odd.")
      .def_property_readonly("ok", &opencv::MaskCheck::ok,
                             "True when every comparison agrees off its band.")
      .def("__bool__", &opencv::MaskCheck::ok, "ok.");

  m.def(
      "check_roi_clip",
      [](const PathsArg& subject, const PathsArg& roi, const PolygonSet& result,
         const py::object& shape, const FillRuleArg& subjectRule, const FillRuleArg& roiRule,
         const ClipOpArg& op, double exactBand, double openCvBand) {
        const Paths s = toPaths(subject.object, "subject");
        const Paths r = toPaths(roi.object, "clip");
        const cv::Size size = toSize(shape);
        opencv::MaskCheckOptions options;
        options.op = op.value;
        options.exactBand = exactBand;
        options.openCvBand = openCvBand;
        py::gil_scoped_release release;
        return opencv::checkRoiClip(s, r, result, subjectRule.value, roiRule.value, size, options);
      },
      py::arg("subject"), py::arg("roi"), py::arg("result"), py::arg("shape"),
      py::arg("subject_fill_rule") = "evenodd", py::arg("roi_fill_rule") = "evenodd",
      py::arg("op") = "intersection", py::arg("exact_band") = opencv::kExactBand,
      py::arg("opencv_band") = opencv::kOpenCvBand,
      "The project's mask check: is `result` (a PolygonSet) what clip(op, subject, roi) should "
      "be? It never clips; it compares "
      "rasterize(result) with rasterize(subject) AND rasterize(roi) (off `exact_band`) and, for "
      "even-odd/even-odd, with cv2.fillPoly(subject) AND cv2.fillPoly(roi) (off `opencv_band`); "
      "AND becomes OR / AND NOT / XOR for other ops. Returns a MaskCheck; assert check.ok.");
}

}  // namespace roiclip::python
