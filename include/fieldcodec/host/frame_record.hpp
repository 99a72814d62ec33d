// fieldcodec — host adapters: one received or logged CAN frame with its time and interface, as
// SocketCAN, slcan adapters and candump logs carry it (base, extended, remote and error frames),
// and the meaning of an error frame.
//
// host/ is the only place of fieldcodec that knows an operating system (docs/cli.md, "Host
// adapters"). A record is wider than canopen::can_frame: it also holds what a CANopen codec
// must not see (29-bit identifiers, controller error frames), so that a monitor or a log reader
// can show them; to_canopen() turns a record into a can_frame or says why it is not one.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace fieldcodec::host {

/// A point in time as seconds and a decimal fraction with its number of digits, so that a log's
/// timestamp is written back exactly as it was read ("1700000000.123456": 1700000000, 123456,
/// 6 digits). digits == 0: no time known.
struct timestamp {
  std::int64_t seconds = 0;
  std::uint32_t fraction = 0;
  std::uint8_t digits = 0; ///< 0 (no time) or 1..9
  /// A wall-clock reading "2024-05-01 12:34:56.123456" (candump -tA, local time): `seconds`
  /// counts from 1970-01-01 00:00 of that reading, no time zone applied; written back as a date.
  bool date = false;

  [[nodiscard]] constexpr bool known() const noexcept { return digits != 0U; }
  /// Microseconds since the epoch (digits beyond 6 are cut).
  [[nodiscard]] constexpr std::int64_t microseconds() const noexcept {
    std::int64_t f = fraction;
    for (unsigned d = digits; d < 6U; ++d) f *= 10;
    for (unsigned d = digits; d > 6U; --d) f /= 10;
    return seconds * 1'000'000 + f;
  }
  /// A time of microsecond resolution (6 digits).
  [[nodiscard]] static constexpr timestamp from_microseconds(std::int64_t us) noexcept {
    return {us / 1'000'000, static_cast<std::uint32_t>(us % 1'000'000), 6};
  }
  friend constexpr bool operator==(const timestamp &, const timestamp &) noexcept = default;
};

/// A network interface name ("can0", "vcan0"): at most 15 characters, as Linux allows.
class interface_name {
public:
  static constexpr std::size_t capacity = 15;
  constexpr interface_name() noexcept = default;
  /// Errors: too_long (more than 15 characters), bad_character (a blank, '/', a control
  /// character or one outside ASCII).
  [[nodiscard]] static constexpr result<interface_name> make(std::string_view s) noexcept {
    if (s.size() > capacity) return errc::too_long;
    interface_name n;
    for (const char c : s) {
      const auto u = static_cast<unsigned char>(c);
      if (u <= 0x20U || u >= 0x7FU || c == '/') return errc::bad_character;
      n.text_[n.size_++] = c;
    }
    return n;
  }
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {text_.data(), size_}; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0U; }
  friend constexpr bool operator==(const interface_name &a, const interface_name &b) noexcept {
    return a.view() == b.view();
  }

private:
  std::array<char, capacity> text_{};
  std::size_t size_ = 0;
};

/// One frame as a bus or a log delivers it.
struct frame_record {
  timestamp time{};       ///< when it was received or logged (time.known() false: not given)
  interface_name iface{}; ///< where (empty: not given)
  std::uint32_t id = 0;   ///< 11 bits, 29 bits when `extended`; error frames: the error class bits
  bool extended = false;  ///< 29-bit identifier
  bool rtr = false;       ///< remote transmission request (dlc = requested length)
  bool error = false;     ///< controller error frame (SocketCAN CAN_ERR_FLAG), see can_error
  std::uint8_t dlc = 0;   ///< 0..8
  std::array<std::uint8_t, 8> data{};

  [[nodiscard]] constexpr std::span<const std::uint8_t> payload() const noexcept {
    return rtr ? std::span<const std::uint8_t>{} : std::span<const std::uint8_t>(data).first(dlc);
  }
  friend constexpr bool operator==(const frame_record &, const frame_record &) noexcept = default;
};

/// A record for a CANopen frame.
[[nodiscard]] constexpr frame_record to_record(const canopen::can_frame &f, timestamp t = {},
                                               interface_name iface = {}) noexcept {
  frame_record r;
  r.time = t;
  r.iface = iface;
  r.id = f.id;
  r.rtr = f.rtr;
  r.dlc = f.dlc;
  if (!f.rtr) r.data = f.data;
  return r;
}

/// The CANopen frame of a record. Errors: unexpected_frame (an error frame or a 29-bit
/// identifier: not CANopen), invalid_argument (identifier above 0x7FF), bad_length (dlc > 8).
[[nodiscard]] constexpr result<canopen::can_frame> to_canopen(const frame_record &r) noexcept {
  if (r.error || r.extended) return errc::unexpected_frame;
  if (r.id > canopen::max_can_id) return errc::invalid_argument;
  if (r.dlc > canopen::max_dlc) return errc::bad_length;
  if (r.rtr) return canopen::make_remote_frame(static_cast<std::uint16_t>(r.id), r.dlc);
  return canopen::make_frame(static_cast<std::uint16_t>(r.id), r.payload());
}

