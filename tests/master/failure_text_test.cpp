// The texts of the master's failure kinds (to_string of boot_failure, config_failure,
// drive_failure, and the states): one per value, distinct, stable — reports and logs compare
// them (docs/master.md).
#include <fieldcodec/master/boot.hpp>
#include <fieldcodec/master/configurator.hpp>
#include <fieldcodec/master/drive.hpp>

#include "enum_texts.hpp"

#include <doctest/doctest.h>

#include <string_view>

namespace master = fieldcodec::master;

namespace {
static_assert(to_string(master::boot_failure::identity_mismatch) == "identity mismatch");
static_assert(to_string(master::config_failure::verify_mismatch) == "read-back differs");

using test_texts::distinct_texts;
} // namespace

TEST_CASE("to_string(boot_failure): the stable texts") {
  using f = master::boot_failure;
  CHECK(to_string(f::no_boot_up) == "no boot-up message");
  CHECK(to_string(f::identity_read_failed) == "identity could not be read");
  CHECK(to_string(f::identity_mismatch) == "identity mismatch");
  CHECK(to_string(f::configuration_failed) == "configuration failed");
  CHECK(to_string(f::no_heartbeat) == "no heartbeat");
  CHECK(to_string(f::not_assigned) == "not a slave of this master");
  CHECK(to_string(f::no_node_state) == "node state unknown");
  CHECK(to_string(f::software_not_checked) == "software version not checked");
  CHECK(to_string(f::software_mismatch) == "software version mismatch");
  CHECK(distinct_texts(f::software_mismatch) == 9U);
}

TEST_CASE("to_string(config_failure): the stable texts") {
  using f = master::config_failure;
  CHECK(to_string(f::transfer_failed) == "transfer failed");
  CHECK(to_string(f::verify_mismatch) == "read-back differs");
  CHECK(to_string(f::bad_item) == "item cannot be sent");
  CHECK(distinct_texts(f::bad_item) == 3U);
}

TEST_CASE("the other master enums have a text for every value") {
  CHECK(distinct_texts(master::boot_state::failed) == 11U);
  CHECK(distinct_texts(master::config_state::failed) == 5U);
  CHECK(distinct_texts(master::drive_state::failed) == 13U);
  CHECK(distinct_texts(master::drive_failure::stop_timeout) == 16U);
  CHECK(distinct_texts(master::identity_field::serial) == 5U);
}
