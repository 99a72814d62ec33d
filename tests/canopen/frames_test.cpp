// CAN frame, COB-IDs, NMT, heartbeat, node guarding, SYNC, TIME, EMCY.
#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/sync.hpp>
#include <fieldcodec/canopen/time_stamp.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>

namespace co = fieldcodec::canopen;
using fieldcodec::errc;

namespace {
constexpr co::can_frame F(std::uint16_t id, std::initializer_list<std::uint8_t> b) {
  return co::make_frame(id, b).value();
}
} // namespace

// DPQ manual (004), NMT example: start node 5 -> 0x000: 01 05.
static_assert(co::nmt::encode(co::nmt::command::start, 5).value() == F(0x000, {0x01, 0x05}));
static_assert(co::cob_id::sdo_rx(5).value() == 0x605);
static_assert(co::cob_id::sdo_tx(5).value() == 0x585);
static_assert(co::cob_id::tpdo(1, 5).value() == 0x185);

TEST_CASE("can_frame construction and validation") {
  const auto f = F(0x123, {1, 2, 3});
  CHECK(f.dlc == 3);
  CHECK(f.payload().size() == 3);
  CHECK(f.is_valid());
  CHECK(co::make_frame(0x800, {}) == errc::invalid_argument);
  const std::array<std::uint8_t, 9> nine{};
  CHECK(co::make_frame(0x100, nine) == errc::too_long);
  auto r = co::make_remote_frame(0x705, 1).value();
  CHECK(r.rtr);
  CHECK(r.payload().empty());
  CHECK(co::make_remote_frame(0x705, 9) == errc::bad_length);
  CHECK(co::make_remote_frame(0x800, 1) == errc::invalid_argument);
  co::can_frame bad = f;
  bad.data[5] = 1; // garbage beyond the DLC
  CHECK(!bad.is_valid());
  bad = f;
  bad.dlc = 9;
  CHECK(!bad.is_valid());
  CHECK(co::expect_data(bad, 8) == errc::bad_length);
  CHECK(co::expect_data(r, 1) == errc::unexpected_frame);
}

TEST_CASE("COB-IDs of the predefined connection set") {
  CHECK(co::cob_id::emcy(1).value() == 0x081);
  CHECK(co::cob_id::emcy(127).value() == 0x0FF);
  CHECK(co::cob_id::emcy(0) == errc::invalid_argument);
  CHECK(co::cob_id::emcy(128) == errc::invalid_argument);
  const std::uint16_t tpdo_base[] = {0x180, 0x280, 0x380, 0x480};
  const std::uint16_t rpdo_base[] = {0x200, 0x300, 0x400, 0x500};
  for (unsigned n = 1; n <= 4; ++n) {
    CHECK(co::cob_id::tpdo(n, 7).value() == tpdo_base[n - 1] + 7);
    CHECK(co::cob_id::rpdo(n, 7).value() == rpdo_base[n - 1] + 7);
  }
  CHECK(co::cob_id::tpdo(0, 7) == errc::invalid_argument);
  CHECK(co::cob_id::rpdo(5, 7) == errc::invalid_argument);
  CHECK(co::cob_id::tpdo(1, 0) == errc::invalid_argument);
  CHECK(co::cob_id::nmt_error(127).value() == 0x77F);
  CHECK(co::cob_id::sdo_rx(0) == errc::invalid_argument);
  CHECK(co::check_node_id(0) == errc::invalid_argument);
  CHECK(co::check_node_id(1).has_value());

  using co::function;
  CHECK(co::classify(0x000).value() == co::cob_id_info{function::nmt, 0});
  CHECK(co::classify(0x080).value() == co::cob_id_info{function::sync, 0});
  CHECK(co::classify(0x085).value() == co::cob_id_info{function::emcy, 5});
  CHECK(co::classify(0x100).value() == co::cob_id_info{function::time, 0});
  CHECK(co::classify(0x185).value() == co::cob_id_info{function::tpdo1, 5});
  CHECK(co::classify(0x205).value() == co::cob_id_info{function::rpdo1, 5});
  CHECK(co::classify(0x4FF).value() == co::cob_id_info{function::tpdo4, 127});
  CHECK(co::classify(0x501).value() == co::cob_id_info{function::rpdo4, 1});
  CHECK(co::classify(0x585).value() == co::cob_id_info{function::sdo_tx, 5});
  CHECK(co::classify(0x605).value() == co::cob_id_info{function::sdo_rx, 5});
  CHECK(co::classify(0x705).value() == co::cob_id_info{function::nmt_error, 5});
  CHECK(co::classify(0x680).value().fn == function::unassigned);
  CHECK(co::classify(0x685).value().fn == function::unassigned);
  CHECK(co::classify(0x7E5).value().fn == function::unassigned); // LSS range
  CHECK(co::classify(0x200).value().fn == function::unassigned);
  CHECK(co::classify(0x800) == errc::invalid_argument);
  CHECK(co::to_string(function::sdo_rx) == "SDO rx");
}

