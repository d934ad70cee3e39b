#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the hand-made seed inputs of the fuzz targets (docs/fuzzing.md) into
OUT/<target>/seed-<name>. The byte encodings of fuzz_simplify and fuzz_clip are those described
at the top of fuzz_simplify.cpp and fuzz_clip.cpp; the readers get the JSON files the reader
tests use, with ROI specs in front for fuzz_board.

usage: tests/fuzz/make_seeds.py OUT   (e.g. tests/fuzz/corpus)
"""
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
RULES = {"evenodd": 0, "nonzero": 1, "positive": 2, "negative": 3}
OPS = {"intersection": 0, "union": 1, "difference": 2, "xor": 3}

# Modes of fuzz_support.hpp decodeCoordinate: 0 -> 0..15, 1 -> -8..7, 2 -> half pixels,
# 3 -> 0..3, 4 -> +-2^22 px, 5 -> 1/256 px steps, 6 -> half pixels around 0, 7 -> 0..45.
BOWTIE = [[(0, 0), (10, 10), (10, 0), (0, 10)]]
PENTAGRAM = [[(8, 0), (13, 15), (0, 5), (15, 5), (3, 15)]]
SQUARE = [(0, 0), (15, 0), (15, 15), (0, 15)]
INNER = [(4, 4), (11, 4), (11, 11), (4, 11)]
NESTED_SAME = [SQUARE, INNER]
NESTED_HOLE = [SQUARE, INNER[::-1]]
SHARED_EDGE = [[(0, 0), (7, 0), (7, 7), (0, 7)], [(7, 0), (14, 0), (14, 7), (7, 7)]]
TOUCHING = [[(0, 0), (5, 0), (5, 5), (0, 5)], [(5, 5), (10, 5), (10, 10), (5, 10)]]
TWICE = [SQUARE + SQUARE]
SPIKE = [[(0, 0), (8, 0), (8, 8), (8, 14), (8, 8), (0, 8)]]
COLLINEAR = [[(0, 0), (3, 0), (6, 0), (9, 0), (9, 9), (6, 9), (6, 0), (3, 0), (3, 9), (0, 9)]]
DEGENERATE = [[(1, 1), (5, 5)], [(2, 2), (2, 2), (2, 2)], [(0, 0), (4, 4), (8, 8)]]
OVERLAP = [[(0, 0), (12, 0), (12, 6), (0, 6)], [(4, 0), (8, 0), (8, 12), (4, 12)]]


def paths_bytes(paths):
    out = bytearray()
    for p in paths:
        out.append(len(p))
        for x, y in p:
            assert 0 <= x < 16 and 0 <= y < 16, (x, y)
            out.append(x | (y << 4))
    return bytes(out)


def simplify_seed(paths, rule, mode=0):
    return bytes([RULES[rule] | (mode << 2)]) + paths_bytes(paths)


def clip_seed(subject, clip, op, srule="evenodd", crule="evenodd", mode=0, convex_clip=False,
              convex_subject=False, reverse=False):
    h0 = RULES[srule] | RULES[crule] << 2 | OPS[op] << 4 | convex_clip << 6 | convex_subject << 7
    h1 = mode | (len(subject) - 1) << 3 | reverse << 5
    return bytes([h0, h1]) + paths_bytes(subject) + paths_bytes(clip)


def lines_seed(lines, region, rule="evenodd", mode=0, convex=False, reverse=False):
    h0 = RULES[rule] | convex << 2 | reverse << 3
    h1 = mode | (len(lines) - 1) << 3
    return bytes([h0, h1]) + paths_bytes(lines) + paths_bytes(region)


def write(out, target, name, data):
    d = out / target
    d.mkdir(parents=True, exist_ok=True)
    (d / ("seed-" + name)).write_bytes(data if isinstance(data, bytes) else data.encode())


def main():
    out = pathlib.Path(sys.argv[1])
    shapes = {"bowtie": BOWTIE, "pentagram": PENTAGRAM, "nested_same": NESTED_SAME,
              "nested_hole": NESTED_HOLE, "shared_edge": SHARED_EDGE, "touching": TOUCHING,
              "twice_wound": TWICE, "spike": SPIKE, "collinear": COLLINEAR,
              "degenerate": DEGENERATE, "overlap": OVERLAP}
    for name, paths in shapes.items():
        for rule in RULES:
            write(out, "fuzz_simplify", f"{name}_{rule}", simplify_seed(paths, rule))
    for mode in range(1, 8):
        write(out, "fuzz_simplify", f"pentagram_nonzero_mode{mode}",
              simplify_seed(PENTAGRAM, "nonzero", mode))
        write(out, "fuzz_simplify", f"bowtie_evenodd_mode{mode}",
              simplify_seed(BOWTIE, "evenodd", mode))

    roi = [[(2, 0), (8, 0), (8, 12), (2, 12)]]
    bowtie = [[(0, 1), (10, 11), (10, 1), (0, 11)]]
    for op in OPS:
        write(out, "fuzz_clip", f"bowtie_roi_{op}", clip_seed(bowtie, roi, op))
        write(out, "fuzz_clip", f"pentagram_square_{op}_nonzero",
              clip_seed(PENTAGRAM, [INNER], op, "nonzero", "nonzero"))
        write(out, "fuzz_clip", f"identical_{op}", clip_seed([SQUARE], [SQUARE], op))
        write(out, "fuzz_clip", f"shared_edge_{op}",
              clip_seed(SHARED_EDGE[:1], SHARED_EDGE[1:], op))
        write(out, "fuzz_clip", f"nested_{op}", clip_seed([SQUARE], [INNER], op))
        write(out, "fuzz_clip", f"touching_{op}", clip_seed(TOUCHING[:1], TOUCHING[1:], op))
        write(out, "fuzz_clip", f"twice_wound_{op}_positive",
              clip_seed(TWICE, [INNER[::-1]], op, "positive", "negative"))
    # The convex fast path (a single strictly convex ring, intersection), both orientations and
    # with the convex ring on either side.
    quad = [[(3, 1), (12, 2), (14, 13), (1, 11)]]
    for rule in RULES:
        write(out, "fuzz_clip", f"convex_quad_{rule}",
              clip_seed(PENTAGRAM, quad, "intersection", rule, rule, convex_clip=True))
        write(out, "fuzz_clip", f"convex_quad_reversed_{rule}",
              clip_seed(PENTAGRAM, quad, "intersection", rule, rule, convex_clip=True,
                        reverse=True))
    write(out, "fuzz_clip", "convex_subject",
          clip_seed(quad, BOWTIE, "intersection", convex_subject=True))
    write(out, "fuzz_clip", "convex_collinear_points",
          clip_seed(COLLINEAR, [[(0, 0), (5, 0), (10, 0), (10, 10), (0, 10), (0, 5)]],
                    "intersection", "nonzero", "evenodd", convex_clip=True))
    for mode in (2, 4, 5):
        write(out, "fuzz_clip", f"convex_quad_mode{mode}",
              clip_seed(PENTAGRAM, quad, "intersection", mode=mode, convex_clip=True))

    # Open polylines: crossing, along the boundary, through a vertex, touching, inside holes.
    line_sets = {"cross": [[(0, 7), (15, 7)]], "along": [[(0, 0), (15, 0), (15, 15)]],
                 "through_vertex": [[(0, 0), (15, 15)]], "zigzag": [[(0, 0), (4, 9), (8, 0),
                                                                     (12, 9), (15, 0)]],
                 "degenerate": [[(3, 3)], [(5, 5), (5, 5)], [(1, 2), (9, 2)]]}
    regions = {"square": [SQUARE], "bowtie": BOWTIE, "hole": NESTED_HOLE,
               "pentagram": PENTAGRAM, "shared_edge": SHARED_EDGE}
    for lname, lines in line_sets.items():
        for rname, region in regions.items():
            write(out, "fuzz_clip_lines", f"{lname}_{rname}", lines_seed(lines, region))
        write(out, "fuzz_clip_lines", f"{lname}_pentagram_nonzero",
              lines_seed(lines, PENTAGRAM, "nonzero"))
        write(out, "fuzz_clip_lines", f"{lname}_convex",
              lines_seed(lines, [[(3, 1), (12, 2), (14, 13), (1, 11)]], convex=True))
        write(out, "fuzz_clip_lines", f"{lname}_convex_reversed",
              lines_seed(lines, [[(3, 1), (12, 2), (14, 13), (1, 11)]], convex=True, reverse=True))
    for mode in (2, 4, 5):
        write(out, "fuzz_clip_lines", f"zigzag_bowtie_mode{mode}",
              lines_seed(line_sets["zigzag"], BOWTIE, mode=mode))

    for f in sorted((ROOT / "tests/data/io").iterdir()):
        write(out, "fuzz_geojson", f.name, f.read_bytes())
    write(out, "fuzz_geojson", "paths_small.json", '{"paths": [[[0,0],[4,0],[4,4]]]}')
    write(out, "fuzz_geojson", "multipolygon.geojson", json.dumps(
        {"type": "MultiPolygon", "coordinates": [[[[0, 0], [10, 0], [10, 10], [0, 0]],
                                                   [[2, 1], [8, 1], [8, 7], [2, 1]]]]}))
    write(out, "fuzz_geojson", "feature_null_geometry.geojson", json.dumps(
        {"type": "FeatureCollection", "features": [
            {"type": "Feature", "geometry": None, "properties": {"name": "a", "n": 1}},
            {"type": "Feature", "properties": {},
             "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}}]}))

    board = (ROOT / "images/board.json").read_text()
    shorthand = (ROOT / "tests/data/apriltag/shorthand.json").read_text()
    specs = ["hull", "hull:0,2,5", "tags:0,1,3,2", "tags:0,1,2,3@top-left", "tags:3,2,1@centre",
             "tags:0,1,5", "board", "board:inspection", "board:strip",
             "tag:4:0.5,-0.5;2.5,-0.5;2.5,0.5;0.5,0.5", "tag:0:0,0;1,0;1,1|2,2;3,2;3,3",
             "tag:4:-20,-20;20,-20;20,20;-20,20", "bottom_right", "center"]
    for i, spec in enumerate(specs):
        body = board if "board" in spec else shorthand
        write(out, "fuzz_board", f"spec{i:02d}", spec + "\n" + body)
    for f in sorted((ROOT / "tests/data/apriltag").iterdir()):
        write(out, "fuzz_board", f.name, "board\n" + f.read_text())

    configs = {
        "readme.json": {"roi": "hull", "jobs": 2},
        "full.json": {"roi": "tags:0,1,2,3@top-left", "method": "threshold:100",
                      "polarity": "light", "fill-rule": "nonzero", "roi-fill-rule": "positive",
                      "force": True, "recursive": False, "min-area": 20.5, "approx": 0,
                      "masks": None, "board": "images/board.json", "family": "tag25h9"},
        "array.json": {"method": ["otsu", "canny", "adaptive"], "roi": ["hull:1,2", "board:x"]},
        "bad_type.json": {"roi": {"nested": 1}},
        "tag_roi.json": {"roi": "tag:5:0.5,-0.5;2.5,-0.5;2.5,0.5;0.5,0.5", "decimate": 1.5},
    }
    for name, cfg in configs.items():
        write(out, "fuzz_run_config", name, json.dumps(cfg))
    write(out, "fuzz_run_config", "not_object.json", "[1, 2, 3]")
    write(out, "fuzz_run_config", "syntax.json", '{"roi": "hull",')


if __name__ == "__main__":
    main()
