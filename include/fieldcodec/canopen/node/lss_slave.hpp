// fieldcodec — the LSS slave (CiA 305 layer setting services): an LSS master finds the node by
// its identity (1018h sub 1..4), gives it a node-ID and a bit timing, and has it store them.
//
//   node::lss_slave lss(lss::unconfigured, {.store = my_store, .context = &flash});
//   (void)lss.load(store, now);                    // the LSS address from 1018h
//   const auto r = lss.on_frame(frame);            // a frame on 7E5h
//   if (r.answer) send(*r.answer);                 // on 7E4h
//   if (r.boot) ...                                // node-ID given: NMT reset communication
//
// node::device serves it with capacity::lss (device.hpp): a device without it links none of
// this. The machine alone does no I/O and keeps no clock.
//
// LSS states (lss_mode): waiting (after power-on and every NMT reset) and configuration. The
// services by state (CiA 305):
//   - either state: switch state global, identify remote slave (46h–4Bh → 4Fh), identify
//     non-configured remote slave (4Ch → 50h, only while the node has no node-ID, active or
//     pending);
//   - waiting only: switch state selective (40h–43h; the four values of the last such sequence
//     equal to the LSS address → configuration, answer 44h), fastscan (51h; only a node without
//     node-ID, active or pending, takes part; answer 4Fh; the last part matched with
//     bit_checked 0 and LSSNext < LSSSub → configuration);
//   - configuration only: configure node-ID (1..127, or FFh "unconfigured"; 0 and 80h..FEh are
//     answered with error code 1), configure bit timing (table 0 and an index
//     lss_options::bit_rates allows; otherwise error code 1), activate bit timing (no answer: an
//     event for the application), store configuration (lss_options::store; error code 1 "not
//     supported" without one), inquire vendor-ID, product code, revision number, serial number
//     (5Ah–5Dh) and node-ID (5Eh: the active node-ID, FFh while unconfigured).
// A command of the other state is ignored (error(): bad_state), as are frames that are not 8
// bytes long (bad_length), remote frames (unexpected_frame), command specifiers CiA 305 does not
// give the master (unknown_command) and malformed arguments (invalid_argument: a switch mode
// other than 0 and 1, a fastscan probe with bit_checked > 31 and ≠ 80h or LSSSub/LSSNext > 3).
//
// Node-IDs: the active node-ID is the one the node uses; configure node-ID sets the pending
// one, which becomes active at the next NMT reset communication or reset node (activate()). A
// node without active node-ID (FFh) that is switched back to waiting with a pending node-ID
// boots with it by itself (the step's `boot`: the device carries out a reset communication).
//
// Bit timing: the node cannot reprogram its CAN controller. Configure bit timing only records
// the pending bit timing; activate bit timing reports it (lss_event::kind::activate_bit_timing,
// with the switch delay): the application then stays silent for the delay, switches the
// controller to the pending bit timing, and stays silent for the delay again (CiA 305).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/lss.hpp>
#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <cstdint>
#include <optional>
#include <string_view>

