// The block segment path of issue 18 (round 5): block_receiver::take_next takes the common
// segment (in sequence, not the last of the transfer or of its sub-block, within the announced
// size and the capacity) with one bound and no segment_result, and the SDO server calls
// on_segment only when take_next declines. The receiver of round 4 is kept here as the
// reference: both are fed the same random streams of segments (in sequence, repeated, out of
// order, sequence number 0, last segments, ends with right and wrong CRCs, acknowledgements)
// under random capacities, announced sizes, CRC and block sizes, and must agree on every result
// and on every observable after every call.
#include <fieldcodec/canopen/sdo_transfer.hpp>

#include <doctest/doctest.h>

#include "xorshift.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace fc = fieldcodec;
namespace sdo = fieldcodec::canopen::sdo;
using sdo::abort_code;

namespace {

/// block_receiver of round 4, verbatim but for the name and the result types.
class round4_receiver {
public:
  constexpr void start(std::size_t capacity, std::optional<std::uint32_t> announced, bool crc,
                       std::uint8_t block_size) noexcept {
    capacity_ = capacity;
    announced_ = announced;
    crc_enabled_ = crc;
    crc_ = 0;
    count_ = 0;
    sequence_ = 0;
    block_size_ = block_size;
    final_ = false;
    previous_ = {};
    have_previous_ = false;
  }
  [[nodiscard]] constexpr std::size_t count() const noexcept { return count_; }
  [[nodiscard]] constexpr bool final_received() const noexcept { return final_; }
  [[nodiscard]] constexpr std::uint8_t block_size() const noexcept { return block_size_; }

