# SPDX-License-Identifier: MIT
"""Type stub of the roiclip package (the compiled module roiclip._roiclip, re-exported).

Conventions: pixels, x right, y down, (0, 0) the centre of the top-left pixel (OpenCV's).
Inputs snap to a 1/256 px grid, |coordinate| <= 4,194,304 px.
"""

import os
from typing import Any, ClassVar, Iterator, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

#: One closed path (or open polyline): array-like of shape (N, 2) or cv2's (N, 1, 2).
PathLike = Union[npt.ArrayLike, np.ndarray]
#: Several paths (a list, cv2.findContours' tuple, a (K, N, 2) array), a single path or a
#: PolygonSet (its rings).
Paths = Union["PolygonSet", PathLike, Sequence[PathLike]]
#: A numpy image or mask shape: (H, W) or (H, W, C).
Shape = Sequence[int]

EXACT_BAND: float
OPENCV_BAND: float

class Error(Exception):
    """Root of all roiclip exceptions."""

class InvalidInputError(Error, ValueError):
    """NaN/infinite or out-of-range coordinates, malformed arrays or files, wrong image types;
    the message names the input."""

class InternalError(Error):
    """A bug in roiclip; please report the input."""

class MissingTagsError(Error):
    """An ROI builder did not find the tags it needs."""

    needed: list[int]
    seen: list[int]
    missing: list[int]
    duplicated: list[int]
    minimum_needed: int

class _Enum:
    """pybind11 enum: int(member) is its value, .name its name."""

    def __init__(self, value: int) -> None: ...
    def __int__(self) -> int: ...
    def __index__(self) -> int: ...
    @property
    def name(self) -> str: ...
    @property
    def value(self) -> int: ...

class FillRule(_Enum):
    """Which points closed paths cover by winding number w; functions also take the names
    'evenodd', 'nonzero', 'positive', 'negative'."""

    EVEN_ODD: ClassVar["FillRule"]
    NON_ZERO: ClassVar["FillRule"]
    POSITIVE: ClassVar["FillRule"]
    NEGATIVE: ClassVar["FillRule"]

class ClipOp(_Enum):
    """Boolean operation; functions also take 'intersection', 'union', 'difference', 'xor'."""

    INTERSECTION: ClassVar["ClipOp"]
    UNION: ClassVar["ClipOp"]
    DIFFERENCE: ClassVar["ClipOp"]
    XOR: ClassVar["ClipOp"]

class LinePart(_Enum):
    """Which parts clip_lines() returns; functions also take 'inside', 'outside'."""

    INSIDE: ClassVar["LinePart"]
    OUTSIDE: ClassVar["LinePart"]

FillRuleLike = Union[FillRule, str]
ClipOpLike = Union[ClipOp, str]
LinePartLike = Union[LinePart, str]

class Polygon:
    """One connected region: outer ring (negative shoelace sum) and holes (positive)."""

    @property
    def exterior(self) -> npt.NDArray[np.float64]:
        """Outer ring, (N, 2) float64 (a new array)."""
    @property
    def holes(self) -> list[npt.NDArray[np.float64]]:
        """Holes, each (N, 2) float64."""
    @property
    def area(self) -> float:
        """Outer area minus hole areas, px^2."""
    @property
    def parent(self) -> Optional[int]:
        """Index of the polygon whose hole this one lies in, None at the top level."""
    @property
    def parent_hole(self) -> Optional[int]:
        """Index into the parent's holes, or None."""
    @property
    def __geo_interface__(self) -> dict[str, Any]: ...

class PolygonSet:
    """A region as a forest of polygons with holes; parents come before children."""

    def __init__(self) -> None: ...
    @property
    def area(self) -> float:
        """Total filled area, px^2."""
    @property
    def ring_count(self) -> int: ...
    def __len__(self) -> int: ...
    def __getitem__(self, index: int) -> Polygon: ...
    def __iter__(self) -> Iterator[Polygon]: ...
    def to_paths(self) -> list[npt.NDArray[np.float64]]:
        """Every ring as an (N, 2) float64 array."""
    def to_contours(
        self, dtype: npt.DTypeLike = np.int32
    ) -> Tuple[Tuple[np.ndarray, ...], Optional[npt.NDArray[np.int32]]]:
        """(contours, hierarchy) as cv2.findContours(..., cv2.RETR_CCOMP, ...) returns them:
        contours (N, 1, 2) of `dtype` (int32, float32, float64), hierarchy (1, M, 4) int32
        [next, previous, first_child, parent] or None when empty.

        int32 is the region snap-rounded to whole pixels (round_to(set, 1)): no crossings or
        overlaps, holes inside, each boundary point moved by up to 0.71 px, parts thinner than a
        pixel gone; float32/float64 keep the sub-pixel vertices."""
    @property
    def __geo_interface__(self) -> dict[str, Any]:
        """MultiPolygon mapping, rings closed: shapely.geometry.shape(result) works."""

