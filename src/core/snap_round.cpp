// SPDX-License-Identifier: MIT
// Stage 5 (on request): snap rounding of a region onto a grid of a chosen step (roundTo()).
//
// Hobby's and Guibas-Marimont's snap rounding on the exact arrangement of the region's
// boundary: the pixel (a square of side one step around a grid point) containing any vertex of
// the arrangement is hot; every boundary piece is replaced by the chain through the centres of
// the hot pixels it meets, in the order it meets them. Pieces only meet at vertices and every
// crossing is a vertex, so the chains cannot cross each other; they may collapse onto each
// other. The region is then rebuilt from the chains by the core (winding number > 0), which
// merges what collapsed. Should that rebuild still find a vertex off the grid (a crossing of two
// chains: only a missed hot pixel could make one, and none of 270,000 seeded calls on random
// and pixel-boundary inputs did), its pixel becomes hot and the chains are rounded again, as in
// iterated snap rounding (round_to_test.cpp gives it the crossing chains of such a pass).
//
// Coordinates are first snapped to a working grid `unitsPerStep` times finer than the step
// grid, with an origin near the region's centre, so that the result depends on the region's
// extent in steps, not on its absolute position.
#include <algorithm>
#include <cmath>
#include <string>

#include <roiclip/error.hpp>
#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"

namespace roiclip {
namespace detail {
namespace {

// Largest |coordinate| of a working grid (the sweep's range, pipeline.hpp).
constexpr std::int64_t kMaxUnits = Grid::kMaxUnits;
// The working grid need not be finer than this many units per step.
constexpr std::int64_t kMaxUnitsPerStep = std::int64_t{1} << 16;
// Rounding passes before giving up (one always settles; the rest guard against a bug).
constexpr int kMaxPasses = 8;

// floor(a / d + 1/2) for d > 0: the index of the pixel containing a / d (ties up).
std::int64_t roundDiv(i128 a, i128 d) {
  const i128 n = 2 * a + d, den = 2 * d;
  i128 q = n / den;
  if ((n % den != 0) && (n < 0)) --q;
  return std::int64_t(q);
}

IPoint pixelOf(const XPoint& p, std::int64_t unitsPerStep) {
  const i128 d = p.w * unitsPerStep;
  return {roundDiv(p.x, d), roundDiv(p.y, d)};
}

// Exact: does the piece p..q on the integer line a-b meet the pixel around grid point c? A pixel
// is half-open, [c - 1/2, c + 1/2) on each axis (pixelOf() rounds ties up), so every point lies
// in one pixel and a piece that only touches a pixel's top or right side does not meet it. That
// is the closed box shrunk by an infinitesimal e at its top and right, tested by separating axes
// (the two axes: bounding boxes; the line's normal: not all four corners strictly on one side),
// with the sign at a moved corner taken from the direction it moves in where it lies on the line.
bool meetsPixel(IPoint a, IPoint b, const XPoint& p, const XPoint& q, IPoint c,
                std::int64_t unitsPerStep) {
  const i128 m = unitsPerStep;
  // Pixel bounds in half working units.
  const i128 x0 = 2 * i128(c.x) * m - m, x1 = 2 * i128(c.x) * m + m;
  const i128 y0 = 2 * i128(c.y) * m - m, y1 = 2 * i128(c.y) * m + m;
  const auto outside = [](i128 s, i128 sw, i128 t, i128 tw, i128 lo, i128 hi) {
    if (compareCoord(s, sw, lo, 2) < 0 && compareCoord(t, tw, lo, 2) < 0) return true;
    return compareCoord(s, sw, hi, 2) >= 0 && compareCoord(t, tw, hi, 2) >= 0;
  };
  if (outside(p.x, p.w, q.x, q.w, x0, x1) || outside(p.y, p.w, q.y, q.w, y0, y1)) return false;
  const i128 dx = b.x - a.x, dy = b.y - a.y;
  // Twice the cross product of a->b with a->corner; at a moved corner, where that is 0, the
  // sign of its change as the corner moves left (-dF/dx = dy) and/or down (-dF/dy = -dx).
  const auto side = [&](i128 cx, i128 cy, bool left, bool down) {
    const int s = signOf(dx * (cy - 2 * i128(a.y)) - dy * (cx - 2 * i128(a.x)));
    if (s != 0 || (!left && !down)) return s;
    return signOf((left ? dy : 0) - (down ? dx : 0));
  };
  const int corners[4] = {side(x0, y0, false, false), side(x1, y0, true, false),
                          side(x0, y1, false, true), side(x1, y1, true, true)};
  int positive = 0, negative = 0;
  for (const int s : corners) {
    positive += s > 0;
    negative += s < 0;
  }
  return positive != 4 && negative != 4;
}

// The hot pixels in square buckets of `side` pixels, to find the candidates near a piece.
class HotPixels {
 public:
  explicit HotPixels(std::vector<IPoint> pixels) : pixels_(std::move(pixels)) {
    std::sort(pixels_.begin(), pixels_.end());
    pixels_.erase(std::unique(pixels_.begin(), pixels_.end()), pixels_.end());
    if (pixels_.empty()) return;
    lo_ = hi_ = pixels_[0];
    for (const IPoint& c : pixels_) {
      lo_ = {std::min(lo_.x, c.x), std::min(lo_.y, c.y)};
      hi_ = {std::max(hi_.x, c.x), std::max(hi_.y, c.y)};
    }
    const double span = double(std::max(hi_.x - lo_.x, hi_.y - lo_.y)) + 1;
    side_ = std::max(1.0, std::ceil(span / std::sqrt(double(pixels_.size()))));
    columns_ = std::int64_t(double(hi_.x - lo_.x) / side_) + 1;
    rows_ = std::int64_t(double(hi_.y - lo_.y) / side_) + 1;
    first_.assign(std::size_t(columns_ * rows_) + 1, 0);
    for (const IPoint& c : pixels_) ++first_[std::size_t(bucket(c)) + 1];
    for (std::size_t i = 1; i < first_.size(); ++i) first_[i] += first_[i - 1];
    order_.resize(pixels_.size());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for (std::size_t i = 0; i < pixels_.size(); ++i) {
      order_[next[std::size_t(bucket(pixels_[i]))]++] = i;
    }
  }

