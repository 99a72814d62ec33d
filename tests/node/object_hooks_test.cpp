// The application's hooks on single objects (node/object_hooks.hpp, capacity::hooks;
// docs/canopen.md, "Application hooks"): read hooks (SDO upload, TPDO sampling), write hooks
// (SDO download, RPDO), streamed DOMAIN contents (expedited, segmented, block), with the
// node's checks kept and the abort codes on the wire.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/object_hooks.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>

#include <string>

using namespace test_node;

namespace {

constexpr node::capacity hook_caps = [] {
  node::capacity c = caps;
  c.hooks = 4;
  return c;
}();
using hook_device = node::device<store_type, hook_caps>;

/// The application in the tests: what its hooks were asked, what they answer.
struct app {
  std::uint32_t counter = 1000;       ///< read: the computed value (then + 1)
  abort_code read_answer{};           ///< read: refuse with this
  std::uint64_t computed_value = 0;   ///< read of 2002h: this value (may be out of its limits)
  std::vector<std::uint32_t> written; ///< write: the values accepted
  abort_code write_answer{};          ///< write: refuse odd values with this
  // the stream: the application's own contents (its file, its flash), not the node's
  std::vector<std::uint8_t> contents;
  std::vector<std::uint8_t> received;
  std::vector<std::size_t> offsets;      ///< the offsets of the parts, upload and download
  std::size_t completed = 0;             ///< downloads that ended with `last`
  std::size_t stop_at = ~std::size_t{0}; ///< abort a part at or past this offset …
  abort_code stop_with = abort_code::cannot_store; ///< … with this
  std::vector<std::pair<od::address, abort_code>> ended;

  static abort_code read(void *c, od::address a, std::span<std::uint8_t> v) noexcept {
    auto &s = *static_cast<app *>(c);
    if (s.read_answer != abort_code::none) return s.read_answer;
    const std::uint64_t x = a.index == 0x2002 ? s.computed_value : s.counter++;
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint8_t>(x >> (8U * i));
    return abort_code::none;
  }
  static abort_code write(void *c, od::address, std::span<const std::uint8_t> v) noexcept {
    auto &s = *static_cast<app *>(c);
    std::uint32_t x = 0;
    for (std::size_t i = v.size(); i-- > 0;) x = (x << 8U) | v[i];
    if ((x & 1U) != 0U && s.write_answer != abort_code::none) return s.write_answer;
    s.written.push_back(x);
    return abort_code::none;
  }
  static abort_code upload(void *c, od::address, std::size_t offset, std::span<std::uint8_t> out,
                           std::size_t &total) noexcept {
    auto &s = *static_cast<app *>(c);
    s.offsets.push_back(offset);
    if (offset >= s.stop_at) return s.stop_with;
    total = s.contents.size();
    for (std::size_t i = 0; i < out.size() && offset + i < total; ++i) {
      out[i] = s.contents[offset + i];
    }
    return abort_code::none;
  }
  static abort_code download(void *c, od::address, std::size_t offset,
                             std::span<const std::uint8_t> part, bool last) noexcept {
    auto &s = *static_cast<app *>(c);
    s.offsets.push_back(offset);
    if (offset + part.size() > s.stop_at) return s.stop_with;
    if (offset == 0U) s.received.clear();
    if (offset != s.received.size()) return abort_code::general_error; // never: in order
    s.received.insert(s.received.end(), part.begin(), part.end());
    if (last) ++s.completed;
    return abort_code::none;
  }
  static void end(void *c, od::address a, abort_code why) noexcept {
    static_cast<app *>(c)->ended.emplace_back(a, why);
  }

