# SPDX-License-Identifier: MIT
"""The core through Python: operand forms, enums and names, results and their conversions."""

import numpy as np
import pytest

import roiclip

BOWTIE = [[0, 0], [10, 10], [10, 0], [0, 10]]
BAND = [[2, -1], [8, -1], [8, 11], [2, 11]]
SQUARE = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], dtype=np.int32)


def test_readme_example():
    inside = roiclip.intersect(BOWTIE, BAND, roiclip.FillRule.EVEN_ODD)
    assert inside.area == pytest.approx(18.0)
    assert len(inside) == 2
    simple = roiclip.simplify(BOWTIE, roiclip.FillRule.NON_ZERO)
    assert simple.area == pytest.approx(50.0)
    kept = roiclip.clip_lines([[-5, 5], [15, 5]], BAND)
    assert len(kept) == 1
    np.testing.assert_array_equal(kept[0], [[2, 5], [8, 5]])


@pytest.mark.parametrize("make", [
    lambda p: p,                                          # list of points: one path
    lambda p: [p],                                        # list of paths
    lambda p: tuple([np.asarray(p)]),                     # cv2.findContours' tuple
    lambda p: np.asarray(p, dtype=np.int32),              # (N, 2) int32
    lambda p: np.asarray(p, dtype=np.float32),            # (N, 2) float32
    lambda p: np.asarray(p, dtype=np.int32)[:, None, :],  # cv2's (N, 1, 2)
    lambda p: np.asarray([p], dtype=np.float64),          # (K, N, 2)
    lambda p: np.asarray(p, dtype=np.float64)[::-1][::-1],  # non-contiguous view
    lambda p: roiclip.simplify(p, "nonzero"),             # a PolygonSet
])
def test_operand_forms(make):
    square = [[0, 0], [10, 0], [10, 10], [0, 10]]
    assert roiclip.intersect(make(square), BAND).area == pytest.approx(60.0)
    assert roiclip.simplify(make(square)).area == pytest.approx(100.0)


def test_empty_operands():
    assert roiclip.simplify([]).area == 0
    assert len(roiclip.simplify(np.zeros((0, 2)))) == 0
    assert roiclip.union([], SQUARE).area == pytest.approx(100.0)
    assert roiclip.intersect(SQUARE, []).area == 0
    assert not roiclip.PolygonSet()


def test_fill_rules_and_ops_by_enum_and_name():
    twice = [SQUARE, SQUARE]  # winding number 2 inside (or -2, by orientation)
    assert roiclip.simplify(twice, "evenodd").area == 0
    assert roiclip.simplify(twice, roiclip.FillRule.NON_ZERO).area == pytest.approx(100.0)
    assert roiclip.simplify(twice, "non-zero").area == pytest.approx(100.0)
    signed = roiclip.simplify(twice, "positive").area + roiclip.simplify(twice, "negative").area
    assert signed == pytest.approx(100.0)
    shifted = SQUARE + 5
    areas = {op: roiclip.clip(op, SQUARE, shifted).area for op in
             ("intersection", "union", "difference", "xor")}
    assert areas == pytest.approx({"intersection": 25, "union": 175, "difference": 75, "xor": 150})
    for op, name in [(roiclip.ClipOp.INTERSECTION, "intersection"), (roiclip.ClipOp.UNION, "union"),
                     (roiclip.ClipOp.DIFFERENCE, "difference"), (roiclip.ClipOp.XOR, "xor")]:
        assert roiclip.clip(op, SQUARE, shifted).area == pytest.approx(areas[name])
        assert op.name == name.upper()
    assert roiclip.union(SQUARE, shifted).area == pytest.approx(175)
    assert roiclip.difference(SQUARE, shifted).area == pytest.approx(75)
    assert roiclip.xor(SQUARE, shifted).area == pytest.approx(150)
    assert roiclip.clip("and", SQUARE, twice, clip_fill_rule="evenodd").area == 0


def test_polygon_set_structure():
    outer = [[0, 0], [30, 0], [30, 30], [0, 30]]
    hole = [[5, 5], [25, 5], [25, 25], [5, 25]]
    island = [[10, 10], [20, 10], [20, 20], [10, 20]]
    result = roiclip.simplify([outer, hole, island])
    assert len(result) == 2 and result.ring_count == 3
    assert result.area == pytest.approx(900 - 400 + 100)
    top, inner = result[0], result[1]
    assert result[-1].area == inner.area
    assert top.parent is None and top.parent_hole is None
    assert inner.parent == 0 and inner.parent_hole == 0
    assert top.exterior.shape == (4, 2) and top.exterior.dtype == np.float64
    assert len(top.holes) == 1 and top.holes[0].shape == (4, 2)
    assert top.area == pytest.approx(500) and inner.area == pytest.approx(100)
    assert [p.area for p in result] == [top.area, inner.area]
    assert sum(1 for _ in result) == 2
    with pytest.raises(IndexError):
        result[2]
    # Orientation as cv2.findContours: outer rings negative shoelace sum, holes positive.
    assert _shoelace(top.exterior) < 0 and _shoelace(top.holes[0]) > 0
    assert len(result.to_paths()) == 3
    assert "2 polygons" in repr(result)


