// Benchmarks of the CANopen PDO engine (issue 18) against hand-written equivalents: two
// synchronous TPDOs per SYNC, one RPDO per frame, over a dictionary_store.
//
// Every operation is one complete exchange: a SYNC to an engine whose two TPDOs are sent on
// every SYNC (the frames copied into the result), or an RPDO written into the store. The engines
// and stores live in globals (the lambdas are captureless); the inputs select which of several
// nodes a call works on. SDO block transfer is measured by codec_sdo_block.cpp, a translation
// unit of its own so that one group's inlining does not move the other's rows.
#include "codec_harness.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/node/pdo_engine.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deque>
#include <optional>
#include <span>
#include <vector>

namespace {

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace node = fieldcodec::canopen::node;
namespace od = fieldcodec::od;

using store_type = co::dictionary_store<>;

// ---------------------------------------------------------------------------------------------
// PDO engine: node 5 with two synchronous TPDOs (type 1: every SYNC) of four objects and 8 bytes
// each, and one event-driven RPDO (type 255) of four objects and 8 bytes.

constexpr std::uint8_t pdo_node = 5;
constexpr std::size_t node_count = 16; // independent nodes (stores + engines); inputs pick one

constexpr od::number U(std::uint64_t v) { return {od::number_kind::unsigned_, 0, v}; }
constexpr od::entry_spec var(std::uint16_t index, std::uint8_t sub, od::data_type t,
                             std::uint64_t def, od::pdo_mapping p = od::pdo_mapping::no) {
  return {.index = index,
          .sub = sub,
          .type = t,
          .access_type = od::access::rw,
          .pdo = p,
          .default_value = U(def)};
}

constexpr auto u8 = od::data_type::unsigned8;
constexpr auto u16 = od::data_type::unsigned16;
constexpr auto u32 = od::data_type::unsigned32;
constexpr auto yes = od::pdo_mapping::yes;

constexpr std::array<od::entry_spec, 54> pdo_entries{
    {// RPDO 1: controlword, target position, modes of operation, digital outputs
     var(0x1400, 0, u8, 5), var(0x1400, 1, u32, 0x200U + pdo_node), var(0x1400, 2, u8, 255),
     var(0x1400, 3, u16, 0), var(0x1400, 4, u8, 0), var(0x1400, 5, u16, 0), var(0x1600, 0, u8, 4),
     var(0x1600, 1, u32, 0x6040'0010U), var(0x1600, 2, u32, 0x607A'0020U),
     var(0x1600, 3, u32, 0x6060'0008U), var(0x1600, 4, u32, 0x2003'0008U),
     // TPDO 1 and 2: synchronous, every SYNC
     var(0x1800, 0, u8, 6), var(0x1800, 1, u32, 0x180U + pdo_node), var(0x1800, 2, u8, 1),
     var(0x1800, 3, u16, 0), var(0x1800, 4, u8, 0), var(0x1800, 5, u16, 0), var(0x1800, 6, u8, 0),
     var(0x1801, 0, u8, 6), var(0x1801, 1, u32, 0x280U + pdo_node), var(0x1801, 2, u8, 1),
     var(0x1801, 3, u16, 0), var(0x1801, 4, u8, 0), var(0x1801, 5, u16, 0), var(0x1801, 6, u8, 0),
     // statusword, position actual, modes display, digital inputs
     var(0x1A00, 0, u8, 4), var(0x1A00, 1, u32, 0x6041'0010U), var(0x1A00, 2, u32, 0x6064'0020U),
     var(0x1A00, 3, u32, 0x6061'0008U), var(0x1A00, 4, u32, 0x2000'0008U),
     // velocity actual, torque actual, two status bytes
     var(0x1A01, 0, u8, 4), var(0x1A01, 1, u32, 0x606C'0020U), var(0x1A01, 2, u32, 0x6077'0010U),
     var(0x1A01, 3, u32, 0x2001'0008U), var(0x1A01, 4, u32, 0x2002'0008U),
     // application objects
     var(0x2000, 0, u8, 0, yes), var(0x2001, 0, u8, 0, yes), var(0x2002, 0, u8, 0, yes),
     var(0x2003, 0, u8, 0, yes), var(0x6040, 0, u16, 0, yes), var(0x6041, 0, u16, 0, yes),
     var(0x6060, 0, od::data_type::integer8, 0, yes),
     var(0x6061, 0, od::data_type::integer8, 0, yes),
     var(0x6064, 0, od::data_type::integer32, 0, yes),
     var(0x606C, 0, od::data_type::integer32, 0, yes),
     var(0x6077, 0, od::data_type::integer16, 0, yes),
     var(0x607A, 0, od::data_type::integer32, 0, yes),
     // padding objects the PDOs do not map (a dictionary has more than its PDO objects)
     var(0x1000, 0, u32, 0x0002'0192U), var(0x1001, 0, u8, 0), var(0x1017, 0, u16, 100),
     var(0x1018, 0, u8, 1), var(0x1018, 1, u32, 0x0F1CU), var(0x2004, 0, u32, 0),
     var(0x6502, 0, u32, 0x65U)}};

constexpr std::array<od::entry_spec, 54> sorted_pdo_specs = [] {
  auto e = pdo_entries;
  for (std::size_t i = 1; i < e.size(); ++i) { // insertion sort by (index, sub)
    for (std::size_t k = i; k > 0 && (e[k].index < e[k - 1].index ||
                                      (e[k].index == e[k - 1].index && e[k].sub < e[k - 1].sub));
         --k) {
      const od::entry_spec t = e[k];
      e[k] = e[k - 1];
      e[k - 1] = t;
    }
  }
  return e;
}();
constexpr auto sorted_pdo_entries = od::entries_of<sorted_pdo_specs>;
constexpr od::dictionary pdo_dict{sorted_pdo_entries};
static_assert(pdo_dict.is_valid());
constexpr auto pdo_layout = co::make_layout<sorted_pdo_entries.size()>(pdo_dict);

/// Where the value of `index` (sub 0) starts in a node's storage.
constexpr std::size_t slot(std::uint16_t index) {
  for (std::size_t i = 0; i < sorted_pdo_entries.size(); ++i) {
    if (sorted_pdo_entries[i].index == index && sorted_pdo_entries[i].sub == 0U) {
      return pdo_layout.offsets[i];
    }
  }
  return ~std::size_t{0};
}

using engine_type = node::pdo_engine<store_type, 1, 2, 4>;

struct pdo_node_state {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(pdo_layout.storage_size());
  store_type store{pdo_dict, pdo_layout, storage};
  engine_type engine{store, pdo_dict};
};
/// The nodes fieldcodec's engines run on, and the storage the hand-written RPDO writes into.
std::deque<pdo_node_state> g_nodes;
std::array<std::vector<std::uint8_t>, node_count> g_hand_storage;

struct sync_in {
  std::uint8_t node = 0;
  bool operator==(const sync_in &) const = default;
};
struct rpdo_in {
  std::uint8_t node = 0;
  co::can_frame frame{};
  bool operator==(const rpdo_in &) const = default;
};
bench::inputs<sync_in> g_syncs;
bench::inputs<rpdo_in> g_rpdos;

struct sync_out {
  std::array<co::can_frame, 2> f{};
  std::size_t n = 0;
  bool operator==(const sync_out &) const = default;
};
/// The stored values of the RPDO's four objects after the frame.
struct rpdo_out {
  std::array<std::uint8_t, 8> v{};
  bool operator==(const rpdo_out &) const = default;
};

bool fill_pdo_inputs() {
  bench::rng r(402);
  for (std::size_t i = 0; i < node_count; ++i) {
    pdo_node_state &n = g_nodes.emplace_back();
    if (!n.store.init_defaults(pdo_node) || !n.engine.reload()) return false;
    n.engine.set_operational(true, 0);
    constexpr std::array<std::uint16_t, 8> tpdo_objects{0x2000, 0x2001, 0x2002, 0x6041,
                                                        0x6061, 0x6064, 0x606C, 0x6077};
    for (const std::uint16_t index : tpdo_objects) {
      const auto *e = pdo_dict.find(index, 0);
      if (e == nullptr) return false;
      for (std::size_t k = 0; k < e->width(); ++k) {
        n.storage[slot(index) + k] = static_cast<std::uint8_t>(r.next());
      }
    }
    g_hand_storage[i] = n.storage;
  }
  for (std::size_t i = 0; i < bench::input_count; ++i) {
    g_syncs[i].node = static_cast<std::uint8_t>(r.below(node_count));
    g_rpdos[i].node = static_cast<std::uint8_t>(r.below(node_count));
    g_rpdos[i].frame = co::can_frame{static_cast<std::uint16_t>(0x200U + pdo_node), false, 8, {}};
    for (auto &b : g_rpdos[i].frame.data) b = static_cast<std::uint8_t>(r.next());
  }
  return true;
}

template <class T>
T load_le(const std::vector<std::uint8_t> &s, std::size_t at) {
  T v{};
  std::memcpy(&v, s.data() + at, sizeof(T)); // little-endian host (x86-64, Cortex-M)
  return v;
}

/// Hand-written: read the eight variables and pack the two TPDOs.
sync_out hand_sync(const sync_in &in) {
  sync_out o;
  const auto &s = g_nodes[in.node].storage;
  const auto sw = load_le<std::uint16_t>(s, slot(0x6041));
  const auto pos = load_le<std::uint32_t>(s, slot(0x6064));
  const auto mode = load_le<std::uint8_t>(s, slot(0x6061));
  const auto in0 = load_le<std::uint8_t>(s, slot(0x2000));
  const auto vel = load_le<std::uint32_t>(s, slot(0x606C));
  const auto torque = load_le<std::uint16_t>(s, slot(0x6077));
  const auto st1 = load_le<std::uint8_t>(s, slot(0x2001));
  const auto st2 = load_le<std::uint8_t>(s, slot(0x2002));
  o.f[0] = {0x180U + pdo_node,
            false,
            8,
            {static_cast<std::uint8_t>(sw), static_cast<std::uint8_t>(sw >> 8U),
             static_cast<std::uint8_t>(pos), static_cast<std::uint8_t>(pos >> 8U),
             static_cast<std::uint8_t>(pos >> 16U), static_cast<std::uint8_t>(pos >> 24U), mode,
             in0}};
  o.f[1] = {0x280U + pdo_node,
            false,
            8,
            {static_cast<std::uint8_t>(vel), static_cast<std::uint8_t>(vel >> 8U),
             static_cast<std::uint8_t>(vel >> 16U), static_cast<std::uint8_t>(vel >> 24U),
             static_cast<std::uint8_t>(torque), static_cast<std::uint8_t>(torque >> 8U), st1, st2}};
  o.n = 2;
  return o;
}

rpdo_out stored_rpdo(const std::vector<std::uint8_t> &s) {
  rpdo_out o;
  std::memcpy(o.v.data(), s.data() + slot(0x6040), 2);
  std::memcpy(o.v.data() + 2, s.data() + slot(0x607A), 4);
  o.v[6] = s[slot(0x6060)];
  o.v[7] = s[slot(0x2003)];
  return o;
}

/// Hand-written: take the RPDO if it is ours and long enough, store the four variables.
rpdo_out hand_rpdo(const rpdo_in &in) {
  auto &s = g_hand_storage[in.node];
  const co::can_frame &f = in.frame;
  if (f.id == 0x200U + pdo_node && !f.rtr && f.dlc >= 8U) {
    const std::uint16_t cw = static_cast<std::uint16_t>(f.data[0] | (f.data[1] << 8U));
    const std::uint32_t target = static_cast<std::uint32_t>(f.data[2]) |
                                 (static_cast<std::uint32_t>(f.data[3]) << 8U) |
                                 (static_cast<std::uint32_t>(f.data[4]) << 16U) |
                                 (static_cast<std::uint32_t>(f.data[5]) << 24U);
    std::memcpy(s.data() + slot(0x6040), &cw, 2);
    std::memcpy(s.data() + slot(0x607A), &target, 4);
    s[slot(0x6060)] = f.data[6];
    s[slot(0x2003)] = f.data[7];
  }
  return stored_rpdo(s);
}

void add_pdo(bench::registry &reg) {
  bench::add<g_syncs>(
      reg, "pdo engine/on_sync, 2 TPDOs of 4 objects",
      [](const sync_in &in) {
        sync_out o;
        const auto s = g_nodes[in.node].engine.on_sync(std::nullopt, 0);
        // the transmit queue takes the step's frames in one call, as a driver with a queue
        // would (frames::copy_to; as the SDO block benchmark does since round 4)
        o.n = s.send.copy_to(o.f);
        return o;
      },
      [](const sync_in &in) { return hand_sync(in); });
  bench::add<g_rpdos>(
      reg, "pdo engine/on_frame, RPDO of 4 objects",
      [](const rpdo_in &in) {
        pdo_node_state &n = g_nodes[in.node];
        (void)n.engine.on_frame(in.frame, 0);
        return stored_rpdo(n.storage);
      },
      [](const rpdo_in &in) { return hand_rpdo(in); });
}

/// --check compares fieldcodec with the baseline; this makes sure what they agree on is a
/// whole transfer (initiate answer, 127 segments, end) and not two identical failures.
} // namespace

int main(int argc, char **argv) {
  if (!fill_pdo_inputs()) {
    std::fprintf(stderr, "codec_pdo_engine: the PDO nodes could not be set up\n");
    return 1;
  }
  bench::registry reg;
  bench::add_harness<g_syncs>(reg);
  add_pdo(reg);
  return bench::main(argc, argv, reg);
}