  node::object_hook value_hook(od::address first, od::address last, bool r, bool w) {
    node::object_hook h;
    h.first = first;
    h.last = last;
    h.context = this;
    if (r) h.read = &app::read;
    if (w) h.write = &app::write;
    return h;
  }
  node::object_hook stream_hook(od::address a, bool up = true, bool down = true) {
    node::object_hook h;
    h.first = h.last = a;
    h.context = this;
    if (up) h.upload = &app::upload;
    if (down) h.download = &app::download;
    h.ended = &app::end;
    return h;
  }
};

/// Run a transfer of `c` (its first step `first`) against node 5 `dev`: frames both ways until
/// nothing moves. `cancel_after`: the client aborts after that many frames of the node.
template <class Device>
sdo::transfer_state pump(Device &dev, sdo::client &c, fieldcodec::result<sdo::step> first,
                         std::uint32_t now, std::size_t cancel_after = ~std::size_t{0}) {
  REQUIRE(first.has_value());
  const auto response_id = sdo::channel::default_for(5).value().response_id;
  std::vector<co::can_frame> to_node = list(first.value().send);
  std::size_t seen = 0;
  while (!to_node.empty()) {
    std::vector<co::can_frame> to_client;
    for (const auto &f : to_node) {
      for (const auto &g : dev.on_frame(f, now).send) {
        if (g.id == response_id) to_client.push_back(g);
      }
    }
    to_node.clear();
    for (const auto &g : to_client) {
      if (++seen > cancel_after && c.busy()) {
        for (const auto &h : c.cancel(abort_code::general_error).send) to_node.push_back(h);
        break;
      }
      for (const auto &h : c.on_frame(g, now).send) to_node.push_back(h);
    }
  }
  return c.state();
}

/// A node with hooks over the test dictionary (2005h: a DOMAIN of capacity 4000).
struct hook_rig {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout5.storage_size());
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(4000);
  store_type store{dict5, layout5, storage, staging};
  hook_device dev;
  std::uint32_t now = 0;
  sdo::channel ch = sdo::channel::default_for(5).value();

  hook_rig() : dev(init(store), 5) {}
  static store_type &init(store_type &s) {
    REQUIRE(s.init_defaults(5).has_value());
    return s;
  }
  std::vector<co::can_frame> feed(const co::can_frame &f) {
    return list(dev.on_frame(f, now).send);
  }
  void operational() {
    (void)dev.start(now);
    (void)feed(F(0, {0x01, 5}));
    REQUIRE(dev.state() == co::nmt::state::operational);
  }

  sdo::transfer_state run(sdo::client &c, fieldcodec::result<sdo::step> first,
                          std::size_t cancel_after = ~std::size_t{0}) {
    return pump(dev, c, first, now, cancel_after);
  }
  /// The abort code the node sent last for the transfer of `c`, or none.
  static abort_code abort_of(const sdo::client &c) {
    const auto e = c.error();
    return e ? e->abort : abort_code::none;
  }

  /// SDO upload of `a` (expedited or segmented): the bytes, or the abort code.
  std::pair<std::vector<std::uint8_t>, abort_code> upload(od::address a, bool block = false) {
    sdo::client c(5);
    std::vector<std::uint8_t> buf(8192);
    const auto st = run(c, block ? c.block_upload(a, buf, now) : c.upload(a, buf, now));
    if (st != sdo::transfer_state::done) return {{}, abort_of(c)};
    const auto r = c.received();
    return {{r.begin(), r.end()}, abort_code::none};
  }
  abort_code download(od::address a, std::span<const std::uint8_t> data, bool block = false,
                      std::size_t cancel_after = ~std::size_t{0}) {
    sdo::client c(5);
    const auto st =
        run(c, block ? c.block_download(a, data, now) : c.download(a, data, now), cancel_after);
    return st == sdo::transfer_state::done ? abort_code::none : abort_of(c);
  }
  abort_code write_u32(od::address a, std::uint32_t v, std::size_t width = 4) {
    std::array<std::uint8_t, 4> b{};
    for (std::size_t i = 0; i < 4; ++i) b[i] = static_cast<std::uint8_t>(v >> (8U * i));
    return download(a, std::span<const std::uint8_t>(b).first(width));
  }
  std::optional<std::uint64_t> read_uint(od::address a) {
    const auto [bytes, code] = upload(a);
    if (code != abort_code::none) return std::nullopt;
    std::uint64_t x = 0;
    for (std::size_t i = bytes.size(); i-- > 0;) x = (x << 8U) | bytes[i];
    return x;
  }
  std::uint64_t stored(od::address a) {
    const auto v = store.value(a).value();
    std::uint64_t x = 0;
    for (std::size_t i = v.size(); i-- > 0;) x = (x << 8U) | v[i];
    return x;
  }
};

std::vector<std::uint8_t> bytes_of(std::span<const std::uint8_t> s) { return {s.begin(), s.end()}; }

std::vector<std::uint8_t> pattern(std::size_t n, unsigned seed) {
  std::vector<std::uint8_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>((i * 31U + seed) >> 1U);
  return v;
}

} // namespace

