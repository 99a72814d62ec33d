// The code paths a build for size takes (-Os, firmware: __OPTIMIZE_SIZE__): test_size_paths is
// built with -Os (tests/CMakeLists.txt) so that the host suite runs them. store_unsigned /
// load_unsigned with a width known only at run time take one compact loop there instead of the
// unrolled body of each width, and pdo::pack / unpack take their bit loop for whole bytes too;
// the bytes and errors must be those of the other paths: compared here with a plain reference,
// for every width, both byte orders and random values (the unrolled paths have their own tests
// in the Debug build of the suite).
#include "xorshift.hpp"

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/core/bytes.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

#if !defined(__OPTIMIZE_SIZE__)
#error "tests/size_paths/ must be compiled with -Os (tests/CMakeLists.txt)"
#endif

namespace fc = fieldcodec;
namespace pdo = fieldcodec::canopen::pdo;
using fc::byte_order;
using fc::errc;

namespace {
// a width the compiler cannot see: the run-time path
volatile std::size_t hidden = 0;
std::size_t opaque(std::size_t v) {
  hidden = v;
  return hidden;
}
} // namespace

TEST_CASE("-Os: store_unsigned and load_unsigned with a run-time width") {
  fc::test::xorshift rng(0x05B17E5);
  for (int round = 0; round < 2000; ++round) {
    const std::size_t w = opaque(1U + rng.next() % 8U);
    const auto order = (round & 1) != 0 ? byte_order::big : byte_order::little;
    const std::uint64_t mask = w == 8U ? ~std::uint64_t{0} : (std::uint64_t{1} << (8U * w)) - 1U;
    const std::uint64_t v = rng.next() & mask;
    std::array<std::uint8_t, 9> out{};
    out[w] = 0xAA; // the byte after the field stays
    REQUIRE(fc::store_unsigned(out, w, v, order));
    for (std::size_t i = 0; i < w; ++i) {
      const std::size_t at = order == byte_order::little ? i : w - 1U - i;
      CHECK(out[at] == static_cast<std::uint8_t>(v >> (8U * i)));
    }
    CHECK(out[w] == 0xAA);
    CHECK(fc::load_unsigned(out, w, order).value() == v);
    if (w < 8U) CHECK(fc::store_unsigned(out, w, mask + 1U, order).is(errc::overflow));
    CHECK(fc::store_unsigned(std::span<std::uint8_t>(out).first(w - 1U), w, v, order)
              .is(errc::buffer_too_small));
  }
  std::array<std::uint8_t, 8> out{};
  CHECK(fc::store_unsigned(out, opaque(0), 0, byte_order::little).is(errc::bad_length));
  CHECK(fc::store_unsigned(out, opaque(9), 0, byte_order::little).is(errc::bad_length));
}

TEST_CASE("-Os: pdo::pack and unpack at whole bytes and between them") {
  fc::test::xorshift rng(0x9D0F00D);
  for (int round = 0; round < 2000; ++round) {
    const std::size_t length = opaque(1U + rng.next() % 64U);
    // every other round byte-aligned (the path a normal build stores with store_unsigned)
    const std::size_t offset = opaque((round & 1) != 0 ? 8U * (rng.next() % 4U) : rng.next() % 32U);
    const bool whole = (round & 1) != 0;
    const std::size_t len = whole ? opaque((length + 7U) / 8U * 8U) : length;
    if (offset + len > 96U) continue;
    const std::uint64_t mask = len == 64U ? ~std::uint64_t{0} : (std::uint64_t{1} << len) - 1U;
    const std::uint64_t v = rng.next() & mask;
    std::array<std::uint8_t, 12> before{};
    for (auto &b : before) b = static_cast<std::uint8_t>(rng.next());
    auto frame = before;
    REQUIRE(pdo::pack(frame, offset, len, v));
    for (std::size_t bit = 0; bit < 96U; ++bit) {
      const bool inside = bit >= offset && bit < offset + len;
      const unsigned got = static_cast<unsigned>(frame[bit / 8U] >> (bit % 8U)) & 1U;
      const unsigned want = inside ? static_cast<unsigned>((v >> (bit - offset)) & 1U)
                                   : static_cast<unsigned>(before[bit / 8U] >> (bit % 8U)) & 1U;
      CHECK(got == want);
    }
    CHECK(pdo::unpack(frame, offset, len).value() == v);
    if (len < 64U) CHECK(pdo::pack(frame, offset, len, mask + 1U).is(errc::overflow));
  }
  std::array<std::uint8_t, 4> small{};
  CHECK(pdo::pack(small, opaque(16), 32, 1).is(errc::buffer_too_small));
  CHECK(pdo::unpack(small, opaque(16), 32).is(errc::truncated));
}
