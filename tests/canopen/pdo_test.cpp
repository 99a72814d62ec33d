// PDO mapping entries, bit packing, mappings against dictionaries, communication parameters.
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat.hpp>
#include <fieldcodec/dictionaries/xenax_powerlink.hpp>

#include "doc_blocks.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace co = fieldcodec::canopen;
namespace pdo = fieldcodec::canopen::pdo;
namespace od = fieldcodec::od;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;
namespace xecat = fieldcodec::dictionaries::xenax_ethercat;
namespace xpl = fieldcodec::dictionaries::xenax_powerlink;
using fieldcodec::errc;
using pdo::mapping_entry;
using pdo::mapping_problem;

static_assert(pdo::mapping_value(0x6040, 0, 16) == 0x60400010U);
static_assert(mapping_entry::from_u32(0x60FE0120U) == mapping_entry{0x60FE, 1, 32});

// XENAX (003) 9.2.1: RxPDO 2 = controlword + target position, TxPDO 2 = statusword + actual
// position, checked at compile time against the CAN dictionary.
constexpr mapping_entry rx2_entries[] = {{0x6040, 0, 16}, {0x607A, 0, 32}};
constexpr auto rx2 = pdo::make_static_mapping(xcan::dictionary, pdo::direction::rpdo, rx2_entries);
static_assert(rx2.total_bits == 48);
static_assert(rx2.offsets[1] == 16);
static_assert(rx2.bytes() == 6);
static_assert(rx2.values()[0] == 0x60400010U && rx2.values()[1] == 0x607A0020U);
constexpr mapping_entry tx2_entries[] = {{0x6041, 0, 16}, {0x6064, 0, 32}};
constexpr auto tx2 = pdo::make_static_mapping(xcan::dictionary, pdo::direction::tpdo, tx2_entries);
static_assert(tx2.bytes() == 6);
static_assert(tx2.signs[0] == pdo::signedness::unsigned_ &&
              tx2.signs[1] == pdo::signedness::signed_);
static_assert(tx2.get(std::array<std::uint8_t, 6>{0x37, 0x12, 0xFE, 0xFF, 0xFF, 0xFF}, 1).value() ==
              -2);
// A length-only mapping with a bit field.
constexpr mapping_entry bits_entries[] = {{0x2000, 1, 1}, {0x2000, 2, 3}, {0x2000, 3, 12}};
constexpr auto bits = pdo::make_static_mapping(bits_entries);
static_assert(bits.total_bits == 16);
static_assert(bits.signs[1] == pdo::signedness::unknown);

// Mistakes do not compile. Each of these (checked by hand with g++ and clang++) stops the build
// with a diagnostic naming compile_error::pdo_mapping_<problem>:
//   constexpr mapping_entry bad1[] = {{0x6041, 0, 16}};  // statusword is read-only
//   constexpr auto m1 = pdo::make_static_mapping(xcan::dictionary, pdo::direction::rpdo, bad1);
//   constexpr mapping_entry bad2[] = {{0x607A, 0, 16}};  // INTEGER32 mapped as 16 bits
//   constexpr mapping_entry bad3[] = {{0x6064, 0, 32}, {0x607A, 0, 32}, {0x6040, 0, 16}}; // 80
//   bits constexpr mapping_entry bad4[] = {{0x6085, 0, 32}};  // quick-stop deceleration: not
//   mappable

