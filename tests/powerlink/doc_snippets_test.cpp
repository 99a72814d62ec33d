// The C++ block of the POWERLINK section of docs/canopen.md, as written there, and what its
// comments state: the MN writes 6081h of a XENAX CN through WriteByIndex in an ASnd frame, the
// CN reads the request through od::decode, and the MN reads the CN's answer.
// tests/docs_check/run.cmake fails when the block of the page and its copy here differ.
#include <fieldcodec/canopen/powerlink/sdo.hpp>
#include <fieldcodec/dictionaries/xenax_powerlink.hpp>
#include <fieldcodec/od/value.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

TEST_CASE("docs: writing a XENAX POWERLINK object by WriteByIndex over ASnd") {
  // what the CN answers: the response to transaction 5, sequence numbers 4 / 4, no data
  const std::array<std::uint8_t, 16> cn_answer{0x06, 0xF0, 0x01, 0x05, 0x12, 0x12, 0x00, 0x00,
                                               0x00, 0x05, 0x80, 0x01, 0x00, 0x00, 0x00, 0x00};
  // clang-format off
namespace od = fieldcodec::od;
namespace pl = fieldcodec::canopen::powerlink;
namespace xenax = fieldcodec::dictionaries::xenax_powerlink;

// od::encode checks the value against the object first; WriteByIndex carries it after the
// index header, expedited (the whole value in one frame)
std::array<std::uint8_t, 4> value{};
const auto width = od::encode(xenax::speed, 250'000, value).value();   // 4 bytes
std::array<std::uint8_t, 8> request{};
const auto n = pl::encode_by_index(request, {xenax::speed.index, xenax::speed.sub},
                                   std::span(value).first(width)).value();
const pl::asnd_sdo write{1, 240,
                         {3, pl::receive_con::connection_valid, 4, pl::send_con::connection_valid},
                         pl::command{5, false, false, pl::segmentation::expedited,
                                     pl::command_id::write_by_index, std::nullopt,
                                     std::span(request).first(n)}};
std::array<std::uint8_t, 46> frame{};   // the Ethernet payload: 46 bytes at least
const auto k = pl::encode_asnd(frame, write).value();
// k == 24: 06 01 F0 05 | 0E 12 00 00 | 00 05 00 01 08 00 00 00 | 81 60 00 00 90 D0 03 00

auto low = od::encode(xenax::speed, 5, value);   // errc::out_of_range: nothing to send

// the CN: the object, the bytes, od::decode with the object's limits
const auto received = pl::decode_asnd(frame).value();   // bytes after the segment: padding
const auto req = pl::decode_index_request(*received.cmd).value();   // 6081h:00, 4 bytes
const auto speed = od::decode<std::uint32_t>(xenax::speed, req.data).value();   // 250000

// the CN's answer: the response flag and no data, or an abort with its code
const auto answer = pl::decode_asnd(cn_answer).value();
const pl::command reply = answer.cmd.value_or(pl::command{});   // none: a NIL command
auto code = pl::decode_abort(reply);   // no abort: errc::unexpected_frame, the write is done
  // clang-format on

  CHECK(width == 4);
  CHECK(k == 24);
  CHECK(std::vector<std::uint8_t>(frame.begin(), frame.begin() + 24) ==
        std::vector<std::uint8_t>{0x06, 0x01, 0xF0, 0x05, 0x0E, 0x12, 0x00, 0x00,
                                  0x00, 0x05, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00,
                                  0x81, 0x60, 0x00, 0x00, 0x90, 0xD0, 0x03, 0x00});
  CHECK(low == fieldcodec::errc::out_of_range);
  CHECK(received.destination == 1);
  CHECK(received.source == 240);
  CHECK(req.id == pl::command_id::write_by_index);
  CHECK(req.address == od::address{0x6081, 0});
  CHECK(req.value_size == 4);
  CHECK(speed == 250'000U);
  CHECK(reply.response);
  CHECK(reply.transaction_id == 5);
  CHECK(reply.id == pl::command_id::write_by_index);
  CHECK(code == fieldcodec::errc::unexpected_frame);
}
