// The CoE SDO adapters against hand-made mailboxes: the error cases of
// tests/canopen/sdo_transfer_test.cpp ("client: toggle errors, …", "server: toggle errors, …")
// as mailboxes, and what only CoE has: mailbox counters, mailbox error replies, other services,
// lengths that disagree, complete access.
#include "test_link.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <vector>

using namespace coe_test;
using fieldcodec::errc;
using bytes = std::vector<std::uint8_t>;

namespace {
constexpr sdo::abort_code A(std::uint32_t v) { return static_cast<sdo::abort_code>(v); }
constexpr std::uint8_t req = 0x20; // CoE header byte 1: SDO request
constexpr std::uint8_t res = 0x30; // SDO response

/// A CoE mailbox: counter, CoE header byte 1 (service << 4), then the body.
bytes M(std::uint8_t counter, std::uint8_t svc, std::initializer_list<std::uint8_t> body) {
  bytes b{static_cast<std::uint8_t>(2 + body.size()),        0,    0,  0, 0,
          static_cast<std::uint8_t>(0x03 | (counter << 4U)), 0x00, svc};
  b.insert(b.end(), body);
  return b;
}
bytes body_of(std::span<const std::uint8_t> mbx) { return {mbx.begin() + 8, mbx.end()}; }
/// The SDO abort code of a mailbox an adapter sent.
sdo::abort_code abort_in(std::span<const std::uint8_t> mbx) {
  const auto m = coe::decode_sdo(mbx, sdo::direction::to_client);
  REQUIRE(m.has_value());
  REQUIRE(m.value().sdo.type == sdo::message_type::abort);
  CHECK(mbx[7] == req); // an abort is an SDO request
  return m.value().sdo.abort;
}
coe::mailbox_error error_in(std::span<const std::uint8_t> mbx) {
  return coe::decode_error_reply(coe::decode(mbx).value()).value();
}

struct client_fixture {
  std::vector<std::uint8_t> sm0;
  coe::sdo_client c;
  std::array<std::uint8_t, 16> buf{};
  explicit client_fixture(std::size_t size = 128, std::uint32_t timeout = 1000)
      : sm0(size), c(sm0, size, timeout) {}
};
} // namespace

