// COMPAX helpers users had to write themselves (issue 13): the combined objects POSRXSPEEDY and
// PRXSDYALZ (2.8.4, 2.8.5), FKT_GRUPPE (2.3.1), CAM_MEM (2.11.8), S23_S26 (2.5.7), PCP
// confirmations, the LAGE_ZIEL set-point handshake (2.7.3) and the manual's STEUERWORT /
// STATUSWORT terms (2.4.7, 2.4.8). L… = line in ../shared/seeds/000_b4c1e0d4025b123d.txt.
#include <fieldcodec/compax/cam.hpp>
#include <fieldcodec/compax/control.hpp>
#include <fieldcodec/compax/diagnosis.hpp>
#include <fieldcodec/compax/identification.hpp>
#include <fieldcodec/compax/pcp.hpp>
#include <fieldcodec/compax/set_point.hpp>
#include <fieldcodec/compax/speed_profile.hpp>
#include <fieldcodec/core/decimal.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace cx = fieldcodec::compax;
using fieldcodec::decimal;
using fieldcodec::equal;
using fieldcodec::errc;
using bytes = std::vector<std::uint8_t>;

namespace {
template <std::size_t N>
bytes v(const std::array<std::uint8_t, N> &a) {
  return bytes(a.begin(), a.end());
}
} // namespace

// 2.8.4 example (L2199-2208): "continue travel at 33 % of the nominal speed after 580 mm":
// Length 8, Param. counter 7, data 00 08 D9 A0 00 00 80 E8.
static_assert(cx::encode_posrxspeedy({decimal{580, 0}, decimal{33, 0}}).value() ==
              std::array<std::uint8_t, 8>{0x00, 0x08, 0xD9, 0xA0, 0x00, 0x00, 0x80, 0xE8});

TEST_CASE("POSRXSPEEDY (2.8.4): manual example and range checks") {
  const bytes printed{0x00, 0x08, 0xD9, 0xA0, 0x00, 0x00, 0x80, 0xE8};
  auto b = cx::encode_posrxspeedy({decimal{580, 0}, decimal{33, 0}});
  REQUIRE(b.has_value());
  CHECK(v(b.value()) == printed);
  auto r = cx::pcp_write(0x5FE4, 0, b.value());
  REQUIRE(r.has_value());
  CHECK(r.value().param_counter == 7); // printed "Param. counter 7"
  auto s = cx::decode_posrxspeedy(printed);
  REQUIRE(s.has_value());
  CHECK(equal(s.value().position, decimal{580, 0}));
  CHECK(equal(s.value().speed, decimal{33, 0}));
  // negative positions are two's complement; 0.001 resolution on both values
  CHECK(v(cx::encode_posrxspeedy({decimal{-1, 3}, decimal{1, 3}}).value()) ==
        bytes{0xFF, 0xFF, 0xFF, 0xFF, 0x00, 0x00, 0x00, 0x01});
  CHECK(v(cx::encode_posrxspeedy({decimal{-2147483648, 3}, decimal{600, 0}}).value()) ==
        bytes{0x80, 0x00, 0x00, 0x00, 0x00, 0x09, 0x27, 0xC0});
  CHECK(v(cx::encode_posrxspeedy({decimal{2147483647, 3}, decimal{600, 0}}).value()) ==
        bytes{0x7F, 0xFF, 0xFF, 0xFF, 0x00, 0x09, 0x27, 0xC0});
  // range checks: position 32-bit, speed 0.001 … 600 %, resolution 0.001
  CHECK(cx::encode_posrxspeedy({decimal{2147483648, 3}, decimal{1, 0}}).error() ==
        errc::out_of_range);
  CHECK(cx::encode_posrxspeedy({decimal{-2147483649, 3}, decimal{1, 0}}).error() ==
        errc::out_of_range);
  CHECK(cx::encode_posrxspeedy({decimal{1, 0}, decimal{0, 0}}).error() == errc::out_of_range);
  CHECK(cx::encode_posrxspeedy({decimal{1, 0}, decimal{600001, 3}}).error() == errc::out_of_range);
  CHECK(cx::encode_posrxspeedy({decimal{1, 0}, decimal{-1, 0}}).error() == errc::out_of_range);
  CHECK(cx::encode_posrxspeedy({decimal{1, 4}, decimal{1, 0}}).error() == errc::not_representable);
  CHECK(cx::encode_posrxspeedy({decimal{1, 0}, decimal{15, 4}}).error() == errc::not_representable);
  // bad input
  CHECK(cx::decode_posrxspeedy(bytes(7)).error() == errc::truncated);
  CHECK(cx::decode_posrxspeedy(bytes(9)).error() == errc::bad_length);
  CHECK(cx::decode_posrxspeedy(bytes{0, 0, 0, 1, 0, 0, 0, 0}).error() == errc::out_of_range);
  CHECK(cx::decode_posrxspeedy(bytes{0, 0, 0, 1, 0, 0x09, 0x27, 0xC1}).error() ==
        errc::out_of_range);
}

