// fieldcodec — host adapter: slcan (the LAWICEL CAN232/CANUSB ASCII protocol that cheap USB–CAN
// adapters speak) over a serial line: the line codec, and a host::can_bus on a serial port.
//
//   host::slcan_bus bus;
//   if (!bus.open("/dev/ttyACM0", 500000)) die(bus.last_error().what);   // C, S6, O
//   bus.send(frame);                                                      // t60582B00…\r
//   auto r = bus.receive(std::chrono::milliseconds(500));
//
// Lines end with CR. Host → adapter: "Sn" bit rate (S0 10k, S1 20k, S2 50k, S3 100k, S4 125k,
// S5 250k, S6 500k, S7 800k, S8 1M), "O" open, "C" close, "tiiildd…" base frame,
// "Tiiiiiiiildd…" extended frame, "riiil" / "Riiiiiiiil" remote frames. Adapter → host: CR
// (OK) or BEL (error) after each command, "z"/"Z" after a transmitted frame, received frames in
// the same notation (optionally followed by a 4-digit millisecond timestamp, which is read and
// dropped: the bus stamps frames with the host clock). The codec is pure; the bus does I/O.
#pragma once

#include <fieldcodec/host/serial_port.hpp>

#ifdef FIELDCODEC_HAS_TERMIOS

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/deadline.hpp>
#include <fieldcodec/host/frame_record.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace fieldcodec::host::slcan {

inline constexpr char cr = '\r';  ///< ends every line; alone: "OK"
inline constexpr char bel = '\a'; ///< the adapter's "error" answer

/// The "Sn" command of a bit rate in bit/s. Errors: invalid_argument (not one of 10k, 20k, 50k,
/// 100k, 125k, 250k, 500k, 800k, 1M).
[[nodiscard]] constexpr result<char> bitrate_code(std::uint32_t bitrate) noexcept {
  switch (bitrate) {
  case 10'000: return '0';
  case 20'000: return '1';
  case 50'000: return '2';
  case 100'000: return '3';
  case 125'000: return '4';
  case 250'000: return '5';
  case 500'000: return '6';
  case 800'000: return '7';
  case 1'000'000: return '8';
  default: return errc::invalid_argument;
  }
}

/// The text of one line (at most "T" + 8 + 1 + 16 digits + CR).
struct line_text {
  std::array<char, 32> text{};
  std::size_t size = 0;
  [[nodiscard]] constexpr std::string_view view() const noexcept { return {text.data(), size}; }
};

/// The line for a frame, with its CR: "t60582B00180564000000\r" / "r7051\r".
/// Errors: invalid_argument (id above 7FF), bad_length (dlc above 8).
[[nodiscard]] constexpr result<line_text> encode(const canopen::can_frame &f) noexcept {
  if (f.id > canopen::max_can_id) return errc::invalid_argument;
  if (f.dlc > canopen::max_dlc) return errc::bad_length;
  constexpr char digits[] = "0123456789ABCDEF";
  line_text out;
  auto put = [&out](char c) { out.text[out.size++] = c; };
  put(f.rtr ? 'r' : 't');
  for (int i = 2; i >= 0; --i) put(digits[(f.id >> (4 * i)) & 0xFU]);
  put(static_cast<char>('0' + f.dlc));
  if (!f.rtr) {
    for (std::size_t i = 0; i < f.dlc; ++i) {
      put(digits[f.data[i] >> 4U]);
      put(digits[f.data[i] & 0xFU]);
    }
  }
  put(cr);
  return out;
}

/// What one line from an adapter is.
enum class line_kind : std::uint8_t {
  frame,       ///< a received frame (t, T, r, R)
  ok,          ///< an empty line: the answer CR to a command
  transmitted, ///< "z" / "Z": a frame was put on the bus
  status,      ///< "Fxx": status flags (see status_flags)
  other,       ///< version "Vxxxx", serial number "Nxxxx", a command echoed by a peer ("O", "S6")
};

/// One decoded line.
struct line {
  line_kind kind = line_kind::other;
  frame_record record{};   ///< kind == frame
  std::uint8_t status = 0; ///< kind == status: the flag byte
};

/// Status flags ("F" answer): bit 2 error warning, bit 5 error passive, bit 7 bus error.
namespace status_flags {
inline constexpr std::uint8_t rx_full = 0x01U;
inline constexpr std::uint8_t tx_full = 0x02U;
inline constexpr std::uint8_t error_warning = 0x04U;
inline constexpr std::uint8_t data_overrun = 0x08U;
inline constexpr std::uint8_t error_passive = 0x20U;
inline constexpr std::uint8_t arbitration_lost = 0x40U;
inline constexpr std::uint8_t bus_error = 0x80U;
} // namespace status_flags

namespace detail {
/// A field of at most 8 hex digits (core/ascii's parser). Errors: bad_digit.
[[nodiscard]] constexpr result<std::uint32_t> hex_field(std::string_view s) noexcept {
  FIELDCODEC_TRY(const std::uint64_t v, ascii::parse_hex(s));
  return static_cast<std::uint32_t>(v);
}
} // namespace detail

