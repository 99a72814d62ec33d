// The C++ blocks of docs/cookbook.md, as written there, and the results their comments state
// (static_asserts in the blocks; doctest cases below for what runs). tests/docs_check/run.cmake
// fails when a block of the page and its copy here differ. Each block sits in a namespace of
// its own (the page's blocks are complete programs; here they share one translation unit).
#include <array>
#include <cstdint>
#include <cstdio>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo_object.hpp>
#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/emergency.hpp>
#include <fieldcodec/dpq/parameter.hpp>
#include <fieldcodec/dpq/sdo.hpp>
#include <fieldcodec/dpq/sdo_abort.hpp>
#include <fieldcodec/od/entry.hpp>
#include <string>
#include <string_view>

#include <doctest/doctest.h>

// clang-format off
namespace cb_dpq_1 { // "Read the identity (1018h) over SDO"
namespace co = fieldcodec::canopen;
namespace od = fieldcodec::od;

constexpr od::entry vendor_id{.index = 0x1018,
                              .sub = 1,
                              .object = od::object_code::record,
                              .type = od::data_type::unsigned32,
                              .access_type = od::access::ro};

// the request: 605: 40 18 10 01 00 00 00 00
constexpr co::can_frame request = co::sdo::upload(5, vendor_id).value();
static_assert(request == co::can_frame{0x605, false, 8, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}});

// the answer 585: 43 18 10 01 2D 01 00 00 is from node 5 and says vendor-ID 0x0000012D
constexpr co::can_frame answer{0x585, false, 8, {0x43, 0x18, 0x10, 0x01, 0x2D, 0x01, 0, 0}};
static_assert(co::sdo::channel::default_for(5).value().is_response(answer));
static_assert(co::sdo::upload_value(vendor_id, answer).value().to_uint64().value() == 0x12D);
} // namespace cb_dpq_1

namespace cb_dpq_2 { // "Write a pressure in bar and read it back"
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::canopen::can_frame;

// Inj. P Limit 1 := 4.0 bar (scale 327.67 → raw 1311): 605: 23 23 20 00 1F 05 00 00
constexpr auto write = dpq::write_request(5, p::inj_p_limit_1, 4.0);
static_assert(write.value() ==
              can_frame{0x605, false, 8, {0x23, 0x23, 0x20, 0x00, 0x1F, 0x05, 0, 0}});
// the card confirms: 585: 60 23 20 00 00 00 00 00
static_assert(dpq::write_response(5, p::inj_p_limit_1,
                                  can_frame{0x585, false, 8, {0x60, 0x23, 0x20, 0x00, 0, 0, 0, 0}})
                  .has_value());

// read it back: 605: 40 23 20 00 …, answer 585: 43 23 20 00 1F 05 00 00 → 4.001 bar
static_assert(dpq::read_request(5, p::inj_p_limit_1).value().data[0] == 0x40);
constexpr auto bar = dpq::read_response(
    5, p::inj_p_limit_1, can_frame{0x585, false, 8, {0x43, 0x23, 0x20, 0x00, 0x1F, 0x05, 0, 0}});
static_assert(bar.value().mantissa == 4001 && bar.value().places == 3);
} // namespace cb_dpq_2

namespace cb_dpq_3 { // "Write a velocity in mm/s from a PLC REAL"
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::errc;

// Analog Vel Max (mm/s, 0…5000, scale 327.67): 90.73 mm/s → raw 29729 = 0x7421
static_assert(p::analog_vel_max.to_raw(90.73F).value() == 29729);
constexpr auto frame = dpq::write_request(5, p::analog_vel_max, 90.73F).value();
static_assert(frame.data[0] == 0x23 && frame.data[4] == 0x21 && frame.data[5] == 0x74);

// 5000.5 mm/s is above the printed maximum; −1 mm/s below the minimum
static_assert(dpq::write_request(5, p::analog_vel_max, 5000.5).is(errc::out_of_range));
static_assert(dpq::write_request(5, p::analog_vel_max, -1).is(errc::out_of_range));
} // namespace cb_dpq_3

namespace cb_dpq_4 { // "Read an actual value (signed, in mm)"
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::canopen::can_frame;
using fieldcodec::errc;

// Position Error : (2F09h, INTEGER32, 327.67 per mm) answered 585: 43 09 2F 00 FF FF FF FF
constexpr can_frame answer{0x585, false, 8, {0x43, 0x09, 0x2F, 0x00, 0xFF, 0xFF, 0xFF, 0xFF}};
static_assert(dpq::read_raw_response(5, p::position_error, answer).value() == -1);
constexpr auto mm = dpq::read_response(5, p::position_error, answer).value(); // exact: −0.003
static_assert(mm.mantissa == -3 && mm.places == 3);
static_assert(p::position_error.to_eu(-1) < -0.00305 && p::position_error.to_eu(-1) > -0.00306);

// it is an actual value: writing it is refused before a frame is built
static_assert(dpq::write_request(5, p::position_error, 0.0).is(errc::access_denied));
} // namespace cb_dpq_4

