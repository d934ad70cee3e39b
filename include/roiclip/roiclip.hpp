// SPDX-License-Identifier: MIT
// roiclip: exact clipping of self-intersecting polygons (extended Weiler-Atherton).
// This header includes only the standard library and GLM. See geometry.hpp for conventions.
// Every function here may be called from several threads at once.
#pragma once

#include <memory>

#include <roiclip/error.hpp>
#include <roiclip/geometry.hpp>

namespace roiclip {

/// Resolve any set of closed paths (self-intersecting, overlapping, touching, wound several
/// times) into simple, non-overlapping outer rings with holes that cover exactly the points the
/// fill rule says the input covers.
///
/// @param paths closed paths; a path with fewer than 3 distinct grid points, or with zero area,
///        contributes nothing (it is not an error).
/// @param rule  fill rule applied to the winding number of all paths together.
/// @param options the snapping grid (default: fitted to the call's operands, see geometry.hpp)
///        and the work limits (default: none). A Grid alone converts to Options.
/// @return outer rings (negative shoelace sum) and holes (positive), nested as a forest; every
///         coordinate is the double nearest its exact value.
/// @throws InvalidInputError on NaN, infinity, a coordinate outside a fixed grid's range, or a
///         bounding box too large for doubles; the message names the path and vertex index.
/// @throws ResourceLimitError when the sweep finds more than options.limits.maxCrossings
///         crossings (before their memory is taken).
PolygonSet simplify(const Paths& paths, FillRule rule, const Options& options = {});

/// Boolean operation between two path sets, each read with its own fill rule:
/// the result covers exactly { p : op(subjectRule(w_subject(p)), clipRule(w_clip(p))) }.
/// Both operands may self-intersect, overlap, share vertices and edges, or contain holes.
/// The grid is fitted to both operands together.
/// @throws InvalidInputError, ResourceLimitError as simplify().
PolygonSet clip(ClipOp op, const Paths& subject, const Paths& clip, FillRule subjectRule,
                FillRule clipRule, const Options& options = {});

/// Shorthands for clip() with one fill rule for both operands.
PolygonSet intersect(const Paths& subject, const Paths& clip, FillRule rule = FillRule::EvenOdd,
                     const Options& options = {});
PolygonSet unite(const Paths& subject, const Paths& clip, FillRule rule = FillRule::EvenOdd,
                 const Options& options = {});
PolygonSet subtract(const Paths& subject, const Paths& clip, FillRule rule = FillRule::EvenOdd,
                    const Options& options = {});
PolygonSet symmetricDifference(const Paths& subject, const Paths& clip,
                               FillRule rule = FillRule::EvenOdd, const Options& options = {});

/// PolygonSet operands: a PolygonSet (e.g. an earlier result) as the subject and/or the clip.
/// A PolygonSet operand is read as its rings (set.toPaths()) under kPolygonSetFillRule
/// (FillRule::NonZero; its rings are simple and nested, so EvenOdd would give the same region,
/// see geometry.hpp), and the result is exactly that of clip() on those paths. The other
/// operand's rule is given as usual. Like any input, the set's vertices are snapped to the grid
/// first: a result's crossing vertices lie off the grid (the doubles nearest the exact points),
/// so feeding a result back moves them by up to half a grid unit per axis. An InvalidInputError
/// names a ring by its index in set.toPaths() ("subject path 2, ...").
PolygonSet clip(ClipOp op, const PolygonSet& subject, const Paths& clip, FillRule clipRule,
                const Options& options = {});
PolygonSet clip(ClipOp op, const Paths& subject, const PolygonSet& clip, FillRule subjectRule,
                const Options& options = {});
PolygonSet clip(ClipOp op, const PolygonSet& subject, const PolygonSet& clip,
                const Options& options = {});

/// Shorthands for the PolygonSet operand clip()s above; `rule` is the Paths operand's rule.
PolygonSet intersect(const PolygonSet& subject, const Paths& clip,
                     FillRule rule = FillRule::EvenOdd, const Options& options = {});
PolygonSet intersect(const Paths& subject, const PolygonSet& clip,
                     FillRule rule = FillRule::EvenOdd, const Options& options = {});
PolygonSet intersect(const PolygonSet& subject, const PolygonSet& clip,
                     const Options& options = {});
PolygonSet unite(const PolygonSet& subject, const Paths& clip, FillRule rule = FillRule::EvenOdd,
                 const Options& options = {});
PolygonSet unite(const Paths& subject, const PolygonSet& clip, FillRule rule = FillRule::EvenOdd,
                 const Options& options = {});
PolygonSet unite(const PolygonSet& subject, const PolygonSet& clip, const Options& options = {});
PolygonSet subtract(const PolygonSet& subject, const Paths& clip, FillRule rule = FillRule::EvenOdd,
                    const Options& options = {});
PolygonSet subtract(const Paths& subject, const PolygonSet& clip, FillRule rule = FillRule::EvenOdd,
                    const Options& options = {});
PolygonSet subtract(const PolygonSet& subject, const PolygonSet& clip, const Options& options = {});
PolygonSet symmetricDifference(const PolygonSet& subject, const Paths& clip,
                               FillRule rule = FillRule::EvenOdd, const Options& options = {});
PolygonSet symmetricDifference(const Paths& subject, const PolygonSet& clip,
                               FillRule rule = FillRule::EvenOdd, const Options& options = {});
PolygonSet symmetricDifference(const PolygonSet& subject, const PolygonSet& clip,
                               const Options& options = {});

/// Snap-round a region onto the grid of multiples of `step` (1: integer pixels for
/// cv::fillPoly / cv::drawContours; 1.0 / 256; 1e-6 for GIS), keeping its topology.
///
/// Every vertex and crossing of the region's rings makes its pixel (the square of side `step`
/// around a grid point) hot; every edge is rerouted through the centres of all hot pixels it
/// passes through (snap rounding, after Hobby and Guibas-Marimont, iterated where a rerouted
/// edge meets a new crossing), and the region is rebuilt from the rerouted rings. So every
/// output vertex is a grid point, no two edges cross, parts do not overlap, holes lie inside
/// their outer ring, and rings touch only at shared vertices: the result is valid for GEOS and
/// OGC consumers, and fillPoly draws it without crossings. Each boundary point moves by at
/// most step * sqrt(2) / 2; parts and holes thinner than a step may collapse and vanish, and
/// parts that come closer than a step may be merged at a vertex or along an edge. A region
/// whose vertices all lie on the grid already is returned unchanged (in its canonical form).
///
/// Output coordinates are n * step, correctly rounded when 1 / step is an integer (1e-6 gives
/// n / 1e6) or step is a power of two.
/// @param region any PolygonSet (read with kPolygonSetFillRule, as every PolygonSet operand).
/// @param step   grid step in pixels, positive and finite.
/// @return a PolygonSet as every other result (orientations, nesting), on the step grid.
/// @throws InvalidInputError when step is not positive and finite, a coordinate is not finite,
///         or the region spans more than 2^30 steps.
PolygonSet roundTo(const PolygonSet& region, double step);

/// Which parts of open polylines clipLines() returns.
enum class LinePart {
  Inside,   ///< the parts in the region, including parts running along its boundary
  Outside,  ///< the parts outside it: together with Inside, every polyline exactly once
};

/// Open polylines (Canny edges, lane lines) clipped to a region: the parts of each polyline
/// inside (or outside) the region { p : regionRule(w_region(p)) }, as open polylines, exactly.
/// The region is closed: a part running along its boundary is inside. Output polylines follow
/// their input's order and direction; they keep the input's vertices (after snapping, without
/// repeated points and without vertices where the line goes straight on) plus the points where
/// the line enters or leaves the region. A polyline whose last point equals its first is read
/// as a loop, so a part through that point is not split there.
/// @param lines  open polylines; one with fewer than 2 distinct grid points gives nothing.
/// @param region closed paths, read with `regionRule`; may self-intersect.
/// @throws InvalidInputError as simplify() (lines are named "line path i", region paths
///         "clip path i").
Paths clipLines(const Paths& lines, const Paths& region, FillRule regionRule,
                LinePart part = LinePart::Inside, const Options& options = {});
const char* toString(LinePart part);

/// A clip region prepared once (snapped, validated, its convexity found) and applied to many
/// subjects, e.g. one ROI and every contour of a video frame. Each call gives what the free
/// function with the same arguments gives (`region` as the clip operand), without reading the
/// region again (exactly the same with a fixed grid; with the default fitted grid the region's
/// grid, power-of-two or decimal as the free function would choose, is fitted to its bounding box
/// grown by twice its side on every side, and a subject reaching beyond that box, or one with a
/// coordinate off a grid that holds the region exactly, is clipped by the free function, so
/// results are the free function's), and works in memory the object owns
/// and keeps between calls (its largest call's working arrays, up to 64 MiB per array), so a loop
/// over small subjects does not allocate working memory. Calls on one object from several threads
/// at once are safe (a call that finds the object's memory in use works in memory of its own). An
/// exception thrown by a call leaves the object usable.
class PreparedRegion {
 public:
  /// @param region closed paths, read with `rule`; may self-intersect.
  /// @param rule   the region's fill rule.
  /// @param options snapping grid (every subject is snapped to it too) and work limits (per
  ///        call).
  /// @throws InvalidInputError as simplify() (region paths are named "clip path i").
  explicit PreparedRegion(const Paths& region, FillRule rule = FillRule::EvenOdd,
                          const Options& options = {});
  /// A PolygonSet region, read as its rings under kPolygonSetFillRule (as the clip() overloads).
  explicit PreparedRegion(const PolygonSet& region, const Options& options = {});
  ~PreparedRegion();
  PreparedRegion(PreparedRegion&& other) noexcept;             ///< takes over other's region
  PreparedRegion& operator=(PreparedRegion&& other) noexcept;  ///< takes over other's region
  PreparedRegion(const PreparedRegion&) = delete;
  PreparedRegion& operator=(const PreparedRegion&) = delete;

