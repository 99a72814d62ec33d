// The pseudo-random generator of the differential tests (xorshift64*, Vigna 2016): fast,
// deterministic for a seed, good enough to spread inputs over a codec's cases. Every test names
// its own seed, so each draws its own stream and a failure repeats exactly.
#pragma once

#include <cstdint>

namespace fieldcodec::test {

class xorshift {
public:
  /// `seed` must not be 0 (the generator would stay at 0).
  constexpr explicit xorshift(std::uint64_t seed) noexcept : s_(seed) {}

  constexpr std::uint64_t next() noexcept {
    s_ ^= s_ >> 12U;
    s_ ^= s_ << 25U;
    s_ ^= s_ >> 27U;
    return s_ * 0x2545F4914F6CDD1DULL;
  }

private:
  std::uint64_t s_;
};

} // namespace fieldcodec::test
