// SDO message codec: every command specifier, the channel, abort codes, bad frames.
#include <fieldcodec/canopen/sdo.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <set>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
using fieldcodec::errc;
using sdo::message_type;

namespace {
constexpr co::can_frame F(std::uint16_t id, std::initializer_list<std::uint8_t> b) {
  return co::make_frame(id, b).value();
}
constexpr sdo::payload P(std::initializer_list<std::uint8_t> b) {
  sdo::payload p{};
  std::size_t i = 0;
  for (auto x : b) p[i++] = x;
  return p;
}
constexpr std::array<std::uint8_t, 2> u16le(std::uint16_t v) {
  return {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8U)};
}
constexpr sdo::channel node5 = sdo::channel::default_for(5).value();
} // namespace

// DPQ manual (004), CANopen SDO example: event timer of TPDO1 (1800h sub 5) of node 5 = 100 ms.
static_assert(node5.request(sdo::expedited_download({0x1800, 5}, u16le(100))).value() ==
              F(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));
static_assert(node5.response(sdo::download_response({0x1800, 5})) ==
              F(0x585, {0x60, 0x00, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00}));
static_assert(node5.response(sdo::expedited_upload_response({0x1800, 5}, u16le(100))).value() ==
              F(0x585, {0x4B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));
// the codec alone: the same 8 bytes, no identifier
static_assert(sdo::expedited_download({0x1800, 5}, u16le(100)).value() ==
              P({0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));

TEST_CASE("DPQ example: TPDO1 event timer on node 5") {
  const auto req = node5.request(sdo::expedited_download({0x1800, 5}, u16le(100))).value();
  auto d = sdo::decode(req).value();
  CHECK(d.node == 5);
  CHECK(d.dir == sdo::direction::to_server);
  CHECK(d.m.type == message_type::initiate_download_request);
  CHECK(d.m.expedited);
  CHECK(d.m.size_indicated);
  CHECK(d.m.address == fieldcodec::od::address{0x1800, 5});
  CHECK(d.m.size == 2);
  CHECK(d.m.value == 100);
  CHECK(d.m.value_bytes() == std::array<std::uint8_t, 4>{0x64, 0x00, 0x00, 0x00});
  CHECK(d.m.bytes().empty()); // expedited data is the number, not segment bytes
  auto rsp = sdo::decode(F(0x585, {0x60, 0x00, 0x18, 0x05, 0, 0, 0, 0})).value();
  CHECK(rsp.dir == sdo::direction::to_client);
  CHECK(rsp.m.type == message_type::initiate_download_response);
  // read-back: upload request 0x40, reply 0x4B ... 64 00
  CHECK(node5.request(sdo::initiate_upload({0x1800, 5})) ==
        F(0x605, {0x40, 0x00, 0x18, 0x05, 0, 0, 0, 0}));
  auto up = sdo::decode(F(0x585, {0x4B, 0x00, 0x18, 0x05, 0x64, 0x00, 0, 0})).value();
  CHECK(up.m.type == message_type::initiate_upload_response);
  CHECK(up.m.expedited);
  CHECK(up.m.size == 2);
  CHECK(up.m.value == 0x64);
  CHECK(up.m.data_size == 0);
}

TEST_CASE("channels: predefined and from SDO parameter objects") {
  CHECK(sdo::channel::default_for(1).value() == sdo::channel{0x601, 0x581});
  CHECK(sdo::channel::default_for(127).value() == sdo::channel{0x67F, 0x5FF});
  CHECK(sdo::channel::default_for(0) == errc::invalid_argument);
  CHECK(sdo::channel::default_for(128) == errc::invalid_argument);
  // 1200h sub 1 = 0x605, sub 2 = 0x585 (as a DCF writes them, $NODEID resolved)
  CHECK(sdo::channel::from_cob_ids(0x605, 0x585).value() == node5);
  CHECK(sdo::channel::from_cob_ids(0x640, 0x5C0).value() == sdo::channel{0x640, 0x5C0});
  CHECK(sdo::channel::from_cob_ids(0x8000'0605U, 0x585) == errc::bad_state);    // not valid
  CHECK(sdo::channel::from_cob_ids(0x605, 0x2000'0585U) == errc::out_of_range); // 29 bit
  CHECK(sdo::channel::from_cob_ids(0x1605, 0x585) == errc::out_of_range);
  // frames on the channel
  const sdo::channel ch{0x640, 0x5C0};
  const auto f = ch.request(sdo::initiate_upload({0x1000, 0}));
  CHECK(f.id == 0x640);
  CHECK(f.dlc == 8);
  CHECK(ch.is_request(f));
  CHECK(!ch.is_response(f));
  CHECK(!ch.is_request(co::make_remote_frame(0x640, 8).value()));
  CHECK(ch.response(sdo::download_response({0x1000, 0})).id == 0x5C0);
  // an error passes through
  CHECK(ch.request(sdo::expedited_download({0x1000, 0}, {})) == errc::bad_length);
  // a channel without identifiers matches nothing (0 is the NMT COB-ID)
  const sdo::channel none{};
  CHECK(!none.is_request(F(0x000, {1, 5})));
}

TEST_CASE("expedited command bytes for 1..4 bytes, with and without size") {
  const std::array<std::uint8_t, 4> v{0x11, 0x22, 0x33, 0x44};
  const std::uint8_t dl[] = {0x2F, 0x2B, 0x27, 0x23};
  const std::uint8_t ul[] = {0x4F, 0x4B, 0x47, 0x43};
  for (std::size_t n = 1; n <= 4; ++n) {
    auto f = sdo::expedited_download({0x2000, 0}, std::span(v).first(n)).value();
    CHECK(f[0] == dl[n - 1]);
    auto m = sdo::decode(f, sdo::direction::to_server).value();
    CHECK(m.size == n);
    CHECK(m.value == (0x44332211U & (0xFFFF'FFFFU >> (8U * (4U - n)))));
    CHECK(m.data_size == 0);
    auto g = sdo::expedited_upload_response({0x2000, 0}, std::span(v).first(n)).value();
    CHECK(g[0] == ul[n - 1]);
    CHECK(sdo::decode(g, sdo::direction::to_client).value().size == n);
    for (std::size_t i = n; i < 4; ++i) CHECK(f[4 + i] == 0); // unused bytes zero
  }
  auto u = sdo::expedited_download_unsized({0x2000, 0}, v).value();
  CHECK(u[0] == 0x22);
  auto um = sdo::decode(u, sdo::direction::to_server).value();
  CHECK(!um.size_indicated);
  CHECK(um.expedited);
  CHECK(um.size == 4);
  CHECK(um.value == 0x44332211U);
  auto uu = sdo::expedited_upload_response_unsized({0x2000, 0}, v).value();
  CHECK(uu[0] == 0x42);
  CHECK(sdo::expedited_download({0x2000, 0}, {}) == errc::bad_length);
  const std::array<std::uint8_t, 5> five{};
  CHECK(sdo::expedited_download({0x2000, 0}, five) == errc::too_long);
  CHECK(sdo::expedited_download_unsized({0x2000, 0}, std::span(v).first(3)) == errc::bad_length);
}

// Round 4: an expedited message carries its data as a number (`value`, `size` bytes of it),
// not in the segment bytes; encode writes it little-endian and refuses what it cannot send.
namespace {
constexpr sdo::message expedited_message(std::uint32_t size, std::uint32_t value,
                                         bool size_indicated = true) {
  sdo::message m;
  m.type = message_type::initiate_download_request;
  m.address = {0x6081, 0};
  m.expedited = true;
  m.size_indicated = size_indicated;
  m.size = size;
  m.value = value;
  return m;
}
} // namespace
static_assert(sdo::encode(expedited_message(4, 0x0001'86A0U)).value() ==
              sdo::payload{0x23, 0x81, 0x60, 0x00, 0xA0, 0x86, 0x01, 0x00});
static_assert(sdo::encode(expedited_message(2, 0x1234U)).value() ==
              sdo::payload{0x2B, 0x81, 0x60, 0x00, 0x34, 0x12, 0x00, 0x00});

TEST_CASE("expedited messages carry their data as a number") {
  for (std::uint32_t n = 1; n <= 4; ++n) {
    const std::uint32_t v = 0xA1B2C3D4U & (0xFFFF'FFFFU >> (8U * (4U - n)));
    const auto p = sdo::encode(expedited_message(n, v)).value();
    const std::array<std::uint8_t, 4> bytes{0xD4, 0xC3, 0xB2, 0xA1};
    // the same bytes as the named constructor that takes bytes
    CHECK(p == sdo::expedited_download({0x6081, 0}, std::span(bytes).first(n)).value());
    const auto m = sdo::decode(p, sdo::direction::to_server).value();
    CHECK(m == expedited_message(n, v));
    CHECK(m.value_bytes()[0] == 0xD4);
    for (std::size_t i = n; i < 4U; ++i) CHECK(m.value_bytes()[i] == 0);
    // a value with bits past its size cannot be sent: nothing is dropped
    if (n < 4U)
      CHECK(sdo::encode(expedited_message(n, v | (1U << (8U * n)))) == errc::out_of_range);
  }
  // unsized: always 4 bytes (0x22), the upload response too (0x42)
  CHECK(sdo::encode(expedited_message(4, 0x01020304U, false)).value() ==
        sdo::payload{0x22, 0x81, 0x60, 0x00, 0x04, 0x03, 0x02, 0x01});
  auto up = expedited_message(1, 0x7F);
  up.type = message_type::initiate_upload_response;
  CHECK(sdo::encode(up).value() == sdo::payload{0x4F, 0x81, 0x60, 0x00, 0x7F, 0, 0, 0});
  // what cannot be sent
  CHECK(sdo::encode(expedited_message(0, 0)) == errc::bad_length);
  CHECK(sdo::encode(expedited_message(5, 0)) == errc::too_long);
  CHECK(sdo::encode(expedited_message(3, 0, false)) == errc::bad_length);
  // data put where segments carry it (the spelling before round 4) is refused, not sent as 0
  auto old = expedited_message(2, 0);
  old.data = {0x64, 0x00};
  old.data_size = 2;
  CHECK(sdo::encode(old) == errc::invalid_argument);
  // a segmented initiate carries no data: a value (or segment bytes) set on it is refused, not
  // dropped (expedited forgotten)
  auto seg = expedited_message(300, 0xFFFF'FFFFU);
  seg.expedited = false;
  CHECK(sdo::encode(seg) == errc::invalid_argument);
  seg.value = 0;
  CHECK(sdo::encode(seg).value() == sdo::payload{0x21, 0x81, 0x60, 0x00, 0x2C, 0x01, 0x00, 0x00});
  seg.data_size = 1;
  CHECK(sdo::encode(seg) == errc::invalid_argument);
  seg.data_size = 0;
  seg.type = message_type::initiate_upload_response;
  seg.value = 1;
  CHECK(sdo::encode(seg) == errc::invalid_argument);
  // and a decoded one has none, whatever its bytes 4..7 hold: decode → encode goes through
  for (const std::uint8_t b0 :
       {std::uint8_t{0x20}, std::uint8_t{0x21}, std::uint8_t{0x40}, std::uint8_t{0x41}}) {
    const sdo::payload p{b0, 0x81, 0x60, 0x00, 0x12, 0x34, 0x56, 0x78};
    const auto dir = b0 < 0x40U ? sdo::direction::to_server : sdo::direction::to_client;
    const auto m = sdo::decode(p, dir).value();
    CHECK(m.value == 0U);
    CHECK(sdo::encode(m).has_value());
  }
}

TEST_CASE("segmented messages") {
  CHECK(node5.request(sdo::initiate_download({0x1008, 0}, 300)) ==
        F(0x605, {0x21, 0x08, 0x10, 0x00, 0x2C, 0x01, 0x00, 0x00}));
  CHECK(sdo::initiate_download({0x1008, 0}, 0, false) == P({0x20, 0x08, 0x10, 0x00}));
  CHECK(sdo::upload_response({0x1008, 0}, 11) == P({0x41, 0x08, 0x10, 0x00, 11}));
  CHECK(sdo::upload_response({0x1008, 0}, 0, false) == P({0x40, 0x08, 0x10, 0x00}));
  const std::array<std::uint8_t, 7> seven{'X', 'E', 'N', 'A', 'X', ' ', 'X'};
  CHECK(sdo::download_segment(false, seven, false).value() ==
        P({0x00, 'X', 'E', 'N', 'A', 'X', ' ', 'X'}));
  CHECK(sdo::download_segment(true, std::span(seven).first(3), true).value() ==
        P({0x19, 'X', 'E', 'N'}));                                    // t=1, n=4, c=1
  CHECK(sdo::download_segment(false, {}, true).value() == P({0x0F})); // n=7, c=1
  CHECK(sdo::download_segment(false, std::span(seven).first(3), false) == errc::bad_length);
  const std::array<std::uint8_t, 8> eight{};
  CHECK(sdo::download_segment(false, eight, true) == errc::too_long);
  CHECK(sdo::upload_segment(true, seven, true).value() ==
        P({0x11, 'X', 'E', 'N', 'A', 'X', ' ', 'X'}));
  CHECK(sdo::upload_segment_request(false) == P({0x60}));
  CHECK(sdo::upload_segment_request(true) == P({0x70}));
  CHECK(sdo::download_segment_response(false) == P({0x20}));
  CHECK(sdo::download_segment_response(true) == P({0x30}));

  auto seg = sdo::decode(P({0x19, 'X', 'E', 'N', 0, 0, 0, 0}), sdo::direction::to_server).value();
  CHECK(seg.type == message_type::download_segment_request);
  CHECK(seg.toggle);
  CHECK(seg.last);
  CHECK(seg.data_size == 3);
  auto useg = sdo::decode(P({0x00, 1, 2, 3, 4, 5, 6, 7}), sdo::direction::to_client).value();
  CHECK(useg.type == message_type::upload_segment_response);
  CHECK(!useg.toggle);
  CHECK(!useg.last);
  CHECK(useg.data_size == 7);
  auto init = sdo::decode(P({0x41, 0x08, 0x10, 0x00, 0x2C, 0x01}), sdo::direction::to_client);
  CHECK(init.value().type == message_type::initiate_upload_response);
  CHECK(!init.value().expedited);
  CHECK(init.value().size_indicated);
  CHECK(init.value().size == 300);
  CHECK(sdo::decode(P({0x70}), sdo::direction::to_server).value().toggle);
  CHECK(sdo::decode(P({0x30}), sdo::direction::to_client).value().type ==
        message_type::download_segment_response);
}

TEST_CASE("abort messages and the abort code table") {
  const auto a = sdo::abort({0x6040, 0}, sdo::abort_code::no_object);
  CHECK(node5.response(a) == F(0x585, {0x80, 0x40, 0x60, 0x00, 0x00, 0x00, 0x02, 0x06}));
  auto m = sdo::decode(node5.response(a)).value();
  CHECK(m.m.type == message_type::abort);
  CHECK(m.m.abort == sdo::abort_code::no_object);
  CHECK(m.m.address.index == 0x6040);
  const auto b = sdo::abort({0x1000, 1}, sdo::abort_code::timeout);
  CHECK(b == P({0x80, 0x00, 0x10, 0x01, 0x00, 0x00, 0x04, 0x05}));
  CHECK(sdo::decode(b, sdo::direction::to_server).value().abort == sdo::abort_code::timeout);
  // an abort code outside the CiA table is kept as it is and reported as unknown
  const auto odd =
      sdo::decode(P({0x80, 0, 0x10, 0, 0x78, 0x56, 0x34, 0x12}), sdo::direction::to_client).value();
  CHECK(static_cast<std::uint32_t>(odd.abort) == 0x12345678U);
  CHECK(!sdo::is_known(odd.abort));
  CHECK(sdo::to_string(odd.abort).empty());
  CHECK(sdo::to_errc(odd.abort) == errc::aborted);
  CHECK(sdo::abort({0x1000, 0}, odd.abort) == P({0x80, 0, 0x10, 0, 0x78, 0x56, 0x34, 0x12}));

  std::set<std::uint32_t> seen;
  std::set<std::string_view> texts;
  std::uint32_t prev = 0;
  for (const auto &row : sdo::abort_codes) {
    const auto v = static_cast<std::uint32_t>(row.code);
    CHECK(v > prev); // numeric order, no duplicates
    prev = v;
    CHECK(sdo::is_known(row.code));
    CHECK(sdo::find_abort(row.code) == &row);
    CHECK(sdo::to_string(row.code) == row.text);
    CHECK(sdo::to_errc(row.code) == row.error);
    CHECK(!row.text.empty());
    seen.insert(v);
    texts.insert(row.text);
  }
  CHECK(seen.size() == 33); // 31 of CiA 301, 2 of CoE complete access (ETG.1000.6)
  CHECK(texts.size() == 33);
  CHECK(!sdo::is_known(sdo::abort_code::none));
  CHECK(sdo::to_string(sdo::abort_code::none) == "no abort");
  CHECK(!sdo::is_known(static_cast<sdo::abort_code>(0x06090012U)));
  // spot checks against CiA 301
  CHECK(static_cast<std::uint32_t>(sdo::abort_code::toggle_not_alternated) == 0x05030000U);
  CHECK(static_cast<std::uint32_t>(sdo::abort_code::no_sub_index) == 0x06090011U);
  CHECK(static_cast<std::uint32_t>(sdo::abort_code::cannot_store_device_state) == 0x08000022U);
  CHECK(static_cast<std::uint32_t>(sdo::abort_code::no_sdo_connection) == 0x060A0023U);
  CHECK(sdo::to_errc(sdo::abort_code::toggle_not_alternated) == errc::bad_toggle);
  CHECK(sdo::to_errc(sdo::abort_code::crc_error) == errc::bad_checksum);
  CHECK(sdo::to_errc(sdo::abort_code::no_object) == errc::unknown_object);
}

// CiA 301 7.2.4.3.9 ff: block download and block upload messages.
TEST_CASE("block transfer messages") {
  using sdo::direction;
  // block download: initiate with CRC and size 300, response with block size 127 and CRC
  CHECK(sdo::block_download_initiate({0x1008, 0}, 300, true, true) ==
        P({0xC6, 0x08, 0x10, 0x00, 0x2C, 0x01, 0x00, 0x00}));
  CHECK(sdo::block_download_initiate({0x1008, 0}, 0, false, false) == P({0xC0, 0x08, 0x10}));
  CHECK(sdo::block_download_initiate_response({0x1008, 0}, 127, true).value() ==
        P({0xA4, 0x08, 0x10, 0x00, 0x7F}));
  CHECK(sdo::block_download_initiate_response({0x1008, 0}, 0, true) == errc::out_of_range);
  CHECK(sdo::block_download_initiate_response({0x1008, 0}, 128, true) == errc::out_of_range);
  // block upload: initiate with block size 127 and threshold 21, response with size 300
  CHECK(sdo::block_upload_initiate({0x1008, 0}, 127, 21, true).value() ==
        P({0xA4, 0x08, 0x10, 0x00, 0x7F, 21}));
  CHECK(sdo::block_upload_initiate({0x1008, 0}, 0, 0, true) == errc::out_of_range);
  CHECK(sdo::block_upload_initiate_response({0x1008, 0}, 300, true, true) ==
        P({0xC6, 0x08, 0x10, 0x00, 0x2C, 0x01}));
  CHECK(sdo::block_upload_start() == P({0xA3}));
  // segments, acknowledgement, end
  const std::array<std::uint8_t, 7> seven{1, 2, 3, 4, 5, 6, 7};
  CHECK(sdo::encode_block_segment(1, seven, false).value() == P({0x01, 1, 2, 3, 4, 5, 6, 7}));
  CHECK(sdo::encode_block_segment(127, std::span(seven).first(2), true).value() == P({0xFF, 1, 2}));
  CHECK(sdo::encode_block_segment(0, seven, false) == errc::out_of_range);
  CHECK(sdo::encode_block_segment(128, seven, false) == errc::out_of_range);
  CHECK(sdo::block_ack(5, 127).value() == P({0xA2, 5, 127}));
  CHECK(sdo::block_ack(128, 1) == errc::out_of_range);
  CHECK(sdo::block_ack(0, 0) == errc::out_of_range);
  CHECK(sdo::block_end(3, 0x31C3).value() == P({0xCD, 0xC3, 0x31}));
  CHECK(sdo::block_end(8, 0) == errc::out_of_range);
  CHECK(sdo::block_end_response() == P({0xA1}));

  // decoding: the same bytes mean different messages in the two directions
  auto di = sdo::decode(P({0xC6, 0x08, 0x10, 0x00, 0x2C, 0x01}), direction::to_server).value();
  CHECK(di.type == message_type::block_download_initiate);
  CHECK(di.crc);
  CHECK(di.size_indicated);
  CHECK(di.size == 300);
  auto ui = sdo::decode(P({0xC6, 0x08, 0x10, 0x00, 0x2C, 0x01}), direction::to_client).value();
  CHECK(ui.type == message_type::block_upload_initiate_response);
  auto dr = sdo::decode(P({0xA4, 0x08, 0x10, 0x00, 0x7F, 21}), direction::to_client).value();
  CHECK(dr.type == message_type::block_download_initiate_response);
  CHECK(dr.block_size == 127);
  auto ur = sdo::decode(P({0xA4, 0x08, 0x10, 0x00, 0x7F, 21}), direction::to_server).value();
  CHECK(ur.type == message_type::block_upload_initiate);
  CHECK(ur.switch_threshold == 21);
  for (auto d : {direction::to_server, direction::to_client}) {
    auto ack = sdo::decode(P({0xA2, 5, 127}), d).value();
    CHECK(ack.type == message_type::block_ack);
    CHECK(ack.sequence == 5);
    CHECK(ack.block_size == 127);
    auto end = sdo::decode(P({0xCD, 0xC3, 0x31}), d).value();
    CHECK(end.type == message_type::block_end);
    CHECK(end.unused == 3);
    CHECK(end.checksum == 0x31C3);
    CHECK(sdo::decode(P({0xA1}), d).value().type == message_type::block_end_response);
  }
  CHECK(sdo::decode(P({0xA3}), direction::to_server).value().type ==
        message_type::block_upload_start);
  CHECK(sdo::decode(P({0xA3}), direction::to_client) == errc::unknown_command);
  auto seg = sdo::decode_block_segment(P({0x85, 9, 8, 7, 6, 5, 4, 3})).value();
  CHECK(seg.sequence == 5);
  CHECK(seg.last);
  CHECK(seg.data_size == 7);
  CHECK(seg.data[6] == 3);
  CHECK(sdo::decode_block_segment(P({0x80})) == errc::out_of_range);
  CHECK(sdo::decode_block_segment(P({0x00})) == errc::out_of_range);
}

TEST_CASE("bad SDO frames") {
  using sdo::direction;
  CHECK(sdo::decode(F(0x605, {0x40, 0x00, 0x18, 0x05}), direction::to_server) == errc::bad_length);
  CHECK(sdo::decode(F(0x605, {0x40, 0, 0, 0, 0, 0, 0}), direction::to_server) == errc::bad_length);
  CHECK(sdo::decode(F(0x585, {}), direction::to_client) == errc::bad_length);
  CHECK(sdo::decode(P({0xE0}), direction::to_server) == errc::unknown_command);
  CHECK(sdo::decode(P({0xFF}), direction::to_client) == errc::unknown_command);
  CHECK(sdo::decode(co::make_remote_frame(0x605, 8).value(), direction::to_server) ==
        errc::unexpected_frame);
  CHECK(sdo::decode(F(0x705, {0x40, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  CHECK(sdo::decode(F(0x580, {0x40, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  CHECK(sdo::decode(F(0x600, {0x40, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  CHECK(sdo::decode(F(0x680, {0x40, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  CHECK(sdo::decode(F(0x67F, {0xE0, 0, 0, 0, 0, 0, 0, 0})) == errc::unknown_command);
  CHECK(sdo::decode(F(0x5FF, {0xE0, 0, 0, 0, 0, 0, 0, 0})) == errc::unknown_command);
  co::can_frame longdlc = F(0x605, {0x40, 0, 0, 0, 0, 0, 0, 0});
  longdlc.dlc = 9;
  CHECK(sdo::decode(longdlc, direction::to_server) == errc::bad_length);
}

TEST_CASE("every command byte decodes, and what decodes encodes back to a message equal to it") {
  for (unsigned b = 0; b < 256; ++b) {
    for (auto d : {sdo::direction::to_server, sdo::direction::to_client}) {
      const auto p = P({static_cast<std::uint8_t>(b), 0x34, 0x12, 0x56, 1, 2, 3, 4});
      auto m = sdo::decode(p, d);
      if ((b >> 5U) == 7U) {
        CHECK(m == errc::unknown_command);
        continue;
      }
      if (!m) {
        CHECK(((b & 0xE3U) == 0xA3U && d == sdo::direction::to_client));
        continue;
      }
      CHECK(m.value().data_size <= 7);
      auto e = sdo::encode(m.value());
      if (!e) continue; // a short non-last segment, a block size of 0: no canonical form
      auto back = sdo::decode(e.value(), d);
      REQUIRE(back.has_value());
      CHECK(back.value() == m.value());
    }
  }
}
