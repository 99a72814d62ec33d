// The frames of a burst of block segments (canopen/step.hpp frames::block_segments) against
// sdo::encode_block_segment, which they were built with before issue 18's services benchmark:
// the segment is now written straight into the frame, and every frame must stay the same.
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/step.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;

namespace {

/// Frame i of a burst as the previous frames::segment made it.
constexpr co::can_frame reference_segment(std::uint16_t id, std::span<const std::uint8_t> data,
                                          std::uint8_t count, bool ends_transfer, std::size_t i) {
  const std::size_t from = std::min<std::size_t>(7U * i, data.size());
  const std::size_t n = std::min<std::size_t>(7U, data.size() - from);
  const bool last = ends_transfer && i + 1U == count;
  co::can_frame f;
  f.id = id;
  f.dlc = 8;
  f.data = sdo::encode_block_segment(static_cast<std::uint8_t>(i + 1U), data.subspan(from, n), last)
               .value_or(sdo::payload{});
  return f;
}

constexpr std::uint8_t bytes10[10] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
// CiA 301 7.2.4.3.12: the last segment carries 0x80 | seqno, unused bytes are zero.
static_assert(co::frames::block_segments(0x585, bytes10, 2, true)[1] ==
              co::can_frame{0x585, false, 8, {0x82, 8, 9, 10, 0, 0, 0, 0}});
static_assert(co::frames::block_segments(0x585, bytes10, 2, false)[0] ==
              co::can_frame{0x585, false, 8, {0x01, 1, 2, 3, 4, 5, 6, 7}});

} // namespace

TEST_CASE("a burst's frames equal encode_block_segment's for every count, length and end") {
  std::vector<std::uint8_t> data(7U * 255U + 8U);
  std::uint32_t x = 2024;
  for (auto &b : data) {
    x = x * 1103515245U + 12345U;
    b = static_cast<std::uint8_t>(x >> 16U);
  }
  std::size_t compared = 0;
  std::size_t mismatches = 0;
  for (unsigned count = 1; count <= 255U; ++count) { // 128..255 are outside 1..127: zeros
    const std::size_t full = 7U * count;
    std::vector<std::size_t> sizes{0, 1, 6, 7, 8, full + 1U, full + 7U};
    for (std::size_t k = 0; k < 7U && k < full; ++k) sizes.push_back(full - k);
    for (const std::size_t size : sizes) {
      const auto window = std::span<const std::uint8_t>(data).first(size);
      for (const bool ends : {false, true}) {
        const auto burst =
            co::frames::block_segments(0x5FF, window, static_cast<std::uint8_t>(count), ends);
        REQUIRE(burst.size() == count);
        std::size_t i = 0;
        for (const co::can_frame f : burst) {
          if (!(f == reference_segment(0x5FF, window, static_cast<std::uint8_t>(count), ends, i))) {
            ++mismatches;
          }
          ++i;
          ++compared;
        }
      }
    }
  }
  CHECK(compared > 100000U);
  CHECK(mismatches == 0U);
}
