// The PA-CONTROL encoder of issue 18 (one capacity check per field, digits written straight
// into the frame) writes the same bytes and returns the same results as the writer it replaced,
// kept here as the reference — also into buffers too small for the frame, byte for byte.
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <doctest/doctest.h>

#include "xorshift.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace fc = fieldcodec;
namespace pac = fieldcodec::pacontrol;

namespace reference {
using namespace fieldcodec;
using namespace fieldcodec::pacontrol;
using namespace fieldcodec::pacontrol::serial;

/// Appends characters to a bounded text buffer.
struct text_writer {
  std::span<std::uint8_t> out;
  std::size_t n = 0;

  constexpr status put(char c) noexcept {
    if (n >= out.size()) return errc::buffer_too_small;
    out[n++] = static_cast<std::uint8_t>(c);
    return {};
  }
  constexpr status put_byte(std::uint8_t b) noexcept {
    if (n >= out.size()) return errc::buffer_too_small;
    out[n++] = b;
    return {};
  }
  /// Appends characters.
  constexpr status put_text(std::span<const char> text) noexcept {
    for (const char c : text) FIELDCODEC_TRY_STATUS(put(c));
    return {};
  }
  constexpr status put_unsigned(std::uint64_t v) noexcept {
    char tmp[20]{};
    auto len = ascii::format_unsigned(v, tmp);
    if (!len) return len.error();
    return put_text(std::span<const char>(tmp, len.value()));
  }
  constexpr status put_value(const value &v) noexcept {
    char tmp[48]{};
    auto len = format_decimal(v.number, tmp);
    if (!len) return len.error();
    if (len.value() > max_field_chars) return errc::too_long; // cannot happen for valid dates
    return put_text(std::span<const char>(tmp, len.value()));
  }
};

/// Writes SOH STX body ETX CHECK EOT, the body produced by `write_body`.
template <class F>
constexpr result<std::size_t> write_frame(std::span<std::uint8_t> out, check_rule rule,
                                          check_mode mode, F &&write_body) noexcept {
  text_writer w{out};
  FIELDCODEC_TRY_STATUS(w.put_byte(soh));
  FIELDCODEC_TRY_STATUS(w.put_byte(stx));
  const std::size_t body_start = w.n;
  FIELDCODEC_TRY_STATUS(write_body(w));
  std::uint8_t check = rule == check_rule::body_and_etx ? etx : std::uint8_t{0};
  check = checksum::xor8(std::span<const std::uint8_t>(out.data() + body_start, w.n - body_start),
                         check);
  FIELDCODEC_TRY_STATUS(w.put_byte(etx));
  FIELDCODEC_TRY_STATUS(w.put_unsigned(mode == check_mode::computed ? check : 0U));
  FIELDCODEC_TRY_STATUS(w.put_byte(eot));
  return w.n;
}

[[nodiscard]] constexpr result<std::size_t>
reference_encode_request(const request &r, std::span<std::uint8_t> out,
                         check_rule rule = check_rule::body,
                         check_mode mode = check_mode::computed) noexcept {
  FIELDCODEC_TRY_STATUS(validate(r.date));
  return write_frame(out, rule, mode, [&](text_writer &w) -> status {
    char cmd[4]{};
    auto n = ascii::format_hex(r.code, 4, cmd, true);
    if (!n) return n.error();
    FIELDCODEC_TRY_STATUS(w.put_text(cmd));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put_unsigned(r.parameter));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put(typ_field(r.date.type).value())); // validated above
    FIELDCODEC_TRY_STATUS(w.put(separator));
    return w.put_value(r.date);
  });
}

[[nodiscard]] constexpr result<std::size_t>
reference_encode_acknowledgement(const acknowledgement &a, std::span<std::uint8_t> out,
                                 check_rule rule = check_rule::body_and_etx,
                                 check_mode mode = check_mode::computed) noexcept {
  FIELDCODEC_TRY_STATUS(validate(a.date));
  return write_frame(out, rule, mode, [&](text_writer &w) -> status {
    FIELDCODEC_TRY_STATUS(w.put_unsigned(a.command_error_number));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put(a.end_of_processing ? '1' : '0'));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put_unsigned(a.operating_status));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put_unsigned(a.controller_error_number));
    FIELDCODEC_TRY_STATUS(w.put(separator));
    FIELDCODEC_TRY_STATUS(w.put(typ_field(a.date.type).value())); // validated above
    FIELDCODEC_TRY_STATUS(w.put(separator));
    return w.put_value(a.date);
  });
}

} // namespace reference

namespace {
struct rng : fieldcodec::test::xorshift {
  rng() : xorshift(0x5555'AAAA'1234'5678ULL) {}
};

pac::value any_value(rng &g) {
  const std::uint64_t r = g.next();
  switch (r % 4U) {
  case 0: return pac::value::of_int(static_cast<std::int32_t>(r >> 32U)).value();
  case 1: return pac::value::of_int(static_cast<std::int32_t>((r >> 32U) % 1000U)).value();
  case 2:
    return pac::value{fc::od::command_value::real,
                      fc::decimal{static_cast<std::int64_t>(r >> 8U) / 1000,
                                  static_cast<std::uint8_t>((r >> 2U) % 19U)}};
  default:
    return pac::value{fc::od::command_value::real,
                      fc::decimal{static_cast<std::int64_t>(r) >> (r % 64U), 3}};
  }
}
} // namespace

TEST_CASE("pacontrol encoder: the same bytes and results as the replaced writer") {
  rng g;
  for (int k = 0; k < 4000; ++k) {
    const std::uint64_t r = g.next();
    const pac::serial::request q{static_cast<std::uint16_t>(r),
                                 static_cast<std::uint16_t>(r >> 16U), any_value(g)};
    const pac::serial::acknowledgement a{static_cast<std::uint16_t>(r >> 20U), (r & 1U) != 0U,
                                         static_cast<std::uint16_t>(r >> 32U),
                                         static_cast<std::uint16_t>(r >> 48U), any_value(g)};
    const auto rule = (r >> 5U) % 2U == 0U ? pac::serial::check_rule::body
                                           : pac::serial::check_rule::body_and_etx;
    const auto mode = (r >> 6U) % 2U == 0U ? pac::serial::check_mode::computed
                                           : pac::serial::check_mode::unchecked;
    // every buffer size up to a full frame: truncated writes must match byte for byte
    const std::size_t size = (r >> 7U) % (pac::serial::max_frame_size + 1U);
    std::array<std::uint8_t, pac::serial::max_frame_size> got{};
    std::array<std::uint8_t, pac::serial::max_frame_size> want{};
    const auto n1 = pac::serial::encode_request(q, std::span(got).first(size), rule, mode);
    const auto n2 = reference::reference_encode_request(q, std::span(want).first(size), rule, mode);
    REQUIRE(n1.has_value() == n2.has_value());
    if (n1) CHECK(n1.value() == n2.value());
    if (!n1) CHECK(n1.error() == n2.error());
    CHECK(got == want);
    got = {};
    want = {};
    const auto m1 = pac::serial::encode_acknowledgement(a, std::span(got).first(size), rule, mode);
    const auto m2 =
        reference::reference_encode_acknowledgement(a, std::span(want).first(size), rule, mode);
    REQUIRE(m1.has_value() == m2.has_value());
    if (m1) CHECK(m1.value() == m2.value());
    if (!m1) CHECK(m1.error() == m2.error());
    CHECK(got == want);
  }
}
