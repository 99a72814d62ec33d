// POWERLINK SDO over ASnd (canopen/powerlink/sdo.hpp): frames byte by byte from the layouts of
// EPSG DS 301 (ASnd frame 4.6.1.1.6, sequence layer 6.3.2.3, command layer 6.3.2.4), and bad
// input with its precise error.
#include <fieldcodec/canopen/powerlink/sdo.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace pl = fieldcodec::canopen::powerlink;
namespace sdo = fieldcodec::canopen::sdo;
using fieldcodec::errc;
using bytes = std::vector<std::uint8_t>;

namespace {
bytes encoded(const pl::asnd_sdo &f) {
  std::array<std::uint8_t, 300> out{};
  const auto n = pl::encode_asnd(out, f);
  REQUIRE(n.has_value());
  return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n.value())};
}
} // namespace

// sequence layer: sequence number in bits 7..2, connection in bits 1..0
static_assert(pl::encode_sequence({3, pl::receive_con::connection_valid, 4,
                                   pl::send_con::connection_valid})
                  .value() == std::array<std::uint8_t, 4>{0x0E, 0x12, 0x00, 0x00});
static_assert(pl::encode_sequence({63, pl::receive_con::error_response, 0,
                                   pl::send_con::acknowledge_request})
                  .value() == std::array<std::uint8_t, 4>{0xFF, 0x03, 0x00, 0x00});
static_assert(pl::decode_sequence(std::array<std::uint8_t, 4>{0x05, 0x09, 0xAA, 0xBB}).value() ==
              pl::sequence_header{1, pl::receive_con::initialization, 2,
                                  pl::send_con::initialization});
static_assert(pl::next_sequence(62) == 63 && pl::next_sequence(63) == 0);

TEST_CASE("POWERLINK SDO: an expedited ReadByIndex and its response, byte by byte") {
  // the MN (node 240) reads 1018h:01 from CN 1: transaction 5, sequence numbers 3 / 4, both
  // connections valid; command layer: request, expedited, ReadByIndex, segment of 4 bytes
  const std::array<std::uint8_t, 4> index{0x18, 0x10, 0x01, 0x00};
  const pl::asnd_sdo req{1,
                         240,
                         {3, pl::receive_con::connection_valid, 4, pl::send_con::connection_valid},
                         pl::command{5, false, false, pl::segmentation::expedited,
                                     pl::command_id::read_by_index, std::nullopt, index}};
  const bytes rb = encoded(req);
  CHECK(rb == bytes{0x06, 0x01, 0xF0, 0x05, 0x0E, 0x12, 0x00, 0x00, 0x00, 0x05,
                    0x00, 0x02, 0x04, 0x00, 0x00, 0x00, 0x18, 0x10, 0x01, 0x00});
  const auto d = pl::decode_asnd(rb).value();
  CHECK(d.destination == 1);
  CHECK(d.source == 240);
  REQUIRE(d.cmd.has_value());
  CHECK(d.cmd->id == pl::command_id::read_by_index);
  CHECK(pl::decode_by_index(d.cmd->segment).value().address == fieldcodec::od::address{0x1018, 1});
  // the response: flags 80 (response, expedited), the 4 data bytes
  const std::array<std::uint8_t, 4> vendor{0x92, 0x01, 0x42, 0x00};
  const pl::asnd_sdo res{240,
                         1,
                         {4, pl::receive_con::connection_valid, 4, pl::send_con::connection_valid},
                         pl::command{5, true, false, pl::segmentation::expedited,
                                     pl::command_id::read_by_index, std::nullopt, vendor}};
  CHECK(encoded(res) == bytes{0x06, 0xF0, 0x01, 0x05, 0x12, 0x12, 0x00, 0x00, 0x00, 0x05,
                              0x80, 0x02, 0x04, 0x00, 0x00, 0x00, 0x92, 0x01, 0x42, 0x00});
  // the same in an Ethernet frame (EtherType 88ABh, big-endian), padded to 60 bytes
  bytes eth(12, 0x11);
  eth.push_back(0x88);
  eth.push_back(0xAB);
  eth.insert(eth.end(), rb.begin(), rb.end());
  eth.resize(60, 0);
  const auto e = pl::decode_ethernet(eth).value();
  CHECK(e.cmd->segment.size() == 4);
  CHECK(e.sequence.send_sequence == 4);
}

