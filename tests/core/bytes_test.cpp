#include <fieldcodec/core/bytes.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

namespace fc = fieldcodec;
using fc::byte_order;
using fc::errc;

namespace {
constexpr std::array<std::uint8_t, 8> seq{0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x88};
}

// Every width in both orders.
static_assert(fc::load_unsigned(seq, 1, byte_order::big).value() == 0x01);
static_assert(fc::load_unsigned(seq, 3, byte_order::big).value() == 0x010203);
static_assert(fc::load_unsigned(seq, 3, byte_order::little).value() == 0x030201);
static_assert(fc::load_unsigned(seq, 5, byte_order::little).value() == 0x0504030201);
static_assert(fc::load_unsigned(seq, 6, byte_order::big).value() == 0x010203040506);
static_assert(fc::load_unsigned(seq, 7, byte_order::little).value() == 0x07060504030201);
static_assert(fc::load_unsigned(seq, 8, byte_order::big).value() == 0x0102030405060788);
static_assert(fc::load_unsigned(seq, 8, byte_order::little).value() == 0x8807060504030201);
// Sign extension of odd widths (INTEGER24/40/48/56).
static_assert(fc::load_signed(std::array<std::uint8_t, 3>{0xFF, 0xFF, 0xFF}, 3, byte_order::little)
                  .value() == -1);
static_assert(fc::load_signed(std::array<std::uint8_t, 3>{0x00, 0x00, 0x80}, 3, byte_order::little)
                  .value() == -8388608);
static_assert(fc::load_signed(std::array<std::uint8_t, 5>{0xFF, 0xFF, 0xFF, 0xFF, 0x7F}, 5,
                              byte_order::little)
                  .value() == 549755813887);
static_assert(fc::load_signed(std::array<std::uint8_t, 6>{0x80, 0, 0, 0, 0, 0}, 6, byte_order::big)
                  .value() == -140737488355328);
static_assert(fc::load_signed(std::array<std::uint8_t, 7>{0xFE, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF},
                              7, byte_order::little)
                  .value() == -2);
static_assert(fc::load_signed(seq, 8, byte_order::little).value() ==
              static_cast<std::int64_t>(0x8807060504030201ULL));
// Errors.
static_assert(fc::load_unsigned(seq, 0, byte_order::big).error() == errc::bad_length);
static_assert(fc::load_unsigned(seq, 9, byte_order::big).error() == errc::bad_length);
static_assert(fc::load_unsigned(std::span(seq).first(2), 3, byte_order::big).error() ==
              errc::truncated);

// Field limits.
static_assert(fc::signed_min(3) == -8388608 && fc::signed_max(3) == 8388607);
static_assert(fc::signed_min(8) == INT64_MIN && fc::signed_max(8) == INT64_MAX);
static_assert(fc::unsigned_max(1) == 255 && fc::unsigned_max(7) == 0xFFFFFFFFFFFFFF);
static_assert(fc::unsigned_max(8) == UINT64_MAX);

// to_bytes/from_bytes.
static_assert(fc::to_bytes<std::uint16_t>(0x051F, byte_order::little) ==
              std::array<std::uint8_t, 2>{0x1F, 0x05}); // DPQ Inj. P Limit 1 raw 1311
static_assert(fc::to_bytes<std::int32_t>(-2, byte_order::big) ==
              std::array<std::uint8_t, 4>{0xFF, 0xFF, 0xFF, 0xFE});
static_assert(fc::from_bytes<std::int16_t>({0x80, 0x00}, byte_order::big) == -32768);
static_assert(fc::from_bytes<std::uint32_t>({0x78, 0x56, 0x34, 0x12}, byte_order::little) ==
              0x12345678);

namespace {
template <std::size_t N>
constexpr std::array<std::uint8_t, N> stored_u(std::size_t w, std::uint64_t v, byte_order o) {
  std::array<std::uint8_t, N> out{};
  (void)fc::store_unsigned(out, w, v, o).value();
  return out;
}
} // namespace
static_assert(stored_u<3>(3, 0x123456, byte_order::little) ==
              std::array<std::uint8_t, 3>{0x56, 0x34, 0x12});
