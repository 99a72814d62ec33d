// The checked-in generated dictionaries: shapes other modules rely on.
#include <fieldcodec/dictionaries/compax_objects.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/od/value.hpp>

#include <doctest/doctest.h>

namespace dpq = fieldcodec::dictionaries::dpq_parameters;
namespace pac = fieldcodec::dictionaries::pacontrol_commands;
namespace xc = fieldcodec::dictionaries::xenax_canopen;
using fieldcodec::errc;

// DPQ manual 004, chapter 3: Inj. P Limit 1 = 4.0 bar with scale 327,67 → 1311 (0x051F).
static_assert(dpq::inj_p_limit_1.index == 0x2023);
static_assert(dpq::inj_p_limit_1.to_raw(4.0).value() == 1311);
static_assert(dpq::inj_p_limit_1.to_raw(5000.5).error() == errc::out_of_range);
// a named descriptor is a standalone copy of its table row (entry, info, scale)
static_assert(dpq::dictionary.info(*dpq::dictionary.lookup(0x2023, 0).value()).name ==
              dpq::inj_p_limit_1.info.name);
// 221 bus parameters of chapter 4 + 19 communication objects of chapter 3 (docs/dpq.md)
static_assert(dpq::dictionary.size() == 240);

static_assert(pac::table.find(0x0600) == &pac::cmd_stop);
static_assert(pac::cmd_stop.allowed_in("online"));

TEST_CASE("generated: xenax_canopen identity object") {
  const auto *e = xc::dictionary.find(0x1018, 1);
  REQUIRE(e != nullptr);
  CHECK(e->type == fieldcodec::od::data_type::unsigned32);
  CHECK(xc::dictionary.object(0x1018).size() >= 2);
}

// COMPAX manual 000, 2.10.4: OUTPUT_MASK (5FF5h, OCTET_STRING of 2 bytes) is 0 after power on.
// The CSV writes it as the hex digits 0000: the default is two zero bytes, not the text "0".
TEST_CASE("generated: an OCTET_STRING default is its bytes, NULs included") {
  const auto *e = fieldcodec::dictionaries::compax_objects::dictionary.find(0x5FF5, 0);
  REQUIRE(e != nullptr);
  CHECK(e->capacity() == 2);
  CHECK(e->default_text() == std::string_view("\0\0", 2));
}

TEST_CASE("generated: XENAX strings have a capacity (issue 12.1)") {
  const auto *e = xc::dictionary.find(0x1008, 0);
  REQUIRE(e != nullptr);
  CHECK(e->default_text() == "Servocontroller XENAX Xvi xxVx");
  CHECK(e->capacity() >= e->default_text().size()); // its default's length at least (30)
}
