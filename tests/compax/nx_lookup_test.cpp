// Issue 18: the Nx command tables are looked up in one step (family_index, code_index, built at
// compile time from `families`). These tests compare them with the table scans they replaced,
// kept here as the reference, for every op value and every code byte.
#include <fieldcodec/compax/nx.hpp>

#include <doctest/doctest.h>

#include <cstddef>
#include <cstdint>

namespace nx = fieldcodec::compax::nx;
namespace d = fieldcodec::compax::nx::detail;

namespace {
// The scans, answering with positions in d::families (d::no_family: none).
std::uint8_t reference_family_position(nx::op o) {
  for (std::size_t i = 0; i < d::families.size(); ++i) {
    if (d::families[i].o == o) return static_cast<std::uint8_t>(i);
  }
  return d::no_family;
}

fieldcodec::result<d::decoded_code> reference_find_code(std::uint8_t code) {
  for (const auto &f : d::families) {
    if (code == f.code) return d::decoded_code{f, nx::arg_kind::value};
    if (f.has_forms && code == (f.code | d::parameter_flag))
      return d::decoded_code{f, nx::arg_kind::parameter};
    if (f.has_forms && code == (f.code | d::variable_flag))
      return d::decoded_code{f, nx::arg_kind::variable};
  }
  return fieldcodec::errc::unknown_command;
}
} // namespace

TEST_CASE("nx: find_family finds what the table scan found, for every op value") {
  for (unsigned v = 0; v < 256U; ++v) {
    const auto o = static_cast<nx::op>(v);
    INFO("op ", v);
    const std::uint8_t want = reference_family_position(o);
    CHECK(d::family_position(o) == want);
    const auto f = d::find_family(o);
    REQUIRE(f.has_value() == (want != d::no_family));
    if (f) {
      CHECK(f.value() == d::families[want]);
    } else {
      CHECK(f.error() == fieldcodec::errc::unknown_command);
    }
  }
  static_assert(d::find_family(nx::op::posr).value().code == 0x52);
  static_assert(d::family_position(nx::op::none) == d::no_family);
  static_assert(!d::find_family(nx::op::none));
}

TEST_CASE("nx: find_code finds what the table scan found, for every code byte") {
  int known = 0;
  for (unsigned c = 0; c < 256U; ++c) {
    const auto code = static_cast<std::uint8_t>(c);
    const auto got = d::find_code(code);
    const auto want = reference_find_code(code);
    INFO("code ", c);
    REQUIRE(got.has_value() == want.has_value());
    if (!got) {
      CHECK(got.error() == want.error());
      continue;
    }
    ++known;
    CHECK(got.value().f == want.value().f);
    CHECK(got.value().kind == want.value().kind);
  }
  CHECK(known > 16); // value, parameter and variable forms
  // COMPAX manual (002), Nx program records: 0x72 is POSR with a parameter, 0xD2 with a variable.
  static_assert(d::find_code(0x72).value().f.o == nx::op::posr);
  static_assert(d::find_code(0x72).value().kind == nx::arg_kind::parameter);
  static_assert(d::find_code(0xD2).value().kind == nx::arg_kind::variable);
}