TEST_CASE("add_hook: what a hook may serve, and when") {
  hook_rig r;
  app a;
  node::object_hook none;
  none.first = none.last = {0x2000, 0};
  CHECK(r.dev.add_hook(none).error() == errc::invalid_argument); // no function
  auto both = a.value_hook({0x2000, 0}, {0x2000, 0}, true, false);
  both.upload = &app::upload;
  CHECK(r.dev.add_hook(both).error() == errc::invalid_argument); // value and stream
  CHECK(r.dev.add_hook(a.value_hook({0x2001, 0}, {0x2000, 0}, true, false)).error() ==
        errc::invalid_argument); // first after last
  CHECK(r.dev.add_hook(a.value_hook({0x2200, 0}, {0x22FF, 0xFF}, true, false)).error() ==
        errc::unknown_object);
  // a computed value has a fixed size, outside the node's communication area
  CHECK(r.dev.add_hook(a.value_hook({0x2006, 0}, {0x2006, 0}, true, false)).error() ==
        errc::type_mismatch);
  CHECK(r.dev.add_hook(a.value_hook({0x1017, 0}, {0x1017, 0}, true, false)).error() ==
        errc::type_mismatch);
  CHECK(r.dev.add_hook(a.stream_hook({0x2006, 0})).error() == errc::type_mismatch);
  CHECK(r.dev.add_hook(a.value_hook({0x1017, 0}, {0x1017, 0}, false, true))); // a write hook may
  CHECK(r.dev.add_hook(a.value_hook({0x2000, 0}, {0x2004, 0xFF}, true, true)));
  CHECK(r.dev.add_hook(a.value_hook({0x2004, 0}, {0x2004, 0}, false, true)).error() ==
        errc::invalid_argument); // overlaps
  CHECK(r.dev.add_hook(a.stream_hook({0x2005, 0})));
  CHECK(r.dev.add_hook(a.value_hook({0x2008, 0}, {0x2008, 0}, false, true)));
  CHECK(r.dev.add_hook(a.value_hook({0x2100, 0}, {0x2100, 0}, true, false)).error() ==
        errc::too_long); // capacity::hooks = 4
  hook_rig started;
  (void)started.dev.start(0);
  CHECK(started.dev.add_hook(a.value_hook({0x2000, 0}, {0x2000, 0}, true, false)).error() ==
        errc::bad_state);
}

TEST_CASE("read hook: the value computed at each SDO upload, with the store's checks") {
  hook_rig r;
  app a;
  REQUIRE(r.dev.add_hook(a.value_hook({0x2000, 0}, {0x2002, 0}, true, false)));
  REQUIRE(r.dev.add_hook(a.value_hook({0x2009, 0}, {0x2009, 0}, true, false)));
  (void)r.dev.start(0);
  CHECK(r.read_uint({0x2000, 0}) == 1000U);
  CHECK(r.read_uint({0x2000, 0}) == 1001U);
  CHECK(r.stored({0x2000, 0}) == 1001U); // the store keeps the last computed value
  CHECK(r.read_uint({0x2001, 0}) == 1002U);
  CHECK(r.dev.value({0x2000, 0}).value().size() == 4U); // value() asks no hook
  CHECK(a.counter == 1003U);
  // the hook refuses: its code on the wire, the store unchanged
  a.read_answer = abort_code::no_data;
  CHECK(r.upload({0x2000, 0}).second == abort_code::no_data);
  CHECK(r.stored({0x2000, 0}) == 1001U);
  a.read_answer = abort_code::none;
  // a computed value the store refuses (2002h: 0..100): general error, the stored value stays
  a.computed_value = 42;
  CHECK(r.read_uint({0x2002, 0}) == 42U);
  a.computed_value = 200;
  CHECK(r.upload({0x2002, 0}).second == abort_code::general_error);
  CHECK(r.stored({0x2002, 0}) == 42U);
  // access first: a write-only object is not computed
  const std::uint32_t before = a.counter;
  CHECK(r.upload({0x2009, 0}).second == abort_code::read_write_only);
  CHECK(a.counter == before);
  // a write to an object with only a read hook is an ordinary write
  CHECK(r.write_u32({0x2000, 0}, 7) == abort_code::none);
  CHECK(r.stored({0x2000, 0}) == 7U);
}

