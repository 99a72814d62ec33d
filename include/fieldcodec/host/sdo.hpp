// fieldcodec — host adapters: blocking SDO reads and writes on a host::can_bus, on top of the
// non-blocking canopen::sdo::client machine.
//
//   host::socketcan_bus bus;  bus.open("can0");
//   auto v = host::sdo_read(bus, 5, {0x1018, 1}, 500ms);  // result<vector<uint8_t>, sdo_error>
//   if (!v) print(v.error().what);   // "node 5, 1018h:01: SDO abort 06020000h: object not in
//                                    //  the object dictionary"
//   host::sdo_write(bus, 5, {0x6040, 0}, bytes, 500ms);  // result<void, sdo_error>
//
//   host::sdo_session node5(bus, 5);                      // several transfers, options, one
//   auto w = node5.read({0x1008, 0});                      // buffer: result<span, sdo_error>
//
//   node5.read_parts({0x2000, 0}, [](std::span<const std::uint8_t> part) { ...; return true; });
//   node5.write_parts({0x2000, 0}, size, [](std::span<std::uint8_t> out) { ...; return n; });
//                                                         // a large DOMAIN in parts
//
// The session owns the buffer of its uploads (sdo_options::max_size bytes); frames that are not
// its SDO responses are ignored while it waits (a busy bus is fine), error frames are ignored
// unless the controller went bus-off.
#pragma once

#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/host/bus.hpp>
#include <fieldcodec/host/clock.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/engineering.hpp>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fieldcodec::host {

/// Options of a blocking SDO session.
struct sdo_options {
  std::chrono::milliseconds timeout{1000}; ///< SDO timeout: the longest wait for one answer
  bool block = false;                      ///< use block transfer (upload and download)
  canopen::sdo::block_options block_options{};
  std::size_t max_size = 1U << 20U; ///< largest value an upload takes (bytes)
  /// read_parts / write_parts: the bytes of one part (at least 7); the session holds one buffer
  /// of this size, made once.
  std::size_t part_size = 4096;
};

/// Why a blocking transfer failed: an error with context (docs/contributing.md, "Errors").
struct sdo_error {
  /// aborted: the server aborted with `abort`; bad_state with bus_failed: the bus failed (see
  /// `what`); otherwise the client found the problem (timeout, bad_toggle, buffer_too_small, …)
  /// and sent `abort`; invalid_argument: the transfer could not start (node-ID not 1..127).
  errc code = errc::aborted;
  canopen::sdo::abort_code abort = canopen::sdo::abort_code::none;
  od::address address{};
  bool bus_failed = false;
  /// A value refused before any frame (host::remote_node): issue != none, code == value.code.
  od::value_error value{};
  std::string what; ///< one line naming node, object, abort code and its text
  sdo_error() = default;
  sdo_error(errc e) : code(e) {} // NOLINT: plain errors propagate into it
};

/// "1018h:01".
[[nodiscard]] inline std::string format_address(od::address a) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04Xh:%02X", static_cast<unsigned>(a.index),
                static_cast<unsigned>(a.sub));
  return buf;
}

/// "SDO abort 06020000h: object not in the object dictionary" (a code CiA 301 does not define:
/// "SDO abort 12345678h (not a CiA 301 code)").
[[nodiscard]] inline std::string describe_abort(canopen::sdo::abort_code code) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "SDO abort %08Xh", static_cast<unsigned>(code));
  const std::string_view text = canopen::sdo::to_string(code);
  return std::string(buf) +
         (text.empty() ? std::string(" (not a CiA 301 code)") : ": " + std::string(text));
}

class sdo_session {
public:
  /// A session with the SDO server of `node` on the predefined channel (0x600/0x580 + node).
  sdo_session(can_bus &bus, std::uint8_t node, sdo_options o = {})
      : bus_(&bus), node_(node), options_(o),
        client_(node, static_cast<std::uint32_t>(o.timeout.count())) {
    if (options_.part_size < 7U) options_.part_size = 7U;
  }

  /// Read `a`. The bytes stay valid until the next call. Errors (sdo_error::code): aborted,
  /// timeout, buffer_too_small, bad_toggle, unexpected_frame, …; invalid_argument for a
  /// node-ID outside 1..127; bad_state when the bus failed. last_error() keeps the same.
  result<std::span<const std::uint8_t>, sdo_error> read(od::address a) {
    buffer_.resize(options_.max_size);
    const std::uint32_t t0 = now();
    auto s = options_.block ? client_.block_upload(a, buffer_, t0, options_.block_options)
                            : client_.upload(a, buffer_, t0);
    if (!run(a, s)) return error_;
    return client_.received();
  }

