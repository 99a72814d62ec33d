// fieldcodec — the boot-up of one device by a master, after CiA 302's slave boot-up, simplified
// (docs/master.md, "Boot-up"):
//
//   1. reset communication (NMT 0x82) and wait for the boot-up message, or only wait for it;
//   2. read 1000h and 1018h sub 1..4 and compare them with the expected identity (0 = not
//      checked); a mismatch names the field, the expected and the actual value;
//   3. run the configuration list (master::configurator: retries, timeout, verify);
//   4. optionally wait for the first heartbeat of the device (its producer runs), then start
//      the master's heartbeat consumption: `heartbeat_entry()` is the 1016h entry {node,
//      consumer time} for the caller's `canopen::node::heartbeat_consumer`;
//   5. NMT start (0x01), report.
//
// One machine per device; a master with several devices runs several, each with its own SDO
// client. Pure: no heap, no I/O, time passed in; every call returns a canopen::step.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/node/heartbeat.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/master/config.hpp>
#include <fieldcodec/master/configurator.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace fieldcodec::master {

enum class boot_state : std::uint8_t {
  idle,
  waiting_boot_up,
  reading_identity,
  configuring,
  waiting_heartbeat,
  done, ///< NMT start sent (or, with start = false, the device left pre-operational)
  failed,
};

[[nodiscard]] constexpr std::string_view to_string(boot_state s) noexcept {
  switch (s) {
  case boot_state::idle: return "idle";
  case boot_state::waiting_boot_up: return "waiting for boot-up";
  case boot_state::reading_identity: return "reading identity";
  case boot_state::configuring: return "configuring";
  case boot_state::waiting_heartbeat: return "waiting for heartbeat";
  case boot_state::done: return "done";
  case boot_state::failed: return "failed";
  }
  return "?";
}

enum class boot_failure : std::uint8_t {
  no_boot_up,           ///< no boot-up message in time
  identity_read_failed, ///< reading 1000h / 1018h failed (sdo says why)
  identity_mismatch,    ///< `field` differs: expected / actual
  configuration_failed, ///< the configurator failed (config says which item and why)
  no_heartbeat,         ///< no heartbeat in time
};

/// The identity fields, in the order they are read.
enum class identity_field : std::uint8_t { device_type, vendor_id, product_code, revision, serial };

[[nodiscard]] constexpr std::string_view to_string(identity_field f) noexcept {
  switch (f) {
  case identity_field::device_type: return "device type (1000h)";
  case identity_field::vendor_id: return "vendor-ID (1018h sub 1)";
  case identity_field::product_code: return "product code (1018h sub 2)";
  case identity_field::revision: return "revision number (1018h sub 3)";
  case identity_field::serial: return "serial number (1018h sub 4)";
  }
  return "?";
}

struct boot_error {
  boot_failure failure = boot_failure::no_boot_up;
  errc code = errc::timeout;
  identity_field field = identity_field::device_type; ///< identity failures
  std::uint32_t expected = 0;                         ///< identity_mismatch
  std::uint32_t actual = 0;                           ///< identity_mismatch
  std::optional<canopen::sdo::transfer_error> sdo{};  ///< identity_read_failed
  std::optional<config_error> config{};               ///< configuration_failed

  [[nodiscard]] constexpr bool is(errc e) const noexcept { return code == e; }
};

struct boot_options {
  bool reset_communication = true; ///< send NMT reset communication first
  bool wait_boot_up = true;        ///< wait for the boot-up message (after the reset, or alone)
  std::uint32_t boot_timeout_ms = 2000;
  std::uint32_t heartbeat_timeout_ms = 0; ///< 0: do not wait for a heartbeat
  /// The master's heartbeat consumer time for this node (ms; 0: none): heartbeat_entry().
  /// Usually 1.5 to 2 × the producer time the configuration list writes to 1017h.
  std::uint16_t consumer_time_ms = 0;
  bool start = true;       ///< send NMT start at the end
  config_options config{}; ///< for the configuration list
};

class boot {
public:
  using step = canopen::step<boot_state>;

  /// The boot-up of `node` (1..127) through `client` (the node's SDO client, owned by the
  /// caller and not used by anyone else while this runs).
  constexpr boot(std::uint8_t node, canopen::sdo::client &client, boot_options o = {}) noexcept
      : node_(node), client_(&client), opt_(o), config_run_(client, o.config) {}

