// SPDX-License-Identifier: MIT
// Stage 3: link the result pieces into simple closed rings with the paper's stack method.
//
// Every result piece is directed so that the filled side is on its left; at every vertex as
// many result pieces leave as arrive. Walking unused pieces and pushing vertices on a stack,
// a vertex that is already on the stack closes a contour, which is popped. A popped contour
// never repeats a vertex and pieces only meet at vertices, so it is a simple ring; rings that
// touch at a vertex come out as separate rings. Where several rings share a vertex, the walk
// leaves along the piece next clockwise to the one it arrived on, so the rings only touch
// there; a free choice can make two rings cross at that vertex (found by fuzz_simplify).
// Vertices where a ring goes straight on are removed, except where other result pieces meet
// the ring (a touch point): there every ring through the point keeps it as a vertex.
#include <algorithm>

#include <roiclip/error.hpp>

#include "pipeline.hpp"
#include "workspace.hpp"

namespace roiclip::detail {
namespace {

// A piece seen from one of its ends: the direction from that end along the piece.
struct Ray {
  IPoint d;
  int piece = -1;
  bool outgoing = false;
};

// Piece e's direction away from vertex v.
template <class Pieces>
[[gnu::always_inline]] inline IPoint awayFrom(const Pieces& pieces, int v, int e) {
  const IPoint d = pieces[std::size_t(e)].direction();
  return pieces[std::size_t(e)].left == v ? d : IPoint{-d.x, -d.y};
}

// Two rings touching (every crossing of an even-odd result): no sort. The incoming piece that
// lies counter-clockwise between the two outgoing ones pairs with the first of them.
template <class Pieces>
[[gnu::always_inline]] inline void pairTwo(const Pieces& pieces, int v, int o1, int o2, int i1,
                                           int i2, std::vector<int>& pairOut) {
  const IPoint d1 = awayFrom(pieces, v, o1), d2 = awayFrom(pieces, v, o2);
  const bool first = inSectorCcw(d1, d2, awayFrom(pieces, v, i1));
  if (first == inSectorCcw(d1, d2, awayFrom(pieces, v, i2))) {
    throw InternalError("traceContours: pieces around a vertex do not alternate");
  }
  pairOut[std::size_t(i1)] = first ? o1 : o2;
  pairOut[std::size_t(i2)] = first ? o2 : o1;
}

// Pairs the `count` pieces arriving at vertex v with the `count` (> 2: two each take pairTwo())
// leaving it: each incoming piece with the outgoing piece next to it clockwise. Apart from
// traceContours' loop (rare on most inputs, and it keeps that loop small).
template <class Pieces>
[[gnu::noinline]] void pairAtSharedVertex(const Pieces& pieces, int v, const int* outgoing,
                                          const int* incoming, int count, std::vector<Ray>& rays,
                                          std::vector<int>& pairOut) {
  const auto along = [&](int e) { return awayFrom(pieces, v, e); };
  rays.clear();
  for (int i = 0; i < count; ++i) rays.push_back({along(outgoing[i]), outgoing[i], true});
  for (int i = 0; i < count; ++i) rays.push_back({along(incoming[i]), incoming[i], false});
  std::sort(rays.begin(), rays.end(),
            [](const Ray& a, const Ray& b) { return ccwBefore(a.d, b.d); });
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (rays[i].outgoing) continue;
    const Ray& clockwise = rays[(i + rays.size() - 1) % rays.size()];
    if (!clockwise.outgoing) {
      throw InternalError("traceContours: pieces around a vertex do not alternate");
    }
    pairOut[std::size_t(rays[i].piece)] = clockwise.piece;
  }
}

}  // namespace

Contours traceContours(const Arrangement& arrangement) {
  TraceScratch scratch;
  return traceContours(arrangement, scratch);
}

