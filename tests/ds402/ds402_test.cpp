// CiA 402 controlword, statusword, modes and state machine.
#include <fieldcodec/ds402/controlword.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/ds402/statusword.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>

namespace ds402 = fieldcodec::ds402;
using ds402::command;
using ds402::state;
using fieldcodec::errc;

// Compile-time checks of the tables.
static_assert(ds402::command_bits(command::shutdown) == 0x06);
static_assert(ds402::command_bits(command::switch_on) == 0x07);
static_assert(ds402::command_bits(command::switch_on_enable) == 0x0F);
static_assert(ds402::command_bits(command::fault_reset) == 0x80);
static_assert(ds402::decode_state(0x0250).value() == state::switch_on_disabled);
static_assert(ds402::decode_state(0x0237).value() == state::operation_enabled);
static_assert(ds402::decode_state(0x0001) == errc::bad_state);
static_assert(ds402::next_controlword(0x0040, state::operation_enabled, 0).value() == 0x06);
static_assert(ds402::next_controlword(0x0021, state::operation_enabled, 0x06).value() == 0x0F);

namespace {
// The statusword table of CiA 402 (and XENAX manual 4.2.3, l. 1213-1221) as printed, most
// significant bit first, 'x' = don't care. Parsed here independently of the header's masks.
struct printed_row {
  std::string_view pattern;
  state s;
};
constexpr printed_row printed_table[] = {
    {"xxxxxxxxx0xx0000", state::not_ready_to_switch_on},
    {"xxxxxxxxx1xx0000", state::switch_on_disabled},
    {"xxxxxxxxx01x0001", state::ready_to_switch_on},
    {"xxxxxxxxx01x0011", state::switched_on},
    {"xxxxxxxxx01x0111", state::operation_enabled},
    {"xxxxxxxxx00x0111", state::quick_stop_active},
    {"xxxxxxxxx0xx1111", state::fault_reaction_active},
    {"xxxxxxxxx0xx1000", state::fault},
};
bool matches(std::string_view pattern, std::uint16_t word) {
  for (std::size_t i = 0; i < 16; ++i) {
    const char c = pattern[i];
    const bool bit = ((static_cast<unsigned>(word) >> (15U - i)) & 1U) != 0U;
    if (c == '1' && !bit) return false;
    if (c == '0' && bit) return false;
  }
  return true;
}
} // namespace

TEST_CASE("every statusword decodes as the CiA 402 table says") {
  std::array<int, 8> counts{};
  int undefined = 0;
  for (std::uint32_t w = 0; w <= 0xFFFFU; ++w) {
    const auto word = static_cast<std::uint16_t>(w);
    std::optional<state> expected;
    int hits = 0;
    for (const auto &row : printed_table) {
      if (matches(row.pattern, word)) {
        expected = row.s;
        ++hits;
      }
    }
    REQUIRE(hits <= 1); // the printed rows never overlap
    const auto got = ds402::decode_state(word);
    if (expected) {
      REQUIRE(got.has_value());
      REQUIRE(got.value() == *expected);
      ++counts[static_cast<std::size_t>(*expected)];
    } else {
      REQUIRE(got == errc::bad_state);
      ++undefined;
    }
  }
  // rows with 5 significant bits match 2^11 words each, rows with 6 bits 2^10.
  CHECK(counts[0] == 2048);
  CHECK(counts[1] == 2048);
  CHECK(counts[2] == 1024);
  CHECK(counts[3] == 1024);
  CHECK(counts[4] == 1024);
  CHECK(counts[5] == 1024);
  CHECK(counts[6] == 2048);
  CHECK(counts[7] == 2048);
  CHECK(undefined == 65536 - 4 * 2048 - 4 * 1024);
}

TEST_CASE("state_bits round-trip and flags") {
  for (auto s : {state::not_ready_to_switch_on, state::switch_on_disabled,
                 state::ready_to_switch_on, state::switched_on, state::operation_enabled,
                 state::quick_stop_active, state::fault_reaction_active, state::fault}) {
    CHECK(ds402::decode_state(ds402::state_bits(s)).value() == s);
    CHECK(!ds402::to_string(s).empty());
  }
  const auto f = ds402::decode_flags(0x1637);
  CHECK(f.voltage_enabled);
  CHECK(f.remote);
  CHECK(f.target_reached);
  CHECK(!f.internal_limit_active);
  CHECK(f.bit12);
  CHECK(!f.bit13);
  CHECK(!f.warning);
}