namespace cb_dpq_5 { // "Decode an emergency and print its text"
namespace co = fieldcodec::canopen;
namespace dpq = fieldcodec::dpq;

// 085: 02 83 01 00 00 00 00 00 → "node 5: 8302 pressure monitor tripped [generic error]"
std::string emcy_text(const co::can_frame &f) {
  auto e = co::emcy::decode(f);
  if (!e) return std::string(fieldcodec::to_string(e.error())); // not an EMCY, or DLC ≠ 8
  const co::emcy::message &m = e.value().m;
  char head[24];
  std::snprintf(head, sizeof head, "node %u: %04X ", unsigned{e.value().node},
                unsigned{m.error_code});
  std::string text = head;
  const std::string_view what = dpq::describe_emcy(m.error_code);
  text += what.empty() ? std::string_view{"not listed by the DPQ manual"} : what;
  std::array<std::string_view, 8> bits{};
  const std::size_t n = dpq::error_register::describe(m.error_register, bits);
  for (std::size_t i = 0; i < n; ++i) (text += i == 0 ? " [" : ", ") += bits[i];
  if (n > 0) text += ']';
  return text;
}
} // namespace cb_dpq_5

namespace cb_dpq_6 { // "Read the error history (1003h)"
namespace co = fieldcodec::canopen;
namespace dpq = fieldcodec::dpq;
namespace od = fieldcodec::od;

constexpr od::entry error_count{.index = 0x1003,
                                .sub = 0,
                                .object = od::object_code::array,
                                .type = od::data_type::unsigned8,
                                .access_type = od::access::rw};
constexpr od::entry newest_error{.index = 0x1003,
                                 .sub = 1,
                                 .object = od::object_code::array,
                                 .type = od::data_type::unsigned32,
                                 .access_type = od::access::ro};

// 605: 40 03 10 00 → 585: 4F 03 10 00 02 …: two errors recorded
static_assert(co::sdo::upload(5, error_count).value().data[1] == 0x03);
static_assert(co::sdo::upload_value(error_count, co::can_frame{0x585, false, 8,
                                                               {0x4F, 0x03, 0x10, 0x00, 0x02}})
                  .value()
                  .to_uint64()
                  .value() == 2);

// 605: 40 03 10 01 → 585: 43 03 10 01 00 34 00 00: code 3400h, "current input: cable break"
constexpr auto newest = co::sdo::upload_value(newest_error,
                                              co::can_frame{0x585, false, 8,
                                                            {0x43, 0x03, 0x10, 0x01, 0x00, 0x34}})
                            .value()
                            .to_uint64()
                            .value();
constexpr auto code = static_cast<std::uint16_t>(newest & 0xFFFFU);
static_assert(code == 0x3400 && (newest >> 16U) == 0); // no manufacturer-specific part
static_assert(dpq::describe_emcy(code) == "current input: cable break");

// writing 0 to sub 0 clears the history: 605: 2F 03 10 00 00 00 00 00
static_assert(co::sdo::download(5, error_count, 0).value().data[0] == 0x2F);
} // namespace cb_dpq_6

namespace cb_dpq_7 { // "Understand an SDO abort from the card"
namespace co = fieldcodec::canopen;
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;
using fieldcodec::errc;

// the card refused the write of Inj. P Limit 1: 585: 80 23 20 00 31 00 09 06
constexpr co::can_frame refused{0x585, false, 8, {0x80, 0x23, 0x20, 0x00, 0x31, 0x00, 0x09, 0x06}};
static_assert(dpq::write_response(5, p::inj_p_limit_1, refused).is(errc::aborted));

constexpr auto why = co::sdo::decode(refused, co::sdo::direction::to_client).value().abort;
static_assert(why == co::sdo::abort_code::value_too_high); // 0609 0031h
static_assert(dpq::describe_sdo_abort(why) == "value too large");
static_assert(dpq::sdo_abort_errc(why) == errc::out_of_range);
} // namespace cb_dpq_7

namespace cb_dpq_8 { // "Configure the TPDO1 event timer and start the card"
namespace co = fieldcodec::canopen;
namespace od = fieldcodec::od;
using fieldcodec::errc;

constexpr od::entry tpdo1_event_timer{.index = 0x1800,
                                      .sub = 5,
                                      .object = od::object_code::record,
                                      .type = od::data_type::unsigned16};

// 605: 2B 00 18 05 64 00 00 00, confirmed by 585: 60 00 18 05 …
constexpr auto timer = co::sdo::download(5, tpdo1_event_timer, 100);
static_assert(timer.value() ==
              co::can_frame{0x605, false, 8, {0x2B, 0x00, 0x18, 0x05, 0x64, 0, 0, 0}});
static_assert(co::sdo::download(5, tpdo1_event_timer, 70000).is(errc::overflow));

// then start node 5: 000: 01 05
static_assert(co::nmt::encode(co::nmt::command::start, 5).value() ==
              co::can_frame{0x000, false, 2, {0x01, 0x05}});
} // namespace cb_dpq_8

