// The frames of a burst of block segments (canopen/sdo_transfer.hpp sdo::block_segments) against
// sdo::encode_block_segment, which they were built with before issue 18's services benchmark:
// the segment is now written straight into the frame, and every frame must stay the same.
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/result.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;

namespace {

/// encode_block_segment before round 5 (which now checks and calls
/// sdo::detail::write_block_segment, the writer a burst's loop calls too), verbatim.
constexpr fieldcodec::result<sdo::payload>
round4_encode_block_segment(std::uint8_t sequence, std::span<const std::uint8_t> bytes,
                            bool last) noexcept {
  if (bytes.size() > 7U) return fieldcodec::errc::too_long;
  if (sequence == 0U || sequence > sdo::max_block_size) return fieldcodec::errc::out_of_range;
  sdo::payload p{};
  p[0] = static_cast<std::uint8_t>((last ? 0x80U : 0U) | sequence);
  if (bytes.size() == 7U) {
    for (std::size_t i = 0; i < 7U; ++i) p[1U + i] = bytes[i];
  } else {
    for (std::size_t i = 0; i < bytes.size(); ++i) p[1U + i] = bytes[i];
  }
  return p;
}

/// Frame i of a burst as the previous frames::segment made it.
constexpr co::can_frame reference_segment(std::uint16_t id, std::span<const std::uint8_t> data,
                                          std::uint8_t count, bool ends_transfer, std::size_t i) {
  const std::size_t from = std::min<std::size_t>(7U * i, data.size());
  const std::size_t n = std::min<std::size_t>(7U, data.size() - from);
  const bool last = ends_transfer && i + 1U == count;
  co::can_frame f;
  f.id = id;
  f.dlc = 8;
  f.data =
      round4_encode_block_segment(static_cast<std::uint8_t>(i + 1U), data.subspan(from, n), last)
          .value_or(sdo::payload{});
  return f;
}

constexpr std::uint8_t bytes10[10] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
// CiA 301 7.2.4.3.12: the last segment carries 0x80 | seqno, unused bytes are zero.
static_assert(co::sdo::block_segments(0x585, bytes10, 2, true)[1] ==
              co::can_frame{0x585, false, 8, {0x82, 8, 9, 10, 0, 0, 0, 0}});
static_assert(co::sdo::block_segments(0x585, bytes10, 2, false)[0] ==
              co::can_frame{0x585, false, 8, {0x01, 1, 2, 3, 4, 5, 6, 7}});

} // namespace

TEST_CASE("a burst's frames (operator[] and copy_to) equal encode_block_segment's for every count, "
          "length and end") {
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
            co::sdo::block_segments(0x5FF, window, static_cast<std::uint8_t>(count), ends);
        REQUIRE(burst.size() == count);
        std::size_t i = 0;
        for (const co::can_frame f : burst) {
          if (!(f == reference_segment(0x5FF, window, static_cast<std::uint8_t>(count), ends, i))) {
            ++mismatches;
          }
          ++i;
          ++compared;
        }
        // copy_to's loop (full segments apart from the rest) makes the same frames
        std::vector<co::can_frame> copied(count);
        if (burst.copy_to(copied) != count) ++mismatches;
        for (std::size_t j = 0; j < count; ++j) {
          if (!(copied[j] ==
                reference_segment(0x5FF, window, static_cast<std::uint8_t>(count), ends, j))) {
            ++mismatches;
          }
          ++compared;
        }
      }
    }
  }
  CHECK(compared > 200000U);
  CHECK(mismatches == 0U);
}

namespace {

/// copy_to(out, first) against operator[]: k = min(out.size(), size() − first) frames written,
/// each equal to frames[first + j]; the rest of `out` untouched.
bool copy_matches(const co::frames &fs, std::size_t first, std::size_t room) {
  const co::can_frame marker{0x7FF, true, 5, {0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE, 0xEE}};
  std::vector<co::can_frame> out(room + 2U, marker);
  const std::size_t k = fs.copy_to(std::span<co::can_frame>(out).first(room), first);
  const std::size_t left = first < fs.size() ? fs.size() - first : 0U;
  if (k != std::min(room, left)) return false;
  for (std::size_t j = 0; j < k; ++j) {
    if (!(out[j] == fs[first + j])) return false;
  }
  for (std::size_t j = k; j < out.size(); ++j) {
    if (!(out[j] == marker)) return false;
  }
  return true;
}

constexpr bool copy_in_constant_expression() {
  std::array<co::can_frame, 3> out{};
  const auto burst = co::sdo::block_segments(0x585, bytes10, 2, true);
  return burst.copy_to(out) == 2U && out[0] == burst[0] && out[1] == burst[1] &&
         out[2] == co::can_frame{};
}
static_assert(copy_in_constant_expression());

} // namespace

