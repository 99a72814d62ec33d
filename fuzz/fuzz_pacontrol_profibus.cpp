// Fuzz harness for the PA-CONTROL Profibus-DP / Interbus-S telegrams (pacontrol/profibus_*.hpp)
// and the position formats (pacontrol/position.hpp). Byte 0 selects the telegram (low 3 bits),
// the position format (bit 3: ×1000 integer) and the flag-module layout (bit 4: as printed);
// the rest is the telegram.
//
// Property: what decodes re-encodes to its canonical bytes, and those decode to the same value.
// Canonical forms:
// * CMD request: the 8 bytes unchanged (every bit is assigned).
// * CMD reply: bits 14-8 of word 2 (unused) cleared.
// * CTRL command / status: the assigned bits of word 0 kept, every other bit (word 0 bits 14-5
//   of the control word, bits 14-12, 7-3 of the status word; words 1-3) cleared.
// * Axis command / status, flag module: a float position/R register unchanged; a ×1000 one
//   unchanged while |raw| < 16 384 000 (there a float still tells neighbouring thousandths
//   apart); beyond that the decoded float stands for several raw values, and re-encoding gives
//   the raw of its shortest decimal — which decodes to the same float. Unused bytes cleared
//   (word-aligned flag module: bytes 2-3; as printed: bytes 0-1 and 4-5). An axis command
//   whose fields the encoder refuses (reserved control bits, acceleration 0, speed 0 or above
//   1000) has no canonical form: the encoder must refuse it with the documented error.
// * Positions as exact decimals (decode_position_decimal → encode_position(decimal)): the 4
//   bytes unchanged in both formats (floats below 1e-8 or from 9e18 on have no such decimal:
//   documented in value.hpp, shortest_decimal). A decimal has no sign of zero: the float -0.0
//   (80 00 00 00) comes back as +0.0 (00 00 00 00) on this path.
// * The CMD handshake fed arbitrary replies: progress is waiting/idle exactly when RF ≠ SF, and
//   start() toggles the SEND flag exactly when the previous command was seen.
#include "check.hpp"

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/pacontrol/position.hpp>
#include <fieldcodec/pacontrol/profibus_axis.hpp>
#include <fieldcodec/pacontrol/profibus_cmd.hpp>
#include <fieldcodec/pacontrol/profibus_ctrl.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fc = fieldcodec;
namespace pac = fieldcodec::pacontrol;
namespace pb = fieldcodec::pacontrol::profibus;
using fc::errc;
using pac::position_format;

