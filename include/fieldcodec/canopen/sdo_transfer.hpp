// fieldcodec — the shared core of the SDO transfer machines (sdo_client.hpp, sdo_server.hpp):
// states, errors with context, the step shape, and the rules of segmented and block transfer
// that both sides follow.
//
// A transfer moves bytes from a sending side to a receiving side:
//   download: client sends, server receives;   upload: server sends, client receives.
// The four roles below hold the protocol rules of one side of one transfer kind and nothing
// else: where the bytes come from and go to (a borrowed span, a server buffer over a store),
// which frame type carries them and how a failure is reported stay with the client and the
// server. So the toggle, size, sequence-number, block-size and CRC rules exist once.
//   segment_sender    segmented: the next segment, toggle check of the answer
//   segment_receiver  segmented: toggle, announced size and capacity checks
//   block_sender      block: sub-block bursts, acknowledgements, retransmission, end (CRC)
//   block_receiver    block: sequence numbers, when to acknowledge, end (unused bytes, CRC)
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <type_traits>

namespace fieldcodec::canopen::sdo {

/// The state of a transfer machine.
enum class transfer_state : std::uint8_t { idle, busy, done, failed };

/// Why a transfer failed: the error, the abort code sent or received (none when no abort
/// message was involved, e.g. a refused frame), and the object. The one SDO error with context
/// of the library: the machines, the master and the device folders' SDO helpers return it.
///   code == errc::aborted: the peer sent `abort`; `text()` is its CiA 301 description from the
///     one abort table `abort_codes`, `cause()` the errc that table maps it to;
///   otherwise the problem was detected here (a refused frame, a timeout, …) and `abort` is the
///     code sent to the peer, or none.
struct transfer_error {
  errc code = errc::aborted;
  abort_code abort = abort_code::none;
  od::address address{};

  [[nodiscard]] constexpr bool is(errc e) const noexcept { return code == e; }
  /// The CiA 301 text of `abort` ("no abort" for none, empty for a code CiA 301 lacks).
  [[nodiscard]] constexpr std::string_view text() const noexcept { return to_string(abort); }
  /// The errc the abort table maps `abort` to (e.g. out_of_range for 0609 0031h); `code` when
  /// there is no abort code.
  [[nodiscard]] constexpr errc cause() const noexcept {
    return abort == abort_code::none ? code : to_errc(abort);
  }
  friend constexpr bool operator==(const transfer_error &,
                                   const transfer_error &) noexcept = default;
  friend constexpr bool operator==(const transfer_error &a, errc e) noexcept { return a.code == e; }
};

/// What every call into an SDO machine returns.
using step = canopen::step<transfer_state>;

/// Segments needed for `size` bytes of a segmented or block transfer (at least one: a 0-byte
/// transfer sends one empty last segment).
[[nodiscard]] constexpr std::uint32_t segments_for(std::uint32_t size) noexcept {
  return size == 0U ? 1U : size / 7U + (size % 7U != 0U ? 1U : 0U);
}

// ---------------------------------------------------------------------------------------------
// Segmented transfer

/// The sending side of a segmented transfer of `size` bytes.
class segment_sender {
public:
  constexpr void start(std::uint32_t size) noexcept {
    size_ = size;
    offset_ = 0;
    toggle_ = false;
  }
  /// Bytes of the next segment and where they start.
  [[nodiscard]] constexpr std::uint32_t offset() const noexcept { return offset_; }
  [[nodiscard]] constexpr std::uint32_t next_length() const noexcept {
    return size_ - offset_ < 7U ? size_ - offset_ : 7U;
  }
  [[nodiscard]] constexpr bool next_is_last() const noexcept { return size_ - offset_ <= 7U; }
  [[nodiscard]] constexpr bool toggle() const noexcept { return toggle_; }
  [[nodiscard]] constexpr bool finished() const noexcept { return offset_ == size_ && sent_last_; }

