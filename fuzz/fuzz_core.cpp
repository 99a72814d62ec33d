// Fuzz harness for the core primitives. The first input byte selects the primitive; the rest is
// its input. Properties: what decodes re-encodes to the same bytes/text (canonical form noted),
// what parses formats back to the same value.
#include "check.hpp"

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/bcd.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/ieee754.hpp>
#include <fieldcodec/core/scaling.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fc = fieldcodec;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  const std::uint8_t selector = data[0];
  const std::span<const std::uint8_t> in(data + 1, size - 1);
  const std::string_view text(reinterpret_cast<const char *>(in.data()), in.size());

  switch (selector % 6U) {
  case 0: { // unsigned BCD: decode → encode gives the same bytes
    auto v = fc::bcd::decode(in);
    if (v) {
      std::array<std::uint8_t, fc::bcd::max_bytes> out{};
      auto o = std::span(out).first(in.size());
      FUZZ_CHECK(fc::bcd::encode(v.value(), o));
      FUZZ_CHECK(std::equal(o.begin(), o.end(), in.begin()));
    }
    break;
  }
  case 1: { // signed BCD: canonical form is "zero is positive"
    auto v = fc::bcd::decode_signed(in);
    if (v) {
      std::array<std::uint8_t, 1 + fc::bcd::max_bytes> out{};
      auto o = std::span(out).first(in.size());
      FUZZ_CHECK(fc::bcd::encode_signed(v.value(), o));
      const bool negative_zero = v.value() == 0 && in[0] == 0xFF;
      FUZZ_CHECK(std::equal(o.begin() + 1, o.end(), in.begin() + 1));
      FUZZ_CHECK(negative_zero ? o[0] == 0x00 : o[0] == in[0]);
    }
    break;
  }
  case 2: { // decimal text: parse → format gives the same text
    auto d = fc::parse_decimal(text);
    if (d) {
      std::array<char, 48> buf{};
      auto n = fc::format_decimal(d.value(), buf);
      FUZZ_CHECK(n.has_value());
      const std::string_view back(buf.data(), n.value());
      // Canonical text: no leading zeros, no "-" on zero; parsing it gives exactly the
      // same mantissa and places, and formatting that again gives the same text.
      auto again = fc::parse_decimal(back);
      FUZZ_CHECK(again.has_value());
      FUZZ_CHECK(again.value().mantissa == d.value().mantissa);
      FUZZ_CHECK(again.value().places == d.value().places);
      std::string_view ip = text.substr(text.starts_with('-') ? 1 : 0);
      ip = ip.substr(0, ip.find('.'));
      const bool canonical = ip == "0" || ip.front() != '0';
      if (d.value().mantissa != 0 && canonical) FUZZ_CHECK(back == text);
    }
    break;
  }
  case 3: { // integer text
    auto s = fc::ascii::parse_signed(text);
    if (s) {
      std::array<char, 24> buf{};
      auto n = fc::ascii::format_signed(s.value(), buf);
      FUZZ_CHECK(n.has_value());
      auto again = fc::ascii::parse_signed({buf.data(), n.value()});
      FUZZ_CHECK(again && again.value() == s.value());
    }
    auto h = fc::ascii::parse_hex(text, fc::ascii::hex_case::upper);
    if (h) {
      std::array<char, 24> buf{};
      auto n = fc::ascii::format_hex(h.value(), text.size() > 16 ? 16 : text.size(), buf);
      FUZZ_CHECK(n.has_value());
      FUZZ_CHECK(fc::ascii::parse_hex({buf.data(), n.value()}).value() == h.value());
    }
    break;
  }
  case 4: { // IEEE-754: decode → encode gives the same bytes; non-finite rejected
    for (auto order : {fc::byte_order::big, fc::byte_order::little}) {
      auto f = fc::ieee754::decode_float32(in, order);
      if (f) {
        auto back = fc::ieee754::encode_float32(f.value(), order);
        FUZZ_CHECK(back && std::equal(back.value().begin(), back.value().end(), in.begin()));
      } else if (in.size() >= 4) {
        FUZZ_CHECK(f.error() == fc::errc::not_representable);
      }
    }
    break;
  }
  case 5: { // scaling: to_raw result fits the field and converts back within half a step
    if (in.size() < 12) break;
    const auto scale_m =
        static_cast<std::int64_t>(fc::load<std::uint16_t>(in, fc::byte_order::big).value());
    const auto eu_m = fc::load<std::int32_t>(in.subspan(2), fc::byte_order::big).value();
    const auto places = static_cast<std::uint8_t>(in[6] % 7U);
    const auto off_m = fc::load<std::int16_t>(in.subspan(7), fc::byte_order::big).value();
    const fc::scaling::field field{static_cast<std::uint8_t>(1U + in[9] % 8U), (in[10] & 1U) != 0};
    const fc::scaling::linear lin{{scale_m, static_cast<std::uint8_t>(in[11] % 4U)}, {off_m, 0}};
    auto raw = fc::scaling::to_raw(fc::decimal{eu_m, places}, lin, field);
    if (raw) {
      FUZZ_CHECK(fc::scaling::check_field(raw.value(), field).has_value());
      // back to engineering units: within half a raw step of the input
      double eu = static_cast<double>(eu_m);
      for (unsigned i = 0; i < places; ++i) eu /= 10.0;
      double scale = static_cast<double>(scale_m);
      for (unsigned i = 0; i < lin.scale.places; ++i) scale /= 10.0;
      const double back = fc::scaling::to_eu(raw.value(), lin);
      const double err = back > eu ? back - eu : eu - back;
      FUZZ_CHECK(err <= 0.5 / scale * (1 + 1e-9) + 1e-9 * (eu < 0 ? -eu : eu) + 1e-9);
    } else {
      FUZZ_CHECK(raw.error() == fc::errc::overflow || raw.error() == fc::errc::invalid_argument);
    }
    break;
  }
  }
  return 0;
}