TEST_CASE("controlword commands decode with the CiA 402 priorities") {
  CHECK(ds402::decode_command(0x0006, 0) == command::shutdown);
  CHECK(ds402::decode_command(0x000E, 0) == command::shutdown); // bit 3 is x
  CHECK(ds402::decode_command(0x0007, 0) == command::switch_on);
  CHECK(ds402::decode_command(0x000F, 0) == command::enable_operation);
  CHECK(ds402::decode_command(0x0000, 0) == command::disable_voltage);
  CHECK(ds402::decode_command(0x000D, 0) == command::disable_voltage);
  CHECK(ds402::decode_command(0x0002, 0) == command::quick_stop);
  CHECK(ds402::decode_command(0x000B, 0) == command::quick_stop);
  CHECK(ds402::decode_command(0x0080, 0x0000) == command::fault_reset);
  CHECK(ds402::decode_command(0x0080, 0x0080) == command::disable_voltage); // no edge
  CHECK(ds402::decode_command(0x008F, 0x000F) == command::fault_reset);
  // mode bits do not change the command (XENAX 5.2.1 0x1F, 0x5F, 5.2.3 0x10F, 5.4.1 0x11F)
  for (int w : {0x1F, 0x5F, 0x10F, 0x11F}) {
    CHECK(ds402::decode_command(static_cast<std::uint16_t>(w), 0x0F) == command::enable_operation);
  }
  CHECK(ds402::with_command(0x0150, command::shutdown) == 0x0156);
  CHECK(ds402::with_command(0x01FF, command::disable_voltage) == 0x0170);
  for (auto c : {command::shutdown, command::switch_on, command::switch_on_enable,
                 command::disable_voltage, command::quick_stop, command::disable_operation,
                 command::enable_operation, command::fault_reset}) {
    CHECK(!ds402::to_string(c).empty());
  }
}

TEST_CASE("transitions 2..16 on a drive") {
  using ds402::apply;
  using ds402::step;
  constexpr auto none = ds402::no_transition;
  CHECK(apply(state::switch_on_disabled, 0x06, 0) == step{state::ready_to_switch_on, 2, none});
  CHECK(apply(state::ready_to_switch_on, 0x07, 0x06) == step{state::switched_on, 3, none});
  CHECK(apply(state::switched_on, 0x0F, 0x07) == step{state::operation_enabled, 4, none});
  CHECK(apply(state::operation_enabled, 0x07, 0x0F) == step{state::switched_on, 5, none});
  CHECK(apply(state::switched_on, 0x06, 0x07) == step{state::ready_to_switch_on, 6, none});
  CHECK(apply(state::ready_to_switch_on, 0x00, 0x06) == step{state::switch_on_disabled, 7, none});
  CHECK(apply(state::ready_to_switch_on, 0x02, 0x06) == step{state::switch_on_disabled, 7, none});
  CHECK(apply(state::operation_enabled, 0x06, 0x0F) == step{state::ready_to_switch_on, 8, none});
  CHECK(apply(state::operation_enabled, 0x00, 0x0F) == step{state::switch_on_disabled, 9, none});
  CHECK(apply(state::switched_on, 0x00, 0x07) == step{state::switch_on_disabled, 10, none});
  CHECK(apply(state::switched_on, 0x02, 0x07) == step{state::switch_on_disabled, 10, none});
  CHECK(apply(state::operation_enabled, 0x02, 0x0F) == step{state::quick_stop_active, 11, none});
  CHECK(apply(state::quick_stop_active, 0x00, 0x02) == step{state::switch_on_disabled, 12, none});
  CHECK(apply(state::fault, 0x80, 0x00) == step{state::switch_on_disabled, 15, none});
  CHECK(apply(state::quick_stop_active, 0x0F, 0x02) == step{state::operation_enabled, 16, none});
  // two transitions at once: 0x0F from ready to switch on
  CHECK(apply(state::ready_to_switch_on, 0x0F, 0x06) == step{state::operation_enabled, 3, 4});
  // no transition
  CHECK(apply(state::fault, 0x80, 0x80) == step{state::fault, none, none}); // held, no edge
  CHECK(apply(state::fault, 0x0F, 0x00) == step{state::fault, none, none});
  CHECK(apply(state::switch_on_disabled, 0x0F, 0) == step{state::switch_on_disabled, none, none});
  CHECK(apply(state::operation_enabled, 0x1F, 0x0F) == step{state::operation_enabled, none, none});
  CHECK(apply(state::quick_stop_active, 0x06, 0x02) == step{state::quick_stop_active, none, none});
  CHECK(apply(state::not_ready_to_switch_on, 0x06, 0) ==
        step{state::not_ready_to_switch_on, none, none});
  // a fault-reset edge outside fault is just the other bits
  CHECK(apply(state::switch_on_disabled, 0x86, 0x00) == step{state::ready_to_switch_on, 2, none});
}