TEST_CASE("read hook: a mapped object is computed at each TPDO sampling") {
  hook_rig r;
  app a;
  REQUIRE(r.dev.add_hook(a.value_hook({0x2100, 0}, {0x2100, 0}, true, false)));
  r.operational();
  REQUIRE(r.dev.request_tpdo(1));
  auto out = on(list(r.dev.poll(r.now).send), 0x185);
  REQUIRE(out.size() == 1U);
  CHECK(list(out) == std::vector{F(0x185, {0xE8, 0x03, 0, 0, 0, 0})}); // 1000, then 2101h
  r.now += 10;
  REQUIRE(r.dev.request_tpdo(1));
  out = on(list(r.dev.poll(r.now).send), 0x185);
  REQUIRE(out.size() == 1U);
  CHECK(out[0].data[0] == 0xE9); // 1001
  // a refused read: no TPDO
  a.read_answer = abort_code::hardware_error;
  r.now += 10;
  REQUIRE(r.dev.request_tpdo(1));
  CHECK(on(list(r.dev.poll(r.now).send), 0x185).empty());
}

TEST_CASE("write hook: refuses with its abort code, or accepts what is then stored") {
  hook_rig r;
  app a;
  a.write_answer = abort_code::cannot_store_device_state;
  REQUIRE(r.dev.add_hook(a.value_hook({0x2000, 0}, {0x2002, 0}, false, true)));
  REQUIRE(r.dev.add_hook(a.value_hook({0x1017, 0}, {0x1017, 0}, false, true)));
  r.operational();
  CHECK(r.write_u32({0x2000, 0}, 10) == abort_code::none);
  CHECK(r.stored({0x2000, 0}) == 10U);
  CHECK(r.write_u32({0x2000, 0}, 11) == abort_code::cannot_store_device_state);
  CHECK(r.stored({0x2000, 0}) == 10U);
  // the node's checks come first: the hook never sees a value the store refuses
  CHECK(r.write_u32({0x2002, 0}, 200, 1) == abort_code::value_too_high);
  CHECK(r.write_u32({0x2001, 0}, 4, 4) == abort_code::length_too_high);
  CHECK(r.write_u32({0x2001, 0}, 4, 1) == abort_code::length_too_low);
  CHECK(a.written == std::vector<std::uint32_t>{10});
  // the owning service's CiA 301 rule first, then the hook, then the service follows
  CHECK(r.write_u32({0x1017, 0}, 0x10001, 4) == abort_code::length_too_high);
  CHECK(r.write_u32({0x1017, 0}, 101, 2) == abort_code::cannot_store_device_state);
  CHECK(r.write_u32({0x1017, 0}, 100, 2) == abort_code::none);
  CHECK(r.dev.producer().period() == 100U);
  CHECK(a.written == std::vector<std::uint32_t>{10, 100});
  // the application's own set() asks no hook
  CHECK(r.dev.set({0x2000, 0}, std::array<std::uint8_t, 4>{3, 0, 0, 0}) == abort_code::none);
  CHECK(r.stored({0x2000, 0}) == 3U);
  CHECK(a.written.size() == 2U);
  // an RPDO is a write: RPDO 1 maps 2000h (u32) and 2001h (u16)
  (void)r.feed(F(0x205, {0x20, 0, 0, 0, 0x05, 0}));
  CHECK(r.stored({0x2000, 0}) == 0x20U);
  CHECK(a.written.back() == 0x20U);
  (void)r.feed(F(0x205, {0x21, 0, 0, 0, 0x06, 0}));
  CHECK(r.stored({0x2000, 0}) == 0x20U); // refused by the hook
}

TEST_CASE("write hook: a value longer than the SDO buffer is refused, not seen in parts") {
  hook_rig r;
  app a;
  // 2006h is a VISIBLE_STRING of 32: whole values reach the hook
  auto h = a.value_hook({0x2006, 0}, {0x2006, 0}, false, true);
  REQUIRE(r.dev.add_hook(h));
  (void)r.dev.start(0);
  const std::string text = "hooked";
  CHECK(r.download({0x2006, 0}, std::span(reinterpret_cast<const std::uint8_t *>(text.data()),
                                          text.size())) == abort_code::none);
  CHECK(a.written.size() == 1U);
  CHECK(r.upload({0x2006, 0}).first.size() == text.size());
}

