// Benchmarks of canopen/ (SDO expedited frames, PDO packing) against hand-written equivalents.
#include "codec_harness.hpp"

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/core/bytes.hpp>

#include <array>
#include <cstddef>
#include <cstdint>

namespace {

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace pdo = fieldcodec::canopen::pdo;
using fieldcodec::byte_order;

struct sdo_write {
  std::uint8_t node = 1;
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint32_t value = 0;
  bool operator==(const sdo_write &) const = default;
};

struct sdo_decoded {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint8_t size = 0;
  std::uint32_t value = 0;
  bool ok = false;
  bool operator==(const sdo_decoded &) const = default;
};

/// An RPDO of a CiA 402 drive: controlword (16), target position (32), modes of operation (8),
/// digital outputs (8) = 8 bytes.
struct rpdo_values {
  std::uint16_t controlword = 0;
  std::int32_t target_position = 0;
  std::int8_t mode = 0;
  std::uint8_t outputs = 0;
  bool ok = false;
  bool operator==(const rpdo_values &) const = default;
};

struct pdo_bytes {
  std::array<std::uint8_t, 8> b{};
  bool ok = false;
  bool operator==(const pdo_bytes &) const = default;
};

bench::inputs<sdo_write> g_writes;
bench::inputs<co::can_frame> g_sdo_frames;
bench::inputs<rpdo_values> g_rpdo;
bench::inputs<pdo_bytes> g_rpdo_bytes;

constexpr pdo::mapping_entry rpdo_entries[] = {
    {0x6040, 0, 16}, {0x607A, 0, 32}, {0x6060, 0, 8}, {0x60FE, 1, 8}};
constexpr auto rpdo_map = pdo::make_static_mapping(rpdo_entries);

void fill_inputs() {
  bench::rng r(7);
  for (std::size_t i = 0; i < bench::input_count; ++i) {
    auto &w = g_writes[i];
    w.node = static_cast<std::uint8_t>(r.between(1, 127));
    w.index = static_cast<std::uint16_t>(r.between(0x1000, 0x6FFF));
    w.sub = static_cast<std::uint8_t>(r.below(256));
    w.value = static_cast<std::uint32_t>(r.next());
    const auto size = static_cast<std::size_t>(r.between(1, 4));
    const auto bytes = fieldcodec::to_bytes<std::uint32_t>(w.value, byte_order::little);
    g_sdo_frames[i] = sdo::channel::default_for(w.node)
                          .value()
                          .request(sdo::expedited_download(
                              {w.index, w.sub}, std::span<const std::uint8_t>(bytes).first(size)))
                          .value();
    auto &v = g_rpdo[i];
    v.controlword = static_cast<std::uint16_t>(r.below(0x10000));
    v.target_position = static_cast<std::int32_t>(r.between(-2'000'000'000, 2'000'000'000));
    v.mode = static_cast<std::int8_t>(r.between(-128, 127));
    v.outputs = static_cast<std::uint8_t>(r.below(256));
    v.ok = true;
    for (auto &b : g_rpdo_bytes[i].b) b = static_cast<std::uint8_t>(r.next());
  }
}

inline sdo_decoded hand_decode_expedited(const co::can_frame &f) {
  sdo_decoded d;
  if (f.rtr || f.dlc != 8U) return d;
  const std::uint8_t cmd = f.data[0];
  if ((cmd >> 5U) != 1U || (cmd & 0x02U) == 0U) return d; // initiate download, expedited
  d.size = (cmd & 0x01U) != 0U ? static_cast<std::uint8_t>(4U - ((cmd >> 2U) & 3U)) : 4U;
  d.index = static_cast<std::uint16_t>(f.data[1] | (f.data[2] << 8U));
  d.sub = f.data[3];
  std::uint32_t v = 0;
  for (std::size_t i = d.size; i-- > 0;) v = (v << 8U) | f.data[4U + i];
  d.value = v;
  d.ok = true;
  return d;
}

void add_sdo(bench::registry &reg) {
  bench::add<g_writes>(
      reg, "sdo/expedited_download encode u32",
      [](const sdo_write &w) {
        const auto bytes = fieldcodec::to_bytes<std::uint32_t>(w.value, byte_order::little);
        const auto ch = sdo::channel::default_for(w.node);
        if (!ch) return co::can_frame{};
        return ch.value()
            .request(sdo::expedited_download({w.index, w.sub}, bytes))
            .value_or(co::can_frame{});
      },
      [](const sdo_write &w) {
        co::can_frame f;
        if (w.node < 1U || w.node > 127U) return f;
        f.id = static_cast<std::uint16_t>(0x600U + w.node);
        f.dlc = 8;
        f.data = {0x23,
                  static_cast<std::uint8_t>(w.index),
                  static_cast<std::uint8_t>(w.index >> 8U),
                  w.sub,
                  static_cast<std::uint8_t>(w.value),
                  static_cast<std::uint8_t>(w.value >> 8U),
                  static_cast<std::uint8_t>(w.value >> 16U),
                  static_cast<std::uint8_t>(w.value >> 24U)};
        return f;
      });
  // A server reading an expedited download request: the narrow accessor (what a server's hot
  // path calls) and the general decoder that builds the whole message, against the same
  // hand-written code.
  bench::add<g_sdo_frames>(
      reg, "sdo/decode_expedited_write",
      [](const co::can_frame &f) {
        sdo_decoded d;
        auto w = sdo::decode_expedited_write(f);
        if (!w) return d;
        d.index = w.value().address.index;
        d.sub = w.value().address.sub;
        d.size = w.value().size;
        d.value = w.value().value;
        d.ok = true;
        return d;
      },
      [](const co::can_frame &f) { return hand_decode_expedited(f); });
  bench::add<g_sdo_frames>(
      reg, "sdo/decode_request expedited download",
      [](const co::can_frame &f) {
        sdo_decoded d;
        auto m = sdo::decode(f, sdo::direction::to_server);
        if (!m || m.value().type != sdo::message_type::initiate_download_request ||
            !m.value().expedited) {
          return d;
        }
        const auto &msg = m.value();
        d.index = msg.address.index;
        d.sub = msg.address.sub;
        d.size = static_cast<std::uint8_t>(msg.size); // 1..4 for an expedited message
        d.value = msg.value;
        d.ok = true;
        return d;
      },
      [](const co::can_frame &f) { return hand_decode_expedited(f); });
}

pdo_bytes hand_pack(const rpdo_values &v) {
  pdo_bytes p;
  const auto pos = static_cast<std::uint32_t>(v.target_position);
  p.b = {static_cast<std::uint8_t>(v.controlword), static_cast<std::uint8_t>(v.controlword >> 8U),
         static_cast<std::uint8_t>(pos),           static_cast<std::uint8_t>(pos >> 8U),
         static_cast<std::uint8_t>(pos >> 16U),    static_cast<std::uint8_t>(pos >> 24U),
         static_cast<std::uint8_t>(v.mode),        v.outputs};
  p.ok = true;
  return p;
}

void add_pdo(bench::registry &reg) {
  bench::add<g_rpdo>(
      reg, "pdo/pack 8-byte RPDO (static_mapping::set)",
      [](const rpdo_values &v) {
        pdo_bytes p;
        p.ok = rpdo_map.set(p.b, 0, v.controlword).has_value() &&
               rpdo_map.set(p.b, 1, v.target_position).has_value() &&
               rpdo_map.set(p.b, 2, v.mode).has_value() &&
               rpdo_map.set(p.b, 3, v.outputs).has_value();
        return p;
      },
      [](const rpdo_values &v) { return hand_pack(v); });
  bench::add<g_rpdo>(
      reg, "pdo/pack_all 8-byte RPDO",
      [](const rpdo_values &v) {
        pdo_bytes p;
        // signed values as signed: a uint64 of 2^64 - 5 is never taken as -5 for a 32-bit
        // field (the checked packing of the xenax work), so the values go in as int64
        const std::array<std::int64_t, 4> raws{v.controlword, v.target_position, v.mode, v.outputs};
        p.ok = pdo::pack_all(rpdo_entries, raws, p.b).has_value();
        return p;
      },
      [](const rpdo_values &v) { return hand_pack(v); });
  bench::add<g_rpdo_bytes>(
      reg, "pdo/unpack 8-byte RPDO (static_mapping::get)",
      [](const pdo_bytes &p) {
        rpdo_values v;
        auto cw = rpdo_map.get(p.b, 0);
        auto pos = rpdo_map.get_signed(p.b, 1);
        auto mode = rpdo_map.get_signed(p.b, 2);
        auto out = rpdo_map.get(p.b, 3);
        if (!cw || !pos || !mode || !out) return v;
        v.controlword = static_cast<std::uint16_t>(cw.value());
        v.target_position = static_cast<std::int32_t>(pos.value());
        v.mode = static_cast<std::int8_t>(mode.value());
        v.outputs = static_cast<std::uint8_t>(out.value());
        v.ok = true;
        return v;
      },
      [](const pdo_bytes &p) {
        rpdo_values v;
        v.controlword = static_cast<std::uint16_t>(p.b[0] | (p.b[1] << 8U));
        v.target_position = static_cast<std::int32_t>(static_cast<std::uint32_t>(p.b[2]) |
                                                      (static_cast<std::uint32_t>(p.b[3]) << 8U) |
                                                      (static_cast<std::uint32_t>(p.b[4]) << 16U) |
                                                      (static_cast<std::uint32_t>(p.b[5]) << 24U));
        v.mode = static_cast<std::int8_t>(p.b[6]);
        v.outputs = p.b[7];
        v.ok = true;
        return v;
      });
}

bench::registry make_registry() {
  fill_inputs();
  bench::registry r;
  bench::add_harness<g_writes>(r);
  add_sdo(r);
  add_pdo(r);
  return r;
}

} // namespace

int main(int argc, char **argv) { return bench::main(argc, argv, make_registry()); }
