// Streamed SDO: canopen::sdo::client's part transfers (upload_parts / next_part, download_parts
// / feed) and host::sdo_session::read_parts / write_parts, host::remote_node's on a DOMAIN of
// 5000 bytes through one buffer of 64 bytes, against a fieldcodec SDO server on an in-memory
// bus (tests/sdo_test_dictionary.hpp). Bad input: a source that ends early, a sink that stops,
// a value beyond the DOMAIN's capacity, a non-byte-string object, a frame while a part waits,
// a part too short to go on, calls in the wrong state.
#include "sdo_test_dictionary.hpp"

#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/host/remote_node.hpp>

#include <doctest/doctest.h>

#include <deque>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace host = fieldcodec::host;
namespace od = fieldcodec::od;
using fieldcodec::errc;

namespace {

constexpr auto layout = co::make_layout<std::size(sdo_test::entries)>(sdo_test::dict);
constexpr od::address domain{0x2020, 0}; // DOMAIN, capacity 5000

/// Node 5, an SDO server over the test dictionary, on an in-memory bus.
class server_bus final : public host::can_bus {
public:
  server_bus() {
    name_ = "test0";
    REQUIRE(store.init_defaults(5).has_value());
  }
  fieldcodec::status send(const co::can_frame &f) override {
    ++frames;
    for (const auto &g : server.on_frame(f, 0).send) queue.push_back(g);
    return {};
  }
  fieldcodec::result<host::frame_record> receive_record(std::chrono::milliseconds) override {
    if (queue.empty()) return fail(errc::timeout, 0, "no frame in time");
    auto r = host::to_record(queue.front());
    queue.pop_front();
    return r;
  }
  std::vector<std::uint8_t> storage =
      std::vector<std::uint8_t>(co::dictionary_store<>::storage_size(sdo_test::dict));
  co::dictionary_store<> store{sdo_test::dict, layout, storage};
  std::vector<std::uint8_t> server_buffer = std::vector<std::uint8_t>(8192);
  sdo::server<co::dictionary_store<>> server{5, store, server_buffer};
  std::deque<co::can_frame> queue;
  std::size_t frames = 0;
};

std::vector<std::uint8_t> pattern(std::size_t n) {
  std::vector<std::uint8_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>((i * 7U + 3U) & 0xFFU);
  return v;
}

} // namespace

TEST_CASE("sdo_session: a DOMAIN of 5000 bytes written and read in parts of 64") {
  server_bus bus;
  host::sdo_session s(bus, 5, {.part_size = 64});
  const auto data = pattern(5000);
  std::size_t at = 0;
  std::size_t calls = 0;
  auto w = s.write_parts(domain, 5000, [&](std::span<std::uint8_t> out) {
    ++calls;
    CHECK(out.size() <= 64);
    const std::size_t n = std::min(out.size(), data.size() - at);
    std::copy_n(data.begin() + static_cast<std::ptrdiff_t>(at), n, out.begin());
    at += n;
    return n;
  });
  REQUIRE_MESSAGE(w, w.error().what);
  CHECK(calls > 5000 / 64);
  auto stored = bus.store.value(domain).value();
  CHECK(std::vector<std::uint8_t>(stored.begin(), stored.end()) == data);

  std::vector<std::uint8_t> back;
  std::size_t parts = 0;
  auto r = s.read_parts(domain, [&](std::span<const std::uint8_t> p) {
    ++parts;
    CHECK(p.size() <= 64);
    back.insert(back.end(), p.begin(), p.end());
    return true;
  });
  REQUIRE_MESSAGE(r, r.error().what);
  CHECK(r.value() == 5000);
  CHECK(back == data);
  CHECK(parts >= 5000 / 64);

  // small objects: expedited through the same calls
  std::vector<std::uint8_t> small;
  auto e = s.read_parts({0x1000, 0}, [&](std::span<const std::uint8_t> p) {
    small.assign(p.begin(), p.end());
    return true;
  });
  REQUIRE(e);
  CHECK(small == std::vector<std::uint8_t>{0x92, 0x01, 0x02, 0x00});
}

TEST_CASE("sdo_session parts: a source that ends early, a sink that stops") {
  server_bus bus;
  host::sdo_session s(bus, 5, {.part_size = 64});
  const std::size_t before = bus.frames;
  auto none = s.write_parts(domain, 100, [](std::span<std::uint8_t>) { return std::size_t{0}; });
  REQUIRE_FALSE(none);
  CHECK(none.error().code == errc::bad_length);
  CHECK(none.error().what == "node 5, 2020h:00: the source gave 0 of 100 bytes");
  CHECK(bus.frames == before); // nothing sent

  std::size_t given = 0;
  auto short_source = s.write_parts(domain, 1000, [&](std::span<std::uint8_t> out) {
    if (given >= 200) return std::size_t{0};
    std::fill(out.begin(), out.end(), std::uint8_t{1});
    given += out.size();
    return out.size();
  });
  REQUIRE_FALSE(short_source);
  CHECK(short_source.error().code == errc::bad_length);
  CHECK(bus.frames > before); // started, then aborted

  REQUIRE(s.write_parts(domain, 200, [](std::span<std::uint8_t> out) {
    std::fill(out.begin(), out.end(), std::uint8_t{2});
    return out.size();
  }));
  auto stop = s.read_parts(domain, [](std::span<const std::uint8_t>) { return false; });
  REQUIRE_FALSE(stop);
  CHECK(stop.error().code == errc::aborted);
  CHECK(stop.error().what ==
        "node 5, 2020h:00: stopped by the caller (sent SDO abort 08000000h: general error)");
}