TEST_CASE("PRXSDYALZ (2.8.5): POSRXSPEEDY plus the ramp time MSB first") {
  // no printed example: the layout of L2226-2246 (bytes 1..4 position, 5..8 speed, 9 MSB and
  // 10 LSB of the ramp time in ms, 0 … 65 000) applied to the 2.8.4 example plus 200 ms
  const bytes expected{0x00, 0x08, 0xD9, 0xA0, 0x00, 0x00, 0x80, 0xE8, 0x00, 0xC8};
  auto b = cx::encode_prxsdyalz({decimal{580, 0}, decimal{33, 0}, 200});
  REQUIRE(b.has_value());
  CHECK(v(b.value()) == expected);
  CHECK(cx::pcp_write(0x5FC7, 0, b.value()).value().param_counter == 8);
  auto s = cx::decode_prxsdyalz(expected);
  REQUIRE(s.has_value());
  CHECK(equal(s.value().position, decimal{580, 0}));
  CHECK(equal(s.value().speed, decimal{33, 0}));
  CHECK(s.value().ramp_ms == 200);
  CHECK(v(cx::encode_prxsdyalz({decimal{0, 0}, decimal{1, 3}, 65000}).value()) ==
        bytes{0, 0, 0, 0, 0, 0, 0, 1, 0xFD, 0xE8});
  CHECK(cx::encode_prxsdyalz({decimal{0, 0}, decimal{1, 0}, 65001}).error() == errc::out_of_range);
  CHECK(cx::encode_prxsdyalz({decimal{0, 0}, decimal{1, 0}, -1}).error() == errc::out_of_range);
  CHECK(cx::encode_prxsdyalz({decimal{0, 0}, decimal{0, 0}, 0}).error() == errc::out_of_range);
  CHECK(cx::decode_prxsdyalz(bytes{0, 0, 0, 0, 0, 0, 0, 1, 0xFD, 0xE9}).error() ==
        errc::out_of_range);
  CHECK(cx::decode_prxsdyalz(bytes(9)).error() == errc::truncated);
  CHECK(cx::decode_prxsdyalz(bytes(11)).error() == errc::bad_length);
}

TEST_CASE("FKT_GRUPPE (2.3.1): profile number, function group, version") {
  // 2.3.1 example (L733-736): read the 3rd function group description = read request sub 3
  const auto rd = cx::pcp_read(0x600F, 3).value();
  CHECK(rd.param_counter == 3);
  CHECK(rd.sub == 3);
  // layout L703-721: bytes 1-2 profile number, byte 3 function group id, byte 4 version;
  // group in bits 15..12 of the profile number (erratum CX-35)
  auto f = cx::decode_function_group(bytes{0x20, 0x16, 0x06, 0x01});
  REQUIRE(f.has_value());
  CHECK(f.value().profile_number == 0x2016);
  CHECK(f.value().profile() == cx::profile_group::drivecom);
  CHECK(f.value().profile_version() == 0x016);
  CHECK(f.value().id() == cx::function_group_id::position);
  CHECK(f.value().version == 1);
  CHECK(cx::to_string(f.value().profile()) == "DRIVECOM");
  CHECK(cx::to_string(f.value().id()) == "position functions");
  CHECK(v(cx::encode_function_group(f.value())) == bytes{0x20, 0x16, 0x06, 0x01});
  CHECK(cx::make_profile_number(cx::profile_group::drivecom, 22).value() == 0x2016);
  CHECK(cx::make_profile_number(cx::profile_group::drivecom, 0x1000).error() == errc::out_of_range);
  // a read-only object: codes the tables do not list are kept, with no text
  auto odd = cx::decode_function_group(bytes{0x30, 0x00, 0x0B, 0x00});
  REQUIRE(odd.has_value());
  CHECK(cx::to_string(odd.value().profile()).empty());
  CHECK(cx::to_string(odd.value().id()).empty());
  CHECK(cx::decode_function_group(bytes(3)).error() == errc::truncated);
  CHECK(cx::decode_function_group(bytes(5)).error() == errc::bad_length);
}

