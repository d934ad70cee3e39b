// SPDX-License-Identifier: MIT
// The one workspace: per-thread instance, lease with re-entry guard, recycling.
#include "workspace.hpp"

#include <type_traits>

namespace roiclip::detail {
namespace {

Workspace& threadWorkspace() {
  thread_local Workspace workspace;
  return workspace;
}

}  // namespace

void Workspace::recycleAll() {
  chains.forEach([](auto& v) { recycle(v); });
  weiler.forEach([](auto& v) { recycle(v); });
  if (!generalPathUsed) return;
  generalPathUsed = false;
  pinched.forEach([](auto& v) { recycle(v); });
  overlaps.forEach([](auto& v) { recycle(v); });
  recycle(pieces);
  recycle(exactRights);
  recycle(openLefts);
  recycle(starts);
  recycle(sortedStarts);
  recycle(queue);
  recycle(eventPoints);
  recycle(freeEventPoints);
  if (nodes.size() * sizeof(StatusNode) > kKeptScratchBytes) {
    std::deque<StatusNode>().swap(nodes);
  } else {
    nodes.clear();
  }
  recycle(freeNodes);
  recycle(starting);
  recycle(through);
  recycle(slabOrder);
  recycle(slabEvents);
  recycle(slabBuckets);
  recycle(slabBucketStarts);
  recycle(slabEventScratch);
  recycle(path);
  recycle(next);
  recycle(clipped);
  recycle(edges);
  trace.forEach([](auto& v) { recycle(v); });
  nesting.forEach([](auto& v) { recycle(v); });
  forEachLent([](auto& v) { recycle(v); });
}

template <class F>
void Workspace::forEachLent(F f) {
  f(arrangement.vertices);
  f(arrangement.lines);
  f(arrangement.offGrid);
  f(arrangement.pieces);
  f(arrangement.sides);
  f(arrangement.openPieces);
  f(trace.contours.rings);
  f(trace.contours.ringOfPiece);
  f(trace.contours.vertices);
}

void Workspace::releaseSweepIfAbove(std::size_t bytes) {
  if (nodes.size() * sizeof(StatusNode) > bytes) std::deque<StatusNode>().swap(nodes);
  releaseEachAbove(bytes, freeNodes, pieces, pieceLines, openLefts, exactRights, starts,
                   sortedStarts, queue, eventPoints, freeEventPoints, starting, through, slabOrder,
                   slabEvents, slabBuckets, slabBucketStarts, slabEventScratch);
}

void Workspace::release() {
  std::vector<SweepPiece>().swap(pieces);
  std::vector<int>().swap(pieceLines);
  std::vector<XPoint>().swap(openLefts);
  std::vector<XPoint>().swap(exactRights);
  std::vector<SweepStart>().swap(starts);
  std::vector<SweepStart>().swap(sortedStarts);
  std::vector<SweepEvent>().swap(queue);
  std::vector<ExactCoords>().swap(eventPoints);
  std::vector<int>().swap(freeEventPoints);
  std::deque<StatusNode>().swap(nodes);
  std::vector<StatusNode*>().swap(freeNodes);
  std::vector<int>().swap(starting);
  std::vector<int>().swap(through);
  std::vector<SlabEntry>().swap(slabOrder);
  std::vector<SweepEvent>().swap(slabEvents);
  std::vector<std::uint32_t>().swap(slabBuckets);
  std::vector<std::uint32_t>().swap(slabBucketStarts);
  std::vector<SweepEvent>().swap(slabEventScratch);
  std::vector<ClipVertex>().swap(path);
  std::vector<ClipVertex>().swap(next);
  std::vector<ExactEdge>().swap(clipped);
  std::vector<InputEdge>().swap(edges);
  chains.forEach([](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); });
  weiler.forEach([](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); });
  pinched.forEach([](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); });
  overlaps.forEach([](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); });
  trace.forEach([](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); });
  nesting.forEach([](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); });
  forEachLent([](auto& v) { std::remove_reference_t<decltype(v)>().swap(v); });
  for (Rings& rings : operandRings) Rings().swap(rings);
}

WorkspaceLease::WorkspaceLease() { acquire(threadWorkspace()); }

WorkspaceLease::WorkspaceLease(Workspace& preferred) { acquire(preferred); }

void WorkspaceLease::acquire(Workspace& preferred) {
  if (!preferred.busy.exchange(true, std::memory_order_acquire)) {
    ws_ = &preferred;
    return;
  }
  own_ = std::make_unique<Workspace>();
  own_->busy.store(true, std::memory_order_relaxed);
  ws_ = own_.get();
}

WorkspaceLease::~WorkspaceLease() {
  ws_->recycleAll();
  ws_->busy.store(false, std::memory_order_release);
}

void releaseThreadWorkspace() {
  Workspace& ws = threadWorkspace();
  if (!ws.busy.load(std::memory_order_acquire)) ws.release();
}

}  // namespace roiclip::detail
