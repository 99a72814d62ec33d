// The texts of the node's event kinds (to_string of event::kind, heartbeat_event::kind,
// pdo_event::kind): one per kind, distinct, and stable — logs and tests of applications compare
// them, so a change here is a change of the public interface (docs/canopen.md, "Node services").
#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/node/heartbeat.hpp>
#include <fieldcodec/canopen/node/pdo_engine.hpp>

#include "enum_texts.hpp"

#include <doctest/doctest.h>

#include <string_view>

namespace node = fieldcodec::canopen::node;

namespace {
// to_string is found by argument-dependent lookup, as an application writes it
static_assert(to_string(node::event::kind::sync) == "SYNC received");
static_assert(to_string(node::heartbeat_event::kind::lost) == "heartbeat lost");
static_assert(to_string(node::pdo_event::kind::too_short) == "RPDO too short");

using test_texts::distinct_texts;
} // namespace

TEST_CASE("to_string(event::kind): the stable texts") {
  using k = node::event::kind;
  CHECK(to_string(k::nmt_state) == "NMT state changed");
  CHECK(to_string(k::reset_application) == "reset application");
  CHECK(to_string(k::reset_communication) == "reset communication");
  CHECK(to_string(k::heartbeat) == "heartbeat consumer event");
  CHECK(to_string(k::life_guard_lost) == "life guarding lost");
  CHECK(to_string(k::life_guard_resumed) == "life guarding resumed");
  CHECK(to_string(k::pdo) == "PDO event");
  CHECK(to_string(k::sync) == "SYNC received");
  CHECK(distinct_texts(k::sync) == 8U);
}

TEST_CASE("to_string(heartbeat_event::kind): the stable texts") {
  using k = node::heartbeat_event::kind;
  CHECK(to_string(k::started) == "heartbeat started");
  CHECK(to_string(k::state_changed) == "NMT state changed");
  CHECK(to_string(k::boot_up) == "boot-up");
  CHECK(to_string(k::lost) == "heartbeat lost");
  CHECK(to_string(k::resumed) == "heartbeat resumed");
  CHECK(distinct_texts(k::resumed) == 5U);
}

TEST_CASE("to_string(pdo_event::kind): the stable texts") {
  using k = node::pdo_event::kind;
  CHECK(to_string(k::received) == "RPDO received");
  CHECK(to_string(k::too_short) == "RPDO too short");
  CHECK(to_string(k::too_long) == "RPDO too long");
  CHECK(to_string(k::outside_window) == "RPDO outside the synchronous window");
  CHECK(to_string(k::timeout) == "RPDO timeout");
  CHECK(to_string(k::not_sent) == "TPDO not sent");
  CHECK(distinct_texts(k::not_sent) == 6U);
}