  // Calls visit(c) for every hot pixel within one pixel (Chebyshev) of the segment between
  // (px, py) and (qx, py) in pixel units (and for some others further away).
  template <class Visit>
  void near(double px, double py, double qx, double qy, Visit visit) const {
    if (pixels_.empty()) return;
    if (qx < px) {
      std::swap(px, qx);
      std::swap(py, qy);
    }
    const double slope = qx - px > 1e-9 ? (qy - py) / (qx - px) : 0.0;
    const bool steep = !(qx - px > 1e-9);
    const std::int64_t c0 = column(px - 1), c1 = column(qx + 1);
    for (std::int64_t col = c0; col <= c1; ++col) {
      double xa = std::max(px, double(lo_.x) + double(col) * side_ - 1);
      double xb = std::min(qx, double(lo_.x) + double(col + 1) * side_ + 1);
      if (xa > xb) xa = xb = std::clamp(xa, px, qx);
      double ya = steep ? py : py + slope * (xa - px);
      double yb = steep ? qy : py + slope * (xb - px);
      if (ya > yb) std::swap(ya, yb);
      const std::int64_t r0 = row(ya - 1.5), r1 = row(yb + 1.5);
      for (std::int64_t r = r0; r <= r1; ++r) {
        const std::size_t b = std::size_t(col * rows_ + r);
        for (std::size_t i = first_[b]; i < first_[b + 1]; ++i) visit(pixels_[order_[i]]);
      }
    }
  }

 private:
  [[nodiscard]] std::int64_t bucket(IPoint c) const {
    return std::int64_t(double(c.x - lo_.x) / side_) * rows_ +
           std::int64_t(double(c.y - lo_.y) / side_);
  }
  [[nodiscard]] std::int64_t column(double x) const {
    return std::clamp(std::int64_t(std::floor((x - double(lo_.x)) / side_)), std::int64_t{0},
                      columns_ - 1);
  }
  [[nodiscard]] std::int64_t row(double y) const {
    return std::clamp(std::int64_t(std::floor((y - double(lo_.y)) / side_)), std::int64_t{0},
                      rows_ - 1);
  }

