# SPDX-License-Identifier: MIT
"""Errors are Python exceptions with the core's messages."""

import numpy as np
import pytest

import roiclip

SQUARE = [[0, 0], [10, 0], [10, 10], [0, 10]]


def test_hierarchy():
    assert issubclass(roiclip.InvalidInputError, roiclip.Error)
    assert issubclass(roiclip.InvalidInputError, ValueError)
    assert issubclass(roiclip.InternalError, roiclip.Error)
    assert issubclass(roiclip.MissingTagsError, roiclip.Error)
    assert issubclass(roiclip.Error, Exception)


# Finite coordinates are taken wherever they lie (the grid is fitted to each call's operands).
def test_far_coordinates_are_taken():
    far = np.array(SQUARE, np.float64) + 1e12
    assert roiclip.intersect(far, far).area == pytest.approx(roiclip.intersect(SQUARE, SQUARE).area)


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf])
def test_bad_coordinates(bad):
    subject = np.array(SQUARE, np.float64)
    subject[2, 1] = bad
    with pytest.raises(ValueError) as info:
        roiclip.intersect(subject, SQUARE)
    assert isinstance(info.value, roiclip.InvalidInputError)
    assert "subject path 0, vertex 2: y" in str(info.value)
    with pytest.raises(roiclip.InvalidInputError, match="clip path 1, vertex 2"):
        roiclip.intersect(SQUARE, [SQUARE, subject])
    with pytest.raises(roiclip.InvalidInputError, match="line path 0"):
        roiclip.clip_lines(subject, SQUARE)


def test_bad_arrays():
    with pytest.raises(roiclip.InvalidInputError, match=r"subject path 0: .*shape \(4, 3\)"):
        roiclip.simplify(np.zeros((4, 3)))
    with pytest.raises(roiclip.InvalidInputError, match="clip path 1"):
        roiclip.intersect(SQUARE, [SQUARE, [[1, 2, 3]]])
    with pytest.raises(roiclip.InvalidInputError, match="dtype"):
        roiclip.simplify(np.array([["a", "b"], ["c", "d"]]))
    with pytest.raises(roiclip.InvalidInputError, match="got str"):
        roiclip.simplify("square")
    with pytest.raises(roiclip.InvalidInputError, match="got int"):
        roiclip.simplify(3)
    with pytest.raises(roiclip.InvalidInputError):
        roiclip.simplify([[[0, 0], [1, 0]], [[0, 0], [1]]])  # ragged path


def test_bad_names():
    with pytest.raises(roiclip.InvalidInputError, match="unknown fill rule 'bogus'"):
        roiclip.simplify(SQUARE, "bogus")
    with pytest.raises(roiclip.InvalidInputError, match="unknown operation 'cut'"):
        roiclip.clip("cut", SQUARE, SQUARE)
    with pytest.raises(roiclip.InvalidInputError, match="unknown line part"):
        roiclip.clip_lines(SQUARE, SQUARE, part="middle")
    with pytest.raises(TypeError):
        roiclip.simplify(SQUARE, 3.5)
    with pytest.raises(roiclip.InvalidInputError, match="dtype"):
        roiclip.simplify(SQUARE).to_contours(np.int16)


def test_degenerate_input_is_not_an_error():
    assert roiclip.simplify([[0, 0], [1, 1]]).area == 0
    assert roiclip.intersect(SQUARE, [[5, 5], [5, 5], [5, 5]]).area == 0


def test_vision_errors(scene_gray):
    with pytest.raises(roiclip.InvalidInputError):
        roiclip.detect_tags(scene_gray, family="tag99h99")
    with pytest.raises(roiclip.InvalidInputError):
        roiclip.detect_tags(np.zeros((10, 10), np.float64))
    with pytest.raises(roiclip.InvalidInputError, match="image"):
        roiclip.detect_tags(np.zeros(10, np.uint8))
    tags = roiclip.detect_tags(scene_gray)
    with pytest.raises(roiclip.MissingTagsError) as info:
        roiclip.convex_hull_of_tags(tags, [0, 7])
    assert info.value.missing == [7] and info.value.seen == [0, 1, 2, 3]
    assert "missing [7]" in str(info.value)
    with pytest.raises(roiclip.InvalidInputError, match="nonsense"):
        roiclip.parse_roi_spec("nonsense")
    with pytest.raises(roiclip.InvalidInputError):
        roiclip.Board.load("/nonexistent/board.json")
    with pytest.raises(roiclip.InvalidInputError):
        roiclip.compare_masks(np.zeros((4, 4), np.uint8), np.zeros((5, 5), np.uint8), 1.0, [])
    with pytest.raises(roiclip.InvalidInputError, match="shape"):
        roiclip.rasterize(SQUARE, (10,))
