# SPDX-License-Identifier: MIT
"""Check a COCO file `roiclip run` wrote (BatchOptions::coco) the way a COCO reader sees it.

Only json and numpy (pycocotools is not packaged in Debian), so the COCO API's own reading is
redone here: polygons are flat [x1, y1, x2, y2, ...] lists unioned per annotation, RLE is an
uncompressed {"size": [h, w], "counts": [...]} of column-major runs starting with 0s.

    python3 check_coco.py FILE

Checks: the top-level layout; every annotation's image_id exists, ids are unique; hole-free
annotations' shoelace areas add up to `area` (the exact area roiclip computed, so only float
rounding separates them); RLE pixel counts match `area` within the rasterisation tolerance
(a pixel is in when its centre is, so only pixels the boundary crosses can differ: half a
pixel each for straight edges, about a quarter of boundary_pixels()); bbox contains the segmentation (polygon vertices; RLE pixel
centres); all coordinates lie within the image. Exits non-zero naming every failure.
"""

import json
import sys

import numpy as np


def shoelace(xy):
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def perimeter(xy):
    return float(np.sum(np.hypot(*(np.roll(xy, -1, axis=0) - xy).T)))


def boundary_pixels(mask):
    """Pixels on either side of the mask's edge (with an 8-neighbour of the other kind): every
    pixel whose square the exact boundary crosses is one of them, so they are about twice the
    pixels it crosses."""
    padded = np.pad(mask, 1)
    h, w = mask.shape
    any_in = np.zeros_like(mask)
    any_out = np.zeros_like(mask)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            shifted = padded[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]
            any_in |= shifted
            any_out |= ~shifted
    return int(np.count_nonzero(mask & any_out) + np.count_nonzero(~mask & any_in))


def decode_rle(segmentation):
    h, w = segmentation["size"]
    counts = np.asarray(segmentation["counts"], dtype=np.int64)
    assert counts.sum() == h * w, f"counts add up to {counts.sum()}, not {h} x {w}"
    assert (counts[1:] > 0).all(), "an empty run after the first"
    values = np.zeros(len(counts), dtype=bool)
    values[1::2] = True
    flat = np.repeat(values, counts)
    return flat.reshape((w, h)).T  # column-major (Fortran order), as COCO stores masks


def check(coco):
    errors = []
    for key in ("schema_version", "roiclip_version", "images", "annotations", "categories"):
        if key not in coco:
            errors.append(f"no '{key}' member")
    if errors:
        return errors
    images = {}
    for image in coco["images"]:
        for key in ("id", "file_name", "width", "height"):
            if key not in image:
                errors.append(f"image {image}: no '{key}'")
        images[image["id"]] = image
    if len(images) != len(coco["images"]):
        errors.append("image ids are not unique")
    categories = {c["id"] for c in coco["categories"]}
    seen = set()
    rle = polygons = 0
    for a in coco["annotations"]:
        where = f"annotation {a.get('id')}"
        if a["id"] in seen:
            errors.append(f"{where}: id used twice")
        seen.add(a["id"])
        image = images.get(a["image_id"])
        if image is None:
            errors.append(f"{where}: image_id {a['image_id']} is not in images")
            continue
        if a["category_id"] not in categories:
            errors.append(f"{where}: category {a['category_id']} unknown")
        if a["iscrowd"] not in (0, 1):
            errors.append(f"{where}: iscrowd {a['iscrowd']}")
        w, h = image["width"], image["height"]
        x, y, bw, bh = a["bbox"]
        slack = 1e-9 * max(w, h)
        inside_box = lambda px, py: (  # noqa: E731
            (px >= x - slack).all() and (px <= x + bw + slack).all()
            and (py >= y - slack).all() and (py <= y + bh + slack).all())
        segmentation = a["segmentation"]
        if isinstance(segmentation, dict):
            rle += 1
            if segmentation["size"] != [h, w]:
                errors.append(f"{where}: RLE size {segmentation['size']}, image {h} x {w}")
                continue
            mask = decode_rle(segmentation)
            rows, cols = np.nonzero(mask)
            pixels = len(rows)
            # Half a pixel per pixel the boundary crosses (about half of boundary_pixels):
            # what a straight edge can be off by against the pixel-centre rule.
            tolerance = 0.25 * boundary_pixels(mask) + 2
            if abs(pixels - a["area"]) > tolerance:
                errors.append(f"{where}: {pixels} pixels, area {a['area']:.3f}")
            if pixels and not inside_box(cols + 0.5, rows + 0.5):
                errors.append(f"{where}: a pixel centre lies outside bbox {a['bbox']}")
        else:
            polygons += 1
            total = 0.0
            for flat in segmentation:
                if len(flat) < 6 or len(flat) % 2:
                    errors.append(f"{where}: a polygon of {len(flat)} numbers")
                    continue
                xy = np.asarray(flat, dtype=np.float64).reshape(-1, 2)
                total += shoelace(xy)
                if not inside_box(xy[:, 0], xy[:, 1]):
                    errors.append(f"{where}: a vertex lies outside bbox {a['bbox']}")
                if (xy < 0).any() or (xy[:, 0] > w).any() or (xy[:, 1] > h).any():
                    errors.append(f"{where}: a vertex lies outside the {w} x {h} image")
            if abs(total - a["area"]) > 1e-9 * max(1.0, a["area"]) + 1e-9:
                errors.append(f"{where}: shoelace {total!r}, area {a['area']!r}")
        if not (0 <= x and 0 <= y and x + bw <= w + slack and y + bh <= h + slack):
            errors.append(f"{where}: bbox {a['bbox']} leaves the {w} x {h} image")
    if not coco["annotations"]:
        errors.append("no annotations")
    print(f"{len(images)} images, {len(coco['annotations'])} annotations "
          f"({polygons} polygons, {rle} RLE)")
    return errors


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        coco = json.load(f)
    errors = check(coco)
    for e in errors:
        print("FAIL:", e)
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
