// PA-CONTROL RS232 byte-at-a-time decoder: bad input, resynchronisation, streams.
#include <fieldcodec/pacontrol/serial_decoder.hpp>

#include "pac_test_util.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace fc = fieldcodec;
namespace serial = fc::pacontrol::serial;
using fc::errc;
using pactest::frame;
using pactest::hex;
using serial::frame_kind;

namespace {

/// One event per completed frame or error while feeding `b` byte by byte.
struct event {
  bool ok;
  frame_kind kind;
  errc error;
};

std::vector<event> feed(serial::decoder &d, std::span<const std::uint8_t> b) {
  std::vector<event> out;
  for (const auto byte : b) {
    auto r = d.push(byte);
    if (!r) {
      out.push_back({false, frame_kind::none, r.error()});
    } else if (r.value() != frame_kind::none) {
      out.push_back({true, r.value(), errc{}});
    }
  }
  return out;
}

errc error_of(const pactest::bytes &b, serial::decoder_options o = {}) {
  auto d = serial::decode_frame(b.span(), o);
  return d ? errc{} : d.error();
}

// Frame 3 and 4 of 3.4.2 (valid).
constexpr auto req_ok = hex("01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 04");
constexpr auto ack_ok = hex("01 02 30 3B 31 3B 31 3B 30 3B 30 3B 31 03 35 37 04");

} // namespace

// A poll is a lone EOT; the decoder works in constant expressions.
static_assert(serial::decode_frame(hex("04").span()).value().kind == frame_kind::poll);
static_assert(serial::decode_frame(hex("01 02 31 39").span()).error() == errc::truncated);
static_assert(serial::decode_frame(hex("").span()).error() == errc::truncated);

TEST_CASE("pacontrol serial decoder: field errors are precise") {
  // Lower-case and 3-digit command codes.
  CHECK(error_of(frame("0a87;2;1;5552.0", "0")) == errc::bad_digit);
  CHECK(error_of(frame("A87;2;1;5552.0", "0")) == errc::bad_length);
  CHECK(error_of(frame("00A87;2;1;5552.0", "0")) == errc::bad_length);
  CHECK(error_of(frame("0G87;2;1;5552.0", "0")) == errc::bad_digit);
  CHECK(error_of(frame(";2;1;5552.0", "0")) == errc::bad_syntax);
  // Letters and signs in decimal fields.
  CHECK(error_of(frame("0A87;A;1;5552.0", "0")) == errc::bad_digit);
  CHECK(error_of(frame("0A87;-2;1;5552.0", "0")) == errc::bad_sign);
  CHECK(error_of(frame("0A87;2;1;55x2.0", "0")) == errc::bad_digit);
  CHECK(error_of(frame("0A87;2;1;5552,0", "0")) == errc::bad_digit);
  CHECK(error_of(frame("0A87;2;1;5.5e3", "0")) == errc::bad_digit);
  CHECK(error_of(frame("0A87;2;1; 5552.0", "0")) == errc::bad_digit);
  CHECK(error_of(frame("0;1;1;0;0;1x", "0")) == errc::bad_digit);
  CHECK(error_of(frame("0;1;B;0;0;1", "0")) == errc::bad_digit);
  CHECK(error_of(frame("0;1;1;-5;0;1", "0")) == errc::bad_sign);
  // Missing and empty fields.
  CHECK(error_of(frame("0A87;2;1", "0")) == errc::bad_length);
  CHECK(error_of(frame("0A87;2;1;", "0")) == errc::bad_syntax);
  CHECK(error_of(frame("0;1;1;0;0", "0")) == errc::bad_length);
  CHECK(error_of(frame("0;1;1;0;;1", "0")) == errc::bad_syntax);
  CHECK(error_of(frame("", "0")) == errc::bad_length);
  CHECK(error_of(frame("0;1;1;0;0;1;2", "0")) == errc::bad_length);
  // Ranges.
  CHECK(error_of(frame("0A87;65536;0;0", "0")) == errc::overflow);
  CHECK(error_of(frame("0A87;2;2;0", "0")) == errc::out_of_range);
  CHECK(error_of(frame("0;2;1;0;0;1", "0")) == errc::out_of_range);
  CHECK(error_of(frame("0906;5;0;2147483648", "0")) == errc::overflow);
  CHECK(error_of(frame("0906;5;0;-2147483649", "0")) == errc::overflow);
  CHECK(serial::decode_frame(frame("0906;5;0;-2147483648", "0").span()));
  // A fraction in an integer date.
  CHECK(error_of(frame("0906;5;0;12.5", "0")) == errc::type_mismatch);
  CHECK(error_of(frame("0;1;1;0;0;1.0", "0")) == errc::type_mismatch);
  // An integer text in a real date is fine (3.4.2 frame 9 sends "0" with TYP 1).
  auto d = serial::decode_frame(frame("0907;1;1;-12", "0").span());
  REQUIRE(d);
  CHECK(d.value().req.date.type == fc::od::command_value::real);
  CHECK(d.value().req.date.as_float() == -12.0F);
  CHECK(d.value().req.date.as_int().error() == errc::type_mismatch);
}

