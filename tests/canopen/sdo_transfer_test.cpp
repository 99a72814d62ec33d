// SDO client and server machines against each other over an in-memory bus, and against
// hand-made bad frames.
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>

#include "sdo_test_dictionary.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
using fieldcodec::errc;
using od::data_type;

namespace {
constexpr co::can_frame F(std::uint16_t id, std::initializer_list<std::uint8_t> b) {
  return co::make_frame(id, b).value();
}
constexpr sdo::abort_code A(std::uint32_t v) { return static_cast<sdo::abort_code>(v); }
/// The abort code of the (only) frame a server step sends.
sdo::abort_code code_of(const sdo::step &s) {
  REQUIRE(s.send.size() == 1);
  auto m = sdo::decode(s.send[0], sdo::direction::to_client);
  REQUIRE(m.has_value());
  REQUIRE(m.value().type == sdo::message_type::abort);
  return m.value().abort;
}

constexpr const auto &test_entries = sdo_test::entries; // tests/sdo_test_dictionary.hpp
constexpr od::dictionary test_dict{test_entries};
static_assert(test_dict.is_valid());

constexpr auto test_layout = co::make_layout<std::size(test_entries)>(test_dict);

/// A client and a server on one in-memory bus. Frames travel in order; a burst is delivered
/// frame by frame. `fault` may change the frames of a burst on their way (lose, repeat,
/// reorder). When nothing is in flight but a machine waits, time jumps to its deadline.
struct bus {
  static constexpr std::uint8_t node = 5;
  std::vector<std::uint8_t> storage =
      std::vector<std::uint8_t>(co::dictionary_store<>::storage_size(test_dict));
  co::dictionary_store<> store{test_dict, test_layout, storage};
  std::vector<std::uint8_t> server_buffer = std::vector<std::uint8_t>(1024);
  sdo::server<co::dictionary_store<>> server{node, store, server_buffer};
  sdo::client client{node};
  std::uint32_t now = 0;
  std::size_t frames = 0;
  std::deque<co::can_frame> to_server, to_client;
  std::function<void(std::vector<co::can_frame> &)> fault;

  bus() { REQUIRE(store.init_defaults(node).has_value()); }
  explicit bus(std::size_t server_buffer_size) : server_buffer(server_buffer_size) {
    REQUIRE(store.init_defaults(node).has_value());
  }

  void push(std::deque<co::can_frame> &q, const sdo::step &s) {
    std::vector<co::can_frame> out(s.send.begin(), s.send.end());
    if (s.send.is_burst() && fault) fault(out);
    for (const auto &f : out) {
      CHECK(f.is_valid());
      q.push_back(f);
    }
  }
  void run(const sdo::step &first) {
    push(to_server, first);
    for (int guard = 0; guard < 200000; ++guard) {
      if (!to_server.empty()) {
        auto f = to_server.front();
        to_server.pop_front();
        ++frames;
        push(to_client, server.on_frame(f, now));
      } else if (!to_client.empty()) {
        auto f = to_client.front();
        to_client.pop_front();
        ++frames;
        push(to_server, client.on_frame(f, now));
      } else if (client.busy() || server.busy()) {
        now += 1000;
        push(to_server, client.poll(now));
        push(to_client, server.poll(now));
      } else {
        return;
      }
    }
    FAIL("the machines never settled");
  }
  sdo::transfer_state write(std::uint16_t index, std::uint8_t sub,
                            std::span<const std::uint8_t> data) {
    run(client.download({index, sub}, data, now).value());
    return client.state();
  }
  sdo::transfer_state read(std::uint16_t index, std::uint8_t sub, std::span<std::uint8_t> buf) {
    run(client.upload({index, sub}, buf, now).value());
    return client.state();
  }
  [[nodiscard]] sdo::abort_code code() const {
    return client.error() ? client.error()->abort : sdo::abort_code::none;
  }
  [[nodiscard]] fieldcodec::errc err() const {
    REQUIRE(client.error().has_value());
    return client.error()->code;
  }
};

std::vector<std::uint8_t> pattern(std::size_t n, std::uint8_t seed) {
  std::vector<std::uint8_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>(0x21U + (seed + i) % 90U);
  return v;
}
} // namespace