TEST_CASE(
    "copy_to writes a burst's frames equal to operator[]'s for every shape, window and room") {
  std::vector<std::uint8_t> data(7U * 127U + 8U);
  std::uint32_t x = 77;
  for (auto &b : data) {
    x = x * 1103515245U + 12345U;
    b = static_cast<std::uint8_t>(x >> 16U);
  }
  std::size_t checked = 0;
  std::size_t failures = 0;
  for (unsigned count = 1; count <= 127U; ++count) {
    // the last segment carries 0..7 bytes (0: the window ends before it, zeros)
    for (std::size_t last_len = 0; last_len <= 7U; ++last_len) {
      const std::size_t size = 7U * (count - 1U) + last_len;
      // a window of the data at an offset (as a machine cuts its next sub-block)
      for (const std::size_t offset : {std::size_t{0}, std::size_t{3}}) {
        const auto window = std::span<const std::uint8_t>(data).subspan(offset, size);
        for (const bool ends : {false, true}) {
          const auto burst =
              co::sdo::block_segments(0x5FF, window, static_cast<std::uint8_t>(count), ends);
          // the whole burst at once, into exactly enough and into more room
          if (!copy_matches(burst, 0, count)) ++failures;
          if (!copy_matches(burst, 0, count + 5U)) ++failures;
          // the next k frames from a position: a queue with room for fewer than the burst
          for (const std::size_t first :
               {std::size_t{1}, std::size_t{count / 2U}, std::size_t{count - 1U}}) {
            for (const std::size_t room : {std::size_t{0}, std::size_t{1}, std::size_t{7}}) {
              if (!copy_matches(burst, first, room)) ++failures;
              ++checked;
            }
          }
          // past the end: nothing written
          if (!copy_matches(burst, count, 4)) ++failures;
          if (!copy_matches(burst, count + 9U, 4)) ++failures;
          checked += 4U;
        }
      }
    }
  }
  CHECK(checked == 127U * 8U * 2U * 2U * 13U);
  CHECK(failures == 0U);
}

TEST_CASE("copy_to in pieces gives the whole burst in order") {
  std::array<std::uint8_t, 7U * 127U> data{};
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 31U + 1U);
  const auto burst = co::sdo::block_segments(0x585, data, 127, true);
  std::vector<co::can_frame> queue;
  std::array<co::can_frame, 5> room{}; // a transmit queue that frees 5 places at a time
  std::size_t i = 0;
  while (i < burst.size()) {
    const std::size_t k = burst.copy_to(room, i);
    REQUIRE(k > 0U);
    queue.insert(queue.end(), room.begin(), room.begin() + static_cast<std::ptrdiff_t>(k));
    i += k;
  }
  REQUIRE(queue.size() == 127U);
  for (std::size_t j = 0; j < queue.size(); ++j) CHECK(queue[j] == burst[j]);
  CHECK(queue.back().data[0] == 0xFF); // 0x80 | 127: the last segment of the transfer
  CHECK(queue.front() == co::can_frame{0x585, false, 8, {0x01, 1, 32, 63, 94, 125, 156, 187}});
}

TEST_CASE("copy_to of no frames, one frame and a list of frames") {
  const co::can_frame marker{0x123, false, 1, {9}};
  std::array<co::can_frame, 3> out{marker, marker, marker};
  // empty: nothing written, 0 returned, whatever the room and position
  CHECK(co::frames{}.copy_to(out) == 0U);
  CHECK(co::frames{}.copy_to(out, 2) == 0U);
  CHECK(out[0] == marker);
  // one frame
  const co::can_frame one{0x605, false, 8, {0x40, 0x00, 0x10, 0, 0, 0, 0, 0}};
  const co::frames single(one);
  CHECK(single.copy_to(std::span<co::can_frame>(out).first(0)) == 0U);
  CHECK(out[0] == marker);
  CHECK(single.copy_to(out, 1) == 0U);
  CHECK(out[0] == marker);
  CHECK(single.copy_to(out) == 1U);
  CHECK(out[0] == one);
  CHECK(out[1] == marker);
  // a list: from a position, into less room than is left
  const std::array<co::can_frame, 4> list{
      co::can_frame{0x181, false, 1, {1}}, co::can_frame{0x182, false, 1, {2}},
      co::can_frame{0x183, false, 1, {3}}, co::can_frame{0x184, false, 1, {4}}};
  const co::frames many{std::span<const co::can_frame>(list)};
  out = {marker, marker, marker};
  CHECK(many.copy_to(std::span<co::can_frame>(out).first(2), 1) == 2U);
  CHECK(out[0] == list[1]);
  CHECK(out[1] == list[2]);
  CHECK(out[2] == marker);
  CHECK(many.copy_to(out, 3) == 1U);
  CHECK(out[0] == list[3]);
  CHECK(many.copy_to(out, 4) == 0U);
}

