// DPQ SDO abort table mapped onto CiA 301 abort codes (manual 004, 3.3 "Interruption of an SDO
// transfer"). The manual prints bytes 4, 5 ("additional code"), 6 ("error code"), 7 ("error
// class") of the abort frame; read little-endian they are the 32-bit CiA 301 abort code.
#include <fieldcodec/dpq/sdo_abort.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <set>

namespace fc = fieldcodec;
namespace dpq = fieldcodec::dpq;
using fc::errc;

namespace {
constexpr dpq::abort_code A(std::uint32_t v) { return static_cast<dpq::abort_code>(v); }
} // namespace

static_assert(dpq::compose_abort_code(0x0011, 0x09, 0x06) == A(0x06090011U));
static_assert(dpq::find_sdo_abort(A(0x06020000U))->error() == errc::unknown_object);
static_assert(dpq::find_sdo_abort(A(0x08000000U)) == nullptr);

TEST_CASE("dpq sdo abort: the manual's 16 rows, byte by byte") {
  struct printed {
    std::uint8_t b4, b5, b6, b7;
    std::uint32_t cia;
  };
  // Columns as printed: additional code (two bytes), error code, error class.
  constexpr std::array<printed, 16> table{{
      {0x11, 0x0, 0x9, 0x6, 0x06090011}, // no sub
      {0x0, 0x0, 0x1, 0x6, 0x06010000},  // only reading or writing possible
      {0x31, 0x0, 0x9, 0x6, 0x06090031}, // value too great
      {0x32, 0x0, 0x9, 0x6, 0x06090032}, // value too small
      {0x10, 0x0, 0x7, 0x6, 0x06070010}, // data type not known
      {0x12, 0x0, 0x7, 0x6, 0x06070012}, // data length too great
      {0x13, 0x0, 0x7, 0x6, 0x06070013}, // data length too short
      {0x41, 0x0, 0x4, 0x6, 0x06040041}, // cannot be mapped
      {0x42, 0x0, 0x4, 0x6, 0x06040042}, // PDO too long
      {0x43, 0x0, 0x4, 0x6, 0x06040043}, // invalid value
      {0x0, 0x0, 0x3, 0x5, 0x05030000},  // toggle bit
      {0x0, 0x0, 0x2, 0x6, 0x06020000},  // object not available
      {0x21, 0x0, 0x0, 0x8, 0x08000021}, // internal error
      {0x22, 0x0, 0x0, 0x8, 0x08000022}, // service error
      {0x1, 0x0, 0x4, 0x5, 0x05040001},  // unknown service request
      {0x47, 0x0, 0x4, 0x6, 0x06040047}, // initialization error
  }};
  std::set<std::uint32_t> codes;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto &p = table[i];
    const auto &row = dpq::sdo_abort_table[i];
    const std::uint32_t le = std::uint32_t{p.b4} | (std::uint32_t{p.b5} << 8U) |
                             (std::uint32_t{p.b6} << 16U) | (std::uint32_t{p.b7} << 24U);
    CHECK(le == p.cia);
    CHECK(row.code == A(p.cia));
    CHECK(row.additional == (std::uint32_t{p.b4} | (std::uint32_t{p.b5} << 8U)));
    CHECK(row.error_code == p.b6);
    CHECK(row.error_class == p.b7);
    CHECK(dpq::compose_abort_code(row.additional, row.error_code, row.error_class) == A(p.cia));
    CHECK(dpq::find_sdo_abort(A(p.cia)) == &row);
    CHECK(!row.dpq_text.empty());
    CHECK(!row.cia_text().empty());
    codes.insert(p.cia);
  }
  CHECK(codes.size() == 16);
}

TEST_CASE("dpq sdo abort: texts and errc") {
  CHECK(dpq::describe_sdo_abort(A(0x06090011)) == "no such sub-index");
  CHECK(dpq::describe_sdo_abort(A(0x05030000)) == "toggle bit wrong");
  CHECK(dpq::describe_sdo_abort(A(0x08000000)).empty()); // CiA general error: not in the DPQ list
  CHECK(dpq::sdo_abort_errc(A(0x06010000)) == errc::access_denied);
  CHECK(dpq::sdo_abort_errc(A(0x06090031)) == errc::out_of_range);
  CHECK(dpq::sdo_abort_errc(A(0x06090032)) == errc::out_of_range);
  CHECK(dpq::sdo_abort_errc(A(0x06070010)) == errc::type_mismatch);
  CHECK(dpq::sdo_abort_errc(A(0x06070012)) == errc::too_long);
  CHECK(dpq::sdo_abort_errc(A(0x06070013)) == errc::bad_length);
  CHECK(dpq::sdo_abort_errc(A(0x05030000)) == errc::bad_toggle);
  CHECK(dpq::sdo_abort_errc(A(0x05040001)) == errc::unknown_command);
  CHECK(dpq::sdo_abort_errc(A(0x08000022)) == errc::bad_state);
  CHECK(dpq::sdo_abort_errc(A(0x06020000)) == errc::unknown_object);
  CHECK(dpq::sdo_abort_errc(A(0x12345678)) == errc::aborted);
}