TEST_CASE("CoE client: toggle errors, size disagreements, buffer, over every mailbox size") {
  for (const std::size_t size : mailbox_sizes) {
    CAPTURE(size);
    SUBCASE("toggle error in an upload") {
      client_fixture f(size);
      const auto s = f.c.upload({0x1008, 0}, f.buf, 0).value();
      CHECK(body_of(s.send) == bytes{0x40, 0x08, 0x10, 0, 0, 0, 0, 0});
      // normal response: 10 bytes in all, none of them here (segments follow)
      auto o = f.c.on_mailbox(M(1, res, {0x41, 0x08, 0x10, 0x00, 10, 0, 0, 0}), 1);
      CHECK(body_of(o.send) == bytes{0x60, 0, 0, 0, 0, 0, 0, 0});
      o = f.c.on_mailbox(M(2, res, {0x00, 1, 2, 3, 4, 5, 6, 7}), 2);
      CHECK(body_of(o.send) == bytes{0x70, 0, 0, 0, 0, 0, 0, 0});
      o = f.c.on_mailbox(M(3, res, {0x05, 8, 9, 10, 0, 0, 0, 0}), 3); // toggle 0 again
      CHECK(o.state == sdo::transfer_state::failed);
      CHECK(f.c.error()->code == errc::bad_toggle);
      CHECK(body_of(o.send) == bytes{0x80, 0x08, 0x10, 0x00, 0x00, 0x00, 0x03, 0x05});
    }
    SUBCASE("segments disagree with the announced size") {
      client_fixture f(size);
      (void)f.c.upload({0x1008, 0}, f.buf, 0);
      (void)f.c.on_mailbox(M(1, res, {0x41, 0x08, 0x10, 0x00, 10, 0, 0, 0}), 1);
      (void)f.c.on_mailbox(M(2, res, {0x00, 1, 2, 3, 4, 5, 6, 7}), 2);
      // t=1, 5 unused (2 bytes), last: 9 bytes of 10
      auto o = f.c.on_mailbox(M(3, res, {0x1B, 8, 9, 0, 0, 0, 0, 0}), 3);
      CHECK(o.state == sdo::transfer_state::failed);
      CHECK(f.c.error()->code == errc::bad_length);
      CHECK(f.c.error()->abort == A(0x06070013U));
      CHECK(abort_in(o.send) == A(0x06070013U));
    }
    SUBCASE("more data than announced") {
      client_fixture f(size);
      (void)f.c.upload({0x1008, 0}, f.buf, 0);
      (void)f.c.on_mailbox(M(1, res, {0x41, 0x08, 0x10, 0x00, 5, 0, 0, 0}), 1);
      auto o = f.c.on_mailbox(M(2, res, {0x01, 1, 2, 3, 4, 5, 6, 7}), 2);
      CHECK(f.c.error()->code == errc::bad_length);
      CHECK(f.c.error()->abort == A(0x06070012U));
      CHECK(abort_in(o.send) == A(0x06070012U));
      // in CoE also: a normal response with more data than its complete size
      client_fixture g(size);
      (void)g.c.upload({0x1008, 0}, g.buf, 0);
      o = g.c.on_mailbox(M(1, res, {0x41, 0x08, 0x10, 0x00, 1, 0, 0, 0, 'a', 'b'}), 1);
      // (18 bytes: longer than a 16-byte response mailbox)
      CHECK(g.c.error()->code == (size == 16 ? errc::too_long : errc::bad_length));
      CHECK(abort_in(o.send) == A(0x08000000U));
    }
    SUBCASE("upload larger than the buffer") {
      client_fixture f(size);
      (void)f.c.upload({0x1008, 0}, std::span(f.buf).first(4), 0);
      auto o = f.c.on_mailbox(M(1, res, {0x41, 0x08, 0x10, 0x00, 10, 0, 0, 0}), 1);
      CHECK(f.c.error()->code == errc::buffer_too_small);
      CHECK(body_of(o.send) == bytes{0x80, 0x08, 0x10, 0x00, 0x05, 0x00, 0x04, 0x05});
      client_fixture d(size);
      (void)d.c.upload({0x1008, 0}, std::span(d.buf).first(1), 0);
      (void)d.c.on_mailbox(M(1, res, {0x4B, 0x08, 0x10, 0x00, 1, 2, 0, 0}), 1);
      CHECK(d.c.error()->code == errc::buffer_too_small);
    }
  }
}

