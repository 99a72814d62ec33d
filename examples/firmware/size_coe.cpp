// coe: the SDO server of an EtherCAT slave — coe::sdo_server (the CiA 301 server machine behind
// the mailbox adapter: expedited, normal and segmented transfer, mailbox error replies, the
// mailbox counter) — over the generated dictionary of the small I/O node (io_node.eds: 164
// entries) with its store, answering mailboxes of 128 bytes. Mailboxes come from and go to
// volatile registers, so every path stays reachable.
#include "io.hpp"
#include "io_node_dictionary.hpp"

#include <fieldcodec/canopen/coe/sdo_server.hpp>
#include <fieldcodec/canopen/object_store.hpp>

#include <array>
#include <cstdint>

namespace coe = fieldcodec::canopen::coe;
namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace io = fieldcodec::dictionaries::io_node;

namespace {
constexpr fieldcodec::od::dictionary dict{io::entries};
constexpr auto layout = co::make_layout<io::entries.size()>(dict);

using store_type = co::dictionary_store<>;
std::array<std::uint8_t, layout.storage_size()> storage{};
store_type store{dict, layout, storage};
std::array<std::uint8_t, 64> buffer{};
std::array<std::uint8_t, 128> sm1{}; // the send mailbox
coe::sdo_server<store_type> server(store, buffer, sm1, 128);

std::array<std::uint8_t, 128> receive_mailbox() {
  std::array<std::uint8_t, 128> m{};
  for (std::size_t i = 0; i < m.size(); ++i) m[i] = fw::rx_register[i % 64U];
  return m;
}
void send(const coe::step &s) {
  fw::transmit(s.send);
  if (s.deadline) fw::tx_register[60] = static_cast<std::uint8_t>(*s.deadline);
}
} // namespace

int main() {
  (void)store.init_defaults(0);
  for (int cycle = 0; cycle < 4; ++cycle) {
    const auto m = receive_mailbox();
    send(server.on_mailbox(m, fw::tick));
    send(server.poll(fw::tick));
  }
  return 0;
}
