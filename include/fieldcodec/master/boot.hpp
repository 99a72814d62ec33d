// fieldcodec — the boot-up of one device by a master ("boot slave", CiA 302-2), in either of two
// forms (docs/master.md, "Boot-up"):
//
// * from a C++ `configuration` (config.hpp; fieldcodec-gen --config-list writes one from the
//   device's DCF):
//   1. reset communication (NMT 0x82) and wait for the boot-up message, or only wait for it;
//   2. read 1000h and 1018h sub 1..4 and compare them with the expected identity (0 = not
//      checked); a mismatch names the field, the expected and the actual value;
//   3. run the configuration list (master::configurator: retries, timeout, verify);
//   4. optionally wait for the first heartbeat of the device (its producer runs), then start
//      the master's heartbeat consumption: `heartbeat_entry()` is the 1016h entry {node,
//      consumer time} for the caller's `canopen::node::heartbeat_consumer`;
//   5. NMT start (0x01), report.
//
// * from the CiA 302 objects of the master's own DCF for that node (`slave_objects`:
//   1F81h slave assignment, 1F84h..1F88h expected identity, 1F22h concise DCF, the master's
//   1016h consumer time, 1F55h, 1F26h/1F27h, 1F8Ah; fieldcodec-gen --nmt-slaves writes them
//   from a master DCF), the boot slave process of CiA 302-2 as lely's master runs it: not in the
//   network list (A); 1000h always read (B, C) and 1018h sub 1..4 checked when expected (D, M, N,
//   O); with the keep-alive bit the node's state first (heartbeat or node guarding, E / F; an
//   operational node keeps running: L); the software version (G, H, I); restore defaults and the
//   concise DCF unless 1020h shows the expected configuration date and time (J); the first
//   heartbeat (K); NMT start. A failure reports the CiA 302-2 error status letter.
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
#include <span>
#include <string_view>