  /// Start. Errors: invalid_argument (node not 1..127), bad_state (running, or the client is
  /// busy).
  [[nodiscard]] constexpr result<step> start(const configuration &c, std::uint32_t now) noexcept {
    if (node_ < 1U || node_ > 127U) return errc::invalid_argument;
    if (busy() || client_->busy()) return errc::bad_state;
    config_ = c;
    error_.reset();
    read_ = {};
    out_ = {};
    if (opt_.reset_communication) {
      out_ = canopen::nmt::encode(canopen::nmt::command::reset_communication, node_).value();
    }
    if (opt_.reset_communication || opt_.wait_boot_up) {
      state_ = boot_state::waiting_boot_up;
      deadline_ = now + opt_.boot_timeout_ms;
      return make(out_ ? canopen::frames(*out_) : canopen::frames{});
    }
    return read_identity(identity_field::device_type, now);
  }

  /// Consume a received frame (NMT error control of the node and its SDO responses; others are
  /// ignored).
  [[nodiscard]] constexpr step on_frame(const canopen::can_frame &f, std::uint32_t now) noexcept {
    const bool heartbeat = f.id == 0x700U + node_ && f.dlc == 1U && !f.rtr;
    switch (state_) {
    case boot_state::waiting_boot_up:
      if (heartbeat && f.data[0] == 0U) return read_identity(identity_field::device_type, now);
      return make({});
    case boot_state::reading_identity: return identity_answer(client_->on_frame(f, now), now);
    case boot_state::configuring: return configured(config_run_.on_frame(f, now), now);
    case boot_state::waiting_heartbeat:
      if (heartbeat && f.data[0] != 0U) return start_node();
      return make({});
    default: return make({});
    }
  }

  /// Check the timeouts.
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    switch (state_) {
    case boot_state::waiting_boot_up:
      if (deadline_ && canopen::reached(*deadline_, now)) {
        return fail({boot_failure::no_boot_up, errc::timeout});
      }
      return make({});
    case boot_state::reading_identity: return identity_answer(client_->poll(now), now);
    case boot_state::configuring: return configured(config_run_.poll(now), now);
    case boot_state::waiting_heartbeat:
      if (deadline_ && canopen::reached(*deadline_, now)) {
        return fail({boot_failure::no_heartbeat, errc::timeout});
      }
      return make({});
    default: return make({});
    }
  }

  [[nodiscard]] constexpr boot_state state() const noexcept { return state_; }
  [[nodiscard]] constexpr bool busy() const noexcept {
    return state_ != boot_state::idle && state_ != boot_state::done && state_ != boot_state::failed;
  }
  [[nodiscard]] constexpr std::optional<boot_error> error() const noexcept { return error_; }
  /// The identity read from the device (fields not checked stay 0).
  [[nodiscard]] constexpr identity read_identity_values() const noexcept { return read_; }
  [[nodiscard]] constexpr std::uint8_t node() const noexcept { return node_; }
  /// The entry with which the master consumes this node's heartbeat (1016h format: node,
  /// consumer_time_ms); inactive when consumer_time_ms is 0. Start consumption when state() is
  /// done: `consumer.configure(i, boot.heartbeat_entry().to_u32(), now)`.
  [[nodiscard]] constexpr canopen::node::consumer_entry heartbeat_entry() const noexcept {
    return {node_, opt_.consumer_time_ms};
  }

