// The block segment path of issue 18 (round 4): block_receiver::on_segment reads a segment's
// sequence number, last flag and 7 bytes in place instead of taking the `message` that
// decode_block_segment built (and the server and client no longer build one). The receiver of
// round 3 is kept here as the reference, with decode_block_segment in front of it as the
// machines called it: both are fed the same random streams of segments (in sequence, repeated,
// out of order, sequence number 0, last segments, ends, acknowledgements) under random
// capacities, announced sizes, CRC and block sizes, and must agree on every result and on
// every observable after every call.
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

/// block_receiver before round 4, verbatim but for the name and the segment_result type.
class reference_receiver {
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
  [[nodiscard]] constexpr segment_result on_segment(const sdo::message &m,
                                                    const sdo::payload &raw) noexcept {
    segment_result r;
    if (final_) return r;
    const bool in_sequence = m.sequence == sequence_ + 1U;
    if (!in_sequence) {
      if (sequence_ != 0U && m.sequence != sequence_) r.acknowledge = true;
      return r;
    }
    sequence_ = m.sequence;
    previous_ = raw;
    have_previous_ = true;
    if (m.last) {
      final_ = true;
      for (std::size_t i = 0; i < 7U; ++i) last_[i] = m.data[i];
    } else {
      if (announced_ && count_ + 7U > *announced_) {
        r.abort = abort_code::length_too_high;
        return r;
      }
      if (count_ + 7U > capacity_) {
        r.abort = abort_code::out_of_memory;
        return r;
      }
      r.bytes = m.bytes();
      r.offset = count_;
      if (crc_enabled_) crc_ = fc::crc::ccitt16(r.bytes, crc_);
      count_ += 7U;
    }
    r.acknowledge = m.sequence == block_size_ || m.last;
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

/// What the machines did with a segment before round 4: decode_block_segment (sequence 0:
/// invalid_sequence_number, as both machines answered), then on_segment(message, raw).
struct reference_result {
  abort_code abort = abort_code::none;
  std::vector<std::uint8_t> bytes;
  std::size_t offset = 0;
  bool acknowledge = false;
  bool operator==(const reference_result &) const = default;
};
reference_result reference_segment(reference_receiver &rx, const sdo::payload &raw) {
  const auto seg = sdo::decode_block_segment(raw);
  if (!seg) return {abort_code::invalid_sequence_number, {}, 0, false};
  const auto r = rx.on_segment(seg.value(), raw);
  return {r.abort, {r.bytes.begin(), r.bytes.end()}, r.offset, r.acknowledge};
}
reference_result new_segment(sdo::block_receiver &rx, const sdo::payload &raw) {
  const auto r = rx.on_segment(raw);
  return {r.abort, {r.bytes.begin(), r.bytes.end()}, r.offset, r.acknowledge};
}

struct rng : fieldcodec::test::xorshift {
  rng() : xorshift(0x0F1E'2D3C'4B5A'6978ULL) {}
  unsigned below(unsigned n) { return static_cast<unsigned>(next() % n); }
};

} // namespace

TEST_CASE("sdo: block_receiver::on_segment reading the frame gives what decode_block_segment + "
          "the old on_segment gave") {
  rng g;
  for (int run = 0; run < 3000; ++run) {
    sdo::block_receiver now;
    reference_receiver ref;
    const std::size_t capacity = g.below(4) == 0 ? g.below(60) : 2000U;
    const std::optional<std::uint32_t> announced =
        g.below(2) == 0 ? std::nullopt : std::optional<std::uint32_t>(g.below(120));
    const bool crc = g.below(2) == 0;
    const auto block_size = static_cast<std::uint8_t>(1U + g.below(8));
    now.start(capacity, announced, crc, block_size);
    ref.start(capacity, announced, crc, block_size);
    std::uint8_t expected = 1; // the sequence number a well-behaved sender sends next
    sdo::payload last_raw{};   // the segment sent last (is_repeat is asked about it)
    for (int k = 0; k < 40; ++k) {
      INFO("run ", run, " step ", k);
      const unsigned what = g.below(16);
      if (what == 0) { // an acknowledgement with a new block size (0 and over 127 clamped)
        const auto n = static_cast<std::uint8_t>(g.below(256));
        CHECK(now.acknowledge(n) == ref.acknowledge(n));
        expected = 1;
      } else if (what == 1) { // the end message
        sdo::message end;
        end.type = sdo::message_type::block_end;
        end.unused = static_cast<std::uint8_t>(g.below(8));
        end.checksum = static_cast<std::uint16_t>(g.next());
        const auto a = now.on_end(end);
        const auto b = ref.on_end(end);
        CHECK(a.abort == b.abort);
        CHECK(a.offset == b.offset);
        CHECK(std::vector<std::uint8_t>(a.bytes.begin(), a.bytes.end()) ==
              std::vector<std::uint8_t>(b.bytes.begin(), b.bytes.end()));
      } else { // a segment: mostly the next one, else a repeat, a gap, 0 or any number
        sdo::payload raw{};
        const std::uint64_t r = g.next();
        for (std::size_t i = 1; i < 8U; ++i) raw[i] = static_cast<std::uint8_t>(r >> (8U * i));
        unsigned seq = expected;
        const unsigned kind = g.below(10);
        if (kind == 0) seq = expected > 1U ? expected - 1U : 1U;
        if (kind == 1) seq = expected + 1U + g.below(3);
        if (kind == 2) seq = 0;
        if (kind == 3) seq = g.below(128);
        const bool last = g.below(12) == 0;
        raw[0] = static_cast<std::uint8_t>((last ? 0x80U : 0U) | (seq & 0x7FU));
        last_raw = raw;
        const auto a = new_segment(now, raw);
        const auto b = reference_segment(ref, raw);
        CHECK(a == b);
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
}