namespace fieldcodec::canopen::node {

/// The states of the LSS slave (the values of switch state global).
enum class lss_mode : std::uint8_t { waiting = 0, configuration = 1 };

[[nodiscard]] constexpr std::string_view to_string(lss_mode m) noexcept {
  return m == lss_mode::waiting ? "LSS waiting" : "LSS configuration";
}

/// A bit timing of configure bit timing: a table selector (0: CiA 305's standard table, see
/// lss::standard_bit_rate) and an index into it.
struct lss_bit_timing {
  std::uint8_t table = 0;
  std::uint8_t index = 0;
  friend constexpr bool operator==(const lss_bit_timing &, const lss_bit_timing &) = default;
};

/// The answer of the application's store hook: lss::error_code::none, storage_access, or
/// manufacturer with the manufacturer's own code.
struct lss_store_result {
  std::uint8_t code = lss::error_code::none;
  std::uint8_t manufacturer = 0;
};

/// The application's store configuration: keep `node_id` (the pending node-ID) and `timing`
/// (the pending bit timing; nullopt when none was configured since power-on) for the next
/// power-on, e.g. in a flash page or a file. Called from on_frame.
using lss_store_hook = lss_store_result (*)(void *context, std::uint8_t node_id,
                                            std::optional<lss_bit_timing> timing) noexcept;

/// Choices of the application.
struct lss_options {
  /// The indices of the standard bit timing table (selector 0) the CAN controller can run: bit
  /// i set = index i. The default: every rate the table defines (0..4, 6..8: 1000 to 10 kbit/s),
  /// not automatic detection (9). Other tables are not supported.
  std::uint16_t bit_rates = 0x01DF;
  lss_store_hook store = nullptr; ///< none: store configuration answers error code 1
  void *context = nullptr;        ///< handed to `store`
};

/// What a frame did besides its answer.
struct lss_event {
  enum class kind : std::uint8_t {
    mode,                ///< the LSS state changed (`mode`)
    node_id,             ///< a pending node-ID was configured (`node_id`)
    bit_timing,          ///< a pending bit timing was configured (`timing`)
    activate_bit_timing, ///< switch to `timing` after `delay_ms` (see above)
    stored,              ///< store configuration was asked (`code`: the answer's error code)
  };
  kind what = kind::mode;
  lss_mode mode = lss_mode::waiting;
  std::uint8_t node_id = 0;
  lss_bit_timing timing{};
  std::uint16_t delay_ms = 0;
  std::uint8_t code = 0;
  friend constexpr bool operator==(const lss_event &, const lss_event &) = default;
};

[[nodiscard]] constexpr std::string_view to_string(lss_event::kind k) noexcept {
  switch (k) {
  case lss_event::kind::mode: return "LSS state changed";
  case lss_event::kind::node_id: return "LSS node-ID configured";
  case lss_event::kind::bit_timing: return "LSS bit timing configured";
  case lss_event::kind::activate_bit_timing: return "LSS activate bit timing";
  case lss_event::kind::stored: return "LSS store configuration";
  }
  return "?";
}

/// Is `node` a node-ID configure node-ID accepts (1..127, or FFh)?
[[nodiscard]] constexpr bool lss_node_id(std::uint8_t node) noexcept {
  return is_node_id(node) || node == lss::unconfigured;
}

class lss_slave {
public:
  /// What on_frame did.
  struct step {
    std::optional<can_frame> answer{}; ///< on 7E4h
    std::optional<lss_event> event{};
    /// The node had no node-ID and now has a pending one: carry out an NMT reset
    /// communication (activate(), then boot with it).
    bool boot = false;
  };

  /// A slave whose active and pending node-ID is `node` (1..127, or lss::unconfigured).
  constexpr explicit lss_slave(std::uint8_t node, lss_options o = {}) noexcept
      : options_(o), active_(node), pending_(node) {}

  // ----- the node's service members (device.hpp each_service) ------------------------------

  [[nodiscard]] constexpr abort_code check_write(od::address, std::uint32_t) const noexcept {
    return abort_code::none;
  }
  /// 1018h sub 1..4 is the LSS address.
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t) noexcept {
    if (a.index != 0x1018U) return;
    switch (a.sub) {
    case 1: address_.vendor = v; break;
    case 2: address_.product = v; break;
    case 3: address_.revision = v; break;
    case 4: address_.serial = v; break;
    default: break;
    }
  }
  /// The LSS address from 1018h in `store` (a missing sub-index counts as 0).
  template <class Store>
  constexpr status load(const Store &store, std::uint32_t now) noexcept {
    address_ = {};
    for (std::uint8_t sub = 1; sub <= 4U; ++sub) {
      if (const auto v = read_u32(store, {0x1018, sub})) written({0x1018, sub}, *v, now);
    }
    return {};
  }

  // ----- frames ----------------------------------------------------------------------------

  /// A frame on 7E5h (other identifiers: nothing, error() unexpected_frame).
  [[nodiscard]] constexpr step on_frame(const can_frame &f) noexcept {
    step s;
    error_ = errc{};
    const auto m = lss::decode(f);
    if (!m || !m.value().from_master) {
      error_ = m ? errc::unexpected_frame : m.error();
      return s;
    }
    take(m.value(), s);
    if (s.event) last_event_ = *s.event;
    return s;
  }

  /// NMT reset communication or reset node: the pending node-ID becomes active, the slave is
  /// waiting again. Returns the active node-ID.
  constexpr std::uint8_t activate() noexcept {
    active_ = pending_;
    mode_ = lss_mode::waiting;
    selected_ = 0;
    identify_ = 0;
    fastscan_sub_ = 0;
    return active_;
  }

