// COMPAX control and status objects (manual 000, 2.4.3-2.4.10, 2.7.13, 2.7.14, 2.8.2, 2.9.1,
// 2.10, 2.12.8), fault codes (2.5.1) and P196 (chapter 4).
#include <fieldcodec/compax/control.hpp>
#include <fieldcodec/compax/faults.hpp>
#include <fieldcodec/compax/process_data.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

namespace cx = fieldcodec::compax;
using fieldcodec::decimal;
using fieldcodec::errc;
using b2 = std::array<std::uint8_t, 2>;

// STEUERBYTE: record select in bits 3..0 (CX-16), start, continue, stop, quit.
static_assert([] {
  cx::steuerbyte s{};
  if (!s.set_record(5)) return false;
  s.set(cx::steuerbyte_bit::start);
  return s.raw == 0x15 && s.record() == 5 && s.test(cx::steuerbyte_bit::record_1) == false &&
         s.set_record(16).error() == errc::out_of_range;
}());

// CPX_STW: FreezePAD 1[0] = bit 8, ObjectReqEnable 1[1] = bit 9 (CX-17); Hand+ 2[1], Hand- 2[2]
// (CX-18).
static_assert(cx::cpx_stw{}.with(cx::cpx_stw_bit::freeze_pad).bytes() == b2{0x01, 0x00});
static_assert(cx::cpx_stw{}.with(cx::cpx_stw_bit::object_req_enable).bytes() == b2{0x02, 0x00});
static_assert(cx::cpx_stw{}.with(cx::cpx_stw_bit::hand_plus).bytes() == b2{0x00, 0x02});
static_assert(cx::cpx_stw{}.with(cx::cpx_stw_bit::hand_minus).bytes() == b2{0x00, 0x04});
static_assert(cx::cpx_stw_bit::approach_machine_zero == cx::cpx_stw_bit::hand_plus);

// CPX_ZSW: "no fault" and "no warning" are inverted.
static_assert(!cx::has_fault(cx::cpx_zsw{0x0003}));
static_assert(cx::has_fault(cx::cpx_zsw{0x0002}));
static_assert(cx::has_warning(cx::cpx_zsw{0x0001}));
static_assert(cx::has_fault(cx::cpx_zsw_s16{0x0000}));
static_assert(cx::cpx_zsw::decode(b2{0x01, 0x03}).value().test(cx::cpx_zsw_bit::ack_toggle));
static_assert(cx::output_a0(cx::cpx_zsw_s16{0x0040}).value() == 1);
static_assert(cx::output_a0(cx::cpx_zsw_s16{0x0080}).value() == 2);
static_assert(cx::output_a0(cx::cpx_zsw_s16{0x00C0}).error() == errc::out_of_range);

// STEUERWORT / STATUSWORT: DRIVECOM low byte, COMPAX high byte.
static_assert(cx::steuerwort{}
                  .with(cx::steuerwort_bit::switch_on)
                  .with(cx::steuerwort_bit::enable_voltage)
                  .with(cx::steuerwort_bit::quick_stop)
                  .with(cx::steuerwort_bit::enable_operation)
                  .raw == 0x000F);
static_assert(cx::steuerwort{}.with(cx::steuerwort_bit::spm).bytes() == b2{0x80, 0x00});
static_assert(cx::statuswort::decode(b2{0x01, 0x27}).value().test(cx::statuswort_bit::ack_toggle));
static_assert(
    cx::statuswort::decode(b2{0x01, 0x27}).value().test(cx::statuswort_bit::operation_enabled));

TEST_CASE("STATUSWORT pop-up messages (2.4.9)") {
  const cx::steuerwort c{};
  CHECK(!cx::shows_popup(cx::statuswort{0x0027}, c));
  CHECK(cx::decode_popup(cx::statuswort{0x0027}, c).error() == errc::bad_state);
  // SPM toggled, identifier 1 (error), error number 10
  const cx::statuswort s{0x810A};
  CHECK(cx::shows_popup(s, c));
  CHECK(cx::decode_popup(s, c).value() == cx::popup_message{cx::popup_kind::error, 10});
  CHECK(cx::decode_popup(cx::statuswort{0x830A}, c).value().kind ==
        cx::popup_kind::comparator_reached);
  CHECK(cx::decode_popup(cx::statuswort{0x840A}, c).error() == errc::out_of_range);
  const auto ack = cx::acknowledge_popup(s, c);
  CHECK(!cx::shows_popup(s, ack));
}