namespace cb_dpq_9 { // "Read the actual values in a TPDO"
namespace co = fieldcodec::canopen;
namespace p = fieldcodec::dictionaries::dpq_parameters;
namespace dpq = fieldcodec::dpq;

constexpr auto tpdo1 = co::pdo::make_static_mapping(
    p::dictionary, co::pdo::direction::tpdo, {{0x2F07, 0, 32}, {0x2F11, 0, 32}});

// 185: FF 7F 00 00 FE FF 00 00 → position 100.000 mm, pressure 200.000 bar
constexpr co::can_frame f{0x185, false, 8, {0xFF, 0x7F, 0x00, 0x00, 0xFE, 0xFF, 0x00, 0x00}};
constexpr auto mm = dpq::to_eu_decimal(p::position_fb, tpdo1.get_signed(f.payload(), 0).value());
constexpr auto bar = dpq::to_eu_decimal(p::pressure_fb, tpdo1.get_signed(f.payload(), 1).value());
static_assert(mm.value().mantissa == 100000 && mm.value().places == 3);
static_assert(bar.value().mantissa == 200000 && bar.value().places == 3);
} // namespace cb_dpq_9
// clang-format on

TEST_CASE("cookbook, DPQ: an emergency and its text") {
  namespace co = fieldcodec::canopen;
  const co::can_frame pressure{0x085, false, 8, {0x02, 0x83, 0x01, 0, 0, 0, 0, 0}};
  CHECK(cb_dpq_5::emcy_text(pressure) == "node 5: 8302 pressure monitor tripped [generic error]");
  const co::can_frame cleared{0x085, false, 8, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0}};
  CHECK(cb_dpq_5::emcy_text(cleared) == "node 5: 0000 no error (all errors cleared)");
  const co::can_frame vendor{0x0FF, false, 8, {0x01, 0xFF, 0x81, 0, 0, 0, 0, 0}};
  CHECK(cb_dpq_5::emcy_text(vendor) ==
        "node 127: FF01 not listed by the DPQ manual [generic error, manufacturer-specific]");
  const co::can_frame short_frame{0x085, false, 7, {0x02, 0x83, 0x01, 0, 0, 0, 0, 0}};
  CHECK(cb_dpq_5::emcy_text(short_frame) == fieldcodec::to_string(fieldcodec::errc::bad_length));
  const co::can_frame sdo{0x585, false, 8, {}};
  CHECK(cb_dpq_5::emcy_text(sdo) == fieldcodec::to_string(fieldcodec::errc::unexpected_frame));
}

TEST_CASE("cookbook, DPQ: the frames the recipes state, at run time") {
  namespace co = fieldcodec::canopen;
  // the identity request and answer
  CHECK(cb_dpq_1::request.id == 0x605);
  CHECK(co::sdo::upload_value(cb_dpq_1::vendor_id, cb_dpq_1::answer).value().to_uint64().value() ==
        0x12D);
  // the event timer write is 2B 00 18 05 64 00 00 00 and its confirmation matches the channel's
  const auto ch = co::sdo::channel::default_for(5).value();
  CHECK(ch.response(co::sdo::download_response({0x1800, 5})) ==
        co::can_frame{0x585, false, 8, {0x60, 0x00, 0x18, 0x05, 0, 0, 0, 0}});
  CHECK(cb_dpq_8::timer.value() ==
        ch.request(co::sdo::expedited_download({0x1800, 5}, std::array<std::uint8_t, 2>{0x64, 0}))
            .value());
  // the error history request of sub 1 is 40 03 10 01
  CHECK(co::sdo::upload(5, cb_dpq_6::newest_error).value() ==
        co::can_frame{0x605, false, 8, {0x40, 0x03, 0x10, 0x01, 0, 0, 0, 0}});
  CHECK(co::sdo::download(5, cb_dpq_6::error_count, 0).value() ==
        co::can_frame{0x605, false, 8, {0x2F, 0x03, 0x10, 0x00, 0, 0, 0, 0}});
  // the read-back request of the bar recipe
  CHECK(fieldcodec::dpq::read_request(5, fieldcodec::dictionaries::dpq_parameters::inj_p_limit_1)
            .value() == co::can_frame{0x605, false, 8, {0x40, 0x23, 0x20, 0x00, 0, 0, 0, 0}});
}
