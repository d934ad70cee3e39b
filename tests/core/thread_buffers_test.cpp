// SPDX-License-Identifier: MIT
// The pipeline keeps its large working arrays per thread between calls (pipeline.hpp,
// recycle()). Nothing of one call may leak into the next: results must be the same whatever
// ran before on the thread (larger, smaller, failed calls) and with several threads at once.
#include <gtest/gtest.h>

#include <malloc.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <random>
#include <thread>
#include <vector>

#include <roiclip/roiclip.hpp>

#include "pipeline.hpp"
#include "support/oracle.hpp"
#include "support/same_set.hpp"

// Bytes live in operator new, counted for this test binary (works under AddressSanitizer too,
// unlike mallinfo2).
namespace {
std::atomic<std::int64_t> gLiveBytes{0};
std::atomic<std::int64_t> gNewCalls{0};
std::atomic<std::int64_t> gPeakBytes{0};  // the largest gLiveBytes since the test last set it
}  // namespace

void* operator new(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  const std::int64_t live = gLiveBytes += std::int64_t(malloc_usable_size(p));
  std::int64_t peak = gPeakBytes.load();
  while (live > peak && !gPeakBytes.compare_exchange_weak(peak, live)) {
  }
  ++gNewCalls;
  return p;
}
void operator delete(void* p) noexcept {
  if (p == nullptr) return;
  gLiveBytes -= std::int64_t(malloc_usable_size(p));
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept { operator delete(p); }
// The nothrow forms must pair with the delete above too (std::stable_sort's buffer uses them;
// under AddressSanitizer the library's own nothrow new would not go through operator new).
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return operator new(size);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void operator delete(void* p, const std::nothrow_t&) noexcept { operator delete(p); }

namespace roiclip {
namespace {

struct Job {
  ClipOp op;
  Paths subject, clip;
  FillRule rule;
};

PolygonSet run(const Job& job) { return clip(job.op, job.subject, job.clip, job.rule, job.rule); }

// Each job's result on a thread that has run nothing before.
std::vector<PolygonSet> freshResults(const std::vector<Job>& jobs) {
  std::vector<PolygonSet> out(jobs.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    std::thread([&] { out[i] = run(jobs[i]); }).join();
  }
  return out;
}

// Large and small operands, the convex fast path (a quad) and the general path, every op.
std::vector<Job> makeJobs() {
  std::mt19937 rng(20261201);
  const Paths quad = {{{30.25, 20.5}, {170.75, 35.5}, {160.5, 180.25}, {25.5, 150.75}}};
  std::vector<Job> jobs;
  const ClipOp ops[] = {ClipOp::Intersection, ClipOp::Union, ClipOp::Difference, ClipOp::Xor};
  for (int i = 0; i < 16; ++i) {
    const int n = i % 3 == 0 ? 400 : 12 + i;
    Paths subject = {testing::randomPolygon(rng, n, 200)};
    Paths other = i % 2 == 0 ? quad : Paths{testing::randomPolygon(rng, 9 + i, 200)};
    jobs.push_back({ops[i % 4], std::move(subject), std::move(other),
                    i % 4 < 2 ? FillRule::EvenOdd : FillRule::NonZero});
  }
  return jobs;
}

TEST(ThreadBuffers, ResultsDoNotDependOnEarlierCallsOnTheThread) {
  const std::vector<Job> jobs = makeJobs();
  const std::vector<PolygonSet> fresh = freshResults(jobs);
  // Forwards, backwards and forwards again on one thread: every job follows larger and smaller
  // ones, convex-path and general-path ones.
  for (int pass = 0; pass < 3; ++pass) {
    for (std::size_t k = 0; k < jobs.size(); ++k) {
      const std::size_t i = pass == 1 ? jobs.size() - 1 - k : k;
      testing::expectSameSet(run(jobs[i]), fresh[i], "same thread, after other calls");
    }
  }
}

TEST(ThreadBuffers, ACallThatThrowsLeavesTheNextOneCorrect) {
  const std::vector<Job> jobs = makeJobs();
  const std::vector<PolygonSet> fresh = freshResults(jobs);
  const double nan = std::nan("");
  Paths bad = jobs[0].subject;
  bad[0][bad[0].size() / 2].x = nan;  // rejected while reading the input
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    EXPECT_THROW(clip(jobs[i].op, bad, jobs[i].clip, jobs[i].rule, jobs[i].rule),
                 InvalidInputError);
    testing::expectSameSet(run(jobs[i]), fresh[i], "after a call that threw");
  }
}

TEST(ThreadBuffers, ThreadsRunningAtOnceGetTheirOwnBuffers) {
  const std::vector<Job> jobs = makeJobs();
  const std::vector<PolygonSet> fresh = freshResults(jobs);
  constexpr int kThreads = 4;
  std::vector<std::vector<PolygonSet>> got(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int round = 0; round < 5; ++round) {
        for (std::size_t k = 0; k < jobs.size(); ++k) {
          const std::size_t i = (k + std::size_t(t) * 5) % jobs.size();  // different orders
          got[std::size_t(t)].push_back(run(jobs[i]));
        }
      }
    });
  }
  for (std::thread& th : threads) th.join();
  for (int t = 0; t < kThreads; ++t) {
    for (std::size_t n = 0; n < got[std::size_t(t)].size(); ++n) {
      const std::size_t i = (n % jobs.size() + std::size_t(t) * 5) % jobs.size();
      testing::expectSameSet(got[std::size_t(t)][n], fresh[i], "concurrent threads");
    }
  }
}