TEST_CASE("CONTROL, selection codes, polarity, override, I/O words") {
  CHECK(cx::decode_control(1).value() == cx::control_command::go_to_machine_zero);
  CHECK(cx::decode_control(21).value() == cx::control_command::object_rsp_disable);
  CHECK(cx::decode_control(0).error() == errc::out_of_range);
  CHECK(cx::decode_control(22).error() == errc::out_of_range);
  for (unsigned n = 1; n <= 21; ++n) {
    CHECK(!cx::to_string(static_cast<cx::control_command>(n)).empty());
  }
  CHECK(cx::decode_selection<cx::operating_mode>(b2{0xFF, 0xFE}).value() ==
        cx::operating_mode::reset);
  CHECK(cx::decode_selection<cx::operating_mode>(b2{0x00, 0x02}).error() == errc::out_of_range);
  CHECK(cx::decode_selection<cx::ref_mode>(b2{0x00, 0x0C}).value() ==
        cx::ref_mode::initiator_direction_2);
  CHECK(cx::decode_selection<cx::ramp_form>(b2{0x00, 0x02}).value() == cx::ramp_form::jerk_free);
  CHECK(cx::decode_selection<cx::ramp_form>(b2{0x00, 0x01}).error() == errc::out_of_range);
  CHECK(cx::decode_selection<cx::ramp_form>(std::array<std::uint8_t, 1>{0}).error() ==
        errc::truncated);
  CHECK(cx::decode_polarity(0x80));
  CHECK(cx::decode_polarity(0xFF));
  CHECK(!cx::decode_polarity(0x7F));
  CHECK(cx::encode_polarity(false) == 0x00);
  CHECK(cx::encode_override(decimal{100, 0}).value() == 255);
  CHECK(cx::encode_override(decimal{0, 0}).value() == 0);
  CHECK(cx::encode_override(decimal{1001, 1}).error() == errc::out_of_range);
  CHECK(cx::encode_override(decimal{-1, 0}).error() == errc::out_of_range);
  CHECK(fieldcodec::equal(cx::decode_override(255).value(), decimal{100, 0}));
  CHECK(fieldcodec::equal(cx::decode_override(0x80).value(), decimal{5020, 2}));
  cx::io_word w{};
  CHECK(w.set(17).error() == errc::out_of_range);
  REQUIRE(w.set(1).has_value());
  REQUIRE(w.set(16).has_value());
  CHECK(w.bytes() == b2{0x80, 0x01});
  CHECK(cx::io_word::decode(b2{0x80, 0x01}).value().test(16).value());
  CHECK(!cx::io_word::decode(b2{0x80, 0x01}).value().test(2).value());
  cx::cpx_stw v{};
  REQUIRE(v.set_virtual_input(32, true).has_value());
  CHECK(v.bytes() == b2{0x80, 0x00});
  CHECK(v.virtual_input(32).value());
  CHECK(v.virtual_input(16).error() == errc::out_of_range);
  // any integer type, checked (2^32 + 17 is not E17)
  CHECK(v.virtual_input((std::int64_t{1} << 32) + 17).error() == errc::out_of_range);
  CHECK(v.set_virtual_input(std::uint64_t{17}, true).has_value());
  CHECK(v.virtual_input(short{17}).value());
  CHECK(w.test(-1).error() == errc::out_of_range);
  CHECK(w.test((std::int64_t{1} << 32) + 1).error() == errc::out_of_range);
  CHECK(w.set(std::uint64_t{17}).error() == errc::out_of_range);
  cx::steuerbyte sb{};
  CHECK(sb.set_record(271).error() == errc::out_of_range); // would be record 15 if wrapped
  CHECK(sb.set_record(-1).error() == errc::out_of_range);
  CHECK(sb.set_record(std::uint64_t{15}).has_value());
  CHECK(sb.record() == 15);
}

TEST_CASE("STOERUNG fault codes and error texts (2.5.1, chapter 5)") {
  CHECK(cx::fault_code_of(10).raw == 0x8611);
  CHECK(cx::fault_code_of(10).main_group() == 8);
  CHECK(cx::fault_code_of(10).subgroup() == 6);
  CHECK(cx::fault_code_of(10).details() == 0x11);
  CHECK(cx::fault_code_of(0).raw == 0);
  CHECK(!cx::fault_code_of(0).is_fault());
  CHECK(cx::fault_code_of(65).raw == 0x7305);
  CHECK(cx::fault_code_of(200).raw == 0x1000);
  CHECK(cx::fault_code::decode(b2{0x86, 0x11}).value() == cx::fault_code{0x8611});
  CHECK(cx::error_text(73) == "bus time-out");
  CHECK(cx::error_text(3).empty());
  for (std::size_t i = 0; i < cx::compax_errors.size(); ++i)
    CHECK(cx::compax_errors[i].number == i);
}

TEST_CASE("P196 channel layouts (1.4, chapter 4)") {
  const auto eight = cx::p196::decode(0xA4).value();
  CHECK(eight.pd_mode == 4);
  CHECK(!eight.has_pcp());
  CHECK(eight.pd_bytes() == 8);
  CHECK(eight.first_free_pd_byte() == 3);
  CHECK(eight.temporary_object_req);
  CHECK(eight.cpx_words);
  CHECK(!eight.object_rsp_explicit);
  CHECK(eight.id_code() == 3);
  CHECK(eight.raw() == 0xA4);
  CHECK(cx::p196::decode(0).value().pd_bytes() == 2);
  CHECK(cx::p196::decode(3).value().pd_bytes() == 6);
  CHECK(cx::p196::decode(3).value().id_code() == 227);
  CHECK(cx::p196::decode(5).error() == errc::out_of_range);
  CHECK(cx::p196::decode(8).error() == errc::out_of_range);
}
