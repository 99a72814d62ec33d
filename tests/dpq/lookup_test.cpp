// DPQ lookup by printed name and manual section, and value acceptance (manual 004, chapter 4:
// each parameter's name, section number and "Value acceptance"), dpq/lookup.hpp and the DPQ
// column table generated beside the dictionary (dpq/columns.hpp).
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/lookup.hpp>
#include <fieldcodec/od/address.hpp>

#include <doctest/doctest.h>

#include <cstddef>
#include <span>
#include <string>

namespace fc = fieldcodec;
namespace dpq = fieldcodec::dpq;
namespace p = fieldcodec::dictionaries::dpq_parameters;
using fc::errc;

// 4.100 "Inj. P Limit 1" is 2023h (the manual's SDO example).
static_assert(dpq::find_by_name(p::dictionary, "Inj. P Limit 1").value().index == 0x2023);
static_assert(dpq::find_by_section(p::dictionary, "4.100").value().index == 0x2023);
static_assert(dpq::find_by_name(p::dictionary, "  inj.  P LIMIT\t1 ", dpq::name_match::normalised)
                  .value()
                  .index == 0x2023);
static_assert(dpq::parse_acceptance("also with active enabling") ==
              dpq::acceptance::also_when_enabled);
static_assert(dpq::check_acceptance(p::dpq_columns, p::cyl_area_ratio, dpq::enabling::active) ==
              errc::bad_state);
static_assert(dpq::columns_of(p::dpq_columns, p::inj_p_limit_1).bus == dpq::bus_manager::available);
static_assert(fc::od::rows_sorted(std::span<const dpq::parameter_columns>(p::dpq_columns)));

TEST_CASE("dpq lookup: by exact name") {
  auto d = dpq::find_by_name(p::dictionary, "BackP: Decomp Rate 2");
  REQUIRE(d.has_value());
  CHECK(d.value().index == 0x219C);
  CHECK(d.value().info.section == "4.2");
  // exact means exact: case, spacing and punctuation count
  CHECK(dpq::find_by_name(p::dictionary, "backp: decomp rate 2") == errc::unknown_object);
  CHECK(dpq::find_by_name(p::dictionary, "BackP:  Decomp Rate 2") == errc::unknown_object);
  CHECK(dpq::find_by_name(p::dictionary, "BackP Decomp Rate 2") == errc::unknown_object);
  CHECK(dpq::find_by_name(p::dictionary, "") == errc::unknown_object);
  CHECK(dpq::find_by_name(p::dictionary, "No Such Parameter") == errc::unknown_object);
}

TEST_CASE("dpq lookup: normalised name") {
  const auto n = dpq::name_match::normalised;
  CHECK(dpq::find_by_name(p::dictionary, "backp: decomp rate 2", n).value().index == 0x219C);
  CHECK(dpq::find_by_name(p::dictionary, "BACKP:   DECOMP RATE 2  ", n).value().index == 0x219C);
  // punctuation is kept: Limit- and Limit+ stay two parameters, no colon is no match
  auto minus = dpq::find_by_name(p::dictionary, "decompres.: limit-", n);
  auto plus = dpq::find_by_name(p::dictionary, "decompres.: limit+", n);
  REQUIRE(minus.has_value());
  REQUIRE(plus.has_value());
  CHECK(minus.value().index != plus.value().index);
  CHECK(dpq::find_by_name(p::dictionary, "backp decomp rate 2", n) == errc::unknown_object);
  CHECK(dpq::find_by_name(p::dictionary, "backp: decomp rate", n) == errc::unknown_object);
  CHECK(dpq::find_by_name(p::dictionary, "backp: decomp rate 22", n) == errc::unknown_object);
  CHECK(dpq::find_by_name(p::dictionary, "   ", n) == errc::unknown_object);
  CHECK(dpq::find_by_name(p::dictionary, "backp:decomp rate 2", n) == errc::unknown_object);
}