// transfer_error is the one SDO error with context (dpq::sdo_error is the same type): `code`
// as docs/contributing.md "Errors" asks, the abort's CiA 301 text and the errc it maps to.
static_assert(sdo::transfer_error{errc::aborted, sdo::abort_code::value_too_high, {0x2000, 1}} ==
              errc::aborted);
static_assert(sdo::transfer_error{errc::aborted, sdo::abort_code::value_too_high, {}}.cause() ==
              errc::out_of_range);
static_assert(sdo::transfer_error{errc::timeout, sdo::abort_code::none, {}}.cause() ==
              errc::timeout);
static_assert(sdo::transfer_error{errc::timeout, sdo::abort_code::none, {}}.is(errc::timeout));
static_assert(sdo::transfer_error{}.text() == "no abort");
static_assert(sdo::transfer_error{errc::bad_length, sdo::abort_code::unknown_command, {}}.text() ==
              sdo::to_string(sdo::abort_code::unknown_command));
static_assert(!(sdo::transfer_error{errc::bad_length, sdo::abort_code::none, {}} == errc::aborted));

TEST_CASE("client and server transfer every fixed-size type") {
  bus b;
  std::size_t checked = 0;
  for (const auto &e : test_dict) {
    if (od::is_byte_string(e.type) || !od::writable(e.access_type)) continue;
    const auto w = e.width();
    // a value that is valid for every type: all 0x01 bytes (BOOLEAN: one byte 1), and a second
    // pattern with high bytes set where the type allows it
    std::vector<std::uint8_t> v(w, 0x01);
    if (e.type == data_type::real32) v = {0x00, 0x00, 0xC0, 0x3F}; // 1.5f
    if (e.type == data_type::real64) v = {0, 0, 0, 0, 0, 0, 0xF8, 0x3F};
    if (e.type == data_type::time_of_day || e.type == data_type::time_difference) {
      v = {0x10, 0x20, 0x30, 0x04, 0x50, 0x60};
    }
    if (e.index == 0x3000) v = {0xF6, 0xFF}; // -10 within -20..20
    CAPTURE(e.index);
    CHECK(b.write(e.index, e.sub, v) == sdo::transfer_state::done);
    if (!od::readable(e.access_type)) continue;
    std::array<std::uint8_t, 16> buf{};
    CHECK(b.read(e.index, e.sub, buf) == sdo::transfer_state::done);
    REQUIRE(b.client.received().size() == w);
    CHECK(std::equal(v.begin(), v.end(), b.client.received().begin()));
    ++checked;
  }
  CHECK(checked == 22); // 21 fixed-size types + the limited INTEGER16
  // expedited transfers are two frames each way: 4 frames per write + read.
}

TEST_CASE("client and server transfer byte strings of 0 to several hundred bytes") {
  const std::size_t sizes[] = {0,  1,  2,  3,  4,  5,  6,   7,   8,   9,   13, 14,
                               15, 20, 21, 22, 63, 64, 100, 255, 256, 399, 400};
  for (std::uint16_t index :
       {std::uint16_t{0x2009}, std::uint16_t{0x200A}, std::uint16_t{0x200F}}) {
    for (auto n : sizes) {
      CAPTURE(index);
      CAPTURE(n);
      bus b;
      const auto v = pattern(n, static_cast<std::uint8_t>(n));
      REQUIRE(b.write(index, 0, v) == sdo::transfer_state::done);
      // frames: initiate + response, then one segment + response per 7 bytes (at least one)
      // for the segmented case; 2 frames for 1..4 bytes.
      const std::size_t segments = n == 0 ? 1 : (n + 6) / 7;
      CHECK(b.frames == (n >= 1 && n <= 4 ? 2 : 2 + 2 * segments));
      std::array<std::uint8_t, 1024> buf{};
      REQUIRE(b.read(index, 0, buf) == sdo::transfer_state::done);
      // Issue 12 #2: the store keeps the length written and an upload returns exactly that
      // (before, an OCTET_STRING or DOMAIN answered its whole slot, padded with zeros).
      auto got = b.client.received();
      REQUIRE(got.size() == n);
      CHECK(std::equal(v.begin(), v.end(), got.begin()));
      CHECK(b.store.value({index, 0}).value().size() == n);
    }
  }
  // unicode string: even lengths only
  bus b;
  const auto v = pattern(10, 3);
  CHECK(b.write(0x200B, 0, v) == sdo::transfer_state::done);
  CHECK(b.write(0x200B, 0, pattern(9, 3)) == sdo::transfer_state::failed);
  CHECK(b.client.error()->abort == A(0x06090030U));
}

