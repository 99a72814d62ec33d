// Benchmarks of pacontrol/ (RS232 request frame encoder, byte-at-a-time stream decoder) against
// hand-written equivalents. Dates are integers (N registers, inputs, parameters).
#include "codec_harness.hpp"

#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

namespace {

namespace pac = fieldcodec::pacontrol;
namespace serial = fieldcodec::pacontrol::serial;

struct req {
  std::uint16_t command = 0;
  std::uint16_t parameter = 0;
  std::int32_t date = 0;
  bool ok = false;
  bool operator==(const req &) const = default;
};

/// A frame as bytes (SOH STX … EOT), at most 40 bytes for an integer request.
struct frame {
  std::array<std::uint8_t, 40> b{};
  std::size_t len = 0;
  bool operator==(const frame &) const = default;
};

bench::inputs<req> g_requests;
bench::inputs<frame> g_frames;

void fill_inputs() {
  bench::rng r(232);
  for (std::size_t i = 0; i < bench::input_count; ++i) {
    auto &q = g_requests[i];
    q.command = static_cast<std::uint16_t>(r.below(0x10000));
    q.parameter = static_cast<std::uint16_t>(r.below(r.below(2) != 0U ? 10 : 0x10000));
    q.date = static_cast<std::int32_t>(
        r.between(r.below(2) != 0U ? -1000 : INT32_MIN, r.below(2) != 0U ? 1000 : INT32_MAX));
    q.ok = true;
    const serial::request s{q.command, q.parameter, pac::value::of_int(q.date).value()};
    g_frames[i].len = serial::encode_request(s, g_frames[i].b).value();
  }
}

/// Hand-written: decimal digits of v at p, returns the new end.
std::uint8_t *put_dec(std::uint8_t *p, std::uint64_t v) {
  char tmp[20];
  std::size_t n = 0;
  do {
    tmp[n++] = static_cast<char>('0' + v % 10U);
    v /= 10U;
  } while (v != 0U);
  while (n > 0U) *p++ = static_cast<std::uint8_t>(tmp[--n]);
  return p;
}

frame hand_encode(const req &q) {
  frame f;
  std::uint8_t *p = f.b.data();
  *p++ = 0x01; // SOH
  *p++ = 0x02; // STX
  std::uint8_t *body = p;
  constexpr char hex[] = "0123456789ABCDEF";
  for (unsigned s = 12;; s -= 4U) {
    *p++ = static_cast<std::uint8_t>(hex[(q.command >> s) & 0xFU]);
    if (s == 0U) break;
  }
  *p++ = ';';
  p = put_dec(p, q.parameter);
  *p++ = ';';
  *p++ = '0'; // integer
  *p++ = ';';
  if (q.date < 0) *p++ = '-';
  p = put_dec(p, q.date < 0 ? 0U - static_cast<std::uint64_t>(static_cast<std::int64_t>(q.date))
                            : static_cast<std::uint64_t>(q.date));
  std::uint8_t check = 0;
  for (const std::uint8_t *c = body; c != p; ++c) check = static_cast<std::uint8_t>(check ^ *c);
  *p++ = 0x03; // ETX
  p = put_dec(p, check);
  *p++ = 0x04; // EOT
  f.len = static_cast<std::size_t>(p - f.b.data());
  return f;
}

/// Hand-written stream decoder for requests: SOH STX CMD;PAR;0;DATE ETX CHECK EOT.
class hand_decoder {
public:
  /// Feeds one byte; true when it completed a valid request (in `out`).
  bool push(std::uint8_t b, req &out) {
    switch (state_) {
    case 0: // idle
      if (b == 0x01U) state_ = 1;
      return false;
    case 1: // after SOH
      if (b != 0x02U) return fail();
      state_ = 2;
      n_ = 0;
      return false;
    case 2: // body
      if (b == 0x03U) {
        state_ = 3;
        check_ = 0;
        check_digits_ = 0;
        return false;
      }
      if (b < 0x20U || b >= 0x7FU || n_ == body_.size()) return fail();
      body_[n_++] = b;
      return false;
    default: // check
      if (b == 0x04U) {
        state_ = 0;
        return check_digits_ != 0U && finish(out);
      }
      if (b < '0' || b > '9' || check_digits_ == 3U) return fail();
      check_ = check_ * 10U + (b - '0');
      ++check_digits_;
      return false;
    }
  }

private:
  bool fail() {
    state_ = 0;
    return false;
  }
  bool finish(req &out) {
    std::uint8_t x = 0;
    for (std::size_t i = 0; i < n_; ++i) x = static_cast<std::uint8_t>(x ^ body_[i]);
    if (check_ != 0U && check_ != x) return false;
    std::size_t i = 0;
    std::uint32_t cmd = 0;
    for (; i < 4U; ++i) {
      const std::uint8_t c = i < n_ ? body_[i] : 0;
      unsigned d = 0;
      if (c >= '0' && c <= '9') {
        d = c - '0';
      } else if (c >= 'A' && c <= 'F') {
        d = c - 'A' + 10U;
      } else {
        return false;
      }
      cmd = (cmd << 4U) | d;
    }
    if (i >= n_ || body_[i++] != ';') return false;
    std::uint32_t par = 0;
    const std::size_t par_start = i;
    while (i < n_ && body_[i] >= '0' && body_[i] <= '9') {
      par = par * 10U + (body_[i++] - '0');
      if (par > 0xFFFFU) return false;
    }
    if (i == par_start || i >= n_ || body_[i++] != ';') return false;
    if (i + 1U >= n_ || body_[i] != '0' || body_[i + 1U] != ';') return false; // integer
    i += 2U;
    const bool neg = i < n_ && body_[i] == '-';
    if (neg) ++i;
    const std::size_t date_start = i;
    std::int64_t v = 0;
    while (i < n_ && body_[i] >= '0' && body_[i] <= '9') {
      v = v * 10 + (body_[i++] - '0');
      if (v > 2147483648LL) return false;
    }
    if (i == date_start || i != n_) return false;
    if (neg) v = -v;
    if (v > INT32_MAX) return false;
    out = {static_cast<std::uint16_t>(cmd), static_cast<std::uint16_t>(par),
           static_cast<std::int32_t>(v), true};
    return true;
  }

