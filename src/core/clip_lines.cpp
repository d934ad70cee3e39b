// SPDX-License-Identifier: MIT
// Open polylines (Canny edges, lane lines) clipped to a region.
//
// The polylines' segments go through the same sweep as the region's edges (stage 1), as open
// edges: they are cut at every point where anything crosses or touches them, but contribute
// nothing to any winding number. Each open piece is placed from the region's exact winding
// numbers on its two sides (stage 2), and this stage chains the kept pieces back into
// polylines in the order and direction of the input. A cut appears only where the place
// changes, so the output keeps the input's vertices plus the points where a line enters or
// leaves the region.
#include <algorithm>

#include <roiclip/roiclip.hpp>

#include "output.hpp"
#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip {
namespace detail {
namespace {

class LineAssembler {
 public:
  LineAssembler(const std::vector<OpenPiece>& pieces, std::size_t edgeCount, LinePart part,
                const Grid& grid)
      : pieces_(pieces), part_(part), frame_(grid) {
    // Group the pieces by edge, keeping the sweep order (left to right) within each edge.
    first_.assign(edgeCount + 1, 0);
    for (const OpenPiece& piece : pieces) ++first_[std::size_t(piece.edge) + 1];
    for (std::size_t e = 0; e < edgeCount; ++e) first_[e + 1] += first_[e];
    order_.resize(pieces.size());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      order_[next[std::size_t(pieces[i].edge)]++] = int(i);
    }
  }

  // Appends the kept parts of the polyline made of edges [begin, end) to `out`.
  void assemble(const std::vector<InputEdge>& edges, std::size_t begin, std::size_t end,
                Paths& out) {
    const std::size_t firstOut = out.size();
    bool open = false;  // a part is being built in out.back()
    bool startsAtFirstVertex = false;
    for (std::size_t e = begin; e < end; ++e) {
      const bool forward = edges[e].direction > 0;
      const std::size_t lo = first_[e];
      const std::size_t hi = first_[e + 1];
      for (std::size_t k = 0; k < hi - lo; ++k) {
        const OpenPiece& piece = pieces_[std::size_t(order_[forward ? lo + k : hi - 1 - k])];
        const XPoint& from = forward ? piece.left : piece.right;
        const XPoint& to = forward ? piece.right : piece.left;
        if (!kept(piece.place)) {
          open = false;
          continue;
        }
        if (!open) {
          out.emplace_back();
          push(out.back(), from);
          open = true;
          if (out.size() == firstOut + 1 && e == begin && k == 0) startsAtFirstVertex = true;
        }
        // Cuts inside one input segment between kept pieces are not shape: leave them out.
        const bool last = k + 1 == hi - lo;
        if (last || !kept(pieces_[std::size_t(order_[forward ? lo + k + 1 : hi - 2 - k])].place)) {
          push(out.back(), to);
        }
      }
    }
    // A closed polyline (last point == first) kept across its start is one part, not two.
    const bool closed =
        end > begin && pointAt(edges[begin], true) == pointAt(edges[end - 1], false);
    if (closed && open && startsAtFirstVertex && out.size() - firstOut >= 2) {
      Path& last = out.back();
      Path& head = out[firstOut];
      last.insert(last.end(), head.begin() + 1, head.end());
      head = std::move(last);
      out.pop_back();
    }
  }

 private:
  [[nodiscard]] bool kept(LinePlace place) const {
    return part_ == LinePart::Inside ? place != LinePlace::Outside : place == LinePlace::Outside;
  }
  // The polyline's point at the start (or end) of an input edge, in path order.
  static IPoint pointAt(const InputEdge& e, bool start) {
    return (e.direction > 0) == start ? e.a : e.b;
  }
  void push(Path& path, const XPoint& p) const { path.push_back(frame_.point(p)); }