TEST_CASE("server answers bad accesses with the precise abort code") {
  bus b;
  std::array<std::uint8_t, 64> buf{};
  const std::array<std::uint8_t, 2> two{1, 0};
  const std::array<std::uint8_t, 3> three{1, 0, 0};
  const std::array<std::uint8_t, 1> one{1};
  struct row {
    bool write;
    std::uint16_t index;
    std::uint8_t sub;
    std::span<const std::uint8_t> data;
    std::uint32_t code;
  };
  const std::array<std::uint8_t, 2> too_high{21, 0};
  const std::array<std::uint8_t, 2> too_low{0xEB, 0xFF}; // -21
  const row rows[] = {
      {false, 0x4000, 0, {}, 0x06020000U},                           // no object
      {false, 0x2001, 1, {}, 0x06090011U},                           // no sub-index
      {true, 0x1000, 0, std::span(two).first(2), 0x06010002U},       // read-only
      {true, 0x1008, 0, std::span(two).first(2), 0x06010002U},       // const
      {false, 0x3000, 1, {}, 0x06010001U},                           // write-only
      {true, 0x2006, 0, one, 0x06070013U},                           // too short
      {true, 0x2006, 0, three, 0x06070012U},                         // too long
      {true, 0x3000, 2, too_high, 0x06090031U},                      // above 20
      {true, 0x3000, 2, too_low, 0x06090032U},                       // below -20
      {true, 0x2001, 0, std::span(three).first(1).subspan(0, 1), 0}, // BOOLEAN 1: fine
      {false, 0x3001, 0, {}, 0x06010000U},                           // domain without size
  };
  for (const auto &r : rows) {
    CAPTURE(r.index);
    CAPTURE(static_cast<int>(r.sub));
    auto st = r.write ? b.write(r.index, r.sub, r.data) : b.read(r.index, r.sub, buf);
    if (r.code == 0) {
      CHECK(st == sdo::transfer_state::done);
      continue;
    }
    CHECK(st == sdo::transfer_state::failed);
    CHECK(b.client.error()->code == errc::aborted);
    CHECK(b.code() == A(r.code));
  }
  const std::array<std::uint8_t, 1> bool2{2};
  CHECK(b.write(0x2001, 0, bool2) == sdo::transfer_state::failed);
  CHECK(b.client.error()->abort == A(0x06090030U));
  // the visible string default and the device type default are served
  CHECK(b.read(0x1008, 0, buf) == sdo::transfer_state::done);
  CHECK(std::string_view(reinterpret_cast<const char *>(b.client.received().data()),
                         b.client.received().size()) == "XENAX Xvi 75V8S");
  CHECK(b.read(0x1000, 0, buf) == sdo::transfer_state::done);
  CHECK(b.client.received().size() == 4);
  CHECK(b.client.received()[0] == 0x92);
  CHECK(b.client.received()[2] == 0x02);
}