  std::vector<IPoint> pixels_;
  IPoint lo_, hi_;
  double side_ = 1;
  std::int64_t columns_ = 1, rows_ = 1;
  std::vector<std::size_t> first_, order_;
};

void appendEdge(IPoint s, IPoint t, std::vector<InputEdge>& out) {
  if (s == t) return;
  if (s < t) {
    out.push_back({s, t, +1, 0});
  } else {
    out.push_back({t, s, -1, 0});
  }
}

}  // namespace

std::vector<InputEdge> snapRoundPieces(const Arrangement& arrangement, std::int64_t unitsPerStep) {
  std::vector<IPoint> pixelOfVertex;
  pixelOfVertex.reserve(arrangement.vertices.size());
  bool moves = false;  // some vertex is not a pixel centre
  for (std::size_t i = 0; i < arrangement.vertices.size(); ++i) {
    const XPoint v = arrangement.point(int(i));
    pixelOfVertex.push_back(pixelOf(v, unitsPerStep));
    const IPoint c = pixelOfVertex.back();
    moves = moves || v.w != 1 || v.x != i128(c.x) * unitsPerStep || v.y != i128(c.y) * unitsPerStep;
  }
  // Where nothing moves, nothing is rerouted: the region is already on the grid.
  const HotPixels hot(moves ? pixelOfVertex : std::vector<IPoint>{});
  const double inv = 1.0 / double(unitsPerStep);

  std::vector<InputEdge> out;
  struct Hit {
    i128 along;
    IPoint c;
  };
  std::vector<Hit> hits;
  for (std::size_t e = 0; e < arrangement.pieces.size(); ++e) {
    const EdgePiece& piece = arrangement.pieces[e];
    const bool forward = arrangement.sides[e] == Side::Above;  // left -> right
    const int from = forward ? piece.left : piece.right;
    const int to = forward ? piece.right : piece.left;
    const XPoint p = arrangement.point(from);
    const XPoint q = arrangement.point(to);
    const IPoint first = pixelOfVertex[std::size_t(from)];
    const IPoint last = pixelOfVertex[std::size_t(to)];
    IPoint d = piece.direction();
    if (!forward) d = {-d.x, -d.y};
    hits.clear();
    hot.near(p.fx * inv, p.fy * inv, q.fx * inv, q.fy * inv, [&](IPoint c) {
      if (c == first || c == last) return;
      if (meetsPixel(piece.lineA(), piece.lineB(), p, q, c, unitsPerStep)) {
        hits.push_back({i128(c.x) * d.x + i128(c.y) * d.y, c});
      }
    });
    // Pixels of one size met by one line are met in the order of their centres along it.
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
      return a.along < b.along || (a.along == b.along && a.c < b.c);
    });
    IPoint at = first;
    for (const Hit& h : hits) {
      appendEdge(at, h.c, out);
      at = h.c;
    }
    appendEdge(at, last, out);
  }
  return out;
}

namespace {

bool allOnGrid(const Arrangement& arrangement) {
  // A crossing vertex is off the grid (the sweep keeps one on the grid as a grid point).
  return std::all_of(
      arrangement.vertices.begin(), arrangement.vertices.end(), [&](const ArrangementVertex& v) {
        return v.onGrid() || (!v.isCrossing() && arrangement.offGrid[v.offGridIndex()].w == 1);
      });
}

// The output coordinate of step index n: correctly rounded n * step where that is cheap to
// get (an integer reciprocal such as 1e6 divides exactly; powers of two multiply exactly).
class StepScale {
 public:
  explicit StepScale(double step) : step_(step) {
    const double r = 1.0 / step;
    if (r >= 1 && r == std::floor(r) && r < 9007199254740992.0 && 1.0 / r == step) {
      reciprocal_ = r;
    }
  }
  [[nodiscard]] double toOutput(std::int64_t n) const {
    return reciprocal_ > 0 ? double(n) / reciprocal_ : double(n) * step_;
  }
  [[nodiscard]] double toSteps(double v) const {
    return reciprocal_ > 0 ? v * reciprocal_ : v / step_;
  }

 private:
  double step_;
  double reciprocal_ = 0;
};

}  // namespace