TEST_CASE("pacontrol serial decoder: check field errors") {
  CHECK(error_of(frame("1900;5;0;0", "")) == errc::bad_syntax);
  CHECK(error_of(frame("1900;5;0;0", "7")) == errc::bad_checksum);
  CHECK(serial::decode_frame(frame("1900;5;0;0", "006").span())); // leading zeros are harmless
  CHECK(error_of(frame("1900;5;0;0", "0006")) == errc::too_long);
  CHECK(error_of(frame("1900;5;0;0", "256")) == errc::out_of_range);
  CHECK(error_of(frame("1900;5;0;0", "6A")) == errc::bad_digit);
  CHECK(error_of(frame("1900;5;0;0", "-6")) == errc::bad_digit);
  // An ETX or STX in the check field.
  CHECK(error_of(hex("01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 03 04")) == errc::bad_syntax);
  CHECK(error_of(hex("01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 02 04")) == errc::bad_syntax);
}

TEST_CASE("pacontrol serial decoder: characters outside the protocol's set") {
  CHECK(error_of(hex("01 02 31 39 30 30 3B 35 3B 30 3B 80 03 36 04")) == errc::bad_character);
  CHECK(error_of(hex("01 02 31 39 30 30 3B 35 3B 30 3B 7F 03 36 04")) == errc::bad_character);
  CHECK(error_of(hex("01 02 31 39 30 30 3B 35 3B 30 3B 0D 03 36 04")) == errc::bad_character);
  CHECK(error_of(hex("01 02 31 39 30 30 3B 35 3B 30 3B 00 03 36 04")) == errc::bad_character);
  CHECK(error_of(hex("01 02 31 39 30 30 3B 35 3B 02 3B 30 03 36 04")) == errc::bad_syntax);
  CHECK(error_of(hex("01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 0A 04")) == errc::bad_character);
  // SOH not followed by STX.
  CHECK(error_of(hex("01 31 39")) == errc::bad_syntax);
}

TEST_CASE("pacontrol serial decoder: overlong fields never overrun the buffer") {
  // 21 characters per field are accepted, 22 are not.
  CHECK(serial::decode_frame(frame("0907;1;1;123456789012345678901", "0").span()).error() ==
        errc::overflow); // 21 digits: accepted by length, more than int64 holds
  CHECK(error_of(frame("0907;1;1;99999999999.999999999", "0")) == errc::overflow);
  CHECK(error_of(frame("0907;1;1;1234567890123456789012", "0")) == errc::too_long);
  CHECK(error_of(frame("0907;0000000000000000000001;1;0", "0")) == errc::too_long);
  CHECK(serial::decode_frame(frame("0907;000000000000000000001;1;0", "0").span()));
  // The longest dates the encoder can write fit (fuzz finding F1).
  CHECK(serial::decode_frame(frame("0907;1;1;-0.000000000000000001", "0").span()));
  CHECK(serial::decode_frame(frame("0907;1;1;-922337203685477580.8", "0").span()));
  // A stream that never ends a frame: every field at the limit, then more fields.
  serial::decoder d;
  CHECK(d.push(0x01).value() == frame_kind::none);
  CHECK(d.push(0x02).value() == frame_kind::none);
  errc first{};
  std::size_t errors = 0;
  for (int i = 0; i < 10000; ++i) {
    const std::uint8_t b = (i % 22 == 21) ? std::uint8_t{';'} : std::uint8_t{'7'};
    auto r = d.push(b);
    if (!r) {
      if (errors++ == 0) first = r.error();
    }
  }
  CHECK(first == errc::bad_length); // the 7th field
  CHECK(errors == 1);               // then silent until the next SOH
  // Long garbage without any SOH/EOT is one error.
  serial::decoder g;
  std::size_t garbage_errors = 0;
  for (int i = 0; i < 5000; ++i) {
    if (!g.push(static_cast<std::uint8_t>(0x20 + i % 90))) ++garbage_errors;
  }
  CHECK(garbage_errors == 1);
  auto ev = feed(g, req_ok.span());
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == frame_kind::request);
}

