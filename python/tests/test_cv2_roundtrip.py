# SPDX-License-Identifier: MIT
"""cv2.findContours -> roiclip -> cv2.drawContours gives back the same pixels off a 1 px band."""

import cv2
import numpy as np
import pytest

import roiclip


def _scene():
    image = np.zeros((240, 320), np.uint8)
    cv2.rectangle(image, (20, 20), (140, 120), 255, -1)
    cv2.rectangle(image, (50, 45), (100, 90), 0, -1)          # a hole
    cv2.rectangle(image, (65, 60), (80, 75), 255, -1)         # an island in the hole
    cv2.circle(image, (230, 80), 50, 255, -1)
    cv2.circle(image, (230, 80), 20, 0, -1)
    cv2.fillPoly(image, [np.array([[40, 200], [160, 150], [300, 230], [120, 220]], np.int32)], 255)
    cv2.ellipse(image, (260, 180), (40, 15), 30, 0, 360, 255, -1)
    return image


def _draw(contours, hierarchy, shape):
    out = np.zeros(shape, np.uint8)
    if contours:
        cv2.drawContours(out, contours, -1, 255, cv2.FILLED, hierarchy=hierarchy)
    return out


def _assert_equal_off_band(expected, actual, edges, band=1.0):
    comparison = roiclip.compare_masks(expected, actual, band, edges)
    assert comparison.agrees_off_band, comparison
    # The same with numpy alone: no pixel differs outside the band.
    outside = roiclip.boundary_band_mask(edges, band, expected.shape) == 0
    assert np.array_equal(expected[outside] > 0, actual[outside] > 0)
    return comparison


def test_findcontours_roundtrip():
    binary = _scene()
    contours, hierarchy = cv2.findContours(binary, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_SIMPLE)
    paths = roiclip.from_contours(contours, hierarchy)
    region = roiclip.simplify(paths)
    out_contours, out_hierarchy = region.to_contours()
    assert out_hierarchy.shape == (1, len(out_contours), 4)
    # Areas: the same polygons cv2 measures.
    signed = sum(cv2.contourArea(c, True) for c in out_contours)
    assert -signed == pytest.approx(region.area)
    redrawn = _draw(out_contours, out_hierarchy, binary.shape)
    comparison = _assert_equal_off_band(binary, redrawn, paths)
    assert comparison.iou > 0.99


def test_clip_to_rectangle_roundtrip():
    binary = _scene()
    contours, hierarchy = cv2.findContours(binary, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_SIMPLE)
    rect = np.array([[60, 30], [280, 30], [280, 210], [60, 210]], np.int32)
    inside = roiclip.intersect(roiclip.from_contours(contours, hierarchy), rect)
    out_contours, out_hierarchy = inside.to_contours()
    redrawn = _draw(out_contours, out_hierarchy, binary.shape)
    rect_mask = np.zeros_like(binary)
    cv2.fillPoly(rect_mask, [rect], 255)
    expected = cv2.bitwise_and(binary, rect_mask)
    _assert_equal_off_band(expected, redrawn, roiclip.from_contours(contours) + [rect])


def test_scene_clip_matches_raster_route(scene_contours, scene_gray):
    binary, contours, hierarchy = scene_contours
    roi = roiclip.convex_hull_of_tags(roiclip.detect_tags(scene_gray))
    subject = roiclip.from_contours(contours, hierarchy)
    inside = roiclip.intersect(subject, roi)
    # Vector result drawn exactly vs. the subject and ROI masks (exact rasteriser).
    expected = cv2.bitwise_and(roiclip.rasterize(subject, binary.shape),
                               roiclip.rasterize(roi, binary.shape))
    _assert_equal_off_band(expected, roiclip.rasterize(inside, binary.shape), subject + roi,
                           band=roiclip.EXACT_BAND)
    # And through cv2's own drawing, sub-pixel vertices rounded: off OpenCV's band.
    out_contours, out_hierarchy = inside.to_contours()
    roi_mask = np.zeros_like(binary)
    cv2.fillPoly(roi_mask, [np.round(roi[0]).astype(np.int32)], 255)
    _assert_equal_off_band(cv2.bitwise_and(binary, roi_mask),
                           _draw(out_contours, out_hierarchy, binary.shape), subject + roi,
                           band=roiclip.OPENCV_BAND)