// The table's bus parameters of chapter 4 ("4.n"); the other rows are chapter 3's
// communication objects.
static bool is_parameter(const fc::od::entry_info &info) {
  return info.section.view().substr(0, 2) == "4.";
}

TEST_CASE("dpq lookup: every entry by name (both rules), every parameter by section, all unique") {
  // 221 bus parameters + 19 communication objects
  REQUIRE(p::infos.size() == 240);
  std::size_t parameters = 0;
  for (std::size_t i = 0; i < p::infos.size(); ++i) {
    const auto &info = p::infos[i];
    const auto at = fc::od::address{p::entries[i].index, p::entries[i].sub};
    auto exact = dpq::find_by_name(p::dictionary, info.name);
    REQUIRE_MESSAGE(exact.has_value(), info.name);
    CHECK_MESSAGE((fc::od::address{exact.value().index, exact.value().sub} == at), info.name);
    // upper-cased and padded: still exactly this entry (no two names collide)
    std::string shouted(info.name);
    for (char &c : shouted) {
      if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    }
    shouted = " " + shouted + "\t";
    auto norm = dpq::find_by_name(p::dictionary, shouted, dpq::name_match::normalised);
    REQUIRE_MESSAGE(norm.has_value(), info.name);
    CHECK_MESSAGE((fc::od::address{norm.value().index, norm.value().sub} == at), info.name);
    if (is_parameter(info)) ++parameters;
  }
  CHECK(parameters == 221);
  for (std::size_t n = 1; n <= 221; ++n) {
    const std::string section = "4." + std::to_string(n);
    auto sec = dpq::find_by_section(p::dictionary, section);
    REQUIRE_MESSAGE(sec.has_value(), section);
    CHECK_MESSAGE(sec.value().info.section == section, section);
  }
  // a section of chapter 3 describes several objects: ambiguous
  CHECK(dpq::find_by_section(p::dictionary, "3.4") == errc::invalid_argument);
  CHECK(dpq::find_by_section(p::dictionary, "3.5") == errc::invalid_argument);
}

TEST_CASE("dpq lookup: bad sections") {
  CHECK(dpq::find_by_section(p::dictionary, "4.0") == errc::unknown_object);
  CHECK(dpq::find_by_section(p::dictionary, "4.222") == errc::unknown_object);
  CHECK(dpq::find_by_section(p::dictionary, "4.1000") == errc::unknown_object);
  CHECK(dpq::find_by_section(p::dictionary, "4.100 ") == errc::unknown_object);
  CHECK(dpq::find_by_section(p::dictionary, "") == errc::unknown_object);
  CHECK(dpq::find_by_section(fc::od::dictionary{}, "4.1") == errc::unknown_object);
  CHECK(dpq::find_by_name(fc::od::dictionary{}, "Analog Vel Max") == errc::unknown_object);
}

TEST_CASE("dpq acceptance: the printed texts as data") {
  CHECK(dpq::parse_acceptance("only with deactivated enabling") ==
        dpq::acceptance::only_when_disabled);
  CHECK(dpq::parse_acceptance("Also with active enabling") == dpq::acceptance::unknown);
  CHECK(dpq::parse_acceptance("") == dpq::acceptance::unknown);
  // 4.34 Cyl. Area Ratio: rw, only with deactivated enabling
  CHECK(dpq::acceptance_of(p::dpq_columns, p::cyl_area_ratio) ==
        dpq::acceptance::only_when_disabled);
  CHECK(dpq::check_acceptance(p::dpq_columns, p::cyl_area_ratio, dpq::enabling::inactive)
            .has_value());
  CHECK(dpq::check_acceptance(p::dpq_columns, p::cyl_area_ratio, dpq::enabling::active) ==
        errc::bad_state);
  // 4.100 Inj. P Limit 1: also with active enabling
  CHECK(dpq::acceptance_of(p::dpq_columns, p::inj_p_limit_1) == dpq::acceptance::also_when_enabled);
  CHECK(dpq::check_acceptance(p::dpq_columns, p::inj_p_limit_1, dpq::enabling::active).has_value());
  CHECK(
      dpq::check_acceptance(p::dpq_columns, p::inj_p_limit_1, dpq::enabling::inactive).has_value());
  // read-only parameters are never written
  auto ro = dpq::find_by_section(p::dictionary, "4.221");
  REQUIRE(ro.has_value());
  CHECK(dpq::check_acceptance(p::dpq_columns, ro.value(), dpq::enabling::inactive) ==
        errc::access_denied);
  // an entry without a DPQ acceptance: not in the table given (an empty one, another's)
  CHECK(dpq::check_acceptance({}, p::inj_p_limit_1, dpq::enabling::inactive) ==
        errc::invalid_argument);
  CHECK(dpq::acceptance_of({}, p::inj_p_limit_1) == dpq::acceptance::unknown);
}

