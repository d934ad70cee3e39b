# SPDX-License-Identifier: MIT
"""roiclip: exact clipping of self-intersecting polygons for vision pipelines.

Arrays in, arrays out. A *path* is any array-like of shape (N, 2) or cv2's (N, 1, 2), int32 or
float; *paths* are a list of those (cv2.findContours' tuple works), a single one, or a
PolygonSet. Results are PolygonSet objects (``.area``, ``len()``, iteration over Polygon with
``.exterior``, ``.holes``, ``.area``, ``.parent``), convertible back to cv2 contours with
``.to_contours()`` and to shapely with ``shapely.geometry.shape(result)``.

    import cv2, roiclip
    gray = cv2.imread("images/scene_01.png", cv2.IMREAD_GRAYSCALE)
    roi = roiclip.convex_hull_of_tags(roiclip.detect_tags(gray))
    _, binary = cv2.threshold(gray, 0, 255, cv2.THRESH_BINARY_INV | cv2.THRESH_OTSU)
    contours, hierarchy = cv2.findContours(binary, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_SIMPLE)
    inside = roiclip.intersect(roiclip.from_contours(contours, hierarchy), roi)
    print(inside.area)

Conventions: pixels, x right, y DOWN, (0, 0) the centre of the top-left pixel (as OpenCV).
Inputs are snapped to a 1/256 px grid, |coordinate| <= 4,194,304 px; every topological decision
after that is exact. Outer rings of results have a negative shoelace sum (cv2.contourArea(c,
True) < 0) and holes a positive one. Fill rules and operations are enums (FillRule.NON_ZERO,
ClipOp.UNION) or their names ('nonzero', 'union').

The whole `roiclip run` pipeline on one image (tags -> ROI -> contours -> exact clip -> mask
check) is ``roiclip.process_image(image_or_path, roi="hull", ...)``: it returns the dict
NAME.json holds (docs/outputs.md), with the clipped polygons as a GeoJSON FeatureCollection.

Errors: roiclip.Error is the root; InvalidInputError (also a ValueError) for NaN, out-of-range
coordinates, malformed arrays or files, with the C++ library's message naming the input;
MissingTagsError when an ROI builder lacks tags; InternalError for bugs. The GIL is released
while clipping, rasterising and detecting, so threads run in parallel.
"""

from ._roiclip import (  # noqa: F401  (re-exported)
    EXACT_BAND,
    OPENCV_BAND,
    Board,
    ClipOp,
    Detector,
    Error,
    FillRule,
    InternalError,
    InvalidInputError,
    LinePart,
    MaskCheck,
    MaskComparison,
    MissingTagsError,
    Polygon,
    PolygonSet,
    RoiSpec,
    Tag,
    __version__,
    available_families,
    board_roi,
    boundary_band_mask,
    build_roi,
    check_roi_clip,
    clip,
    clip_lines,
    compare_masks,
    convex_hull_of_tags,
    detect_tags,
    difference,
    family_size,
    from_contours,
    from_shapely,
    intersect,
    parse_roi_spec,
    polygon_through_tags,
    process_image,
    rasterize,
    release_thread_buffers,
    render_tag,
    round_to,
    simplify,
    tag_frame_roi,
    union,
    xor,
)

__all__ = [
    "EXACT_BAND",
    "OPENCV_BAND",
    "Board",
    "ClipOp",
    "Detector",
    "Error",
    "FillRule",
    "InternalError",
    "InvalidInputError",
    "LinePart",
    "MaskCheck",
    "MaskComparison",
    "MissingTagsError",
    "Polygon",
    "PolygonSet",
    "RoiSpec",
    "Tag",
    "__version__",
    "available_families",
    "board_roi",
    "boundary_band_mask",
    "build_roi",
    "check_roi_clip",
    "clip",
    "clip_lines",
    "compare_masks",
    "convex_hull_of_tags",
    "detect_tags",
    "difference",
    "family_size",
    "from_contours",
    "from_shapely",
    "intersect",
    "parse_roi_spec",
    "polygon_through_tags",
    "process_image",
    "rasterize",
    "release_thread_buffers",
    "render_tag",
    "round_to",
    "simplify",
    "tag_frame_roi",
    "union",
    "xor",
]

# Classes report the public package (roiclip.PolygonSet), not the compiled module.
for _name in ("Board", "ClipOp", "Detector", "FillRule", "LinePart", "MaskCheck",
              "MaskComparison", "Polygon", "PolygonSet", "RoiSpec", "Tag"):
    globals()[_name].__module__ = __name__
del _name
