# SPDX-License-Identifier: MIT
"""Shared fixtures: the source tree (images/) and the bundled scene."""

import os
import pathlib

import cv2
import pytest

SOURCE_DIR = pathlib.Path(
    os.environ.get("ROICLIP_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def scene_gray():
    image = cv2.imread(str(SOURCE_DIR / "images" / "scene_01.png"), cv2.IMREAD_GRAYSCALE)
    assert image is not None, "images/scene_01.png not readable"
    return image


@pytest.fixture(scope="session")
def scene_contours(scene_gray):
    """The batch pipeline's contours: Otsu, inverted (dark objects), RETR_CCOMP, SIMPLE."""
    _, binary = cv2.threshold(scene_gray, 0, 255, cv2.THRESH_BINARY_INV | cv2.THRESH_OTSU)
    contours, hierarchy = cv2.findContours(binary, cv2.RETR_CCOMP, cv2.CHAIN_APPROX_SIMPLE)
    return binary, contours, hierarchy
