// fieldcodec — host adapters: a CiA 402 drive on the bus, as python canopen's BaseNode402 gives
// it: master::drive (the pure helper that knows words, not frames) run by a cyclic task over a
// host::remote_node that sets itself up.
//
//   host::remote_node node(bus, 5, x::dictionary, xenax::canopen_units);
//   host::remote_drive axis(node);
//   auto r = axis.setup();                                   // PDOs found, or SDO
//   if (r) r = axis.enable();                                // operation enabled
//   if (r) r = axis.switch_mode(ds402::mode::profile_position);
//   if (r) r = axis.move_to(od::signed_number(12345));       // 607Ah in its unit, checked
//   if (!r) puts(r.error().what.c_str());
//
// setup() reads the node's PDO mappings (remote_node::read_pdos) and looks for the controlword
// 6040h in a valid RPDO, the statusword 6041h in a valid TPDO, the targets 607Ah / 60FFh in an
// RPDO and the mode display 6061h in a TPDO, each PDO event-driven (transmission type 254/255:
// one on SYNC would need a SYNC producer); each word it does not find travels by SDO (python's
// setup_402_state_machine does the same). When a PDO is used it starts the node (NMT start:
// PDOs run in operational only). The commands block: a cycle every `cycle` (10 ms by default)
// gives the statusword to the machine and sends its controlword and target, runs the SDO
// transfers the machine asks for through the node (6060h, 607Ah when not in a PDO, 603Fh), and
// hands the node's EMCYs to it, until the command is done, failed, or its time is up.
//
// One value path: a target is a value of 607Ah / 60FFh in the object's unit (od::encode_value
// with its limits and scale, via remote_node::to_raw); every word and target, in a PDO or by
// SDO, goes out through remote_node's checked calls. Host only.
#pragma once

#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/state_machine.hpp>
#include <fieldcodec/host/remote_node.hpp>
#include <fieldcodec/master/drive.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/number.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

namespace fieldcodec::host {

/// Why a command of remote_drive failed.
struct remote_drive_error {
  errc code = errc::bad_state;
  std::optional<master::drive_error> drive{}; ///< the machine's failure (fault, timeout, …)
  std::optional<sdo_error> node{};            ///< a call of the node failed (SDO, PDO, bus)
  std::string what;                           ///< one line
};

/// Where the words travel (setup's findings).
struct drive_channels {
  std::uint16_t controlword_rpdo = 0;  ///< RPDO number carrying 6040h; 0: by SDO
  std::uint16_t statusword_tpdo = 0;   ///< TPDO number carrying 6041h; 0: by SDO
  std::uint16_t position_rpdo = 0;     ///< RPDO carrying 607Ah; 0: by SDO
  std::uint16_t velocity_rpdo = 0;     ///< RPDO carrying 60FFh; 0: by SDO
  std::uint16_t mode_display_tpdo = 0; ///< TPDO carrying 6061h; 0: read by SDO when needed
};

struct remote_drive_options {
  master::drive_options drive{};                    ///< the machine's (profile, timeouts)
  std::chrono::milliseconds cycle{10};              ///< the cyclic task's period
  std::chrono::milliseconds command_timeout{10000}; ///< the longest a command may run
  bool use_pdos = true;   ///< false: every word by SDO, whatever the mapping
  bool start_node = true; ///< setup() sends NMT start when a PDO is used
};

class remote_drive {
public:
  static constexpr od::address controlword{0x6040, 0};
  static constexpr od::address statusword{0x6041, 0};

  /// The drive `node` (borrowed; it must outlive this).
  explicit remote_drive(remote_node &node, remote_drive_options o = {})
      : node_(&node), opt_(o), axis_(o.drive) {}