TEST_CASE("NMT commands") {
  using co::nmt::command;
  CHECK(co::nmt::encode(command::stop, 0).value() == F(0, {0x02, 0x00})); // all nodes
  CHECK(co::nmt::encode(command::enter_pre_operational, 127).value() == F(0, {0x80, 0x7F}));
  CHECK(co::nmt::encode(command::reset_node, 1).value() == F(0, {0x81, 0x01}));
  CHECK(co::nmt::encode(command::reset_communication, 3).value() == F(0, {0x82, 0x03}));
  CHECK(co::nmt::encode(command::start, 128) == errc::invalid_argument);
  CHECK(co::nmt::decode(F(0, {0x01, 0x05})).value() == co::nmt::message{command::start, 5});
  CHECK(co::nmt::decode(F(0, {0x01})) == errc::bad_length);
  CHECK(co::nmt::decode(F(0, {0x01, 0x05, 0x00})) == errc::bad_length);
  CHECK(co::nmt::decode(F(0, {0x03, 0x05})) == errc::unknown_command);
  CHECK(co::nmt::decode(F(0, {0x01, 0x80})) == errc::invalid_argument);
  CHECK(co::nmt::decode(F(1, {0x01, 0x05})) == errc::unexpected_frame);
  CHECK(co::nmt::state_after(command::start) == co::nmt::state::operational);
  CHECK(co::nmt::state_after(command::stop) == co::nmt::state::stopped);
  CHECK(co::nmt::state_after(command::enter_pre_operational) == co::nmt::state::pre_operational);
  CHECK(co::nmt::state_after(command::reset_node) == co::nmt::state::boot_up);
}

TEST_CASE("boot-up and heartbeat") {
  using co::nmt::state;
  CHECK(co::nmt::encode_boot_up(5).value() == F(0x705, {0x00}));
  CHECK(co::nmt::encode_heartbeat(5, state::operational).value() == F(0x705, {0x05}));
  CHECK(co::nmt::encode_heartbeat(5, state::pre_operational).value() == F(0x705, {0x7F}));
  CHECK(co::nmt::encode_heartbeat(5, state::stopped).value() == F(0x705, {0x04}));
  CHECK(co::nmt::encode_heartbeat(0, state::stopped) == errc::invalid_argument);
  auto hb = co::nmt::decode_heartbeat(F(0x705, {0x00})).value();
  CHECK(hb.is_boot_up());
  CHECK(hb.node == 5);
  CHECK(co::nmt::decode_heartbeat(F(0x77F, {0x7F})).value().s == state::pre_operational);
  CHECK(co::nmt::decode_heartbeat(F(0x705, {0x85})) == errc::out_of_range); // toggle set
  CHECK(co::nmt::decode_heartbeat(F(0x705, {0x06})) == errc::out_of_range);
  CHECK(co::nmt::decode_heartbeat(F(0x705, {})) == errc::bad_length);
  CHECK(co::nmt::decode_heartbeat(F(0x705, {5, 0})) == errc::bad_length);
  CHECK(co::nmt::decode_heartbeat(F(0x700, {5})) == errc::unexpected_frame);
  CHECK(co::nmt::decode_heartbeat(F(0x605, {5})) == errc::unexpected_frame);
  CHECK(co::nmt::decode_heartbeat(co::make_remote_frame(0x705, 1).value()) ==
        errc::unexpected_frame);
}

