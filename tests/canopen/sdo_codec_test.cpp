// SDO frame codec: every command specifier, abort codes, bad frames.
#include <fieldcodec/canopen/sdo.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <set>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
using fieldcodec::errc;

namespace {
constexpr co::can_frame F(std::uint16_t id, std::initializer_list<std::uint8_t> b) {
  return co::make_frame(id, b).value();
}
constexpr std::array<std::uint8_t, 2> u16le(std::uint16_t v) {
  return {static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8U)};
}
} // namespace

// DPQ manual (004), CANopen SDO example: event timer of TPDO1 (1800h sub 5) of node 5 = 100 ms.
static_assert(sdo::expedited_download(5, 0x1800, 5, u16le(100)).value() ==
              F(0x605, {0x2B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));
static_assert(sdo::download_response(5, 0x1800, 5).value() ==
              F(0x585, {0x60, 0x00, 0x18, 0x05, 0x00, 0x00, 0x00, 0x00}));
static_assert(sdo::expedited_upload_response(5, 0x1800, 5, u16le(100)).value() ==
              F(0x585, {0x4B, 0x00, 0x18, 0x05, 0x64, 0x00, 0x00, 0x00}));

TEST_CASE("DPQ example: TPDO1 event timer on node 5") {
  const auto req = sdo::expedited_download(5, 0x1800, 5, u16le(100)).value();
  auto d = sdo::decode(req).value();
  CHECK(d.node == 5);
  CHECK(d.dir == sdo::direction::to_server);
  CHECK(d.m.k == sdo::kind::initiate_download_request);
  CHECK(d.m.expedited);
  CHECK(d.m.size_indicated);
  CHECK(d.m.index == 0x1800);
  CHECK(d.m.sub == 5);
  CHECK(d.m.size == 2);
  CHECK(d.m.bytes()[0] == 0x64);
  CHECK(d.m.bytes()[1] == 0x00);
  auto rsp = sdo::decode(F(0x585, {0x60, 0x00, 0x18, 0x05, 0, 0, 0, 0})).value();
  CHECK(rsp.dir == sdo::direction::to_client);
  CHECK(rsp.m.k == sdo::kind::initiate_download_response);
  // read-back: upload request 0x40, reply 0x4B ... 64 00
  CHECK(sdo::initiate_upload(5, 0x1800, 5).value() ==
        F(0x605, {0x40, 0x00, 0x18, 0x05, 0, 0, 0, 0}));
  auto up = sdo::decode(F(0x585, {0x4B, 0x00, 0x18, 0x05, 0x64, 0x00, 0, 0})).value();
  CHECK(up.m.k == sdo::kind::initiate_upload_response);
  CHECK(up.m.expedited);
  CHECK(up.m.size == 2);
  CHECK(up.m.bytes().size() == 2);
  CHECK(up.m.bytes()[0] == 0x64);
}

TEST_CASE("expedited command bytes for 1..4 bytes, with and without size") {
  const std::array<std::uint8_t, 4> v{0x11, 0x22, 0x33, 0x44};
  const std::uint8_t dl[] = {0x2F, 0x2B, 0x27, 0x23};
  const std::uint8_t ul[] = {0x4F, 0x4B, 0x47, 0x43};
  for (std::size_t n = 1; n <= 4; ++n) {
    auto f = sdo::expedited_download(1, 0x2000, 0, std::span(v).first(n)).value();
    CHECK(f.data[0] == dl[n - 1]);
    auto m = sdo::decode_request(f).value();
    CHECK(m.size == n);
    CHECK(m.bytes().size() == n);
    auto g = sdo::expedited_upload_response(1, 0x2000, 0, std::span(v).first(n)).value();
    CHECK(g.data[0] == ul[n - 1]);
    CHECK(sdo::decode_response(g).value().data_size == n);
    for (std::size_t i = n; i < 4; ++i) CHECK(f.data[4 + i] == 0); // unused bytes zero
  }
  auto u = sdo::expedited_download_unsized(1, 0x2000, 0, v).value();
  CHECK(u.data[0] == 0x22);
  auto um = sdo::decode_request(u).value();
  CHECK(!um.size_indicated);
  CHECK(um.expedited);
  CHECK(um.data_size == 4);
  auto uu = sdo::expedited_upload_response_unsized(1, 0x2000, 0, v).value();
  CHECK(uu.data[0] == 0x42);
  CHECK(sdo::expedited_download(1, 0x2000, 0, {}) == errc::bad_length);
  const std::array<std::uint8_t, 5> five{};
  CHECK(sdo::expedited_download(1, 0x2000, 0, five) == errc::too_long);
  CHECK(sdo::expedited_download_unsized(1, 0x2000, 0, std::span(v).first(3)) == errc::bad_length);
  CHECK(sdo::expedited_download(0, 0x2000, 0, v) == errc::invalid_argument);
  CHECK(sdo::expedited_download(128, 0x2000, 0, v) == errc::invalid_argument);
}

TEST_CASE("segmented frames") {
  CHECK(sdo::initiate_download(5, 0x1008, 0, 300).value() ==
        F(0x605, {0x21, 0x08, 0x10, 0x00, 0x2C, 0x01, 0x00, 0x00}));
  CHECK(sdo::initiate_download(5, 0x1008, 0, 0, false).value() ==
        F(0x605, {0x20, 0x08, 0x10, 0x00, 0, 0, 0, 0}));
  CHECK(sdo::upload_response(5, 0x1008, 0, 11).value() ==
        F(0x585, {0x41, 0x08, 0x10, 0x00, 11, 0, 0, 0}));
  CHECK(sdo::upload_response(5, 0x1008, 0, 0, false).value() ==
        F(0x585, {0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0}));
  const std::array<std::uint8_t, 7> seven{'X', 'E', 'N', 'A', 'X', ' ', 'X'};
  CHECK(sdo::download_segment(5, false, seven, false).value() ==
        F(0x605, {0x00, 'X', 'E', 'N', 'A', 'X', ' ', 'X'}));
  CHECK(sdo::download_segment(5, true, std::span(seven).first(3), true).value() ==
        F(0x605, {0x19, 'X', 'E', 'N', 0, 0, 0, 0})); // t=1, n=4, c=1
  CHECK(sdo::download_segment(5, false, {}, true).value() ==
        F(0x605, {0x0F, 0, 0, 0, 0, 0, 0, 0})); // n=7, c=1
  CHECK(sdo::download_segment(5, false, std::span(seven).first(3), false) == errc::bad_length);
  const std::array<std::uint8_t, 8> eight{};
  CHECK(sdo::download_segment(5, false, eight, true) == errc::too_long);
  CHECK(sdo::upload_segment(5, true, seven, true).value() ==
        F(0x585, {0x11, 'X', 'E', 'N', 'A', 'X', ' ', 'X'}));
  CHECK(sdo::upload_segment_request(5, false).value() == F(0x605, {0x60, 0, 0, 0, 0, 0, 0, 0}));
  CHECK(sdo::upload_segment_request(5, true).value() == F(0x605, {0x70, 0, 0, 0, 0, 0, 0, 0}));
  CHECK(sdo::download_segment_response(5, false).value() == F(0x585, {0x20, 0, 0, 0, 0, 0, 0, 0}));
  CHECK(sdo::download_segment_response(5, true).value() == F(0x585, {0x30, 0, 0, 0, 0, 0, 0, 0}));

  auto seg = sdo::decode_request(F(0x605, {0x19, 'X', 'E', 'N', 0, 0, 0, 0})).value();
  CHECK(seg.k == sdo::kind::download_segment_request);
  CHECK(seg.toggle);
  CHECK(seg.last);
  CHECK(seg.data_size == 3);
  auto useg = sdo::decode_response(F(0x585, {0x00, 1, 2, 3, 4, 5, 6, 7})).value();
  CHECK(useg.k == sdo::kind::upload_segment_response);
  CHECK(!useg.toggle);
  CHECK(!useg.last);
  CHECK(useg.data_size == 7);
  auto init = sdo::decode_response(F(0x585, {0x41, 0x08, 0x10, 0x00, 0x2C, 0x01, 0, 0})).value();
  CHECK(init.k == sdo::kind::initiate_upload_response);
  CHECK(!init.expedited);
  CHECK(init.size_indicated);
  CHECK(init.size == 300);
  CHECK(sdo::decode_request(F(0x605, {0x70, 0, 0, 0, 0, 0, 0, 0})).value().toggle);
  CHECK(sdo::decode_response(F(0x585, {0x30, 0, 0, 0, 0, 0, 0, 0})).value().k ==
        sdo::kind::download_segment_response);
}

TEST_CASE("abort frames and the abort code table") {
  const auto a = sdo::abort(sdo::direction::to_client, 5, 0x6040, 0, sdo::abort_code::no_object);
  CHECK(a.value() == F(0x585, {0x80, 0x40, 0x60, 0x00, 0x00, 0x00, 0x02, 0x06}));
  auto m = sdo::decode(a.value()).value();
  CHECK(m.m.k == sdo::kind::abort);
  CHECK(m.m.code == 0x06020000U);
  CHECK(m.m.index == 0x6040);
  const auto b = sdo::abort(sdo::direction::to_server, 5, 0x1000, 1, sdo::abort_code::timeout);
  CHECK(b.value() == F(0x605, {0x80, 0x00, 0x10, 0x01, 0x00, 0x00, 0x04, 0x05}));
  CHECK(sdo::decode_request(b.value()).value().code == 0x05040000U);

  std::set<std::uint32_t> seen;
  std::set<std::string_view> texts;
  std::uint32_t prev = 0;
  for (auto c : sdo::all_abort_codes) {
    const auto v = static_cast<std::uint32_t>(c);
    CHECK(v > prev); // numeric order, no duplicates
    prev = v;
    CHECK(sdo::is_known(v));
    CHECK(!sdo::to_string(c).empty());
    seen.insert(v);
    texts.insert(sdo::to_string(c));
  }
  CHECK(seen.size() == 31);
  CHECK(texts.size() == 31);
  CHECK(!sdo::is_known(0));
  CHECK(!sdo::is_known(0x06090012U));
  CHECK(sdo::to_string(static_cast<sdo::abort_code>(0x12345678U)).empty());
  // spot checks against CiA 301
  CHECK(static_cast<std::uint32_t>(sdo::abort_code::toggle_not_alternated) == 0x05030000U);
  CHECK(static_cast<std::uint32_t>(sdo::abort_code::no_sub_index) == 0x06090011U);
  CHECK(static_cast<std::uint32_t>(sdo::abort_code::cannot_store_device_state) == 0x08000022U);
  CHECK(static_cast<std::uint32_t>(sdo::abort_code::no_sdo_connection) == 0x060A0023U);
}

TEST_CASE("block transfer frames are recognised") {
  auto r = sdo::decode_request(F(0x605, {0xC6, 0x08, 0x10, 0x00, 0, 0, 0, 0})).value();
  CHECK(r.k == sdo::kind::block_download_request);
  CHECK(r.index == 0x1008);
  CHECK(sdo::decode_request(F(0x605, {0xA4, 0x08, 0x10, 0x00, 0x7F, 0, 0, 0})).value().k ==
        sdo::kind::block_upload_request);
  CHECK(sdo::decode_response(F(0x585, {0xA4, 0x08, 0x10, 0x00, 0x7F, 0, 0, 0})).value().k ==
        sdo::kind::block_download_response);
  CHECK(sdo::decode_response(F(0x585, {0xC6, 0x08, 0x10, 0x00, 0, 0, 0, 0})).value().k ==
        sdo::kind::block_upload_response);
}

TEST_CASE("bad SDO frames") {
  CHECK(sdo::decode_request(F(0x605, {0x40, 0x00, 0x18, 0x05})) == errc::bad_length);
  CHECK(sdo::decode_request(F(0x605, {0x40, 0, 0, 0, 0, 0, 0})) == errc::bad_length);
  CHECK(sdo::decode_response(F(0x585, {})) == errc::bad_length);
  CHECK(sdo::decode_request(F(0x605, {0xE0, 0, 0, 0, 0, 0, 0, 0})) == errc::unknown_command);
  CHECK(sdo::decode_response(F(0x585, {0xFF, 0, 0, 0, 0, 0, 0, 0})) == errc::unknown_command);
  CHECK(sdo::decode_request(co::make_remote_frame(0x605, 8).value()) == errc::unexpected_frame);
  CHECK(sdo::decode(F(0x705, {0x40, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  CHECK(sdo::decode(F(0x580, {0x40, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  CHECK(sdo::decode(F(0x600, {0x40, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  CHECK(sdo::decode(F(0x680, {0x40, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  CHECK(sdo::decode(F(0x67F, {0xE0, 0, 0, 0, 0, 0, 0, 0})) == errc::unknown_command);
  CHECK(sdo::decode(F(0x5FF, {0xE0, 0, 0, 0, 0, 0, 0, 0})) == errc::unknown_command);
  co::can_frame longdlc = F(0x605, {0x40, 0, 0, 0, 0, 0, 0, 0});
  longdlc.dlc = 9;
  CHECK(sdo::decode_request(longdlc) == errc::bad_length);
}

TEST_CASE("every command byte decodes without reading out of bounds") {
  for (unsigned b = 0; b < 256; ++b) {
    auto f = F(0x605, {static_cast<std::uint8_t>(b), 0x34, 0x12, 0x56, 1, 2, 3, 4});
    auto q = sdo::decode_request(f);
    auto r = sdo::decode_response(f);
    if ((b >> 5U) == 7U) {
      CHECK(q == errc::unknown_command);
      CHECK(r == errc::unknown_command);
    } else {
      REQUIRE(q.has_value());
      REQUIRE(r.has_value());
      CHECK(q.value().data_size <= 7);
      CHECK(r.value().data_size <= 7);
    }
  }
}
