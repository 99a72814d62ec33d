// fieldcodec — the step shape every CANopen machine returns: the frames to send, the machine's
// state, and the next deadline.
//
//   auto s = machine.on_frame(frame, now);   // or machine.poll(now), or a start call
//   for (const can_frame &f : s.send) transmit(f);
//   if (s.deadline) sleep_until(*s.deadline);   // poll(now) at the latest then
//
// or, for a transmit queue that takes several frames at once (a burst in one tight loop):
//
//   for (std::size_t i = 0; i < s.send.size();) i += s.send.copy_to(queue_room(), i);
//
// `frames` needs no heap and holds no copies of large data. It is one of:
// * nothing, or one frame held inline (every SDO request and response);
// * a span of frames the machine owns (for services that send several frames at once);
// * a burst of SDO block segments: a run of 1..127 frames on one COB-ID cut from a span of
//   bytes the machine borrows (byte 0 = sequence number 1..n, the last one of a transfer with
//   bit 7 set, then 7 data bytes). The frames are made when the caller reads them, so a burst of
//   127 segments costs no memory; the caller may also send them as its transmit queue frees up
//   (`copy_to` writes the next k frames into the caller's queue in one call).
// The frames (and the bytes a burst refers to) stay valid until the next call into the machine.
//
// Deadlines are absolute times in the caller's own millisecond counter (the `now` passed in);
// the counter may wrap around (comparisons are modulo 2^32, see `reached`).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/sdo.hpp>

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <span>

namespace fieldcodec::canopen {

/// The frames one step asks the caller to send.
class frames {
public:
  constexpr frames() noexcept : one_() {}
  /// One frame.
  constexpr frames(const can_frame &one) noexcept : one_(one), size_(1), kind_(kind::one) {}
  /// Frames the machine owns.
  constexpr explicit frames(std::span<const can_frame> list) noexcept
      : list_(list), size_(list.size()), kind_(kind::list) {}

  /// A burst of block segments: `count` (1..127) frames on `id`, segment i (from 0) carries
  /// sequence number i + 1 and bytes [7 i, 7 i + 7) of `data` (zero-padded); `ends_transfer`
  /// marks the last of them as the last segment of the transfer.
  [[nodiscard]] static constexpr frames block_segments(std::uint16_t id,
                                                       std::span<const std::uint8_t> data,
                                                       std::uint8_t count,
                                                       bool ends_transfer) noexcept {
    // only code that builds a burst, or calls copy_to, links the segment encoder
    return frames(burst{data, &frames::segment, id, ends_transfer}, count);
  }

  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0U; }
  /// True for a burst of block segments.
  [[nodiscard]] constexpr bool is_burst() const noexcept { return kind_ == kind::burst; }

  /// Frame `i` (0 ≤ i < size()).
  [[nodiscard]] constexpr can_frame operator[](std::size_t i) const noexcept {
    switch (kind_) {
    case kind::one: return one_;
    case kind::list: return list_[i];
    case kind::burst: return burst_.make(*this, i);
    case kind::none: break;
    }
    return {};
  }

  /// Write frames `first`, `first` + 1, … into `out`, as many as fit: k = min(out.size(),
  /// size() − first) frames (none when `first` ≥ size()), each equal to (*this)[first + j].
  /// Returns k. One call per queue refill instead of one per frame: a burst's segments are made
  /// in one loop straight into `out`; `frames` stays lazy (nothing is held beyond the span).
  /// The loop is called directly (no pointer in `frames`), so firmware that never calls copy_to
  /// does not link it, and firmware that does links the segment encoder even without bursts.
  [[nodiscard]] constexpr std::size_t copy_to(std::span<can_frame> out,
                                              std::size_t first = 0) const noexcept {
    if (first >= size_) return 0;
    const std::size_t k = out.size() < size_ - first ? out.size() : size_ - first;
    if (k == 0U) return 0; // no room
    switch (kind_) {
    case kind::one: out[0] = one_; break;
    case kind::list:
      for (std::size_t j = 0; j < k; ++j) out[j] = list_[first + j];
      break;
    case kind::burst: segments(*this, first, out.first(k)); break;
    case kind::none: break;
    }
    return k;
  }

  class iterator {
  public:
    using iterator_category = std::input_iterator_tag;
    using value_type = can_frame;
    using difference_type = std::ptrdiff_t;
    using pointer = void;
    using reference = can_frame;
    constexpr iterator() noexcept = default;
    constexpr iterator(const frames *f, std::size_t i) noexcept : f_(f), i_(i) {}
    [[nodiscard]] constexpr can_frame operator*() const noexcept { return (*f_)[i_]; }
    constexpr iterator &operator++() noexcept {
      ++i_;
      return *this;
    }
    constexpr iterator operator++(int) noexcept {
      iterator old = *this;
      ++i_;
      return old;
    }
    friend constexpr bool operator==(const iterator &a, const iterator &b) noexcept {
      return a.i_ == b.i_;
    }