TEST_CASE("pacontrol serial decoder: streams, cuts and noise") {
  serial::decoder d;
  // Two frames back to back, then a poll.
  std::vector<std::uint8_t> s(req_ok.span().begin(), req_ok.span().end());
  s.insert(s.end(), ack_ok.span().begin(), ack_ok.span().end());
  s.push_back(0x04);
  auto ev = feed(d, s);
  REQUIRE(ev.size() == 3);
  CHECK(ev[0].kind == frame_kind::request);
  CHECK(d.request().code == 0x1900);
  CHECK(ev[1].kind == frame_kind::acknowledgement);
  CHECK(ev[2].kind == frame_kind::poll);
  CHECK(d.acknowledgement().date.as_int().value() == 1);
  CHECK(d.idle());

  // A frame cut in the middle by the next frame's SOH: one truncated, then the frame.
  std::vector<std::uint8_t> cut(req_ok.span().begin(), req_ok.span().begin() + 7);
  cut.insert(cut.end(), ack_ok.span().begin(), ack_ok.span().end());
  ev = feed(d, cut);
  REQUIRE(ev.size() == 2);
  CHECK((!ev[0].ok && ev[0].error == errc::truncated));
  CHECK(ev[1].kind == frame_kind::acknowledgement);

  // A frame cut by EOT (its tail lost): truncated; the EOT is not a poll.
  std::vector<std::uint8_t> cut_eot(req_ok.span().begin(), req_ok.span().begin() + 7);
  cut_eot.push_back(0x04);
  cut_eot.insert(cut_eot.end(), req_ok.span().begin(), req_ok.span().end());
  ev = feed(d, cut_eot);
  REQUIRE(ev.size() == 2);
  CHECK(ev[0].error == errc::truncated);
  CHECK(ev[1].kind == frame_kind::request);

  // Noise between frames: one error per run, frames around it decode.
  std::vector<std::uint8_t> noisy(req_ok.span().begin(), req_ok.span().end());
  for (int b : {0x55, 0xAA, 0x02, 0x03, 0xFF, 0x00}) noisy.push_back(static_cast<std::uint8_t>(b));
  noisy.insert(noisy.end(), ack_ok.span().begin(), ack_ok.span().end());
  ev = feed(d, noisy);
  REQUIRE(ev.size() == 3);
  CHECK(ev[0].kind == frame_kind::request);
  CHECK(ev[1].error == errc::bad_syntax);
  CHECK(ev[2].kind == frame_kind::acknowledgement);

  // A lost SOH: the rest of the frame is noise, its EOT ends the noise but is no poll.
  std::vector<std::uint8_t> lost(req_ok.span().begin() + 1, req_ok.span().end());
  lost.insert(lost.end(), ack_ok.span().begin(), ack_ok.span().end());
  ev = feed(d, lost);
  REQUIRE(ev.size() == 2);
  CHECK(ev[0].error == errc::bad_syntax);
  CHECK(ev[1].kind == frame_kind::acknowledgement);

  // A lost byte inside a frame: a wrong check (or field error), then back in step.
  std::vector<std::uint8_t> dropped;
  for (std::size_t i = 0; i < req_ok.size; ++i) {
    if (i != 4) dropped.push_back(req_ok.data[i]);
  }
  dropped.insert(dropped.end(), req_ok.span().begin(), req_ok.span().end());
  ev = feed(d, dropped);
  REQUIRE(ev.size() == 2);
  CHECK(!ev[0].ok);
  CHECK(ev[1].kind == frame_kind::request);

  // Every single-byte loss in a frame gives exactly one error and no false frame.
  for (std::size_t lose = 0; lose < ack_ok.size; ++lose) {
    serial::decoder x;
    std::vector<std::uint8_t> v;
    for (std::size_t i = 0; i < ack_ok.size; ++i) {
      if (i != lose) v.push_back(ack_ok.data[i]);
    }
    v.insert(v.end(), ack_ok.span().begin(), ack_ok.span().end());
    auto e = feed(x, v);
    INFO("lost byte ", lose);
    REQUIRE(!e.empty());
    CHECK(e.back().kind == frame_kind::acknowledgement);
    std::size_t frames = 0;
    for (const auto &one : e) frames += one.ok ? 1U : 0U;
    CHECK(frames == 1);
  }
}

