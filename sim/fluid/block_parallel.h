// sim/fluid/block_parallel.h — the solver's deterministic parallel loop: [0, n) in fixed blocks, each
// block processed by one task, so per-block partial results (and any sums of them taken in block
// order) do not depend on the thread count.
#pragma once

#include <algorithm>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace fluidsound::sim {

/// Runs body(block, begin, end) for the blocks [b·size, min(n, (b+1)·size)) of [0, n). Callers
/// write only entries of their own block (or the block's own partial-sum slot).
template <typename Body>
void forEachBlock(std::size_t n, std::size_t size, const Body& body) {
  const std::size_t blocks = (n + size - 1) / size;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t b = r.begin(); b < r.end(); ++b) body(b, b * size, std::min(n, (b + 1) * size));
  });
}

}  // namespace fluidsound::sim