  [[nodiscard]] constexpr lss_mode mode() const noexcept { return mode_; }
  [[nodiscard]] constexpr std::uint8_t active_node() const noexcept { return active_; }
  [[nodiscard]] constexpr std::uint8_t pending_node() const noexcept { return pending_; }
  /// The bit timing configured since power-on (nullopt: none).
  [[nodiscard]] constexpr std::optional<lss_bit_timing> pending_bit_timing() const noexcept {
    return timing_;
  }
  [[nodiscard]] constexpr const lss::address &address() const noexcept { return address_; }
  /// The event of the last frame that made one (node::device reports it as an
  /// event::kind::lss and keeps the details here).
  [[nodiscard]] constexpr const lss_event &last_event() const noexcept { return last_event_; }
  /// No node-ID, active or pending (identify non-configured, fastscan).
  [[nodiscard]] constexpr bool unconfigured() const noexcept {
    return active_ == lss::unconfigured && pending_ == lss::unconfigured;
  }
  /// Why the last frame was ignored (empty when it was taken).
  [[nodiscard]] constexpr std::optional<errc> error() const noexcept {
    if (error_ == errc{}) return std::nullopt;
    return error_;
  }

private:
  using command = lss::command;

  constexpr void take(const lss::message &m, step &s) noexcept {
    switch (m.cs) {
    case command::switch_global: return switch_global(m.b1, s);
    case command::identify_vendor:
    case command::identify_product:
    case command::identify_revision_low:
    case command::identify_revision_high:
    case command::identify_serial_low:
    case command::identify_serial_high: return identify(m, s);
    case command::identify_non_configured:
      if (unconfigured()) answer(s, lss::answer(command::identify_non_configured_slave));
      return;
    default: break;
    }
    const bool waiting_only =
        m.cs == command::fastscan ||
        (m.cs >= command::switch_selective_vendor && m.cs <= command::switch_selective_serial);
    if (waiting_only != (mode_ == lss_mode::waiting)) {
      error_ = errc::bad_state;
      return;
    }
    switch (m.cs) {
    case command::switch_selective_vendor:
    case command::switch_selective_product:
    case command::switch_selective_revision:
    case command::switch_selective_serial: return select(m, s);
    case command::fastscan: return fastscan(m, s);
    case command::configure_node_id: return configure_node_id(m.b1, s);
    case command::configure_bit_timing: return configure_bit_timing(m.b1, m.b2, s);
    case command::activate_bit_timing:
      if (!timing_) {
        error_ = errc::bad_state; // nothing to activate
        return;
      }
      s.event = lss_event{lss_event::kind::activate_bit_timing, mode_, 0, *timing_,
                          static_cast<std::uint16_t>(m.value),  0};
      return;
    case command::store_configuration: return store(s);
    case command::inquire_vendor:
    case command::inquire_product:
    case command::inquire_revision:
    case command::inquire_serial: {
      lss::message a = lss::answer(m.cs);
      a.value = address_.part(static_cast<std::uint8_t>(static_cast<std::uint8_t>(m.cs) - 0x5AU));
      return answer(s, a);
    }
    case command::inquire_node_id: return answer(s, lss::answer(m.cs, active_));
    default: break; // the slave answers (decode refuses them on 7E5h)
    }
  }

  constexpr void answer(step &s, const lss::message &a) noexcept { s.answer = lss::encode(a); }

  constexpr void enter(lss_mode to, step &s) noexcept {
    selected_ = 0;
    if (to == mode_) return;
    mode_ = to;
    s.event = lss_event{lss_event::kind::mode, to};
  }

  constexpr void switch_global(std::uint8_t mode, step &s) noexcept {
    if (mode > 1U) {
      error_ = errc::invalid_argument;
      return;
    }
    const auto to = static_cast<lss_mode>(mode);
    if (to == lss_mode::waiting && mode_ == lss_mode::configuration &&
        active_ == lss::unconfigured && pending_ != lss::unconfigured) {
      s.boot = true;
    }
    enter(to, s);
  }

  /// Switch state selective: bit i of selected_ = part i received and equal.
  constexpr void select(const lss::message &m, step &s) noexcept {
    const auto part = static_cast<std::uint8_t>(static_cast<std::uint8_t>(m.cs) - 0x40U);
    if (part == 0U) selected_ = 0;
    if (address_.part(part) == m.value) {
      selected_ = static_cast<std::uint8_t>(selected_ | (1U << part));
    } else {
      selected_ = static_cast<std::uint8_t>(selected_ & ~(1U << part));
    }
    if (part != 3U) return;
    const bool all = selected_ == 0x0FU;
    selected_ = 0;
    if (!all) return;
    enter(lss_mode::configuration, s);
    answer(s, lss::answer(command::switch_selective_response));
  }

