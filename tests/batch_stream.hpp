// The traffic of the batch differential tests (tests/canopen/sdo_server_batch_test.cpp,
// sdo_client_batch_test.cpp, tests/node/device_batch_test.cpp): each feeds one machine frame by
// frame and another the same frames in random batches, over a link that loses, corrupts and
// repeats frames, with foreign frames mixed in. The draws are made one after the other (never
// two in one call's arguments, whose order differs between compilers), so a seed gives the
// same stream under g++ and clang++.
#pragma once

#include "xorshift.hpp"

#include <fieldcodec/canopen/can_frame.hpp>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <span>
#include <utility>
#include <vector>

namespace fieldcodec::test {

/// A number in 0..n-1.
inline std::size_t below(xorshift &r, std::uint64_t n) {
  return static_cast<std::size_t>(r.next() % n);
}

/// The frames `fs` over a faulty link into `to`: of every 1000 frames, about fault_per_mille / 3
/// are lost, as many arrive after `corrupt(frame)` changed a byte, and as many arrive twice.
template <class Frames, class Corrupt>
void send_over_faulty_link(const Frames &fs, std::deque<canopen::can_frame> &to,
                           unsigned fault_per_mille, xorshift &r, Corrupt corrupt) {
  for (const canopen::can_frame &f : fs) {
    const std::size_t roll = below(r, 1000);
    if (roll < fault_per_mille / 3U) continue; // lost
    if (roll < 2U * fault_per_mille / 3U) {    // corrupted
      canopen::can_frame g = f;
      corrupt(g);
      to.push_back(g);
      continue;
    }
    to.push_back(f);
    if (roll < fault_per_mille) to.push_back(f); // repeated
  }
}

/// What arrives at once: `chunk` becomes 1..most frames from the front of `q`; in
/// foreign_percent % of the chunks 1..foreign_most frames of `foreign()` are inserted at random
/// places; with `swaps`, in one chunk of ten two neighbours change places.
template <class Foreign>
void take_chunk(std::deque<canopen::can_frame> &q, std::vector<canopen::can_frame> &chunk,
                xorshift &r, std::size_t most, unsigned foreign_percent, std::size_t foreign_most,
                Foreign foreign, bool swaps) {
  chunk.clear();
  for (std::size_t k = 1U + below(r, most); k > 0U && !q.empty(); --k) {
    chunk.push_back(q.front());
    q.pop_front();
  }
  if (below(r, 100) < foreign_percent) {
    for (std::size_t k = 1U + below(r, foreign_most); k > 0U; --k) {
      const std::size_t where = below(r, chunk.size() + 1U);
      chunk.insert(chunk.begin() + static_cast<std::ptrdiff_t>(where), foreign());
    }
  }
  if (swaps && !chunk.empty() && below(r, 10) == 0) {
    const std::size_t k = below(r, chunk.size());
    if (k + 1U < chunk.size()) std::swap(chunk[k], chunk[k + 1U]);
  }
}

/// `chunk` in random batches, one in eight of them empty: `batch(span)` takes a batch and
/// returns how many of its frames were consumed (0 for an empty one, at least 1 otherwise); the
/// next batch starts after them.
template <class Batch>
void in_random_batches(std::span<const canopen::can_frame> chunk, xorshift &r, Batch batch) {
  std::size_t at = 0;
  do {
    const std::size_t len = below(r, 8) == 0 ? 0 : 1U + below(r, chunk.size() - at + 1U);
    const std::size_t take = len < chunk.size() - at ? len : chunk.size() - at;
    at += batch(chunk.subspan(at, take));
  } while (at < chunk.size());
}

} // namespace fieldcodec::test