TEST_CASE("CAM_MEM (2.11.8): 24 bits MSB first, signedness named by the caller") {
  // L3252: data bytes 1..3 = MSB … LSB
  CHECK(v(cx::encode_cam_mem_unsigned(0x123456).value()) == bytes{0x12, 0x34, 0x56});
  CHECK(cx::decode_cam_mem_unsigned(bytes{0x12, 0x34, 0x56}).value() == 0x123456U);
  CHECK(v(cx::encode_cam_mem_unsigned(16'777'215U).value()) == bytes{0xFF, 0xFF, 0xFF});
  CHECK(cx::decode_cam_mem_unsigned(bytes{0xFF, 0xFF, 0xFF}).value() == 16'777'215U);
  CHECK(v(cx::encode_cam_mem_signed(-1).value()) == bytes{0xFF, 0xFF, 0xFF});
  CHECK(cx::decode_cam_mem_signed(bytes{0xFF, 0xFF, 0xFF}).value() == -1);
  CHECK(v(cx::encode_cam_mem_signed(-8'388'608LL).value()) == bytes{0x80, 0x00, 0x00});
  CHECK(cx::decode_cam_mem_signed(bytes{0x80, 0x00, 0x00}).value() == -8'388'608);
  CHECK(v(cx::encode_cam_mem_signed(std::uint64_t{8'388'607}).value()) == bytes{0x7F, 0xFF, 0xFF});
  // nothing wraps into 24 bits
  CHECK(cx::encode_cam_mem_unsigned(16'777'216).error() == errc::out_of_range);
  CHECK(cx::encode_cam_mem_unsigned(-1).error() == errc::out_of_range);
  CHECK(cx::encode_cam_mem_unsigned(~std::uint64_t{0}).error() == errc::out_of_range);
  CHECK(cx::encode_cam_mem_signed(8'388'608).error() == errc::out_of_range);
  CHECK(cx::encode_cam_mem_signed(-8'388'609).error() == errc::out_of_range);
  CHECK(cx::encode_cam_mem_signed(~std::uint64_t{0}).error() == errc::out_of_range);
  CHECK(cx::decode_cam_mem_unsigned(bytes(2)).error() == errc::truncated);
  CHECK(cx::decode_cam_mem_signed(bytes(4)).error() == errc::bad_length);
  // CAM_MEM_P (2.11.7): 1 … 5460
  CHECK(v(cx::encode_cam_mem_pointer(5460).value()) == bytes{0x15, 0x54});
  CHECK(cx::encode_cam_mem_pointer(0).error() == errc::out_of_range);
  CHECK(cx::encode_cam_mem_pointer(5461L).error() == errc::out_of_range);
  CHECK(cx::encode_cam_mem_pointer(65537).error() == errc::out_of_range);
  CHECK(cx::decode_cam_mem_pointer(bytes{0x00, 0x01}).value() == 1);
  CHECK(cx::decode_cam_mem_pointer(bytes{0x15, 0x55}).error() == errc::out_of_range);
  CHECK(cx::decode_cam_mem_pointer(bytes{0x00}).error() == errc::truncated);
}

TEST_CASE("S23_S26 (2.5.7): four status words") {
  // L1421-1422: sub-index 1 drive, 2 switch, 3 limits, 4 final stage
  CHECK(cx::status_number(cx::diagnosis_item::drive).value() == 23);
  CHECK(cx::status_number(cx::diagnosis_item::final_stage).value() == 26);
  CHECK(cx::diagnosis_item_of(3).value() == cx::diagnosis_item::limits);
  CHECK(cx::diagnosis_item_of(0).error() == errc::unknown_object);
  CHECK(cx::diagnosis_item_of(257).error() == errc::unknown_object); // would wrap to 1
  CHECK(cx::to_string(cx::diagnosis_item::switch_) == "S24 status switch");
  // data byte 1 = bits 15..8, data byte 2 = bits 7..0
  auto w = cx::diagnosis_word::decode(bytes{0x80, 0x01});
  REQUIRE(w.has_value());
  CHECK(w.value().raw == 0x8001);
  CHECK(w.value().bit(15).value());
  CHECK(w.value().bit(0).value());
  CHECK_FALSE(w.value().bit(1).value());
  CHECK(w.value().bit(16).error() == errc::out_of_range);
  CHECK(w.value().bit(-1).error() == errc::out_of_range);
  CHECK(v(w.value().bytes()) == bytes{0x80, 0x01});
  CHECK(cx::diagnosis_word::decode(bytes{0x80}).error() == errc::truncated);
  CHECK(cx::diagnosis_word::decode(bytes{0x80, 0, 0}).error() == errc::bad_length);
}