  /// The next segment (`bytes` = the next_length() bytes at offset()) as message `type`
  /// (download_segment_request or upload_segment_response); moves on and flips the toggle.
  [[nodiscard]] constexpr payload next(message_type type,
                                       std::span<const std::uint8_t> bytes) noexcept {
    const bool last = next_is_last();
    // the bits of the two segment commands as constants (no look-up in the command table)
    const unsigned bits = type == message_type::download_segment_request
                              ? detail::bits_of<message_type::download_segment_request>
                              : detail::bits_of<message_type::upload_segment_response>;
    const payload p = detail::put_segment(bits, toggle_, bytes, last); // 7 bytes, or fewer last
    offset_ += static_cast<std::uint32_t>(bytes.size());
    sent_last_ = last;
    toggle_ = !toggle_;
    return p;
  }
  /// Does the toggle the peer answered with belong to the segment just sent?
  [[nodiscard]] constexpr bool answer_matches(bool peer_toggle) const noexcept {
    return peer_toggle != toggle_; // next() has flipped it already
  }

private:
  std::uint32_t size_ = 0;
  std::uint32_t offset_ = 0;
  bool toggle_ = false;
  bool sent_last_ = false;
};

/// The receiving side of a segmented transfer.
class segment_receiver {
public:
  /// `capacity`: most bytes the receiver can take; `announced`: the size the sender indicated.
  constexpr void start(std::size_t capacity, std::optional<std::uint32_t> announced) noexcept {
    capacity_ = capacity;
    announced_ = announced;
    count_ = 0;
    toggle_ = false;
  }
  /// The toggle the next segment (or segment request) must carry.
  [[nodiscard]] constexpr bool toggle() const noexcept { return toggle_; }
  [[nodiscard]] constexpr std::size_t count() const noexcept { return count_; }

  /// Check a received segment; on success the caller stores m.bytes() at the old count().
  /// Returns none or the abort code: toggle_not_alternated, out_of_memory (over capacity),
  /// length_too_high / length_too_low (disagrees with the announced size).
  [[nodiscard]] constexpr abort_code accept(const message &m) noexcept {
    return accept(m.toggle, m.data_size, m.last);
  }
  /// The same for a segment read in place: its toggle, data bytes (0..7) and last flag.
  [[nodiscard]] constexpr abort_code accept(bool toggle, std::size_t size, bool last) noexcept {
    if (toggle != toggle_) return abort_code::toggle_not_alternated;
    if (announced_ && count_ + size > *announced_) return abort_code::length_too_high;
    if (count_ + size > capacity_) return abort_code::out_of_memory;
    if (last && announced_ && count_ + size != *announced_) return abort_code::length_too_low;
    count_ += size;
    toggle_ = !toggle_;
    return abort_code::none;
  }

private:
  std::size_t capacity_ = 0;
  std::optional<std::uint32_t> announced_{};
  std::size_t count_ = 0;
  bool toggle_ = false;
};

// ---------------------------------------------------------------------------------------------
// Block transfer

namespace detail {
/// The maker of a burst of block segments (frames::burst; see block_segments): segments
/// first, first + 1, … into `out`. Segment i (from 0) has sequence number i + 1 and bytes
/// [7 i, 7 i + 7) of the data, zero-padded; the last flag on the burst's last frame when it
/// ends the transfer; a sequence number above 127 is no segment (all zeros, as
/// encode_block_segment refuses it). The full segments run in a loop of their own (7 bytes, not
/// the transfer's last: a copy of constant length each).
constexpr void make_block_segments(const frames &b, std::size_t first,
                                   std::span<can_frame> out) noexcept {
  const auto data = b.burst_data();
  std::size_t full = data.size() / 7U;
  if (b.burst_flag() && full >= b.size() && b.size() > 0U) full = b.size() - 1U;
  if (full > max_block_size) full = max_block_size;
  for (std::size_t j = 0; j < out.size(); ++j) {
    const std::size_t i = first + j;
    can_frame &f = out[j];
    f.id = b.burst_id();
    f.rtr = false;
    f.dlc = 8;
    if (i < full) {
      write_block_segment(f.data, static_cast<std::uint8_t>(i + 1U), data.subspan(7U * i, 7U),
                          false);
    } else if (i < max_block_size) {
      const std::size_t from = 7U * i < data.size() ? 7U * i : data.size();
      const std::size_t n = data.size() - from > 7U ? 7U : data.size() - from;
      write_block_segment(f.data, static_cast<std::uint8_t>(i + 1U), data.subspan(from, n),
                          b.burst_flag() && i + 1U == b.size());
    } else {
      f.data = {};
    }
  }
}
} // namespace detail

/// A burst of block segments: `count` (1..127) frames on `id`, segment i (from 0) carries
/// sequence number i + 1 and bytes [7 i, 7 i + 7) of `data` (zero-padded); `ends_transfer`
/// marks the last of them as the last segment of the transfer. The frames are made when they
/// are read (canopen::frames, step.hpp).
[[nodiscard]] constexpr frames block_segments(std::uint16_t id, std::span<const std::uint8_t> data,
                                              std::uint8_t count, bool ends_transfer) noexcept {
  return frames::burst(id, data, count, ends_transfer, &detail::make_block_segments);
}

/// The sending side of a block transfer of `size` bytes: sub-blocks of block_size() segments,
/// retransmission from the first segment the receiver did not acknowledge, and the end message
/// with the unused bytes of the last segment and the CRC of the data, computed by `Crc`
/// (crc::ccitt16_no_table or crc::ccitt16_with_table, core/crc.hpp).
template <class Crc = crc::ccitt16_no_table>
class basic_block_sender {
public:
  constexpr void start(std::uint32_t size, bool crc, std::uint8_t block_size) noexcept {
    size_ = size;
    acked_ = 0;
    crc_enabled_ = crc;
    crc_ = 0;
    block_size_ = block_size;
    in_flight_ = 0;
  }
  /// Where the next burst starts, how many segments and bytes it has, and whether it holds the
  /// last segment of the transfer.
  [[nodiscard]] constexpr std::uint32_t offset() const noexcept { return acked_; }
  [[nodiscard]] constexpr std::uint8_t burst_segments() const noexcept {
    const std::uint32_t left = segments_for(size_) - acked_ / 7U;
    return static_cast<std::uint8_t>(left < block_size_ ? left : block_size_);
  }
  [[nodiscard]] constexpr std::uint32_t burst_bytes() const noexcept {
    const std::uint32_t n = 7U * burst_segments();
    return size_ - acked_ < n ? size_ - acked_ : n;
  }
  [[nodiscard]] constexpr bool burst_ends_transfer() const noexcept {
    return acked_ / 7U + burst_segments() == segments_for(size_);
  }
  [[nodiscard]] constexpr std::uint8_t block_size() const noexcept { return block_size_; }
  [[nodiscard]] constexpr std::uint32_t acknowledged() const noexcept { return acked_; }

