// A generic CiA 301 node dictionary for the node tests (every communication object the node
// services use, two PDOs per direction, an extra SDO server and one SDO client channel), and a
// harness that holds a store and a device over it.
#pragma once

#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <vector>

namespace test_node {

namespace co = fieldcodec::canopen;
namespace node = fieldcodec::canopen::node;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
using fieldcodec::errc;
using sdo::abort_code;

/// A store over `Store` that offers only the address interface (co::object_store and what
/// node::node_store adds), not positions: a user-written store that predates
/// co::positioned_store, which engines and devices must use by address.
template <class Store>
class address_only_store {
public:
  explicit address_only_store(Store &s) : s_(&s) {}
  [[nodiscard]] abort_code read(od::address a, std::size_t offset, std::span<std::uint8_t> out,
                                std::size_t &total) const {
    return s_->read(a, offset, out, total);
  }
  [[nodiscard]] abort_code begin_write(od::address a, std::optional<std::uint32_t> size) {
    return s_->begin_write(a, size);
  }
  [[nodiscard]] abort_code write(od::address a, std::size_t offset,
                                 std::span<const std::uint8_t> part, bool last) {
    return s_->write(a, offset, part, last);
  }
  [[nodiscard]] abort_code set(od::address a, std::span<const std::uint8_t> v) {
    return s_->set(a, v);
  }
  [[nodiscard]] fieldcodec::result<std::span<const std::uint8_t>> value(od::address a) const {
    return s_->value(a);
  }
  [[nodiscard]] od::dictionary dictionary() const { return s_->dictionary(); }
  [[nodiscard]] fieldcodec::status restore_defaults(std::uint16_t first, std::uint16_t last) {
    return s_->restore_defaults(first, last);
  }

private:
  Store *s_;
};

/// A store over `Store` that offers the address interface and positions
/// (co::positioned_store) but does not show where values live (not co::plain_store): a
/// user-written store with positions, which engines serve by read_at / write_at.
template <class Store>
class positions_only_store : public address_only_store<Store> {
public:
  explicit positions_only_store(Store &s) : address_only_store<Store>(s), p_(&s) {}
  [[nodiscard]] std::size_t position(od::address a) const { return p_->position(a); }
  [[nodiscard]] od::address address_at(std::size_t at) const { return p_->address_at(at); }
  [[nodiscard]] abort_code read_at(std::size_t at, std::size_t offset, std::span<std::uint8_t> out,
                                   std::size_t &total) const {
    return p_->read_at(at, offset, out, total);
  }
  [[nodiscard]] abort_code write_at(std::size_t at, std::size_t offset,
                                    std::span<const std::uint8_t> part, bool last) {
    return p_->write_at(at, offset, part, last);
  }

private:
  Store *p_;
};

/// A store over `Store` with positions that shows plain values (co::plain_store) where its
/// storage is shorter than the store's: slots that reach past `room` bytes are broken promises,
/// which an engine must not copy.
template <class Store>
class short_plain_store : public positions_only_store<Store> {
public:
  short_plain_store(Store &s, std::size_t room)
      : positions_only_store<Store>(s), s_(&s), room_(room) {}
  [[nodiscard]] std::span<std::uint8_t> plain_storage() { return s_->plain_storage().first(room_); }
  [[nodiscard]] co::plain_slot plain_at(std::size_t at) const { return s_->plain_at(at); }

private:
  Store *s_;
  std::size_t room_;
};

constexpr od::number U(std::uint64_t v) { return {od::number_kind::unsigned_, 0, v}; }
constexpr od::number I(std::int64_t v) {
  return {od::number_kind::signed_, 0, static_cast<std::uint64_t>(v)};
}

using od::access;
using od::data_type;
using od::pdo_mapping;

constexpr od::entry_spec var(std::uint16_t index, std::uint8_t sub, data_type t, access a,
                             std::uint64_t def, pdo_mapping p = pdo_mapping::no) {
  return {
      .index = index, .sub = sub, .type = t, .access_type = a, .pdo = p, .default_value = U(def)};
}

inline constexpr std::size_t entry_count = 113;

/// The dictionary of node `n` (node-ID-relative defaults resolved for n), as specs
/// (od::entries_of packs them).
constexpr std::array<od::entry_spec, entry_count> make_specs(std::uint8_t n) {
  const auto u8 = data_type::unsigned8;
  const auto u16 = data_type::unsigned16;
  const auto u32 = data_type::unsigned32;
  const auto ro = access::ro;
  const auto rw = access::rw;
  const auto yes = pdo_mapping::yes;
  return {{
      var(0x1000, 0, u32, ro, 0x000F0191U),
      var(0x1001, 0, u8, ro, 0),
      var(0x1003, 0, u8, rw, 0),
      var(0x1003, 1, u32, ro, 0),
      var(0x1003, 2, u32, ro, 0),
      var(0x1003, 3, u32, ro, 0),
      var(0x1003, 4, u32, ro, 0),
      var(0x1005, 0, u32, rw, 0x80),
      var(0x1006, 0, u32, rw, 0),
      var(0x1007, 0, u32, rw, 0),
      {.index = 0x1008,
       .type = data_type::visible_string,
       .access_type = access::constant,
       .size = 16,
       .default_text = "fieldcodec node"},
      var(0x100C, 0, u16, rw, 0),
      var(0x100D, 0, u8, rw, 0),
      var(0x1010, 0, u8, ro, 4),
      var(0x1010, 1, u32, rw, 1),
      var(0x1010, 2, u32, rw, 1),
      var(0x1010, 3, u32, rw, 1),
      var(0x1010, 4, u32, rw, 1),
      var(0x1011, 0, u8, ro, 4),
      var(0x1011, 1, u32, rw, 1),
      var(0x1011, 2, u32, rw, 1),
      var(0x1011, 3, u32, rw, 1),
      var(0x1011, 4, u32, rw, 1),
      var(0x1012, 0, u32, rw, 0x100),
      var(0x1014, 0, u32, rw, 0x80U + n),
      var(0x1015, 0, u16, rw, 0),
      var(0x1016, 0, u8, ro, 3),
      var(0x1016, 1, u32, rw, 0),
      var(0x1016, 2, u32, rw, 0),
      var(0x1016, 3, u32, rw, 0),
      var(0x1017, 0, u16, rw, 0),
      var(0x1018, 0, u8, ro, 4),
      var(0x1018, 1, u32, ro, 0x0000'0F1CU),
      var(0x1018, 2, u32, ro, 0x0000'0001U),
      var(0x1018, 3, u32, ro, 0x0001'0000U),
      var(0x1018, 4, u32, ro, 0),
      var(0x1019, 0, u8, rw, 0),
      var(0x1029, 0, u8, ro, 2),
      var(0x1029, 1, u8, rw, 0),
      var(0x1029, 2, u8, rw, 0),
      var(0x1200, 0, u8, ro, 2),
      var(0x1200, 1, u32, ro, 0x600U + n),
      var(0x1200, 2, u32, ro, 0x580U + n),
      var(0x1201, 0, u8, ro, 3),
      var(0x1201, 1, u32, rw, 0x8000'0000U),
      var(0x1201, 2, u32, rw, 0x8000'0000U),
      var(0x1201, 3, u8, rw, 0),
      var(0x1280, 0, u8, ro, 3),
      var(0x1280, 1, u32, rw, 0x8000'0000U),
      var(0x1280, 2, u32, rw, 0x8000'0000U),
      var(0x1280, 3, u8, rw, 0),
      // RPDO 1: 2000h (u32) + 2001h (u16), event-driven
      var(0x1400, 0, u8, ro, 5),
      var(0x1400, 1, u32, rw, 0x200U + n),
      var(0x1400, 2, u8, rw, 255),
      var(0x1400, 3, u16, rw, 0),
      var(0x1400, 4, u8, rw, 0),
      var(0x1400, 5, u16, rw, 0),
      // RPDO 2: controlword 6040h, synchronous
      var(0x1401, 0, u8, ro, 5),
      var(0x1401, 1, u32, rw, 0x300U + n),
      var(0x1401, 2, u8, rw, 1),
      var(0x1401, 3, u16, rw, 0),
      var(0x1401, 4, u8, rw, 0),
      var(0x1401, 5, u16, rw, 0),
      var(0x1600, 0, u8, rw, 2),
      var(0x1600, 1, u32, rw, 0x2000'0020U),
      var(0x1600, 2, u32, rw, 0x2001'0010U),
      var(0x1600, 3, u32, rw, 0),
      var(0x1600, 4, u32, rw, 0),
      var(0x1601, 0, u8, rw, 1),
      var(0x1601, 1, u32, rw, 0x6040'0010U),
      var(0x1601, 2, u32, rw, 0),
      var(0x1601, 3, u32, rw, 0),
      var(0x1601, 4, u32, rw, 0),
      // TPDO 1: 2100h (u32) + 2101h (u16), event-driven
      var(0x1800, 0, u8, ro, 6),
      var(0x1800, 1, u32, rw, 0x180U + n),
      var(0x1800, 2, u8, rw, 255),
      var(0x1800, 3, u16, rw, 0),
      var(0x1800, 4, u8, rw, 0),
      var(0x1800, 5, u16, rw, 0),
      var(0x1800, 6, u8, rw, 0),
      // TPDO 2: statusword 6041h, synchronous every SYNC
      var(0x1801, 0, u8, ro, 6),
      var(0x1801, 1, u32, rw, 0x280U + n),
      var(0x1801, 2, u8, rw, 1),
      var(0x1801, 3, u16, rw, 0),
      var(0x1801, 4, u8, rw, 0),
      var(0x1801, 5, u16, rw, 0),
      var(0x1801, 6, u8, rw, 0),
      var(0x1A00, 0, u8, rw, 2),
      var(0x1A00, 1, u32, rw, 0x2100'0020U),
      var(0x1A00, 2, u32, rw, 0x2101'0010U),
      var(0x1A00, 3, u32, rw, 0),
      var(0x1A00, 4, u32, rw, 0),
      var(0x1A01, 0, u8, rw, 1),
      var(0x1A01, 1, u32, rw, 0x6041'0010U),
      var(0x1A01, 2, u32, rw, 0),
      var(0x1A01, 3, u32, rw, 0),
      var(0x1A01, 4, u32, rw, 0),
      // application objects
      var(0x2000, 0, u32, rw, 0, yes),
      var(0x2001, 0, u16, rw, 0, yes),
      {.index = 0x2002,
       .type = u8,
       .access_type = rw,
       .pdo = yes,
       .low = U(0),
       .high = U(100),
       .default_value = U(0)},
      var(0x2003, 0, data_type::boolean, rw, 0, yes),
      var(0x2004, 0, data_type::integer32, rw, 0, yes),
      {.index = 0x2005, .type = data_type::domain, .access_type = rw, .size = 4000},
      {.index = 0x2006, .type = data_type::visible_string, .access_type = rw, .size = 32},
      var(0x2007, 0, u32, ro, 0x1234'5678U, yes),
      var(0x2008, 0, u32, rw, 0), // not PDO-mappable
      var(0x2009, 0, u32, access::wo, 0, yes),
      var(0x2100, 0, u32, rw, 0, yes),
      var(0x2101, 0, u16, rw, 0, yes),
      var(0x2102, 0, data_type::integer8, ro, 0, yes),
      var(0x2103, 0, u8, rw, 7, yes),
      var(0x6040, 0, u16, rw, 0, yes),
      var(0x6041, 0, u16, ro, 0x0250, yes),
  }};
}

inline constexpr auto specs5 = make_specs(5);
inline constexpr auto entries5 = od::entries_of<specs5>;
inline constexpr od::dictionary dict5{entries5};
static_assert(dict5.is_valid());
inline constexpr auto layout5 = co::make_layout<entry_count>(dict5);

inline constexpr node::capacity caps = node::capacity_for(dict5);
static_assert(caps.rpdos == 2 && caps.tpdos == 2 && caps.mapped == 4);
static_assert(caps.heartbeat_consumers == 3 && caps.error_history == 4);
static_assert(caps.sdo_servers == 2 && caps.sdo_clients == 1);
static_assert(caps.error_classes == 2);
static_assert(caps.time);
static_assert(caps.storage);

using store_type = co::dictionary_store<>;
using device_type = node::device<store_type, caps>;

/// Frames as a vector.
template <class Frames>
std::vector<co::can_frame> list(const Frames &f) {
  return {f.begin(), f.end()};
}

inline co::can_frame F(std::uint16_t id, std::initializer_list<std::uint8_t> b) {
  return co::make_frame(id, b).value();
}
inline co::can_frame R(std::uint16_t id, std::uint8_t dlc = 0) {
  return co::make_remote_frame(id, dlc).value();
}
constexpr sdo::abort_code A(std::uint32_t v) { return static_cast<sdo::abort_code>(v); }

/// A node over the test dictionary with its own storage.
template <std::uint8_t N = 5>
struct rig {
  static constexpr auto specs = make_specs(N);
  static constexpr auto entries = od::entries_of<specs>;
  static constexpr od::dictionary dict{entries};
  static constexpr auto layout = co::make_layout<entry_count>(dict);

  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout.storage_size());
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(4000);
  store_type store{dict, layout, storage, staging};
  device_type dev;
  std::uint32_t now = 0;

  explicit rig(node::options o = {}) : dev(init(store), N, o) {}

  static store_type &init(store_type &s) {
    REQUIRE(s.init_defaults(N).has_value());
    return s;
  }

  /// The deadline of the last step.
  std::optional<std::uint32_t> deadline;

  std::vector<co::can_frame> start() { return take(dev.start(now).value()); }
  std::vector<co::can_frame> feed(const co::can_frame &f) { return take(dev.on_frame(f, now)); }
  std::vector<co::can_frame> tick(std::uint32_t ms = 0) {
    now += ms;
    return take(dev.poll(now));
  }
  std::vector<co::can_frame> take(const typename device_type::step &s) {
    deadline = s.deadline;
    return list(s.send);
  }
  /// Start and enter operational.
  void operational() {
    (void)start();
    (void)feed(F(0, {0x01, N}));
    REQUIRE(dev.state() == co::nmt::state::operational);
  }

  // an SDO client on the default channel of this node, driven synchronously
  std::uint64_t read_u(std::uint16_t index, std::uint8_t sub) {
    auto v = store.value({index, sub}).value();
    std::uint64_t r = 0;
    for (std::size_t i = v.size(); i-- > 0;) r = (r << 8U) | v[i];
    return r;
  }
  /// SDO expedited download of `width` bytes of `value` through the node: the abort code (none
  /// when the server confirmed).
  abort_code sdo_write(std::uint16_t index, std::uint8_t sub, std::uint32_t value,
                       std::size_t width) {
    std::array<std::uint8_t, 4> b{};
    for (std::size_t i = 0; i < width; ++i) b[i] = static_cast<std::uint8_t>(value >> (8U * i));
    const auto ch = sdo::channel::default_for(N).value();
    auto req = ch.request(
        sdo::expedited_download({index, sub}, std::span<const std::uint8_t>(b).first(width))
            .value());
    auto out = feed(req);
    REQUIRE(out.size() >= 1);
    const co::can_frame *resp = nullptr;
    for (const auto &f : out) {
      if (f.id == ch.response_id) resp = &f;
    }
    REQUIRE(resp != nullptr);
    auto m = sdo::decode(resp->data, sdo::direction::to_client).value();
    if (m.type == sdo::message_type::abort) return m.abort;
    CHECK(m.type == sdo::message_type::initiate_download_response);
    return abort_code::none;
  }
  /// The frames the last accepted set_send sent.
  std::vector<co::can_frame> set_frames;
  abort_code set_u(std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::size_t width) {
    std::array<std::uint8_t, 4> b{};
    for (std::size_t i = 0; i < width; ++i) b[i] = static_cast<std::uint8_t>(value >> (8U * i));
    return dev.set({index, sub}, std::span<const std::uint8_t>(b).first(width));
  }
  /// The same with device::set(a, value, now): the frames its step sends are set_frames.
  abort_code set_send(std::uint16_t index, std::uint8_t sub, std::uint32_t value,
                      std::size_t width) {
    std::array<std::uint8_t, 4> b{};
    for (std::size_t i = 0; i < width; ++i) b[i] = static_cast<std::uint8_t>(value >> (8U * i));
    set_frames.clear();
    auto r = dev.set({index, sub}, std::span<const std::uint8_t>(b).first(width), now);
    if (!r) return r.error();
    set_frames = list(r.value().send);
    deadline = r.value().deadline;
    return abort_code::none;
  }
};

/// Frames of `out` on identifier `id`.
inline std::vector<co::can_frame> on(const std::vector<co::can_frame> &out, std::uint16_t id) {
  std::vector<co::can_frame> r;
  for (const auto &f : out) {
    if (f.id == id) r.push_back(f);
  }
  return r;
}

} // namespace test_node