TEST_CASE("POWERLINK SDO: a segmented WriteByIndex, an abort, frames of the sequence layer") {
  // initiate: flags 10; data size = its own 4 bytes + index header 4 + 300 data bytes
  std::array<std::uint8_t, 64> seg{};
  const std::array<std::uint8_t, 6> first{1, 2, 3, 4, 5, 6};
  const auto n = pl::encode_by_index(seg, {0x2000, 1}, first).value();
  CHECK(n == 10);
  const pl::command init{9,
                         false,
                         false,
                         pl::segmentation::initiate,
                         pl::command_id::write_by_index,
                         308,
                         std::span<const std::uint8_t>(seg).first(n)};
  std::array<std::uint8_t, 64> out{};
  const auto k = pl::encode_command(out, init).value();
  CHECK(bytes(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(k)) ==
        bytes{0x00, 0x09, 0x10, 0x01, 0x0E, 0x00, 0x00, 0x00, 0x34, 0x01, 0x00,
              0x00, 0x00, 0x20, 0x01, 0x00, 1,    2,    3,    4,    5,    6});
  const auto c = pl::decode_command(std::span(out).first(k)).value();
  CHECK(c.seg == pl::segmentation::initiate);
  CHECK(c.data_size == 308U);
  CHECK(pl::decode_by_index(c.segment).value().data.size() == 6);
  // a segment (20) and the complete one (30)
  CHECK(
      pl::encode_command(out, {9, false, false, pl::segmentation::segment, 1, std::nullopt, first})
          .value() == 14);
  CHECK(out[2] == 0x20);
  CHECK(
      pl::encode_command(out, {9, false, false, pl::segmentation::complete, 1, std::nullopt, first})
          .value() == 14);
  CHECK(out[2] == 0x30);
  // the server's abort: flags C0 (response, abort), the code 06020000h little-endian
  const std::array<std::uint8_t, 4> code{0x00, 0x00, 0x02, 0x06};
  const auto a =
      pl::encode_command(out, {9, true, true, pl::segmentation::expedited, 1, std::nullopt, code})
          .value();
  CHECK(bytes(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(a)) ==
        bytes{0x00, 0x09, 0xC0, 0x01, 0x04, 0x00, 0x00, 0x00, 0x00, 0x00, 0x02, 0x06});
  CHECK(pl::decode_abort(pl::decode_command(std::span(out).first(a)).value()) ==
        sdo::abort_code::no_object);
  // a frame of the sequence layer alone: no command when the bytes end there, a NIL command of
  // size 0 when Ethernet padded it with zeros
  const bytes init_con{0x06, 0x01, 0xF0, 0x05, 0x00, 0x01, 0x00, 0x00};
  const auto s = pl::decode_asnd(init_con).value();
  CHECK(s.sequence.scon == pl::send_con::initialization);
  CHECK(!s.cmd.has_value());
  bytes padded = init_con;
  padded.resize(46, 0);
  const auto p = pl::decode_asnd(padded).value();
  REQUIRE(p.cmd.has_value());
  CHECK(p.cmd->id == pl::command_id::nil);
  CHECK(p.cmd->segment.empty());
  CHECK(encoded({1, 240, s.sequence, std::nullopt}) == init_con);
}

