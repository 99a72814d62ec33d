// The C++ blocks of the CoE section of docs/canopen.md, as written there, and what their
// comments state: a XENAX EtherCAT walk-through with the generated `xenax_ethercat` dictionary.
// The slave behind the mailboxes is a simulated XENAX module: coe::sdo_server over a
// dictionary store of the same dictionary (as firmware on the module would run it).
// tests/docs_check/run.cmake fails when a block of the page and its copy here differ.
#include <fieldcodec/canopen/coe/sdo_client.hpp>
#include <fieldcodec/canopen/coe/sdo_server.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace {
namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace xe = fieldcodec::dictionaries::xenax_ethercat;

/// A simulated XENAX EtherCAT module: its object dictionary behind an SDO server over CoE, with
/// a send mailbox (SM1) of 128 bytes and a receive mailbox (SM0) of 128.
struct xenax_module {
  static constexpr auto layout = co::make_layout<xe::dictionary.size()>(xe::dictionary);
  std::vector<std::uint8_t> storage =
      std::vector<std::uint8_t>(co::dictionary_store<>::storage_size(xe::dictionary));
  co::dictionary_store<> store{xe::dictionary, layout, storage};
  std::vector<std::uint8_t> buffer = std::vector<std::uint8_t>(256);
  std::array<std::uint8_t, 128> sm1{};
  fieldcodec::canopen::coe::sdo_server<co::dictionary_store<>> server{store, buffer, sm1, 128};
  std::vector<std::uint8_t> sm1_content; ///< what the master reads next
  xenax_module() { REQUIRE(store.init_defaults(1).has_value()); }
};
xenax_module *module = nullptr;
std::vector<std::vector<std::uint8_t>> written; ///< every mailbox the master wrote

// What an EtherCAT master library offers: write the slave's SM0, read its SM1.
void ethercat_write_sm0(std::span<const std::uint8_t> mailbox) {
  written.emplace_back(mailbox.begin(), mailbox.end());
  const auto answer = module->server.on_mailbox(mailbox, 0);
  module->sm1_content.assign(answer.send.begin(), answer.send.end());
}
std::span<const std::uint8_t> ethercat_read_sm1() { return module->sm1_content; }
} // namespace

TEST_CASE("docs: a XENAX EtherCAT walk-through over a CoE mailbox") {
  xenax_module m;
  module = &m;
  written.clear();
  // clang-format off
namespace coe = fieldcodec::canopen::coe;
namespace xenax = fieldcodec::dictionaries::xenax_ethercat;

std::array<std::uint8_t, 128> sm0{};   // the buffer for the module's receive mailbox (SM0)
coe::sdo_client client(sm0, 128);      // its send mailbox (SM1) holds 128 bytes too
std::uint32_t now = 0;                 // your millisecond counter

// write Speed (6081h, UNSIGNED32, 10..100000000): od::encode checks the value first
auto s = client.write(xenax::speed, 250'000, now);
ethercat_write_sm0(s.value().send);    // 0A 00 00 00 00 13 | 00 20 | 23 81 60 00 90 D0 03 00
auto r = client.on_mailbox(ethercat_read_sm1(), now);   // r.state == done

auto low = client.write(xenax::speed, 5, now);   // errc::out_of_range: nothing is sent

// read the device name (1008h, VISIBLE_STRING of 30 bytes: a normal transfer)
std::array<std::uint8_t, 30> name{};
r = client.upload({0x1008, 0}, name, now).value();
ethercat_write_sm0(r.send);
r = client.on_mailbox(ethercat_read_sm1(), now);   // client.received(): the 30 bytes

// read the XENAX error number (2004h, INTEGER8) as an int
r = client.read(xenax::xenax_error_number, now).value();
ethercat_write_sm0(r.send);
r = client.on_mailbox(ethercat_read_sm1(), now);
auto error_number = client.value<int>(xenax::xenax_error_number);   // 0: no error
  // clang-format on
  REQUIRE(written.size() == 3);
  CHECK(written[0] == std::vector<std::uint8_t>{0x0A, 0x00, 0x00, 0x00, 0x00, 0x13, 0x00, 0x20,
                                                0x23, 0x81, 0x60, 0x00, 0x90, 0xD0, 0x03, 0x00});
  CHECK(low == fieldcodec::errc::out_of_range);
  CHECK(m.store.value({0x6081, 0}).value().size() == 4);
  CHECK(m.store.value({0x6081, 0}).value()[1] == 0xD0);
  CHECK(std::string_view(reinterpret_cast<const char *>(client.received().data()), 0) == "");
  CHECK(error_number == 0);
  CHECK(r.state == sdo::transfer_state::done);
  // the device name went as a normal transfer: 30 bytes in one response of 6 + 10 + 30
  CHECK(written[1][8] == 0x40);
  CHECK(std::string_view(reinterpret_cast<const char *>(name.data()), name.size()) ==
        "Servocontroller XENAX Xvi xxVx");
}

TEST_CASE("XENAX over CoE: every readable object of the EtherCAT dictionary, 16-byte mailboxes") {
  // the module's whole dictionary read through the smallest mailboxes (segments of 7 bytes),
  // each value equal to the store's, and every writable fixed-size object written back
  xenax_module m;
  std::array<std::uint8_t, 16> sm0{};
  std::array<std::uint8_t, 16> sm1{};
  fieldcodec::canopen::coe::sdo_server<co::dictionary_store<>> server{m.store, m.buffer, sm1, 16};
  fieldcodec::canopen::coe::sdo_client client(sm0, 16);
  const auto exchange = [&](fieldcodec::canopen::coe::step s) {
    for (int i = 0; i < 1000 && !s.send.empty(); ++i) {
      const auto a = server.on_mailbox(s.send, 0);
      if (a.send.empty()) break;
      s = client.on_mailbox(a.send, 0);
    }
    return client.state();
  };
  std::size_t read = 0, written_back = 0;
  for (const auto &e : xe::dictionary) {
    CAPTURE(e.index);
    CAPTURE(static_cast<int>(e.sub));
    if (!fieldcodec::od::readable(e.access_type)) continue;
    std::array<std::uint8_t, 64> buf{};
    REQUIRE(exchange(client.upload({e.index, e.sub}, buf, 0).value()) == sdo::transfer_state::done);
    const auto stored = m.store.value({e.index, e.sub}).value();
    REQUIRE(client.received().size() == stored.size());
    CHECK(std::equal(stored.begin(), stored.end(), client.received().begin()));
    ++read;
    if (!fieldcodec::od::writable(e.access_type) || fieldcodec::od::fixed_size(e.type) == 0U) {
      continue;
    }
    const std::vector<std::uint8_t> v(client.received().begin(), client.received().end());
    // every value the store holds is one it takes back: an object without a default (5003h
    // sub 12 and sub 20, a low limit above 0) starts at its low limit (fuzz/FINDINGS.md F25)
    CHECK(exchange(client.download({e.index, e.sub}, v, 0).value()) == sdo::transfer_state::done);
    ++written_back;
  }
  CHECK(read == 342);         // the readable objects of xenax_ethercat.eds
  CHECK(written_back == 227); // the writable fixed-size ones
}