// PCP confirmations (docs/compax.md, "PCP responses"): the manual prints requests only; the
// layout follows the PCP service definitions as Interbus drive manuals print them.
TEST_CASE("PCP confirmations: read (+), write (+), negative") {
  // read of LAGE_ZIEL (2.7.3 example value −1000.000 mm = FF F0 BD C0)
  auto req = cx::pcp_read(0x607A, 0).value();
  req.invoke_id = 0x00;
  req.comm_ref = 0x02;
  const bytes read_ok{0x80, 0x81, 0x00, 0x05, 0x00, 0x02, 0x00,
                      0x00, 0x00, 0x04, 0xFF, 0xF0, 0xBD, 0xC0};
  auto r = cx::decode_pcp_response(read_ok);
  REQUIRE(r.has_value());
  CHECK(r.value().service == cx::pcp_service::read_request);
  CHECK_FALSE(r.value().is_error);
  CHECK(r.value().comm_ref == 2);
  CHECK(bytes(r.value().payload().begin(), r.value().payload().end()) ==
        bytes{0xFF, 0xF0, 0xBD, 0xC0});
  CHECK(cx::answers(req, r.value()));
  const std::array<std::uint8_t, 4> data{0xFF, 0xF0, 0xBD, 0xC0};
  CHECK(cx::pcp_confirm(req, data).value() == r.value());
  std::array<std::uint8_t, 64> wire{};
  auto n = cx::encode_pcp_response(r.value(), wire);
  REQUIRE(n.has_value());
  CHECK(bytes(wire.begin(), wire.begin() + static_cast<std::ptrdiff_t>(n.value())) == read_ok);
  CHECK(n.value() == cx::pcp_response_size(r.value()));

  // odd length: one pad byte 0x00 (a CONTROL read would be 1 byte; here S30 sub 1 = E10)
  const bytes read_odd{0x80, 0x81, 0x00, 0x04, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01, 0x0A, 0x00};
  auto odd = cx::decode_pcp_response(read_odd);
  REQUIRE(odd.has_value());
  CHECK(odd.value().length == 1);
  CHECK(odd.value().data[0] == 0x0A);
  bytes bad_pad = read_odd;
  bad_pad.back() = 0x20;
  CHECK(cx::decode_pcp_response(bad_pad).error() == errc::unexpected_frame);

  // write (+): the result word only (counter 2)
  const bytes write_ok{0x80, 0x82, 0x00, 0x02, 0x00, 0x02, 0x00, 0x00};
  auto w = cx::decode_pcp_response(write_ok);
  REQUIRE(w.has_value());
  CHECK(w.value().service == cx::pcp_service::write_request);
  CHECK(w.value().length == 0);
  auto wreq = cx::pcp_write(0x5FE9, 0, bytes{0x01}).value();
  wreq.comm_ref = 2;
  CHECK(cx::answers(wreq, w.value()));
  CHECK_FALSE(cx::answers(req, w.value()));
  CHECK(cx::pcp_confirm(wreq).value() == w.value());

  // negative: error class / error code, additional code (counter 3). The bytes are those of
  // the negative read confirmation in the SEW UFI11A Interbus manual's application example.
  const bytes refused{0x80, 0x81, 0x00, 0x03, 0x00, 0x02, 0x08, 0x00, 0x00, 0x10};
  auto e = cx::decode_pcp_response(refused);
  REQUIRE(e.has_value());
  CHECK(e.value().is_error);
  CHECK(e.value().error_class == 8);
  CHECK(e.value().error_code == 0);
  CHECK(e.value().additional_code == 0x10);
  CHECK(cx::pcp_refuse(req, 8, 0, 0x10).value() == e.value());
  n = cx::encode_pcp_response(e.value(), wire);
  CHECK(bytes(wire.begin(), wire.begin() + static_cast<std::ptrdiff_t>(n.value())) == refused);
}