namespace fieldcodec::master {

// ---------------------------------------------------------------------------------------------
// States and errors

enum class boot_state : std::uint8_t {
  idle,
  waiting_boot_up,
  reading_identity,
  checking_node_state,    ///< keep-alive: heartbeat or guarding answer awaited
  checking_software,      ///< 1F56h sub 1 read
  restoring,              ///< "load" written to 1011h, then the reset and the boot-up
  checking_configuration, ///< 1020h sub 1 / 2 read
  configuring,
  waiting_heartbeat,
  done, ///< NMT start sent (or not asked for, or the node was operational already: status L)
  failed,
};

[[nodiscard]] constexpr std::string_view to_string(boot_state s) noexcept {
  switch (s) {
  case boot_state::idle: return "idle";
  case boot_state::waiting_boot_up: return "waiting for boot-up";
  case boot_state::reading_identity: return "reading identity";
  case boot_state::checking_node_state: return "checking node state";
  case boot_state::checking_software: return "checking software version";
  case boot_state::restoring: return "restoring defaults";
  case boot_state::checking_configuration: return "checking configuration date";
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
  configuration_failed, ///< the configurator failed (config says which item and why), or the
                        ///< restore before it
  no_heartbeat,         ///< no heartbeat in time
  not_assigned,         ///< 1F81h bit 0 clear: not a slave of this master
  no_node_state,        ///< keep-alive: neither heartbeat nor guarding answer in time
  software_not_checked, ///< bit 5: 1F55h is 0, or 1F56h sub 1 could not be read
  software_mismatch,    ///< 1F56h sub 1 differs from 1F55h (`expected`, `actual`)
};

/// A short, stable text for a boot failure (for reports; the texts do not change between
/// versions).
[[nodiscard]] constexpr std::string_view to_string(boot_failure f) noexcept {
  switch (f) {
  case boot_failure::no_boot_up: return "no boot-up message";
  case boot_failure::identity_read_failed: return "identity could not be read";
  case boot_failure::identity_mismatch: return "identity mismatch";
  case boot_failure::configuration_failed: return "configuration failed";
  case boot_failure::no_heartbeat: return "no heartbeat";
  case boot_failure::not_assigned: return "not a slave of this master";
  case boot_failure::no_node_state: return "node state unknown";
  case boot_failure::software_not_checked: return "software version not checked";
  case boot_failure::software_mismatch: return "software version mismatch";
  }
  return "?";
}

/// The error status of the boot slave process, CiA 302-2: the letter a CiA 302 manager
/// reports for a slave (`code(s)`), 0 when the boot succeeded.
enum class boot_status : char {
  ok = 0,
  not_in_network_list = 'A',     ///< 1F81h bit 0 clear
  no_device_type = 'B',          ///< no answer to the read of 1000h (nor a boot-up before it)
  device_type_mismatch = 'C',    ///< 1000h differs from 1F84h
  vendor_id_mismatch = 'D',      ///< 1018h sub 1 differs from 1F85h, or could not be read
  no_heartbeat_state = 'E',      ///< keep-alive: no heartbeat to tell the node's state
  no_guarding_state = 'F',       ///< keep-alive: no answer to node guarding
  software_not_configured = 'G', ///< version check asked for, 1F55h not set or 1F56h unread
  software_mismatch = 'H',       ///< 1F56h differs from 1F55h, no update allowed
  software_update_failed = 'I',  ///< 1F56h differs, update allowed but not done
  configuration_failed = 'J',    ///< restore or configuration download failed
  no_heartbeat = 'K',            ///< no heartbeat after the error control service started
  initially_operational = 'L',   ///< keep-alive: the node was operational; it keeps running
  product_code_mismatch = 'M',   ///< 1018h sub 2 differs from 1F86h, or could not be read
  revision_mismatch = 'N',       ///< 1018h sub 3 differs from 1F87h, or could not be read
  serial_mismatch = 'O',         ///< 1018h sub 4 differs from 1F88h, or could not be read
};

/// The CiA 302-2 letter ('A'…'O'; '\0' for ok).
[[nodiscard]] constexpr char code(boot_status s) noexcept { return static_cast<char>(s); }

/// A short, stable text for an error status (for reports; the texts do not change between
/// versions).
[[nodiscard]] constexpr std::string_view to_string(boot_status s) noexcept {
  switch (s) {
  case boot_status::ok: return "booted";
  case boot_status::not_in_network_list: return "A: not in the network list";
  case boot_status::no_device_type: return "B: no answer for the device type";
  case boot_status::device_type_mismatch: return "C: device type mismatch";
  case boot_status::vendor_id_mismatch: return "D: vendor-ID mismatch";
  case boot_status::no_heartbeat_state: return "E: no heartbeat for the node state";
  case boot_status::no_guarding_state: return "F: no guarding answer for the node state";
  case boot_status::software_not_configured: return "G: software version not configured";
  case boot_status::software_mismatch: return "H: software version mismatch";
  case boot_status::software_update_failed: return "I: software update failed";
  case boot_status::configuration_failed: return "J: configuration download failed";
  case boot_status::no_heartbeat: return "K: no heartbeat";
  case boot_status::initially_operational: return "L: initially operational";
  case boot_status::product_code_mismatch: return "M: product code mismatch";
  case boot_status::revision_mismatch: return "N: revision number mismatch";
  case boot_status::serial_mismatch: return "O: serial number mismatch";
  }
  return "?";
}

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
  std::uint32_t expected = 0;                         ///< identity / software mismatch
  std::uint32_t actual = 0;                           ///< identity / software mismatch
  std::optional<canopen::sdo::transfer_error> sdo{};  ///< a read or the restore failed
  std::optional<config_error> config{};               ///< configuration_failed by the configurator
  boot_status status = boot_status::no_device_type;   ///< the CiA 302-2 letter of this failure

  [[nodiscard]] constexpr bool is(errc e) const noexcept { return code == e; }
};

struct boot_options {
  bool reset_communication = true; ///< send NMT reset communication first (not to a keep-alive
                                   ///< slave: its state is checked instead)
  bool wait_boot_up = true;        ///< wait for the boot-up message (after the reset, or alone)
  std::uint32_t boot_timeout_ms = 2000; ///< for each boot-up awaited
  /// configuration: 0 = do not wait for a heartbeat (slave_objects: the consumer time is the
  /// wait, 0 = none)
  std::uint32_t heartbeat_timeout_ms = 0;
  /// configuration: the master's heartbeat consumer time for this node (ms; 0: none):
  /// heartbeat_entry(). Usually 1.5 to 2 × the producer time the list writes to 1017h.
  /// (slave_objects: consumer_time_ms there.)
  std::uint16_t consumer_time_ms = 0;
  std::uint8_t read_retries = 0;     ///< further attempts of a timed-out identity or version read
  std::uint32_t guard_wait_ms = 100; ///< keep-alive without heartbeat: wait for a guarding answer
  bool start = true;                 ///< send NMT start at the end
  config_options config{};           ///< for the configuration list or concise DCF
};

class boot {
public:
  using step = canopen::step<boot_state>;