  /// The burst of the next sub-block on `id`; `window` = the burst_bytes() bytes at offset().
  [[nodiscard]] constexpr frames burst(std::uint16_t id,
                                       std::span<const std::uint8_t> window) noexcept {
    in_flight_ = burst_segments();
    return block_segments(id, window, in_flight_, burst_ends_transfer());
  }

  /// What an acknowledgement asks for.
  enum class next : std::uint8_t { burst, end };
  /// Take an acknowledgement of the burst whose bytes were `window`: the receiver got segments
  /// 1..sequence and wants `block_size` segments next. Returns what to send next, or the abort
  /// code: invalid_sequence_number (more segments acknowledged than sent), invalid_block_size
  /// (next block size not 1..127).
  struct ack_result {
    abort_code abort = abort_code::none;
    next what = next::burst;
  };
  [[nodiscard]] constexpr ack_result on_ack(const message &m,
                                            std::span<const std::uint8_t> window) noexcept {
    return on_ack(m.sequence, m.block_size, window);
  }
  /// The same for an acknowledgement read in place: its sequence number and block size.
  [[nodiscard]] constexpr ack_result on_ack(std::uint8_t sequence, std::uint8_t block_size,
                                            std::span<const std::uint8_t> window) noexcept {
    if (sequence > in_flight_) return {abort_code::invalid_sequence_number, next::burst};
    const bool ended = burst_ends_transfer() && sequence == in_flight_;
    std::uint32_t n = 7U * sequence;
    if (n > window.size()) n = static_cast<std::uint32_t>(window.size());
    if (crc_enabled_) crc_ = Crc::update(window.first(n), crc_);
    acked_ += n;
    in_flight_ = 0;
    if (ended) return {abort_code::none, next::end};
    if (block_size < 1U || block_size > max_block_size) {
      return {abort_code::invalid_block_size, next::burst};
    }
    block_size_ = block_size;
    return {abort_code::none, next::burst};
  }
  /// The end message once every segment is acknowledged.
  [[nodiscard]] constexpr payload end() const noexcept {
    const auto unused = static_cast<std::uint8_t>(7U * segments_for(size_) - size_);
    return detail::put_block_end(detail::bits_of<message_type::block_end>, unused, // 0..6
                                 crc_enabled_ ? crc_ : std::uint16_t{0});
  }

private:
  std::uint32_t size_ = 0;
  std::uint32_t acked_ = 0;
  std::uint16_t crc_ = 0;
  bool crc_enabled_ = false;
  std::uint8_t block_size_ = 1;
  std::uint8_t in_flight_ = 0;
};

/// The receiving side of a block transfer: takes segments in sequence, ignores duplicates and
/// segments after a gap, says when to acknowledge, and checks the end (size, CRC). The last
/// segment of the transfer is held back until the end message says how many of its bytes are
/// data. `Crc` computes the CRC, as for basic_block_sender.
template <class Crc = crc::ccitt16_no_table>
class basic_block_receiver {
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
    limit_ = announced && *announced < capacity ? std::size_t{*announced} : capacity;
  }
  [[nodiscard]] constexpr std::size_t count() const noexcept { return count_; }
  [[nodiscard]] constexpr bool final_received() const noexcept { return final_; }
  [[nodiscard]] constexpr std::uint8_t block_size() const noexcept { return block_size_; }