  /// Find the words' PDOs (or SDO: channels() says which), start the node when a PDO is used,
  /// read the statusword.
  /// Errors: those of remote_node::read_pdos and send_nmt, of the first statusword read.
  result<void, remote_drive_error> setup() {
    using canopen::pdo::direction;
    ch_ = {};
    if (opt_.use_pdos) {
      if (auto r = node_->read_pdos(); !r) return failed(r.error());
      // an event-driven (asynchronous) PDO: one on SYNC (transmission type 0..240) would need
      // a SYNC producer, which this helper does not run
      const auto number = [this](direction d, od::address a) -> std::uint16_t {
        for (const remote_pdo &p : node_->pdos()) {
          if (p.dir == d && p.valid && p.transmission >= 254U && p.find(a) < p.map.size())
            return p.number;
        }
        return 0;
      };
      ch_.controlword_rpdo = number(direction::rpdo, controlword);
      ch_.statusword_tpdo = number(direction::tpdo, statusword);
      ch_.position_rpdo = number(direction::rpdo, master::obj::target_position);
      ch_.velocity_rpdo = number(direction::rpdo, master::obj::target_velocity);
      ch_.mode_display_tpdo = number(direction::tpdo, master::obj::modes_of_operation_display);
    }
    master::drive_options d = opt_.drive;
    // a target the RPDOs do not carry is written by SDO (the machine's own requests)
    const bool velocity_known = node_->dictionary().contains(master::obj::target_velocity);
    d.target_over_sdo = ch_.position_rpdo == 0U || (velocity_known && ch_.velocity_rpdo == 0U);
    axis_ = master::drive(d);
    const bool any_pdo = ch_.controlword_rpdo != 0U || ch_.statusword_tpdo != 0U;
    if (any_pdo && opt_.start_node) {
      if (auto r = node_->send_nmt(canopen::nmt::command::start); !r) return failed(r.error());
    }
    emcy_seen_ = node_->emcy_count();
    if (auto s = read_statusword(); !s) return s.error();
    ready_ = true;
    return {};
  }

  /// Walk to operation enabled. Errors: bad_state (setup() not done, or the machine refuses:
  /// a fault), the machine's failure (enable_timeout, fault: drive set), the node's.
  result<void, remote_drive_error> enable() {
    return command([this](std::uint32_t now) { return axis_.enable(now); });
  }
  /// Walk to `target` (switch on disabled by default).
  result<void, remote_drive_error> disable(ds402::state target = ds402::state::switch_on_disabled) {
    return command([this, target](std::uint32_t now) { return axis_.disable(now, target); });
  }
  /// Fault reset (rising edge of bit 7, bounded retries).
  result<void, remote_drive_error> reset_fault() {
    return command([this](std::uint32_t now) { return axis_.reset_fault(now); });
  }
  /// Write 6060h and wait for 6061h to show `m`.
  result<void, remote_drive_error> switch_mode(ds402::mode m) {
    return command([this, m](std::uint32_t now) { return axis_.switch_mode(m, now); });
  }
  /// Profile position: go to `target`, a value of 607Ah in its unit (checked against its
  /// limits and field, scaled), and wait until target reached. Errors: the value's (nothing
  /// sent), those of the machine (set-point not acknowledged, following error, …).
  result<void, remote_drive_error> move_to(od::number target, bool relative = false) {
    auto raw = target_raw(master::obj::target_position, target);
    if (!raw) return raw.error();
    return command([this, raw, relative](std::uint32_t now) {
      return axis_.move_to(raw.value(), now, relative);
    });
  }
  /// Profile velocity: run at `velocity` (60FFh in its unit, checked); returns once the
  /// command is in effect — keep the cyclic task running with cycle_for().
  result<void, remote_drive_error> run_velocity(od::number velocity) {
    auto raw = target_raw(master::obj::target_velocity, velocity);
    if (!raw) return raw.error();
    return command([this, raw](std::uint32_t now) { return axis_.run_velocity(raw.value(), now); });
  }
  /// Keep the cyclic task running for `ms` (a running velocity, the words' keep-alive).
  result<void, remote_drive_error> cycle_for(std::chrono::milliseconds ms) {
    const auto end = std::chrono::steady_clock::now() + ms;
    while (std::chrono::steady_clock::now() < end) {
      if (auto r = one_cycle(); !r) return r;
      if (axis_.state() == master::drive_state::fault ||
          axis_.state() == master::drive_state::failed)
        return machine_failed();
    }
    return {};
  }