TEST_CASE("CoE client: unexpected mailboxes") {
  const std::array<std::uint8_t, 2> v{1, 2};
  SUBCASE("a response for another object, of another kind, an unknown command") {
    client_fixture c;
    (void)c.c.download({0x6040, 0}, v, 0);
    auto o = c.c.on_mailbox(M(1, res, {0x60, 0x41, 0x60, 0, 0, 0, 0, 0}), 1);
    CHECK(c.c.error()->code == errc::unexpected_frame);
    CHECK(abort_in(o.send) == A(0x08000000U)); // as the CAN client: another object
    client_fixture d;
    (void)d.c.download({0x6040, 0}, v, 0);
    o = d.c.on_mailbox(M(1, res, {0x4B, 0x40, 0x60, 0, 1, 2, 0, 0}), 1);
    CHECK(d.c.error()->code == errc::unexpected_frame);
    CHECK(d.c.error()->abort == A(0x05040001U));
    client_fixture e;
    (void)e.c.download({0x6040, 0}, v, 0);
    o = e.c.on_mailbox(M(1, res, {0xE0, 0x40, 0x60, 0, 0, 0, 0, 0}), 1);
    CHECK(e.c.error()->code == errc::unknown_command);
    CHECK(abort_in(o.send) == A(0x05040001U));
  }
  SUBCASE("mailboxes that cannot be read end the transfer with their error") {
    struct row {
      bytes mbx;
      errc e;
    };
    const row rows[] = {
        {M(1, res, {0x60, 0x40, 0x60}), errc::truncated}, // SDO part of 3 bytes
        {M(1, res, {0x60, 0x40, 0x60, 0, 0, 0, 0, 0, 0}), errc::too_long},
        {{0x0A, 0x00, 0x00, 0x00, 0x00, 0x13, 0x00}, errc::bad_length},         // length says 10
        {{0x0A, 0x00, 0x00}, errc::truncated},                                  // not even a header
        {M(1, 0x00, {0x60, 0x40, 0x60, 0, 0, 0, 0, 0}), errc::unknown_command}, // service 0
        {M(1, req, {0x60, 0x40, 0x60, 0, 0, 0, 0, 0}), errc::unexpected_frame}, // as a request
    };
    for (const auto &r : rows) {
      client_fixture c;
      (void)c.c.download({0x6040, 0}, v, 0);
      const auto o = c.c.on_mailbox(r.mbx, 1);
      CHECK(o.state == sdo::transfer_state::failed);
      CHECK(c.c.error()->code == r.e);
      CHECK(c.c.error()->address == od::address{0x6040, 0});
      CHECK(!o.send.empty());
      CHECK(c.c.refused() == r.e);
    }
    // longer than the response mailbox (SM1 of 16 bytes, a mailbox of 17)
    std::vector<std::uint8_t> sm0(16);
    std::array<std::uint8_t, 16> buf{};
    coe::sdo_client s2(sm0, 16);
    (void)s2.upload({0x1008, 0}, buf, 0);
    auto o = s2.on_mailbox(M(1, res, {0x41, 0x08, 0x10, 0x00, 1, 0, 0, 0, 'a'}), 1);
    CHECK(s2.error()->code == errc::too_long);
    CHECK(abort_in(o.send) == A(0x08000000U));
  }
  SUBCASE("a mailbox error reply ends the transfer without an abort") {
    client_fixture c;
    (void)c.c.download({0x6040, 0}, v, 0);
    const auto o = c.c.on_mailbox(bytes{4, 0, 0, 0, 0, 0x10, 0x01, 0x00, 0x04, 0x00}, 1);
    CHECK(o.send.empty());
    CHECK(o.state == sdo::transfer_state::failed);
    CHECK(c.c.error()->code == errc::unknown_command); // service not supported
    CHECK(c.c.error()->abort == sdo::abort_code::none);
    client_fixture d;
    (void)d.c.download({0x6040, 0}, v, 0);
    (void)d.c.on_mailbox(bytes{4, 0, 0, 0, 0, 0x10, 0x01, 0x00, 0x06, 0x00}, 1);
    CHECK(d.c.error()->code == errc::truncated); // size too short
    client_fixture e;
    (void)e.c.download({0x6040, 0}, v, 0);
    (void)e.c.on_mailbox(bytes{3, 0, 0, 0, 0, 0x10, 0x01, 0x00, 0x06}, 1);
    CHECK(e.c.error()->code == errc::truncated); // a broken error reply
  }
  SUBCASE("other services, other mailbox types and repeats are left alone") {
    client_fixture c;
    (void)c.c.download({0x6040, 0}, v, 0);
    const bytes emergency = M(1, 0x10, {0x30, 0x81, 0x11, 1, 2, 3, 4, 5});
    CHECK(c.c.on_mailbox(emergency, 1).send.empty());
    CHECK(c.c.refused() == errc::unexpected_frame);
    CHECK(c.c.busy());
    CHECK(c.c.on_mailbox(bytes{2, 0, 0, 0, 0, 0x22, 0, 0}, 1).send.empty()); // EoE
    CHECK(c.c.refused() == errc::unexpected_frame);
    CHECK(c.c.on_mailbox(M(3, 0x80, {0x02, 0, 0, 0, 1, 0}), 1).send.empty()); // SDO information
    CHECK(c.c.busy());
    // the response, then the same mailbox again (same counter): dropped
    const bytes resp = M(4, res, {0x60, 0x40, 0x60, 0, 0, 0, 0, 0});
    CHECK(c.c.on_mailbox(resp, 2).state == sdo::transfer_state::done);
    CHECK(c.c.refused().has_value());
    CHECK(c.c.on_mailbox(resp, 3).send.empty());
    CHECK(c.c.refused() == errc::unexpected_frame);
    // when idle, SDO responses are not taken either
    CHECK(c.c.on_mailbox(M(5, res, {0x60, 0x40, 0x60, 0, 0, 0, 0, 0}), 3).state ==
          sdo::transfer_state::done);
    CHECK(c.c.refused() == errc::unexpected_frame);
    CHECK(c.c.on_mailbox(bytes{4, 0, 0, 0, 0, 0x60, 0x01, 0x00, 0x04, 0x00}, 3).send.empty());
    CHECK(c.c.refused() == errc::unexpected_frame);
    CHECK(c.c.on_mailbox(bytes{1, 2}, 3).send.empty());
    CHECK(c.c.refused() == errc::truncated);
  }
  SUBCASE("counter 0 is never a repeat") {
    client_fixture c;
    (void)c.c.upload({0x1008, 0}, c.buf, 0);
    (void)c.c.on_mailbox(M(0, res, {0x41, 0x08, 0x10, 0x00, 10, 0, 0, 0}), 1);
    auto o = c.c.on_mailbox(M(0, res, {0x00, 1, 2, 3, 4, 5, 6, 7}), 2);
    CHECK(!o.send.empty());
    CHECK(c.c.refused().has_value());
  }
}

