// Typed PA-CONTROL requests from command table entries, and the code tables.
// Entries below copy rows of dictionaries/pacontrol_commands.csv (manual 001, 5.2).
#include <fieldcodec/pacontrol/codes.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>

#include "pac_test_util.hpp"

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <limits>

namespace fc = fieldcodec;
namespace pac = fc::pacontrol;
namespace od = fc::od;
using fc::decimal;
using fc::errc;
using od::command_value;

namespace {

constexpr od::command make(std::uint16_t code, std::int64_t lo, std::int64_t hi, command_value date,
                           command_value reply) {
  od::command c{};
  c.code = code;
  c.parameter_min = lo < 0 ? od::number{} : od::signed_number(lo);
  c.parameter_max = hi < 0 ? od::number{} : od::signed_number(hi);
  c.date_type = date;
  c.reply_type = reply;
  return c;
}

constexpr auto start_online = make(0x0603, -1, -1, command_value::none, command_value::none);
constexpr auto get_input = make(0x1900, 1, 1024, command_value::none, command_value::integer);
constexpr auto put_int_reg = make(0x0906, 1, 1024, command_value::integer, command_value::integer);
constexpr auto get_int_reg = make(0x1906, 1, 1024, command_value::none, command_value::integer);
constexpr auto put_float_reg = make(0x0907, 1, 1024, command_value::real, command_value::real);
constexpr auto get_float_reg = make(0x1907, 1, 1024, command_value::none, command_value::real);
constexpr auto pos_absolute = make(0x0A87, 1, 16, command_value::real, command_value::real);

constexpr pactest::bytes encode(const fc::result<pac::serial::request> &r) {
  pactest::bytes b;
  if (!r) return b;
  std::array<std::uint8_t, pac::serial::max_frame_size> buf{};
  auto n = pac::serial::encode_request(r.value(), buf);
  if (!n) return b;
  for (std::size_t i = 0; i < n.value(); ++i) b.data[b.size++] = buf[i];
  return b;
}
constexpr bool same(const pactest::bytes &a, const pactest::bytes &b) { return a == b.span(); }

// The requests of manual 3.4, built from the table (corrected bytes, errata serial frames).
static_assert(same(encode(pac::make_request(put_int_reg, 5, 12345)),
                   pactest::hex("01 02 30 39 30 36 3B 35 3B 30 3B 31 32 33 34 35 03 30 04")));
static_assert(same(encode(pac::make_request(get_input, 5)),
                   pactest::hex("01 02 31 39 30 30 3B 35 3B 30 3B 30 03 36 04")));
static_assert(same(encode(pac::make_request(get_int_reg, 2)),
                   pactest::hex("01 02 31 39 30 36 3B 32 3B 30 3B 30 03 37 04")));
static_assert(same(encode(pac::make_request(put_int_reg, 3, 333)),
                   pactest::hex("01 02 30 39 30 36 3B 33 3B 30 3B 33 33 33 03 34 04")));
// Read R1: no date, sent with TYP 1 because the reply is a real number (3.4.2 warning).
static_assert(same(encode(pac::make_request(get_float_reg, 1)),
                   pactest::hex("01 02 31 39 30 37 3B 31 3B 31 3B 30 03 34 04")));
static_assert(same(encode(pac::make_request(start_online)),
                   pactest::hex("01 02 30 36 30 33 3B 30 3B 30 3B 30 03 31 34 04")));
static_assert(same(encode(pac::make_request(pos_absolute, 2, 5552.0F)),
                   pactest::hex("01 02 30 41 38 37 3B 32 3B 31 3B 35 35 35 32 2E 30 03 39 35 04")));
static_assert(same(encode(pac::make_request(pos_absolute, 2, 5552.0)),
                   pactest::hex("01 02 30 41 38 37 3B 32 3B 31 3B 35 35 35 32 2E 30 03 39 35 04")));
static_assert(same(encode(pac::make_request(pos_absolute, 2, decimal{55520, 1})),
                   pactest::hex("01 02 30 41 38 37 3B 32 3B 31 3B 35 35 35 32 2E 30 03 39 35 04")));

// 0907 write R27 = 10.0 (5.2.4.13, l. 2727): "0907;27;1;10.0"; on Profibus 4120 0000.
static_assert(same(encode(pac::make_request(put_float_reg, 27, 10.0F)),
                   pactest::frame("0907;27;1;10.0", "30")));
static_assert(pac::cmd_date(put_float_reg, pac::value::of_float(10.0F).value()).value() ==
              0x41200000U);

// Type discipline.
static_assert(pac::make_request(put_int_reg, 5, 12.5F).error() == errc::type_mismatch);
static_assert(pac::make_request(put_int_reg, 5, 12.0).error() == errc::type_mismatch);
static_assert(pac::make_request(put_int_reg, 5, decimal{125, 1}).error() == errc::type_mismatch);
static_assert(pac::make_request(put_int_reg, 5, pac::value::of_float(1.0F).value()).error() ==
              errc::type_mismatch);
static_assert(pac::make_request(pos_absolute, 2, 5552).error() == errc::type_mismatch);
static_assert(pac::make_request(get_int_reg, 2, 7).error() == errc::type_mismatch);
static_assert(pac::make_request(put_int_reg, 5).error() == errc::type_mismatch);
static_assert(pac::make_request(pos_absolute, 2, std::numeric_limits<float>::quiet_NaN()).error() ==
              errc::not_representable);
static_assert(pac::make_request(pos_absolute, 2, std::numeric_limits<double>::infinity()).error() ==
              errc::not_representable);
static_assert(pac::make_request(pos_absolute, 2, 1.0e39).error() == errc::not_representable);
// Parameter ranges from the table.
static_assert(pac::make_request(pos_absolute, 17, 1.0F).error() == errc::out_of_range);
static_assert(pac::make_request(pos_absolute, 0, 1.0F).error() == errc::out_of_range);
static_assert(pac::make_request(get_input, 1025).error() == errc::out_of_range);
static_assert(pac::make_request(get_input, 1024).has_value());

} // namespace