  [[nodiscard]] const master::drive &machine() const noexcept { return axis_; }
  [[nodiscard]] const drive_channels &channels() const noexcept { return ch_; }
  [[nodiscard]] remote_node &node() noexcept { return *node_; }
  /// The statusword of the last cycle.
  [[nodiscard]] std::uint16_t last_statusword() const noexcept { return sw_; }

private:
  template <class Start>
  result<void, remote_drive_error> command(Start start) {
    if (!ready_) {
      remote_drive_error e;
      e.what = "node " + std::to_string(node_->node()) + ": the drive is not set up (setup())";
      return e;
    }
    if (auto s = start(node_->now()); !s) {
      remote_drive_error e;
      e.code = s.error();
      e.what = "node " + std::to_string(node_->node()) + ": the drive helper refuses the command" +
               " in state '" + std::string(master::to_string(axis_.state())) +
               "' (drive: " + std::string(ds402::to_string(axis_.drive_status())) + ")";
      return e;
    }
    const auto end = std::chrono::steady_clock::now() + opt_.command_timeout;
    bool first = true;
    for (;;) {
      if (auto r = one_cycle(); !r) return r;
      const auto st = axis_.state();
      if (st == master::drive_state::fault || st == master::drive_state::failed)
        return machine_failed();
      if (!first && !axis_.busy() && !axis_.sdo_pending()) return {};
      first = false;
      if (std::chrono::steady_clock::now() >= end) {
        remote_drive_error e;
        e.code = errc::timeout;
        e.what = "node " + std::to_string(node_->node()) + ": '" +
                 std::string(master::to_string(st)) + "' not done within " +
                 std::to_string(opt_.command_timeout.count()) + " ms";
        return e;
      }
    }
  }

  /// One cycle: the statusword in, the machine, the words out, its SDO transfer, then the bus
  /// until the next cycle.
  result<void, remote_drive_error> one_cycle() {
    if (auto s = read_statusword(); !s) return s.error();
    if (node_->emcy_count() != emcy_seen_) {
      emcy_seen_ = node_->emcy_count();
      if (auto m = node_->last_emcy()) axis_.on_emcy(*m);
    }
    std::optional<std::int8_t> display;
    if (ch_.mode_display_tpdo != 0U) {
      auto m = node_->received(master::obj::modes_of_operation_display, raw_unit());
      if (m) {
        if (auto v = m.value().to_int64(); v && *v >= -128 && *v <= 127)
          display = static_cast<std::int8_t>(*v);
      }
    }
    const std::uint32_t now = node_->now();
    const master::drive_step out = axis_.cycle(sw_, now, display);
    if (auto r = send_words(out); !r) return r;
    if (out.sdo) run_sdo(*out.sdo, now);
    if (auto r = node_->listen(opt_.cycle); !r) return failed(r.error());
    return {};
  }

  result<void, remote_drive_error> send_words(const master::drive_step &out) {
    const od::value_options raw = raw_unit();
    if (ch_.controlword_rpdo != 0U) {
      if (auto r = node_->set_pdo(controlword, od::unsigned_number(out.controlword), raw); !r)
        return failed(r.error());
    } else if (!cw_sent_ || *cw_sent_ != out.controlword) {
      if (auto r = node_->write(controlword, od::unsigned_number(out.controlword), raw); !r)
        return failed(r.error());
    }
    cw_sent_ = out.controlword;
    // the active mode's target, where an RPDO carries it (otherwise the machine writes it)
    const std::int8_t mode = axis_.mode().value_or(0);
    const bool position = mode == static_cast<std::int8_t>(ds402::mode::profile_position);
    const bool velocity = mode == static_cast<std::int8_t>(ds402::mode::profile_velocity);
    const std::uint16_t rpdo = position ? ch_.position_rpdo : velocity ? ch_.velocity_rpdo : 0;
    if (rpdo != 0U) {
      const od::address a = position ? master::obj::target_position : master::obj::target_velocity;
      if (auto r = node_->set_pdo(a, od::signed_number(out.target), raw); !r)
        return failed(r.error());
    }
    // every RPDO the words are in, once per cycle (a cyclic task)
    if (ch_.controlword_rpdo != 0U) {
      if (auto r = node_->send_pdo(ch_.controlword_rpdo); !r) return failed(r.error());
    }
    if (rpdo != 0U && rpdo != ch_.controlword_rpdo) {
      if (auto r = node_->send_pdo(rpdo); !r) return failed(r.error());
    }
    return {};
  }

