# SPDX-License-Identifier: MIT
"""process_image(): the `roiclip run` pipeline on one image, returning the NAME.json record."""

import concurrent.futures
import json
import os
import shutil
import subprocess

import cv2
import numpy as np
import pytest
import shapely.geometry

import roiclip


@pytest.fixture(scope="module")
def scene_path(source_dir):
    return source_dir / "images" / "scene_01.png"


@pytest.fixture(scope="module")
def record(scene_path):
    return roiclip.process_image(scene_path, name="scene_01.png")


def _without_times(record):
    return {k: v for k, v in record.items() if k != "seconds"}


def test_same_record_as_roiclip_run(scene_path, tmp_path):
    cli = os.environ.get("ROICLIP_CLI")
    if not cli:
        pytest.skip("ROICLIP_CLI not set (the roiclip app is not built)")
    images = tmp_path / "images"
    images.mkdir()
    shutil.copy(scene_path, images)
    # The decimation explicitly: `roiclip run --decimate` defaults to 1, the library to 0 (auto).
    subprocess.run([cli, "run", str(images), "-o", str(tmp_path / "out"), "--decimate", "1"],
                   check=True, capture_output=True)
    written = json.loads((tmp_path / "out" / "scene_01.json").read_text())
    record = roiclip.process_image(scene_path, name="scene_01.png", quad_decimate=1)
    assert record["status"] == "ok"
    assert record["clipped_area"] == written["clipped_area"]
    # Everything but the times, down to the last bit of every coordinate.
    assert _without_times(record) == _without_times(written)
    assert record["seconds"].keys() == written["seconds"].keys()


def test_record_layout(record):
    assert record["schema_version"] == 2
    assert record["roiclip_version"] == roiclip.__version__
    assert "y down" in record["coordinates"]
    assert record["mask_check"]["exact"]["iou"] > 0.99
    assert record["seconds"]["read"] > 0 and record["seconds"]["overlay"] == 0
    # 'clipped' is GeoJSON that shapely reads; the features add up to the clipped area.
    clipped = record["clipped"]
    assert clipped["type"] == "FeatureCollection"
    total = 0.0
    for feature in clipped["features"]:
        shape = shapely.geometry.shape(feature["geometry"])
        assert shape.is_valid
        assert shape.area == pytest.approx(feature["properties"]["area"], rel=1e-9)
        assert len(shape.interiors) == feature["properties"]["holes"]
        assert isinstance(feature["properties"]["contour_index"], int)
        assert feature["properties"]["rois"] == ["hull"]
        total += shape.area
    assert total == pytest.approx(record["clipped_area"], rel=1e-9)


def test_array_and_path_agree(record, scene_path):
    image = cv2.imread(str(scene_path), cv2.IMREAD_UNCHANGED)
    from_array = roiclip.process_image(image, name="scene_01.png")
    assert _without_times(from_array) == _without_times(record)
    assert from_array["seconds"]["read"] == 0
    assert roiclip.process_image(image)["image"] == ""
    assert roiclip.process_image(str(scene_path))["image"] == str(scene_path)


def test_options_are_the_run_options(scene_path, source_dir):
    board = str(source_dir / "images" / "board.json")
    both = roiclip.process_image(scene_path, roi=["hull", "board:window"], board=board)
    assert [r["name"] for r in both["rois"]] == ["hull", "window"]
    window = roiclip.process_image(scene_path, roi="board:window", board=board)
    assert window["rois"][0]["clipped_area"] == both["rois"][1]["clipped_area"]
    default = roiclip.process_image(scene_path)
    big = roiclip.process_image(scene_path, min_area=200)
    assert big["contours_in"] < default["contours_in"]
    kept = roiclip.process_image(scene_path, keep_tags=True, fill_rule=roiclip.FillRule.NON_ZERO)
    assert kept["excluded_tags"] == [] and kept["roi"]["area"] > default["roi"]["area"]
    assert "fill=nonzero" in kept["options"]
    threshold = roiclip.process_image(scene_path, method="threshold:100", polarity="dark")
    assert "method=3" in threshold["options"] and "threshold=100" in threshold["options"]
    small = roiclip.process_image(scene_path, max_pixels=1000)
    assert (small["status"], small["failure"]) == ("failed", "too-large")
    with_edges = roiclip.process_image(scene_path, edges=True)
    assert with_edges["edges"]["length"] > 0


@pytest.mark.parametrize("options", [
    {"method": "nope"}, {"polarity": "up"}, {"tag_margin": -1.0}, {"roi": "board"},
    {"roi": "tags:0,1"}, {"fill_rule": "odd"}, {"family": "tag99h99"}, {"roi": [1, 2]},
])
def test_bad_options_raise(scene_path, options):
    with pytest.raises(roiclip.InvalidInputError):
        roiclip.process_image(scene_path, **options)


def test_per_image_problems_are_in_the_record(tmp_path):
    blank = roiclip.process_image(np.full((48, 64), 200, np.uint8))
    assert (blank["status"], blank["failure"]) == ("no-roi", "no-tags")
    assert blank["mask_check"] is None and blank["clipped"]["features"] == []
    missing = roiclip.process_image(tmp_path / "missing.png")
    assert (missing["status"], missing["failure"]) == ("failed", "unreadable")
    assert "missing.png" in missing["reason"]
    with pytest.raises(roiclip.InvalidInputError):
        roiclip.process_image(np.zeros((4, 4), np.complex64))  # not an image at all


def test_threads(scene_gray, record):
    # The GIL is released: threads run the pipeline side by side and agree.
    with concurrent.futures.ThreadPoolExecutor(4) as pool:
        results = list(pool.map(lambda _: roiclip.process_image(scene_gray), range(4)))
    for r in results:
        assert r["clipped_area"] == record["clipped_area"]
