// The CiA 301 SDO client and server machines over CoE (coe/sdo_client.hpp, coe/sdo_server.hpp):
// the transfers of tests/canopen/sdo_transfer_test.cpp re-run through mailboxes of 16, 128 and
// 1486 bytes, compared with the same transfers over CAN.
#include "test_link.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

using namespace coe_test;
using fieldcodec::errc;

namespace {
constexpr sdo::abort_code A(std::uint32_t v) { return static_cast<sdo::abort_code>(v); }
} // namespace

TEST_CASE("CoE: client and server transfer every fixed-size type, as over CAN") {
  for (const std::size_t size : mailbox_sizes) {
    CAPTURE(size);
    mailbox_link l(size);
    can_link c;
    std::size_t checked = 0;
    for (const auto &e : dict) {
      if (od::is_byte_string(e.type) || !od::writable(e.access_type)) continue;
      std::vector<std::uint8_t> v(e.width(), 0x01);
      if (e.type == data_type::real32) v = {0x00, 0x00, 0xC0, 0x3F};
      if (e.type == data_type::real64) v = {0, 0, 0, 0, 0, 0, 0xF8, 0x3F};
      if (e.type == data_type::time_of_day || e.type == data_type::time_difference) {
        v = {0x10, 0x20, 0x30, 0x04, 0x50, 0x60};
      }
      if (e.index == 0x3000) v = {0xF6, 0xFF};
      CAPTURE(e.index);
      CHECK(l.write(e.index, e.sub, v) == sdo::transfer_state::done);
      CHECK(c.write(e.index, e.sub, v) == sdo::transfer_state::done);
      // one request, one response: 1..4 bytes expedited, 5..8 bytes normal in one mailbox
      // (a 16-byte mailbox holds no data in a normal initiate: one segment follows)
      CHECK(l.mailboxes == 2 * requests_for(v.size(), size));
      CHECK(l.store.value({e.index, e.sub}).value().size() == v.size());
      if (!od::readable(e.access_type)) continue;
      std::array<std::uint8_t, 16> buf{};
      CHECK(l.read(e.index, e.sub, buf) == sdo::transfer_state::done);
      REQUIRE(l.client.received().size() == e.width());
      CHECK(std::equal(v.begin(), v.end(), l.client.received().begin()));
      CHECK(l.client.refused().has_value());
      CHECK(l.server.refused().has_value());
      ++checked;
    }
    CHECK(checked == 22);
    CHECK(std::equal(l.storage.begin(), l.storage.end(), c.storage.begin()));
  }
}

TEST_CASE("CoE: byte strings of 0 to 5000 bytes, normal and segmented, both ways") {
  for (const std::size_t size : mailbox_sizes) {
    const std::size_t first = coe::initiate_capacity(size);
    const std::size_t seg = coe::segment_capacity(size);
    std::vector<std::size_t> sizes = {0,   1,   2,   3,   4,   5,   6,    7,    8,
                                      9,   13,  14,  15,  20,  21,  22,   63,   64,
                                      100, 255, 256, 399, 400, 999, 1000, 4999, 5000};
    for (const std::size_t around : {first, first + seg, first + 2 * seg}) {
      for (const std::size_t d : {std::size_t{0}, std::size_t{1}, std::size_t{2}}) {
        if (around + d >= 1) sizes.push_back(around + d - 1);
        sizes.push_back(around + d);
      }
    }
    for (const std::uint16_t index : {std::uint16_t{0x2009}, std::uint16_t{0x200A},
                                      std::uint16_t{0x200F}, std::uint16_t{0x2020}}) {
      const std::size_t capacity = dict.find({index, 0})->capacity();
      for (const std::size_t n : sizes) {
        if (n > capacity) continue;
        CAPTURE(size);
        CAPTURE(index);
        CAPTURE(n);
        mailbox_link l(size);
        can_link c;
        const auto v = pattern(n, static_cast<std::uint8_t>(n));
        REQUIRE(l.write(index, 0, v) == sdo::transfer_state::done);
        CHECK(l.mailboxes == 2 * requests_for(n, size));
        CHECK(l.client.transferred() == n);
        REQUIRE(c.write(index, 0, v) == sdo::transfer_state::done);
        std::vector<std::uint8_t> buf(6000);
        REQUIRE(l.read(index, 0, buf) == sdo::transfer_state::done);
        CHECK(l.mailboxes == 2 * requests_for(n, size));
        const auto got = l.client.received();
        REQUIRE(got.size() == n);
        CHECK(std::equal(v.begin(), v.end(), got.begin()));
        CHECK(l.store.value({index, 0}).value().size() == n);
        CHECK(std::equal(l.storage.begin(), l.storage.end(), c.storage.begin()));
      }
    }
  }
  // unicode string: even lengths only, as on CAN
  mailbox_link l(128);
  CHECK(l.write(0x200B, 0, pattern(10, 3)) == sdo::transfer_state::done);
  CHECK(l.write(0x200B, 0, pattern(9, 3)) == sdo::transfer_state::failed);
  CHECK(l.client.error()->abort == A(0x06090030U));
}