def simplify(paths: Paths, fill_rule: FillRuleLike = "evenodd") -> PolygonSet:
    """Resolve self-intersecting/overlapping closed paths into simple rings with holes."""

def clip(
    op: ClipOpLike,
    subject: Paths,
    clip: Paths,
    subject_fill_rule: FillRuleLike = "evenodd",
    clip_fill_rule: FillRuleLike = "evenodd",
) -> PolygonSet:
    """Boolean operation, each operand read with its own fill rule."""

def intersect(subject: Paths, clip: Paths, fill_rule: FillRuleLike = "evenodd") -> PolygonSet: ...
def union(subject: Paths, clip: Paths, fill_rule: FillRuleLike = "evenodd") -> PolygonSet: ...
def difference(subject: Paths, clip: Paths, fill_rule: FillRuleLike = "evenodd") -> PolygonSet: ...
def xor(subject: Paths, clip: Paths, fill_rule: FillRuleLike = "evenodd") -> PolygonSet: ...
def clip_lines(
    lines: Paths,
    region: Paths,
    fill_rule: FillRuleLike = "evenodd",
    part: LinePartLike = "inside",
) -> list[npt.NDArray[np.float64]]:
    """Open polylines clipped to a closed region (boundary included), exactly."""

def from_contours(
    contours: Sequence[np.ndarray], hierarchy: Optional[np.ndarray] = None
) -> list[npt.NDArray[np.float64]]:
    """cv2.findContours output as paths; with a hierarchy, outer contours get a negative and
    holes a positive shoelace sum."""

def from_shapely(geometry: Any) -> list[npt.NDArray[np.float64]]:
    """Rings of a Polygon/MultiPolygon (anything with __geo_interface__, or a GeoJSON-like
    mapping) as paths, closing points dropped."""

def round_to(region: PolygonSet, step: float) -> PolygonSet:
    """The region snap-rounded onto multiples of `step` (1, 1/256, 1e-6): valid, on the grid."""
def release_thread_buffers() -> None: ...

class Tag:
    """One decoded AprilTag (pixel-centre convention)."""

    id: int
    family: str
    hamming: int
    decision_margin: float
    @property
    def center(self) -> npt.NDArray[np.float64]:
        """(2,) float64."""
    @property
    def corners(self) -> npt.NDArray[np.float64]:
        """(4, 2) float64: bottom-left, bottom-right, top-right, top-left of the upright tag."""
    @property
    def homography(self) -> npt.NDArray[np.float64]:
        """(3, 3) image-from-tag homography acting on column vectors (u, v, 1)."""
    def tag_to_image(self, u: float, v: float) -> npt.NDArray[np.float64]: ...

class Detector:
    """An AprilTag detector for one family; detect() releases the GIL."""

    def __init__(
        self,
        family: str = "tag36h11",
        quad_decimate: float = 0.0,
        quad_sigma: float = 0.0,
        refine_edges: bool = True,
        threads: int = 1,
        decode_sharpening: float = 0.25,
        max_bits_corrected: int = 2,
    ) -> None: ...
    def detect(self, image: np.ndarray) -> list[Tag]:
        """Tags in a uint8 gray (H, W), BGR (H, W, 3) or BGRA (H, W, 4) image, sorted by id."""
    @property
    def family(self) -> str: ...

def detect_tags(
    image: np.ndarray,
    family: str = "tag36h11",
    quad_decimate: float = 0.0,
    quad_sigma: float = 0.0,
    refine_edges: bool = True,
    threads: int = 1,
    decode_sharpening: float = 0.25,
    max_bits_corrected: int = 2,
) -> list[Tag]:
    """Detect AprilTags with a new Detector."""

