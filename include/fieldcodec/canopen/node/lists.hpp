// fieldcodec — the bounded lists of the node services (canopen/node/): the frames and the
// events one call produces, held by the machine and valid until its next call.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/step.hpp>

#include <array>
#include <cstddef>
#include <span>

namespace fieldcodec::canopen::node {

/// The frames one call produces, held by the machine (valid until its next call). A list is
/// sized so that one call cannot overflow it; push() still refuses rather than overwrite, and
/// counts what it refused (lost(), which the tests check is always 0).
template <std::size_t N>
class frame_list {
public:
  constexpr void clear() noexcept { n_ = 0; }
  constexpr bool push(const can_frame &f) noexcept {
    if (n_ == N) {
      ++lost_;
      return false;
    }
    f_[n_++] = f;
    return true;
  }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return n_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return n_ == 0U; }
  [[nodiscard]] constexpr std::span<const can_frame> span() const noexcept {
    return std::span<const can_frame>(f_.data(), n_);
  }
  [[nodiscard]] constexpr frames view() const noexcept {
    if (n_ == 0U) return {};
    if (n_ == 1U) return frames(f_[0]);
    return frames(span());
  }
  /// Frames refused because the list was full (a sizing error; never expected).
  [[nodiscard]] constexpr std::size_t lost() const noexcept { return lost_; }

private:
  std::array<can_frame, N> f_{};
  std::size_t n_ = 0;
  std::size_t lost_ = 0;
};

/// The events one call produces (valid until the next call), sized like frame_list.
template <class Event, std::size_t N>
class event_list {
public:
  constexpr void clear() noexcept { n_ = 0; }
  constexpr bool push(const Event &e) noexcept {
    if (n_ == N) {
      ++lost_;
      return false;
    }
    e_[n_++] = e;
    return true;
  }
  [[nodiscard]] constexpr std::span<const Event> span() const noexcept {
    return std::span<const Event>(e_.data(), n_);
  }
  [[nodiscard]] constexpr std::size_t lost() const noexcept { return lost_; }

private:
  std::array<Event, N> e_{};
  std::size_t n_ = 0;
  std::size_t lost_ = 0;
};

} // namespace fieldcodec::canopen::node
