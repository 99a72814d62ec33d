// A master writes a parameter set to a Rexroth DPQ card (node 5) in engineering units and reads
// it back: the values become raw bytes with dpq/ (manual 004, ch. 3: raw = round(EU × scale)),
// master::configurator writes them (retries, read-back verify), an SDO upload per parameter
// reads them back and dpq::from_bytes turns them into exact decimals again.
// The card is simulated in the same program (an SDO server over the generated DPQ dictionary).
// docs/master.md walks through this program.
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/master/configurator.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace dpq = fieldcodec::dpq;
namespace master = fieldcodec::master;
namespace p = fieldcodec::dictionaries::dpq_parameters;

namespace {

constexpr std::uint8_t node = 5;
constexpr auto layout = co::make_layout<p::dictionary.size()>(p::dictionary);

struct simulated_dpq {
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(layout.storage_size());
  co::dictionary_store<> store{p::dictionary, layout, storage};
  std::array<std::uint8_t, 64> buffer{};
  sdo::server<co::dictionary_store<>> server{node, store, buffer};
  simulated_dpq() { (void)store.init_defaults(node); }
};

/// One parameter of the set: which, the value in engineering units, the unit for the print.
struct setting {
  const fieldcodec::od::descriptor &parameter;
  double value;
  const char *unit;
};

} // namespace

int main() {
  // Pressures in bar (the manual's example: Inj. P Limit 1 = 4.0 bar is raw 1311 = 0x051F);
  // injection velocities in mm/s (scale 10.5; the manual prints no unit for them).
  const setting set[] = {
      {p::inj_p_limit_1, 4.0, "bar"},
      {p::inj_p_limit_2, 120.5, "bar"},
      {p::inj_velocity_1, 85.0, "mm/s"},
      {p::inj_velocity_2, 40.5, "mm/s"},
  };
  constexpr std::size_t n = std::size(set);

  // EU -> bytes, checked against range, field and access before anything is sent
  std::array<dpq::payload, n> bytes{};
  std::array<master::config_item, n> items{};
  for (std::size_t i = 0; i < n; ++i) {
    auto b = dpq::write_bytes(set[i].parameter, set[i].value);
    if (!b) {
      std::printf("%s: %s\n", set[i].parameter.info.name.data(),
                  std::string(fieldcodec::to_string(b.error())).c_str());
      return 1;
    }
    bytes[i] = b.value();
    items[i] = {{set[i].parameter.index, set[i].parameter.sub},
                bytes[i].span(),
                0,
                set[i].parameter.info.name};
  }

  simulated_dpq card;
  sdo::client client(node, 100);
  std::uint32_t now = 0;
  std::deque<co::can_frame> replies;
  const auto send = [&](const co::frames &fs) {
    for (const auto &f : fs) {
      const auto r = card.server.on_frame(f, now);
      replies.insert(replies.end(), r.send.begin(), r.send.end());
    }
  };

  // write the set, verified by reading back
  master::configurator writer(client, {.retries = 2, .timeout_ms = 200, .verify = true});
  auto s = writer.start({items, {}, node}, now);
  if (!s) return 1;
  send(s.value().send);
  while (writer.busy() && !replies.empty()) {
    const auto f = replies.front();
    replies.pop_front();
    send(writer.on_frame(f, ++now).send);
  }
  if (writer.state() != master::config_state::done) {
    const auto e = *writer.error();
    std::printf("writing %.*s failed: abort %08X\n", static_cast<int>(e.name.size()), e.name.data(),
                static_cast<unsigned>(e.abort));
    return 1;
  }
  std::printf("wrote %zu parameters (verified)\n", writer.completed());

  // read every parameter back and show it in engineering units
  int failures = 0;
  for (const auto &x : set) {
    std::array<std::uint8_t, 4> buf{};
    auto u = client.upload({x.parameter.index, x.parameter.sub}, buf, now);
    if (!u) return 1;
    send(u.value().send);
    while (client.busy() && !replies.empty()) {
      const auto f = replies.front();
      replies.pop_front();
      send(client.on_frame(f, ++now).send);
    }
    if (client.state() != sdo::transfer_state::done) return 1;
    auto eu = dpq::from_bytes(x.parameter, client.received());
    if (!eu) return 1;
    std::array<char, 32> text{};
    const auto len = fieldcodec::format_decimal(eu.value(), text).value_or(0);
    std::printf("  %-18.*s %04X:%02X  raw bytes", static_cast<int>(x.parameter.info.name.size()),
                x.parameter.info.name.data(), x.parameter.index, x.parameter.sub);
    for (const std::uint8_t b : client.received()) std::printf(" %02X", b);
    std::printf("  -> %.*s %s (written %.1f)\n", static_cast<int>(len), text.data(), x.unit,
                x.value);
    // what the card holds is what was written
    const auto want = bytes[static_cast<std::size_t>(&x - set)].span();
    if (!std::equal(want.begin(), want.end(), client.received().begin(), client.received().end())) {
      ++failures;
    }
  }
  return failures;
}