/// Decode one line (without its CR). Errors: truncated (a frame line too short for its DLC),
/// bad_digit, bad_length (DLC above 8, or characters after the data that are not a 4-digit
/// timestamp), invalid_argument (a base identifier above 7FF).
[[nodiscard]] constexpr result<line> decode(std::string_view s) noexcept {
  line out;
  if (s.empty()) {
    out.kind = line_kind::ok;
    return out;
  }
  const char c = s.front();
  if ((c == 'z' || c == 'Z') && s.size() == 1U) {
    out.kind = line_kind::transmitted;
    return out;
  }
  if (c == 'F' && s.size() == 3U) {
    auto v = detail::hex_field(s.substr(1));
    if (!v) return v.error();
    out.kind = line_kind::status;
    out.status = static_cast<std::uint8_t>(v.value());
    return out;
  }
  if (c != 't' && c != 'T' && c != 'r' && c != 'R') return out; // other
  const bool extended = c == 'T' || c == 'R';
  const std::size_t id_len = extended ? 8U : 3U;
  if (s.size() < 1U + id_len + 1U) return errc::truncated;
  auto id = detail::hex_field(s.substr(1, id_len));
  if (!id) return id.error();
  const char d = s[1U + id_len];
  if (d < '0' || d > '9') return errc::bad_digit;
  if (d > '8') return errc::bad_length;
  frame_record &r = out.record;
  out.kind = line_kind::frame;
  r.extended = extended;
  r.rtr = c == 'r' || c == 'R';
  r.id = id.value();
  if (extended) {
    if (r.id > 0x1FFFFFFFU) return errc::invalid_argument;
  } else if (r.id > 0x7FFU) {
    return errc::invalid_argument;
  }
  r.dlc = static_cast<std::uint8_t>(d - '0');
  std::string_view rest = s.substr(2U + id_len);
  if (!r.rtr) {
    if (rest.size() < 2U * r.dlc) return errc::truncated;
    for (std::size_t i = 0; i < r.dlc; ++i) {
      auto b = detail::hex_field(rest.substr(2U * i, 2));
      if (!b) return b.error();
      r.data[i] = static_cast<std::uint8_t>(b.value());
    }
    rest.remove_prefix(2U * r.dlc);
  }
  if (rest.empty()) return out;
  if (rest.size() != 4U) return errc::bad_length;
  auto t = detail::hex_field(rest);
  if (!t) return t.error();
  return out;
}

} // namespace fieldcodec::host::slcan

namespace fieldcodec::host {

/// Options of slcan_bus::open.
struct slcan_options {
  line_settings line = slcan_line;
  /// Wait for the adapter's CR after each command (C, Sn, O) and fail on BEL or silence. Off
  /// for a peer that does not answer commands (another slcan host on a null-modem line or a
  /// pseudo-terminal, e.g. python-can's slcan interface).
  bool check_answers = true;
  std::chrono::milliseconds answer_timeout{500};
  /// The interface name received records carry (a candump log needs one): "slcan0", what
  /// can-utils' slcand calls the first adapter.
  interface_name iface = interface_name::make("slcan0").value();
};

/// An slcan adapter on a serial port as a CAN bus.
class slcan_bus final : public can_bus {
public:
  slcan_bus() = default;
  ~slcan_bus() override { close(); }

  /// Open the serial port `path`, set the bit rate and open the CAN channel ("C", "Sn", "O").
  /// Errors: invalid_argument (bit rate, no such port), those of serial_port::open; bad_state
  /// (the adapter answered BEL), timeout (no answer; see slcan_options::check_answers).
  status open(std::string_view path, std::uint32_t bitrate, slcan_options o = {}) {
    close();
    name_ = std::string(path);
    auto code = slcan::bitrate_code(bitrate);
    if (!code)
      return fail(errc::invalid_argument, 0, "no slcan bit rate " + std::to_string(bitrate));
    if (auto s = port_.open(path, o.line); !s) return fail_port();
    iface_ = o.iface;
    return start(code.value(), o);
  }

  /// The same on an open descriptor (a pseudo-terminal in tests); the bus closes it.
  status adopt(int fd, std::string_view name, std::uint32_t bitrate, slcan_options o = {}) {
    close();
    name_ = std::string(name);
    auto code = slcan::bitrate_code(bitrate);
    if (!code)
      return fail(errc::invalid_argument, 0, "no slcan bit rate " + std::to_string(bitrate));
    if (auto s = port_.adopt(fd, name, o.line); !s) return fail_port();
    iface_ = o.iface;
    return start(code.value(), o);
  }

  status send(const canopen::can_frame &f) override {
    if (!port_.is_open()) return fail(errc::bad_state, 0, "not open");
    auto line = slcan::encode(f);
    if (!line) return fail(line.error(), 0, "not a CAN frame");
    if (auto s = port_.write(line.value().view()); !s) return fail_port();
    return {};
  }