namespace {

using bytes = std::span<const std::uint8_t>;

template <std::size_t N>
bool same(const std::array<std::uint8_t, N> &a, bytes b) {
  return b.size() >= N && std::equal(a.begin(), a.end(), b.begin());
}

constexpr std::int32_t exact_milli_limit = 16'384'000;

/// The canonical re-encoding `enc` (4 bytes) of the position `in` (4 bytes, format `f`).
void check_position_bytes(bytes in, bytes enc, position_format f) {
  if (f == position_format::milli_integer) {
    const auto raw = fc::load<std::int32_t>(in, fc::byte_order::big).value();
    if (raw < exact_milli_limit && raw > -exact_milli_limit) {
      FUZZ_CHECK(std::equal(enc.begin(), enc.begin() + 4, in.begin()));
    } else {
      FUZZ_CHECK(pac::decode_position(enc, f).value() == pac::decode_position(in, f).value());
    }
  } else {
    FUZZ_CHECK(std::equal(enc.begin(), enc.begin() + 4, in.begin()));
  }
}

// F2 (fixed): near the int32 limits a ×1000 position decodes to the nearest float towards zero,
// so every decoded position encodes again; the checks below are strict.

void check_position(bytes in, position_format f) {
  auto p = pac::decode_position(in, f);
  auto d = pac::decode_position_decimal(in, f);
  if (in.size() < 4) {
    FUZZ_CHECK(p.is(errc::truncated) && d.is(errc::truncated));
    return;
  }
  if (p && !d) { // documented: too small for 18 places, or >= 9e18
    FUZZ_CHECK(d.is(errc::not_representable) && f == position_format::ieee_float);
    const float a = p.value() < 0.0F ? -p.value() : p.value();
    FUZZ_CHECK(a < 1e-8F || a >= 9e18F);
  }
  if (!p) {
    FUZZ_CHECK(!d);
    FUZZ_CHECK(f == position_format::ieee_float && p.is(errc::not_representable));
    return;
  }
  auto e = pac::encode_position(p.value(), f);
  FUZZ_CHECK(e.has_value());
  check_position_bytes(in, e.value(), f);
  if (!d) return;
  auto ed = pac::encode_position(d.value(), f); // exact decimal: same bytes in both formats
  FUZZ_CHECK(ed.has_value());
  const bool negative_zero = f == position_format::ieee_float && in[0] == 0x80U && in[1] == 0U &&
                             in[2] == 0U && in[3] == 0U;
  if (negative_zero) {
    FUZZ_CHECK(ed.value() == (std::array<std::uint8_t, 4>{0, 0, 0, 0}));
  } else {
    FUZZ_CHECK(same(ed.value(), in));
  }
}

void check_cmd_request(bytes in) {
  auto r = pb::decode_cmd_request(in);
  if (in.size() < pb::cmd_size) {
    FUZZ_CHECK(r.is(errc::truncated));
    return;
  }
  auto e = pb::encode_cmd_request(r.value());
  FUZZ_CHECK(e.has_value() && same(e.value(), in));
}

void check_cmd_reply(bytes in) {
  auto r = pb::decode_cmd_reply(in);
  if (in.size() < pb::cmd_size) {
    FUZZ_CHECK(r.is(errc::truncated));
    return;
  }
  auto e = pb::encode_cmd_reply(r.value());
  FUZZ_CHECK(e.has_value());
  std::array<std::uint8_t, pb::cmd_size> canon{};
  std::copy_n(in.begin(), pb::cmd_size, canon.begin());
  canon[4] &= 0x80U;
  FUZZ_CHECK(e.value() == canon);
  FUZZ_CHECK(pb::decode_cmd_reply(e.value()).value() == r.value());
}

void check_ctrl(bytes in) {
  auto c = pb::decode_ctrl_command(in);
  auto s = pb::decode_ctrl_status(in);
  if (in.size() < pb::ctrl_size) {
    FUZZ_CHECK(c.is(errc::truncated) && s.is(errc::truncated));
    return;
  }
  std::array<std::uint8_t, pb::ctrl_size> canon{};
  canon[0] = static_cast<std::uint8_t>(in[0] & 0x80U);
  canon[1] = static_cast<std::uint8_t>(in[1] & 0x1FU);
  FUZZ_CHECK(pb::encode_ctrl_command(c.value()) == canon);
  FUZZ_CHECK(pb::decode_ctrl_command(canon).value() == c.value());
  canon[0] = static_cast<std::uint8_t>(in[0] & 0x8FU);
  canon[1] = static_cast<std::uint8_t>(in[1] & 0x07U);
  FUZZ_CHECK(pb::encode_ctrl_status(s.value()) == canon);
  FUZZ_CHECK(pb::decode_ctrl_status(canon).value() == s.value());
  FUZZ_CHECK(c.value().format() == ((in[0] & 0x80U) != 0U ? position_format::milli_integer
                                                          : position_format::ieee_float));
}

void check_axis_command(bytes in, position_format f) {
  auto c = pb::decode_axis_command(in, f);
  if (in.size() < pb::module_size) {
    FUZZ_CHECK(c.is(errc::truncated));
    return;
  }
  if (!c) {
    FUZZ_CHECK(c.is(errc::not_representable) && f == position_format::ieee_float);
    return;
  }
  const auto &v = c.value();
  auto e = pb::encode_axis_command(v, f);
  if ((v.control & pb::axis_control::reserved) != 0U) {
    FUZZ_CHECK(e.is(errc::invalid_argument));
  } else if (v.acceleration == 0U || v.speed == 0U || v.speed > pb::max_speed) {
    FUZZ_CHECK(e.is(errc::out_of_range));
  } else {
    FUZZ_CHECK(e.has_value());
    FUZZ_CHECK(std::equal(e.value().begin(), e.value().begin() + 8, in.begin()));
    check_position_bytes(in.subspan(8), std::span(e.value()).subspan(8), f);
    FUZZ_CHECK(pb::decode_axis_command(e.value(), f).value() == v);
  }
}

void check_axis_status(bytes in, position_format f) {
  auto s = pb::decode_axis_status(in, f);
  if (in.size() < pb::module_size) {
    FUZZ_CHECK(s.is(errc::truncated));
    return;
  }
  if (!s) {
    FUZZ_CHECK(s.is(errc::not_representable) && f == position_format::ieee_float);
    return;
  }
  auto e = pb::encode_axis_status(s.value(), f);
  FUZZ_CHECK(e.has_value());
  FUZZ_CHECK(std::equal(e.value().begin(), e.value().begin() + 8, in.begin()));
  check_position_bytes(in.subspan(8), std::span(e.value()).subspan(8), f);
  FUZZ_CHECK(pb::decode_axis_status(e.value(), f).value() == s.value());
}

void check_flag_module(bytes in, position_format f, pb::module_layout layout) {
  auto m = pb::decode_flag_module(in, f, layout);
  if (in.size() < pb::module_size) {
    FUZZ_CHECK(m.is(errc::truncated));
    return;
  }
  if (!m) {
    FUZZ_CHECK(m.is(errc::not_representable) && f == position_format::ieee_float);
    return;
  }
  auto e = pb::encode_flag_module(m.value(), f, layout);
  FUZZ_CHECK(e.has_value());
  std::array<std::uint8_t, 8> canon{};
  std::copy_n(in.begin(), 8, canon.begin());
  if (layout == pb::module_layout::word_aligned) {
    canon[2] = canon[3] = 0;
  } else {
    canon[0] = canon[1] = canon[4] = canon[5] = 0;
  }
  FUZZ_CHECK(std::equal(canon.begin(), canon.end(), e.value().begin()));
  check_position_bytes(in.subspan(8), std::span(e.value()).subspan(8), f);
  FUZZ_CHECK(pb::decode_flag_module(e.value(), f, layout).value() == m.value());
}

// The input is a sequence of 9-byte steps: an op byte and an 8-byte reply.
void check_handshake(bytes in) {
  pb::cmd_handshake hs;
  bool seen = true;
  bool started = false;
  for (std::size_t at = 0; at + 9 <= in.size(); at += 9) {
    const std::uint8_t op = in[at];
    auto reply = pb::decode_cmd_reply(in.subspan(at + 1, 8)).value();
    if ((op & 3U) == 0U) {
      const bool before = hs.send_flag();
      const auto code = static_cast<std::uint16_t>(op << 8U);
      auto req = hs.start(code, op, 0x1234U);
      if (!seen) {
        FUZZ_CHECK(req.is(errc::bad_state) && hs.send_flag() == before);
      } else if (code > pb::max_command_code) {
        FUZZ_CHECK(req.is(errc::overflow) && hs.send_flag() == before); // refused: no toggle
      } else {
        FUZZ_CHECK(req.has_value() && req.value().send_flag == !before);
        FUZZ_CHECK(hs.send_flag() == !before);
        auto enc = pb::encode_cmd_request(req.value());
        FUZZ_CHECK(enc && pb::decode_cmd_request(enc.value()).value() == req.value());
        seen = false;
        started = true;
      }
    } else if ((op & 3U) == 1U) {
      hs.synchronize(reply);
      FUZZ_CHECK(hs.send_flag() == reply.receive_flag);
      seen = true;
      started = false;
    } else {
      const auto p = hs.update(reply);
      if (reply.receive_flag != hs.send_flag()) {
        FUZZ_CHECK(p == (started ? pb::cmd_progress::waiting : pb::cmd_progress::idle));
        if (!started) seen = false;
      } else {
        seen = true;
        if (!started) {
          FUZZ_CHECK(p == pb::cmd_progress::idle);
        } else if (reply.command_error) {
          FUZZ_CHECK(p == pb::cmd_progress::failed);
        } else {
          FUZZ_CHECK(
              p == (reply.end_of_processing ? pb::cmd_progress::done : pb::cmd_progress::running));
        }
      }
    }
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t sel = data[0];
  const bytes in(data + 1, size - 1);
  const auto f = (sel & 8U) != 0U ? position_format::milli_integer : position_format::ieee_float;
  const auto layout =
      (sel & 16U) != 0U ? pb::module_layout::as_printed : pb::module_layout::word_aligned;
  switch (sel & 7U) {
  case 0: check_cmd_request(in); break;
  case 1: check_cmd_reply(in); break;
  case 2: check_ctrl(in); break;
  case 3: check_axis_command(in, f); break;
  case 4: check_axis_status(in, f); break;
  case 5: check_flag_module(in, f, layout); break;
  case 6: check_position(in, f); break;
  case 7: check_handshake(in); break;
  }
  return 0;
}