// Issue 12 #5: a widely used master sends the guarding RTR with DLC 0; CiA 301 shows DLC 1. The
// node must answer both (before the fix, DLC 0 was refused with bad_length and the master saw a
// dead node).
TEST_CASE("node guarding: a remote request is answered whatever its DLC") {
  using co::nmt::state;
  co::nmt::guard_responder node(5);
  for (std::uint8_t dlc = 0; dlc <= 8; ++dlc) {
    CAPTURE(static_cast<int>(dlc));
    const auto req = co::make_remote_frame(0x705, dlc).value();
    CHECK(co::nmt::decode_guard_request(req).value() == 5);
    const auto toggle = static_cast<std::uint8_t>(dlc % 2U == 0U ? 0x00U : 0x80U);
    CHECK(node.respond(req, state::operational).value() ==
          F(0x705, {static_cast<std::uint8_t>(toggle | 0x05U)}));
  }
}

TEST_CASE("node guarding with the alternating toggle") {
  using co::nmt::state;
  const auto req = co::nmt::encode_guard_request(5).value();
  CHECK(req.rtr);
  CHECK(req.id == 0x705);
  CHECK(req.dlc == 1);
  CHECK(co::nmt::decode_guard_request(req).value() == 5);
  CHECK(co::nmt::decode_guard_request(F(0x705, {0})) == errc::unexpected_frame);
  co::can_frame nine = co::make_remote_frame(0x705, 8).value();
  nine.dlc = 9;
  CHECK(co::nmt::decode_guard_request(nine) == errc::bad_length);

  co::nmt::guard_responder node(5);
  co::nmt::guard_monitor master(5);
  const std::uint8_t expected[] = {0x05, 0x85, 0x05, 0x85};
  for (auto b : expected) {
    auto resp = node.respond(req, state::operational).value();
    CHECK(resp == F(0x705, {b}));
    CHECK(master.accept(resp).value() == state::operational);
  }
  // a repeated toggle is an error, and the monitor keeps expecting the same toggle
  CHECK(master.accept(F(0x705, {0x85})) == errc::bad_toggle);
  CHECK(master.accept(F(0x705, {0x85})) == errc::bad_toggle);
  CHECK(master.accept(F(0x705, {0x7F})).value() == state::pre_operational);
  CHECK(master.accept(F(0x706, {0xFF})) == errc::unexpected_frame);
  CHECK(master.accept(F(0x705, {0x80})) == errc::out_of_range); // boot-up is no guarding state
  master.reset();
  CHECK(!master.expected_toggle());
  CHECK(co::nmt::encode_guard_response(5, state::boot_up, false) == errc::invalid_argument);
  CHECK(node.respond(co::nmt::encode_guard_request(6).value(), state::stopped) ==
        errc::unexpected_frame);
  CHECK(co::nmt::decode_guard_response(F(0x705, {0x84})).value() ==
        co::nmt::guard_response{5, state::stopped, true});
  CHECK(co::nmt::decode_guard_response(F(0x705, {})) == errc::bad_length);
}