TEST_CASE("client: toggle errors, unexpected frames, timeouts, size disagreements") {
  std::array<std::uint8_t, 16> buf{};
  SUBCASE("toggle error in an upload") {
    sdo::client c(5);
    CHECK(c.upload({0x1008, 0}, buf, 0).value().send[0] ==
          F(0x605, {0x40, 0x08, 0x10, 0, 0, 0, 0, 0}));
    auto o = c.on_frame(F(0x585, {0x41, 0x08, 0x10, 0x00, 10, 0, 0, 0}), 1);
    CHECK(o.send[0] == F(0x605, {0x60, 0, 0, 0, 0, 0, 0, 0}));
    o = c.on_frame(F(0x585, {0x00, 1, 2, 3, 4, 5, 6, 7}), 2);
    CHECK(o.send[0] == F(0x605, {0x70, 0, 0, 0, 0, 0, 0, 0}));
    o = c.on_frame(F(0x585, {0x00 | 0x05, 8, 9, 10, 0, 0, 0, 0}), 3); // toggle 0 again
    CHECK(o.state == sdo::transfer_state::failed);
    CHECK(c.error()->code == errc::bad_toggle);
    CHECK(o.send[0] == F(0x605, {0x80, 0x08, 0x10, 0x00, 0x00, 0x00, 0x03, 0x05}));
  }
  SUBCASE("segments disagree with the announced size") {
    sdo::client c(5);
    (void)c.upload({0x1008, 0}, buf, 0);
    (void)c.on_frame(F(0x585, {0x41, 0x08, 0x10, 0x00, 10, 0, 0, 0}), 1);
    (void)c.on_frame(F(0x585, {0x00, 1, 2, 3, 4, 5, 6, 7}), 2);
    // t=1, n=5 (2 bytes), c=1: 7 + 2 = 9 bytes, 10 announced
    auto o = c.on_frame(F(0x585, {0x1B, 8, 9, 0, 0, 0, 0, 0}), 3);
    CHECK(o.state == sdo::transfer_state::failed);
    CHECK(c.error()->code == errc::bad_length);
    CHECK(c.error()->abort == A(0x06070013U));
  }
  SUBCASE("more data than announced") {
    sdo::client c(5);
    (void)c.upload({0x1008, 0}, buf, 0);
    (void)c.on_frame(F(0x585, {0x41, 0x08, 0x10, 0x00, 5, 0, 0, 0}), 1);
    auto o = c.on_frame(F(0x585, {0x01, 1, 2, 3, 4, 5, 6, 7}), 2);
    CHECK(c.error()->code == errc::bad_length);
    CHECK(c.error()->abort == A(0x06070012U));
    CHECK(!o.send.empty());
  }
  SUBCASE("upload larger than the buffer") {
    sdo::client c(5);
    (void)c.upload({0x1008, 0}, std::span(buf).first(4), 0);
    auto o = c.on_frame(F(0x585, {0x41, 0x08, 0x10, 0x00, 10, 0, 0, 0}), 1);
    CHECK(c.error()->code == errc::buffer_too_small);
    CHECK(o.send[0] == F(0x605, {0x80, 0x08, 0x10, 0x00, 0x05, 0x00, 0x04, 0x05}));
    sdo::client d(5);
    (void)d.upload({0x1008, 0}, std::span(buf).first(1), 0);
    (void)d.on_frame(F(0x585, {0x4B, 0x08, 0x10, 0x00, 1, 2, 0, 0}), 1);
    CHECK(d.error()->code == errc::buffer_too_small);
  }
  SUBCASE("unexpected frames") {
    sdo::client c(5);
    const std::array<std::uint8_t, 2> v{1, 2};
    (void)c.download({0x6040, 0}, v, 0);
    // other COB-IDs and remote frames are ignored
    CHECK(c.on_frame(F(0x586, {0x60, 0x40, 0x60, 0, 0, 0, 0, 0}), 1).send.empty());
    CHECK(c.busy());
    // a response for another object
    auto o = c.on_frame(F(0x585, {0x60, 0x41, 0x60, 0, 0, 0, 0, 0}), 1);
    CHECK(c.error()->code == errc::unexpected_frame);
    CHECK(!o.send.empty());
    // an upload response to a download
    sdo::client d(5);
    (void)d.download({0x6040, 0}, v, 0);
    o = d.on_frame(F(0x585, {0x4B, 0x40, 0x60, 0, 1, 2, 0, 0}), 1);
    CHECK(d.error()->code == errc::unexpected_frame);
    CHECK(d.error()->abort == A(0x05040001U));
    // an unknown command specifier
    sdo::client e(5);
    (void)e.download({0x6040, 0}, v, 0);
    o = e.on_frame(F(0x585, {0xE0, 0x40, 0x60, 0, 0, 0, 0, 0}), 1);
    CHECK(e.error()->code == errc::unknown_command);
    // a short frame
    sdo::client g(5);
    (void)g.download({0x6040, 0}, v, 0);
    o = g.on_frame(F(0x585, {0x60, 0x40, 0x60}), 1);
    CHECK(g.error()->code == errc::bad_length);
    // frames when idle are ignored
    sdo::client h(5);
    CHECK(h.on_frame(F(0x585, {0x60, 0x40, 0x60, 0, 0, 0, 0, 0}), 1).state ==
          sdo::transfer_state::idle);
  }
  SUBCASE("toggle error in a download and the server's abort") {
    sdo::client c(5);
    const auto v = pattern(20, 0);
    (void)c.download({0x2009, 0}, v, 0);
    auto o = c.on_frame(F(0x585, {0x60, 0x09, 0x20, 0, 0, 0, 0, 0}), 1);
    CHECK(o.send[0].data[0] == 0x00);                         // first segment, toggle 0, 7 bytes
    o = c.on_frame(F(0x585, {0x30, 0, 0, 0, 0, 0, 0, 0}), 2); // toggle 1: wrong
    CHECK(c.error()->code == errc::bad_toggle);
    sdo::client d(5);
    (void)d.download({0x2009, 0}, v, 0);
    o = d.on_frame(F(0x585, {0x80, 0x09, 0x20, 0, 0x00, 0x00, 0x04, 0x05}), 1);
    CHECK(o.send.empty());
    CHECK(d.error()->code == errc::aborted);
    CHECK(d.error()->abort == A(0x05040000U));
  }
  SUBCASE("timeout and cancel, busy") {
    sdo::client c(5, 100);
    (void)c.upload({0x1000, 0}, buf, 0xFFFF'FFF0U); // wraps around
    CHECK(c.upload({0x1000, 0}, buf, 0) == errc::bad_state);
    CHECK(c.poll(0x0000'0050U).send.empty()); // 96 ms
    auto o = c.poll(0x0000'0054U);            // 100 ms
    CHECK(c.error()->code == errc::timeout);
    CHECK(o.send[0] == F(0x605, {0x80, 0x00, 0x10, 0x00, 0x00, 0x00, 0x04, 0x05}));
    (void)c.upload({0x1000, 0}, buf, 0);
    o = c.cancel();
    CHECK(c.error()->code == errc::aborted);
    CHECK(o.send[0].data[0] == 0x80);
    sdo::client bad(0);
    CHECK(bad.upload({0x1000, 0}, buf, 0) == errc::invalid_argument);
  }
}

TEST_CASE("server: toggle errors, stray segments, block requests, timeouts, sizes") {
  bus b;
  auto &s = b.server;
  SUBCASE("stray segment and upload-segment requests") {
    auto r = s.on_frame(F(0x605, {0x00, 1, 2, 3, 4, 5, 6, 7}), 0);
    CHECK(r.send[0].data[0] == 0x80);
    CHECK(code_of(r) == A(0x05040001U));
    r = s.on_frame(F(0x605, {0x60, 0, 0, 0, 0, 0, 0, 0}), 0);
    CHECK(code_of(r) == A(0x05040001U));
  }
  SUBCASE("a server without block transfer refuses it cleanly") {
    std::vector<std::uint8_t> buf(64);
    sdo::server<co::dictionary_store<>> plain(5, b.store, buf, 1000, {.block = false});
    auto r = plain.on_frame(F(0x605, {0xC6, 0x09, 0x20, 0x00, 20, 0, 0, 0}), 0);
    CHECK(r.send[0] == F(0x585, {0x80, 0x09, 0x20, 0x00, 0x01, 0x00, 0x04, 0x05}));
    CHECK(plain.error()->code == errc::unknown_command);
    r = plain.on_frame(F(0x605, {0xA4, 0x09, 0x20, 0x00, 0x7F, 0, 0, 0}), 0);
    CHECK(code_of(r) == A(0x05040001U));
  }
  SUBCASE("command specifier 7 and block messages out of place") {
    auto r = s.on_frame(F(0x605, {0xE0, 0x09, 0x20, 0x00, 0, 0, 0, 0}), 0);
    CHECK(r.send[0] == F(0x585, {0x80, 0x09, 0x20, 0x00, 0x01, 0x00, 0x04, 0x05}));
    CHECK(s.error()->code == errc::unknown_command);
    CHECK(s.error()->address == fieldcodec::od::address{0x2009, 0});
    for (std::uint8_t cmd :
         {std::uint8_t{0xA1}, std::uint8_t{0xA2}, std::uint8_t{0xA3}, std::uint8_t{0xC1}}) {
      CAPTURE(static_cast<int>(cmd));
      r = s.on_frame(F(0x605, {cmd, 1, 127, 0, 0, 0, 0, 0}), 0);
      CHECK(code_of(r) == A(0x05040001U));
    }
  }
  SUBCASE("segment toggle error") {
    CHECK(s.on_frame(F(0x605, {0x21, 0x09, 0x20, 0x00, 14, 0, 0, 0}), 0).send[0].data[0] == 0x60);
    CHECK(s.on_frame(F(0x605, {0x00, 'a', 'b', 'c', 'd', 'e', 'f', 'g'}), 0).send[0].data[0] ==
          0x20);
    auto r = s.on_frame(F(0x605, {0x01, 'a', 'b', 'c', 'd', 'e', 'f', 'g'}), 0);
    CHECK(r.send[0] == F(0x585, {0x80, 0x09, 0x20, 0x00, 0x00, 0x00, 0x03, 0x05}));
    CHECK(s.error()->code == errc::bad_toggle);
  }
  SUBCASE("segments disagree with the announced size") {
    (void)s.on_frame(F(0x605, {0x21, 0x09, 0x20, 0x00, 10, 0, 0, 0}), 0);
    (void)s.on_frame(F(0x605, {0x00, 'a', 'b', 'c', 'd', 'e', 'f', 'g'}), 0);
    auto r = s.on_frame(F(0x605, {0x10, 'a', 'b', 'c', 'd', 'e', 'f', 'g'}), 0);
    CHECK(code_of(r) == A(0x06070012U));
    (void)s.on_frame(F(0x605, {0x21, 0x09, 0x20, 0x00, 10, 0, 0, 0}), 0);
    auto r2 = s.on_frame(F(0x605, {0x0B, 'a', 'b', 0, 0, 0, 0, 0}), 0); // last, 2 bytes
    CHECK(code_of(r2) == A(0x06070013U));
    // 4096 bytes announced for a string of 400: refused at once by the store, before any data
    auto r3 = s.on_frame(F(0x605, {0x21, 0x09, 0x20, 0x00, 0x00, 0x10, 0, 0}), 0);
    CHECK(code_of(r3) == A(0x06070012U));
  }
  SUBCASE("timeout of a segmented transfer") {
    (void)s.on_frame(F(0x605, {0x21, 0x09, 0x20, 0x00, 10, 0, 0, 0}), 0);
    CHECK(s.poll(999).send.empty());
    auto r = s.poll(1000);
    CHECK(r.send[0] == F(0x585, {0x80, 0x09, 0x20, 0x00, 0x00, 0x00, 0x04, 0x05}));
    CHECK(s.state() == sdo::transfer_state::failed);
    CHECK(s.poll(5000).send.empty());
  }
  SUBCASE("frames it does not answer") {
    CHECK(s.on_frame(F(0x606, {0x40, 0, 0x10, 0, 0, 0, 0, 0}), 0).send.empty()); // other node
    CHECK(s.on_frame(F(0x605, {0x40, 0, 0x10}), 0).send.empty());                // short
    CHECK(s.error()->code == errc::bad_length);
    CHECK(
        s.on_frame(F(0x605, {0x80, 0, 0x10, 0, 0, 0, 0, 0}), 0).send.empty()); // abort from client
  }
  SUBCASE("client abort ends a segmented transfer") {
    (void)s.on_frame(F(0x605, {0x21, 0x09, 0x20, 0x00, 10, 0, 0, 0}), 0);
    CHECK(s.on_frame(F(0x605, {0x80, 0x09, 0x20, 0x00, 0, 0, 0, 8}), 0).send.empty());
    CHECK(s.state() == sdo::transfer_state::failed);
    CHECK(s.error()->code == errc::aborted);
  }
}