TEST_CASE("remote_node parts: byte strings only, within the capacity") {
  server_bus bus;
  host::remote_node n(bus, 5, sdo_test::dict, {}, {.part_size = 64});
  const auto d = sdo_test::dict.at(domain).value();
  const auto data = pattern(3000);
  std::size_t at = 0;
  auto w = n.write_parts(d, 3000, [&](std::span<std::uint8_t> out) {
    const std::size_t k = std::min(out.size(), data.size() - at);
    std::copy_n(data.begin() + static_cast<std::ptrdiff_t>(at), k, out.begin());
    at += k;
    return k;
  });
  REQUIRE_MESSAGE(w, w.error().what);
  std::vector<std::uint8_t> back;
  auto r = n.read_parts(d, [&](std::span<const std::uint8_t> p) {
    back.insert(back.end(), p.begin(), p.end());
    return true;
  });
  REQUIRE(r);
  CHECK(back == data);

  const std::size_t before = bus.frames;
  auto big = n.write_parts(d, 5001, [](std::span<std::uint8_t> o) { return o.size(); });
  REQUIRE_FALSE(big);
  CHECK(big.error().value.issue == od::value_issue::capacity);
  CHECK(big.error().value.capacity == 5000);
  auto number = n.read_parts(sdo_test::dict.at({0x2007, 0}).value(),
                             [](std::span<const std::uint8_t>) { return true; });
  REQUIRE_FALSE(number);
  CHECK(number.error().code == errc::type_mismatch);
  CHECK(bus.frames == before);
}

TEST_CASE("sdo::client parts: wrong calls, a frame while a part waits, a short part") {
  sdo::client c(5);
  std::array<std::uint8_t, 6> tiny{};
  CHECK(c.upload_parts(domain, tiny, 0).error() == errc::invalid_argument); // < 7 bytes
  std::array<std::uint8_t, 7> window{};
  CHECK(c.next_part(0).error() == errc::bad_state);
  const std::array<std::uint8_t, 3> three{1, 2, 3};
  CHECK(c.download_parts(domain, 2, three, 0).error() == errc::invalid_argument); // > size
  CHECK(c.download_parts(domain, 10, {}, 0).error() == errc::invalid_argument);   // empty

  // upload: initiate answered with 20 bytes, one segment of 7 fills the window
  REQUIRE(c.upload_parts(domain, window, 0));
  (void)c.on_frame(co::make_frame(0x585, {0x41, 0x20, 0x20, 0x00, 20, 0, 0, 0}).value(), 1);
  (void)c.on_frame(co::make_frame(0x585, {0x00, 1, 2, 3, 4, 5, 6, 7}).value(), 2);
  REQUIRE(c.part_ready());
  CHECK(c.received().size() == 7);
  CHECK(c.poll(100000).send.empty()); // no timeout while the caller holds the part
  CHECK(c.part_ready());
  CHECK(c.feed(three, 3).error() == errc::bad_state); // an upload takes no feed
  // a segment nobody asked for: refused, the transfer aborts, nothing written past the window
  auto stray = c.on_frame(co::make_frame(0x585, {0x10, 9, 9, 9, 9, 9, 9, 9}).value(), 4);
  CHECK(c.state() == sdo::transfer_state::failed);
  REQUIRE(stray.send.size() == 1);
  CHECK(stray.send[0].data[0] == 0x80);

  // download: 10 bytes, the first part holds 7; the next part must hold the 3 left
  sdo::client d(5);
  const std::array<std::uint8_t, 7> first{1, 2, 3, 4, 5, 6, 7};
  REQUIRE(d.download_parts(domain, 10, first, 0));
  auto seg = d.on_frame(co::make_frame(0x585, {0x60, 0x20, 0x20, 0x00, 0, 0, 0, 0}).value(), 1);
  REQUIRE(seg.send.size() == 1); // segment 1: 7 bytes
  auto paused = d.on_frame(co::make_frame(0x585, {0x20, 0, 0, 0, 0, 0, 0, 0}).value(), 2);
  CHECK(paused.send.empty());
  REQUIRE(d.part_ready());
  CHECK(d.transferred() == 7);
  CHECK(d.next_part(3).error() == errc::bad_state); // a download takes feed
  const std::array<std::uint8_t, 2> two{8, 9};
  CHECK(d.feed(two, 3).error() == errc::invalid_argument); // 3 bytes are left
  const std::array<std::uint8_t, 4> four{8, 9, 10, 11};
  CHECK(d.feed(four, 3).error() == errc::invalid_argument); // beyond the 10 announced
  const std::array<std::uint8_t, 3> rest{8, 9, 10};
  auto last = d.feed(rest, 3);
  REQUIRE(last);
  REQUIRE(last.value().send.size() == 1);
  CHECK(last.value().send[0].data[0] == 0x19); // toggle 1, 3 bytes (n = 4), last
  (void)d.on_frame(co::make_frame(0x585, {0x30, 0, 0, 0, 0, 0, 0, 0}).value(), 4);
  CHECK(d.state() == sdo::transfer_state::done);
}

TEST_CASE("docs/host.md: large objects in parts") {
  server_bus bus;
  const auto data = pattern(5000);
  REQUIRE(bus.store.set(domain, data) == sdo::abort_code::none);
  host::sdo_session s(bus, 5, {.part_size = 64});
  std::vector<std::uint8_t> back;
  auto r = s.read_parts(domain, [&](std::span<const std::uint8_t> part) {
    back.insert(back.end(), part.begin(), part.end()); // or write it to a file
    return true;                                       // false stops: abort 08000000h
  });
  // r.value() == 5000: the bytes read, in parts of at most 64
  REQUIRE(r);
  CHECK(r.value() == 5000);
  CHECK(back == data);
}