  std::array<std::uint8_t, 64> body_{};
  std::size_t n_ = 0;
  unsigned state_ = 0;
  unsigned check_ = 0;
  unsigned check_digits_ = 0;
};

bench::registry make_registry() {
  fill_inputs();
  bench::registry r;
  bench::add_harness<g_requests>(r);
  bench::add<g_requests>(
      r, "serial/encode_request (integer date)",
      [](const req &q) {
        frame f;
        const serial::request s{q.command, q.parameter, pac::value::of_int(q.date).value()};
        f.len = serial::encode_request(s, f.b).value_or(0);
        return f;
      },
      [](const req &q) { return hand_encode(q); });
  bench::add<g_frames>(
      r, "serial/decoder request, byte at a time",
      [](const frame &f) {
        req q;
        // one receiver for the whole run, as a serial driver keeps it (not rebuilt per frame)
        static pac::serial::decoder d{
            pac::serial::decoder_options{{}, pac::serial::accept::requests}};
        for (std::size_t i = 0; i < f.len; ++i) {
          auto k = d.push(f.b[i]);
          if (k && k.value() == pac::serial::frame_kind::request) {
            const auto &s = d.request();
            q = {s.code, s.parameter, static_cast<std::int32_t>(s.date.number.mantissa),
                 s.date.type == fieldcodec::od::command_value::integer};
          }
        }
        return q;
      },
      [](const frame &f) {
        req q;
        static hand_decoder d;
        for (std::size_t i = 0; i < f.len; ++i) d.push(f.b[i], q);
        return q;
      });
  return r;
}

} // namespace

int main(int argc, char **argv) { return bench::main(argc, argv, make_registry()); }