TEST_CASE("PCP confirmations: bad input") {
  const bytes read_ok{0x80, 0x81, 0x00, 0x05, 0x00, 0x02, 0x00,
                      0x00, 0x00, 0x04, 0xFF, 0xF0, 0xBD, 0xC0};
  for (std::size_t k = 0; k < read_ok.size(); ++k) {
    CAPTURE(k);
    CHECK(cx::decode_pcp_response(std::span{read_ok}.first(k)).error() == errc::truncated);
  }
  bytes longer = read_ok;
  longer.push_back(0);
  CHECK(cx::decode_pcp_response(longer).error() == errc::bad_length);
  bytes counter = read_ok;
  counter[3] = 6;
  CHECK(cx::decode_pcp_response(counter).error() == errc::bad_length);
  bytes code = read_ok;
  code[1] = 0x83;
  CHECK(cx::decode_pcp_response(code).error() == errc::unknown_command);
  bytes len_hi = read_ok;
  len_hi[8] = 0x01;
  CHECK(cx::decode_pcp_response(len_hi).error() == errc::unexpected_frame);
  bytes too_long = read_ok;
  too_long[9] = 33;
  CHECK(cx::decode_pcp_response(too_long).error() == errc::bad_length);
  // a result word 0x00xx is no error class
  const bytes no_class{0x80, 0x81, 0x00, 0x03, 0x00, 0x02, 0x00, 0x05, 0x00, 0x00};
  CHECK(cx::decode_pcp_response(no_class).error() == errc::unexpected_frame);
  // negative with the wrong counter, write (+) with data
  const bytes neg_counter{0x80, 0x82, 0x00, 0x02, 0x00, 0x02, 0x06, 0x05, 0x00, 0x11};
  CHECK(cx::decode_pcp_response(neg_counter).error() == errc::bad_length);
  const bytes write_data{0x80, 0x82, 0x00, 0x03, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01};
  CHECK(cx::decode_pcp_response(write_data).error() == errc::bad_length);
  // builders refuse what the wire cannot say
  const auto req = cx::pcp_read(0x5FE8, 1).value();
  CHECK(cx::pcp_refuse(req, 0, 1, 2).error() == errc::invalid_argument);
  CHECK(cx::pcp_confirm(req, bytes(33)).error() == errc::bad_length);
  CHECK(cx::pcp_confirm(cx::pcp_write(0x5FE9, 0, bytes{1}).value(), bytes{1}).error() ==
        errc::bad_length);
  cx::pcp_response r{};
  r.is_error = true; // error class 0
  r.param_counter = 3;
  std::array<std::uint8_t, 16> wire{};
  CHECK(cx::encode_pcp_response(r, wire).error() == errc::invalid_argument);
  r = cx::pcp_confirm(req, bytes{1, 2}).value();
  std::array<std::uint8_t, 8> small{};
  CHECK(cx::encode_pcp_response(r, small).error() == errc::buffer_too_small);
}

