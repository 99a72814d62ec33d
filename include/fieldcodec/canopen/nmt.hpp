// fieldcodec — NMT module control, boot-up, heartbeat and node guarding (CiA 301).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/core/result.hpp>

#include <cstdint>
#include <optional>
#include <string_view>

namespace fieldcodec::canopen::nmt {

/// NMT command specifiers (byte 0 of the NMT frame on COB-ID 0).
enum class command : std::uint8_t {
  start = 0x01,
  stop = 0x02,
  enter_pre_operational = 0x80,
  reset_node = 0x81,
  reset_communication = 0x82,
};

[[nodiscard]] constexpr bool is_command(std::uint8_t cs) noexcept {
  return cs == 0x01U || cs == 0x02U || cs == 0x80U || cs == 0x81U || cs == 0x82U;
}

/// NMT states as reported by heartbeat and node guarding (bits 0..6).
enum class state : std::uint8_t {
  boot_up = 0x00, ///< only in the boot-up message
  stopped = 0x04,
  operational = 0x05,
  pre_operational = 0x7F,
};

[[nodiscard]] constexpr bool is_state(std::uint8_t s) noexcept {
  return s == 0x00U || s == 0x04U || s == 0x05U || s == 0x7FU;
}

/// The NMT frame for `node` (1..127, or 0 for all nodes): 0x000 DLC 2 [cs, node].
/// Errors: invalid_argument (node > 127).
[[nodiscard]] constexpr result<can_frame> encode(command cs, std::uint8_t node) noexcept {
  if (node > max_node_id) return errc::invalid_argument;
  return make_frame(cob_id::nmt, {static_cast<std::uint8_t>(cs), node});
}

struct message {
  command cs;
  std::uint8_t node; ///< 0 = all nodes
  friend constexpr bool operator==(const message &, const message &) = default;
};

/// Decode an NMT frame. Errors: unexpected_frame (not COB-ID 0, or a remote frame), bad_length
/// (DLC not 2), unknown_command (command specifier), invalid_argument (node-ID > 127).
[[nodiscard]] constexpr result<message> decode(const can_frame &f) noexcept {
  if (f.id != cob_id::nmt) return errc::unexpected_frame;
  FIELDCODEC_TRY_STATUS(expect_data(f, 2));
  if (!is_command(f.data[0])) return errc::unknown_command;
  if (f.data[1] > max_node_id) return errc::invalid_argument;
  return message{static_cast<command>(f.data[0]), f.data[1]};
}

/// The state a node is in after receiving `cs` (reset commands end in boot-up, after which the
/// node enters pre-operational by itself).
[[nodiscard]] constexpr state state_after(command cs) noexcept {
  switch (cs) {
  case command::start: return state::operational;
  case command::stop: return state::stopped;
  case command::enter_pre_operational: return state::pre_operational;
  case command::reset_node:
  case command::reset_communication: return state::boot_up;
  }
  return state::boot_up;
}

// ---------------------------------------------------------------------------------------------
// Error control: boot-up, heartbeat, node guarding (all on 0x700 + node)

/// Heartbeat of `node` in state `s`: 0x700+node DLC 1 [s]. Errors: invalid_argument (node).
[[nodiscard]] constexpr result<can_frame> encode_heartbeat(std::uint8_t node, state s) noexcept {
  if (!is_node_id(node)) return errc::invalid_argument;
  can_frame f;
  f.id = static_cast<std::uint16_t>(cob_id::nmt_error_base + node);
  f.dlc = 1;
  f.data[0] = static_cast<std::uint8_t>(s);
  return f;
}
/// Boot-up message of `node`: 0x700+node DLC 1 [00].
[[nodiscard]] constexpr result<can_frame> encode_boot_up(std::uint8_t node) noexcept {
  return encode_heartbeat(node, state::boot_up);
}

struct heartbeat {
  std::uint8_t node;
  state s;
  [[nodiscard]] constexpr bool is_boot_up() const noexcept { return s == state::boot_up; }
  friend constexpr bool operator==(const heartbeat &, const heartbeat &) = default;
};

/// Decode a heartbeat or boot-up message. Errors: unexpected_frame (not 0x701..0x77F, or a
/// remote frame, which is a node-guarding request), bad_length (DLC not 1), out_of_range
/// (bit 7 set, the node-guarding toggle, or a state code CiA 301 does not define).
[[nodiscard]] constexpr result<heartbeat> decode_heartbeat(const can_frame &f) noexcept {
  if (f.id <= cob_id::nmt_error_base || f.id > cob_id::nmt_error_base + max_node_id) {
    return errc::unexpected_frame;
  }
  FIELDCODEC_TRY_STATUS(expect_data(f, 1));
  if (!is_state(f.data[0])) return errc::out_of_range;
  return heartbeat{static_cast<std::uint8_t>(f.id - cob_id::nmt_error_base),
                   static_cast<state>(f.data[0])};
}

/// Node-guarding request from the master: remote frame 0x700+node with DLC 1.
[[nodiscard]] constexpr result<can_frame> encode_guard_request(std::uint8_t node) noexcept {
  auto id = cob_id::nmt_error(node);
  if (!id) return id.error();
  return make_remote_frame(id.value(), 1);
}

/// Is `f` a node-guarding request? Returns the node. A remote frame on 0x700 + node is a
/// guarding request whatever its DLC: CiA 301 asks for 1, widely used masters send 0 (issue 12
/// #5), and a node that refused them would look dead to its master.
/// Errors: unexpected_frame (not a remote frame on 0x701..0x77F), bad_length (DLC above 8).
[[nodiscard]] constexpr result<std::uint8_t> decode_guard_request(const can_frame &f) noexcept {
  if (!f.rtr || f.id <= cob_id::nmt_error_base || f.id > cob_id::nmt_error_base + max_node_id) {
    return errc::unexpected_frame;
  }
  if (f.dlc > max_dlc) return errc::bad_length;
  return static_cast<std::uint8_t>(f.id - cob_id::nmt_error_base);
}

/// Node-guarding response: 0x700+node DLC 1 [toggle << 7 | state]. Boot-up is not a guarding
/// state. Errors: invalid_argument (node, or state boot_up).
[[nodiscard]] constexpr result<can_frame> encode_guard_response(std::uint8_t node, state s,
                                                                bool toggle) noexcept {
  if (s == state::boot_up || !is_node_id(node)) return errc::invalid_argument;
  can_frame f;
  f.id = static_cast<std::uint16_t>(cob_id::nmt_error_base + node);
  f.dlc = 1;
  f.data[0] = static_cast<std::uint8_t>(static_cast<unsigned>(s) | (toggle ? 0x80U : 0U));
  return f;
}

struct guard_response {
  std::uint8_t node;
  state s;
  bool toggle;
  friend constexpr bool operator==(const guard_response &, const guard_response &) = default;
};

/// Decode a node-guarding response. Errors: unexpected_frame, bad_length (DLC not 1),
/// out_of_range (state not stopped / operational / pre-operational).
[[nodiscard]] constexpr result<guard_response> decode_guard_response(const can_frame &f) noexcept {
  if (f.id <= cob_id::nmt_error_base || f.id > cob_id::nmt_error_base + max_node_id) {
    return errc::unexpected_frame;
  }
  FIELDCODEC_TRY_STATUS(expect_data(f, 1));
  const auto s = static_cast<std::uint8_t>(f.data[0] & 0x7FU);
  if (!is_state(s) || s == 0U) return errc::out_of_range;
  return guard_response{static_cast<std::uint8_t>(f.id - cob_id::nmt_error_base),
                        static_cast<state>(s), (f.data[0] & 0x80U) != 0U};
}

/// The master's view of one guarded node: checks that the toggle bit alternates, starting with
/// 0 after the node's communication reset.
class guard_monitor {
public:
  constexpr explicit guard_monitor(std::uint8_t node) noexcept : node_(node) {}