  /// Identify remote slave: vendor and product equal, revision and serial within the bounds.
  constexpr void identify(const lss::message &m, step &s) noexcept {
    const auto part = static_cast<std::uint8_t>(static_cast<std::uint8_t>(m.cs) - 0x46U);
    if (part == 0U) identify_ = 0;
    bool ok = false;
    switch (part) {
    case 0: ok = address_.vendor == m.value; break;
    case 1: ok = address_.product == m.value; break;
    case 2: ok = address_.revision >= m.value; break;
    case 3: ok = address_.revision <= m.value; break;
    case 4: ok = address_.serial >= m.value; break;
    default: ok = address_.serial <= m.value; break;
    }
    if (ok) {
      identify_ = static_cast<std::uint8_t>(identify_ | (1U << part));
    } else {
      identify_ = static_cast<std::uint8_t>(identify_ & ~(1U << part));
    }
    if (part != 5U) return;
    const bool all = identify_ == 0x3FU;
    identify_ = 0;
    if (all) answer(s, lss::answer(command::identify_slave));
  }

  constexpr void fastscan(const lss::message &m, step &s) noexcept {
    if ((m.bit_checked > lss::fastscan_last_bit && m.bit_checked != lss::fastscan_reset) ||
        m.lss_sub > 3U || m.lss_next > 3U) {
      error_ = errc::invalid_argument;
      return;
    }
    if (!unconfigured()) return; // only nodes without node-ID take part
    if (m.bit_checked == lss::fastscan_reset) {
      fastscan_sub_ = 0;
      return answer(s, lss::answer(command::identify_slave));
    }
    if (m.lss_sub != fastscan_sub_) return; // an earlier part did not match
    const std::uint32_t mask = 0xFFFF'FFFFU << m.bit_checked;
    if ((address_.part(m.lss_sub) & mask) != (m.value & mask)) return;
    answer(s, lss::answer(command::identify_slave));
    fastscan_sub_ = m.lss_next;
    if (m.bit_checked == 0U && m.lss_next < m.lss_sub) enter(lss_mode::configuration, s);
  }

  constexpr void configure_node_id(std::uint8_t node, step &s) noexcept {
    if (!lss_node_id(node)) {
      return answer(s, lss::answer(command::configure_node_id, lss::error_code::not_supported));
    }
    pending_ = node;
    s.event = lss_event{lss_event::kind::node_id, mode_, node};
    answer(s, lss::answer(command::configure_node_id, lss::error_code::none));
  }

  constexpr void configure_bit_timing(std::uint8_t table, std::uint8_t index, step &s) noexcept {
    if (table != 0U || index > 15U ||
        ((static_cast<unsigned>(options_.bit_rates) >> index) & 1U) == 0U) {
      return answer(s, lss::answer(command::configure_bit_timing, lss::error_code::not_supported));
    }
    timing_ = lss_bit_timing{table, index};
    s.event = lss_event{lss_event::kind::bit_timing, mode_, 0, *timing_};
    answer(s, lss::answer(command::configure_bit_timing, lss::error_code::none));
  }

  constexpr void store(step &s) noexcept {
    lss_store_result r{lss::error_code::not_supported, 0};
    if (options_.store != nullptr) r = options_.store(options_.context, pending_, timing_);
    lss_event e{lss_event::kind::stored, mode_, pending_};
    e.code = r.code;
    if (timing_) e.timing = *timing_;
    s.event = e;
    answer(s,
           lss::answer(command::store_configuration, r.code,
                       r.code == lss::error_code::manufacturer ? r.manufacturer : std::uint8_t{0}));
  }

  lss_options options_;
  lss::address address_{};
  lss_event last_event_{};
  std::optional<lss_bit_timing> timing_{};
  std::uint8_t active_;
  std::uint8_t pending_;
  lss_mode mode_ = lss_mode::waiting;
  std::uint8_t selected_ = 0;     ///< switch state selective: the parts received and equal
  std::uint8_t identify_ = 0;     ///< identify remote slave: the conditions met
  std::uint8_t fastscan_sub_ = 0; ///< fastscan: the part the slave compares next
  /// errc{} (no code of errc is 0) while the last frame was taken (see nmt_slave).
  errc error_{};
};

} // namespace fieldcodec::canopen::node
