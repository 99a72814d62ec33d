// docs/canopen.md, "The node": the block on that page, compiled and run as written (the
// docs_blocks_compiled check finds it here), over the generated XENAX CAN dictionary.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>

#include <vector>

namespace {
std::vector<fieldcodec::canopen::can_frame> sent;
template <class Step>
void send(const Step &s) {
  for (const auto &f : s.send) sent.push_back(f);
}
std::vector<fieldcodec::canopen::node::event> seen;
void handle(const fieldcodec::canopen::node::event &e) { seen.push_back(e); }

// the block needs these names from its surroundings
constexpr std::uint8_t node_id = 5;
constexpr std::uint32_t now = 0;
constexpr std::array<std::uint8_t, 2> bytes{0x37, 0x02};

void the_block() {
  namespace co = fieldcodec::canopen;
  namespace node = fieldcodec::canopen::node;
  namespace gen = fieldcodec::dictionaries::xenax_canopen;

  constexpr auto layout = co::make_layout<gen::entries.size()>(gen::dictionary);
  std::array<std::uint8_t, layout.storage_size()> storage{};
  co::dictionary_store<> store{gen::dictionary, layout, storage};
  (void)store.init_defaults(node_id); // the power-on values
  node::device<co::dictionary_store<>, node::capacity_for(gen::dictionary)> dev(store, node_id);

  send(dev.start(now).value());                        // boot-up, pre-operational
  for (const node::event &e : dev.events()) handle(e); // after each call: NMT state, RPDO, ...
  // every received frame:    send(dev.on_frame(frame, now));
  // at s.deadline at latest: send(dev.poll(now));
  send(dev.set({0x6041, 0}, bytes, now).value()); // the application's values, and the
                                                  // event-driven TPDOs they make due

  CHECK(dev.value({0x6041, 0}).value()[0] == 0x37);
}
} // namespace

TEST_CASE("docs/canopen.md: the node block runs as written") {
  sent.clear();
  seen.clear();
  the_block();
  // the boot-up message of node 5, and the state change to pre-operational as an event
  REQUIRE(sent.size() == 1);
  CHECK(sent[0].id == 0x705);
  CHECK(sent[0].dlc == 1);
  CHECK(sent[0].data[0] == 0x00);
  CHECK_FALSE(seen.empty());
}