TEST_CASE("DOMAIN stream: segmented and block, download and upload, in parts") {
  hook_rig r;
  app a;
  REQUIRE(r.dev.add_hook(a.stream_hook({0x2005, 0})));
  (void)r.dev.start(0);
  const auto data = pattern(3000, 7);
  // segmented download: the parts in order (the server's buffer, 889 bytes), then the end
  CHECK(r.download({0x2005, 0}, data) == abort_code::none);
  CHECK(a.received == data);
  CHECK(a.completed == 1U);
  CHECK(a.offsets == std::vector<std::size_t>{0, 889, 1778, 2667});
  CHECK(r.dev.value({0x2005, 0}).value().empty()); // the store never held the contents
  // segmented upload of the application's contents
  a.contents = pattern(2500, 3);
  a.offsets.clear();
  CHECK(r.upload({0x2005, 0}).first == a.contents);
  CHECK(a.offsets == std::vector<std::size_t>{0, 889, 1778});
  // block download and upload
  const auto big = pattern(3999, 11);
  CHECK(r.download({0x2005, 0}, big, true) == abort_code::none);
  CHECK(a.received == big);
  CHECK(a.completed == 2U);
  a.contents = big;
  CHECK(r.upload({0x2005, 0}, true).first == big);
  // expedited both ways, and 0 bytes
  const std::array<std::uint8_t, 3> small{1, 2, 3};
  CHECK(r.download({0x2005, 0}, small) == abort_code::none);
  CHECK(a.received == std::vector<std::uint8_t>{1, 2, 3});
  a.contents = {9, 8};
  CHECK(r.upload({0x2005, 0}).first == a.contents);
  a.offsets.clear();
  CHECK(r.download({0x2005, 0}, std::span<const std::uint8_t>{}) == abort_code::none);
  CHECK(a.received.empty());
  CHECK(a.offsets == std::vector<std::size_t>{0});
  CHECK(a.completed == 4U);
  CHECK(r.download({0x2005, 0}, std::span<const std::uint8_t>{}, true) == abort_code::none);
  CHECK(a.completed == 5U);
  a.contents.clear();
  const auto empty = r.upload({0x2005, 0});
  CHECK(empty.second == abort_code::none);
  CHECK(empty.first.empty());
  CHECK(a.ended.empty());
}

TEST_CASE("DOMAIN stream: overlong, refused by the application, aborted by the client") {
  hook_rig r;
  app a;
  REQUIRE(r.dev.add_hook(a.stream_hook({0x2005, 0})));
  r.operational();
  // longer than 2005h's declared capacity (4000): refused before the application sees a part
  CHECK(r.download({0x2005, 0}, pattern(4001, 1)) == abort_code::length_too_high);
  CHECK(r.download({0x2005, 0}, pattern(4001, 1), true) == abort_code::length_too_high);
  CHECK(a.offsets.empty());
  CHECK(a.ended.size() == 2U);
  a.ended.clear();
  // the application stops a download mid-transfer: its code reaches the client
  a.stop_at = 1000;
  CHECK(r.download({0x2005, 0}, pattern(3000, 2)) == abort_code::cannot_store);
  CHECK(a.offsets == std::vector<std::size_t>{0, 889});
  CHECK(a.completed == 0U);
  REQUIRE(a.ended.size() == 1U);
  CHECK(a.ended[0] == std::pair{od::address{0x2005, 0}, abort_code::cannot_store});
  CHECK(r.download({0x2005, 0}, pattern(3000, 2), true) == abort_code::cannot_store);
  // … and an upload, segmented and block
  a.contents = pattern(3000, 4);
  a.stop_with = abort_code::hardware_error;
  CHECK(r.upload({0x2005, 0}).second == abort_code::hardware_error);
  CHECK(r.upload({0x2005, 0}, true).second == abort_code::hardware_error);
  CHECK(a.ended.size() == 4U);
  CHECK(a.ended.back().second == abort_code::hardware_error);
  // the client aborts mid-transfer: the application hears of it
  a.stop_at = ~std::size_t{0};
  a.ended.clear();
  a.offsets.clear();
  CHECK(r.download({0x2005, 0}, pattern(3000, 5), false, 200) == abort_code::general_error);
  CHECK(a.completed == 0U);
  CHECK(a.offsets == std::vector<std::size_t>{0});
  REQUIRE(a.ended.size() == 1U);
  CHECK(a.ended[0].second == abort_code::general_error);
  CHECK(r.download({0x2005, 0}, pattern(3000, 5), true, 1) == abort_code::general_error);
  CHECK(a.ended.size() == 2U);
  // a timeout, and an NMT stop, end it too
  sdo::client c(5);
  std::vector<std::uint8_t> data = pattern(3000, 6);
  auto first = c.download({0x2005, 0}, data, r.now);
  REQUIRE(first);
  (void)r.feed(first.value().send[0]);
  r.now += 2000;
  (void)r.dev.poll(r.now);
  REQUIRE(a.ended.size() == 3U);
  CHECK(a.ended.back().second == abort_code::timeout);
  sdo::client c2(5);
  first = c2.download({0x2005, 0}, data, r.now);
  (void)r.feed(first.value().send[0]);
  (void)r.feed(F(0, {0x02, 5})); // stop
  REQUIRE(a.ended.size() == 4U);
  CHECK(a.ended.back().second == abort_code::none);
  CHECK(a.completed == 0U);
}

