#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""report.html of a real `roiclip run` in headless Chromium (CTest roiclip_batch.report_in_chromium).

Usage: report_in_chromium.py ROICLIP_CLI IMAGES_FOLDER

Runs roiclip on three bundled scenes, a file that is not an image and a picture without tags,
then checks in Chromium's DOM that the summary table has one row per image (failures first), the
grid one overlay per image that has one, every overlay file exists, and that sorting works
(report.html#sort=-iou); and that a 1280x2000 screenshot is not blank (not one colour, and the
overlays' dark pixels are there). The screenshot is kept as report_in_chromium.png in the
working folder to look at. Fails, never skips, when chromium is missing: .ci/install-deps
installs it.
"""
import html.parser
import os
import pathlib
import shutil
import subprocess
import sys
import tempfile

import cv2
import numpy as np

SCENES = ("scene_01", "scene_04", "scene_07")
# What the table must list first: failed, then no-roi, then the ok scenes in input order.
EXPECTED_ORDER = ["broken.png", "blank.png"] + [s + ".png" for s in SCENES]


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


class Page(html.parser.HTMLParser):
    """The parts of report.html the checks look at."""

    def __init__(self):
        super().__init__()
        self.rows = []  # (image, attributes) per row of table#summary's body
        self.figures = 0
        self.images = []  # src of every <img>
        self.counts = ""
        self._in_table = self._in_counts = False
        self._row = None
        self._cell = 0

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "table" and a.get("id") == "summary":
            self._in_table = True
        elif tag == "tr" and self._in_table and a.get("id", "").startswith("row-"):
            self._row = [None, a]
            self._cell = 0
        elif tag == "td" and self._row is not None:
            self._cell += 1
        elif tag == "figure":
            self.figures += 1
        elif tag == "img":
            self.images.append(a.get("src", ""))
        elif tag == "p" and a.get("id") == "counts":
            self._in_counts = True

    def handle_endtag(self, tag):
        if tag == "table":
            self._in_table = False
        elif tag == "tr" and self._row is not None:
            self.rows.append(tuple(self._row))
            self._row = None
        elif tag == "p":
            self._in_counts = False

    def handle_data(self, data):
        if self._row is not None and self._cell == 1 and self._row[0] is None:
            self._row[0] = data
        if self._in_counts:
            self.counts += data


def chromium(binary, args, profile):
    command = [binary, "--headless", "--no-sandbox", "--disable-gpu",
               "--disable-background-networking", "--disable-component-update", "--disable-sync",
               "--no-first-run", "--user-data-dir=" + profile] + args
    try:
        r = subprocess.run(command, capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        fail("chromium did not finish in 120 s: " + " ".join(command))
    if r.returncode != 0:
        fail("chromium exited with %d: %s\n%s" % (r.returncode, " ".join(command), r.stderr))
    return r.stdout


def main():
    if len(sys.argv) != 3:
        fail("usage: report_in_chromium.py ROICLIP_CLI IMAGES_FOLDER")
    cli, images = sys.argv[1], sys.argv[2]
    binary = shutil.which("chromium") or shutil.which("chromium-browser")
    if binary is None:
        fail("chromium not found on PATH; this test needs Debian's `chromium` package "
             "(.ci/install-deps installs it; by hand: apt-get install -y chromium)")

    with tempfile.TemporaryDirectory(prefix="roiclip_report_chromium_") as tmp:
        tmp = pathlib.Path(tmp)
        folder = tmp / "in"
        folder.mkdir()
        for scene in SCENES:
            shutil.copy(pathlib.Path(images) / (scene + ".png"), folder)
        (folder / "broken.png").write_text("not a png")
        cv2.imwrite(str(folder / "blank.png"), np.full((300, 400), 200, np.uint8))
        out = tmp / "out"
        run = subprocess.run([cli, "run", str(folder), "-o", str(out), "--jobs", "2"],
                             capture_output=True, text=True, timeout=300)
        if run.returncode != 5:  # 5: some images failed, as they should
            fail("roiclip run exited with %d, expected 5\n%s%s" %
                 (run.returncode, run.stdout, run.stderr))
        url = (out / "report.html").as_uri()

        page = Page()
        page.feed(chromium(binary, ["--dump-dom", url], str(tmp / "profile1")))
        names = [image for image, _ in page.rows]
        if names != EXPECTED_ORDER:
            fail("table rows %s, expected %s (one per image, failures first)" %
                 (names, EXPECTED_ORDER))
        iou = {image: a.get("data-iou") for image, a in page.rows}
        if iou["broken.png"] != "" or iou["blank.png"] != "":
            fail("failed and no-roi rows show an IoU: %s" % iou)
        if page.figures != len(EXPECTED_ORDER):
            fail("%d figures in the grid, expected %d" % (page.figures, len(EXPECTED_ORDER)))
        expected_images = [n.replace(".png", ".overlay.png") for n in EXPECTED_ORDER[1:]]
        if page.images != expected_images:
            fail("grid images %s, expected %s" % (page.images, expected_images))
        for src in page.images:
            if not (out / src).is_file():
                fail("the report shows %s, which is not in %s" % (src, out))
        if "5 of 5 images" not in page.counts or "3 ok" not in page.counts:
            fail("counts at the top read %r" % page.counts)

        # The sort buttons' script, run by the browser: #sort=-iou sorts by IoU, descending,
        # rows without an IoU last.
        page = Page()
        page.feed(chromium(binary, ["--dump-dom", url + "#sort=-iou"], str(tmp / "profile2")))
        values = [a.get("data-iou") for _, a in page.rows]
        numbers = [float(v) for v in values if v != ""]
        if values[len(numbers):] != ["", ""] or numbers != sorted(numbers, reverse=True):
            fail("#sort=-iou gave IoU order %s" % values)

        shot = pathlib.Path.cwd() / "report_in_chromium.png"
        shot.unlink(missing_ok=True)
        chromium(binary, ["--screenshot=" + str(shot), "--window-size=1280,2000", url],
                 str(tmp / "profile3"))
        picture = cv2.imread(str(shot))
        if picture is None:
            fail("no screenshot at %s" % shot)
        if picture.shape[:2] != (2000, 1280):
            fail("screenshot is %s, expected 1280x2000" % (picture.shape[:2],))
        colours = len(np.unique(picture.reshape(-1, 3), axis=0))
        dark = float(np.mean(picture.max(axis=2) < 60))
        # A blank page is one colour; a page whose overlays did not load has text only (well
        # under 1% dark pixels); the overlays' black caption bands and dimmed borders are more.
        if colours < 100 or dark < 0.02:
            fail("screenshot %s looks blank: %d colours, %.1f%% dark pixels" %
                 (shot, colours, 100 * dark))
        print("report.html: %d rows, %d overlays, sorting works; screenshot %s: %d colours, "
              "%.1f%% dark" % (len(names), len(page.images), shot, colours, 100 * dark))


if __name__ == "__main__":
    main()