  private:
    const frames *f_ = nullptr;
    std::size_t i_ = 0;
  };
  [[nodiscard]] constexpr iterator begin() const noexcept { return {this, 0}; }
  [[nodiscard]] constexpr iterator end() const noexcept { return {this, size_}; }

private:
  enum class kind : std::uint8_t { none, one, list, burst };
  struct burst {
    std::span<const std::uint8_t> data;
    can_frame (*make)(const frames &, std::size_t); ///< segment(), for operator[]
    std::uint16_t id;
    bool ends_transfer;
  };
  constexpr frames(const burst &b, std::uint8_t count) noexcept
      : burst_(b), size_(count), kind_(kind::burst) {}

  /// Segment i (from 0) of the burst: sequence number i + 1, bytes [7 i, 7 i + 7) of the data,
  /// zero-padded; the last flag on the burst's last frame if it ends the transfer.
  [[nodiscard]] static constexpr can_frame segment(const frames &self, std::size_t i) noexcept {
    const auto data = self.burst_.data;
    const std::size_t from = 7U * i < data.size() ? 7U * i : data.size();
    const std::size_t n = data.size() - from > 7U ? 7U : data.size() - from;
    const bool last = self.burst_.ends_transfer && i + 1U == self.size_;
    can_frame f;
    f.id = self.burst_.id;
    f.dlc = 8;
    // cannot fail: sequence 1..127 and at most 7 bytes (zeros if it ever did)
    f.data =
        sdo::encode_block_segment(static_cast<std::uint8_t>(i + 1U), data.subspan(from, n), last)
            .value_or(sdo::payload{});
    return f;
  }
  /// Segments first, first + 1, … into `out` (copy_to's loop, called directly: one call per
  /// burst instead of a switch and an indirect call per frame): the full segments in a loop of
  /// their own, the rest (at most the short last one) through segment().
  static constexpr void segments(const frames &self, std::size_t first,
                                 std::span<can_frame> out) noexcept {
    const auto data = self.burst_.data;
    // segments [first, full) carry 7 bytes of data and are not the transfer's last: the same
    // encoder with what segment() would compute for them known in the loop
    std::size_t full = data.size() / 7U;
    if (self.burst_.ends_transfer && full >= self.size_ && self.size_ > 0U) full = self.size_ - 1U;
    // sequence numbers above 127 are no segments (segment() makes them all zeros, as the
    // encoder refuses them): the loop stops before them
    if (full > sdo::max_block_size) full = sdo::max_block_size;
    std::size_t j = 0;
    for (; j < out.size() && first + j < full; ++j) {
      const std::size_t i = first + j;
      can_frame &f = out[j];
      f.id = self.burst_.id;
      f.rtr = false;
      f.dlc = 8;
      // encode_block_segment's writer without its checks, which hold here: sequence i + 1 ≤
      // 127 and 7 bytes
      sdo::detail::write_block_segment(f.data, static_cast<std::uint8_t>(i + 1U),
                                       data.subspan(7U * i, 7U), false);
    }
    for (; j < out.size(); ++j) out[j] = segment(self, first + j); // the rest as segment() does
  }

  // One of the three, as kind_ says (none: one_, unread). A union, so that a step is small
  // (48 bytes instead of 88 on a 64-bit host): an empty step, the answer to most frames (every
  // block segment but the last of a sub-block), writes the 12 bytes of one_, size_ and kind_.
  union {
    can_frame one_;
    std::span<const can_frame> list_;
    burst burst_;
  };
  std::size_t size_ = 0;
  kind kind_ = kind::none;
};

/// What one call into a machine produced: the frames to send, the state after the call, and
/// when the machine wants to be polled next (empty: nothing pending, no timer running).
template <class State>
struct step {
  frames send{};
  State state{};
  std::optional<std::uint32_t> deadline{};
};

/// Has the millisecond counter `now` reached `deadline`? Modulo 2^32: a deadline up to 2^31 − 1
/// ms ahead is "not yet".
[[nodiscard]] constexpr bool reached(std::uint32_t deadline, std::uint32_t now) noexcept {
  return static_cast<std::uint32_t>(now - deadline) < 0x8000'0000U;
}

} // namespace fieldcodec::canopen