TEST_CASE("LAGE_ZIEL set-point handshake (2.7.3, transitions 1-4)") {
  using cx::statuswort_bit;
  using cx::steuerwort_bit;
  const cx::steuerwort base = cx::steuerwort{}.with(steuerwort_bit::enable_operation);
  const cx::statuswort no_ack{};
  const cx::statuswort ack = cx::statuswort{}.with(statuswort_bit::set_point_acknowledge);
  cx::set_point_handshake hs;
  CHECK_FALSE(hs.control(base).test(steuerwort_bit::new_set_point));
  // 2.7.3 example value: −1000.000 mm absolute → FF F0 BD C0
  REQUIRE(hs.submit(decimal{-1000, 0}, false, no_ack, base).has_value());
  CHECK(v(hs.target_bytes()) == bytes{0xFF, 0xF0, 0xBD, 0xC0});
  // transition 1: new set point = 1 with the target
  auto cw = hs.control(base);
  CHECK(cw.test(steuerwort_bit::new_set_point));
  CHECK_FALSE(cw.test(steuerwort_bit::target_position_relative));
  CHECK(cw.test(steuerwort_bit::enable_operation)); // other bits kept
  CHECK(hs.submit(decimal{1, 0}, false, no_ack, base).error() == errc::bad_state);
  CHECK_FALSE(hs.poll(no_ack, cw)); // not acknowledged yet
  CHECK(hs.current_phase() == cx::set_point_handshake::phase::announced);
  // transition 2: the drive acknowledges → poll says so once; transition 3: new set point = 0
  CHECK(hs.poll(ack, cw));
  CHECK_FALSE(hs.poll(ack, cw));
  cw = hs.control(base);
  CHECK_FALSE(cw.test(steuerwort_bit::new_set_point));
  CHECK(hs.busy());
  // transition 4: acknowledgement back to 0 → idle
  CHECK_FALSE(hs.poll(no_ack, cw));
  CHECK_FALSE(hs.busy());
  // relative target (STEUERWORT bit 6), refused while the drive still acknowledges
  CHECK(hs.submit(decimal{5, 1}, true, ack, base).error() == errc::bad_state);
  REQUIRE(hs.submit(decimal{5, 1}, true, no_ack, base).has_value());
  CHECK(hs.control(base).test(steuerwort_bit::target_position_relative));
  CHECK(v(hs.target_bytes()) == bytes{0x00, 0x00, 0x01, 0xF4});
  // a pop-up message (SPM differs) carries no handshake bit
  const cx::statuswort popup = ack.with(statuswort_bit::spm);
  CHECK_FALSE(hs.poll(popup, hs.control(base)));
  CHECK(hs.current_phase() == cx::set_point_handshake::phase::announced);
  hs.cancel();
  CHECK_FALSE(hs.control(base).test(steuerwort_bit::new_set_point));
  // targets the Integer32 cannot carry
  CHECK(hs.submit(decimal{1, 4}, false, no_ack, base).error() == errc::not_representable);
  CHECK(hs.submit(decimal{-2147483648, 3}, false, no_ack, base).error() == errc::overflow);
  CHECK(hs.submit(decimal{2147484, 0}, false, no_ack, base).error() == errc::overflow);
  CHECK(hs.submit(decimal{1, 0}, false, popup, base).error() == errc::bad_state);
  CHECK_FALSE(hs.busy());
}

TEST_CASE("STEUERWORT / STATUSWORT: the manual's own terms") {
  using cx::steuerwort_bit;
  // 2.4.7 (L1021-1032): the manual's names are second names of the same bits
  static_assert(steuerwort_bit::power_on == steuerwort_bit::switch_on);
  static_assert(steuerwort_bit::disable_voltage_n == steuerwort_bit::enable_voltage);
  static_assert(steuerwort_bit::rapid_stop_n == steuerwort_bit::quick_stop);
  static_assert(steuerwort_bit::reset_fault == steuerwort_bit::fault_reset);
  static_assert(steuerwort_bit::target_position_relative == steuerwort_bit::relative);
  CHECK(cx::manual_term(steuerwort_bit::power_on) == "Power on");
  CHECK(cx::manual_term(steuerwort_bit::enable_voltage) == "Disable voltage");
  CHECK(cx::manual_term(steuerwort_bit::quick_stop) == "Rapid stop");
  CHECK(cx::manual_term(steuerwort_bit::new_set_point) == "New set point");
  CHECK(cx::manual_term(steuerwort_bit::fault_reset) == "Reset fault");
  CHECK(cx::manual_term(steuerwort_bit::approach_machine_zero) == "Approach machine zero (MZ)");
  CHECK(cx::manual_term(steuerwort_bit::spm) == "SPM");
  CHECK(cx::manual_term(static_cast<steuerwort_bit>(5)).empty());
  // active low: the bit set means voltage enabled / no rapid stop (CiA 402 0x06 "shutdown")
  CHECK(cx::steuerwort{}
            .with(steuerwort_bit::disable_voltage_n)
            .with(steuerwort_bit::rapid_stop_n)
            .raw == 0x0006);
  // STATUSWORT (2.4.8, L1049-1058)
  using cx::statuswort_bit;
  static_assert(statuswort_bit::ready_to_start == statuswort_bit::ready_to_switch_on);
  static_assert(statuswort_bit::actual_value_acknowledgement ==
                statuswort_bit::set_point_acknowledge);
  static_assert(statuswort_bit::mn_reached == statuswort_bit::machine_zero_reached);
  CHECK(cx::manual_term(statuswort_bit::set_point_acknowledge) == "Actual value acknowledgement");
  CHECK(cx::manual_term(statuswort_bit::message) == "Message/AckToggle");
  CHECK(cx::manual_term(statuswort_bit::mn_reached) == "MN was reached");
}