std::size_t heapInUse() { return std::size_t(gLiveBytes.load()); }

// A small call repeated on a thread takes every array of the pipeline from the thread's
// workspace, the arrangement's, the traced contours' and the snapped operands' rings too. On the
// convex path it allocates only its result (the polygon list and one outer ring: 2); the general
// path frees the subject's rings once it has their edges (they would add to the sweep's peak), so
// it allocates them again (a list and a ring: 2 more).
TEST(ThreadBuffers, ARepeatedSmallCallAllocatesOnlyItsResultAndFreedRings) {
  const Paths subject = {{{10, 10}, {90, 20}, {80, 90}, {40, 60}, {15, 85}}};
  const Paths quad = {{{30.25, 20.5}, {170.75, 35.5}, {160.5, 180.25}, {25.5, 150.75}}};
  const Paths dented = {{{0, 50}, {100, 40}, {60, 100}, {55, 60}}};  // not convex
  for (const auto& [clipPaths, allocations] :
       {std::pair{&quad, 2}, std::pair{&dented, 4}}) {  // the convex path, the general path
    const PolygonSet first = intersect(subject, *clipPaths, FillRule::EvenOdd);
    ASSERT_EQ(first.polygons.size(), 1u);
    ASSERT_TRUE(first.polygons[0].holes.empty());
    const std::int64_t before = gNewCalls.load();
    const PolygonSet again = intersect(subject, *clipPaths, FillRule::EvenOdd);
    EXPECT_EQ(gNewCalls.load() - before, allocations);
    testing::expectSameSet(again, first, "the repeated call");
  }
}

// A 20k-vertex random pixel walk (self-touching) inside a quad takes the general path: the
// pre-clip, the sweep (20k pieces of 160 bytes: 3.2 MB) and tracing. Each stage frees its arrays
// when it is done with them (they would add to the next stage's peak); what the call keeps for
// the next one (the arrangement's and tracing's arrays up to 1 MB each, the nesting's, the
// snapped rings) releaseThreadBuffers() frees.
TEST(ThreadBuffers, TheGeneralPathKeepsNoLargeStageArrayAndReleaseFreesTheRest) {
  std::mt19937 rng(7);
  const Paths chain = {testing::pixelChain(rng, 20000)};
  const Paths quad = {{{-300.5, -400.25}, {350.75, -300.5}, {300.25, 450.5}, {-350.5, 300.75}}};
  releaseThreadBuffers();
  const PolygonSet first = intersect(chain, quad, FillRule::NonZero);
  const std::size_t kept = heapInUse();
  releaseThreadBuffers();
  const std::size_t released = heapInUse();
  EXPECT_GT(kept, released + (std::size_t(512) << 10))
      << "in use after the call " << kept << " bytes, after releaseThreadBuffers " << released;
  EXPECT_LT(kept, released + (std::size_t(2) << 20))
      << "the call kept " << kept - released << " bytes: a stage's large arrays were kept";
  testing::expectSameSet(intersect(chain, quad, FillRule::NonZero), first,
                         "after releaseThreadBuffers");
}