  /// Write `data` to `a`. Errors: as read.
  result<void, sdo_error> write(od::address a, std::span<const std::uint8_t> data) {
    const std::uint32_t t0 = now();
    auto s = options_.block ? client_.block_download(a, data, t0, options_.block_options)
                            : client_.download(a, data, t0);
    if (!run(a, s)) return error_;
    return {};
  }

  /// Read `a` in parts (a large DOMAIN): `sink(std::span<const std::uint8_t>)` gets each part
  /// in order, at most options().part_size bytes, from one buffer the session keeps (valid
  /// during the call); returning false stops the transfer (SDO abort 08000000h, error
  /// aborted). Segmented (or expedited) whatever options().block says. Returns the bytes read.
  /// Errors: those of read; nothing is kept beyond one part.
  template <class Sink>
  result<std::size_t, sdo_error> read_parts(od::address a, Sink &&sink) {
    part_.resize(options_.part_size); // once: the size does not change
    std::size_t total = 0;
    bool stopped = false;
    auto give = [&]() -> bool {
      const auto p = client_.received();
      total += p.size();
      if (p.empty() || sink(p)) return true;
      stopped = true;
      return false;
    };
    const auto started = client_.upload_parts(a, part_, now());
    const bool ok = run(a, started, [&]() -> result<canopen::sdo::step> {
      if (!give()) return client_.cancel(canopen::sdo::abort_code::general_error);
      return client_.next_part(now());
    });
    if (stopped) return stopped_by_caller(a);
    if (!ok) return error_;
    if (!give()) return stopped_by_caller(a);
    return total;
  }

  /// Write `size` bytes to `a` in parts: `source(std::span<std::uint8_t> out)` fills `out`
  /// (at most options().part_size bytes) with the next bytes and returns how many it wrote;
  /// the session keeps one buffer. Segmented (expedited for 1..4 bytes). Errors: bad_length (the
  /// source gave fewer than `size` bytes: the transfer is aborted), those of write.
  template <class Source>
  result<void, sdo_error> write_parts(od::address a, std::uint32_t size, Source &&source) {
    part_.resize(options_.part_size);
    std::size_t given = 0; // bytes the source gave
    std::size_t held = 0;  // of them, in part_
    auto fill = [&]() {
      while (held < part_.size() && given < size) {
        const std::size_t want = std::min(part_.size() - held, std::size_t{size} - given);
        const std::size_t n = source(std::span<std::uint8_t>(part_).subspan(held, want));
        if (n == 0U || n > want) return;
        held += n;
        given += n;
      }
    };
    fill();
    if (given < size && held < part_.size()) return short_source(a, given, size);
    const auto started = client_.download_parts(a, size, std::span(part_).first(held), now());
    bool short_part = false;
    const bool ok = run(a, started, [&]() -> result<canopen::sdo::step> {
      // the bytes not yet sent move to the front, the source fills the rest
      const std::size_t sent = client_.transferred() - (given - held);
      std::copy(part_.begin() + static_cast<std::ptrdiff_t>(sent),
                part_.begin() + static_cast<std::ptrdiff_t>(held), part_.begin());
      held -= sent;
      fill();
      auto s = client_.feed(std::span(part_).first(held), now());
      if (!s) {
        short_part = true;
        return client_.cancel(canopen::sdo::abort_code::general_error);
      }
      return s;
    });
    if (short_part) return short_source(a, given, size);
    if (!ok) return error_;
    return {};
  }

  [[nodiscard]] const sdo_error &last_error() const noexcept { return error_; }
  [[nodiscard]] std::uint8_t node() const noexcept { return node_; }
  /// Show every frame received while a transfer waits to `f` first (with the session's clock),
  /// so that what else the bus carries (a node's EMCY, heartbeat, PDOs: host::remote_node) is
  /// not lost while the session blocks. Empty: those frames are ignored.
  void observe(std::function<void(const canopen::can_frame &, std::uint32_t)> f) {
    observer_ = std::move(f);
  }
  /// The session's milliseconds (the `now` its machine and observer are given).
  [[nodiscard]] std::uint32_t now() const noexcept { return clock_.now(); }
  [[nodiscard]] const sdo_options &options() const noexcept { return options_; }

private:
  bool send_all(const canopen::sdo::step &s) {
    for (const canopen::can_frame &f : s.send) {
      if (!bus_->send(f)) return false;
    }
    return true;
  }