def test_polygon_outlives_its_set():
    polygon = roiclip.simplify(SQUARE)[0]
    assert polygon.area == pytest.approx(100)  # reference_internal keeps the set alive


def test_to_contours_layout():
    outer = [[0, 0], [30, 0], [30, 30], [0, 30]]
    hole = [[5, 5], [25, 5], [25, 25], [5, 25]]
    island = [[10, 10], [20, 10], [20, 20], [10, 20]]
    contours, hierarchy = roiclip.simplify([outer, hole, island]).to_contours()
    assert isinstance(contours, tuple) and len(contours) == 3
    assert all(c.dtype == np.int32 and c.ndim == 3 and c.shape[1:] == (1, 2) for c in contours)
    assert hierarchy.dtype == np.int32 and hierarchy.shape == (1, 3, 4)
    h = hierarchy[0]
    # RETR_CCOMP: outer rings top level and linked, holes children of their outer ring.
    tops = [i for i in range(3) if h[i][3] == -1]
    assert len(tops) == 2
    holes = [i for i in range(3) if h[i][3] != -1]
    assert len(holes) == 1 and h[h[holes[0]][3]][2] == holes[0]
    float_contours, _ = roiclip.simplify([[[0.5, 0], [3, 0], [3, 2]]]).to_contours(np.float64)
    assert float_contours[0].dtype == np.float64 and 0.5 in float_contours[0]
    assert roiclip.simplify([[[0.5, 0], [3, 0], [3, 2]]]).to_contours("float32")[0][0].dtype \
        == np.float32
    assert roiclip.PolygonSet().to_contours() == ((), None)


def test_from_contours_orients_by_hierarchy():
    outer = np.array([[0, 0], [0, 30], [30, 30], [30, 0]], np.int32)[:, None, :]  # either way
    hole = np.array([[5, 5], [5, 25], [25, 25], [25, 5]], np.int32)[:, None, :]
    hierarchy = np.array([[[-1, -1, 1, -1], [-1, -1, -1, 0]]], np.int32)
    paths = roiclip.from_contours((outer, hole), hierarchy)
    assert _shoelace(paths[0]) < 0 and _shoelace(paths[1]) > 0
    assert roiclip.simplify(paths, "nonzero").area == pytest.approx(500)
    kept = roiclip.from_contours([outer, hole])
    np.testing.assert_array_equal(kept[0], outer[:, 0, :])
    assert roiclip.simplify(kept, "evenodd").area == pytest.approx(500)


def test_clip_lines_parts():
    line = np.array([[-5, 5], [15, 5]], np.float32)
    inside = roiclip.clip_lines([line], BAND, part=roiclip.LinePart.INSIDE)
    outside = roiclip.clip_lines(line, BAND, "nonzero", "outside")
    assert sum(np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in inside) == 6
    assert sum(np.linalg.norm(np.diff(p, axis=0), axis=1).sum() for p in outside) == 14


def test_version():
    assert isinstance(roiclip.__version__, str) and roiclip.__version__.count(".") == 2


def _shoelace(ring):
    x, y = np.asarray(ring, np.float64).T
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def test_round_to_keeps_parts_apart():
    # The apex (5.40625, 0.515625) lies just below the edge (0,0)-(10,1): rounded alone it would
    # land inside the other part; snap rounding routes the edge through (5, 1) as well.
    region = roiclip.simplify([[[0, 0], [10, 1], [10, 5], [0, 5]],
                               [[5.40625, 0.515625], [7, -3], [4, -3]]], "nonzero")
    rounded = roiclip.round_to(region, 1.0)
    assert len(rounded) == 2
    for polygon in rounded:
        assert np.array_equal(polygon.exterior, np.round(polygon.exterior))
    assert abs(rounded.area - region.area) < 5
    contours, _ = region.to_contours()
    assert any((c[:, 0] == [5, 1]).all(axis=1).any() for c in contours)
    with pytest.raises(roiclip.InvalidInputError):
        roiclip.round_to(region, 0.0)