def available_families() -> list[str]: ...
def family_size(family: str) -> int: ...
def render_tag(family: str, id: int) -> Tuple[npt.NDArray[np.uint8], int]: ...
def convex_hull_of_tags(
    tags: Sequence[Tag], ids: Optional[Sequence[int]] = None
) -> list[npt.NDArray[np.float64]]:
    """Convex hull of the corners of the tags (all when ids is None); MissingTagsError."""

def polygon_through_tags(
    tags: Sequence[Tag], ids: Sequence[int], anchor: str = "centre"
) -> list[npt.NDArray[np.float64]]: ...
def tag_frame_roi(tags: Sequence[Tag], id: int, paths: Paths) -> list[npt.NDArray[np.float64]]: ...

class Board:
    """A planar board: tags and named ROIs in one board frame."""

    family: str
    units: str
    @staticmethod
    def load(path: str) -> "Board": ...
    @staticmethod
    def from_json(text: str, source: str = "board") -> "Board": ...
    def to_json(self, indent: int = 1) -> str: ...
    @property
    def tag_ids(self) -> list[int]: ...
    @property
    def roi_names(self) -> list[str]: ...
    def roi(self, name: str) -> list[npt.NDArray[np.float64]]: ...

def board_roi(
    board: Board, tags: Sequence[Tag], roi_name: str = "", ransac_threshold: float = 2.0
) -> list[npt.NDArray[np.float64]]: ...

class RoiSpec:
    @property
    def kind(self) -> str:
        """'tags', 'hull', 'board' or 'tag'."""
    ids: list[int]
    roi_name: str
    @property
    def tag_frame_paths(self) -> list[npt.NDArray[np.float64]]: ...

def parse_roi_spec(text: str) -> RoiSpec: ...
def build_roi(
    spec: Union[RoiSpec, str], tags: Sequence[Tag], board: Optional[Board] = None
) -> list[npt.NDArray[np.float64]]: ...
def rasterize(
    region: Paths, shape: Shape, fill_rule: FillRuleLike = "evenodd"
) -> npt.NDArray[np.uint8]:
    """Exact (H, W) uint8 mask: 255 where the pixel centre is inside."""

class MaskComparison:
    only_expected: int
    only_actual: int
    both: int
    iou: float
    boundary_band: float
    band_pixels: int
    off_band_only_expected: int
    off_band_only_actual: int
    off_band_iou: float
    @property
    def agrees_off_band(self) -> bool: ...
    def __bool__(self) -> bool: ...

def compare_masks(
    expected: np.ndarray, actual: np.ndarray, band: float, edges: Paths
) -> MaskComparison: ...
def boundary_band_mask(paths: Paths, band: float, shape: Shape) -> npt.NDArray[np.uint8]: ...

class MaskCheck:
    vector_vs_raster: MaskComparison
    @property
    def vector_vs_opencv(self) -> Optional[MaskComparison]: ...
    @property
    def ok(self) -> bool: ...
    def __bool__(self) -> bool: ...

def check_roi_clip(
    subject: Paths,
    roi: Paths,
    result: PolygonSet,
    shape: Shape,
    subject_fill_rule: FillRuleLike = "evenodd",
    roi_fill_rule: FillRuleLike = "evenodd",
    op: ClipOpLike = "intersection",
    exact_band: float = ...,
    opencv_band: float = ...,
) -> MaskCheck:
    """Check result (clip(op, subject, roi)) against the raster routes off a boundary band."""

def process_image(
    image: Union[np.ndarray, str, os.PathLike[str]],
    *,
    roi: Union[str, Sequence[str]] = ["hull"],
    board: str = "",
    family: str = "tag36h11",
    tag_margin: float = 0.0,
    keep_tags: bool = False,
    method: str = "otsu",
    polarity: str = "dark",
    approx_epsilon: float = 0.0,
    min_area: float = 0.0,
    fill_rule: FillRuleLike = "evenodd",
    roi_fill_rule: FillRuleLike = "evenodd",
    quad_decimate: float = 0.0,
    max_hamming: int = 0,
    min_margin: float = 0.0,
    edges: bool = False,
    max_pixels: int = 100_000_000,
    name: Optional[str] = None,
) -> dict[str, Any]:
    """`roiclip run`'s pipeline on one image (a numpy array or a file path): the NAME.json
    record as a dict (docs/outputs.md; 'clipped' is a GeoJSON FeatureCollection in pixels, y
    down). Per-image problems are in the record's status and reason; bad options raise
    InvalidInputError. Releases the GIL."""