TEST_CASE("CoE: request and response mailboxes of different sizes, a server buffer of 7") {
  // SM0 of 16 bytes (every request segment carries 7 bytes) and SM1 of 1486; then the reverse;
  // a server whose buffer holds one CAN segment moves the value in parts of 7 bytes
  for (const auto &sizes :
       {std::array<std::size_t, 3>{16, 1486, 1024}, std::array<std::size_t, 3>{1486, 16, 1024},
        std::array<std::size_t, 3>{100, 37, 7}, std::array<std::size_t, 3>{37, 100, 7}}) {
    const std::size_t req = sizes[0], resp = sizes[1], buffer = sizes[2];
    CAPTURE(req);
    CAPTURE(resp);
    mailbox_link l(req, resp, buffer);
    const auto v = pattern(999, 7);
    REQUIRE(l.write(0x200F, 0, v) == sdo::transfer_state::done);
    CHECK(l.mailboxes == 2 * requests_for(999, req));
    std::vector<std::uint8_t> buf(1000);
    REQUIRE(l.read(0x200F, 0, buf) == sdo::transfer_state::done);
    CHECK(l.mailboxes == 2 * requests_for(999, resp));
    CHECK(std::equal(v.begin(), v.end(), l.client.received().begin()));
  }
}

TEST_CASE("CoE: the server answers bad accesses with the CAN machine's abort codes") {
  for (const std::size_t size : mailbox_sizes) {
    CAPTURE(size);
    mailbox_link l(size);
    std::array<std::uint8_t, 64> buf{};
    const std::array<std::uint8_t, 2> two{1, 0};
    const std::array<std::uint8_t, 3> three{1, 0, 0};
    const std::array<std::uint8_t, 1> one{1};
    const std::array<std::uint8_t, 2> too_high{21, 0};
    const std::array<std::uint8_t, 2> too_low{0xEB, 0xFF};
    struct row {
      bool write;
      std::uint16_t index;
      std::uint8_t sub;
      std::span<const std::uint8_t> data;
      std::uint32_t code;
    };
    const auto big = pattern(401, 1);
    const row rows[] = {
        {false, 0x4000, 0, {}, 0x06020000U},
        {false, 0x2001, 1, {}, 0x06090011U},
        {true, 0x1000, 0, two, 0x06010002U},
        {true, 0x1008, 0, two, 0x06010002U},
        {false, 0x3000, 1, {}, 0x06010001U},
        {true, 0x2006, 0, one, 0x06070013U},
        {true, 0x2006, 0, three, 0x06070012U},
        {true, 0x3000, 2, too_high, 0x06090031U},
        {true, 0x3000, 2, too_low, 0x06090032U},
        {true, 0x2001, 0, one, 0},
        {false, 0x3001, 0, {}, 0x06010000U},
        {true, 0x2009, 0, big, 0x06070012U}, // 401 bytes into a string of 400
    };
    for (const auto &r : rows) {
      CAPTURE(r.index);
      auto st = r.write ? l.write(r.index, r.sub, r.data) : l.read(r.index, r.sub, buf);
      if (r.code == 0) {
        CHECK(st == sdo::transfer_state::done);
        continue;
      }
      CHECK(st == sdo::transfer_state::failed);
      CHECK(l.client.error()->code == errc::aborted);
      CHECK(l.code() == A(r.code));
      CHECK(l.server.state() == (l.server.busy() ? sdo::transfer_state::busy : l.server.state()));
    }
    CHECK(l.read(0x1008, 0, buf) == sdo::transfer_state::done);
    CHECK(std::string_view(reinterpret_cast<const char *>(l.client.received().data()),
                           l.client.received().size()) == "XENAX Xvi 75V8S");
  }
}