// The general path's peak heap on a long self-touching contour (a 200k-step random pixel walk,
// cut by a quad). Each stage frees its large arrays when it is done (the sweep-free attempts'
// chains and crossings, the pre-clip's path buffers and edges, the sweep's pieces and events),
// and the arrangement grows by half up to 1 MiB: 171 bytes per input vertex at the peak, where the
// arrays held through every stage and the arrangement grown by doubling took 235.
// The arrangement's vertices (chunked_array.hpp): appending never holds two copies or a doubled
// capacity, elements never move once the first chunk is full, and clear() keeps only the first
// chunk. A std::vector of the same 200,000 points peaks at 393,216 of them (12.6 MB).
TEST(ThreadBuffers, TheArrangementsVerticesGrowWithoutADoubledCapacity) {
  using Vertices = detail::ChunkedArray<detail::PackedPoint, 15>;
  constexpr std::size_t kCount = 200000, kChunk = Vertices::kChunk;
  const auto point = [](std::size_t i) {
    return detail::PackedPoint(
        detail::XPoint(detail::i128(i) * 3 - 7, -detail::i128(i), detail::i128(i % 5 + 1)));
  };
  const auto same = [](const detail::PackedPoint& p, const detail::PackedPoint& q) {
    return p.x() == q.x() && p.y() == q.y() && p.w == q.w;
  };
  const std::int64_t before = gLiveBytes.load();
  gPeakBytes = before;
  {
    Vertices v;
    const detail::PackedPoint* first = nullptr;
    for (std::size_t i = 0; i < kCount; ++i) {
      v.push_back(point(i));
      if (i == kChunk - 1) first = &v[0];
      ASSERT_LE(v.capacity(), std::max(v.size() + kChunk, kChunk));
    }
    EXPECT_EQ(first, &v[0]);  // the first chunk did not move after it was full
    ASSERT_EQ(v.size(), kCount);
    std::size_t i = 0;
    for (const detail::PackedPoint& p : v) {
      ASSERT_TRUE(same(p, point(i))) << i;
      ++i;
    }
    ASSERT_EQ(i, kCount);
    EXPECT_TRUE(same(v.back(), point(kCount - 1)));
    const std::int64_t bound = std::int64_t((kCount + kChunk) * sizeof(detail::PackedPoint)) + 4096;
    EXPECT_LE(gPeakBytes.load() - before, bound);

    Vertices moved(std::move(v));
    EXPECT_EQ(moved.size(), kCount);
    EXPECT_TRUE(v.empty());
    moved.clear();
    EXPECT_TRUE(moved.empty());
    EXPECT_EQ(moved.capacity(), kChunk);  // the first chunk stays for the next call
    moved.push_back(point(42));
    EXPECT_TRUE(same(moved[0], point(42)));
    const Vertices copy(moved);
    EXPECT_EQ(copy.size(), 1U);
    EXPECT_TRUE(same(copy[0], point(42)));
  }
  EXPECT_EQ(gLiveBytes.load(), before);  // every chunk freed
}

TEST(ThreadBuffers, TheGeneralPathsPeakOnALongSelfTouchingContour) {
  std::mt19937 rng(11);
  constexpr int kSteps = 200000;
  const Paths chain = {testing::pixelChain(rng, kSteps)};
  const Paths quad = {{{-300.5, -400.25}, {350.75, -300.5}, {300.25, 450.5}, {-350.5, 300.75}}};
  releaseThreadBuffers();
  const std::int64_t before = gLiveBytes.load();
  gPeakBytes = before;
  const PolygonSet result = intersect(chain, quad, FillRule::NonZero);
  const double perVertex = double(gPeakBytes.load() - before) / kSteps;
  std::printf("peak %.1f bytes per vertex\n", perVertex);
  ASSERT_FALSE(result.polygons.empty());
  EXPECT_LT(perVertex, 200.0);
}

// Two random polygons crossing each other everywhere (W3 of bench/suite at half its size: 500
// uniform integer vertices each in a 1000 x 1000 box, about 111k crossings). The arrangement
// keeps a crossing as the two lines through it (8 bytes, not a 32-byte exact point), its pieces
// in chunks of 8192, and tracing pairs and walks the pieces with two arrays a piece, not five:
// the peak of the non-zero intersection fell from 30.0 to 23.9 bytes per crossing, of the
// even-odd one from 106 to 83 (its result has 30 times as many rings).
TEST(ThreadBuffers, TheGeneralPathsPeakOnManyCrossings) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coordinate(0, 1000);
  constexpr int kVertices = 500;
  Paths a(1), b(1);
  for (int i = 0; i < kVertices; ++i) {
    a[0].emplace_back(coordinate(rng), coordinate(rng));
    b[0].emplace_back(coordinate(rng), coordinate(rng));
  }
  // Proper crossings of two edges, by exact orientations (integer coordinates below 2^10).
  const auto orient = [](Point p, Point q, Point r) {
    const double v = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    return (v > 0) - (v < 0);
  };
  std::vector<std::pair<Point, Point>> edges;
  for (const Paths* polygon : {&a, &b}) {
    const Path& ring = (*polygon)[0];
    for (std::size_t i = 0; i < ring.size(); ++i)
      edges.emplace_back(ring[i], ring[(i + 1) % ring.size()]);
  }
  std::int64_t crossings = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    for (std::size_t j = i + 1; j < edges.size(); ++j) {
      const auto [p, q] = edges[i];
      const auto [r, t] = edges[j];
      if (orient(p, q, r) * orient(p, q, t) < 0 && orient(r, t, p) * orient(r, t, q) < 0) {
        ++crossings;
      }
    }
  }
  ASSERT_GT(crossings, 100000);
  for (const auto& [rule, bound] :
       {std::pair{FillRule::NonZero, 26.0}, std::pair{FillRule::EvenOdd, 92.0}}) {
    releaseThreadBuffers();
    const std::int64_t before = gLiveBytes.load();
    gPeakBytes = before;
    const PolygonSet result = intersect(a, b, rule);
    const double perCrossing = double(gPeakBytes.load() - before) / double(crossings);
    std::printf("%lld crossings, peak %.1f bytes per crossing\n", static_cast<long long>(crossings),
                perCrossing);
    ASSERT_FALSE(result.polygons.empty());
    EXPECT_LT(perCrossing, bound);
  }
}

}  // namespace
}  // namespace roiclip
