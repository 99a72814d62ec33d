// node: a complete CiA 301 slave — NMT, SDO server (expedited, segmented, block), 4 RPDOs and
// 4 TPDOs with mapping changes, heartbeat producer and consumer, node and life guarding, EMCY
// with 1001h/1003h, SYNC consumer — over the generated dictionary of a small I/O node
// (io_node.eds: 164 entries). Frames come from and go to volatile registers, so every service
// stays reachable. .ci/steps/cortex_m.sh builds CANopenNode's node with the same services from
// the same EDS and prints both side by side (docs/performance.md "Cortex-M").
#include "io.hpp"
#include "io_node_dictionary.hpp"

#include <fieldcodec/canopen/node/device.hpp>

namespace co = fieldcodec::canopen;
namespace node = fieldcodec::canopen::node;
namespace sdo = fieldcodec::canopen::sdo;
namespace io = fieldcodec::dictionaries::io_node;

// The lean entry: 8 bytes of columns and a pointer to the packed ones (od/entry.hpp), 12 bytes
// on this target. Checked here, where a 32-bit target compiles it.
static_assert(sizeof(fieldcodec::od::entry) == 12);
// An integer-only dictionary: the store links no floating point and no 64-bit division.
static_assert(!io::kinds.real && !io::kinds.wide && !io::kinds.scaled && !io::kinds.numbers);

namespace {
// The node reads no names: a dictionary of the lean entries alone keeps the descriptive table
// (io::infos, 14 kB here) out of the image.
constexpr fieldcodec::od::dictionary dict{io::entries};
// offsets of 16 bits: the node's values take less than 64 kB
constexpr auto layout = co::make_layout<io::entries.size(), std::uint16_t>(dict);
constexpr node::capacity caps = [] {
  node::capacity c = node::capacity_for(dict);
  c.sdo_buffer = 64;    // expedited and segmented of any size; block sub-blocks of 9 segments
  c.pdo_copies = false; // mapped objects one by one: the smaller PDO engine
#ifdef FIELDCODEC_SIZE_NODE_LSS
  c.lss = true; // size_node_lss.cpp: the same node as an LSS slave (CiA 305)
#endif
  return c;
}();
static_assert(caps.rpdos == 4 && caps.tpdos == 4 && caps.mapped == 8);

using store_type = co::dictionary_store<co::accept_writes, io::kinds, std::uint16_t>;
std::array<std::uint8_t, layout.storage_size()> storage{};
constinit store_type store{dict, layout, storage};
node::device<store_type, caps> dev(store, 0x22);

co::can_frame receive_frame() {
  co::can_frame f;
  f.id = static_cast<std::uint16_t>(fw::receive_u16() & 0x7FFU);
  f.rtr = (fw::rx_register[2] & 1U) != 0U;
  f.dlc = static_cast<std::uint8_t>(fw::rx_register[3] & 7U);
  for (std::size_t i = 0; i < f.dlc; ++i) f.data[i] = fw::rx_register[4U + i];
  return f;
}
void send(const node::device<store_type, caps>::step &s) {
  for (const co::can_frame &f : s.send) fw::transmit(f.data);
  if (s.deadline) fw::tx_register[60] = static_cast<std::uint8_t>(*s.deadline);
}
} // namespace

int main() {
  (void)store.init_defaults(0x22);
  if (auto s = dev.start(fw::tick)) send(s.value());
  for (int cycle = 0; cycle < 4; ++cycle) {
    send(dev.on_frame(receive_frame(), fw::tick));
    // the application: inputs into the dictionary, outputs from it
    const std::array<std::uint8_t, 1> inputs{fw::rx_register[12]};
    if (auto s = dev.set({0x6000, 1}, inputs, fw::tick)) send(s.value());
    if (auto out = dev.value({0x6200, 1})) fw::tx_register[61] = out.value()[0];
    send(dev.poll(fw::tick));
  }
  return 0;
}