TEST_CASE("DOMAIN stream: a download without size stops before the part past the capacity") {
  hook_rig r;
  app a;
  REQUIRE(r.dev.add_hook(a.stream_hook({0x2005, 0})));
  (void)r.dev.start(0);
  auto out = on(r.feed(r.ch.request(sdo::initiate_download({0x2005, 0}, 0, false))), 0x585);
  REQUIRE(out.size() == 1U);
  const std::array<std::uint8_t, 7> seven{1, 2, 3, 4, 5, 6, 7};
  bool toggle = false;
  std::optional<abort_code> refused;
  for (int i = 0; i < 700 && !refused; ++i, toggle = !toggle) {
    out = on(r.feed(r.ch.request(sdo::download_segment(toggle, seven, false).value())), 0x585);
    REQUIRE(out.size() == 1U);
    const auto m = sdo::decode(out[0].data, sdo::direction::to_client).value();
    if (m.type == sdo::message_type::abort) refused = m.abort;
  }
  // 2005h holds 4000 bytes: the parts of 889 at 0, 889, 1778, 2667 reach the application, the
  // one that would end at 4445 does not
  CHECK(refused == abort_code::length_too_high);
  CHECK(a.offsets == std::vector<std::size_t>{0, 889, 1778, 2667});
  CHECK(a.completed == 0U);
  REQUIRE(a.ended.size() == 1U);
  CHECK(a.ended[0].second == abort_code::length_too_high);
}

TEST_CASE("write hook on a byte string: whole values up to the SDO buffer, longer ones refused") {
  hook_rig r;
  app a;
  REQUIRE(r.dev.add_hook(a.value_hook({0x2005, 0}, {0x2005, 0}, false, true)));
  (void)r.dev.start(0);
  const auto fits = pattern(889, 3);
  CHECK(r.download({0x2005, 0}, fits) == abort_code::none);
  CHECK(a.written.size() == 1U);
  CHECK(bytes_of(r.dev.value({0x2005, 0}).value()) == fits);
  CHECK(r.download({0x2005, 0}, pattern(890, 4)) == abort_code::out_of_memory);
  CHECK(r.download({0x2005, 0}, pattern(2000, 4), true) == abort_code::out_of_memory);
  CHECK(a.written.size() == 1U);
  CHECK(bytes_of(r.dev.value({0x2005, 0}).value()) == fits);
}

TEST_CASE("DOMAIN stream: one direction, access and unknown sub-indices keep their codes") {
  hook_rig r;
  app a;
  REQUIRE(r.dev.add_hook(a.stream_hook({0x2005, 0}, true, false)));
  (void)r.dev.start(0);
  a.contents = pattern(20, 1);
  CHECK(r.upload({0x2005, 0}).first == a.contents);
  CHECK(r.download({0x2005, 0}, pattern(20, 1)) == abort_code::unsupported_access);
  CHECK(a.received.empty());

  hook_rig w;
  app b;
  REQUIRE(w.dev.add_hook(b.stream_hook({0x2005, 0}, false, true)));
  (void)w.dev.start(0);
  CHECK(w.upload({0x2005, 0}).second == abort_code::unsupported_access);
  CHECK(w.download({0x2005, 0}, pattern(20, 1)) == abort_code::none);
  CHECK(b.received == pattern(20, 1));
}

