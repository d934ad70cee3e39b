// SPDX-License-Identifier: MIT
// roiclip::batch internal: the share of a run's inputs one process takes (BatchOptions::shard).
#pragma once

#include <vector>

#include <roiclip/batch/run.hpp>

#include "folder.hpp"

namespace roiclip::batch::detail {

/// The jobs of `shard`, in their order: those whose fnv1a64(rel) % count == index.
/// @throws InvalidInputError if the shard is out of range (count < 1, index not in [0, count)).
std::vector<Job> selectShard(std::vector<Job> jobs, const Shard& shard);

}  // namespace roiclip::batch::detail