Arrangement rebuildOnStepGrid(std::vector<InputEdge> chains, int& passes) {
  BooleanSpec rebuild;
  rebuild.subjectRule = FillRule::Positive;
  for (;;) {
    Arrangement arrangement = splitEdges(chains, {}, rebuild);
    if (allOnGrid(arrangement)) return arrangement;
    // A vertex off the grid: round the rebuild again, in step units.
    if (passes >= kMaxPasses) throw InternalError("roundTo: snap rounding did not settle");
    chains = snapRoundPieces(arrangement, 1);
    ++passes;
  }
}

PolygonSet roundToCountingPasses(const PolygonSet& region, double step, int& passes) {
  passes = 0;
  if (!(step > 0) || !std::isfinite(step)) {
    throw InvalidInputError("roundTo: step must be positive and finite, got " +
                            std::to_string(step));
  }
  const StepScale scale(step);
  const Paths rings = region.toPaths();

  // The region's box in steps, and the origin (a grid point near its centre).
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (std::size_t i = 0; i < rings[r].size(); ++i) {
      for (int axis = 0; axis < 2; ++axis) {
        const double t = scale.toSteps(rings[r][i][axis]);
        if (!(std::fabs(t) < 0x1p52)) {
          const InputLocation where{"", Operand::Subject, r, i, axis == 0 ? Axis::X : Axis::Y};
          throw InvalidInputError(where, std::isfinite(rings[r][i][axis])
                                             ? "is too large for a step of " + std::to_string(step)
                                             : "is not a finite number");
        }
        lo[axis] = std::min(lo[axis], t);
        hi[axis] = std::max(hi[axis], t);
      }
    }
  }
  if (!(lo[0] <= hi[0])) return {};
  std::int64_t origin[2];
  std::int64_t halfExtent = 1;
  for (int axis = 0; axis < 2; ++axis) {
    const auto a = std::int64_t(std::floor(lo[axis])), b = std::int64_t(std::ceil(hi[axis]));
    origin[axis] = a + (b - a) / 2;
    halfExtent = std::max(halfExtent, std::max(b - origin[axis], origin[axis] - a) + 1);
  }
  if (halfExtent > kMaxUnits / 2) {
    throw InvalidInputError("roundTo: the region spans more than 2^30 steps of " +
                            std::to_string(step));
  }
  std::int64_t unitsPerStep = 1;
  while (unitsPerStep < kMaxUnitsPerStep && 2 * unitsPerStep * halfExtent <= kMaxUnits) {
    unitsPerStep *= 2;
  }

  // The rings on the working grid; the exact arrangement of their boundary under the rule a
  // PolygonSet is read with.
  std::vector<InputEdge> edges;
  std::vector<IPoint> ring;
  for (const Path& path : rings) {
    ring.clear();
    for (const Point& v : path) {
      const IPoint u{std::llround((scale.toSteps(v.x) - double(origin[0])) * double(unitsPerStep)),
                     std::llround((scale.toSteps(v.y) - double(origin[1])) * double(unitsPerStep))};
      if (ring.empty() || ring.back() != u) ring.push_back(u);
    }
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
    if (ring.size() < 3) continue;
    for (std::size_t i = 0; i < ring.size(); ++i)
      appendEdge(ring[i], ring[(i + 1) % ring.size()], edges);
  }
  BooleanSpec read;
  read.subjectRule = kPolygonSetFillRule;
  Arrangement arrangement = splitEdges(edges, {}, read);

  passes = 1;
  arrangement = rebuildOnStepGrid(snapRoundPieces(arrangement, unitsPerStep), passes);
  Grid steps;
  steps.scale = 1.0;  // the arrangement is in steps; vertices come out as exact integers
  PolygonSet result = buildNesting(arrangement, traceContours(arrangement), steps);
  const auto place = [&](Path& path) {
    for (Point& v : path) {
      v = {scale.toOutput(origin[0] + std::int64_t(v.x)),
           scale.toOutput(origin[1] + std::int64_t(v.y))};
    }
  };
  for (Polygon& polygon : result.polygons) {
    place(polygon.outer);
    for (Path& hole : polygon.holes) place(hole);
  }
  return result;
}

}  // namespace detail

PolygonSet roundTo(const PolygonSet& region, double step) {
  int passes = 0;
  return detail::roundToCountingPasses(region, step, passes);
}

}  // namespace roiclip