TEST_CASE("dpq columns: the table beside the dictionary") {
  // one row per chapter 4 parameter (221), none for the 19 communication objects of chapter 3
  CHECK(std::size(p::dpq_columns) == 221);
  // parse_bus_manager: the printed texts only, exactly
  CHECK(dpq::parse_bus_manager("available") == dpq::bus_manager::available);
  CHECK(dpq::parse_bus_manager("not available") == dpq::bus_manager::not_available);
  CHECK(dpq::parse_bus_manager("Available") == dpq::bus_manager::unspecified);
  CHECK(dpq::parse_bus_manager("") == dpq::bus_manager::unspecified);
  // 4.1 Analog Vel Max (2C69h): also with active enabling, not available
  const auto c = dpq::columns_of(p::dpq_columns, fc::od::address{0x2C69, 0});
  CHECK(c.index == 0x2C69);
  CHECK(c.value_acceptance == dpq::acceptance::also_when_enabled);
  CHECK(c.bus == dpq::bus_manager::not_available);
  // a communication object and an address nobody has: the empty row of that address
  const auto none = dpq::columns_of(p::dpq_columns, p::error_register);
  CHECK(none.index == 0x1001);
  CHECK(none.value_acceptance == dpq::acceptance::unknown);
  CHECK(none.bus == dpq::bus_manager::unspecified);
  CHECK(dpq::columns_of(p::dpq_columns, fc::od::address{0xFFFF, 255}).value_acceptance ==
        dpq::acceptance::unknown);
  // every row is an entry of the dictionary
  for (const auto &row : p::dpq_columns) {
    CHECK(p::dictionary.contains({row.index, row.sub}));
  }
}

TEST_CASE("dpq acceptance: every parameter has a known acceptance (221 = 163 + 58)") {
  std::size_t also = 0;
  std::size_t only = 0;
  std::size_t only_rw = 0;
  for (std::size_t i = 0; i < p::infos.size(); ++i) {
    auto d = p::dictionary.describe(p::entries[i]);
    REQUIRE(d.has_value());
    const auto a = dpq::acceptance_of(p::dpq_columns, d.value());
    if (!is_parameter(p::infos[i])) {
      // chapter 3 prints no value acceptance for the communication objects
      CHECK_MESSAGE(a == dpq::acceptance::unknown, p::infos[i].name);
      // read-only ones are refused first; a writable one has no acceptance to check
      CHECK(
          dpq::check_acceptance(p::dpq_columns, d.value(), dpq::enabling::inactive) ==
          (fc::od::writable(d.value().access_type) ? errc::invalid_argument : errc::access_denied));
      continue;
    }
    CHECK_MESSAGE(a != dpq::acceptance::unknown, p::infos[i].name);
    if (a == dpq::acceptance::also_when_enabled) ++also;
    if (a == dpq::acceptance::only_when_disabled) {
      ++only;
      if (fc::od::writable(d.value().access_type)) {
        ++only_rw;
        CHECK(dpq::check_acceptance(p::dpq_columns, d.value(), dpq::enabling::active) ==
              errc::bad_state);
      }
    }
  }
  CHECK(also == 159);
  CHECK(only == 62);
  CHECK(only_rw == 4); // 4.34, 4.98, 4.204, 4.206
}