// The three kinds of `frames` share their storage (issue 18, round 5): a step that sends
// nothing, the answer to most frames, is small to build and to copy.
static_assert(sizeof(void *) != 8U || sizeof(co::frames) == 48U);
static_assert(std::is_trivially_copyable_v<co::frames>);

TEST_CASE("encode_block_segment equals the round-4 encoder for every sequence number, length and "
          "last flag; copy_to overwrites every byte of the queue's frames") {
  std::array<std::uint8_t, 9> bytes{0xA1, 0xB2, 0xC3, 0xD4, 0xE5, 0xF6, 0x07, 0x18, 0x29};
  std::size_t compared = 0;
  for (unsigned seq = 0; seq <= 255U; ++seq) {
    for (std::size_t n = 0; n <= bytes.size(); ++n) {
      for (const bool last : {false, true}) {
        const auto a = sdo::encode_block_segment(
            static_cast<std::uint8_t>(seq), std::span<const std::uint8_t>(bytes).first(n), last);
        const auto b = round4_encode_block_segment(
            static_cast<std::uint8_t>(seq), std::span<const std::uint8_t>(bytes).first(n), last);
        CAPTURE(seq);
        CAPTURE(n);
        REQUIRE(a.has_value() == b.has_value());
        if (a) {
          CHECK(a.value() == b.value());
        } else {
          CHECK(a.error() == b.error());
        }
        ++compared;
      }
    }
  }
  CHECK(compared == 256U * 10U * 2U);
  // a queue whose frames hold old bytes: every field of every frame is written
  std::vector<std::uint8_t> data(7U * 127U);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(i * 7U);
  for (const std::size_t size : {data.size(), data.size() - 3U}) {
    const auto window = std::span<const std::uint8_t>(data).first(size);
    const auto burst = co::sdo::block_segments(0x581, window, 127, true);
    std::vector<co::can_frame> queue(127, co::can_frame{0x7FF, true, 3, {9, 9, 9, 9, 9, 9, 9, 9}});
    CHECK(burst.copy_to(queue) == 127U);
    for (std::size_t j = 0; j < 127U; ++j) {
      CAPTURE(j);
      CHECK(queue[j] == reference_segment(0x581, window, 127, true, j));
    }
  }
}

// frames::burst is generic (step.hpp knows no SDO): any maker, frames made when they are read.
namespace {
/// Frame i of the test burst: on the burst's id, data[0] = i, data[1] = the data's byte i (or 0),
/// data[2] = the flag.
constexpr void test_maker(const co::frames &b, std::size_t first,
                          std::span<co::can_frame> out) noexcept {
  for (std::size_t j = 0; j < out.size(); ++j) {
    const std::size_t i = first + j;
    co::can_frame f;
    f.id = b.burst_id();
    f.dlc = 3;
    f.data[0] = static_cast<std::uint8_t>(i);
    f.data[1] = i < b.burst_data().size() ? b.burst_data()[i] : std::uint8_t{0};
    f.data[2] = b.burst_flag() ? 1U : 0U;
    out[j] = f;
  }
}
constexpr std::array<std::uint8_t, 3> burst_bytes{7, 8, 9};
} // namespace

static_assert(co::frames::burst(0x123, burst_bytes, 5, true, &test_maker).size() == 5U);
static_assert(co::frames::burst(0x123, burst_bytes, 5, true, &test_maker).is_burst());
static_assert(co::frames::burst(0x123, burst_bytes, 5, true, &test_maker)[2].data[1] == 9U);

TEST_CASE("a burst of any maker: operator[], iteration and copy_to give the maker's frames") {
  const auto b = co::frames::burst(0x321, burst_bytes, 4, false, &test_maker);
  CHECK(b.burst_id() == 0x321U);
  CHECK(b.burst_data().size() == 3U);
  CHECK_FALSE(b.burst_flag());
  std::size_t i = 0;
  for (const co::can_frame &f : b) {
    CHECK(f.id == 0x321U);
    CHECK(f.data[0] == i);
    CHECK(f.data[1] == (i < 3U ? burst_bytes[i] : 0U));
    CHECK(f.data[2] == 0U);
    ++i;
  }
  CHECK(i == 4U);
  std::array<co::can_frame, 3> q{};
  CHECK(b.copy_to(q, 2) == 2U); // frames 2 and 3
  CHECK(q[0] == b[2]);
  CHECK(q[1] == b[3]);
  CHECK(b.copy_to(q, 4) == 0U);
}
