// fieldcodec — the TIME producer and consumer (CiA 301 7.2.6, object 1012h "COB-ID time
// stamp"): bit 31 = the node consumes TIME, bit 30 = it produces TIME, bits 0..10 = the CAN-ID
// (default 100h). The frame is canopen/time_stamp.hpp's (6 bytes: milliseconds after midnight,
// days since 1984-01-01).
//
//   node::time_service t;
//   t.written({0x1012, 0}, 0xC000'0100U, now);       // consume and produce on 100h
//   auto f = t.produce({ms_after_midnight, days});    // the application's time, as a frame
//   if (auto r = t.on_frame(frame)) use(r.value());   // a received TIME
//
// The node has no wall clock: the application gives the time to send (node::device::
// produce_time, e.g. once a second from its RTC or when its clock was set) and learns a
// received one from the device's `time` event. What 1012h takes (check_write; 0x06090030
// otherwise): bit 29 (a 29-bit identifier) and bits 11..28 clear; while the node consumes or
// produces (bit 31 or 30 set) a CAN-ID that is not restricted (CiA 301 7.3.5: 100h itself is
// allowed); another CAN-ID only while neither bit is set in the current value or in the new
// one (clear the bits first, then change the identifier; the same value again is taken, as
// configuration tools write back what they read).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/node/cob_id_rules.hpp>
#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/canopen/time_stamp.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/value.hpp>

#include <cstdint>
#include <optional>

namespace fieldcodec::canopen::node {

class time_service {
public:
  static constexpr std::uint16_t index = 0x1012;
  static constexpr std::uint32_t consume = cob_bits::invalid; ///< bit 31
  static constexpr std::uint32_t produce_bit = cob_bits::bit30;
  /// Milliseconds of a day: a time of day is below it.
  static constexpr std::uint32_t day_ms = 86'400'000U;

  /// Would `v` be accepted for 1012h (see above)? none for every other object.
  [[nodiscard]] constexpr abort_code check_write(od::address a, std::uint32_t v) const noexcept {
    if (a.index != index || a.sub != 0U) return abort_code::none;
    if ((v & cob_bits::frame) != 0U || (v & 0x1FFF'F800U) != 0U) return abort_code::invalid_value;
    const bool active = (v & (consume | produce_bit)) != 0U;
    const auto id = static_cast<std::uint16_t>(v & cob_bits::id);
    if (active && is_restricted_can_id(id)) return abort_code::invalid_value;
    if (active && (value_ & (consume | produce_bit)) != 0U && id != id_) {
      return abort_code::invalid_value;
    }
    return abort_code::none;
  }
  /// `v` was stored at 1012h: follow it.
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t) noexcept {
    if (a.index != index || a.sub != 0U) return;
    value_ = v;
    id_ = static_cast<std::uint16_t>(v & cob_bits::id);
  }
  /// 1012h from `store` (absent: neither consumer nor producer). Errors: invalid_argument (a
  /// stored value check_write refuses, e.g. from a DCF: the node neither consumes nor produces).
  template <class Store>
  constexpr status load(const Store &store, std::uint32_t now) noexcept {
    *this = time_service{};
    const auto v = read_u32(store, {index, 0});
    if (!v) return {};
    if (check_write({index, 0}, *v) != abort_code::none) return errc::invalid_argument;
    written({index, 0}, *v, now);
    return {};
  }

  [[nodiscard]] constexpr bool consumer() const noexcept { return (value_ & consume) != 0U; }
  [[nodiscard]] constexpr bool producer() const noexcept { return (value_ & produce_bit) != 0U; }
  [[nodiscard]] constexpr std::uint16_t cob_id() const noexcept { return id_; }
  /// Is `f` a frame for the consumer (its CAN-ID, not a remote frame, consumer on)?
  [[nodiscard]] constexpr bool takes(const can_frame &f) const noexcept {
    return consumer() && !f.rtr && f.id == id_;
  }

  /// The TIME frame for `t` on 1012h's CAN-ID. Errors: bad_state (1012h bit 30 clear),
  /// out_of_range (t.ms not below a day's 86 400 000 ms).
  [[nodiscard]] constexpr result<can_frame> produce(od::time_value t) const noexcept {
    if (!producer()) return errc::bad_state;
    if (t.ms >= day_ms) return errc::out_of_range;
    FIELDCODEC_TRY(can_frame f, time_stamp::encode(t));
    f.id = id_;
    return f;
  }
  /// A frame takes() accepts: the time it carries, kept as received(). Errors (the frame is
  /// ignored, received() stays, error() says why): bad_length (DLC not 6), out_of_range
  /// (reserved bits 28..31 of the milliseconds set, or a time of day not below 24 h).
  [[nodiscard]] constexpr result<od::time_value> on_frame(const can_frame &f) noexcept {
    can_frame g = f;
    g.id = cob_id::time; // the codec knows the default identifier; 1012h may name another
    auto t = time_stamp::decode(g);
    if (t && t.value().ms >= day_ms) t = errc::out_of_range;
    if (!t) {
      error_ = t.error();
      return t.error();
    }
    error_.reset();
    received_ = t.value();
    return t.value();
  }
  /// The last TIME received (nullopt: none since start or reset).
  [[nodiscard]] constexpr std::optional<od::time_value> received() const noexcept {
    return received_;
  }
  /// Why the last TIME frame was ignored (nullopt: the last one was taken).
  [[nodiscard]] constexpr std::optional<errc> error() const noexcept { return error_; }

private:
  std::optional<od::time_value> received_{};
  std::optional<errc> error_{};
  std::uint32_t value_ = 0;
  std::uint16_t id_ = cob_id::time;
};

} // namespace fieldcodec::canopen::node
