// OBJECT_REQ / OBJECT_RSP over the 8-byte process-data channel (manual 000 p.64-66, fragment
// 002) and the AckToggle handshake helper.
#include <fieldcodec/compax/object_channel.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

namespace cx = fieldcodec::compax;
using fieldcodec::errc;
using frame = cx::object_frame;

// Read request for SPEED (pointer 38), sub-index 0: bit 7 set + pointer.
static_assert(cx::encode_object_request(cx::object_read(38).value()).value() ==
              frame{0xA6, 0, 0, 0, 0, 0});
// Write P23 (Px pointer 14, sub 23) = 200 % → raw 200 (P23 resolution 1): the manual's
// "P23=200% write" picture.
static_assert(cx::encode_object_request(
                  cx::object_write(14, 23, std::array<std::uint8_t, 4>{0, 0, 0, 200}).value())
                  .value() == frame{0x0E, 23, 0, 0, 0, 200});
static_assert(cx::decode_object_request(frame{0x8E, 23, 0, 0, 0, 0}).value() ==
              cx::object_read(14, 23).value());
static_assert(cx::object_read(127).error() == errc::out_of_range);
static_assert(cx::encode_object_request(cx::object_request{cx::object_access::read, 127, 0, {}})
                  .error() == errc::out_of_range);
// any integer type, checked: 300 is not pointer 44, sub-index 256 is not 0
static_assert(cx::object_read(300).error() == errc::out_of_range);
static_assert(cx::object_read(38, 256).error() == errc::out_of_range);
static_assert(cx::object_read(38ULL, short{2}).value().sub == 2);
static_assert(cx::decode_object_request(frame{0xFF, 0, 0, 0, 0, 0}).error() == errc::out_of_range);
static_assert(cx::decode_object_request(std::array<std::uint8_t, 5>{}).error() == errc::truncated);
static_assert(cx::decode_object_request(std::array<std::uint8_t, 7>{}).error() == errc::bad_length);
static_assert(cx::object_write(1, 0, std::array<std::uint8_t, 5>{}).error() == errc::bad_length);

// Error reply: 0xFF, sub-index, error number, 0, 0, 0.
static_assert(cx::decode_object_response(frame{0xFF, 3, 83, 0, 0, 0}).value().is_error);
static_assert(cx::decode_object_response(frame{0xFF, 3, 83, 0, 0, 0}).value().error_number == 83);
static_assert(cx::decode_object_response(frame{0xFF, 3, 83, 0, 1, 0}).error() ==
              errc::unexpected_frame);
static_assert(cx::to_string(cx::object_error::bad_pointer) == "wrong index pointer");
static_assert(cx::to_string(cx::object_error::not_writable) == "object not writable");

TEST_CASE("OBJECT_RSP matching") {
  const auto req = cx::object_read(67).value(); // LAGE_IST
  cx::object_response rsp{};
  rsp.access = cx::object_access::read;
  rsp.pointer = 67;
  rsp.data = {0xFF, 0xF0, 0xBD, 0xC0};
  const auto f = cx::encode_object_response(rsp);
  CHECK(f == frame{0xC3, 0, 0xFF, 0xF0, 0xBD, 0xC0});
  CHECK(cx::decode_object_response(f).value() == rsp);
  CHECK(cx::answers(req, rsp));
  rsp.pointer = 66;
  CHECK(!cx::answers(req, rsp));
  // a write acknowledgement echoes all six bytes
  const auto w = cx::object_write(38, 0, std::array<std::uint8_t, 2>{0x12, 0xC0}).value();
  auto ack = cx::decode_object_response(cx::encode_object_request(w).value()).value();
  CHECK(cx::answers(w, ack));
  ack.data[1] = 0;
  CHECK(!cx::answers(w, ack));
  cx::object_response err{};
  err.is_error = true;
  err.error_number = 85;
  CHECK(cx::answers(cx::object_read(38).value(), err));
  CHECK(cx::encode_object_response(err) == frame{0xFF, 0, 85, 0, 0, 0});
}

TEST_CASE("object_channel: AckToggle handshake and pointer 0 between identical requests") {
  cx::object_channel ch{false};
  const auto w = cx::object_write(41, 0, std::array<std::uint8_t, 4>{0, 0, 1, 0}).value();
  REQUIRE(ch.submit(w, false).has_value());
  CHECK(ch.pad() == cx::encode_object_request(w).value());
  CHECK(ch.submit(w, false).error() == errc::bad_state);
  // no toggle yet: pending
  auto p = ch.poll(false, frame{});
  REQUIRE(p.has_value());
  CHECK(!p.value().has_value());
  // toggle: the response arrives
  p = ch.poll(true, ch.pad());
  REQUIRE(p.has_value());
  REQUIRE(p.value().has_value());
  CHECK(!p.value()->is_error);
  CHECK(!ch.busy());

  // the same request again: pointer 0 first, then the request
  REQUIRE(ch.submit(w, true).has_value());
  CHECK(ch.current_phase() == cx::object_channel::phase::clearing);
  CHECK(ch.pad() == frame{0x00, 0, 0, 0, 1, 0});
  p = ch.poll(true, frame{});
  CHECK(!p.value().has_value());
  p = ch.poll(false, frame{}); // pointer 0 acknowledged
  CHECK(!p.value().has_value());
  CHECK(ch.current_phase() == cx::object_channel::phase::waiting);
  CHECK(ch.pad() == cx::encode_object_request(w).value());
  p = ch.poll(true, ch.pad());
  REQUIRE(p.value().has_value());

  // an error reply is a response, not a failure
  REQUIRE(ch.submit(cx::object_read(99).value(), true).has_value());
  p = ch.poll(false, frame{0xFF, 0, 82, 0, 0, 0});
  REQUIRE(p.value().has_value());
  CHECK(p.value()->error_number == 82);

  // a reply for another object is unexpected
  REQUIRE(ch.submit(cx::object_read(38).value(), false).has_value());
  CHECK(ch.poll(true, frame{0xA7, 0, 0, 0, 0, 0}).error() == errc::unexpected_frame);
  CHECK(!ch.busy());

  CHECK(ch.submit(cx::object_read(0).value(), true).error() == errc::invalid_argument);
  CHECK(ch.submit(cx::object_request{cx::object_access::read, 127, 0, {}}, true).error() ==
        errc::out_of_range);
  REQUIRE(ch.submit(cx::object_read(38).value(), true).has_value());
  ch.cancel();
  CHECK(!ch.busy());
}