namespace {

// The pieces of an arrangement that fit one chunk, as a plain array: most calls, which then
// index them without the chunk step.
struct FlatPieces {
  const EdgePiece* data;
  std::size_t count;
  [[nodiscard]] std::size_t size() const { return count; }
  const EdgePiece& operator[](std::size_t i) const { return data[i]; }
};

template <class Pieces>
Contours trace(const Arrangement& arrangement, const Pieces& pieces, TraceScratch& scratch) {
  const auto& sides = arrangement.sides;
  const int vertexCount = int(arrangement.vertices.size());
  auto from = [&](int e) { return sides[e] == Side::Above ? pieces[e].left : pieces[e].right; };
  auto to = [&](int e) { return sides[e] == Side::Above ? pieces[e].right : pieces[e].left; };

  // The result pieces leaving each vertex, as a list through outNext from outHead[v] (-1 ends
  // it).
  std::vector<int>& outHead = scratch.outHead;
  std::vector<int>& outNext = scratch.outNext;
  outHead.assign(std::size_t(vertexCount), -1);
  outNext.resize(pieces.size());
  for (std::size_t e = 0; e < pieces.size(); ++e) {
    if (sides[e] == Side::None) continue;
    const int v = from(int(e));
    outNext[e] = outHead[std::size_t(v)];
    outHead[std::size_t(v)] = int(e);
  }
  // Arriving at a vertex along a piece, the walk goes on along the outgoing piece next to it
  // clockwise: both bound the same filled sector, so rings that share a vertex touch there
  // without crossing. Around a vertex incoming and outgoing pieces alternate (each has the
  // filled side on its left), so this pairs them one to one. Where one piece leaves, it is the
  // one (marked taken in outNext); the pieces arriving where several leave are listed from
  // inHead[w] for pairAtSharedVertex(), which those vertices (`shared`) get once every piece is
  // listed. Until then pairOut links that list: a listed piece's own entry is paired last.
  constexpr int kTaken = -2;
  Contours result = std::move(scratch.contours);  // the kept capacity (resolve() gives it back)
  result.rings.clear();
  result.vertices.clear();
  // pairOut becomes the contours' ringOfPiece (the walk below).
  std::vector<int>& pairOut = result.ringOfPiece;
  std::vector<int>& inHead = scratch.inHead;
  std::vector<int>& shared = scratch.shared;
  pairOut.assign(pieces.size(), -1);
  inHead.assign(std::size_t(vertexCount), -1);
  shared.clear();
  const auto unbalanced = [] {
    throw InternalError("traceContours: result boundary is not balanced at a vertex");
  };
  for (std::size_t e = 0; e < pieces.size(); ++e) {
    if (sides[e] == Side::None) continue;
    const int w = to(int(e));
    const int out = outHead[std::size_t(w)];
    if (out < 0) unbalanced();
    int& next = outNext[std::size_t(out)];
    if (next < 0) {
      if (next == kTaken) unbalanced();  // a second piece arrives where one leaves
      next = kTaken;
      pairOut[e] = out;
      continue;
    }
    if (inHead[std::size_t(w)] < 0) shared.push_back(w);
    pairOut[e] = inHead[std::size_t(w)];
    inHead[std::size_t(w)] = int(e);
  }
  // Where one piece leaves, at most one arrives now; where several leave, as many must arrive
  // (below). So no vertex has more pieces arriving than leaving, and the two counts sum to the
  // same (each piece leaves one vertex and arrives at one): the boundary is balanced.
  std::vector<int>& outs = scratch.outs;
  std::vector<int>& ins = scratch.ins;
  std::vector<Ray> rays;
  for (const int v : shared) {
    // Two leaving and two arriving (every crossing of an even-odd result): straight from the
    // lists, without copying them.
    const int o1 = outHead[std::size_t(v)], o2 = outNext[std::size_t(o1)];
    const int i1 = inHead[std::size_t(v)], i2 = i1 >= 0 ? pairOut[std::size_t(i1)] : -1;
    if (o2 >= 0 && outNext[std::size_t(o2)] < 0 && i2 >= 0 && pairOut[std::size_t(i2)] < 0) {
      pairTwo(pieces, v, o1, o2, i1, i2, pairOut);
      continue;
    }
    outs.clear();
    ins.clear();
    for (int e = outHead[std::size_t(v)]; e >= 0; e = outNext[std::size_t(e)]) outs.push_back(e);
    for (int e = inHead[std::size_t(v)]; e >= 0; e = pairOut[std::size_t(e)]) ins.push_back(e);
    if (outs.size() != ins.size()) unbalanced();
    pairAtSharedVertex(pieces, v, outs.data(), ins.data(), int(outs.size()), rays, pairOut);
  }
  const std::size_t sharedVertices = shared.size();
  // What the walk needs of the pairing besides pairOut: where several pieces leave a vertex.
  std::vector<char>& meets = scratch.meets;
  meets.assign(std::size_t(vertexCount), 0);
  for (const int v : shared) meets[std::size_t(v)] = 1;
  scratch.releasePairingIfAbove(kKeptOutputBytes);

  // One array serves the walk as pairOut and then as each piece's ring (a second array of a
  // piece each was 0.48 MB of W3-1k non-zero's peak): the piece to walk after it while it is not
  // walked (>= 0), kOnWalk while the walk holds it, ringCode(r) once it is in ring r; -1 for the
  // pieces that bound nothing.
  constexpr int kOnWalk = -2;
  const auto ringCode = [](int ring) { return -3 - ring; };
  std::vector<int>& link = pairOut;
  result.sharedVertices = sharedVertices;
  // At most one vertex per piece (a ring keeps a piece's start or drops it): the array never
  // grows while rings point into it.
  result.vertices.reserve(pieces.size());
  std::vector<int>& onStack = scratch.onStack;
  onStack.assign(std::size_t(vertexCount), -1);
  // A walk holds at most every piece once, but mostly a few: the stacks grow as they need.
  std::vector<int>& stackV = scratch.stackV;
  std::vector<int>& stackE = scratch.stackE;
  for (std::size_t start = 0; start < pieces.size(); ++start) {
    if (link[start] < 0) continue;  // walked, or bounds nothing
    const int v0 = from(int(start));
    stackV.assign(1, v0);
    stackE.clear();
    onStack[v0] = 0;
    int e = int(start);
    for (;;) {
      const int nextPiece = link[std::size_t(e)];
      link[std::size_t(e)] = kOnWalk;
      const int w = to(e);
      stackE.push_back(e);
      if (onStack[w] < 0) {
        onStack[w] = int(stackV.size());
        stackV.push_back(w);
      } else {
        // Pop the contour stackV[k..], closed by e.
        const std::size_t k = std::size_t(onStack[w]);
        const std::size_t n = stackV.size() - k;
        TracedRing ring;
        const std::size_t firstVertex = result.vertices.size();
        int minVertex = stackV[k];
        std::size_t minAt = 0, minKeptAt = firstVertex;
        const int ringIndex = int(result.rings.size());
        int in = stackE[k + n - 1];
        for (std::size_t i = 0; i < n; ++i) {
          const int v = stackV[k + i];
          const int out = stackE[k + i];
          link[std::size_t(out)] = ringCode(ringIndex);
          // A straight-on vertex is dropped unless other result pieces meet there too: a hole
          // or another part touching this ring's edge must find a vertex of this ring at the
          // touch point, or after rounding to doubles it may cross the edge. The smallest
          // vertex is never straight-on.
          if (meets[std::size_t(v)] != 0 ||
              crossSign(pieces[in].direction(), pieces[out].direction()) != 0) {
            if (v < minVertex) {
              minVertex = v;
              minAt = i;
              minKeptAt = result.vertices.size();
            }
            result.vertices.push_back(v);
          }
          in = out;
        }
        // The ring starts where its reference piece (the lower of the two at its smallest
        // vertex) comes from, whichever piece the walk began with: at the smallest vertex when
        // the piece leaves it (an outer ring), else at the kept vertex before it (a hole). So
        // each ring comes out the same whatever else the arrangement holds (edges of other
        // operands or groups that split its own).
        const int inMin = stackE[k + (minAt + n - 1) % n];
        const int outMin = stackE[k + minAt];
        const auto kept = result.vertices.begin() + std::ptrdiff_t(firstVertex);
        auto startAt = result.vertices.begin() + std::ptrdiff_t(minKeptAt);
        if (inMin < outMin) startAt = startAt == kept ? result.vertices.end() - 1 : startAt - 1;
        std::rotate(kept, startAt, result.vertices.end());
        ring.vertices = {result.vertices.data() + firstVertex,
                         result.vertices.size() - firstVertex};
        ring.referencePiece = std::min(inMin, outMin);
        ring.belowPiece = pieces[std::size_t(ring.referencePiece)].below;
        ring.hole = sides[ring.referencePiece] == Side::Below;
        if (ring.vertices.size() < 3) throw InternalError("traceContours: degenerate ring");
        result.rings.push_back(std::move(ring));
        for (std::size_t i = k + 1; i < stackV.size(); ++i) onStack[stackV[i]] = -1;
        stackV.resize(k + 1);
        stackE.resize(k);
      }
      if (nextPiece < 0 || link[std::size_t(nextPiece)] < 0) {
        if (stackV.size() == 1) break;  // back at the start, every piece of this walk used
        throw InternalError("traceContours: result boundary is not balanced at a vertex");
      }
      e = nextPiece;
    }
    onStack[v0] = -1;
  }
  for (int& r : link) r = r == -1 ? -1 : -3 - r;  // every result piece is in a ring now
  return result;
}

}  // namespace

Contours traceContours(const Arrangement& arrangement, TraceScratch& scratch) {
  if (const EdgePiece* flat = arrangement.pieces.contiguous()) {
    return trace(arrangement, FlatPieces{flat, arrangement.pieces.size()}, scratch);
  }
  return trace(arrangement, arrangement.pieces, scratch);
}

}  // namespace roiclip::detail