  sdo_error stopped_by_caller(od::address a) {
    error_ = {};
    error_.code = errc::aborted;
    error_.abort = canopen::sdo::abort_code::general_error;
    error_.address = a;
    error_.what = prefix(a) + "stopped by the caller (sent " +
                  describe_abort(canopen::sdo::abort_code::general_error) + ")";
    return error_;
  }
  sdo_error short_source(od::address a, std::size_t given, std::uint32_t size) {
    error_ = {};
    error_.code = errc::bad_length;
    error_.address = a;
    error_.what = prefix(a) + "the source gave " + std::to_string(given) + " of " +
                  std::to_string(size) + " bytes";
    return error_;
  }

  /// Runs the transfer; false when it failed (error_ says why).
  bool run(od::address a, const result<canopen::sdo::step> &started) {
    return run(a, started, []() -> result<canopen::sdo::step> { return errc::bad_state; });
  }
  /// The same, with `on_part()` called whenever a part transfer pauses (its step goes on).
  template <class OnPart>
  bool run(od::address a, const result<canopen::sdo::step> &started, OnPart on_part) {
    error_ = {};
    if (!started) return fail_local(a, started.error(), "cannot start the transfer");
    canopen::sdo::step s = started.value();
    for (;;) {
      if (!send_all(s)) return fail_bus(a);
      if (!client_.busy()) break;
      if (client_.part_ready()) {
        auto n = on_part();
        if (!n) return fail_local(a, n.error(), "cannot go on with the next part");
        s = n.value();
        continue;
      }
      const std::uint32_t t = now();
      std::int64_t wait = options_.timeout.count();
      if (s.deadline) {
        wait = static_cast<std::int32_t>(*s.deadline - t);
        if (wait < 0) wait = 0;
      }
      auto r = bus_->receive(std::chrono::milliseconds(wait));
      if (r) {
        if (observer_) observer_(r.value().frame, now());
        s = client_.on_frame(r.value().frame, now());
        continue;
      }
      if (r.error() == errc::timeout) {
        s = client_.poll(now());
        continue;
      }
      const bus_error &be = bus_->last_error();
      if (be.from_error_frame && !be.frame.is_bus_off()) {
        s = client_.poll(now()); // a warning: keep going, the SDO timeout still runs
        continue;
      }
      (void)client_.cancel(); // nothing more can be sent or received
      return fail_bus(a);
    }
    if (client_.state() == canopen::sdo::transfer_state::done) return true;
    const auto e = client_.error().value_or(canopen::sdo::transfer_error{});
    error_.code = e.code;
    error_.abort = e.abort;
    error_.address = a;
    error_.what = prefix(a);
    if (e.code == errc::aborted) {
      error_.what += describe_abort(e.abort);
    } else {
      error_.what += std::string(to_string(e.code));
      if (e.abort != canopen::sdo::abort_code::none) {
        error_.what += " (sent " + describe_abort(e.abort) + ")";
      }
    }
    return false;
  }

  std::string prefix(od::address a) const {
    return "node " + std::to_string(node_) + ", " + format_address(a) + ": ";
  }
  bool fail_local(od::address a, errc e, std::string_view what) {
    error_.code = e;
    error_.address = a;
    error_.what = prefix(a) + std::string(what) + ": " + std::string(to_string(e));
    return false;
  }
  bool fail_bus(od::address a) {
    error_.code = errc::bad_state;
    error_.address = a;
    error_.bus_failed = true;
    error_.what = prefix(a) + bus_->last_error().what;
    return false;
  }

  can_bus *bus_;
  std::uint8_t node_;
  sdo_options options_;
  canopen::sdo::client client_;
  std::vector<std::uint8_t> buffer_;
  std::vector<std::uint8_t> part_; ///< read_parts / write_parts: one part
  sdo_error error_{};
  steady_ms clock_;
  std::function<void(const canopen::can_frame &, std::uint32_t)> observer_{};
};

/// Read `a` of `node`: its bytes, or why not (sdo_error: code, abort code, address, one line).
/// Errors: those of sdo_session::read.
inline result<std::vector<std::uint8_t>, sdo_error>
sdo_read(can_bus &bus, std::uint8_t node, od::address a,
         std::chrono::milliseconds timeout = std::chrono::milliseconds(1000)) {
  sdo_options o;
  o.timeout = timeout;
  sdo_session s(bus, node, o);
  auto r = s.read(a);
  if (!r) return r.error();
  return std::vector<std::uint8_t>(r.value().begin(), r.value().end());
}

/// Write `data` to `a` of `node`. Errors: those of sdo_session::write.
inline result<void, sdo_error>
sdo_write(can_bus &bus, std::uint8_t node, od::address a, std::span<const std::uint8_t> data,
          std::chrono::milliseconds timeout = std::chrono::milliseconds(1000)) {
  sdo_options o;
  o.timeout = timeout;
  sdo_session s(bus, node, o);
  return s.write(a, data);
}

} // namespace fieldcodec::host
