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
// * a burst: a run of 1..255 frames on one COB-ID made from a span of bytes the machine
//   borrows, by a function the machine gives (`frames::burst`; the SDO block transfer's
//   segments, sdo::block_segments in sdo_transfer.hpp). The frames are made when the caller
//   reads them, so a burst of 127 segments costs no memory; the caller may also send them as
//   its transmit queue frees up (`copy_to` writes the next k frames into the caller's queue in
//   one call).
// The frames (and the bytes a burst refers to) stay valid until the next call into the machine.
//
// Deadlines are absolute times in the caller's own millisecond counter (the `now` passed in);
// the counter may wrap around (comparisons are modulo 2^32, see `reached`).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>

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

  /// How a burst makes its frames: writes frames first, first + 1, … (out.size() of them,
  /// all < size()) into `out`; reads what it needs through burst_id(), burst_data() and
  /// burst_flag().
  using burst_maker = void (*)(const frames &burst, std::size_t first,
                               std::span<can_frame> out) noexcept;
  /// A burst: `count` frames on `id` that `make` writes from `data` when they are read; `flag`
  /// is the maker's (e.g. "the last frame ends the transfer").
  [[nodiscard]] static constexpr frames burst(std::uint16_t id, std::span<const std::uint8_t> data,
                                              std::uint8_t count, bool flag,
                                              burst_maker make) noexcept {
    return frames(burst_parts{data, make, id, flag}, count);
  }
  /// What a burst's maker reads.
  [[nodiscard]] constexpr std::uint16_t burst_id() const noexcept { return burst_.id; }
  [[nodiscard]] constexpr std::span<const std::uint8_t> burst_data() const noexcept {
    return burst_.data;
  }
  [[nodiscard]] constexpr bool burst_flag() const noexcept { return burst_.flag; }

  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0U; }
  /// True for a burst.
  [[nodiscard]] constexpr bool is_burst() const noexcept { return kind_ == kind::burst; }

  /// Frame `i` (0 ≤ i < size()).
  [[nodiscard]] constexpr can_frame operator[](std::size_t i) const noexcept {
    switch (kind_) {
    case kind::one: return one_;
    case kind::list: return list_[i];
    case kind::burst: {
      can_frame f;
      burst_.make(*this, i, std::span<can_frame>(&f, 1));
      return f;
    }
    case kind::none: break;
    }
    return {};
  }

  /// Write frames `first`, `first` + 1, … into `out`, as many as fit: k = min(out.size(),
  /// size() − first) frames (none when `first` ≥ size()), each equal to (*this)[first + j].
  /// Returns k. One call per queue refill instead of one per frame: a burst's maker writes
  /// them in one loop straight into `out`; `frames` stays lazy (nothing is held beyond the
  /// span).
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
    case kind::burst: burst_.make(*this, first, out.first(k)); break;
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
  struct burst_parts {
    std::span<const std::uint8_t> data;
    burst_maker make;
    std::uint16_t id;
    bool flag;
  };
  constexpr frames(const burst_parts &b, std::uint8_t count) noexcept
      : burst_(b), size_(count), kind_(kind::burst) {}

  // One of the three, as kind_ says (none: one_, unread). A union, so that a step is small
  // (48 bytes instead of 88 on a 64-bit host): an empty step, the answer to most frames (every
  // block segment but the last of a sub-block), writes the 12 bytes of one_, size_ and kind_.
  union {
    can_frame one_;
    std::span<const can_frame> list_;
    burst_parts burst_;
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