  const std::vector<OpenPiece>& pieces_;
  LinePart part_;
  OutputFrame frame_;
  std::vector<std::size_t> first_;
  std::vector<int> order_;
};

// The region is one convex ring (a quad through four tags, the common ROI): each segment is cut
// against the ring's half-planes exactly, in O(1), without a sweep. The pieces come out in the
// order the sweep would emit them per edge (left to right).
std::vector<OpenPiece> clipToConvexRing(const std::vector<InputEdge>& edges,
                                        const std::vector<IPoint>& ring, int orientation,
                                        bool filled) {
  std::vector<OpenPiece> pieces;
  pieces.reserve(edges.size() + edges.size() / 4);
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const InputEdge& e = edges[i];
    const XPoint a(e.a), b(e.b);
    XPoint lo = a, hi = b;  // the closed inside interval, while lo < hi
    bool empty = !filled;
    for (std::size_t k = 0; k < ring.size() && !empty; ++k) {
      const IPoint p = ring[k], q = ring[(k + 1) % ring.size()];
      const int oa = orientation * orient(p, q, e.a);
      const int ob = orientation * orient(p, q, e.b);
      if (oa >= 0 && ob >= 0) continue;  // on the inner side (the boundary is inside)
      if (oa <= 0 && ob <= 0) {          // outside, or touching at one end only
        empty = true;
        break;
      }
      XPoint x;
      lineIntersection(p, q, e.a, e.b, x);  // not parallel: the ends are on opposite sides
      if (oa < 0) {
        if (less(lo, x)) lo = x;  // enters here
      } else if (less(x, hi)) {
        hi = x;  // leaves here
      }
    }
    const int edge = int(i);
    if (empty || !less(lo, hi)) {
      pieces.push_back({edge, a, b, LinePlace::Outside});
      continue;
    }
    if (less(a, lo)) pieces.push_back({edge, a, lo, LinePlace::Outside});
    pieces.push_back({edge, lo, hi, LinePlace::Inside});
    if (less(hi, b)) pieces.push_back({edge, hi, b, LinePlace::Outside});
  }
  return pieces;
}

}  // namespace
}  // namespace detail

namespace detail {

Paths clipLinesSnapped(std::vector<InputEdge>& edges, const std::vector<std::size_t>& firstEdge,
                       const SnappedOperand& region, LinePart part, const Grid& grid,
                       const Limits& limits, Workspace& workspace) {
  const std::size_t lineEdges = edges.size();
  std::vector<OpenPiece> pieces;
  if (region.convex != 0) {
    pieces = clipToConvexRing(edges, region.rings[0], region.convex,
                              isFilled(region.rule, region.convex));
  } else {
    appendRingEdges(region.rings, 1, edges);
    // The union with an empty subject is the region itself.
    BooleanSpec spec;
    spec.binary = true;
    spec.op = ClipOp::Union;
    spec.clipRule = region.rule;
    spec.keepBoundary = false;
    spec.maxCrossings = limits.maxCrossings;
    pieces = splitEdges(edges, {}, spec, workspace).openPieces;
  }

  LineAssembler assembler(pieces, lineEdges, part, grid);
  Paths out;
  for (std::size_t i = 0; i + 1 < firstEdge.size(); ++i) {
    assembler.assemble(edges, firstEdge[i], firstEdge[i + 1], out);
  }
  return out;
}

}  // namespace detail

Paths clipLines(const Paths& lines, const Paths& region, FillRule regionRule, LinePart part,
                const Options& options) {
  const Grid grid = resolveGrid(options.grid, lines, region);
  // Lines are read first (their errors come first); region paths are operand 1 so that errors
  // name them "clip".
  std::vector<detail::InputEdge> edges;
  std::vector<std::size_t> firstEdge;
  detail::appendLineEdges(lines, grid, edges, firstEdge);
  const detail::SnappedOperand snapped = detail::snapOperand(region, 1, regionRule, grid);
  const detail::WorkspaceLease workspace;
  return detail::clipLinesSnapped(edges, firstEdge, snapped, part, grid, options.limits,
                                  *workspace);
}

const char* toString(LinePart part) { return part == LinePart::Inside ? "inside" : "outside"; }

}  // namespace roiclip
