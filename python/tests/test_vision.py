# SPDX-License-Identifier: MIT
"""AprilTag detection, ROI builders, rasterize and the mask checks, on images/scene_01.png."""

import json

import cv2
import numpy as np
import pytest

import roiclip


@pytest.fixture(scope="module")
def truth(source_dir):
    return json.loads((source_dir / "images" / "scene_01.json").read_text())


@pytest.fixture(scope="module")
def tags(scene_gray):
    return roiclip.detect_tags(scene_gray)


def test_detect_tags(tags, truth, scene_gray):
    assert [t.id for t in tags] == [0, 1, 2, 3]
    for tag, expected in zip(tags, truth["tags"]):
        assert tag.family == "tag36h11" and tag.hamming == 0 and tag.decision_margin > 10
        assert tag.corners.shape == (4, 2) and tag.corners.dtype == np.float64
        assert tag.center.shape == (2,)
        np.testing.assert_allclose(tag.corners, expected["corners"], atol=0.5)
        np.testing.assert_allclose(tag.center, expected["centre"], atol=0.5)
        # The homography maps the tag frame's corners (+-0.5) onto the corners.
        h = tag.homography
        bottom_left = h @ [-0.5, 0.5, 1.0]
        np.testing.assert_allclose(bottom_left[:2] / bottom_left[2], tag.corners[0], atol=1e-6)
        np.testing.assert_allclose(tag.tag_to_image(0, 0), tag.center, atol=1e-6)
    # BGR, BGRA and a non-contiguous view give the same tags.
    for image in (cv2.cvtColor(scene_gray, cv2.COLOR_GRAY2BGR),
                  cv2.cvtColor(scene_gray, cv2.COLOR_GRAY2BGRA)):
        assert [t.id for t in roiclip.detect_tags(image)] == [0, 1, 2, 3]
    padded = np.zeros((600, 1600), np.uint8)
    padded[:, ::2] = scene_gray
    view = padded[:, ::2]
    np.testing.assert_allclose([t.corners for t in roiclip.Detector().detect(view)],
                               [t.corners for t in tags])
    assert "tag36h11" in roiclip.available_families()
    assert roiclip.family_size("tag36h11") == 587
    image, border = roiclip.render_tag("tag36h11", 0)
    assert image.dtype == np.uint8 and border == 8


def test_roi_builders(tags, truth, source_dir):
    hull = roiclip.convex_hull_of_tags(tags)
    assert len(hull) == 1 and hull[0].shape[1] == 2
    assert roiclip.simplify(hull).area > 0.5 * 800 * 600
    centres = roiclip.polygon_through_tags(tags, [0, 1, 2, 3])
    np.testing.assert_allclose(centres[0], [t.center for t in tags])
    corners = roiclip.polygon_through_tags(tags, [0, 1, 2, 3], anchor="top-left")
    np.testing.assert_allclose(corners[0], [t.corners[3] for t in tags])
    right = roiclip.tag_frame_roi(tags, 0, [[0.5, -0.5], [2.5, -0.5], [2.5, 0.5], [0.5, 0.5]])
    assert roiclip.simplify(right).area == pytest.approx(2 * 118 ** 2, rel=0.05)

    board = roiclip.Board.load(str(source_dir / "images" / "board.json"))
    assert board.family == "tag36h11" and board.tag_ids == [0, 1, 2, 3]
    assert board.roi_names == ["inspection", "window"]
    assert roiclip.Board.from_json(board.to_json()).roi_names == board.roi_names
    inspection = roiclip.board_roi(board, tags, "inspection")
    expected = next(r for r in truth["rois"] if r["name"] == "inspection")["paths"]
    for got, want in zip(inspection, expected):
        np.testing.assert_allclose(got, want, atol=1.0)

    spec = roiclip.parse_roi_spec("board:inspection")
    assert spec.kind == "board" and spec.roi_name == "inspection"
    for a, b in zip(roiclip.build_roi(spec, tags, board), inspection):
        np.testing.assert_array_equal(a, b)
    assert roiclip.parse_roi_spec("hull:0,2").ids == [0, 2]
    for a, b in zip(roiclip.build_roi("hull", tags), hull):
        np.testing.assert_array_equal(a, b)
    with pytest.raises(roiclip.InvalidInputError):
        roiclip.build_roi("board", tags)  # needs a board


def test_rasterize():
    square = [[0, 0], [4, 0], [4, 3], [0, 3]]
    mask = roiclip.rasterize(square, (5, 6))
    assert mask.shape == (5, 6) and mask.dtype == np.uint8
    expected = np.zeros((5, 6), np.uint8)
    expected[0:3, 0:4] = 255  # columns x0 .. x1-1, rows y0 .. y1-1
    np.testing.assert_array_equal(mask, expected)
    region = roiclip.simplify(square)
    np.testing.assert_array_equal(roiclip.rasterize(region, np.zeros((5, 6, 3)).shape), expected)
    twice = [square, square]
    assert roiclip.rasterize(twice, (5, 6), "evenodd").max() == 0
    assert roiclip.rasterize(twice, (5, 6), roiclip.FillRule.NON_ZERO).max() == 255


def test_mask_checks(scene_gray, scene_contours, tags):
    _, contours, hierarchy = scene_contours
    subject = roiclip.from_contours(contours, hierarchy)
    roi = roiclip.convex_hull_of_tags(tags)
    inside = roiclip.intersect(subject, roi)
    check = roiclip.check_roi_clip(subject, roi, inside, scene_gray.shape)
    assert check.ok and bool(check)
    assert check.vector_vs_raster.agrees_off_band and check.vector_vs_raster.iou > 0.999
    assert check.vector_vs_opencv is not None and check.vector_vs_opencv.agrees_off_band
    # A wrong result fails: the union is not the intersection.
    union = roiclip.union(subject, roi, "nonzero")
    assert not roiclip.check_roi_clip(subject, roi, union, scene_gray.shape).ok
    nonzero = roiclip.check_roi_clip(subject, roi, union, scene_gray.shape, "nonzero",
                                     "nonzero", op="union")
    assert nonzero.ok and nonzero.vector_vs_opencv is None

    mask = roiclip.rasterize(subject, scene_gray.shape)
    moved = np.roll(mask, 3, axis=1)
    comparison = roiclip.compare_masks(mask, moved, 1.0, subject)
    assert not comparison.agrees_off_band and comparison.off_band_only_actual > 0
    assert "IoU" in repr(comparison)
    same = roiclip.compare_masks(mask, mask.copy(), 0.0, [])
    assert same and same.iou == 1.0 and same.only_actual == 0