  /// A transfer the machine asked for, through the node's checked calls.
  void run_sdo(const master::sdo_request &q, std::uint32_t now) {
    auto d = node_->dictionary().at(q.address);
    if (!d) { // an object the node's dictionary lacks: nothing sent
      axis_.sdo_failed({errc::unknown_object, canopen::sdo::abort_code::none, q.address}, now);
      return;
    }
    if (q.what == master::sdo_request::kind::upload) {
      auto b = node_->read_bytes(d.value());
      if (b) {
        axis_.sdo_done(b.value(), now);
      } else {
        axis_.sdo_failed({b.error().code, b.error().abort, q.address}, now);
      }
      return;
    }
    // a download: the raw number of the machine's bytes, written through od's checks
    auto v = od::decode_value(d.value(), q.bytes(), raw_unit());
    if (!v) {
      axis_.sdo_failed({v.error(), canopen::sdo::abort_code::none, q.address}, now);
      return;
    }
    auto w = node_->write(q.address, v.value(), raw_unit());
    if (w) {
      axis_.sdo_done({}, now);
    } else {
      axis_.sdo_failed({w.error().code, w.error().abort, q.address}, now);
    }
  }

  /// The statusword: the last TPDO that brought it, else an SDO read.
  result<void, remote_drive_error> read_statusword() {
    if (ch_.statusword_tpdo != 0U) {
      auto v = node_->received(statusword, raw_unit());
      if (v) return take_statusword(v.value());
      if (v.error().code != errc::bad_state) return failed(v.error()); // not received yet: SDO
    }
    auto v = node_->read(statusword, raw_unit());
    if (!v) return failed(v.error());
    return take_statusword(v.value());
  }
  result<void, remote_drive_error> take_statusword(od::number n) {
    auto u = n.to_uint64();
    if (!u || *u > 0xFFFFU) {
      remote_drive_error e;
      e.code = errc::out_of_range;
      e.what = "node " + std::to_string(node_->node()) + ": the statusword is not a 16-bit word";
      return e;
    }
    sw_ = static_cast<std::uint16_t>(*u);
    return {};
  }

  result<std::int32_t, remote_drive_error> target_raw(od::address a, od::number v) {
    auto raw = node_->to_raw(a, v);
    if (!raw) return failed(raw.error());
    if (raw.value() < INT32_MIN || raw.value() > INT32_MAX) {
      remote_drive_error e;
      e.code = errc::overflow;
      e.what = "node " + std::to_string(node_->node()) + ", " + format_address(a) +
               ": the target does not fit 32 bits";
      return e;
    }
    return static_cast<std::int32_t>(raw.value());
  }

  static od::value_options raw_unit() noexcept { return {.unit = od::value_unit::raw}; }

  remote_drive_error failed(const sdo_error &e) const {
    remote_drive_error r;
    r.code = e.code;
    r.node = e;
    r.what = e.what;
    return r;
  }
  remote_drive_error machine_failed() const {
    remote_drive_error r;
    const auto e = axis_.error().value_or(master::drive_error{});
    r.code = e.code;
    r.drive = e;
    char sw[8];
    std::snprintf(sw, sizeof sw, "%04Xh", static_cast<unsigned>(e.statusword));
    r.what = "node " + std::to_string(node_->node()) + ": " +
             std::string(master::to_string(e.failure)) +
             " (drive: " + std::string(ds402::to_string(e.seen)) + ", statusword " + sw + ")";
    if (e.emcy) {
      char c[8];
      std::snprintf(c, sizeof c, "%04Xh", static_cast<unsigned>(e.emcy->error_code));
      r.what += std::string(", EMCY ") + c;
    }
    if (e.error_code_read) {
      char c[8];
      std::snprintf(c, sizeof c, "%04Xh", static_cast<unsigned>(e.error_code));
      r.what += std::string(", 603Fh ") + c;
    }
    if (e.sdo) r.what += ", " + describe_abort(e.sdo->abort);
    return r;
  }

  remote_node *node_;
  remote_drive_options opt_;
  master::drive axis_;
  drive_channels ch_{};
  bool ready_ = false;
  std::uint16_t sw_ = 0;
  std::optional<std::uint16_t> cw_sent_{};
  std::size_t emcy_seen_ = 0;
};

} // namespace fieldcodec::host
