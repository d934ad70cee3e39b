// SPDX-License-Identifier: MIT
// Stage 0: validate input paths and snap them to the call's integer grid (resolveGrid()).
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#endif

#include <roiclip/error.hpp>
#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"

namespace roiclip::detail {
namespace {

// `label` names the operand in the error; the core's operand index (0 or 1, pipeline.hpp) is
// not a label, since polylines are operand 0 too.
[[noreturn]] void rejectCoordinate(double v, const Grid& grid, double originCoordinate, Axis axis,
                                   std::size_t pathIndex, std::size_t vertexIndex, Operand label) {
  const InputLocation where{"", label, pathIndex, vertexIndex, axis};
  if (!std::isfinite(v)) throw InvalidInputError(where, "is not a finite number");
  const std::string range = std::to_string(double(Grid::kMaxUnits) / grid.scale);
  throw InvalidInputError(
      where, "= " + std::to_string(v) + " is outside the supported range " +
                 (originCoordinate == 0.0 ? "+-" + range
                                          : std::to_string(originCoordinate) + " +- " + range));
}

// The grid units of one coordinate (Grid::toUnits(), the one snapping rule).
inline std::int64_t snap(double v, const Grid& grid, double originCoordinate, Axis axis,
                         std::size_t pathIndex, std::size_t vertexIndex, Operand label) {
  const std::optional<std::int64_t> units = grid.toUnits(v, originCoordinate);
  if (!units) rejectCoordinate(v, grid, originCoordinate, axis, pathIndex, vertexIndex, label);
  return *units;
}

// True when a path that moves by d and then by e goes straight on (exact). Snapped points lie
// within +-2^30 units (orientInGrid()): each product of differences is at most 2^62 in magnitude,
// so the cross product is compared and the dot product's sign decided in int64.
inline bool straightOn(IPoint d, IPoint e) {
  return d.x * e.y == d.y * e.x && d.x * e.x > -(d.y * e.y);
}
// a, b and c lie on one line.
inline bool collinear(IPoint a, IPoint b, IPoint c) {
  return (b.x - a.x) * (c.y - b.y) == (b.y - a.y) * (c.x - b.x);
}
// b lies on the way from a to c.
inline bool straightThrough(IPoint a, IPoint b, IPoint c) {
  return straightOn({b.x - a.x, b.y - a.y}, {c.x - b.x, c.y - b.y});
}

// The straight-on and spike vertices (and a repeat of the first point) across the closing
// vertex of a ring whose other ones are merged (snapPoints<true>()). A first vertex that goes
// takes the last one's place, and the last place goes: the ring keeps its cyclic order without
// moving the rest, and the line at the second vertex is the same, so no triple after it changes.
// A spike out to the first vertex and back onto the last one leaves the second vertex a repeat
// of the last: the first two go.
void mergeAcrossClose(std::vector<IPoint>& ring) {
  while (ring.size() >= 3) {
    const std::size_t n = ring.size();
    if (ring[n - 1] == ring[0] || collinear(ring[n - 2], ring[n - 1], ring[0])) {
      ring.pop_back();
    } else if (!collinear(ring[n - 1], ring[0], ring[1])) {
      return;
    } else if (ring[n - 1] == ring[1]) {
      ring.erase(ring.begin(), ring.begin() + 2);
    } else {
      ring[0] = ring[n - 1];
      ring.pop_back();
    }
  }
}

// Drops vertices where a closed ring goes straight on or back along itself: pixel chains become
// a few long edges, and spikes go. Every winding number off the ring is unchanged: what goes is
// a closed path along one line, which winds around no point. A ring left with fewer than three
// vertices encloses nothing (snapRingsInto() drops it); one with three or more has no three
// consecutive vertices on a line, so none of its edges is zero-length or folds back.
void mergeStraightRuns(std::vector<IPoint>& ring) {
  std::size_t kept = 0;
  for (const IPoint q : ring) {
    while (kept >= 2 && collinear(ring[kept - 2], ring[kept - 1], q)) --kept;
    if (kept >= 1 && ring[kept - 1] == q) continue;
    ring[kept++] = q;
  }
  ring.resize(kept);
  mergeAcrossClose(ring);
}

// Grid::toUnits() inline for both coordinates of a point at once (the same operations: round
// v * scale to an integer, subtract origin * scale, test the range). False for a point it cannot
// take (a coordinate out of range or not finite): snap() decides those, giving the same units or
// throwing naming the path, vertex and axis.
//
// The short rounding (u + 1.5 * 2^52) - 1.5 * 2^52 is exact only for |u| < 2^51, and the range
// test alone keeps to that when |origin * scale| <= 2^50: for 2^51 <= |u| < 2^52 the short
// rounding is within 1 of u, beyond that within a relative 2^-51, so its result is at least
// 2^51 - 1 in magnitude and lies more than 2^30 units from the origin (rejected); a result it
// accepts is within 2^50 + 2^30 of 0, so |u| < 2^51 and the rounding was exact. A larger origin
// leaves every point to snap() (the scale NaN fails every range test).
struct FastSnap {
  double s, ox, oy;
  explicit FastSnap(const Grid& grid)
      : s(grid.scale), ox(grid.origin.x * grid.scale), oy(grid.origin.y * grid.scale) {
    if (!(std::fabs(ox) <= 0x1p50 && std::fabs(oy) <= 0x1p50)) s = NAN;
  }
  static constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52, as detail::roundToUnits
  static constexpr double kMax = double(Grid::kMaxUnits);
#if defined(__SSE2__) && defined(__x86_64__)
  // Both coordinates in one SSE2 register: the same operations lane by lane (_mm_cvttsd_si64
  // needs x86-64).
  bool operator()(const Point& v, IPoint& q) const {
    static_assert(sizeof(Point) == 2 * sizeof(double), "x and y in a row");
    const __m128d round = _mm_set1_pd(kRound);
    const __m128d u = _mm_mul_pd(_mm_loadu_pd(&v.x), _mm_set1_pd(s));
    const __m128d d = _mm_sub_pd(_mm_sub_pd(_mm_add_pd(u, round), round), _mm_set_pd(oy, ox));
    const __m128d magnitude = _mm_andnot_pd(_mm_set1_pd(-0.0), d);
    if (_mm_movemask_pd(_mm_cmple_pd(magnitude, _mm_set1_pd(kMax))) != 3) return false;
    q = {_mm_cvttsd_si64(d), _mm_cvttsd_si64(_mm_unpackhi_pd(d, d))};
    return true;
  }
#else
  bool operator()(const Point& v, IPoint& q) const {
    const double ux = v.x * s, uy = v.y * s;
    const double dx = ((ux + kRound) - kRound) - ox, dy = ((uy + kRound) - kRound) - oy;
    if (!(std::fabs(dx) <= kMax && std::fabs(dy) <= kMax)) return false;
    q = {std::int64_t(dx), std::int64_t(dy)};
    return true;
  }
#endif
};

// Snap one path: validated grid points with consecutive repeats removed; with `kMerge` (a
// closed ring), also the vertices where it goes straight on or back along itself.
template <bool kMerge>
void snapPoints(const Path& path, std::size_t count, std::size_t pathIndex, Operand label,
                const Grid& grid, std::vector<IPoint>& out) {
  const FastSnap fast(grid);
  // Written through a pointer into storage for every point (no capacity test per point), then
  // cut to the points kept. A reused array is only grown (resize() zero-fills what it adds).
  if (out.size() < count) out.resize(count);
  IPoint* const kept = out.data();
  std::size_t n = 0;
  IPoint last{std::int64_t{1} << 62, 0};  // kept[n - 1], or no snapped point
  IPoint along{0, 0};  // with kMerge and n >= 2: the direction from kept[n - 2] to kept[n - 1]
  for (std::size_t i = 0; i < count; ++i) {
    IPoint q;
    if (!fast(path[i], q)) {
      q = {snap(path[i].x, grid, grid.origin.x, Axis::X, pathIndex, i, label),
           snap(path[i].y, grid, grid.origin.y, Axis::Y, pathIndex, i, label)};
    }
    if (q == last) continue;
    const IPoint step{q.x - last.x, q.y - last.y};
    last = q;
    // With kMerge, the last point kept goes when the path goes on along the line through it.
    // Straight on: no kept point is such a vertex, and whether one is depends only on the
    // directions of its two edges, so the one before it never goes as well, and `along` keeps
    // its direction. Back along the last edge (a spike, the out-and-back trace of a one-pixel
    // spur): the points before it may go too (mergeStraightRuns()' rule), and q itself when it
    // is the point left last (the spike ends where it began).
    if (kMerge && n >= 2 && along.x * step.y == along.y * step.x) {
      if (along.x * step.x > -(along.y * step.y)) {
        kept[n - 1] = q;
        continue;
      }
      --n;
      while (n >= 2 && collinear(kept[n - 2], kept[n - 1], q)) --n;
      if (kept[n - 1] == q) {
        last = q;
      } else {
        kept[n++] = q;
      }
      along = n >= 2 ? IPoint{kept[n - 1].x - kept[n - 2].x, kept[n - 1].y - kept[n - 2].y}
                     : IPoint{0, 0};
      continue;
    }
    along = step;
    kept[n++] = q;
  }
  out.resize(n);
}

void snapPath(const Path& path, std::size_t pathIndex, Operand label, const Grid& grid,
              std::vector<IPoint>& out) {
  snapPoints<false>(path, path.size(), pathIndex, label, grid, out);
}

// The points of a closed path that count, when the fast snapping decides it: the trailing
// points on the first point's grid point close the ring and are left out (the first one is
// kept). nullopt when a point that decides it needs snap().
std::optional<std::size_t> ringEnd(const Path& path, const FastSnap& fast) {
  IPoint first, q;
  if (path.empty()) return 0;
  if (!fast(path[0], first)) return std::nullopt;
  std::size_t end = path.size();
  for (; end > 1; --end) {
    if (!fast(path[end - 1], q)) return std::nullopt;
    if (q != first) break;
  }
  return end;
}

// One closed path as a ring: snapped, repeats and the closing repeats of the first point
// removed, straight runs merged. In one pass over the points when the fast snapping decides
// where the ring closes; the result is the same as snapping, popping the closing repeats and
// merging (mergeStraightRuns()) one after the other: the merge only reads the deduplicated
// points in order, and leaving out the closing repeats before it is what popping them does.
void snapRing(const Path& path, std::size_t pathIndex, Operand label, const Grid& grid,
              std::vector<IPoint>& ring) {
  if (const std::optional<std::size_t> end = ringEnd(path, FastSnap(grid))) {
    snapPoints<true>(path, *end, pathIndex, label, grid, ring);
    mergeAcrossClose(ring);
    return;
  }
  snapPath(path, pathIndex, label, grid, ring);
  while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
  mergeStraightRuns(ring);
}

// The stages take the grid resolveGrid() chose for the call.
void checkGrid(const Grid& grid) {
  if (grid.isFitted()) throw InternalError("input: the grid was not resolved for the call");
}

}  // namespace

std::vector<std::vector<IPoint>> snapRings(const Paths& paths, int operand, const Grid& grid) {
  Rings rings;
  snapRingsInto(paths, operand, grid, rings);
  return rings;
}

void snapRingsInto(const Paths& paths, int operand, const Grid& grid, Rings& rings) {
  checkGrid(grid);
  if (rings.capacity() < paths.size()) rings.reserve(paths.size());
  std::size_t kept = 0;
  for (std::size_t p = 0; p < paths.size(); ++p) {
    if (kept == rings.size()) rings.emplace_back();
    snapRing(paths[p], p, operand == 0 ? Operand::Subject : Operand::Clip, grid, rings[kept]);
    if (rings[kept].size() >= 3) ++kept;  // a point or a line encloses nothing: its array is reused
  }
  rings.resize(kept);
}

std::size_t countDegenerate(const Paths& paths, const Grid& grid) {
  checkGrid(grid);
  std::size_t count = 0;
  std::vector<IPoint> ring;
  for (std::size_t p = 0; p < paths.size(); ++p) {
    snapPath(paths[p], p, Operand::Subject, grid, ring);
    // Degenerate when every point lies on the line through the first two distinct ones.
    bool flat = true;
    for (std::size_t i = 1; i < ring.size() && flat; ++i) {
      if (ring[i] != ring[0]) {
        for (const IPoint q : ring) flat = flat && orient(ring[0], ring[i], q) == 0;
        break;
      }
    }
    if (flat) ++count;
  }
  return count;
}

void appendInputEdges(const Paths& paths, int operand, const Grid& grid,
                      std::vector<InputEdge>& out) {
  appendRingEdges(snapRings(paths, operand, grid), operand, out);
}

void appendRingEdges(const Rings& rings, int operand, std::vector<InputEdge>& out) {
  for (const std::vector<IPoint>& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      out.push_back(closedEdge(ring[i], ring[(i + 1) % ring.size()], operand));
    }
  }
}

void appendLineEdges(const Paths& lines, const Grid& grid, std::vector<InputEdge>& out,
                     std::vector<std::size_t>& firstEdge) {
  checkGrid(grid);
  firstEdge.clear();
  std::vector<IPoint> line;
  for (std::size_t p = 0; p < lines.size(); ++p) {
    firstEdge.push_back(out.size());
    snapPath(lines[p], p, Operand::Line, grid, line);
    // Interior vertices where the line goes straight on carry no shape; drop them.
    std::size_t kept = 0;
    for (const IPoint q : line) {
      while (kept >= 2 && straightThrough(line[kept - 2], line[kept - 1], q)) --kept;
      line[kept++] = q;
    }
    line.resize(kept);
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
      const IPoint s = line[i];
      const IPoint t = line[i + 1];
      if (s < t) {
        out.push_back({s, t, +1, 0, true});
      } else {
        out.push_back({t, s, -1, 0, true});
      }
    }
  }
  firstEdge.push_back(out.size());
}

}  // namespace roiclip::detail

namespace roiclip {
std::size_t countDegeneratePaths(const Paths& paths, const Grid& grid) {
  return detail::countDegenerate(paths, grid);
}
}  // namespace roiclip