TEST_CASE("POWERLINK SDO: bad input") {
  CHECK(pl::decode_asnd(bytes{0x06, 0x01, 0xF0, 0x05, 0x00, 0x01, 0x00}) == errc::truncated);
  CHECK(pl::decode_asnd(bytes{0x04, 0x01, 0xF0, 0x05, 0, 0, 0, 0}) == errc::unexpected_frame);
  CHECK(pl::decode_asnd(bytes{0x06, 0x01, 0xF0, 0x01, 0, 0, 0, 0}) == errc::unexpected_frame);
  CHECK(pl::decode_asnd(bytes{0x06, 0x01, 0xF0, 0x05, 0, 0, 0, 0, 0, 1, 0}) == errc::truncated);
  CHECK(pl::decode_ethernet(bytes(13, 0)) == errc::truncated);
  bytes other(20, 0);
  other[12] = 0x08; // IPv4
  CHECK(pl::decode_ethernet(other) == errc::unexpected_frame);
  // the segment size says more than there is
  CHECK(pl::decode_command(bytes{0, 1, 0, 2, 5, 0, 0, 0, 1, 2, 3, 4}) == errc::truncated);
  // an initiate without room for its data size
  CHECK(pl::decode_command(bytes{0, 1, 0x10, 1, 3, 0, 0, 0, 1, 2, 3}) == errc::truncated);
  CHECK(pl::decode_by_index(bytes{0x00, 0x20, 1}) == errc::truncated);
  const pl::command no_abort{};
  CHECK(pl::decode_abort(no_abort) == errc::unexpected_frame);
  const std::array<std::uint8_t, 5> five{};
  CHECK(pl::decode_abort({1, true, true, pl::segmentation::expedited, 1, std::nullopt,
                          std::span(five).first(3)}) == errc::truncated);
  CHECK(pl::decode_abort({1, true, true, pl::segmentation::expedited, 1, std::nullopt, five}) ==
        errc::too_long);
  std::array<std::uint8_t, 16> out{};
  CHECK(pl::encode_sequence({64, pl::receive_con::no_connection, 0, pl::send_con::no_connection}) ==
        errc::out_of_range);
  CHECK(pl::encode_sequence({0, static_cast<pl::receive_con>(4), 0, pl::send_con::no_connection}) ==
        errc::out_of_range);
  CHECK(
      pl::encode_command(out, {1, false, false, pl::segmentation::initiate, 1, std::nullopt, {}}) ==
      errc::invalid_argument);
  CHECK(pl::encode_command(out, {1, false, false, pl::segmentation::segment, 1, 4U, {}}) ==
        errc::invalid_argument);
  CHECK(pl::encode_command(out, {1, false, false, pl::segmentation::segment, 1, std::nullopt, five})
            .value() == 13);
  CHECK(pl::encode_command(std::span(out).first(12),
                           {1, false, false, pl::segmentation::segment, 1, std::nullopt, five}) ==
        errc::buffer_too_small);
  std::vector<std::uint8_t> huge(70000);
  std::vector<std::uint8_t> big_out(70100);
  CHECK(pl::encode_command(big_out, {1, false, false, pl::segmentation::segment, 1, std::nullopt,
                                     huge}) == errc::too_long);
  CHECK(pl::encode_by_index(std::span(out).first(5), {0x2000, 1}, five) == errc::buffer_too_small);
  CHECK(pl::encode_asnd(std::span(out).first(7), {}) == errc::buffer_too_small);
}

// a whole frame at compile time: the server's answer to a WriteByIndex (response, no data)
static_assert([] {
  std::array<std::uint8_t, 16> out{};
  const pl::asnd_sdo ack{240,
                         1,
                         {7, pl::receive_con::connection_valid, 8, pl::send_con::connection_valid},
                         pl::command{2,
                                     true,
                                     false,
                                     pl::segmentation::expedited,
                                     pl::command_id::write_by_index,
                                     std::nullopt,
                                     {}}};
  const auto n = pl::encode_asnd(out, ack);
  return n.has_value() && n.value() == 16 &&
         out == std::array<std::uint8_t, 16>{0x06, 0xF0, 0x01, 0x05, 0x1E, 0x22, 0,    0,
                                             0,    0x02, 0x80, 0x01, 0x00, 0x00, 0x00, 0x00};
}());
static_assert(pl::max_segment_size == 1484);
static_assert(pl::data_size_for(304).value() == 308);

TEST_CASE("POWERLINK SDO: the receiver's sequence number rule") {
  // the next number: a new frame; the same again: a repeat; any other: frames were lost
  CHECK(pl::is_next_frame(4, 5).value());
  CHECK(pl::is_next_frame(63, 0).value());
  CHECK_FALSE(pl::is_next_frame(5, 5).value());
  CHECK(pl::is_next_frame(4, 6) == errc::unexpected_frame);
  CHECK(pl::is_next_frame(4, 3) == errc::unexpected_frame);
  CHECK(pl::is_next_frame(0, 63) == errc::unexpected_frame);
  CHECK(pl::is_next_frame(64, 0) == errc::out_of_range);
  CHECK(pl::is_next_frame(0, 64) == errc::out_of_range);
  // what a decoded header yields is always in range
  for (unsigned b = 0; b < 256; ++b) {
    const std::array<std::uint8_t, 4> in{static_cast<std::uint8_t>(b),
                                         static_cast<std::uint8_t>(255 - b), 0, 0};
    const auto h = pl::decode_sequence(in).value();
    CHECK(pl::encode_sequence(h).value() == in);
  }
}