  /// The boot-up of `node` (1..127) through `client` (the node's SDO client, owned by the
  /// caller and not used by anyone else while this runs).
  constexpr boot(std::uint8_t node, canopen::sdo::client &client, boot_options o = {}) noexcept
      : node_(node), client_(&client), opt_(o), config_run_(client, o.config) {}

  /// Start with a configuration. Errors: invalid_argument (node not 1..127), bad_state
  /// (running, or the client is busy).
  [[nodiscard]] constexpr result<step> start(const configuration &c, std::uint32_t now) noexcept {
    if (node_ < 1U || node_ > 127U) return errc::invalid_argument;
    if (busy() || client_->busy()) return errc::bad_state;
    config_ = c;
    slave_ = {assignment_bit::slave | assignment_bit::boot, c.expected, {}, opt_.consumer_time_ms};
    from_302_ = false;
    return begin(now);
  }

  /// Start with the master's CiA 302 objects for this node. A node that is not in the network
  /// list (1F81h bit 0) ends at once: failed with status A. Errors: invalid_argument (node not
  /// 1..127), bad_state (running, or the client is busy), truncated / bad_length (the concise
  /// DCF, check_concise_dcf: nothing is sent).
  [[nodiscard]] constexpr result<step> start(const slave_objects &s, std::uint32_t now) noexcept {
    if (node_ < 1U || node_ > 127U) return errc::invalid_argument;
    if (busy() || client_->busy()) return errc::bad_state;
    if (!s.concise_dcf.empty()) {
      FIELDCODEC_TRY_STATUS(check_concise_dcf(s.concise_dcf));
    }
    config_ = {};
    slave_ = s;
    from_302_ = true;
    if ((s.assignment & assignment_bit::slave) == 0U) {
      clear();
      return fail({boot_failure::not_assigned, errc::invalid_argument},
                  boot_status::not_in_network_list);
    }
    return begin(now);
  }

  /// Consume a received frame (NMT error control of the node and its SDO responses; others are
  /// ignored).
  [[nodiscard]] constexpr step on_frame(const canopen::can_frame &f, std::uint32_t now) noexcept {
    const bool error_control = f.id == 0x700U + node_ && f.dlc == 1U && !f.rtr;
    switch (state_) {
    case boot_state::waiting_boot_up:
      if (error_control && f.data[0] == 0U) return booted_up(now);
      return make({});
    case boot_state::checking_node_state:
      if (error_control) return node_state(static_cast<std::uint8_t>(f.data[0] & 0x7FU), now);
      return make({});
    case boot_state::reading_identity:
    case boot_state::checking_software:
    case boot_state::restoring:
    case boot_state::checking_configuration: return sdo_answer(client_->on_frame(f, now), now);
    case boot_state::configuring: return configured(config_run_.on_frame(f, now), now);
    case boot_state::waiting_heartbeat:
      if (error_control && f.data[0] != 0U) return start_node();
      return make({});
    default: return make({});
    }
  }

  /// Check the timeouts.
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    switch (state_) {
    case boot_state::reading_identity:
    case boot_state::checking_software:
    case boot_state::restoring:
    case boot_state::checking_configuration: return sdo_answer(client_->poll(now), now);
    case boot_state::configuring: return configured(config_run_.poll(now), now);
    case boot_state::waiting_boot_up:
    case boot_state::checking_node_state:
    case boot_state::waiting_heartbeat:
      if (deadline_ && canopen::reached(*deadline_, now)) return timed_out();
      return make({});
    default: return make({});
    }
  }

