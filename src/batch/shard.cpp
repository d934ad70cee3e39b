// SPDX-License-Identifier: MIT
// Sharding a run: a stable hash of each input's relative path picks its shard.
#include "detail/shard.hpp"

#include <algorithm>
#include <cstdlib>

#include <roiclip/error.hpp>

namespace roiclip::batch {

namespace {

void checkShard(const Shard& shard, const std::string& text) {
  if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count) {
    throw InvalidInputError("shard '" + text + "': need I/N with N >= 1 and 0 <= I < N");
  }
}

// A whole non-negative decimal number that fits an int, or -1.
int parseCount(const std::string& s) {
  if (s.empty() || s.size() > 9 ||
      !std::all_of(s.begin(), s.end(), [](unsigned char c) { return c >= '0' && c <= '9'; })) {
    return -1;
  }
  return std::atoi(s.c_str());
}

}  // namespace

Shard parseShard(const std::string& text) {
  const std::size_t slash = text.find('/');
  Shard shard{-1, 0};
  if (slash != std::string::npos) {
    shard.index = parseCount(text.substr(0, slash));
    shard.count = parseCount(text.substr(slash + 1));
  }
  checkShard(shard, text);
  return shard;
}

std::uint64_t fnv1a64(const std::string& text) {
  std::uint64_t h = 14695981039346656037ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

namespace detail {

std::vector<Job> selectShard(std::vector<Job> jobs, const Shard& shard) {
  checkShard(shard, std::to_string(shard.index) + "/" + std::to_string(shard.count));
  if (shard.count == 1) return jobs;
  const auto count = static_cast<std::uint64_t>(shard.count);
  const auto index = static_cast<std::uint64_t>(shard.index);
  jobs.erase(std::remove_if(jobs.begin(), jobs.end(),
                            [&](const Job& j) { return fnv1a64(j.rel) % count != index; }),
             jobs.end());
  return jobs;
}

}  // namespace detail

}  // namespace roiclip::batch
