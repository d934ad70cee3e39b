# SPDX-License-Identifier: MIT
"""Areas against shapely on valid inputs; __geo_interface__ and from_shapely."""

import math

import numpy as np
import pytest
import shapely.geometry
from shapely.geometry import MultiPolygon, Point, Polygon, box, shape

import roiclip

OPS = {
    "intersection": lambda a, b: a.intersection(b),
    "union": lambda a, b: a.union(b),
    "difference": lambda a, b: a.difference(b),
    "xor": lambda a, b: a.symmetric_difference(b),
}


def _star(rng, centre, radius, n):
    """A valid star-shaped polygon with integer vertices (so snapping to the grid is exact)."""
    while True:
        angles = np.sort(rng.uniform(0, 2 * math.pi, n))
        radii = rng.uniform(0.3, 1.0, n) * radius
        points = np.round(np.c_[centre[0] + radii * np.cos(angles),
                                centre[1] + radii * np.sin(angles)])
        polygon = Polygon(points)
        if polygon.is_valid and polygon.area > 0:
            return polygon


def _cases():
    rng = np.random.default_rng(16)
    cases = []
    for i in range(24):
        a = _star(rng, rng.uniform(40, 60, 2), 40, int(rng.integers(5, 40)))
        b = _star(rng, rng.uniform(40, 60, 2), 40, int(rng.integers(5, 40)))
        if i % 3 == 1:  # a with a hole
            hole = box(45, 45, 52, 52)
            if a.contains(hole):
                a = a.difference(hole)
        if i % 3 == 2:  # b a MultiPolygon
            b = MultiPolygon([b, box(120, 0, 140, 30)])
        cases.append((a, b))
    return cases


@pytest.mark.parametrize("op", sorted(OPS))
def test_areas_against_shapely(op):
    for a, b in _cases():
        expected = OPS[op](a, b)
        result = roiclip.clip(op, roiclip.from_shapely(a), roiclip.from_shapely(b))
        assert result.area == pytest.approx(expected.area, rel=1e-9, abs=1e-7)
        # The result converts back and is the same region.
        back = shape(result)
        assert back.is_valid
        assert back.area == pytest.approx(result.area, rel=1e-12, abs=1e-9)
        assert back.symmetric_difference(expected).area < 1e-6


def test_geo_interface_layout():
    region = roiclip.simplify([[[0, 0], [30, 0], [30, 30], [0, 30]],
                               [[5, 5], [25, 5], [25, 25], [5, 25]]])
    geo = region.__geo_interface__
    assert geo["type"] == "MultiPolygon" and len(geo["coordinates"]) == 1
    rings = geo["coordinates"][0]
    assert len(rings) == 2 and all(r[0] == r[-1] for r in rings)  # closed rings
    assert shapely.geometry.shape(region).area == pytest.approx(500)
    assert shapely.geometry.shape(region[0]).area == pytest.approx(500)  # one Polygon
    assert shape(roiclip.PolygonSet()).is_empty


def test_from_shapely_inputs():
    donut = Point(50, 50).buffer(20).difference(Point(50, 50).buffer(10))
    paths = roiclip.from_shapely(donut)
    assert len(paths) == 2 and all(p.shape[1] == 2 for p in paths)
    assert not np.array_equal(paths[0][0], paths[0][-1])  # the closing point dropped
    assert roiclip.simplify(paths).area == pytest.approx(donut.area, rel=1e-4)
    multi = MultiPolygon([box(0, 0, 1, 1), box(2, 0, 3, 1)])
    assert len(roiclip.from_shapely(multi)) == 2
    mapping = {"type": "Feature", "geometry": box(0, 0, 2, 2).__geo_interface__}
    assert roiclip.simplify(roiclip.from_shapely(mapping)).area == pytest.approx(4)
    # Geometries are operands as they are, alone or in a list, and so is a PolygonSet.
    assert roiclip.intersect(box(0, 0, 10, 10), [box(5, 5, 20, 20)]).area == pytest.approx(25)
    region = roiclip.simplify(roiclip.from_shapely(donut))
    assert roiclip.from_shapely(region)[0].shape == region[0].exterior.shape
    with pytest.raises(roiclip.InvalidInputError, match="Point"):
        roiclip.from_shapely(Point(0, 0))