  [[nodiscard]] constexpr boot_state state() const noexcept { return state_; }
  [[nodiscard]] constexpr bool busy() const noexcept {
    return state_ != boot_state::idle && state_ != boot_state::done && state_ != boot_state::failed;
  }
  [[nodiscard]] constexpr std::optional<boot_error> error() const noexcept { return error_; }
  /// The CiA 302-2 error status: ok while running and when booted, initially_operational when
  /// done with a keep-alive node that was running, the failure's letter when failed.
  [[nodiscard]] constexpr boot_status status() const noexcept {
    if (error_) return error_->status;
    return was_operational_ && state_ == boot_state::done ? boot_status::initially_operational
                                                          : boot_status::ok;
  }
  /// The identity read from the device (fields not read stay 0).
  [[nodiscard]] constexpr identity read_identity_values() const noexcept { return read_; }
  [[nodiscard]] constexpr std::uint8_t node() const noexcept { return node_; }
  /// The entry with which the master consumes this node's heartbeat (1016h format: node,
  /// consumer time); inactive when the consumer time is 0. Start consumption when state() is
  /// done: `consumer.configure(i, boot.heartbeat_entry().to_u32(), now)`.
  [[nodiscard]] constexpr canopen::node::consumer_entry heartbeat_entry() const noexcept {
    return {node_, slave_.consumer_time_ms};
  }

private:
  /// What follows the boot-up the machine waits for.
  enum class after : std::uint8_t { identity, software, configuration };
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
  /// The CiA 302-2 letter of a failed or differing identity field.
  [[nodiscard]] static constexpr boot_status status_of(identity_field f, bool read) noexcept {
    switch (f) {
    case identity_field::device_type:
      return read ? boot_status::device_type_mismatch : boot_status::no_device_type;
    case identity_field::vendor_id: return boot_status::vendor_id_mismatch;
    case identity_field::product_code: return boot_status::product_code_mismatch;
    case identity_field::revision: return boot_status::revision_mismatch;
    case identity_field::serial: return boot_status::serial_mismatch;
    }
    return boot_status::no_device_type;
  }
  [[nodiscard]] constexpr bool has(std::uint32_t bit) const noexcept {
    return (slave_.assignment & bit) != 0U;
  }

  [[nodiscard]] constexpr step make(canopen::frames f) const noexcept {
    step s;
    s.send = f;
    s.state = state_;
    if (busy()) s.deadline = deadline_;
    return s;
  }
  [[nodiscard]] constexpr step fail(boot_error e, boot_status status) noexcept {
    e.status = status;
    error_ = e;
    state_ = boot_state::failed;
    deadline_.reset();
    return make({});
  }
  [[nodiscard]] constexpr step send_nmt(canopen::nmt::command c) noexcept {
    out_ = canopen::nmt::encode(c, node_).value();
    return make(canopen::frames(*out_));
  }
  [[nodiscard]] constexpr step wait(boot_state s, std::uint32_t until) noexcept {
    state_ = s;
    deadline_ = until;
    return make({});
  }

  constexpr void clear() noexcept {
    error_.reset();
    read_ = {};
    out_.reset();
    was_operational_ = false;
    attempts_ = 0;
  }
  [[nodiscard]] constexpr step begin(std::uint32_t now) noexcept {
    clear();
    if (!has(assignment_bit::boot)) return error_control(now); // 1F81h: error control only
    if (!has(assignment_bit::keep_alive) && opt_.reset_communication) {
      after_ = after::identity;
      (void)wait(boot_state::waiting_boot_up, now + opt_.boot_timeout_ms);
      return send_nmt(canopen::nmt::command::reset_communication);
    }
    if (!has(assignment_bit::keep_alive) && opt_.wait_boot_up) {
      after_ = after::identity;
      return wait(boot_state::waiting_boot_up, now + opt_.boot_timeout_ms);
    }
    return read_identity(identity_field::device_type, now);
  }