TEST_CASE("SYNC with and without counter") {
  CHECK(co::sync::encode() == F(0x080, {}));
  CHECK(co::sync::encode(1).value() == F(0x080, {1}));
  CHECK(co::sync::encode(240).value() == F(0x080, {240}));
  CHECK(co::sync::encode(0) == errc::out_of_range);
  CHECK(co::sync::encode(241) == errc::out_of_range);
  CHECK(!co::sync::decode(F(0x080, {})).value().has_value());
  CHECK(co::sync::decode(F(0x080, {7})).value().value() == 7);
  CHECK(co::sync::decode(F(0x080, {0})) == errc::out_of_range);
  CHECK(co::sync::decode(F(0x080, {1, 2})) == errc::bad_length);
  CHECK(co::sync::decode(F(0x081, {})) == errc::unexpected_frame);
  co::sync::producer p(3);
  CHECK(p.next() == F(0x80, {1}));
  CHECK(p.next() == F(0x80, {2}));
  CHECK(p.next() == F(0x80, {3}));
  CHECK(p.next() == F(0x80, {1}));
  p.reset();
  CHECK(p.next() == F(0x80, {1}));
  co::sync::producer none;
  CHECK(none.next() == F(0x80, {}));
}

TEST_CASE("TIME") {
  const fieldcodec::od::time_value t{0x0123'4567U, 0x89AB};
  const auto f = co::time_stamp::encode(t).value();
  CHECK(f == F(0x100, {0x67, 0x45, 0x23, 0x01, 0xAB, 0x89}));
  CHECK(co::time_stamp::decode(f).value() == t);
  CHECK(co::time_stamp::encode({0x1000'0000U, 0}) == errc::out_of_range);
  CHECK(co::time_stamp::decode(F(0x100, {0, 0, 0, 0x10, 0, 0})) == errc::out_of_range);
  CHECK(co::time_stamp::decode(F(0x100, {0, 0, 0, 0, 0})) == errc::bad_length);
  CHECK(co::time_stamp::decode(F(0x101, {0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
}

TEST_CASE("EMCY") {
  co::emcy::message m{
      0x8130, co::emcy::reg::generic | co::emcy::reg::communication, {1, 2, 3, 4, 5}};
  const auto f = co::emcy::encode(5, m).value();
  CHECK(f == F(0x085, {0x30, 0x81, 0x11, 1, 2, 3, 4, 5}));
  CHECK(co::emcy::decode(f).value() == co::emcy::received{5, m});
  CHECK(co::emcy::encode(0, m) == errc::invalid_argument);
  CHECK(co::emcy::decode(F(0x085, {0, 0, 0})) == errc::bad_length);
  CHECK(co::emcy::decode(F(0x080, {0, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  CHECK(co::emcy::decode(F(0x100, {0, 0, 0, 0, 0, 0, 0, 0})) == errc::unexpected_frame);
  using co::emcy::error_class;
  CHECK(co::emcy::classify(0x0000) == error_class::no_error);
  CHECK(co::emcy::classify(0x1000) == error_class::generic);
  CHECK(co::emcy::classify(0x2310) == error_class::current);
  CHECK(co::emcy::classify(0x3210) == error_class::voltage);
  CHECK(co::emcy::classify(0x4210) == error_class::temperature);
  CHECK(co::emcy::classify(0x5000) == error_class::device_hardware);
  CHECK(co::emcy::classify(0x6100) == error_class::device_software);
  CHECK(co::emcy::classify(0x7000) == error_class::additional_modules);
  CHECK(co::emcy::classify(0x8130) == error_class::monitoring);
  CHECK(co::emcy::classify(0x9000) == error_class::external);
  CHECK(co::emcy::classify(0xF000) == error_class::additional_functions);
  CHECK(co::emcy::classify(0xFF05) == error_class::device_specific);
  CHECK(co::emcy::classify(0x0100) == error_class::unassigned);
  CHECK(co::emcy::classify(0x5100) == error_class::unassigned);
  CHECK(co::emcy::classify(0xA000) == error_class::unassigned);
  CHECK(co::emcy::to_string(error_class::monitoring) == "monitoring");
}
