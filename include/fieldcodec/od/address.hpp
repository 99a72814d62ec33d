// fieldcodec — od::address, the (index, sub-index) pair that names one sub-object of an object
// dictionary. Ordered by index, then sub-index (the order of a dictionary's entries).
#pragma once

#include <compare>
#include <cstdint>

namespace fieldcodec::od {

struct address {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;

  friend constexpr bool operator==(const address &, const address &) noexcept = default;
  friend constexpr std::strong_ordering operator<=>(const address &,
                                                    const address &) noexcept = default;
};

} // namespace fieldcodec::od