  result<frame_record> receive_record(std::chrono::milliseconds timeout) override {
    if (!port_.is_open()) return fail(errc::bad_state, 0, "not open");
    const auto end = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      std::string l;
      if (auto got = next_line(end, l); !got) return got.error();
      auto d = slcan::decode(l);
      if (!d) return fail(d.error(), 0, "bad line from the adapter: " + printable(l));
      if (d.value().kind != slcan::line_kind::frame) continue;
      frame_record r = d.value().record;
      r.iface = iface_;
      const auto now = std::chrono::system_clock::now().time_since_epoch();
      r.time = timestamp::from_microseconds(
          std::chrono::duration_cast<std::chrono::microseconds>(now).count());
      return r;
    }
  }

  /// Close the CAN channel ("C") and the port.
  void close() noexcept {
    if (port_.is_open()) {
      (void)port_.write(std::string_view("C\r"), std::chrono::milliseconds(100));
    }
    port_.close();
    buffer_.clear();
  }
  [[nodiscard]] bool is_open() const noexcept { return port_.is_open(); }
  [[nodiscard]] int native_handle() const noexcept { return port_.native_handle(); }

private:
  status start(char code, const slcan_options &o) {
    // Empty lines first: ends whatever a previous user left half-typed in the adapter.
    if (auto s = port_.write(std::string_view("\r\r\r")); !s) return fail_port();
    if (o.check_answers) drain(o.answer_timeout);
    const std::string commands[] = {"C", std::string("S") + code, "O"};
    for (const std::string &c : commands) {
      if (auto s = port_.write(std::string_view(c + "\r")); !s) return fail_port();
      if (!o.check_answers) continue;
      if (auto s = expect_answer(c, o.answer_timeout); !s && c != "C") return s;
    }
    return {};
  }

  /// Reads the answer to a command: CR is fine, BEL is a refusal.
  status expect_answer(const std::string &command, std::chrono::milliseconds timeout) {
    const auto end = std::chrono::steady_clock::now() + timeout;
    std::uint8_t b = 0;
    for (;;) {
      auto n = port_.read(std::span<std::uint8_t>(&b, 1), time_left(end));
      if (!n) {
        if (n.error() == errc::timeout) {
          return fail(errc::timeout, 0, "no answer to '" + command + "' (is it an slcan adapter?)");
        }
        return fail_port();
      }
      if (b == static_cast<std::uint8_t>(slcan::cr)) return {};
      if (b == static_cast<std::uint8_t>(slcan::bel)) {
        return fail(errc::bad_state, 0, "the adapter refused '" + command + "'");
      }
    }
  }

  void drain(std::chrono::milliseconds timeout) {
    std::array<std::uint8_t, 64> tmp{};
    const auto end = std::chrono::steady_clock::now() + timeout / 4;
    while (std::chrono::steady_clock::now() < end) {
      if (!port_.read(tmp, std::chrono::milliseconds(20))) break;
    }
    buffer_.clear();
  }

  /// The next line (CR or LF ends it; BEL is a line of its own: an error from the adapter).
  status next_line(std::chrono::steady_clock::time_point end, std::string &line) {
    for (;;) {
      for (std::size_t i = 0; i < buffer_.size(); ++i) {
        const char c = buffer_[i];
        if (c == slcan::bel) {
          buffer_.erase(0, i + 1U);
          return fail(errc::bad_state, 0, "the adapter refused a command or frame (BEL)");
        }
        if (c == '\r' || c == '\n') {
          line = buffer_.substr(0, i);
          buffer_.erase(0, i + 1U);
          if (line.empty() && c == '\n') break; // the LF of a CR LF pair
          return {};
        }
      }
      if (buffer_.size() > 64U) {
        const std::string junk = buffer_;
        buffer_.clear();
        return fail(errc::too_long, 0, "line too long from the adapter: " + printable(junk));
      }
      std::array<std::uint8_t, 256> tmp{};
      auto n = port_.read(tmp, time_left(end));
      if (!n) {
        if (n.error() == errc::timeout) return fail(errc::timeout, 0, "no frame in time");
        return fail_port();
      }
      buffer_.append(reinterpret_cast<const char *>(tmp.data()), n.value());
    }
  }

  static std::string printable(std::string_view s) {
    std::string out;
    for (const char c : s) {
      const auto u = static_cast<unsigned char>(c);
      if (u >= 0x20U && u < 0x7FU) {
        out += c;
      } else {
        static constexpr char digits[] = "0123456789ABCDEF";
        out += "\\x";
        out += digits[u >> 4U];
        out += digits[u & 0xFU];
      }
    }
    return out;
  }

  errc fail(errc code, int sys_errno, const std::string &what) {
    return can_bus::fail(code, sys_errno, what);
  }
  /// The port's failure (its text already names the port).
  errc fail_port() { return can_bus::fail(port_.last_error()); }

  serial_port port_;
  interface_name iface_ = interface_name::make("slcan0").value();
  std::string buffer_;
};

} // namespace fieldcodec::host

#endif // FIELDCODEC_HAS_TERMIOS