TEST_CASE("POWERLINK SDO: requests as a server reads them") {
  std::array<std::uint8_t, 64> seg{};
  // expedited WriteByIndex of 2 bytes to 6040h:00
  const std::array<std::uint8_t, 2> cw{0x0F, 0x00};
  const auto n = pl::encode_by_index(seg, {0x6040, 0}, cw).value();
  const pl::command write{3,
                          false,
                          false,
                          pl::segmentation::expedited,
                          pl::command_id::write_by_index,
                          std::nullopt,
                          std::span<const std::uint8_t>(seg).first(n)};
  auto r = pl::decode_index_request(write).value();
  CHECK(r.id == pl::command_id::write_by_index);
  CHECK(r.address == fieldcodec::od::address{0x6040, 0});
  CHECK(bytes(r.data.begin(), r.data.end()) == bytes{0x0F, 0x00});
  CHECK(r.value_size == 2);
  // an initiate of a 300-byte value with its first 6 bytes
  const std::array<std::uint8_t, 6> first{1, 2, 3, 4, 5, 6};
  const auto k = pl::encode_by_index(seg, {0x2000, 1}, first).value();
  pl::command init{9,
                   false,
                   false,
                   pl::segmentation::initiate,
                   pl::command_id::write_by_index,
                   pl::data_size_for(pl::index_header_size + 300).value(),
                   std::span<const std::uint8_t>(seg).first(k)};
  r = pl::decode_index_request(init).value();
  CHECK(r.value_size == 300);
  CHECK(r.data.size() == 6);
  CHECK(pl::transfer_size(init).value() == 304);
  // a ReadByIndex: the index header alone
  const std::array<std::uint8_t, 4> idx{0x00, 0x10, 0x00, 0x00};
  const pl::command read{
      4,  false, false, pl::segmentation::expedited, pl::command_id::read_by_index, std::nullopt,
      idx};
  r = pl::decode_index_request(read).value();
  CHECK(r.address == fieldcodec::od::address{0x1000, 0});
  CHECK(r.value_size == 0);

  SUBCASE("bad requests") {
    // unknown command: a reserved ID, and a defined one that is no by-index request
    pl::command c = read;
    c.id = 0x07;
    CHECK(!pl::is_defined_command(0x07));
    CHECK(pl::decode_index_request(c) == errc::unknown_command);
    c.id = pl::command_id::read_by_name;
    CHECK(pl::is_defined_command(c.id));
    CHECK(pl::decode_index_request(c) == errc::unknown_command);
    c.id = 0x85; // manufacturer-specific: defined, but not a by-index request
    CHECK(pl::is_defined_command(c.id));
    CHECK(pl::decode_index_request(c) == errc::unknown_command);
    // a response, an abort, a follow-on segment, a segmented ReadByIndex
    c = read;
    c.response = true;
    CHECK(pl::decode_index_request(c) == errc::unexpected_frame);
    c = read;
    c.abort = true;
    CHECK(pl::decode_index_request(c) == errc::unexpected_frame);
    c = write;
    c.seg = pl::segmentation::segment;
    CHECK(pl::decode_index_request(c) == errc::unexpected_frame);
    c.seg = pl::segmentation::complete;
    CHECK(pl::decode_index_request(c) == errc::unexpected_frame);
    c = init;
    c.id = pl::command_id::read_by_index;
    CHECK(pl::decode_index_request(c) == errc::unexpected_frame);
    // overlong: a ReadByIndex with bytes after its index header
    c = read;
    c.segment = std::span<const std::uint8_t>(seg).first(5);
    CHECK(pl::decode_index_request(c) == errc::too_long);
    // truncated: no room for the index header
    c = write;
    c.segment = std::span<const std::uint8_t>(seg).first(3);
    CHECK(pl::decode_index_request(c) == errc::truncated);
    // an initiate whose data size is smaller than what the frame carries
    c = init;
    c.data_size = 4U + 9U;
    CHECK(pl::transfer_size(c) == errc::bad_length);
    CHECK(pl::decode_index_request(c) == errc::bad_length);
    c.data_size = 3U;
    CHECK(pl::decode_index_request(c) == errc::bad_length);
  }
}