TEST_CASE("CoE client: download toggle error, the server's abort, timeout, cancel, starting") {
  SUBCASE("toggle error in a download and the server's abort") {
    client_fixture c(16); // a 16-byte mailbox: the initiate holds no data, segments of 7
    const auto v = pattern(20, 0);
    auto s = c.c.download({0x2009, 0}, v, 0).value();
    CHECK(body_of(s.send) == bytes{0x21, 0x09, 0x20, 0x00, 20, 0, 0, 0});
    auto o = c.c.on_mailbox(M(1, res, {0x60, 0x09, 0x20, 0, 0, 0, 0, 0}), 1);
    CHECK(o.send[8] == 0x00); // first segment, toggle 0, 7 bytes
    CHECK(c.c.transferred() == 0);
    o = c.c.on_mailbox(M(2, res, {0x30, 0, 0, 0, 0, 0, 0, 0}), 2); // toggle 1: wrong
    CHECK(c.c.error()->code == errc::bad_toggle);
    CHECK(abort_in(o.send) == A(0x05030000U));
    client_fixture d(16);
    (void)d.c.download({0x2009, 0}, v, 0);
    o = d.c.on_mailbox(M(1, req, {0x80, 0x09, 0x20, 0, 0x00, 0x00, 0x04, 0x05}), 1);
    CHECK(o.send.empty());
    CHECK(d.c.error()->code == errc::aborted);
    CHECK(d.c.error()->abort == A(0x05040000U));
  }
  SUBCASE("a download confirmed segment by segment counts what the slave took") {
    client_fixture c(16);
    const auto v = pattern(20, 0);
    (void)c.c.download({0x2009, 0}, v, 0);
    auto o = c.c.on_mailbox(M(1, res, {0x60, 0x09, 0x20, 0, 0, 0, 0, 0}), 1);
    o = c.c.on_mailbox(M(2, res, {0x20, 0, 0, 0, 0, 0, 0, 0}), 2);
    CHECK(c.c.transferred() == 7);
    CHECK(o.send[8] == 0x10);
    o = c.c.on_mailbox(M(3, res, {0x30, 0, 0, 0, 0, 0, 0, 0}), 3);
    CHECK(o.send[8] == 0x03); // toggle 0, 1 unused (6 bytes), last
    CHECK(bytes(o.send.begin() + 9, o.send.begin() + 15) == bytes(v.begin() + 14, v.end()));
    CHECK(o.send[15] == 0); // padding
    o = c.c.on_mailbox(M(4, res, {0x20, 0, 0, 0, 0, 0, 0, 0}), 4);
    CHECK(o.state == sdo::transfer_state::done);
    CHECK(c.c.transferred() == 20);
  }
  SUBCASE("timeout and cancel, busy, bad mailboxes and complete access arguments") {
    client_fixture c(128, 100);
    (void)c.c.upload({0x1000, 0}, c.buf, 0xFFFF'FFF0U); // wraps around
    CHECK(c.c.upload({0x1000, 0}, c.buf, 0) == errc::bad_state);
    CHECK(c.c.poll(0x0000'0050U).send.empty());
    auto o = c.c.poll(0x0000'0054U);
    CHECK(c.c.error()->code == errc::timeout);
    CHECK(body_of(o.send) == bytes{0x80, 0x00, 0x10, 0x00, 0x00, 0x00, 0x04, 0x05});
    (void)c.c.upload({0x1000, 0}, c.buf, 0);
    o = c.c.cancel();
    CHECK(c.c.error()->code == errc::aborted);
    CHECK(o.send[8] == 0x80);
    std::vector<std::uint8_t> tiny(15);
    coe::sdo_client bad(tiny, 128);
    CHECK(bad.upload({0x1000, 0}, c.buf, 0) == errc::invalid_argument);
    std::vector<std::uint8_t> ok(16);
    coe::sdo_client bad2(ok, 15);
    CHECK(bad2.download({0x1000, 0}, c.buf, 0) == errc::invalid_argument);
    client_fixture d;
    CHECK(d.c.upload({0x1C12, 2}, d.buf, 0, true) == errc::invalid_argument);
    CHECK(d.c.last_sent().empty());
  }
  SUBCASE("the mailbox counter runs 1..7, and last_sent keeps a mailbox for a repeat") {
    client_fixture c(16);
    const auto v = pattern(70, 0); // 10 segments of 7
    auto s = c.c.download({0x2009, 0}, v, 0).value();
    std::vector<std::uint8_t> counters{static_cast<std::uint8_t>(s.send[5] >> 4U)};
    CHECK(bytes(c.c.last_sent().begin(), c.c.last_sent().end()) ==
          bytes(s.send.begin(), s.send.end()));
    auto o = c.c.on_mailbox(M(1, res, {0x60, 0x09, 0x20, 0, 0, 0, 0, 0}), 1);
    bool toggle = false;
    for (std::uint8_t k = 2; o.state == sdo::transfer_state::busy; ++k) {
      counters.push_back(static_cast<std::uint8_t>(o.send[5] >> 4U));
      o = c.c.on_mailbox(M(static_cast<std::uint8_t>((k - 1U) % 7U + 1U), res,
                           {static_cast<std::uint8_t>(toggle ? 0x30 : 0x20), 0, 0, 0, 0, 0, 0, 0}),
                         k);
      toggle = !toggle;
    }
    CHECK(o.state == sdo::transfer_state::done);
    CHECK(counters == bytes{1, 2, 3, 4, 5, 6, 7, 1, 2, 3, 4});
  }
}

TEST_CASE("CoE server: refused mailboxes get mailbox error replies, the transfer goes on") {
  mailbox_link l(128);
  auto &s = l.server;
  // a running download
  auto r = s.on_mailbox(M(1, req, {0x21, 0x09, 0x20, 0x00, 14, 0, 0, 0}), 0);
  CHECK(r.send[8] == 0x60);
  CHECK(r.send[7] == res);
  struct row {
    bytes mbx;
    errc e;
    coe::mailbox_error detail;
  };
  const row rows[] = {
      {{0x0A, 0x00, 0x00}, errc::truncated, coe::mailbox_error::size_too_short},
      {{0x0A, 0, 0, 0, 0, 0x23, 0x00, 0x20, 0x00},
       errc::bad_length,
       coe::mailbox_error::invalid_size},
      {{2, 0, 0, 0, 0, 0x32, 0, 0},
       errc::unknown_command,
       coe::mailbox_error::unsupported_protocol}, // EoE
      {{1, 0, 0, 0, 0, 0x43, 0}, errc::truncated, coe::mailbox_error::size_too_short},
      {M(5, 0x10, {0x30, 0x81, 0x11, 1, 2, 3, 4, 5}), errc::unknown_command,
       coe::mailbox_error::service_not_supported}, // emergency
      {M(6, 0x80, {0x01, 0, 0, 0, 0x01, 0}), errc::unknown_command,
       coe::mailbox_error::service_not_supported}, // SDO information
      {M(7, res, {0x60, 0x09, 0x20, 0, 0, 0, 0, 0}), errc::unknown_command,
       coe::mailbox_error::service_not_supported}, // an SDO response to the server
      {M(1, req, {0x40, 0x09, 0x20}), errc::truncated, coe::mailbox_error::size_too_short},
      {M(2, req, {0x40, 0x09, 0x20, 0, 0, 0, 0, 0, 0}), errc::too_long,
       coe::mailbox_error::invalid_size},
      {M(3, req, {0x02, 1, 2, 3, 4, 5, 6, 7, 8}), errc::bad_length,
       coe::mailbox_error::invalid_size},
  };
  for (const auto &row : rows) {
    CAPTURE(row.mbx.size());
    const auto a = s.on_mailbox(row.mbx, 0);
    CHECK(s.refused() == row.e);
    CHECK(error_in(a.send) == row.detail);
    CHECK(s.busy());
  }
  // longer than the receive mailbox
  std::vector<std::uint8_t> big(140);
  big[0] = 134;
  big[5] = 0x03; // counter 0
  big[7] = req;
  CHECK(error_in(s.on_mailbox(big, 0).send) == coe::mailbox_error::invalid_size);
  CHECK(s.refused() == errc::too_long);
  // the transfer still takes its segments
  r = s.on_mailbox(M(4, req, {0x00, 'a', 'b', 'c', 'd', 'e', 'f', 'g'}), 0);
  CHECK(r.send[8] == 0x20);
  r = s.on_mailbox(M(5, req, {0x11, 'h', 'i', 'j', 'k', 'l', 'm', 'n'}), 0);
  CHECK(r.send[8] == 0x30);
  CHECK(s.state() == sdo::transfer_state::done);
  CHECK(l.store.value({0x2009, 0}).value().size() == 14);
}

TEST_CASE("CoE server: toggle errors, stray segments, unknown commands, sizes, timeouts") {
  for (const std::size_t size : mailbox_sizes) {
    CAPTURE(size);
    mailbox_link l(size);
    auto &s = l.server;
    SUBCASE("stray segment and upload-segment requests") {
      auto r = s.on_mailbox(M(1, req, {0x00, 1, 2, 3, 4, 5, 6, 7}), 0);
      CHECK(abort_in(r.send) == A(0x05040001U));
      r = s.on_mailbox(M(2, req, {0x60, 0, 0, 0, 0, 0, 0, 0}), 0);
      CHECK(abort_in(r.send) == A(0x05040001U));
    }
    SUBCASE("block transfer and command specifier 7 are unknown commands in CoE") {
      std::uint8_t counter = 0;
      for (const std::uint8_t cmd :
           {std::uint8_t{0xC6}, std::uint8_t{0xA4}, std::uint8_t{0xA1}, std::uint8_t{0xE0}}) {
        CAPTURE(static_cast<int>(cmd));
        counter = coe::next_counter(counter);
        const auto r = s.on_mailbox(M(counter, req, {cmd, 0x09, 0x20, 0x00, 20, 0, 0, 0}), 0);
        CHECK(body_of(r.send) == bytes{0x80, 0x09, 0x20, 0x00, 0x01, 0x00, 0x04, 0x05});
        CHECK(s.error()->code == errc::unknown_command);
        CHECK(s.error()->address == od::address{0x2009, 0});
      }
    }
    SUBCASE("segment toggle error") {
      CHECK(s.on_mailbox(M(1, req, {0x21, 0x09, 0x20, 0x00, 14, 0, 0, 0}), 0).send[8] == 0x60);
      CHECK(s.on_mailbox(M(2, req, {0x00, 'a', 'b', 'c', 'd', 'e', 'f', 'g'}), 0).send[8] == 0x20);
      const auto r = s.on_mailbox(M(3, req, {0x01, 'a', 'b', 'c', 'd', 'e', 'f', 'g'}), 0);
      CHECK(body_of(r.send) == bytes{0x80, 0x09, 0x20, 0x00, 0x00, 0x00, 0x03, 0x05});
      CHECK(s.error()->code == errc::bad_toggle);
      // an upload segment request with the wrong toggle (a value that needs segments)
      const auto big = pattern(2000, 1);
      REQUIRE(l.write(0x2020, 0, big) == sdo::transfer_state::done);
      auto u = s.on_mailbox(M(0, req, {0x40, 0x20, 0x20, 0, 0, 0, 0, 0}), 0);
      CHECK(u.send[8] == 0x41);
      u = s.on_mailbox(M(0, req, {0x70, 0, 0, 0, 0, 0, 0, 0}), 0);
      CHECK(abort_in(u.send) == A(0x05030000U));
      CHECK(s.error()->code == errc::bad_toggle);
    }
    SUBCASE("segments disagree with the announced size") {
      (void)s.on_mailbox(M(1, req, {0x21, 0x09, 0x20, 0x00, 10, 0, 0, 0}), 0);
      (void)s.on_mailbox(M(2, req, {0x00, 'a', 'b', 'c', 'd', 'e', 'f', 'g'}), 0);
      auto r = s.on_mailbox(M(3, req, {0x10, 'a', 'b', 'c', 'd', 'e', 'f', 'g'}), 0);
      CHECK(abort_in(r.send) == A(0x06070012U));
      (void)s.on_mailbox(M(4, req, {0x21, 0x09, 0x20, 0x00, 10, 0, 0, 0}), 0);
      r = s.on_mailbox(M(5, req, {0x0B, 'a', 'b', 0, 0, 0, 0, 0}), 0);
      CHECK(abort_in(r.send) == A(0x06070013U));
      r = s.on_mailbox(M(6, req, {0x21, 0x09, 0x20, 0x00, 0x00, 0x10, 0, 0}), 0);
      CHECK(abort_in(r.send) == A(0x06070012U));
      // a normal initiate with more data than its size: refused (invalid size); with all of
      // it, where the mailbox holds it: done in one mailbox
      r = s.on_mailbox(M(7, req, {0x21, 0x09, 0x20, 0x00, 2, 0, 0, 0, 'a', 'b', 'c'}), 0);
      CHECK(s.refused() == (size >= 19 ? errc::bad_length : errc::too_long));
      CHECK(error_in(r.send) == coe::mailbox_error::invalid_size);
      r = s.on_mailbox(M(1, req,
                         {0x21, 0x09, 0x20, 0x00, 10, 0, 0, 0, 'a', 'b', 'c', 'd', 'e', 'f', 'g',
                          'h', 'i', 'j'}),
                       0);
      if (size >= 26) {
        CHECK(r.send[8] == 0x60);
        CHECK(l.store.value({0x2009, 0}).value().size() == 10);
      } else {
        CHECK(s.refused() == errc::too_long);
      }
    }
    SUBCASE("timeout of a segmented transfer") {
      (void)s.on_mailbox(M(1, req, {0x21, 0x09, 0x20, 0x00, 10, 0, 0, 0}), 0);
      CHECK(s.poll(999).send.empty());
      const auto r = s.poll(1000);
      CHECK(body_of(r.send) == bytes{0x80, 0x09, 0x20, 0x00, 0x00, 0x00, 0x04, 0x05});
      CHECK(s.state() == sdo::transfer_state::failed);
      CHECK(s.poll(5000).send.empty());
    }
    SUBCASE("the client's abort ends a segmented transfer, unanswered") {
      (void)s.on_mailbox(M(1, req, {0x21, 0x09, 0x20, 0x00, 10, 0, 0, 0}), 0);
      CHECK(s.on_mailbox(M(2, req, {0x80, 0x09, 0x20, 0x00, 0, 0, 0, 8}), 0).send.empty());
      CHECK(s.state() == sdo::transfer_state::failed);
      CHECK(s.error()->code == errc::aborted);
    }
  }
}

TEST_CASE("CoE server: complete access is refused with 0x06010004, repeats are dropped") {
  mailbox_link l(128);
  auto &s = l.server;
  (void)s.on_mailbox(M(1, req, {0x21, 0x09, 0x20, 0x00, 14, 0, 0, 0}), 0);
  auto r = s.on_mailbox(M(2, req, {0x50, 0x00, 0x30, 0x00, 0, 0, 0, 0}), 0);
  CHECK(body_of(r.send) == bytes{0x80, 0x00, 0x30, 0x00, 0x04, 0x00, 0x01, 0x06});
  CHECK(s.refused() == errc::access_denied);
  CHECK(s.busy()); // the running download goes on
  r = s.on_mailbox(M(3, req, {0x31, 0x00, 0x30, 0x00, 2, 0, 0, 0, 1, 0}), 0);
  CHECK(abort_in(r.send) == sdo::abort_code::complete_access_unsupported);
  // repeats: the same counter twice is dropped; last_sent keeps the answer for a repeat request
  const bytes seg = M(4, req, {0x00, 'a', 'b', 'c', 'd', 'e', 'f', 'g'});
  r = s.on_mailbox(seg, 0);
  CHECK(r.send[8] == 0x20);
  const bytes answer(r.send.begin(), r.send.end());
  CHECK(s.on_mailbox(seg, 0).send.empty());
  CHECK(s.refused() == errc::unexpected_frame);
  CHECK(bytes(s.last_sent().begin(), s.last_sent().end()) == answer);
  r = s.on_mailbox(M(5, req, {0x11, 'h', 'i', 'j', 'k', 'l', 'm', 'n'}), 0);
  CHECK(s.state() == sdo::transfer_state::done);
  // the server's counters run 1..7, 1, …
  CHECK((r.send[5] >> 4U) == 5); // answers 1..5: the repeat got none
  // a server whose send mailbox is too small refuses every SDO request
  std::vector<std::uint8_t> sm1(15), buf(64);
  coe::sdo_server<store_t> tiny(l.store, buf, sm1, 128);
  CHECK(error_in(tiny.on_mailbox(M(1, req, {0x40, 0x00, 0x10, 0, 0, 0, 0, 0}), 0).send) ==
        coe::mailbox_error::invalid_size);
  CHECK(tiny.refused() == errc::invalid_argument);
}

TEST_CASE("CoE: a client and a server with every mailbox corrupted in one byte end cleanly") {
  // every byte position of every mailbox of a segmented download, flipped once: both sides
  // end (done or failed, nothing left busy), and the object holds nothing or 300 bytes
  const auto v = pattern(300, 9);
  for (std::size_t victim = 0; victim < 12; ++victim) {
    for (std::size_t at = 0; at < 40; ++at) {
      mailbox_link l(64);
      std::size_t k = 0;
      l.fault = [&](std::vector<std::uint8_t> &b) {
        if (k++ == victim && at < b.size()) b[at] ^= 0x5A;
      };
      const auto st = l.write(0x2009, 0, v);
      CHECK(!l.client.busy());
      CHECK(!l.server.busy());
      // CoE has no check sum: a corrupted data byte is stored as it came; sizes are checked
      const auto stored = l.store.value({0x2009, 0}).value();
      if (st == sdo::transfer_state::done) CHECK(stored.size() == 300);
      CHECK((stored.size() == 300 || stored.empty()));
    }
  }
}

TEST_CASE("CoE client: complete access (ETG.1000.6 5.6.2, bit 4 of the initiate)") {
  // upload of 1C12h with sub-index 0 included: 50 12 1C 00; the slave answers normal, with the
  // object's image (here: 2 entries, sub-index 0 padded to 16 bits, then 1600h and 1601h)
  client_fixture c;
  auto s = c.c.upload({0x1C12, 0}, c.buf, 0, true).value();
  CHECK(body_of(s.send) == bytes{0x50, 0x12, 0x1C, 0x00, 0, 0, 0, 0});
  auto o = c.c.on_mailbox(
      M(1, res, {0x51, 0x12, 0x1C, 0x00, 6, 0, 0, 0, 0x02, 0x00, 0x00, 0x16, 0x01, 0x16}), 1);
  CHECK(o.state == sdo::transfer_state::done);
  CHECK(bytes(c.c.received().begin(), c.c.received().end()) ==
        bytes{0x02, 0x00, 0x00, 0x16, 0x01, 0x16});
  // sub-index 0 excluded: sub-index 1
  client_fixture e;
  CHECK(body_of(e.c.upload({0x1C12, 1}, e.buf, 0, true).value().send)[3] == 0x01);
  // a download of the whole object: normal with bit 4 (31), also for 4 bytes
  const std::array<std::uint8_t, 4> image{0x01, 0x00, 0x00, 0x16};
  client_fixture d;
  s = d.c.download({0x1C12, 0}, image, 0, true).value();
  CHECK(body_of(s.send) == bytes{0x31, 0x12, 0x1C, 0x00, 4, 0, 0, 0, 0x01, 0x00, 0x00, 0x16});
  o = d.c.on_mailbox(M(1, res, {0x70, 0x12, 0x1C, 0x00, 0, 0, 0, 0}), 1);
  CHECK(o.state == sdo::transfer_state::done);
  CHECK(d.c.transferred() == 4);
  // in a 16-byte mailbox the 4 bytes do not fit a normal initiate: expedited with bit 4 (33)
  client_fixture t(16);
  s = t.c.download({0x1C12, 0}, image, 0, true).value();
  CHECK(body_of(s.send) == bytes{0x33, 0x12, 0x1C, 0x00, 0x01, 0x00, 0x00, 0x16});
  CHECK(t.c.on_mailbox(M(1, res, {0x70, 0x12, 0x1C, 0x00, 0, 0, 0, 0}), 1).state ==
        sdo::transfer_state::done);
  // an image longer than a mailbox: normal, then segments, as any value
  client_fixture l(16);
  const auto big = pattern(20, 1);
  s = l.c.download({0x1C12, 1}, big, 0, true).value();
  CHECK(body_of(s.send) == bytes{0x31, 0x12, 0x1C, 0x01, 20, 0, 0, 0});
  o = l.c.on_mailbox(M(1, res, {0x70, 0x12, 0x1C, 0x01, 0, 0, 0, 0}), 1);
  CHECK(o.send[8] == 0x00); // the first segment
}