private:
  [[nodiscard]] static constexpr od::address address_of(identity_field f) noexcept {
    if (f == identity_field::device_type) return {0x1000, 0};
    return {0x1018, static_cast<std::uint8_t>(f)};
  }
  [[nodiscard]] static constexpr std::uint32_t value_of(const identity &i,
                                                        identity_field f) noexcept {
    switch (f) {
    case identity_field::device_type: return i.device_type;
    case identity_field::vendor_id: return i.vendor_id;
    case identity_field::product_code: return i.product_code;
    case identity_field::revision: return i.revision;
    case identity_field::serial: return i.serial;
    }
    return 0;
  }
  static constexpr void set(identity &i, identity_field f, std::uint32_t v) noexcept {
    switch (f) {
    case identity_field::device_type: i.device_type = v; break;
    case identity_field::vendor_id: i.vendor_id = v; break;
    case identity_field::product_code: i.product_code = v; break;
    case identity_field::revision: i.revision = v; break;
    case identity_field::serial: i.serial = v; break;
    }
  }

  [[nodiscard]] constexpr step make(canopen::frames f) const noexcept {
    step s;
    s.send = f;
    s.state = state_;
    if (busy()) s.deadline = deadline_;
    return s;
  }
  [[nodiscard]] constexpr step fail(boot_error e) noexcept {
    error_ = e;
    state_ = boot_state::failed;
    deadline_.reset();
    return make({});
  }

  /// Read the next field to check, from `f` on (fields expected as 0 are skipped).
  [[nodiscard]] constexpr step read_identity(identity_field f, std::uint32_t now) noexcept {
    auto i = static_cast<std::uint8_t>(f);
    while (i <= static_cast<std::uint8_t>(identity_field::serial) &&
           value_of(config_.expected, static_cast<identity_field>(i)) == 0U) {
      ++i;
    }
    if (i > static_cast<std::uint8_t>(identity_field::serial)) return configure(now);
    field_ = static_cast<identity_field>(i);
    state_ = boot_state::reading_identity;
    auto s = client_->upload(address_of(field_), buffer_, now);
    if (!s) return fail({boot_failure::identity_read_failed, s.error(), field_});
    deadline_ = s.value().deadline;
    return make(s.value().send);
  }
  [[nodiscard]] constexpr step identity_answer(const canopen::sdo::step &s,
                                               std::uint32_t now) noexcept {
    deadline_ = s.deadline;
    if (client_->state() == canopen::sdo::transfer_state::busy) return make(s.send);
    if (client_->state() == canopen::sdo::transfer_state::failed) {
      const auto e = client_->error();
      boot_error b{boot_failure::identity_read_failed, e ? e->code : errc::aborted, field_};
      b.sdo = e;
      auto r = fail(b);
      r.send = s.send; // the client's abort, if it sent one
      return r;
    }
    const auto v = client_->received();
    if (v.size() != 4U) {
      return fail({boot_failure::identity_read_failed, errc::bad_length, field_});
    }
    std::uint32_t actual = 0;
    for (std::size_t i = 0; i < 4U; ++i) actual |= std::uint32_t{v[i]} << (8U * i);
    set(read_, field_, actual);
    const auto expected = value_of(config_.expected, field_);
    if (actual != expected) {
      return fail({boot_failure::identity_mismatch, errc::out_of_range, field_, expected, actual});
    }
    if (field_ == identity_field::serial) return configure(now);
    return read_identity(static_cast<identity_field>(static_cast<std::uint8_t>(field_) + 1U), now);
  }

  [[nodiscard]] constexpr step configure(std::uint32_t now) noexcept {
    state_ = boot_state::configuring;
    auto s = config_run_.start(config_, now, node_);
    if (!s) return fail({boot_failure::configuration_failed, s.error()});
    return configured(s.value(), now);
  }
  [[nodiscard]] constexpr step configured(const configurator::step &s, std::uint32_t now) noexcept {
    deadline_ = s.deadline;
    if (config_run_.state() == config_state::failed) {
      boot_error b{boot_failure::configuration_failed, errc::aborted};
      b.config = config_run_.error();
      if (b.config) b.code = b.config->code;
      auto r = fail(b);
      r.send = s.send;
      return r;
    }
    if (config_run_.state() != config_state::done) return make(s.send);
    if (opt_.heartbeat_timeout_ms != 0U) {
      state_ = boot_state::waiting_heartbeat;
      deadline_ = now + opt_.heartbeat_timeout_ms;
      return make(s.send);
    }
    return start_node();
  }
  [[nodiscard]] constexpr step start_node() noexcept {
    state_ = boot_state::done;
    deadline_.reset();
    if (!opt_.start) return make({});
    out_ = canopen::nmt::encode(canopen::nmt::command::start, node_).value();
    return make(canopen::frames(*out_));
  }

  std::uint8_t node_;
  canopen::sdo::client *client_;
  boot_options opt_;
  configurator config_run_;
  configuration config_{};
  boot_state state_ = boot_state::idle;
  identity_field field_ = identity_field::device_type;
  identity read_{};
  std::array<std::uint8_t, 4> buffer_{};
  std::optional<canopen::can_frame> out_{};
  std::optional<std::uint32_t> deadline_{};
  std::optional<boot_error> error_{};
};

} // namespace fieldcodec::master
