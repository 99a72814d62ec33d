// fieldcodec — host adapter: the PA-CONTROL RS232 command interface (manual 001, chapter 3) on
// a serial port: send a request (or the EOT poll) and read the acknowledgement through the
// byte-at-a-time decoder (pacontrol/serial_decoder.hpp), with a timeout.
//
//   host::pacontrol_link link;
//   if (!link.open("/dev/ttyS0")) die(link.last_error().what);   // 9600 7N1 (manual 3.1)
//   auto req = pacontrol::make_request(pacontrol::commands::cmd_read_register, 12).value();
//   auto ack = link.transact(req, std::chrono::milliseconds(1000));
#pragma once

#include <fieldcodec/host/serial_port.hpp>

#ifdef FIELDCODEC_HAS_TERMIOS

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/deadline.hpp>
#include <fieldcodec/host/quoted_bytes.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::host {

/// The PA-CONTROL COM1 default (manual 001, 3.1): 9600 baud, 7 data bits, no parity, 1 stop
/// bit. Other formats are set on the control's switches S2/S3 (3.2.1; the "CTS active" ones set
/// rts_cts): pass them instead.
inline constexpr line_settings pacontrol_line{9600, 7, parity::none, 1, false};

/// How the link writes requests and checks acknowledgements.
struct pacontrol_options {
  pacontrol::serial::check_rule request_rule = pacontrol::serial::check_rule::body;
  pacontrol::serial::check_mode request_check = pacontrol::serial::check_mode::computed;
  pacontrol::serial::check_options check{}; ///< acknowledgement check (decoder)
};

class pacontrol_link {
public:
  /// Open `path` with the line settings of the control (default: the manual's 9600 7N1).
  /// Errors: those of serial_port::open.
  status open(std::string_view path, const line_settings &line = pacontrol_line,
              pacontrol_options o = {}) {
    options_ = o;
    if (auto s = port_.open(path, line); !s) return keep_port_error();
    return {};
  }
  /// The same on an open descriptor (a pseudo-terminal in tests); the link closes it.
  status adopt(int fd, std::string_view name, const line_settings &line = pacontrol_line,
               pacontrol_options o = {}) {
    options_ = o;
    if (auto s = port_.adopt(fd, name, line); !s) return keep_port_error();
    return {};
  }

  /// Send `r` and wait at most `timeout` for the acknowledgement. Input received before the
  /// request is dropped; bytes before the acknowledgement's SOH (line noise) are skipped and
  /// kept in received(). Errors: those of pacontrol::serial::encode_request; timeout (no
  /// complete acknowledgement in time); the decoder's errors for a broken answer (bad_checksum,
  /// bad_syntax, truncated, …; last_error() quotes the bytes); bad_state (port failure).
  result<pacontrol::serial::acknowledgement> transact(const pacontrol::serial::request &r,
                                                      std::chrono::milliseconds timeout) {
    std::array<std::uint8_t, pacontrol::serial::max_frame_size> out{};
    auto n =
        pacontrol::serial::encode_request(r, out, options_.request_rule, options_.request_check);
    if (!n) return fail(n.error(), "request cannot be encoded");
    return exchange(std::span<const std::uint8_t>(out.data(), n.value()), timeout);
  }

  /// Send the poll (EOT) and wait for the acknowledgement. Errors: as transact.
  result<pacontrol::serial::acknowledgement> poll(std::chrono::milliseconds timeout) {
    const std::uint8_t eot = pacontrol::serial::eot;
    return exchange(std::span<const std::uint8_t>(&eot, 1), timeout);
  }

  /// The bytes sent by the last transact/poll and those received for it.
  [[nodiscard]] std::span<const std::uint8_t> sent() const noexcept { return sent_; }
  [[nodiscard]] std::span<const std::uint8_t> received() const noexcept { return received_; }
  [[nodiscard]] const bus_error &last_error() const noexcept { return error_; }
  [[nodiscard]] serial_port &port() noexcept { return port_; }

private:
  result<pacontrol::serial::acknowledgement> exchange(std::span<const std::uint8_t> request,
                                                      std::chrono::milliseconds timeout) {
    sent_.assign(request.begin(), request.end());
    received_.clear();
    port_.discard_input();
    if (auto s = port_.write(request); !s) return keep_port_error();
    pacontrol::serial::decoder dec({options_.check, pacontrol::serial::accept::acknowledgements});
    const auto end = std::chrono::steady_clock::now() + timeout;
    std::array<std::uint8_t, 64> buf{};
    bool in_frame = false; ///< an SOH arrived: errors from here on are a broken answer
    for (;;) {
      auto got = port_.read(buf, time_left(end));
      if (!got) {
        if (got.error() == errc::timeout) {
          return fail(errc::timeout,
                      received_.empty() ? "no acknowledgement in time"
                                        : "acknowledgement incomplete: " + quoted_bytes(received_));
        }
        return keep_port_error();
      }
      for (std::size_t i = 0; i < got.value(); ++i) {
        received_.push_back(buf[i]);
        if (buf[i] == pacontrol::serial::soh) in_frame = true;
        auto k = dec.push(buf[i]);
        if (!k) {
          // bytes before the acknowledgement's SOH are line noise: skipped, as decode does
          if (!in_frame) continue;
          return fail(k.error(), "bad acknowledgement (" + std::string(to_string(k.error())) +
                                     "): " + quoted_bytes(received_));
        }
        if (k.value() == pacontrol::serial::frame_kind::acknowledgement) {
          return dec.acknowledgement();
        }
      }
    }
  }

  errc fail(errc code, const std::string &what) {
    error_.code = code;
    error_.sys_errno = 0;
    error_.from_error_frame = false;
    error_.what = std::string(port_.name()) + ": " + what;
    return code;
  }
  errc keep_port_error() {
    error_ = port_.last_error();
    return error_.code;
  }

  serial_port port_;
  pacontrol_options options_{};
  std::vector<std::uint8_t> sent_, received_;
  bus_error error_{};
};

} // namespace fieldcodec::host

#endif // FIELDCODEC_HAS_TERMIOS