  /// clip(op, subject, region, subjectRule, rule, options).
  [[nodiscard]] PolygonSet clip(ClipOp op, const Paths& subject,
                                FillRule subjectRule = FillRule::EvenOdd) const;
  /// clip(op, subject, region, rule, options) for a PolygonSet subject.
  [[nodiscard]] PolygonSet clip(ClipOp op, const PolygonSet& subject) const;
  /// clip(ClipOp::Intersection, subject, region, subjectRule, rule, options).
  [[nodiscard]] PolygonSet intersect(const Paths& subject,
                                     FillRule subjectRule = FillRule::EvenOdd) const;
  /// clipLines(lines, region, rule, part, options).
  [[nodiscard]] Paths clipLines(const Paths& lines, LinePart part = LinePart::Inside) const;

  /// True when the region is a single strictly convex ring (intersections take the linear
  /// pre-clip path).
  [[nodiscard]] bool convex() const;
  /// Free the working memory the object keeps between calls; the next call allocates it again.
  void releaseMemory();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// How many of `paths` contribute nothing to any region: after snapping to `grid` (a resolved
/// grid, resolveGrid(): the one the call fits to all its operands), all of a path's points lie
/// on one line (fewer than 3 distinct points, or a spike out and back along one line). Such paths
/// are ignored by every operation; the CLI reports them as "ignoredRings". A ring that encloses
/// no area without lying on one line (a bent spike A B C B A) is not counted: the core's
/// winding numbers drop it all the same.
/// @throws InvalidInputError as simplify() on NaN, infinity or a coordinate off the grid's range.
std::size_t countDegeneratePaths(const Paths& paths, const Grid& grid);

/// Free the working arrays the calling thread keeps for the free functions above (its largest
/// call's, up to 64 MiB per array; of the general path's pre-clip and sweep only arrays up to
/// 4 KB, of its arrangement and tracing up to 1 MiB; freed anyway when the thread exits). The
/// next call allocates them again.
void releaseThreadBuffers();

/// True when the fill rule counts winding number w as inside. (Inline: the sweep asks this for
/// every piece.)
inline bool isFilled(FillRule rule, long long w) {
  switch (rule) {
    case FillRule::EvenOdd:
      return (w & 1) != 0;
    case FillRule::NonZero:
      return w != 0;
    case FillRule::Positive:
      return w > 0;
    case FillRule::Negative:
      return w < 0;
  }
  return false;
}

/// Parse "evenodd", "nonzero", "positive", "negative" (case-insensitive; also "even-odd",
/// "non-zero"). @throws InvalidInputError on anything else.
FillRule parseFillRule(const char* name);
const char* toString(FillRule rule);
/// Parse "intersection", "union", "difference", "xor". @throws InvalidInputError.
ClipOp parseClipOp(const char* name);
const char* toString(ClipOp op);

}  // namespace roiclip