namespace {
// A simulated drive: applies controlwords, shows canonical statuswords, can be put in fault.
struct sim_drive {
  state s = state::switch_on_disabled;
  std::uint16_t prev = 0;
  int fault_resets_needed = 0; // a persisting fault needs more edges
  std::uint16_t statusword() const { return ds402::state_bits(s); }
  void receive(std::uint16_t cw) {
    auto st = ds402::apply(s, cw, prev);
    if (s == state::fault && st.transition == 15 && fault_resets_needed > 0) {
      --fault_resets_needed;
    } else {
      s = st.to;
    }
    prev = cw;
  }
};
constexpr state all_states[] = {state::not_ready_to_switch_on, state::switch_on_disabled,
                                state::ready_to_switch_on,     state::switched_on,
                                state::operation_enabled,      state::quick_stop_active,
                                state::fault_reaction_active,  state::fault};
constexpr state targets[] = {state::switch_on_disabled, state::ready_to_switch_on,
                             state::switched_on, state::operation_enabled,
                             state::quick_stop_active};
} // namespace

TEST_CASE("next_controlword walks a drive from every state to every target") {
  for (auto from : all_states) {
    if (from == state::not_ready_to_switch_on || from == state::fault_reaction_active) continue;
    for (auto target : targets) {
      for (std::uint16_t initial_prev : {std::uint16_t{0}, std::uint16_t{0x80}}) {
        CAPTURE(static_cast<int>(from));
        CAPTURE(static_cast<int>(target));
        sim_drive d;
        d.s = from;
        d.prev = initial_prev;
        std::uint16_t prev = initial_prev;
        int cycles = 0;
        while (d.s != target && cycles < 10) {
          auto cw = ds402::next_controlword(d.statusword(), target, prev);
          REQUIRE(cw.has_value());
          d.receive(cw.value());
          prev = cw.value();
          ++cycles;
        }
        CHECK(d.s == target);
        CHECK(cycles <= 5);
        // once there, it stays there
        for (int i = 0; i < 3; ++i) {
          auto cw = ds402::next_controlword(d.statusword(), target, prev);
          REQUIRE(cw.has_value());
          d.receive(cw.value());
          prev = cw.value();
          CHECK(d.s == target);
        }
      }
    }
  }
}

TEST_CASE("next_controlword: the XENAX power-on sequence and the 3+4 shortcut") {
  // XENAX 5.1.2 (l. 1552-1568) sends 0x06, 0x07, 0x0F step by step; towards switched on the
  // helper sends exactly that, towards operation enabled it takes 0x0F from ready to switch on.
  CHECK(ds402::next_controlword(0x0250, state::switched_on, 0).value() == 0x06);
  CHECK(ds402::next_controlword(0x0231, state::switched_on, 0x06).value() == 0x07);
  CHECK(ds402::next_controlword(0x0233, state::operation_enabled, 0x07).value() == 0x0F);
  CHECK(ds402::next_controlword(0x0231, state::operation_enabled, 0x06).value() == 0x0F);
  CHECK(ds402::next_controlword(0x0237, state::quick_stop_active, 0x0F).value() == 0x02);
  CHECK(ds402::next_controlword(0x0217, state::operation_enabled, 0x02).value() == 0x0F);
  CHECK(ds402::next_controlword(0x0217, state::switch_on_disabled, 0x02).value() == 0x00);
  CHECK(ds402::next_controlword(0x0000, state::operation_enabled, 0).value() == 0x00);
  CHECK(ds402::next_controlword(0x000F, state::operation_enabled, 0).value() == 0x00);
  // fault: edge, then 0x00, then edge again while the fault persists
  CHECK(ds402::next_controlword(0x0218, state::operation_enabled, 0x0F).value() == 0x80);
  CHECK(ds402::next_controlword(0x0218, state::operation_enabled, 0x80).value() == 0x00);
  // errors
  CHECK(ds402::next_controlword(0x0001, state::operation_enabled, 0) == errc::bad_state);
  CHECK(ds402::next_controlword(0x0040, state::fault, 0) == errc::invalid_argument);
  CHECK(ds402::next_controlword(0x0040, state::not_ready_to_switch_on, 0) ==
        errc::invalid_argument);
  CHECK(ds402::next_controlword(0x0040, state::fault_reaction_active, 0) == errc::invalid_argument);
}