namespace {
/// The application of the docs block: a sensor and a log kept elsewhere (a flash area).
struct sensor_t {
  std::uint32_t reads = 0;
  std::uint32_t read() noexcept { return 2150U + reads++; }
};
struct flash_log_t {
  std::vector<std::uint8_t> bytes, incoming;
  std::size_t discarded = 0;
  node::abort_code read(std::size_t offset, std::span<std::uint8_t> out,
                        std::size_t &total) const noexcept {
    total = bytes.size();
    for (std::size_t i = 0; i < out.size() && offset + i < total; ++i) out[i] = bytes[offset + i];
    return node::abort_code::none;
  }
  node::abort_code write(std::size_t offset, std::span<const std::uint8_t> part,
                         bool last) noexcept {
    if (offset == 0U) incoming.clear();
    incoming.insert(incoming.end(), part.begin(), part.end());
    if (last) bytes = incoming;
    return node::abort_code::none;
  }
  void discard() noexcept {
    incoming.clear();
    ++discarded;
  }
};
} // namespace

TEST_CASE("docs/canopen.md, Application hooks: the block, compiled and run") {
  using Store = store_type;
  static constexpr od::dictionary dict = dict5;
  std::vector<std::uint8_t> storage(layout5.storage_size());
  Store store{dict, layout5, storage};
  REQUIRE(store.init_defaults(5));
  sensor_t sensor;
  flash_log_t flash_log;

  node::object_hook temperature; // 2000h, computed at each SDO read and TPDO
  temperature.first = temperature.last = {0x2000, 0};
  temperature.context = &sensor;
  temperature.read = [](void *s, od::address, std::span<std::uint8_t> v) noexcept {
    const std::uint32_t t = static_cast<sensor_t *>(s)->read(); // little-endian, width() bytes
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint8_t>(t >> (8U * i));
    return node::abort_code::none; // or a code: the client gets it
  };
  node::object_hook setpoint; // 2008h: the application has the last word on writes
  setpoint.first = setpoint.last = {0x2008, 0};
  setpoint.write = [](void *, od::address, std::span<const std::uint8_t> v) noexcept {
    return v[0] % 2U == 0U ? node::abort_code::none // accepted: stored and followed
                           : node::abort_code::cannot_store_device_state; // 0800 0022h
  };
  node::object_hook log; // 2005h: a DOMAIN streamed in parts, never held by the node
  log.first = log.last = {0x2005, 0};
  log.context = &flash_log;
  log.upload = [](void *f, od::address, std::size_t offset, std::span<std::uint8_t> out,
                  std::size_t &total) noexcept {
    return static_cast<flash_log_t *>(f)->read(offset, out, total);
  };
  log.download = [](void *f, od::address, std::size_t offset, std::span<const std::uint8_t> part,
                    bool last) noexcept {
    return static_cast<flash_log_t *>(f)->write(offset, part, last);
  };
  log.ended = [](void *f, od::address, node::abort_code) noexcept {
    static_cast<flash_log_t *>(f)->discard(); // aborted or timed out: drop the parts
  };
  node::device<Store, node::capacity_for(dict, {.hooks = 3})> dev(store, 5);
  for (const auto &h : {temperature, setpoint, log}) (void)dev.add_hook(h); // before start()

  REQUIRE(dev.start(0));
  sdo::client c(5);
  std::vector<std::uint8_t> buf(4096);
  REQUIRE(pump(dev, c, c.upload({0x2000, 0}, buf, 0), 0) == sdo::transfer_state::done);
  CHECK(bytes_of(c.received()) == std::vector<std::uint8_t>{0x66, 0x08, 0, 0}); // 2150
  const std::array<std::uint8_t, 4> odd{3, 0, 0, 0};
  CHECK(pump(dev, c, c.download({0x2008, 0}, odd, 0), 0) == sdo::transfer_state::failed);
  CHECK(c.error()->abort == abort_code::cannot_store_device_state);
  const auto text = pattern(2000, 9);
  REQUIRE(pump(dev, c, c.block_download({0x2005, 0}, text, 0), 0) == sdo::transfer_state::done);
  CHECK(flash_log.bytes == text);
  REQUIRE(pump(dev, c, c.upload({0x2005, 0}, buf, 0), 0) == sdo::transfer_state::done);
  CHECK(bytes_of(c.received()) == text);
  CHECK(pump(dev, c, c.download({0x2005, 0}, text, 0), 0, 3) == sdo::transfer_state::failed);
  CHECK(flash_log.discarded == 1U);
  CHECK(flash_log.bytes == text);
}