static_assert(stored_u<6>(6, 0xA1B2C3D4E5F6, byte_order::big) ==
              std::array<std::uint8_t, 6>{0xA1, 0xB2, 0xC3, 0xD4, 0xE5, 0xF6});

TEST_CASE("store rejects values that do not fit the width") {
  std::array<std::uint8_t, 8> out{};
  CHECK(fc::store_unsigned(out, 1, 255, byte_order::big));
  CHECK(fc::store_unsigned(out, 1, 256, byte_order::big).is(errc::overflow));
  CHECK(fc::store_unsigned(out, 3, 0xFFFFFF, byte_order::big));
  CHECK(fc::store_unsigned(out, 3, 0x1000000, byte_order::big).is(errc::overflow));
  CHECK(fc::store_signed(out, 3, 8388607, byte_order::big));
  CHECK(fc::store_signed(out, 3, 8388608, byte_order::big).is(errc::overflow));
  CHECK(fc::store_signed(out, 3, -8388608, byte_order::big));
  CHECK(fc::store_signed(out, 3, -8388609, byte_order::big).is(errc::overflow));
  CHECK(fc::store_signed(out, 8, INT64_MIN, byte_order::little));
  CHECK(fc::store_unsigned(out, 8, UINT64_MAX, byte_order::little));
  CHECK(fc::store_unsigned(out, 0, 0, byte_order::big).is(errc::bad_length));
  CHECK(fc::store_unsigned(std::span(out).first(2), 3, 1, byte_order::big)
            .is(errc::buffer_too_small));
}

TEST_CASE("signed round trip at every width and both ends of the range") {
  for (std::size_t w = 1; w <= 8; ++w) {
    for (auto order : {byte_order::little, byte_order::big}) {
      for (std::int64_t v : {fc::signed_min(w), fc::signed_min(w) + 1, std::int64_t{-1},
                             std::int64_t{0}, std::int64_t{1}, fc::signed_max(w)}) {
        std::array<std::uint8_t, 8> buf{};
        REQUIRE(fc::store_signed(buf, w, v, order));
        CHECK(fc::load_signed(buf, w, order).value() == v);
      }
      std::array<std::uint8_t, 8> buf{};
      REQUIRE(fc::store_unsigned(buf, w, fc::unsigned_max(w), order));
      CHECK(fc::load_unsigned(buf, w, order).value() == fc::unsigned_max(w));
    }
  }
}

TEST_CASE("byte order does not depend on the host") {
  std::array<std::uint8_t, 4> out{};
  REQUIRE(fc::store<std::uint32_t>(out, 0x11223344U, byte_order::big));
  CHECK(out == std::array<std::uint8_t, 4>{0x11, 0x22, 0x33, 0x44});
  REQUIRE(fc::store<std::uint32_t>(out, 0x11223344U, byte_order::little));
  CHECK(out == std::array<std::uint8_t, 4>{0x44, 0x33, 0x22, 0x11});
}

TEST_CASE("byte_reader reports truncation and does not move on failure") {
  const std::array<std::uint8_t, 5> in{0x12, 0x34, 0x56, 0x78, 0x9A};
  fc::byte_reader r(in);
  CHECK(r.read<std::uint16_t>(byte_order::big).value() == 0x1234);
  CHECK(r.position() == 2);
  CHECK(r.read<std::uint32_t>(byte_order::big).error() == errc::truncated);
  CHECK(r.position() == 2);
  CHECK(r.read_unsigned(3, byte_order::little).value() == 0x9A7856);
  CHECK(r.empty());
  CHECK(r.read_u8().error() == errc::truncated);
  CHECK(r.read_bytes(1).error() == errc::truncated);
  CHECK(r.skip(1).is(errc::truncated));

  fc::byte_reader r2(in);
  CHECK(r2.read_signed(1, byte_order::big).value() == 0x12);
  auto b = r2.read_bytes(2);
  REQUIRE(b);
  CHECK(b.value()[0] == 0x34);
  CHECK(r2.skip(1));
  CHECK(r2.remaining() == 1);
  CHECK(r2.rest()[0] == 0x9A);
}

