# SPDX-License-Identifier: MIT
"""A pytest mask check, as a vision project would write one: the exact clip of the contours of
images/scene_01.png to its tag hull agrees with the raster route (masks ANDed) off a thin band.

    PYTHONPATH=build/python python3 -m pytest examples/python/test_mask_check.py
"""

import os
import pathlib

import cv2
import numpy as np
import pytest

import roiclip

IMAGES = pathlib.Path(os.environ.get("ROICLIP_SOURCE_DIR",
                                     pathlib.Path(__file__).resolve().parents[2])) / "images"


@pytest.fixture(scope="module")
def scene():
    gray = cv2.imread(str(IMAGES / "scene_01.png"), cv2.IMREAD_GRAYSCALE)
    _, binary = cv2.threshold(gray, 0, 255, cv2.THRESH_BINARY_INV | cv2.THRESH_OTSU)
    contours, hierarchy = cv2.findContours(binary, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_SIMPLE)
    roi = roiclip.convex_hull_of_tags(roiclip.detect_tags(gray))
    return gray.shape, roiclip.from_contours(contours, hierarchy), roi


def test_clip_agrees_with_raster_route(scene):
    shape, subject, roi = scene
    inside = roiclip.intersect(subject, roi)
    check = roiclip.check_roi_clip(subject, roi, inside, shape)
    assert check.ok, (check.vector_vs_raster, check.vector_vs_opencv)


def test_by_hand_with_numpy(scene):
    shape, subject, roi = scene
    inside = roiclip.intersect(subject, roi)
    expected = roiclip.rasterize(subject, shape) & roiclip.rasterize(roi, shape)
    actual = roiclip.rasterize(inside, shape)
    # Off a 0.05 px band around every input edge the masks are equal pixel for pixel.
    off_band = roiclip.boundary_band_mask(subject + roi, roiclip.EXACT_BAND, shape) == 0
    assert np.array_equal(expected[off_band], actual[off_band])
    # And the area of the vector result is the pixel count, up to the boundary pixels.
    assert abs(inside.area - np.count_nonzero(actual)) < 0.01 * inside.area