TEST_CASE("pack and unpack at arbitrary bit offsets") {
  std::array<std::uint8_t, 8> p{};
  CHECK(pdo::pack(p, 0, 16, 0x1237).has_value());
  CHECK(p[0] == 0x37);
  CHECK(p[1] == 0x12);
  CHECK(pdo::pack(p, 16, 32, 0xFFFFFFFFU).has_value());
  CHECK(p == std::array<std::uint8_t, 8>{0x37, 0x12, 0xFF, 0xFF, 0xFF, 0xFF, 0, 0});
  CHECK(pdo::unpack_signed(p, 16, 32).value() == -1);
  // a 3-bit field at bit 5 crosses a byte boundary
  std::array<std::uint8_t, 2> q{};
  CHECK(pdo::pack(q, 5, 3, 0b101).has_value());
  CHECK(q[0] == 0b1010'0000);
  CHECK(pdo::pack(q, 6, 4, 0b1111).has_value());
  CHECK(q[0] == 0b1110'0000);
  CHECK(q[1] == 0b0000'0011);
  CHECK(pdo::unpack(q, 6, 4).value() == 0b1111);
  CHECK(pdo::unpack(q, 5, 1).value() == 1);
  // errors
  CHECK(pdo::pack(q, 0, 0, 0) == errc::bad_length);
  CHECK(pdo::pack(q, 0, 65, 0) == errc::bad_length);
  CHECK(pdo::pack(q, 0, 3, 8) == errc::overflow);
  CHECK(pdo::pack(q, 10, 7, 0) == errc::buffer_too_small);
  CHECK(pdo::unpack(q, 10, 7) == errc::truncated);
  CHECK(pdo::pack_signed(q, 0, 4, -8).has_value());
  CHECK(pdo::unpack_signed(q, 0, 4).value() == -8);
  CHECK(pdo::pack_signed(q, 0, 4, -9) == errc::overflow);
  CHECK(pdo::pack_signed(q, 0, 4, 8) == errc::overflow);
  std::array<std::uint8_t, 8> full{};
  CHECK(pdo::pack(full, 0, 64, 0x0123456789ABCDEFU).has_value());
  CHECK(pdo::unpack(full, 0, 64).value() == 0x0123456789ABCDEFU);
  CHECK(pdo::pack_signed(full, 0, 64, INT64_MIN).has_value());
  CHECK(pdo::unpack_signed(full, 0, 64).value() == INT64_MIN);
}

TEST_CASE("pack/unpack round trip for every offset and length") {
  for (std::size_t len = 1; len <= 64; ++len) {
    for (std::size_t off = 0; off + len <= 96; off += 5) {
      std::array<std::uint8_t, 12> p{};
      p.fill(0xA5);
      const auto before = p;
      const std::uint64_t v =
          (len == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << len) - 1U) & 0x9E3779B97F4A7C15U;
      REQUIRE(pdo::pack(p, off, len, v).has_value());
      REQUIRE(pdo::unpack(p, off, len).value() == v);
      // bits outside the field are untouched
      for (std::size_t k = 0; k < 96; ++k) {
        if (k >= off && k < off + len) continue;
        REQUIRE(((p[k / 8] >> (k % 8)) & 1) == ((before[k / 8] >> (k % 8)) & 1));
      }
      const std::int64_t s = len == 64 ? INT64_MIN + 5 : -(std::int64_t{1} << (len - 1));
      REQUIRE(pdo::pack_signed(p, off, len, s).has_value());
      REQUIRE(pdo::unpack_signed(p, off, len).value() == s);
    }
  }
}

TEST_CASE("copy_bits moves the bits pack and unpack move, and no others") {
  // from bit `from` of a source to bit `to` of a destination: the destination's field holds what
  // unpack reads at the source, every other destination bit is untouched
  std::array<std::uint8_t, 9> src{};
  for (std::size_t k = 0; k < src.size(); ++k)
    src[k] = static_cast<std::uint8_t>(0x3C ^ (k * 0x47));
  for (std::size_t len = 1; len <= 64; ++len) {
    for (std::size_t from = 0; from + len <= 72; from += 3) {
      for (std::size_t to = 0; to + len <= 72; to += 7) {
        std::array<std::uint8_t, 9> dst{};
        dst.fill(0x5A);
        const auto before = dst;
        REQUIRE(pdo::copy_bits(src, from, dst, to, len));
        REQUIRE(pdo::unpack(dst, to, len).value() == pdo::unpack(src, from, len).value());
        for (std::size_t k = 0; k < 72; ++k) {
          if (k >= to && k < to + len) continue;
          REQUIRE(((dst[k / 8] >> (k % 8)) & 1) == ((before[k / 8] >> (k % 8)) & 1));
        }
      }
    }
  }
  // a range beyond either buffer: false, nothing written
  std::array<std::uint8_t, 2> small{0x11, 0x22};
  CHECK_FALSE(pdo::copy_bits(src, 70, small, 0, 3));
  CHECK_FALSE(pdo::copy_bits(src, 0, small, 10, 7));
  CHECK(small == std::array<std::uint8_t, 2>{0x11, 0x22});
  CHECK(pdo::copy_bits(src, 0, small, 9, 7));
  CHECK(pdo::copy_bits(src, 0, small, 0, 0));
}

TEST_CASE("XENAX CAN RxPDO 2 and TxPDO 2 byte layout") {
  // derived from 9.2.1 (l. 2558-2596): RPDO2 (0x301 on node 1) controlword 0x1F, target 1000
  std::array<std::uint8_t, 8> p{};
  CHECK(rx2.set(p, 0, 0x001F).has_value());
  CHECK(rx2.set(p, 1, 1000).has_value());
  auto f = pdo::to_frame({0x301, true, true}, std::span(p).first(rx2.bytes())).value();
  CHECK(f == co::make_frame(0x301, {0x1F, 0x00, 0xE8, 0x03, 0x00, 0x00}).value());
  // negative target (INTEGER32): any integer type, checked against the object's type
  CHECK(rx2.set(p, 1, std::int8_t{-2}).has_value());
  CHECK(rx2.get(p, 1).value() == -2);
  CHECK(rx2.get_signed(p, 1).value() == -2);
  CHECK(rx2.set(p, 1, std::int64_t{-2147483648}).has_value());
  CHECK(rx2.set(p, 1, std::int64_t{-2147483649}) == errc::overflow);
  CHECK(rx2.set(p, 1, 0x80000000U) == errc::overflow); // above INTEGER32's maximum: no wrap
  CHECK(rx2.set(p, 1, static_cast<std::uint64_t>(std::int64_t{-2})) == errc::overflow);
  // the controlword is UNSIGNED16: -1 and 65536 are refused, 65535 fits
  CHECK(rx2.set(p, 0, -1) == errc::overflow);
  CHECK(rx2.set(p, 0, 0x10000L) == errc::overflow);
  CHECK(rx2.set(p, 0, std::uint16_t{0xFFFF}).has_value());
  CHECK(rx2.set(p, 2, 0) == errc::invalid_argument);
  // TPDO2 statusword 0x1237, actual position -1: the position comes out signed (issue 13)
  const std::array<std::uint8_t, 6> t{0x37, 0x12, 0xFF, 0xFF, 0xFF, 0xFF};
  CHECK(tx2.get(t, 0).value() == 0x1237);
  CHECK(tx2.get(t, 1).value() == -1);
  CHECK(tx2.get<std::int32_t>(t, 1).value() == -1);
  CHECK(tx2.get<std::uint32_t>(t, 1) == errc::overflow);
  CHECK(tx2.get<std::int8_t>(t, 0) == errc::overflow);
  CHECK(tx2.get<std::uint16_t>(t, 0).value() == 0x1237);
  CHECK(tx2.get_signed(t, 1).value() == -1);
  CHECK(tx2.get(std::span(t).first(4), 1) == errc::truncated);
  CHECK(tx2.get(t, 2) == errc::invalid_argument);
  CHECK(pdo::to_frame({0x181, false, true}, t) == errc::bad_state);
}

TEST_CASE("run-time mapping checks against the XENAX dictionaries") {
  const auto &d = xcan::dictionary;
  using pdo::direction;
  const mapping_entry statusword_rx[] = {{0x6041, 0, 16}};
  CHECK(pdo::check_mapping(d, direction::rpdo, statusword_rx).problem ==
        mapping_problem::no_access);
  CHECK(pdo::validate(d, direction::rpdo, statusword_rx) == errc::access_denied);
  const mapping_entry quick_stop_dec[] = {{0x6085, 0, 32}};
  CHECK(pdo::check_mapping(d, direction::tpdo, quick_stop_dec).problem ==
        mapping_problem::not_mappable);
  const mapping_entry wrong_len[] = {{0x6040, 0, 16}, {0x607A, 0, 16}};
  auto r = pdo::check_mapping(d, direction::rpdo, wrong_len);
  CHECK(r.problem == mapping_problem::length_mismatch);
  CHECK(r.entry == 1);
  const mapping_entry missing[] = {{0x6040, 0, 16}, {0x4711, 0, 16}};
  CHECK(pdo::validate(d, direction::rpdo, missing) == errc::unknown_object);
  const mapping_entry zero[] = {{0x6040, 0, 0}};
  CHECK(pdo::validate(d, direction::rpdo, zero) == errc::bad_length);
  const mapping_entry too_long[] = {{0x6040, 0, 16}, {0x607A, 0, 32}, {0x6081, 0, 32}};
  CHECK(pdo::validate(d, direction::rpdo, too_long) == errc::too_long);
  CHECK(pdo::validate(d, direction::rpdo, too_long, 80).value() == 80);
  // dummy entries (data type indices) reserve space
  const mapping_entry dummy[] = {{0x0006, 0, 16}, {0x6041, 0, 16}, {0x0001, 0, 1}};
  CHECK(pdo::validate(d, direction::tpdo, dummy).value() == 33);
  const mapping_entry bad_dummy[] = {{0x0006, 0, 8}};
  CHECK(pdo::validate(d, direction::tpdo, bad_dummy) == errc::bad_length);
  std::vector<mapping_entry> many(65, mapping_entry{0x0005, 0, 8});
  CHECK(pdo::check_mapping(d, direction::tpdo, many, 1000).problem ==
        mapping_problem::too_many_entries);
  for (auto p :
       {mapping_problem::none, mapping_problem::zero_length, mapping_problem::no_object,
        mapping_problem::not_mappable, mapping_problem::no_access, mapping_problem::length_mismatch,
        mapping_problem::too_long, mapping_problem::too_many_entries, mapping_problem::overlap}) {
    CHECK(!pdo::to_string(p).empty());
  }
}

namespace {
// Every mapping object (1600h..17FFh, 1A00h..1BFFh) of a dictionary: its default mapping is
// read with the bus's entry format and checked against the dictionary; returns how many.
int check_default_mappings(const od::dictionary &d, bool powerlink, std::size_t max_bits) {
  int checked = 0;
  for (std::uint16_t idx = 0x1600; idx <= 0x1BFF; ++idx) {
    if (d.object(idx).empty()) continue;
    if (idx >= 0x1800 && idx < 0x1A00) continue;
    const auto dir = idx < 0x1800 ? pdo::direction::rpdo : pdo::direction::tpdo;
    CAPTURE(idx);
    if (powerlink) {
      const auto m = pdo::default_powerlink_mapping(d, idx);
      REQUIRE(m.has_value());
      CHECK(pdo::check_mapping(d, dir, m.value().entries(), max_bits).ok());
      CHECK(pdo::default_mapping(d, idx) == errc::type_mismatch);
    } else {
      const auto m = pdo::default_mapping(d, idx);
      REQUIRE(m.has_value());
      const auto r = pdo::check_mapping(d, dir, m.value().entries(), max_bits);
      CHECK_MESSAGE(r.ok(), "entry ", r.entry, ": ", pdo::to_string(r.problem));
      CHECK(pdo::make_mapping(d, dir, m.value().entries(), max_bits).has_value());
      CHECK(pdo::default_powerlink_mapping(d, idx) == errc::type_mismatch);
    }
    ++checked;
  }
  return checked;
}
} // namespace

TEST_CASE("every default mapping of the XENAX dictionaries is valid for its bus") {
  // CAN: 1600h, 1601h, 1610h-1617h, 1A00h, 1A01h, 1A10h-1A17h (issue 12 #6: all sixteen PDOs
  // 17-24 have a mapping object); EtherCAT: 7 Rx + 6 Tx; POWERLINK: 1600h, 1A00h.
  CHECK(check_default_mappings(xcan::dictionary, false, pdo::can_max_bits) == 20);
  CHECK(check_default_mappings(xecat::dictionary, false, 8 * 1024) == 13);
  CHECK(check_default_mappings(xpl::dictionary, true, 8 * 1490) == 2);
}

TEST_CASE("every PDO communication parameter has its mapping parameter (issue 12 #6)") {
  // CiA 301: a supported PDO has both; python canopen's RemoteNode raises KeyError otherwise.
  for (const od::dictionary *d : {&xcan::dictionary, &xecat::dictionary, &xpl::dictionary}) {
    for (std::uint16_t idx = 0x1400; idx <= 0x15FF; ++idx) {
      CAPTURE(idx);
      if (!d->object(idx).empty())
        CHECK(!d->object(static_cast<std::uint16_t>(idx + 0x200)).empty());
    }
    for (std::uint16_t idx = 0x1800; idx <= 0x19FF; ++idx) {
      CAPTURE(idx);
      if (!d->object(idx).empty())
        CHECK(!d->object(static_cast<std::uint16_t>(idx + 0x200)).empty());
    }
  }
}

TEST_CASE("default mappings read from the XENAX dictionaries (manual 9.1, 7.1, 8.1)") {
  // CAN TxPDO 2 (9.1.16, l. 2505-2510): statusword 0x60410010, actual position 0x60640020
  constexpr auto tx2_default = pdo::default_mapping(xcan::dictionary, 0x1A01);
  static_assert(tx2_default.value().size() == 2);
  static_assert(tx2_default.value()[0] == mapping_entry{0x6041, 0, 16});
  static_assert(tx2_default.value()[1] == mapping_entry{0x6064, 0, 32});
  // CAN RxPDO 17 (9.1.6, l. 2417): digital outputs 0x60FE0120
  const auto rx17 = pdo::default_mapping(xcan::dictionary, 0x1610).value();
  REQUIRE(rx17.size() == 1);
  CHECK(rx17[0] == mapping_entry{0x60FE, 1, 32});
  // The added mapping objects of PDO 22/23 and 18/19/22 map nothing by default (docs/xenax.md)
  for (const std::uint16_t idx :
       {std::uint16_t{0x1615}, std::uint16_t{0x1616}, std::uint16_t{0x1A11}, std::uint16_t{0x1A12},
        std::uint16_t{0x1A15}}) {
    CAPTURE(idx);
    const auto m = pdo::default_mapping(xcan::dictionary, idx);
    REQUIRE(m.has_value());
    CHECK(m.value().empty());
    CHECK(xcan::dictionary.object(idx).size() == 3);
  }
  // EtherCAT RxPDO 18 (1612h, 7.1.2): nine entries, 34 bytes
  const auto ecat = pdo::default_mapping(xecat::dictionary, 0x1612).value();
  CHECK(ecat.size() == 9);
  CHECK(ecat[0] == mapping_entry{0x6040, 0, 16});
  // POWERLINK 1600h / 1A00h (8.1.2, 8.1.4): eight UNSIGNED64 entries, none mapped by default
  const auto pl = pdo::default_powerlink_mapping(xpl::dictionary, 0x1600);
  REQUIRE(pl.has_value());
  CHECK(pl.value().empty());
  CHECK(pdo::default_powerlink_mapping(xpl::dictionary, 0x1A00).value().empty());
  // errors
  CHECK(pdo::default_mapping(xcan::dictionary, 0x1602) == errc::unknown_object);
  CHECK(pdo::default_mapping(xcan::dictionary, 0x1000) == errc::type_mismatch);
  CHECK(pdo::default_mapping<1>(xcan::dictionary, 0x1A01) == errc::too_long);
  CHECK(pdo::default_mapping<2>(xcan::dictionary, 0x1A01).value().size() == 2);
}

TEST_CASE("a mapping built from a dictionary reads and writes with each object's signedness") {
  // Issue 13: CAN TxPDO 20 (1A13h, 9.1.18): following error 60F4h (INTEGER32) + process status
  // register 2006h (INTEGER32, 3.3.7). A following error of -1 must come out as -1, not
  // 4294967295.
  const auto list = pdo::default_mapping(xcan::dictionary, 0x1A13).value();
  const auto m = pdo::make_mapping(xcan::dictionary, pdo::direction::tpdo, list.entries()).value();
  REQUIRE(m.size() == 2);
  CHECK(m[0] == pdo::slot{0x60F4, 0, pdo::signedness::signed_, 0, 32});
  CHECK(m[1] == pdo::slot{0x2006, 0, pdo::signedness::signed_, 32, 32});
  CHECK(m.bytes() == 8);
  // following error -1, PSR = ERROR | IN_POSITION (bits 0 and 3)
  const std::array<std::uint8_t, 8> frame{0xFF, 0xFF, 0xFF, 0xFF, 0x09, 0x00, 0x00, 0x00};
  std::array<std::int64_t, 2> values{};
  REQUIRE(m.unpack_all(frame, values).has_value());
  CHECK(values[0] == -1);
  CHECK(values[1] == 9);
  std::array<std::uint64_t, 2> unsigned_values{};
  CHECK(m.unpack_all(frame, unsigned_values) == errc::overflow); // -1 has no uint64 form
  CHECK(m.get<std::int32_t>(frame, 0).value() == -1);
  CHECK(m.get<std::uint32_t>(frame, 0) == errc::overflow);
  CHECK(m.get<std::uint8_t>(frame, 1).value() == 9U);
  CHECK(m.get(std::span(frame).first(7), 1) == errc::truncated);
  CHECK(m.get(frame, 2) == errc::invalid_argument);
  // the other way: any integer type, checked against the object
  std::array<std::uint8_t, 8> out{};
  CHECK(m.pack_all(std::array<std::int64_t, 2>{-2, 0x0000'0004}, out).value() == 8);
  CHECK(out == std::array<std::uint8_t, 8>{0xFE, 0xFF, 0xFF, 0xFF, 0x04, 0x00, 0x00, 0x00});
  CHECK(m.pack_all(std::array<std::int64_t, 2>{0, 0x8000'0000}, out) == errc::overflow);
  CHECK(m.pack_all(std::array<std::uint64_t, 2>{0x8000'0000U, 0}, out) == errc::overflow);
  CHECK(m.pack_all(std::array<std::int64_t, 1>{0}, out) == errc::bad_length);
  CHECK(m.set(out, 0, -2147483648LL).has_value());
  CHECK(m.set(out, 1, 0x7FFF'FFFFULL).has_value());
  CHECK(m.set(out, 1, 0xFFFF'FFFFULL) == errc::overflow);
  CHECK(m.set(out, 0, short{-300}).has_value());
  CHECK(m.get(out, 0).value() == -300);
  std::array<std::int64_t, 1> small{};
  CHECK(m.unpack_all(frame, small) == errc::bad_length);
  CHECK(m.set(std::span(out).first(6), 1, 1) == errc::buffer_too_small);
  // a mapping that the dictionary refuses is not built
  const mapping_entry statusword_rx[] = {{0x6041, 0, 16}};
  CHECK(pdo::make_mapping(xcan::dictionary, pdo::direction::rpdo, statusword_rx) ==
        errc::access_denied);
  const mapping_entry five[] = {{0x6040, 0, 16}, {0x6040, 0, 16}, {0x6040, 0, 16}};
  CHECK(pdo::make_mapping<2>(xcan::dictionary, pdo::direction::rpdo, five) == errc::too_long);
  // a dummy entry takes its data type's signedness (0x0003 = INTEGER16)
  const mapping_entry dummy[] = {{0x0003, 0, 16}, {0x6041, 0, 16}};
  const auto md = pdo::make_mapping(xcan::dictionary, pdo::direction::tpdo, dummy).value();
  CHECK(md[0].sign == pdo::signedness::signed_);
}

TEST_CASE("POWERLINK 64-bit mapping entries") {
  // EPSG DS 301 mapping entry (UNSIGNED64): length bits 48-63, offset 32-47, reserved 24-31,
  // sub-index 16-23, index 0-15. Controlword 6040h at bit 0, 16 bits; target position 607Ah
  // at bit 16, 32 bits.
  static_assert(pdo::powerlink_mapping_value(0x6040, 0, 0, 16) == 0x0010'0000'0000'6040U);
  static_assert(pdo::powerlink_mapping_value(0x607A, 0, 16, 32) == 0x0020'0010'0000'607AU);
  static_assert(pdo::powerlink_mapping_entry::from_u64(0x0008'0030'0001'60FEU).value() ==
                pdo::powerlink_mapping_entry{0x60FE, 1, 48, 8});
  CHECK(pdo::powerlink_mapping_entry::from_u64(0x0010'0000'0100'6040U) == errc::out_of_range);
  CHECK(pdo::powerlink_mapping_entry::from_u64(0x0010'0000'8000'6040U) == errc::out_of_range);
  CHECK(pdo::powerlink_mapping_entry::from_u64(0).value().is_empty());
  CHECK(!pdo::powerlink_mapping_entry{0x6040, 0, 0, 16}.is_empty());
  for (std::uint64_t v : {0x0010'0000'0000'6040ULL, 0xFFFF'FFFF'00FF'FFFFULL, 0x1ULL}) {
    CHECK(pdo::powerlink_mapping_entry::from_u64(v).value().to_u64() == v);
  }
}

TEST_CASE("a POWERLINK RPDO of the XENAX (8.1.2) packs at the offsets its entries name") {
  using pdo::powerlink_mapping_entry;
  const auto &d = xpl::dictionary;
  // 1600h sub 1..8 are an ARRAY of UNSIGNED64 (issue 12 #10)
  REQUIRE(d.object(0x1600).size() == 9);
  CHECK(d.object(0x1600)[1].object == od::object_code::array);
  CHECK(d.object(0x1600)[1].type == od::data_type::unsigned64);
  CHECK(d.object(0x1A00)[8].object == od::object_code::array);
  // The values a master writes to 1600h sub 1..3 (out of order on purpose: POWERLINK entries
  // carry their offset): modes of operation at byte 6, controlword at 0, target at 2.
  const std::array<std::uint64_t, 3> written{0x0008'0030'0000'6060U, 0x0010'0000'0000'6040U,
                                             0x0020'0010'0000'607AU};
  std::array<powerlink_mapping_entry, 3> entries{};
  for (std::size_t i = 0; i < 3; ++i) {
    entries[i] = powerlink_mapping_entry::from_u64(written[i]).value();
  }
  const std::size_t max_bits = 8 * 1490;
  CHECK(pdo::validate(d, pdo::direction::rpdo, entries, max_bits).value() == 56);
  const auto m = pdo::make_mapping(d, pdo::direction::rpdo, entries, max_bits).value();
  CHECK(m.bytes() == 7);
  // jog mode (-1, 5.4.1), controlword 0x1F, target -1000
  std::array<std::uint8_t, 7> frame{};
  CHECK(m.pack_all(std::array<std::int64_t, 3>{-1, 0x1F, -1000}, frame).value() == 7);
  CHECK(frame == std::array<std::uint8_t, 7>{0x1F, 0x00, 0x18, 0xFC, 0xFF, 0xFF, 0xFF});
  std::array<std::int64_t, 3> back{};
  REQUIRE(m.unpack_all(frame, back).has_value());
  CHECK(back == std::array<std::int64_t, 3>{-1, 0x1F, -1000});
  CHECK(m.set(frame, 0, 128) == errc::overflow); // INTEGER8
  // empty entries are skipped; gaps stay as the buffer had them
  const std::array<powerlink_mapping_entry, 3> gap{powerlink_mapping_entry{0x6040, 0, 8, 16},
                                                   powerlink_mapping_entry{},
                                                   powerlink_mapping_entry{0x6060, 0, 32, 8}};
  const auto g = pdo::make_mapping(d, pdo::direction::rpdo, gap, max_bits).value();
  CHECK(g.size() == 2);
  CHECK(g.total_bits() == 40);
  std::array<std::uint8_t, 5> gf{0xAA, 0, 0, 0xBB, 0};
  CHECK(g.pack_all(std::array<std::int64_t, 2>{0x0F, 8}, gf).value() == 5);
  CHECK(gf == std::array<std::uint8_t, 5>{0xAA, 0x0F, 0x00, 0xBB, 0x08});
  // mistakes
  const std::array<powerlink_mapping_entry, 2> overlap{powerlink_mapping_entry{0x6040, 0, 0, 16},
                                                       powerlink_mapping_entry{0x6060, 0, 8, 8}};
  auto r = pdo::check_mapping(d, pdo::direction::rpdo, overlap, max_bits);
  CHECK(r.problem == mapping_problem::overlap);
  CHECK(r.entry == 1);
  CHECK(pdo::validate(d, pdo::direction::rpdo, overlap, max_bits) == errc::invalid_argument);
  CHECK(pdo::validate(d, pdo::direction::rpdo, entries, 48) == errc::too_long);
  const std::array<powerlink_mapping_entry, 1> statusword{
      powerlink_mapping_entry{0x6041, 0, 0, 16}};
  CHECK(pdo::validate(d, pdo::direction::rpdo, statusword, max_bits) == errc::access_denied);
  CHECK(pdo::make_mapping(d, pdo::direction::tpdo, statusword, max_bits).has_value());
  const std::array<powerlink_mapping_entry, 1> wrong_len{powerlink_mapping_entry{0x6040, 0, 0, 32}};
  CHECK(pdo::validate(d, pdo::direction::rpdo, wrong_len, max_bits) == errc::bad_length);
  const std::array<powerlink_mapping_entry, 1> no_object{powerlink_mapping_entry{0x4711, 0, 0, 8}};
  CHECK(pdo::validate(d, pdo::direction::rpdo, no_object, max_bits) == errc::unknown_object);
  std::vector<powerlink_mapping_entry> many(255, powerlink_mapping_entry{0x0005, 0, 0, 8});
  CHECK(pdo::check_mapping(d, pdo::direction::tpdo, many, max_bits).problem ==
        mapping_problem::too_many_entries);
  CHECK(pdo::make_mapping<2>(d, pdo::direction::rpdo, entries, max_bits) == errc::too_long);
}

TEST_CASE("EtherCAT mappings are longer than a CAN frame") {
  const auto &d = xecat::dictionary;
  const auto list = pdo::default_mapping(d, 0x1612); // 34 bytes
  REQUIRE(list.has_value());
  const auto m = list.value().entries();
  REQUIRE(!m.empty());
  auto r = pdo::check_mapping(d, pdo::direction::rpdo, m);
  CHECK(r.problem == mapping_problem::too_long);
  auto ok = pdo::check_mapping(d, pdo::direction::rpdo, m, 8 * 1024);
  CHECK(ok.ok());
  CHECK(ok.total_bits == 34 * 8);
  // pack and unpack the whole 34-byte PDO
  std::vector<std::uint64_t> raws(m.size());
  for (std::size_t i = 0; i < raws.size(); ++i) raws[i] = i + 1;
  std::array<std::uint8_t, 34> bytes{};
  CHECK(pdo::pack_all(m, raws, bytes).value() == 34);
  std::vector<std::uint64_t> back(m.size());
  CHECK(pdo::unpack_all(m, bytes, back).has_value());
  CHECK(back == raws);
  CHECK(pdo::unpack_all(m, std::span(bytes).first(33), back) == errc::truncated);
  CHECK(pdo::pack_all(m, std::span(raws).first(2), bytes) == errc::bad_length);
  raws[0] = 0x10000; // controlword does not fit 16 bits
  CHECK(pdo::pack_all(m, raws, bytes) == errc::overflow);
  // Without a dictionary a uint64 is never a negative number (issue 13: no wrap) ...
  raws[0] = static_cast<std::uint64_t>(std::int64_t{-1});
  CHECK(pdo::pack_all(m, raws, bytes) == errc::overflow);
  // ... but an int64 -1 fits 16 bits as two's complement
  std::vector<std::int64_t> signed_raws(m.size(), 1);
  signed_raws[0] = -1;
  CHECK(pdo::pack_all(m, signed_raws, bytes).value() == 34);
  CHECK(bytes[0] == 0xFF);
  CHECK(bytes[1] == 0xFF);
  signed_raws[0] = -32769; // below the 16-bit two's complement range
  CHECK(pdo::pack_all(m, signed_raws, bytes) == errc::overflow);
}

TEST_CASE("communication parameters") {
  CHECK(pdo::encode_cob_id({0x181, true, true}).value() == 0x181U);
  CHECK(pdo::encode_cob_id({0x181, false, true}).value() == 0x80000181U);
  CHECK(pdo::encode_cob_id({0x181, true, false}).value() == 0x40000181U);
  CHECK(pdo::encode_cob_id({0x800, true, true}) == errc::invalid_argument);
  CHECK(pdo::decode_cob_id(0x80000000U).value() == pdo::cob_id_param{0, false, true});
  CHECK(pdo::decode_cob_id(0xC0000281U).value() == pdo::cob_id_param{0x281, false, false});
  CHECK(pdo::decode_cob_id(0x20000181U) == errc::out_of_range);
  CHECK(pdo::decode_cob_id(0x00000800U) == errc::out_of_range);
  using pdo::transmission;
  CHECK(pdo::classify_transmission(0) == transmission::synchronous_acyclic);
  CHECK(pdo::classify_transmission(1) == transmission::synchronous_cyclic);
  CHECK(pdo::classify_transmission(240) == transmission::synchronous_cyclic);
  CHECK(pdo::classify_transmission(241) == transmission::reserved);
  CHECK(pdo::classify_transmission(251) == transmission::reserved);
  CHECK(pdo::classify_transmission(252) == transmission::rtr_synchronous);
  CHECK(pdo::classify_transmission(253) == transmission::rtr_event);
  CHECK(pdo::classify_transmission(254) == transmission::event_manufacturer);
  CHECK(pdo::classify_transmission(255) == transmission::event_profile);
  pdo::comm_params p{{0x185, true, true}, 0xFF, 10, 100, 0};
  CHECK(p.inhibit_us() == 1000);
  CHECK(pdo::check(p, pdo::direction::tpdo).has_value());
  p.transmission_type = 252;
  CHECK(pdo::check(p, pdo::direction::tpdo).has_value());
  CHECK(pdo::check(p, pdo::direction::rpdo) == errc::out_of_range);
  p.transmission_type = 245;
  CHECK(pdo::check(p, pdo::direction::tpdo) == errc::out_of_range);
  p.transmission_type = 1;
  p.sync_start = 241;
  CHECK(pdo::check(p, pdo::direction::tpdo) == errc::out_of_range);
}

TEST_CASE("64-bit and 1-bit fields keep their full range with their signedness") {
  pdo::mapping<4> m;
  REQUIRE(m.add({0x1111, 0, pdo::signedness::unsigned_, 0, 64}).has_value());
  REQUIRE(m.add({0x2222, 0, pdo::signedness::signed_, 64, 64}).has_value());
  REQUIRE(m.add({0x3333, 0, pdo::signedness::unsigned_, 128, 1}).has_value());
  REQUIRE(m.add({0x4444, 0, pdo::signedness::signed_, 129, 3}).has_value());
  CHECK(m.bytes() == 17);
  std::array<std::uint8_t, 17> b{};
  CHECK(m.set(b, 0, ~std::uint64_t{0}).has_value());
  CHECK(m.get<std::uint64_t>(b, 0).value() == ~std::uint64_t{0});
  CHECK(m.get(b, 0) == errc::overflow); // above INT64_MAX has no int64 form
  CHECK(m.set(b, 0, -1) == errc::overflow);
  CHECK(m.set(b, 1, INT64_MIN).has_value());
  CHECK(m.get(b, 1).value() == INT64_MIN);
  CHECK(m.get<std::uint64_t>(b, 1) == errc::overflow);
  CHECK(m.set(b, 1, ~std::uint64_t{0}) == errc::overflow);
  CHECK(m.set(b, 2, 1).has_value());
  CHECK(m.set(b, 2, 2) == errc::overflow);
  CHECK(m.get(b, 2).value() == 1);
  CHECK(m.set(b, 3, -4).has_value());
  CHECK(m.set(b, 3, 4) == errc::overflow);
  CHECK(m.set(b, 3, -5) == errc::overflow);
  CHECK(m.get(b, 3).value() == -4);
  CHECK(m.get<std::uint8_t>(b, 3) == errc::overflow);
  CHECK(b[16] == 0b1001);
  CHECK(m.add({0x5555, 0, pdo::signedness::unknown, 132, 8}) == errc::too_long); // full
  CHECK(m.size() == 4);
}

TEST_CASE("docs/canopen.md, PDO: the example compiles and says what it does") {
  namespace pdo = fieldcodec::canopen::pdo;
  namespace xcan = fieldcodec::dictionaries::xenax_canopen;

  const auto entries = pdo::default_mapping(xcan::dictionary, 0x1A13).value();
  const auto tpdo20 = pdo::make_mapping(xcan::dictionary, pdo::direction::tpdo, entries.entries());
  const std::array<std::uint8_t, 8> frame{0xFF, 0xFF, 0xFF, 0xFF, 0x09, 0x00, 0x00, 0x00};
  std::array<std::int64_t, 2> values{};
  const auto unpacked = tpdo20.value().unpack_all(frame, values);
  // unpacked.has_value(), values == {-1, 9}: a following error of -1, not 4294967295

  CHECK(unpacked.has_value());
  CHECK(values == std::array<std::int64_t, 2>{-1, 9});
  // the block in the document is this one
  int found = 0;
  for (const auto &block :
       doc_blocks::cpp_blocks(doc_blocks::beside(__FILE__, "../../docs/canopen.md"))) {
    if (block.find("pdo::default_mapping") == std::string::npos) continue;
    CHECK(doc_blocks::holds(doc_blocks::read_file(__FILE__), block));
    ++found;
  }
  CHECK(found == 1);
}
