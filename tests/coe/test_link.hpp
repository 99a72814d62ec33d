// A CoE SDO client and server adapter on one in-memory EtherCAT mailbox link, over the test
// dictionary of tests/canopen/sdo_transfer_test.cpp (plus a long domain), for the CoE tests.
#pragma once

#include <fieldcodec/canopen/coe/sdo_client.hpp>
#include <fieldcodec/canopen/coe/sdo_server.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>

#include "sdo_test_dictionary.hpp"

#include <doctest/doctest.h>

#include <cstdint>
#include <deque>
#include <functional>
#include <span>
#include <vector>

namespace coe_test {

namespace coe = fieldcodec::canopen::coe;
namespace sdo = fieldcodec::canopen::sdo;
namespace co = fieldcodec::canopen;
namespace od = fieldcodec::od;
using od::data_type;

using sdo_test::dict;
using sdo_test::entries;
inline constexpr auto layout = co::make_layout<std::size(entries)>(dict);

using store_t = co::dictionary_store<>;

/// A client adapter and a server adapter on one link: mailboxes travel in order, each written
/// into a SyncManager area of its mailbox size (the rest padded with 0xEE, which the receiver
/// must ignore). When nothing is in flight but an adapter waits, time jumps to its deadline.
struct mailbox_link {
  std::size_t request_size;  ///< SM0: client → server
  std::size_t response_size; ///< SM1: server → client
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(store_t::storage_size(dict));
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(5000); // values in parts
  store_t store{dict, layout, storage, staging};
  std::vector<std::uint8_t> server_buffer;
  std::vector<std::uint8_t> sm0;
  std::vector<std::uint8_t> sm1;
  coe::sdo_server<store_t> server;
  coe::sdo_client client;
  std::uint32_t now = 0;
  std::size_t mailboxes = 0;
  std::deque<std::vector<std::uint8_t>> to_server, to_client;
  std::function<void(std::vector<std::uint8_t> &)> fault; ///< may change a mailbox on its way
  std::vector<std::vector<std::uint8_t>> wire; ///< the SDO part of every mailbox sent, in order

  explicit mailbox_link(std::size_t mailbox_size, std::size_t server_buffer_size = 1024)
      : mailbox_link(mailbox_size, mailbox_size, server_buffer_size) {}
  mailbox_link(std::size_t request, std::size_t response, std::size_t server_buffer_size)
      : request_size(request), response_size(response), server_buffer(server_buffer_size),
        sm0(request), sm1(response), server(store, server_buffer, sm1, request),
        client(sm0, response) {
    REQUIRE(store.init_defaults(5).has_value());
  }

  void push(std::deque<std::vector<std::uint8_t>> &q, std::span<const std::uint8_t> mbx,
            std::size_t area) {
    if (mbx.empty()) return;
    CHECK(mbx.size() <= area);
    std::vector<std::uint8_t> b(mbx.begin(), mbx.end());
    wire.emplace_back(b.begin() + 8, b.end()); // the SDO part
    if (fault) fault(b);
    b.resize(area, 0xEE);
    q.push_back(std::move(b));
  }
  void run(const coe::step &first) {
    push(to_server, first.send, request_size);
    for (int guard = 0; guard < 100000; ++guard) {
      if (!to_server.empty()) {
        auto b = to_server.front();
        to_server.pop_front();
        ++mailboxes;
        push(to_client, server.on_mailbox(b, now).send, response_size);
      } else if (!to_client.empty()) {
        auto b = to_client.front();
        to_client.pop_front();
        ++mailboxes;
        push(to_server, client.on_mailbox(b, now).send, request_size);
      } else if (client.busy() || server.busy()) {
        now += 1000;
        push(to_server, client.poll(now).send, request_size);
        push(to_client, server.poll(now).send, response_size);
      } else {
        return;
      }
    }
    FAIL("the adapters never settled");
  }
  sdo::transfer_state write(std::uint16_t index, std::uint8_t sub,
                            std::span<const std::uint8_t> data) {
    mailboxes = 0;
    run(client.download({index, sub}, data, now).value());
    return client.state();
  }
  sdo::transfer_state read(std::uint16_t index, std::uint8_t sub, std::span<std::uint8_t> buf) {
    mailboxes = 0;
    run(client.upload({index, sub}, buf, now).value());
    return client.state();
  }
  [[nodiscard]] sdo::abort_code code() const {
    return client.error() ? client.error()->abort : sdo::abort_code::none;
  }
};

/// The same transfers over CAN with the CiA 301 machines, for comparison.
struct can_link {
  static constexpr std::uint8_t node = 5;
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(store_t::storage_size(dict));
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(5000);
  store_t store{dict, layout, storage, staging};
  std::vector<std::uint8_t> server_buffer = std::vector<std::uint8_t>(1024);
  sdo::server<store_t> server{node, store, server_buffer};
  sdo::client client{node};
  std::uint32_t now = 0;
  std::deque<co::can_frame> to_server, to_client;

  can_link() { REQUIRE(store.init_defaults(node).has_value()); }
  std::vector<std::vector<std::uint8_t>> wire; ///< the data of every frame sent, in order
  void push(std::deque<co::can_frame> &q, const sdo::step &s) {
    for (const auto &f : s.send) {
      q.push_back(f);
      wire.emplace_back(f.data.begin(), f.data.end());
    }
  }
  void run(const sdo::step &first) {
    push(to_server, first);
    for (int guard = 0; guard < 100000; ++guard) {
      if (!to_server.empty()) {
        auto f = to_server.front();
        to_server.pop_front();
        push(to_client, server.on_frame(f, now));
      } else if (!to_client.empty()) {
        auto f = to_client.front();
        to_client.pop_front();
        push(to_server, client.on_frame(f, now));
      } else if (client.busy() || server.busy()) {
        now += 1000;
        push(to_server, client.poll(now));
        push(to_client, server.poll(now));
      } else {
        return;
      }
    }
    FAIL("the machines never settled");
  }
  sdo::transfer_state write(std::uint16_t index, std::uint8_t sub,
                            std::span<const std::uint8_t> data) {
    run(client.download({index, sub}, data, now).value());
    return client.state();
  }
  sdo::transfer_state read(std::uint16_t index, std::uint8_t sub, std::span<std::uint8_t> buf) {
    run(client.upload({index, sub}, buf, now).value());
    return client.state();
  }
};

inline std::vector<std::uint8_t> pattern(std::size_t n, std::uint8_t seed) {
  std::vector<std::uint8_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint8_t>(0x21U + (seed + i) % 90U);
  return v;
}

/// Mailboxes one way of a transfer of `n` bytes in mailboxes of `size` bytes: the initiate,
/// then one segment per segment capacity beyond what the initiate holds.
inline std::size_t requests_for(std::size_t n, std::size_t size) {
  if (n >= 1 && n <= 4) return 1;
  const std::size_t first = coe::initiate_capacity(size);
  if (n <= first) return 1;
  const std::size_t seg = coe::segment_capacity(size);
  return 1 + (n - first + seg - 1) / seg;
}

inline constexpr std::size_t mailbox_sizes[] = {16, 128, 1486};

} // namespace coe_test
