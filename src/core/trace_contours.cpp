// Stage 3: link the result pieces into simple closed rings with the paper's stack method.
//
// Every result piece is directed so that the filled side is on its left; at every vertex as
// many result pieces leave as arrive. Walking unused pieces and pushing vertices on a stack,
// a vertex that is already on the stack closes a contour, which is popped. A popped contour
// never repeats a vertex and pieces only meet at vertices, so it is a simple ring; rings that
// touch at a vertex come out as separate rings.
#include <roiclip/error.hpp>

#include "pipeline.hpp"

namespace roiclip::detail {
namespace {

IPoint direction(const EdgePiece& p) { return {p.lineB.x - p.lineA.x, p.lineB.y - p.lineA.y}; }

}  // namespace

Contours traceContours(const Arrangement& arrangement) {
  const auto& sides = arrangement.sides;
  const auto& pieces = arrangement.pieces;
  const int vertexCount = int(arrangement.vertices.size());
  auto from = [&](int e) { return sides[e] == Side::Above ? pieces[e].left : pieces[e].right; };
  auto to = [&](int e) { return sides[e] == Side::Above ? pieces[e].right : pieces[e].left; };

  // Outgoing result pieces per vertex (compressed rows).
  std::vector<int> first(vertexCount + 1, 0);
  for (std::size_t e = 0; e < pieces.size(); ++e) {
    if (sides[e] != Side::None) ++first[from(int(e)) + 1];
  }
  for (int v = 0; v < vertexCount; ++v) first[v + 1] += first[v];
  std::vector<int> outgoing(first[vertexCount]);
  std::vector<int> next(first.begin(), first.end() - 1);
  for (std::size_t e = 0; e < pieces.size(); ++e) {
    if (sides[e] != Side::None) outgoing[next[from(int(e))]++] = int(e);
  }
  std::vector<int> cursor(first.begin(), first.end() - 1);
  std::vector<char> used(pieces.size(), 0);
  auto nextUnused = [&](int v) {
    while (cursor[v] < first[v + 1]) {
      const int e = outgoing[cursor[v]++];
      if (!used[e]) return e;
    }
    return -1;
  };

  Contours result;
  result.ringOfPiece.assign(pieces.size(), -1);
  std::vector<int> onStack(vertexCount, -1);
  std::vector<int> stackV, stackE;
  for (std::size_t start = 0; start < pieces.size(); ++start) {
    if (sides[start] == Side::None || used[start]) continue;
    const int v0 = from(int(start));
    stackV.assign(1, v0);
    stackE.clear();
    onStack[v0] = 0;
    int cur = v0;
    for (;;) {
      const int e = nextUnused(cur);
      if (e < 0) {
        if (stackV.size() == 1) break;
        throw InternalError("traceContours: result boundary is not balanced at a vertex");
      }
      used[e] = 1;
      const int w = to(e);
      stackE.push_back(e);
      if (onStack[w] < 0) {
        onStack[w] = int(stackV.size());
        stackV.push_back(w);
        cur = w;
        continue;
      }
      // Pop the contour stackV[k..], closed by e.
      const std::size_t k = std::size_t(onStack[w]);
      const std::size_t n = stackV.size() - k;
      TracedRing ring;
      int minVertex = stackV[k];
      std::size_t minAt = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const int v = stackV[k + i];
        if (v < minVertex) {
          minVertex = v;
          minAt = i;
        }
        const int in = stackE[k + (i + n - 1) % n];
        const int out = stackE[k + i];
        if (crossSign(direction(pieces[in]), direction(pieces[out])) != 0) {
          ring.vertices.push_back(v);
        }
      }
      const int inMin = stackE[k + (minAt + n - 1) % n];
      const int outMin = stackE[k + minAt];
      ring.referencePiece = std::min(inMin, outMin);
      ring.hole = sides[ring.referencePiece] == Side::Below;
      if (ring.vertices.size() < 3) throw InternalError("traceContours: degenerate ring");
      for (std::size_t i = 0; i < n; ++i)
        result.ringOfPiece[stackE[k + i]] = int(result.rings.size());
      result.rings.push_back(std::move(ring));
      for (std::size_t i = k + 1; i < stackV.size(); ++i) onStack[stackV[i]] = -1;
      stackV.resize(k + 1);
      stackE.resize(k);
      cur = w;
    }
    onStack[v0] = -1;
  }
  return result;
}

}  // namespace roiclip::detail
