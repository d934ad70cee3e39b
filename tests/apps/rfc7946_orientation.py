# SPDX-License-Identifier: MIT
"""RFC 7946 ring order of `roiclip simplify` / `clip` output, checked with shapely.

Usage: python3 rfc7946_orientation.py ROICLIP DATA_DIR

Default output: every exterior ring counter-clockwise (shapely's is_ccw, on the raw x, y
numbers), every hole clockwise, i.e. what shapely.geometry.polygon.orient(p, 1.0) gives;
--orientation opencv: the opposite. The areas shapely computes match roiclip's.
"""
import json
import subprocess
import sys

from shapely.geometry import shape
from shapely.geometry.polygon import LinearRing, orient

roiclip, data = sys.argv[1], sys.argv[2]


def polygons(args):
    out = subprocess.run([roiclip] + args, check=True, capture_output=True, text=True).stdout
    for feature in json.loads(out)["features"]:
        geometry = shape(feature["geometry"])
        assert geometry.is_valid, (args, feature)
        for polygon in getattr(geometry, "geoms", [geometry]):
            yield feature, polygon


cases = [
    ["simplify", f"{data}/frame.geojson"],
    ["simplify", f"{data}/bowtie.json"],
    ["simplify", "--dissolve", f"{data}/parcels.geojson"],
    ["clip", f"{data}/parcels.geojson", f"{data}/two_rois.geojson"],
    ["clip", "--op", "xor", f"{data}/frame.geojson", f"{data}/roi.geojson"],
]
checked = 0
for args in cases:
    for _, polygon in polygons(args):
        assert LinearRing(polygon.exterior.coords).is_ccw, (args, "exterior not ccw")
        for hole in polygon.interiors:
            assert not LinearRing(hole.coords).is_ccw, (args, "hole not cw")
        # orient(p, 1.0) is RFC 7946's order: nothing to change.
        assert list(orient(polygon, 1.0).exterior.coords) == list(polygon.exterior.coords), args
        checked += 1
    for _, polygon in polygons(args + ["--orientation", "opencv"]):
        assert not LinearRing(polygon.exterior.coords).is_ccw, (args, "opencv exterior is ccw")
        for hole in polygon.interiors:
            assert LinearRing(hole.coords).is_ccw, (args, "opencv hole is cw")

# Areas: shapely's (orientation-free) equal roiclip's summary.
out = subprocess.run([roiclip, "simplify", "--dissolve", f"{data}/frame.geojson"], check=True,
                     capture_output=True, text=True).stdout
feature = json.loads(out)["features"][0]
assert abs(shape(feature["geometry"]).area - feature["properties"]["area"]) < 1e-9, feature
# The frame has a hole: the check above saw at least one.
assert any(p.interiors for _, p in polygons(["simplify", f"{data}/frame.geojson"]))
print(f"RFC 7946 order: {checked} polygons checked with shapely")