TEST_CASE("power_sequencer holds bit 7 until the drive leaves fault (XENAX 5.1.9)") {
  // XENAX 5.1.9 (l. 1662-1675): 0x80 until fault clears, then 0x06, 0x07, 0x0F.
  sim_drive d;
  d.s = state::fault;
  d.fault_resets_needed = 0;
  ds402::power_sequencer seq;
  std::array<std::uint16_t, 6> sent{};
  std::array<std::uint16_t, 6> expected{0x80, 0x06, 0x0F, 0x0F, 0x0F, 0x0F};
  for (auto &w : sent) {
    w = seq.next(d.statusword(), state::operation_enabled).value();
    d.receive(w);
  }
  CHECK(sent == expected);
  CHECK(d.s == state::operation_enabled);

  // a persisting fault: the sequencer holds 0x80 and the drive sees only one edge.
  sim_drive d2;
  d2.s = state::fault;
  d2.fault_resets_needed = 1;
  ds402::power_sequencer seq2;
  for (int i = 0; i < 4; ++i) d2.receive(seq2.next(d2.statusword(), state::switched_on).value());
  CHECK(d2.s == state::fault);
  CHECK(seq2.previous() == 0x80);

  // entering fault with bit 7 already high: the sequencer first drops it to make an edge.
  ds402::power_sequencer seq3(0x80);
  CHECK(seq3.next(0x0008, state::operation_enabled).value() == 0x00);
  CHECK(seq3.next(0x0008, state::operation_enabled).value() == 0x80);
  CHECK(seq3.next(0x0008, state::operation_enabled).value() == 0x80);
  CHECK(seq3.next(0x0040, state::operation_enabled).value() == 0x06);

  // mode bits are kept, command bits are the sequencer's
  ds402::power_sequencer seq4;
  CHECK(seq4.next(0x0237, state::operation_enabled, 0x0150).value() == 0x015F);
  CHECK(seq4.next(0x0001, state::operation_enabled) == errc::bad_state);
}

TEST_CASE("modes of operation") {
  CHECK(ds402::decode_mode(1).value() == ds402::mode::profile_position);
  CHECK(ds402::decode_mode(6).value() == ds402::mode::homing);
  CHECK(ds402::decode_mode(8).value() == ds402::mode::cyclic_sync_position);
  CHECK(ds402::decode_mode(11).value() == ds402::mode::cyclic_sync_torque_commutation);
  CHECK(ds402::decode_mode(5) == errc::out_of_range);
  CHECK(ds402::decode_mode(12) == errc::out_of_range);
  // Issue 13: a manufacturer-specific mode is a valid mode, not an unknown command. It comes
  // back holding its value for the vendor's module (xenax::decode_mode(-1) = jog).
  const auto vendor = ds402::decode_mode(-1);
  REQUIRE(vendor.has_value());
  CHECK(static_cast<std::int8_t>(vendor.value()) == -1);
  CHECK(ds402::is_manufacturer_mode(vendor.value()));
  CHECK(!ds402::is_standard_mode(vendor.value()));
  CHECK(ds402::to_string(vendor.value()) == "manufacturer-specific");
  CHECK(static_cast<std::int8_t>(ds402::decode_mode(-128).value()) == -128);
  CHECK(ds402::is_manufacturer_mode(-1));
  CHECK(!ds402::is_manufacturer_mode(0));
  CHECK(ds402::is_standard_mode(ds402::mode::cyclic_sync_position));
  CHECK(ds402::to_string(static_cast<ds402::mode>(5)) == "reserved");
  int standard = 0;
  int vendor_modes = 0;
  for (int v = -128; v <= 127; ++v) {
    const auto m = ds402::decode_mode(static_cast<std::int8_t>(v));
    if (!m) {
      CHECK(m == errc::out_of_range);
      CHECK((v == 5 || v >= 12));
      continue;
    }
    CHECK(static_cast<int>(static_cast<std::int8_t>(m.value())) == v);
    if (ds402::is_standard_mode(m.value())) {
      ++standard;
      CHECK(ds402::to_string(m.value()) != "manufacturer-specific");
    } else {
      ++vendor_modes;
    }
  }
  CHECK(standard == 11);
  CHECK(vendor_modes == 128);
}

static_assert(std::is_same_v<std::underlying_type_t<ds402::mode>, std::int8_t>);