TEST_CASE("POWERLINK SDO: aborts with the abort codes of CiA 301") {
  std::array<std::uint8_t, 16> out{};
  // the server: response and abort flags (C0), the code little-endian
  auto n =
      pl::encode_abort(out, 7, pl::command_id::write_by_index, sdo::abort_code::write_read_only)
          .value();
  CHECK(bytes(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n)) ==
        bytes{0x00, 0x07, 0xC0, 0x01, 0x04, 0x00, 0x00, 0x00, 0x02, 0x00, 0x01, 0x06});
  auto c = pl::decode_command(std::span(out).first(n)).value();
  CHECK(pl::decode_abort(c) == sdo::abort_code::write_read_only);
  CHECK(fieldcodec::canopen::sdo::to_errc(pl::decode_abort(c).value()) == errc::access_denied);
  // the client: abort flag alone (40)
  n = pl::encode_abort(out, 7, pl::command_id::read_by_index, sdo::abort_code::timeout, false)
          .value();
  CHECK(out[2] == 0x40);
  c = pl::decode_command(std::span(out).first(n)).value();
  CHECK(!c.response);
  CHECK(pl::decode_abort(c) == sdo::abort_code::timeout);
  // a code fieldcodec does not name is kept as sent
  const std::array<std::uint8_t, 12> vendor{0, 1, 0x40, 1, 4, 0, 0, 0, 0x78, 0x56, 0x34, 0x12};
  const auto v = pl::decode_abort(pl::decode_command(vendor).value()).value();
  CHECK(static_cast<std::uint32_t>(v) == 0x12345678U);
  CHECK(!sdo::is_known(v));
  // in a frame: ASnd and sequence layer without a command, the abort after them
  std::array<std::uint8_t, 46> frame{};
  const pl::asnd_sdo head{240,
                          1,
                          {2, pl::receive_con::connection_valid, 3, pl::send_con::connection_valid},
                          std::nullopt};
  const auto h = pl::encode_asnd(frame, head).value();
  CHECK(h == 8);
  CHECK(pl::encode_abort(std::span(frame).subspan(h), 7, pl::command_id::read_by_index,
                         sdo::abort_code::no_sub_index)
            .value() == 12);
  const auto f = pl::decode_asnd(frame).value();
  CHECK(f.sequence == head.sequence);
  REQUIRE(f.cmd.has_value());
  CHECK(f.cmd->transaction_id == 7);
  CHECK(pl::decode_abort(*f.cmd) == sdo::abort_code::no_sub_index);
  // bad input
  CHECK(pl::encode_abort(out, 7, 1, sdo::abort_code::none) == errc::invalid_argument);
  CHECK(pl::encode_abort(std::span(out).first(11), 7, 1, sdo::abort_code::timeout) ==
        errc::buffer_too_small);
}

TEST_CASE("POWERLINK SDO: frames longer than Ethernet carries") {
  // 1500 bytes: the longest ASnd frame; 1501: too long, decoded or encoded
  bytes frame{0x06, 0x01, 0xF0, 0x05, 0x00, 0x01, 0x00, 0x00};
  frame.resize(pl::max_frame_size, 0);
  CHECK(pl::decode_asnd(frame).has_value());
  frame.push_back(0);
  CHECK(pl::decode_asnd(frame) == errc::too_long);
  bytes eth(12, 0);
  eth.push_back(0x88);
  eth.push_back(0xAB);
  eth.insert(eth.end(), frame.begin(), frame.end());
  CHECK(pl::decode_ethernet(eth) == errc::too_long);
  eth.pop_back();
  CHECK(pl::decode_ethernet(eth).has_value());

  const bytes full(pl::max_segment_size, 0xA5);
  bytes out(2000);
  pl::asnd_sdo f{1,
                 240,
                 {},
                 pl::command{1, false, false, pl::segmentation::segment,
                             pl::command_id::write_by_index, std::nullopt, full}};
  CHECK(pl::encode_asnd(out, f).value() == pl::max_frame_size);
  const auto back = pl::decode_asnd(std::span(out).first(pl::max_frame_size)).value();
  CHECK(back.cmd->segment.size() == pl::max_segment_size);
  const bytes over(pl::max_segment_size + 1, 0xA5);
  f.cmd->segment = over;
  CHECK(pl::encode_asnd(out, f) == errc::too_long);
  // an initiate's data size field counts against the segment
  f.cmd->segment = full;
  f.cmd->seg = pl::segmentation::initiate;
  f.cmd->data_size = 5000U;
  CHECK(pl::encode_asnd(out, f) == errc::too_long);
  CHECK(pl::data_size_for(0xFFFFFFFCU) == errc::too_long);
}