/// What a controller error frame reports (the classes and details of Linux
/// <linux/can/error.h>, whose values these are: candump logs and SocketCAN use them).
struct can_error {
  // error class (the identifier bits of an error frame)
  static constexpr std::uint32_t tx_timeout = 0x001U;
  static constexpr std::uint32_t lost_arbitration = 0x002U;
  static constexpr std::uint32_t controller = 0x004U; ///< details in data[1]
  static constexpr std::uint32_t protocol = 0x008U;   ///< details in data[2], data[3]
  static constexpr std::uint32_t transceiver = 0x010U;
  static constexpr std::uint32_t no_ack = 0x020U;
  static constexpr std::uint32_t bus_off = 0x040U;
  static constexpr std::uint32_t bus_error = 0x080U;
  static constexpr std::uint32_t restarted = 0x100U;
  static constexpr std::uint32_t counters = 0x200U; ///< data[6] tx, data[7] rx error counters
  // controller details (data[1])
  static constexpr std::uint8_t rx_overflow = 0x01U;
  static constexpr std::uint8_t tx_overflow = 0x02U;
  static constexpr std::uint8_t rx_warning = 0x04U;
  static constexpr std::uint8_t tx_warning = 0x08U;
  static constexpr std::uint8_t rx_passive = 0x10U;
  static constexpr std::uint8_t tx_passive = 0x20U;
  static constexpr std::uint8_t active = 0x40U;

  std::uint32_t classes = 0; ///< the bits above
  std::uint8_t controller_state = 0;
  std::uint8_t tx_errors = 0; ///< valid when classes has `counters`
  std::uint8_t rx_errors = 0;

  [[nodiscard]] constexpr bool is_bus_off() const noexcept { return (classes & bus_off) != 0U; }
  [[nodiscard]] constexpr bool is_error_passive() const noexcept {
    return (classes & controller) != 0U && (controller_state & (rx_passive | tx_passive)) != 0U;
  }
  friend constexpr bool operator==(const can_error &, const can_error &) noexcept = default;
};

/// The content of an error frame. Errors: unexpected_frame (not an error frame).
[[nodiscard]] constexpr result<can_error> decode_error(const frame_record &r) noexcept {
  if (!r.error) return errc::unexpected_frame;
  can_error e;
  e.classes = r.id & 0x1FFFFFFFU;
  e.controller_state = r.dlc > 1U ? r.data[1] : std::uint8_t{0};
  if (r.dlc > 7U) {
    e.tx_errors = r.data[6];
    e.rx_errors = r.data[7];
  }
  return e;
}

/// The error frame's meaning in words, most severe first ("bus-off", "error passive (tx)",
/// "no ACK", ..., "tx errors 128, rx errors 0").
[[nodiscard]] inline std::string describe(const can_error &e) {
  std::string out;
  const auto add = [&out](std::string_view s) {
    if (!out.empty()) out += ", ";
    out += s;
  };
  if ((e.classes & can_error::bus_off) != 0U) add("bus-off");
  if ((e.classes & can_error::controller) != 0U) {
    const std::uint8_t c = e.controller_state;
    if ((c & can_error::tx_passive) != 0U) add("error passive (tx)");
    if ((c & can_error::rx_passive) != 0U) add("error passive (rx)");
    if ((c & can_error::tx_warning) != 0U) add("error warning (tx)");
    if ((c & can_error::rx_warning) != 0U) add("error warning (rx)");
    if ((c & can_error::rx_overflow) != 0U) add("rx buffer overflow");
    if ((c & can_error::tx_overflow) != 0U) add("tx buffer overflow");
    if ((c & can_error::active) != 0U) add("back to error active");
    if (c == 0U) add("controller problem");
  }
  if ((e.classes & can_error::restarted) != 0U) add("controller restarted");
  if ((e.classes & can_error::no_ack) != 0U) add("no ACK");
  if ((e.classes & can_error::tx_timeout) != 0U) add("tx timeout");
  if ((e.classes & can_error::lost_arbitration) != 0U) add("lost arbitration");
  if ((e.classes & can_error::protocol) != 0U) add("protocol violation");
  if ((e.classes & can_error::transceiver) != 0U) add("transceiver problem");
  if ((e.classes & can_error::bus_error) != 0U) add("bus error");
  if ((e.classes & can_error::counters) != 0U) {
    add("tx errors " + std::to_string(e.tx_errors) + ", rx errors " + std::to_string(e.rx_errors));
  }
  if (out.empty()) out = "error frame";
  return out;
}

} // namespace fieldcodec::host