TEST_CASE("pacontrol command: replies checked against the table") {
  using pac::serial::acknowledgement;
  const acknowledgement r1{0, true, 1, 0, pac::value::of_real(decimal{6400000, 4}).value()};
  auto v = pac::reply_value(get_float_reg, r1);
  REQUIRE(v);
  CHECK(v->as_float() == 640.0F);
  CHECK(pac::reply_value(get_int_reg, r1).error() == errc::type_mismatch);
  const acknowledgement online{0, true, 31, 0, pac::value::of_int(0).value()};
  CHECK(pac::reply_value(start_online, online));
}

TEST_CASE("pacontrol command: Profibus dates and handshake") {
  pac::profibus::cmd_handshake hs;
  auto req = pac::start_command(hs, put_int_reg, 3, pac::value::of_int(333).value());
  REQUIRE(req);
  // 4.2.4: write N3 = 333 → 00 00 01 4D 00 03 89 06.
  auto bytes = pac::profibus::encode_cmd_request(req.value());
  CHECK(pactest::hex("00 00 01 4D 00 03 89 06") == std::span<const std::uint8_t>(bytes.value()));
  CHECK(hs.update({333, false, 1, true, false, true, 0}) == pac::profibus::cmd_progress::done);
  req = pac::start_command(hs, pos_absolute, 2, pac::value::of_float(200.0F).value());
  REQUIRE(req);
  CHECK(req->date == 0x43480000U); // 200.0 (0A87, l. 3445)
  CHECK(pac::start_command(hs, pos_absolute, 2, pac::value::of_int(200).value()).error() ==
        errc::type_mismatch);
  CHECK(hs.update({0x449CE666U, false, 31, false, false, true, 0}) ==
        pac::profibus::cmd_progress::done);
  req = pac::start_command(hs, get_float_reg, 1);
  REQUIRE(req);
  CHECK(req->date == 0);
  CHECK(pac::start_command(hs, put_int_reg, 1, pac::value::of_int(5).value()).error() ==
        errc::bad_state); // the previous toggle not seen yet
  const pac::profibus::cmd_reply r1{0x44200000U, false, 1, true, false, true, 0};
  CHECK(hs.update(r1) == pac::profibus::cmd_progress::done);
  auto v = pac::reply_value(get_float_reg, r1);
  REQUIRE(v);
  CHECK(v->as_float() == 640.0F);
  CHECK(
      pac::reply_value(get_int_reg, {12345678, false, 1, true, false, true, 0})->as_int().value() ==
      12345678);
  CHECK(pac::reply_value(get_float_reg, {0x7F800000U, false, 1, true, false, true, 0}).error() ==
        errc::not_representable);
  CHECK(pac::start_command(hs, put_int_reg, 0, pac::value::of_int(1).value()).error() ==
        errc::out_of_range);
  CHECK(pac::start_command(hs, put_int_reg).error() == errc::type_mismatch);
}