TEST_CASE("CoE: typed writes and reads through od's encode and decode") {
  mailbox_link l(128);
  const od::entry &i16 = *dict.find({0x3000, 2}); // INTEGER16, -20..20
  auto s = l.client.write(i16, -7, l.now);
  REQUIRE(s.has_value());
  l.run(s.value());
  CHECK(l.client.state() == sdo::transfer_state::done);
  CHECK(l.store.value({0x3000, 2}).value()[0] == 0xF9);
  // limits are od::encode's: refused before anything is sent
  CHECK(l.client.write(i16, 21, l.now) == errc::out_of_range);
  CHECK(l.client.write(i16, 40000, l.now) == errc::out_of_range);
  CHECK(l.client.write(*dict.find({0x1000, 0}), 1, l.now) == errc::access_denied);
  CHECK(l.client.write(*dict.find({0x2009, 0}), 1, l.now) == errc::type_mismatch);
  l.run(l.client.read(i16, l.now).value());
  CHECK(l.client.value<int>(i16) == -7);
  CHECK(l.client.value<std::uint8_t>(i16) == errc::overflow); // never narrowed
  l.run(l.client.read(*dict.find({0x1000, 0}), l.now).value());
  CHECK(l.client.value<std::uint32_t>(*dict.find({0x1000, 0})) == 0x00020192U);
  CHECK(l.client.read(*dict.find({0x3000, 1}), l.now) == errc::access_denied);
  CHECK(l.client.read(*dict.find({0x2009, 0}), l.now) == errc::type_mismatch);
  // byte strings: checked like od::decode_bytes, then moved as they are
  const std::string_view text = "fieldcodec over CoE";
  const std::span<const std::uint8_t> tb(reinterpret_cast<const std::uint8_t *>(text.data()),
                                         text.size());
  l.run(l.client.write_bytes(*dict.find({0x2009, 0}), tb, l.now).value());
  CHECK(l.client.state() == sdo::transfer_state::done);
  const std::array<std::uint8_t, 2> ctl{'a', 0x07};
  CHECK(l.client.write_bytes(*dict.find({0x2009, 0}), ctl, l.now) == errc::bad_character);
  CHECK(l.client.write_bytes(*dict.find({0x2006, 0}), ctl, l.now) == errc::type_mismatch);
  CHECK(l.client.write_bytes(*dict.find({0x1008, 0}), tb, l.now) == errc::access_denied);
  // value<T> only after an upload
  l.run(l.client.write(i16, 3, l.now).value());
  CHECK(l.client.value<int>(i16) == errc::bad_state);
}

TEST_CASE("CoE over 16-byte mailboxes: the SDO part of every mailbox is the CAN frame's bytes") {
  // A 16-byte mailbox holds the 8 SDO bytes and nothing more: a normal initiate carries no data
  // and every segment 7 bytes (the last one padded), exactly the messages of CAN. So every
  // transfer of tests/canopen/sdo_transfer_test.cpp sends, frame for frame, the bytes it sends
  // on CAN — also when it fails. Except for a value of 0 bytes: a normal initiate with complete
  // size 0 is the whole transfer in CoE, where CAN sends one empty segment after it.
  struct row {
    bool write;
    std::uint16_t index;
    std::uint8_t sub;
    std::vector<std::uint8_t> data;
  };
  std::vector<row> rows = {
      {false, 0x4000, 0, {}}, {false, 0x2001, 1, {}},       {true, 0x1000, 0, {1, 0}},
      {true, 0x2006, 0, {1}}, {true, 0x2006, 0, {1, 0, 0}}, {true, 0x3000, 2, {21, 0}},
      {false, 0x3000, 1, {}}, {false, 0x3001, 0, {}},       {true, 0x2009, 0, pattern(401, 1)},
  };
  for (const auto &e : dict) {
    if (od::writable(e.access_type) && !od::is_byte_string(e.type)) {
      rows.push_back({true, e.index, e.sub, std::vector<std::uint8_t>(e.width(), 0x01)});
    }
    if (od::readable(e.access_type)) rows.push_back({false, e.index, e.sub, {}});
  }
  for (const std::size_t n : {0U, 1U, 4U, 5U, 7U, 8U, 13U, 14U, 15U, 100U, 400U}) {
    rows.push_back({true, 0x2009, 0, pattern(n, 2)});
    rows.push_back({false, 0x2009, 0, {}});
  }
  mailbox_link l(16);
  can_link c;
  std::size_t frames = 0;
  for (const auto &r : rows) {
    CAPTURE(r.index);
    CAPTURE(r.data.size());
    l.wire.clear();
    c.wire.clear();
    std::array<std::uint8_t, 512> a{}, b{};
    const auto sl = r.write ? l.write(r.index, r.sub, r.data) : l.read(r.index, r.sub, a);
    const auto sc = r.write ? c.write(r.index, r.sub, r.data) : c.read(r.index, r.sub, b);
    CHECK(sl == sc);
    const bool empty_value =
        r.write ? r.data.empty() : sc == sdo::transfer_state::done && c.client.received().empty();
    if (empty_value) {
      REQUIRE(c.wire.size() == 4);
      CHECK(l.wire.size() == 2);
      CHECK(l.wire[0] == c.wire[0]); // the initiate (size 0)
      CHECK(l.wire[1] == c.wire[1]); // its response
      continue;
    }
    CHECK(l.wire == c.wire);
    frames += c.wire.size();
  }
  CHECK(frames > 400);
}