  /// Check a response. Errors: those of decode_guard_response, unexpected_frame (another
  /// node), bad_toggle (toggle did not alternate: the response is ignored and the same toggle
  /// is expected again).
  [[nodiscard]] constexpr result<state> accept(const can_frame &f) noexcept {
    auto r = decode_guard_response(f);
    if (!r) return r.error();
    if (r.value().node != node_) return errc::unexpected_frame;
    if (r.value().toggle != expected_) return errc::bad_toggle;
    expected_ = !expected_;
    return r.value().s;
  }
  /// After NMT reset node / reset communication (or a boot-up): the next toggle is 0.
  constexpr void reset() noexcept { expected_ = false; }
  [[nodiscard]] constexpr bool expected_toggle() const noexcept { return expected_; }

private:
  std::uint8_t node_;
  bool expected_ = false;
};

/// The node's side: answers guarding requests with an alternating toggle.
class guard_responder {
public:
  constexpr explicit guard_responder(std::uint8_t node) noexcept : node_(node) {}
  /// The response to a request frame. Errors: those of decode_guard_request, unexpected_frame
  /// (request for another node), invalid_argument (state boot_up).
  [[nodiscard]] constexpr result<can_frame> respond(const can_frame &request, state s) noexcept {
    auto n = decode_guard_request(request);
    if (!n) return n.error();
    if (n.value() != node_) return errc::unexpected_frame;
    if (const auto f = answer(s)) return *f;
    return errc::invalid_argument;
  }
  /// The response to a request the caller has recognised as this node's already (a remote
  /// frame on 0x700 + node, DLC ≤ 8): respond() without decoding it again; nullopt where
  /// respond() fails with invalid_argument (state boot_up, node-ID not 1..127).
  [[nodiscard]] constexpr std::optional<can_frame> answer(state s) noexcept {
    const auto r = encode_guard_response(node_, s, toggle_);
    if (!r) return std::nullopt;
    toggle_ = !toggle_;
    return r.value();
  }
  constexpr void reset() noexcept { toggle_ = false; }

private:
  std::uint8_t node_;
  bool toggle_ = false;
};

[[nodiscard]] constexpr std::string_view to_string(state s) noexcept {
  switch (s) {
  case state::boot_up: return "boot-up";
  case state::stopped: return "stopped";
  case state::operational: return "operational";
  case state::pre_operational: return "pre-operational";
  }
  return "?";
}

} // namespace fieldcodec::canopen::nmt