TEST_CASE("byte_writer reports a full buffer and does not move on failure") {
  std::array<std::uint8_t, 5> out{};
  fc::byte_writer w(out);
  CHECK(w.write<std::int16_t>(-2, byte_order::little));
  CHECK(w.write<std::uint32_t>(1, byte_order::big).is(errc::buffer_too_small));
  CHECK(w.size() == 2);
  CHECK(w.write_unsigned(2, 0xBEEF, byte_order::big));
  CHECK(w.write_signed(1, -1, byte_order::big));
  CHECK(w.write_u8(0).is(errc::buffer_too_small));
  CHECK(w.pad(1).is(errc::buffer_too_small));
  CHECK(out == std::array<std::uint8_t, 5>{0xFE, 0xFF, 0xBE, 0xEF, 0xFF});
  CHECK(w.written().size() == 5);

  std::array<std::uint8_t, 4> out2{};
  fc::byte_writer w2(out2);
  const std::array<std::uint8_t, 2> two{0xAA, 0xBB};
  CHECK(w2.write_bytes(two));
  CHECK(w2.pad(2, 0x55));
  CHECK(w2.write_bytes(two).is(errc::buffer_too_small));
  CHECK(out2 == std::array<std::uint8_t, 4>{0xAA, 0xBB, 0x55, 0x55});
  CHECK(w2.write_unsigned(1, 256, byte_order::big).is(errc::overflow)); // value checked first
  CHECK(w2.write_unsigned(1, 255, byte_order::big).is(errc::buffer_too_small));
}

// copy_bytes: exactly n bytes, in order, nothing past them; the same in constant evaluation.
namespace {
template <std::size_t N>
constexpr std::array<std::uint8_t, 10> copied_fixed() {
  std::array<std::uint8_t, 10> to{};
  to.fill(0xEE);
  fc::copy_bytes<N>(seq.data(), to.data());
  return to;
}
constexpr std::array<std::uint8_t, 10> copied_n(std::size_t n) {
  std::array<std::uint8_t, 10> to{};
  to.fill(0xEE);
  fc::copy_bytes(seq.data(), to.data(), n);
  return to;
}
constexpr bool copies_exactly(const std::array<std::uint8_t, 10> &to, std::size_t n) {
  for (std::size_t i = 0; i < to.size(); ++i) {
    if (to[i] != (i < n ? seq[i] : 0xEE)) return false;
  }
  return true;
}
} // namespace
static_assert(copies_exactly(copied_fixed<7>(), 7));
static_assert(copies_exactly(copied_fixed<1>(), 1));
static_assert(copies_exactly(copied_n(0), 0));
static_assert(copies_exactly(copied_n(3), 3));
static_assert(copies_exactly(copied_n(8), 8));

TEST_CASE("copy_bytes copies exactly the bytes asked for, at every length, at run time") {
  CHECK(copies_exactly(copied_fixed<0>(), 0));
  CHECK(copies_exactly(copied_fixed<1>(), 1));
  CHECK(copies_exactly(copied_fixed<2>(), 2));
  CHECK(copies_exactly(copied_fixed<3>(), 3));
  CHECK(copies_exactly(copied_fixed<4>(), 4));
  CHECK(copies_exactly(copied_fixed<5>(), 5));
  CHECK(copies_exactly(copied_fixed<6>(), 6));
  CHECK(copies_exactly(copied_fixed<7>(), 7));
  CHECK(copies_exactly(copied_fixed<8>(), 8));
  for (std::size_t n = 0; n <= seq.size(); ++n) {
    CAPTURE(n);
    CHECK(copies_exactly(copied_n(n), n));
  }
}