TEST_CASE("pacontrol codes: tables are sorted, unique and described") {
  for (std::size_t i = 1; i < pac::command_errors.size(); ++i) {
    CHECK(pac::command_errors[i - 1].code < pac::command_errors[i].code);
  }
  for (std::size_t i = 1; i < pac::operating_status_codes.size(); ++i) {
    CHECK(pac::operating_status_codes[i - 1].code < pac::operating_status_codes[i].code);
  }
  for (const auto &e : pac::command_errors) CHECK(!e.text.empty());
  // 6.5 corrections (errata "Other examples and tables"): 30 = 1E, 37 = 25, 46 = 2E, 47 = 2F.
  CHECK(pac::describe_command_error(0x1E).value() == "EPROM erase failed");
  CHECK(pac::describe_command_error(0x25).value() == "flag number not allowed");
  CHECK(pac::describe_command_error(0x2E).value() == "axis not ready");
  CHECK(pac::describe_command_error(0x2F).value() == "not a servoTEC axis");
  CHECK(pac::describe_command_error(262).value() == "AS-i configuration faulty");
  CHECK(pac::describe_command_error(7).error() == errc::unknown_object);
  CHECK(pac::describe_command_error(60).error() == errc::unknown_object);
  CHECK(pac::describe_command_error(0x1FFF).error() == errc::unknown_object);
  // Status: decimal codes (190B's "hex" label is wrong, errata "Protocol text").
  CHECK(pac::describe_operating_status(31).value() == "ONLINE");
  CHECK(pac::describe_operating_status(pac::operating_status::online_stopped).value() ==
        "ONLINE stopped");
  CHECK(pac::describe_operating_status(0x1F).value() == "ONLINE");
  CHECK(pac::describe_operating_status(16).value() ==
        "AUTOMATIC, start-after-stop program running");
  CHECK(pac::describe_operating_status(4).error() == errc::unknown_object);
  // PA-CONTROL error numbers.
  CHECK(pac::classify_controller_error(0) == pac::controller_error_class::none);
  CHECK(pac::classify_controller_error(99) == pac::controller_error_class::cpu);
  CHECK(pac::classify_controller_error(100) == pac::controller_error_class::system);
  CHECK(pac::classify_controller_error(499) == pac::controller_error_class::system);
  CHECK(pac::classify_controller_error(500) == pac::controller_error_class::operation);
  CHECK(pac::classify_controller_error(999) == pac::controller_error_class::operation);
  CHECK(pac::classify_controller_error(1000) == pac::controller_error_class::out_of_list);
  CHECK(pac::describe_controller_error(529).value() ==
        "positive limit switch reached or cable broken");
  CHECK(pac::describe_controller_error(530).value() == "fault in AUTOMATIC or ONLINE mode");
  CHECK(pac::describe_controller_error(1000).error() == errc::unknown_object);
  // The QUIT a device-side receiver answers for decoder errors.
  CHECK(pac::command_error_for(errc::bad_checksum) == 16);
  CHECK(pac::command_error_for(errc::truncated) == 17);
  CHECK(pac::command_error_for(errc::type_mismatch) == 41);
  const auto bad = pac::serial::decode_frame(pactest::frame("1900;5;0;0", "7").span());
  CHECK(pac::command_error_for(bad.error()) == pac::command_error::bad_check);
}