  /// What a segment asks for: the bytes to store (at `offset`), whether to acknowledge now.
  struct segment_result {
    abort_code abort = abort_code::none;
    std::span<const std::uint8_t> bytes{}; ///< store at `offset` (empty: nothing new)
    std::size_t offset = 0;
    bool acknowledge = false;
  };
  /// Take a segment frame's 8 bytes (byte 0 = last << 7 | sequence number, then 7 data bytes,
  /// as decode_block_segment reads them; read here in place, without a `message`: this runs
  /// for every segment of a block transfer). `bytes` of the result points into `raw`. The
  /// rules (as the common C stacks apply them):
  /// * sequence number 0 is no segment: invalid_sequence_number;
  /// * the next sequence number is taken; the last one of the sub-block (or the last segment of
  ///   the transfer) asks for the acknowledgement;
  /// * a repeat of the segment just taken, and anything before the first segment of a
  ///   sub-block, is ignored (leftovers of a burst that was already acknowledged);
  /// * any other sequence number (a gap, a reordered frame) asks for the acknowledgement at
  ///   once: the sender retransmits from the first segment missing.
  /// With sub-blocks of one segment a repeated frame cannot be told from the next segment (both
  /// carry sequence number 1): it is taken as new data, and only the CRC finds it. Keep the CRC
  /// on over links that may repeat frames.
  [[nodiscard]] constexpr segment_result on_segment(const payload &raw) noexcept {
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
      if (crc_enabled_) crc_ = Crc::update(r.bytes, crc_);
      count_ += 7U;
    }
    r.acknowledge = sequence == block_size_ || last;
    return r;
  }
  /// The common segment, taken by a short path (issue 18: it is nearly every frame of a block
  /// transfer): the next sequence number, not the last segment of the transfer nor of the
  /// sub-block, within the announced size and the capacity. Then it is taken exactly as
  /// on_segment(raw) takes it — which would return no abort, no acknowledgement and the 7 bytes
  /// raw[1..7] at the old count() — and the result is true. Otherwise nothing changes and the
  /// result is false: call on_segment(raw).
  [[nodiscard]] constexpr bool take_next(const payload &raw) noexcept {
    // raw[0] < block_size_ (≤ 127): last flag clear; == sequence_ + 1: not 0, in sequence
    if (raw[0] != sequence_ + 1U || raw[0] >= block_size_ || final_ || count_ + 7U > limit_) {
      return false;
    }
    sequence_ = raw[0];
    previous_ = raw;
    have_previous_ = true;
    if (crc_enabled_) crc_ = Crc::update(std::span<const std::uint8_t>(raw).subspan<1, 7>(), crc_);
    count_ += 7U;
    return true;
  }
  /// take_next over a run of received frames (round 6: a CAN driver hands over its receive
  /// FIFO): takes frames from the front of `fs` while each is a data frame on `id` with DLC 8
  /// whose payload take_next(payload) would take, and copies the 7 data bytes of the k-th one
  /// to out[7 k, 7 k + 7), at most out.size() / 7 frames. Returns how many it took, k; the
  /// receiver is then where k calls of take_next would have left it (the CRC over the k × 7
  /// bytes in one update, the same value). Frame k, if any, is the one to look at next.
  /// `id` must be a valid 11-bit identifier (the check of expect_data(f, 8) then reduces to
  /// the ones made here).
  [[nodiscard]] constexpr std::size_t take_run(std::span<const can_frame> fs, std::uint16_t id,
                                               std::span<std::uint8_t> out) noexcept {
    if (final_ || sequence_ >= block_size_ || count_ > limit_) return 0;
    // the bounds of take_next for the whole run: sequence numbers up to block_size_ − 1, the
    // count up to limit_, and the room in `out`
    std::size_t most = static_cast<std::size_t>(block_size_ - 1U - sequence_);
    if (const std::size_t n = (limit_ - count_) / 7U; n < most) most = n;
    if (const std::size_t n = out.size() / 7U; n < most) most = n;
    if (const std::size_t n = fs.size(); n < most) most = n;
    std::size_t k = 0;
    auto next = static_cast<std::uint8_t>(sequence_ + 1U);
#if defined(__GNUC__)
    if (!std::is_constant_evaluated() && std::endian::native == std::endian::little) {
      // the same four checks as one: id, rtr, dlc and data[0] are the first 5 bytes of a
      // frame (asserted below), read as one little-endian word and compared under a mask
      static_assert(sizeof(can_frame) == 12U && offsetof(can_frame, rtr) == 2U &&
                    offsetof(can_frame, dlc) == 3U && offsetof(can_frame, data) == 4U);
      // the expected word of the next frame: its sequence number counts up in bits 32..39
      std::uint64_t want =
          std::uint64_t{id} | (std::uint64_t{8} << 24U) | (std::uint64_t{next} << 32U);
      for (; k < most; ++k, want += std::uint64_t{1} << 32U) {
        std::uint64_t w = 0;
        __builtin_memcpy(&w, &fs[k], 8);
        if ((w & 0xFF'FFFF'FFFFU) != want) break;
        fieldcodec::copy_bytes<7>(fs[k].data.data() + 1, out.data() + 7U * k);
      }
    } else
#endif
    {
      for (; k < most; ++k) {
        const can_frame &f = fs[k];
        if (f.id != id || f.rtr || f.dlc != 8U || f.data[0] != next) break;
        fieldcodec::copy_bytes<7>(f.data.data() + 1, out.data() + 7U * k);
        ++next;
      }
    }
    if (k == 0U) return 0;
    sequence_ = static_cast<std::uint8_t>(sequence_ + k);
    previous_ = fs[k - 1U].data;
    have_previous_ = true;
    if (crc_enabled_) crc_ = Crc::update(std::span<const std::uint8_t>(out).first(7U * k), crc_);
    count_ += 7U * k;
    return k;
  }
  /// Is `raw` a repeat of the segment taken last? (After the last segment, while the end
  /// message is awaited, such a repeat is ignored instead of being read as a message.)
  [[nodiscard]] constexpr bool is_repeat(const payload &raw) const noexcept {
    return have_previous_ && raw == previous_;
  }
  /// The acknowledgement of the current sub-block, asking for `next_block_size` segments next;
  /// the next sub-block starts. Errors: none (out-of-range sizes are clamped to 1..127).
  [[nodiscard]] constexpr payload acknowledge(std::uint8_t next_block_size) noexcept {
    if (next_block_size < 1U) next_block_size = 1U;
    if (next_block_size > max_block_size) next_block_size = max_block_size;
    const std::uint8_t seq = sequence_;
    sequence_ = 0;
    block_size_ = next_block_size;
    // sequence_ never passes block_size_ (≤ 127); the size is clamped above
    return detail::put_block_ack(detail::bits_of<message_type::block_ack>, seq, next_block_size);
  }

  /// Check the end message; on success the caller stores `bytes` (the data of the last
  /// segment) at `offset`, and the transfer is complete. Abort codes: unknown_command (end
  /// before the last segment), length_too_high / length_too_low (against the announced size),
  /// out_of_memory (over capacity), crc_error.
  struct end_result {
    abort_code abort = abort_code::none;
    std::span<const std::uint8_t> bytes{};
    std::size_t offset = 0;
  };
  [[nodiscard]] constexpr end_result on_end(const message &m) noexcept {
    return on_end(m.unused, m.checksum);
  }
  /// The same for an end message read in place: its unused bytes (0..7) and CRC.
  [[nodiscard]] constexpr end_result on_end(std::uint8_t unused, std::uint16_t checksum) noexcept {
    end_result r;
    if (!final_) {
      r.abort = abort_code::unknown_command;
      return r;
    }
    const std::size_t n = 7U - unused;
    const std::size_t total = count_ + n;
    if (announced_ && total > *announced_) r.abort = abort_code::length_too_high;
    if (announced_ && total < *announced_) r.abort = abort_code::length_too_low;
    if (r.abort == abort_code::none && total > capacity_) r.abort = abort_code::out_of_memory;
    if (r.abort != abort_code::none) return r;
    r.bytes = std::span<const std::uint8_t>(last_).first(n);
    r.offset = count_;
    if (crc_enabled_ && Crc::update(r.bytes, crc_) != checksum) {
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
  payload previous_{};
  std::size_t limit_ = 0; ///< min(capacity, announced size): take_next's one bound
};

/// The block transfer roles with the CRC computed without a table (what the machines use by
/// default).
using block_sender = basic_block_sender<>;
using block_receiver = basic_block_receiver<>;

// ---------------------------------------------------------------------------------------------
// What client and server share: state, error, deadline

/// What server::on_frames or client::on_frames did with a run of received frames.
struct batch_step {
  std::size_t consumed = 0; ///< frames taken from the front of the span (≥ 1 unless it is empty)
  step last{};              ///< the step to act on: on_frame's step for the last frame taken
};

/// The bookkeeping every SDO machine has: state, the object, the error of the last failure, the
/// time of the last activity and the timeout.
class machine_core {
public:
  constexpr explicit machine_core(std::uint32_t timeout_ms) noexcept : timeout_ms_(timeout_ms) {}

  [[nodiscard]] constexpr transfer_state state() const noexcept { return state_; }
  [[nodiscard]] constexpr bool busy() const noexcept { return state_ == transfer_state::busy; }
  /// Why the last transfer failed or the last frame on the channel was refused; empty when
  /// neither happened since the last transfer started.
  [[nodiscard]] constexpr std::optional<transfer_error> error() const noexcept { return error_; }
  [[nodiscard]] constexpr od::address address() const noexcept { return address_; }
  [[nodiscard]] constexpr std::uint32_t timeout_ms() const noexcept { return timeout_ms_; }

  constexpr void begin(od::address a, std::uint32_t now) noexcept {
    address_ = a;
    last_ = now;
    error_.reset();
    state_ = transfer_state::busy;
  }
  constexpr void touch(std::uint32_t now) noexcept { last_ = now; }
  constexpr void finish() noexcept { state_ = transfer_state::done; }
  constexpr void fail(errc e, abort_code code) noexcept {
    error_ = transfer_error{e, code, address_};
    state_ = transfer_state::failed;
  }
  /// Note a refused frame without touching the transfer.
  constexpr void refuse(errc e, od::address a) noexcept {
    error_ = transfer_error{e, abort_code::none, a};
  }
  constexpr void stop() noexcept { state_ = transfer_state::idle; }
  /// The deadline make() reports has passed (modulo 2^32 like every deadline: a `now` a little
  /// older than the last activity is "not yet", not a wrapped-around timeout).
  [[nodiscard]] constexpr bool timed_out(std::uint32_t now) const noexcept {
    return busy() && reached(last_ + timeout_ms_, now);
  }
  [[nodiscard]] constexpr step make(const frames &f) const noexcept {
    // built in place, not default-built and then assigned (issue 18)
    return step{f, state_, deadline()};
  }
  /// A step that sends nothing: the answer to most frames, e.g. to every block segment but the
  /// last of a sub-block (its `frames` built in place, not copied from an argument).
  [[nodiscard]] constexpr step make() const noexcept { return step{frames{}, state_, deadline()}; }

private:
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline() const noexcept {
    return busy() ? std::optional<std::uint32_t>(last_ + timeout_ms_) : std::nullopt;
  }

  std::uint32_t timeout_ms_;
  std::uint32_t last_ = 0;
  od::address address_{};
  std::optional<transfer_error> error_{};
  transfer_state state_ = transfer_state::idle;
};

} // namespace fieldcodec::canopen::sdo