TEST_CASE("pacontrol serial decoder: the span interface and reset") {
  serial::decoder d;
  std::vector<std::uint8_t> s(req_ok.span().begin(), req_ok.span().end());
  s.insert(s.end(), ack_ok.span().begin(), ack_ok.span().end());
  std::size_t used = 0;
  auto r = d.push(s, used);
  REQUIRE(r);
  CHECK(r.value() == frame_kind::request);
  CHECK(used == req_ok.size);
  r = d.push(std::span<const std::uint8_t>(s).subspan(used), used);
  REQUIRE(r);
  CHECK(r.value() == frame_kind::acknowledgement);
  CHECK(used == ack_ok.size);
  // Half a frame, reset, then a poll is a poll.
  r = d.push(std::span<const std::uint8_t>(s).first(5), used);
  CHECK(r.value() == frame_kind::none);
  CHECK_FALSE(d.idle());
  d.reset();
  CHECK(d.push(0x04).value() == frame_kind::poll);
  // Trailing bytes after one frame.
  std::vector<std::uint8_t> two(ack_ok.span().begin(), ack_ok.span().end());
  two.push_back(0x04);
  CHECK(serial::decode_frame(two).error() == errc::bad_length);
}

TEST_CASE("pacontrol serial decoder: which frames a side accepts") {
  serial::decoder master({{}, serial::accept::acknowledgements});
  CHECK(master.push(0x04).error() == errc::unexpected_frame);
  auto ev = feed(master, req_ok.span());
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].error == errc::unexpected_frame);
  ev = feed(master, ack_ok.span());
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == frame_kind::acknowledgement);

  serial::decoder device({{}, serial::accept::requests});
  CHECK(device.push(0x04).value() == frame_kind::poll);
  ev = feed(device, ack_ok.span());
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].error == errc::unexpected_frame);
  ev = feed(device, req_ok.span());
  REQUIRE(ev.size() == 1);
  CHECK(ev[0].kind == frame_kind::request);
}

TEST_CASE("pacontrol serial decoder: every byte value in every position is handled") {
  // Replace each byte of a valid frame with every possible value: the decoder never reports
  // the original frame for a changed body unless the check still matches, and always
  // recovers for the following frame.
  for (std::size_t pos = 0; pos < ack_ok.size; ++pos) {
    for (int v = 0; v < 256; ++v) {
      serial::decoder d;
      auto bad = ack_ok;
      bad.data[pos] = static_cast<std::uint8_t>(v);
      std::vector<std::uint8_t> s(bad.span().begin(), bad.span().end());
      s.insert(s.end(), ack_ok.span().begin(), ack_ok.span().end());
      auto ev = feed(d, s);
      REQUIRE(!ev.empty());
      CHECK(ev.back().kind == frame_kind::acknowledgement);
      CHECK(d.acknowledgement().date.as_int().value() == 1);
    }
  }
}