  [[nodiscard]] constexpr step booted_up(std::uint32_t now) noexcept {
    switch (after_) {
    case after::identity: return read_identity(identity_field::device_type, now);
    case after::software: return check_software(now);
    case after::configuration: return check_configuration(now);
    }
    return make({});
  }
  [[nodiscard]] constexpr step timed_out() noexcept {
    switch (state_) {
    case boot_state::waiting_boot_up:
      // after a restore the configuration failed; after a keep-alive reset the node state is
      // what could not be established; otherwise the device never answered
      if (after_ == after::configuration) {
        return fail({boot_failure::configuration_failed, errc::timeout},
                    boot_status::configuration_failed);
      }
      if (after_ == after::software) {
        return fail({boot_failure::no_node_state, errc::timeout}, node_state_status());
      }
      return fail({boot_failure::no_boot_up, errc::timeout}, boot_status::no_device_type);
    case boot_state::checking_node_state:
      return fail({boot_failure::no_node_state, errc::timeout}, node_state_status());
    default: return fail({boot_failure::no_heartbeat, errc::timeout}, boot_status::no_heartbeat);
    }
  }
  [[nodiscard]] constexpr boot_status node_state_status() const noexcept {
    return slave_.consumer_time_ms != 0U ? boot_status::no_heartbeat_state
                                         : boot_status::no_guarding_state;
  }

  // ----- SDO reads and the restore ----------------------------------------------------------