  using segment_result = sdo::block_receiver::segment_result;
  [[nodiscard]] constexpr segment_result on_segment(const sdo::payload &raw) noexcept {
    segment_result r;
    const auto sequence = static_cast<std::uint8_t>(raw[0] & 0x7FU);
    const bool last = (raw[0] & 0x80U) != 0U;
    if (sequence == 0U) {
      r.abort = abort_code::invalid_sequence_number;
      return r;
    }
    if (final_) return r; // a repeat after the last segment: nothing new
    const bool in_sequence = sequence == sequence_ + 1U;
    if (!in_sequence) {
      if (sequence_ != 0U && sequence != sequence_) r.acknowledge = true;
      return r;
    }
    sequence_ = sequence;
    previous_ = raw;
    have_previous_ = true;
    if (last) {
      final_ = true;
      for (std::size_t i = 0; i < 7U; ++i) last_[i] = raw[1U + i];
    } else {
      if (announced_ && count_ + 7U > *announced_) {
        r.abort = abort_code::length_too_high;
        return r;
      }
      if (count_ + 7U > capacity_) {
        r.abort = abort_code::out_of_memory;
        return r;
      }
      r.bytes = std::span<const std::uint8_t>(raw).subspan(1, 7);
      r.offset = count_;
      if (crc_enabled_) crc_ = fc::crc::ccitt16(r.bytes, crc_);
      count_ += 7U;
    }
    r.acknowledge = sequence == block_size_ || last;
    return r;
  }
  [[nodiscard]] constexpr bool is_repeat(const sdo::payload &raw) const noexcept {
    return have_previous_ && raw == previous_;
  }
  [[nodiscard]] constexpr sdo::payload acknowledge(std::uint8_t next_block_size) noexcept {
    if (next_block_size < 1U) next_block_size = 1U;
    if (next_block_size > sdo::max_block_size) next_block_size = sdo::max_block_size;
    const std::uint8_t seq = sequence_;
    sequence_ = 0;
    block_size_ = next_block_size;
    return sdo::block_ack(seq, next_block_size).value_or(sdo::payload{});
  }
  using end_result = sdo::block_receiver::end_result;
  [[nodiscard]] constexpr end_result on_end(const sdo::message &m) noexcept {
    end_result r;
    if (!final_) {
      r.abort = abort_code::unknown_command;
      return r;
    }
    const std::size_t n = 7U - m.unused;
    const std::size_t total = count_ + n;
    if (announced_ && total > *announced_) r.abort = abort_code::length_too_high;
    if (announced_ && total < *announced_) r.abort = abort_code::length_too_low;
    if (r.abort == abort_code::none && total > capacity_) r.abort = abort_code::out_of_memory;
    if (r.abort != abort_code::none) return r;
    r.bytes = std::span<const std::uint8_t>(last_).first(n);
    r.offset = count_;
    if (crc_enabled_ && fc::crc::ccitt16(r.bytes, crc_) != m.checksum) {
      r.abort = abort_code::crc_error;
      return r;
    }
    count_ = total;
    return r;
  }

private:
  std::size_t capacity_ = 0;
  std::optional<std::uint32_t> announced_{};
  std::size_t count_ = 0;
  std::uint16_t crc_ = 0;
  bool crc_enabled_ = false;
  bool final_ = false;
  bool have_previous_ = false;
  std::uint8_t sequence_ = 0;
  std::uint8_t block_size_ = 1;
  std::array<std::uint8_t, 7> last_{};
  sdo::payload previous_{};
};

struct result {
  abort_code abort = abort_code::none;
  std::vector<std::uint8_t> bytes;
  std::size_t offset = 0;
  bool acknowledge = false;
  bool operator==(const result &) const = default;
};
result reference_segment(round4_receiver &rx, const sdo::payload &raw) {
  const auto r = rx.on_segment(raw);
  return {r.abort, {r.bytes.begin(), r.bytes.end()}, r.offset, r.acknowledge};
}
/// What the server does with a segment since round 5: take_next, else on_segment.
result new_segment(sdo::block_receiver &rx, const sdo::payload &raw, int &taken) {
  const std::size_t before = rx.count();
  if (rx.take_next(raw)) {
    ++taken;
    return {abort_code::none, {raw.begin() + 1, raw.end()}, before, false};
  }
  const auto r = rx.on_segment(raw);
  return {r.abort, {r.bytes.begin(), r.bytes.end()}, r.offset, r.acknowledge};
}

struct rng : fieldcodec::test::xorshift {
  rng() : xorshift(0x5EED'7A4E'0B10'C505ULL) {}
  unsigned below(unsigned n) { return static_cast<unsigned>(next() % n); }
};

} // namespace

TEST_CASE("sdo: block_receiver::take_next, else on_segment, does what the round-4 on_segment "
          "did") {
  rng g;
  int taken = 0;    // segments take_next took (the test must exercise both paths)
  int declined = 0; // in-sequence segments it left to on_segment
  int crc_ends = 0; // ends whose CRC was right and accepted
  for (int run = 0; run < 4000; ++run) {
    sdo::block_receiver now;
    round4_receiver ref;
    // bounds near what the stream reaches, so that both limits are hit
    const std::size_t capacity = g.below(3) == 0 ? g.below(200) : ~std::size_t{0};
    const std::optional<std::uint32_t> announced =
        g.below(2) == 0 ? std::nullopt : std::optional<std::uint32_t>(g.below(200));
    const bool crc = g.below(2) == 0;
    const auto block_size =
        static_cast<std::uint8_t>(g.below(4) == 0 ? 1U + g.below(127) : 1U + g.below(8));
    now.start(capacity, announced, crc, block_size);
    ref.start(capacity, announced, crc, block_size);
    std::uint8_t expected = 1;      // the sequence number a well-behaved sender sends next
    sdo::payload last_raw{};        // the segment sent last (is_repeat is asked about it)
    std::vector<std::uint8_t> data; // what the reference took, for a right CRC in the end
    std::array<std::uint8_t, 7> final_bytes{};
    for (int k = 0; k < 60; ++k) {
      INFO("run ", run, " step ", k);
      const unsigned what = g.below(20);
      if (what == 0) { // an acknowledgement with a new block size (0 and over 127 clamped)
        const auto n = static_cast<std::uint8_t>(g.below(4) == 0 ? g.below(256) : g.below(9));
        CHECK(now.acknowledge(n) == ref.acknowledge(n));
        expected = 1;
      } else if (what == 1) { // the end message, its CRC right half of the time
        sdo::message end;
        end.type = sdo::message_type::block_end;
        end.unused = static_cast<std::uint8_t>(g.below(8));
        end.checksum = static_cast<std::uint16_t>(g.next());
        const bool right = g.below(2) == 0;
        if (right) {
          std::vector<std::uint8_t> all = data;
          all.insert(all.end(), final_bytes.begin(), final_bytes.begin() + (7 - end.unused));
          end.checksum = fc::crc::ccitt16(all);
        }
        const auto a = now.on_end(end);
        const auto b = ref.on_end(end);
        CHECK(a.abort == b.abort);
        CHECK(a.offset == b.offset);
        CHECK(std::vector<std::uint8_t>(a.bytes.begin(), a.bytes.end()) ==
              std::vector<std::uint8_t>(b.bytes.begin(), b.bytes.end()));
        if (right && crc && ref.final_received() && b.abort == abort_code::none) ++crc_ends;
      } else { // a segment: mostly the next one, else a repeat, a gap, 0 or any number
        sdo::payload raw{};
        const std::uint64_t r = g.next();
        for (std::size_t i = 1; i < 8U; ++i) raw[i] = static_cast<std::uint8_t>(r >> (8U * i));
        unsigned seq = expected;
        const unsigned kind = g.below(14);
        if (kind == 0) seq = expected > 1U ? expected - 1U : 1U;
        if (kind == 1) seq = expected + 1U + g.below(3);
        if (kind == 2) seq = 0;
        if (kind == 3) seq = g.below(128);
        const bool last = g.below(25) == 0;
        raw[0] = static_cast<std::uint8_t>((last ? 0x80U : 0U) | (seq & 0x7FU));
        last_raw = raw;
        const bool final_before = ref.final_received();
        const int taken_before = taken;
        const auto a = new_segment(now, raw, taken);
        const auto b = reference_segment(ref, raw);
        CHECK(a == b);
        if (taken == taken_before && b.abort == abort_code::none && !b.bytes.empty()) ++declined;
        data.insert(data.end(), b.bytes.begin(), b.bytes.end());
        if (!final_before && ref.final_received()) {
          for (std::size_t i = 0; i < 7U; ++i) final_bytes[i] = raw[1U + i];
        }
        if (b.abort == abort_code::none && seq == expected && expected < 127U) ++expected;
      }
      CHECK(now.count() == ref.count());
      CHECK(now.final_received() == ref.final_received());
      CHECK(now.block_size() == ref.block_size());
      sdo::payload probe{};
      probe[0] = static_cast<std::uint8_t>(g.below(256));
      CHECK(now.is_repeat(probe) == ref.is_repeat(probe));
      CHECK(now.is_repeat(last_raw) == ref.is_repeat(last_raw));
    }
  }
  CHECK(taken > 10000);
  CHECK(declined > 100);
  CHECK(crc_ends > 50);
}

TEST_CASE("sdo: block_receiver::take_next declines what on_segment must decide") {
  sdo::block_receiver rx;
  rx.start(100, 21, false, 3);
  sdo::payload p{0x01, 1, 2, 3, 4, 5, 6, 7};
  CHECK(rx.take_next(p)); // segment 1 of 3
  CHECK(rx.count() == 7U);
  CHECK_FALSE(rx.take_next(p)); // a repeat
  p[0] = 0x03;
  CHECK_FALSE(rx.take_next(p)); // a gap
  p[0] = 0x82;
  CHECK_FALSE(rx.take_next(p)); // the last segment of the transfer
  p[0] = 0x00;
  CHECK_FALSE(rx.take_next(p)); // sequence number 0
  p[0] = 0x02;
  CHECK(rx.take_next(p)); // segment 2 of 3
  p[0] = 0x03;
  CHECK_FALSE(rx.take_next(p)); // the last of the sub-block: an acknowledgement is due
  CHECK(rx.count() == 14U);
  const auto r = rx.on_segment(p);
  CHECK(r.acknowledge);
  CHECK(rx.count() == 21U);
  (void)rx.acknowledge(3);
  p[0] = 0x01;
  CHECK_FALSE(rx.take_next(p)); // 28 bytes would exceed the 21 announced
  CHECK(rx.on_segment(p).abort == abort_code::length_too_high);

  sdo::block_receiver small;
  small.start(10, std::nullopt, false, 127);
  p[0] = 0x01;
  CHECK(small.take_next(p));
  p[0] = 0x02;
  CHECK_FALSE(small.take_next(p)); // 14 bytes would exceed the capacity of 10
  CHECK(small.on_segment(p).abort == abort_code::out_of_memory);
}