  /// Start reading `a` (4 bytes) in state `s`.
  [[nodiscard]] constexpr step read(od::address a, boot_state s, std::uint32_t now) noexcept {
    state_ = s;
    reading_ = a;
    auto r = client_->upload(a, buffer_, now);
    if (!r) return read_failed(r.error(), {}, now);
    deadline_ = r.value().deadline;
    return make(r.value().send);
  }
  [[nodiscard]] constexpr step sdo_answer(const canopen::sdo::step &s, std::uint32_t now) noexcept {
    deadline_ = s.deadline;
    if (client_->state() == canopen::sdo::transfer_state::busy) return make(s.send);
    if (client_->state() == canopen::sdo::transfer_state::failed) {
      const auto e = client_->error();
      const errc code = e ? e->code : errc::aborted;
      if (code == errc::timeout && state_ != boot_state::restoring &&
          attempts_ < opt_.read_retries) {
        ++attempts_;
        auto r = read(reading_, state_, now); // once more
        return with_first(s.send, r);         // after the client's abort, if it sent one
      }
      return with_first(s.send, read_failed(code, e, now));
    }
    attempts_ = 0;
    if (state_ == boot_state::restoring) return restored(now);
    const auto v = client_->received();
    if (v.size() != 4U) return read_failed(errc::bad_length, {}, now);
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4U; ++i) value |= std::uint32_t{v[i]} << (8U * i);
    switch (state_) {
    case boot_state::reading_identity: return identity_read(value, now);
    case boot_state::checking_software: return software_read(value, now);
    default: return configuration_read(value, now);
    }
  }
  /// `r` with the frames of `first` sent before its own (at most one each).
  [[nodiscard]] constexpr step with_first(const canopen::frames &first, step r) noexcept {
    if (first.empty()) return r;
    if (r.send.empty()) {
      r.send = first;
      return r;
    }
    pair_ = {first[0], r.send[0]};
    r.send = canopen::frames(std::span<const canopen::can_frame>(pair_));
    return r;
  }
  [[nodiscard]] constexpr step read_failed(errc code, std::optional<canopen::sdo::transfer_error> e,
                                           std::uint32_t now) noexcept {
    attempts_ = 0;
    switch (state_) {
    case boot_state::reading_identity: {
      boot_error b{boot_failure::identity_read_failed, code, field_};
      b.sdo = e;
      return fail(b, status_of(field_, false));
    }
    case boot_state::checking_software: {
      boot_error b{boot_failure::software_not_checked, code};
      b.sdo = e;
      return fail(b, boot_status::software_not_configured);
    }
    case boot_state::restoring: {
      boot_error b{boot_failure::configuration_failed, code};
      b.sdo = e;
      return fail(b, boot_status::configuration_failed);
    }
    default: return download(now); // 1020h unreadable: the configuration is downloaded
    }
  }

  // ----- identity ---------------------------------------------------------------------------

  /// Read the next field to check, from `f` on (fields expected as 0 are skipped, except the
  /// device type of a CiA 302 boot, which is always read: it tells that the device is there).
  [[nodiscard]] constexpr step read_identity(identity_field f, std::uint32_t now) noexcept {
    auto i = static_cast<std::uint8_t>(f);
    while (i <= static_cast<std::uint8_t>(identity_field::serial) &&
           value_of(slave_.expected, static_cast<identity_field>(i)) == 0U &&
           !(from_302_ && i == 0U)) {
      ++i;
    }
    if (i > static_cast<std::uint8_t>(identity_field::serial)) return identity_checked(now);
    field_ = static_cast<identity_field>(i);
    return read(address_of(field_), boot_state::reading_identity, now);
  }
  [[nodiscard]] constexpr step identity_read(std::uint32_t actual, std::uint32_t now) noexcept {
    set(read_, field_, actual);
    const auto expected = value_of(slave_.expected, field_);
    if (expected != 0U && actual != expected) {
      return fail({boot_failure::identity_mismatch, errc::out_of_range, field_, expected, actual},
                  status_of(field_, true));
    }
    if (field_ == identity_field::serial) return identity_checked(now);
    return read_identity(static_cast<identity_field>(static_cast<std::uint8_t>(field_) + 1U), now);
  }
  [[nodiscard]] constexpr step identity_checked(std::uint32_t now) noexcept {
    if (!has(assignment_bit::keep_alive)) return check_software(now);
    // keep-alive: the node's state decides (operational: it keeps running)
    state_ = boot_state::checking_node_state;
    if (slave_.consumer_time_ms != 0U) {
      return wait(boot_state::checking_node_state, now + slave_.consumer_time_ms);
    }
    (void)wait(boot_state::checking_node_state, now + opt_.guard_wait_ms);
    out_ = canopen::nmt::encode_guard_request(node_).value();
    return make(canopen::frames(*out_));
  }
  [[nodiscard]] constexpr step node_state(std::uint8_t s, std::uint32_t now) noexcept {
    if (s == static_cast<std::uint8_t>(canopen::nmt::state::operational)) {
      was_operational_ = true;
      return error_control(now);
    }
    // not operational: reset it and go on as without keep-alive
    after_ = after::software;
    (void)wait(boot_state::waiting_boot_up, now + opt_.boot_timeout_ms);
    return send_nmt(canopen::nmt::command::reset_communication);
  }

  // ----- software version, restore, configuration -------------------------------------------

  [[nodiscard]] constexpr step check_software(std::uint32_t now) noexcept {
    if (!has(assignment_bit::verify_software)) return restore(now);
    if (slave_.software_version == 0U) {
      return fail({boot_failure::software_not_checked, errc::invalid_argument},
                  boot_status::software_not_configured);
    }
    return read({0x1F56, 1}, boot_state::checking_software, now);
  }
  [[nodiscard]] constexpr step software_read(std::uint32_t actual, std::uint32_t now) noexcept {
    if (actual == slave_.software_version) return restore(now);
    boot_error b{boot_failure::software_mismatch, errc::out_of_range};
    b.expected = slave_.software_version;
    b.actual = actual;
    // an update is allowed only without keep-alive; this machine downloads no software, so an
    // allowed update counts as failed (I)
    if ((slave_.assignment & (assignment_bit::update_software | assignment_bit::keep_alive)) ==
        assignment_bit::update_software) {
      return fail(b, boot_status::software_update_failed);
    }
    return fail(b, boot_status::software_mismatch);
  }
  [[nodiscard]] constexpr step restore(std::uint32_t now) noexcept {
    if (!has(assignment_bit::restore) || slave_.restore_sub == 0U) return check_configuration(now);
    state_ = boot_state::restoring;
    reading_ = {0x1011, slave_.restore_sub};
    auto r = client_->download(reading_, load_signature, now);
    if (!r) return read_failed(r.error(), {}, now);
    deadline_ = r.value().deadline;
    return make(r.value().send);
  }
  [[nodiscard]] constexpr step restored(std::uint32_t now) noexcept {
    // communication parameters (sub 2): reset communication; the others: reset node
    after_ = after::configuration;
    (void)wait(boot_state::waiting_boot_up, now + opt_.boot_timeout_ms);
    return send_nmt(slave_.restore_sub == 2U ? canopen::nmt::command::reset_communication
                                             : canopen::nmt::command::reset_node);
  }
  [[nodiscard]] constexpr step check_configuration(std::uint32_t now) noexcept {
    if (!from_302_ || slave_.configuration_date == 0U || slave_.configuration_time == 0U) {
      return download(now);
    }
    return read({0x1020, 1}, boot_state::checking_configuration, now);
  }
  [[nodiscard]] constexpr step configuration_read(std::uint32_t v, std::uint32_t now) noexcept {
    if (reading_.sub == 1U) {
      if (v != slave_.configuration_date) return download(now);
      return read({0x1020, 2}, boot_state::checking_configuration, now);
    }
    if (v != slave_.configuration_time) return download(now);
    return error_control(now); // the device keeps the expected configuration
  }
  [[nodiscard]] constexpr step download(std::uint32_t now) noexcept {
    if (from_302_ && slave_.concise_dcf.empty()) return error_control(now);
    state_ = boot_state::configuring;
    auto s = from_302_ ? config_run_.start_concise(slave_.concise_dcf, now)
                       : config_run_.start(config_, now, node_);
    if (!s) {
      return fail({boot_failure::configuration_failed, s.error()},
                  boot_status::configuration_failed);
    }
    return configured(s.value(), now);
  }
  [[nodiscard]] constexpr step configured(const configurator::step &s, std::uint32_t now) noexcept {
    deadline_ = s.deadline;
    if (config_run_.state() == config_state::failed) {
      boot_error b{boot_failure::configuration_failed, errc::aborted};
      b.config = config_run_.error();
      if (b.config) b.code = b.config->code;
      auto r = fail(b, boot_status::configuration_failed);
      r.send = s.send;
      return r;
    }
    if (config_run_.state() != config_state::done) return make(s.send);
    auto r = error_control(now);
    if (r.send.empty()) r.send = s.send;
    return r;
  }

  // ----- error control and start ------------------------------------------------------------

  [[nodiscard]] constexpr step error_control(std::uint32_t now) noexcept {
    const std::uint32_t wait_ms = from_302_ ? slave_.consumer_time_ms : opt_.heartbeat_timeout_ms;
    if (wait_ms != 0U) return wait(boot_state::waiting_heartbeat, now + wait_ms);
    return start_node();
  }
  [[nodiscard]] constexpr step start_node() noexcept {
    state_ = boot_state::done;
    deadline_.reset();
    if (!opt_.start || was_operational_) return make({});
    return send_nmt(canopen::nmt::command::start);
  }

  /// "load" (CiA 301, 1011h): 6Ch 6Fh 61h 64h.
  static constexpr std::array<std::uint8_t, 4> load_signature{'l', 'o', 'a', 'd'};

  std::uint8_t node_;
  canopen::sdo::client *client_;
  boot_options opt_;
  configurator config_run_;
  configuration config_{};
  slave_objects slave_{};
  bool from_302_ = false;
  bool was_operational_ = false;
  after after_ = after::identity;
  std::uint8_t attempts_ = 0;
  boot_state state_ = boot_state::idle;
  identity_field field_ = identity_field::device_type;
  od::address reading_{};
  identity read_{};
  std::array<std::uint8_t, 4> buffer_{};
  std::optional<canopen::can_frame> out_{};
  std::array<canopen::can_frame, 2> pair_{}; ///< an abort and the request that follows it
  std::optional<std::uint32_t> deadline_{};
  std::optional<boot_error> error_{};
};

} // namespace fieldcodec::master
