// fieldcodec — runs a configuration list (master/config.hpp) through an SDO client: one download
// per item, in order, with retries, a per-transfer timeout, and optionally a read-back that
// checks what the device kept.
//
//   sdo::client client(node);
//   master::configurator run(client, {.retries = 2, .timeout_ms = 500, .verify = true});
//   auto s = run.start(dcf::config::configuration, now);    // result<step>
//   for every frame: s = run.on_frame(frame, now);  when s.deadline passes: s = run.poll(now)
//   send s.send; run.state() == done / failed: run.error() names the item, its object's name,
//   the abort code and the attempts.
//   run.start_concise(concise_dcf_bytes, now) runs the entries of a concise DCF (1F22h format).
//
// The client belongs to the caller (a boot-up machine shares it); while the configurator runs
// nothing else may use it. Pure: no heap, no I/O, time passed in.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/master/config.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace fieldcodec::master {

enum class config_state : std::uint8_t { idle, writing, verifying, done, failed };

[[nodiscard]] constexpr std::string_view to_string(config_state s) noexcept {
  switch (s) {
  case config_state::idle: return "idle";
  case config_state::writing: return "writing";
  case config_state::verifying: return "verifying";
  case config_state::done: return "done";
  case config_state::failed: return "failed";
  }
  return "?";
}

enum class config_failure : std::uint8_t {
  transfer_failed, ///< the download (or the read-back) failed on every attempt
  verify_mismatch, ///< the read-back differs from what was written
  bad_item,        ///< the item cannot be sent (node-relative without a node-ID, overflow ...)
};

/// A short, stable text for a configuration failure (for reports; the texts do not change
/// between versions).
[[nodiscard]] constexpr std::string_view to_string(config_failure f) noexcept {
  switch (f) {
  case config_failure::transfer_failed: return "transfer failed";
  case config_failure::verify_mismatch: return "read-back differs";
  case config_failure::bad_item: return "item cannot be sent";
  }
  return "?";
}

/// What failed: the item (position, object, name), why, and how often it was tried.
struct config_error {
  config_failure failure = config_failure::transfer_failed;
  errc code = errc::aborted; ///< timeout, aborted, out_of_range (mismatch)...
  std::size_t item = 0;      ///< position in the list
  od::address address{};
  std::string_view name{}; ///< the object's name from the list
  canopen::sdo::abort_code abort = canopen::sdo::abort_code::none; ///< sent or received
  std::uint8_t attempts = 0;

  [[nodiscard]] constexpr bool is(errc e) const noexcept { return code == e; }
};

struct config_options {
  std::uint8_t retries = 2;                ///< further attempts after a failed transfer
  std::uint32_t timeout_ms = 1000;         ///< per transfer (the client's own timeout also applies)
  bool verify = false;                     ///< read every item back (except no_verify ones)
  std::span<std::uint8_t> verify_buffer{}; ///< for values longer than 8 bytes when verifying
};

class configurator {
public:
  using step = canopen::step<config_state>;

  constexpr explicit configurator(canopen::sdo::client &client, config_options o = {}) noexcept
      : client_(&client), opt_(o) {}

  /// Start running `c` for `node` (0: the list's node-ID). Errors: bad_state (running, or the
  /// client is busy).
  [[nodiscard]] constexpr result<step> start(const configuration &c, std::uint32_t now,
                                             std::uint8_t node = 0) noexcept {
    if (busy() || client_->busy()) return errc::bad_state;
    config_ = c;
    dcf_ = {};
    load_ = &configurator::load_item;
    count_ = c.items.size();
    return begin(now, node != 0U ? node : c.node_id);
  }
  /// Start downloading the entries of a concise DCF (object 1F22h format, config.hpp) in order,
  /// with the same retries, timeout and verify; a failed entry is named by its position and
  /// address (a concise DCF has no names). The whole DCF is checked before anything is sent;
  /// `dcf` must stay valid while the configurator runs. Errors: bad_state (running, or the
  /// client is busy), truncated / bad_length (check_concise_dcf).
  [[nodiscard]] constexpr result<step> start_concise(std::span<const std::uint8_t> dcf,
                                                     std::uint32_t now) noexcept {
    if (busy() || client_->busy()) return errc::bad_state;
    FIELDCODEC_TRY(const std::uint32_t n, check_concise_dcf(dcf));
    config_ = {};
    dcf_ = dcf;
    dcf_at_ = 4;
    load_ = &configurator::load_entry;
    count_ = n;
    return begin(now, 0);
  }

  /// Consume a received frame (frames of other services are ignored).
  [[nodiscard]] constexpr step on_frame(const canopen::can_frame &f, std::uint32_t now) noexcept {
    if (!busy()) return make();
    out_count_ = 0;
    from_client(client_->on_frame(f, now));
    return after_client(now);
  }

  /// Check the timeouts.
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    if (!busy()) return make();
    out_count_ = 0;
    from_client(client_->poll(now));
    if (client_->busy() && deadline_ && canopen::reached(*deadline_, now)) {
      collect(client_->cancel(canopen::sdo::abort_code::timeout).send);
      return retry_or_fail(errc::timeout, canopen::sdo::abort_code::timeout, now);
    }
    return after_client(now);
  }

  [[nodiscard]] constexpr config_state state() const noexcept { return state_; }
  [[nodiscard]] constexpr bool busy() const noexcept {
    return state_ == config_state::writing || state_ == config_state::verifying;
  }
  [[nodiscard]] constexpr std::optional<config_error> error() const noexcept { return error_; }
  /// Items completed so far.
  [[nodiscard]] constexpr std::size_t completed() const noexcept { return at_; }

private:
  [[nodiscard]] constexpr step make() const noexcept {
    step s;
    s.send = canopen::frames(std::span<const canopen::can_frame>(out_).first(out_count_));
    s.state = state_;
    if (busy()) {
      s.deadline = deadline_;
      if (const auto d = client_deadline_;
          d && (!s.deadline || canopen::reached(*d, *s.deadline))) {
        s.deadline = d;
      }
    }
    return s;
  }
  constexpr void collect(const canopen::frames &f) noexcept {
    for (const auto &fr : f) {
      if (out_count_ < out_.size()) out_[out_count_++] = fr;
    }
  }
  constexpr void from_client(const canopen::sdo::step &s) noexcept {
    collect(s.send);
    client_deadline_ = s.deadline;
  }
  constexpr void started(const canopen::sdo::step &s, std::uint32_t now) noexcept {
    from_client(s);
    deadline_.reset();
    if (opt_.timeout_ms != 0U) deadline_ = now + opt_.timeout_ms;
  }

  [[nodiscard]] constexpr const config_item &item() const noexcept { return current_; }
  // The item at at_ into current_: from the list, or the next entry of the concise DCF (only a
  // program that runs one links its reader).
  [[nodiscard]] constexpr bool load_item() noexcept {
    current_ = config_.items[at_];
    return true;
  }
  [[nodiscard]] constexpr bool load_entry() noexcept {
    const auto e = read_concise_entry(dcf_, dcf_at_); // checked when it started
    if (!e) return false;
    current_ = {e.value().address, e.value().value, 0, {}};
    return true;
  }

  [[nodiscard]] constexpr step begin(std::uint32_t now, std::uint8_t node) noexcept {
    node_ = node;
    at_ = 0;
    error_.reset();
    out_count_ = 0;
    return next_item(now);
  }

  [[nodiscard]] constexpr step fail(config_failure f, errc e,
                                    canopen::sdo::abort_code code) noexcept {
    const auto &i = item();
    error_ = config_error{f, e, at_, i.address, i.name, code, attempts_};
    state_ = config_state::failed;
    deadline_.reset();
    return make();
  }

  [[nodiscard]] constexpr step next_item(std::uint32_t now) noexcept {
    if (at_ >= count_) {
      state_ = config_state::done;
      deadline_.reset();
      return make();
    }
    attempts_ = 0;
    state_ = config_state::writing;
    if (!(this->*load_)()) {
      return fail(config_failure::bad_item, errc::truncated, canopen::sdo::abort_code::none);
    }
    auto v = resolved_value(item(), node_, scratch_);
    if (!v) return fail(config_failure::bad_item, v.error(), canopen::sdo::abort_code::none);
    value_ = v.value();
    return write(now);
  }
  [[nodiscard]] constexpr step write(std::uint32_t now) noexcept {
    ++attempts_;
    state_ = config_state::writing;
    auto s = client_->download(item().address, value_, now);
    if (!s) return fail(config_failure::transfer_failed, s.error(), canopen::sdo::abort_code::none);
    started(s.value(), now);
    return make();
  }
  [[nodiscard]] constexpr step read_back(std::uint32_t now) noexcept {
    ++attempts_;
    state_ = config_state::verifying;
    std::span<std::uint8_t> buf =
        value_.size() <= readback_.size() ? std::span<std::uint8_t>(readback_) : opt_.verify_buffer;
    if (buf.size() < value_.size()) {
      return fail(config_failure::bad_item, errc::buffer_too_small, canopen::sdo::abort_code::none);
    }
    auto s = client_->upload(item().address, buf, now);
    if (!s) return fail(config_failure::transfer_failed, s.error(), canopen::sdo::abort_code::none);
    started(s.value(), now);
    return make();
  }

  [[nodiscard]] constexpr step after_client(std::uint32_t now) noexcept {
    switch (client_->state()) {
    case canopen::sdo::transfer_state::busy: return make();
    case canopen::sdo::transfer_state::failed: {
      const auto e = client_->error();
      return retry_or_fail(e ? e->code : errc::aborted,
                           e ? e->abort : canopen::sdo::abort_code::none, now);
    }
    case canopen::sdo::transfer_state::done: break;
    case canopen::sdo::transfer_state::idle: return make();
    }
    if (state_ == config_state::writing) {
      if (opt_.verify && (item().flags & config_flag::no_verify) == 0U) {
        attempts_ = 0;
        return read_back(now);
      }
    } else { // verifying
      const auto got = client_->received();
      bool same = got.size() == value_.size();
      for (std::size_t i = 0; same && i < got.size(); ++i) same = got[i] == value_[i];
      if (!same) {
        return fail(config_failure::verify_mismatch, errc::out_of_range,
                    canopen::sdo::abort_code::none);
      }
    }
    ++at_;
    return next_item(now);
  }

  [[nodiscard]] constexpr step retry_or_fail(errc e, canopen::sdo::abort_code code,
                                             std::uint32_t now) noexcept {
    if (attempts_ > opt_.retries) return fail(config_failure::transfer_failed, e, code);
    if (state_ == config_state::verifying) return read_back(now);
    return write(now);
  }

  canopen::sdo::client *client_;
  config_options opt_;
  configuration config_{};
  std::span<const std::uint8_t> dcf_{}; ///< a concise DCF runs (else config_.items)
  std::size_t dcf_at_ = 0;              ///< offset of its next entry
  std::size_t count_ = 0;               ///< items or entries
  config_item current_{};
  bool (configurator::*load_)() = &configurator::load_item;
  std::uint8_t node_ = 0;
  std::size_t at_ = 0;
  std::uint8_t attempts_ = 0;
  config_state state_ = config_state::idle;
  std::optional<config_error> error_{};
  std::optional<std::uint32_t> deadline_{};
  std::optional<std::uint32_t> client_deadline_{};
  std::array<std::uint8_t, 8> scratch_{};
  std::array<std::uint8_t, 8> readback_{};
  std::span<const std::uint8_t> value_{};
  std::array<canopen::can_frame, 3> out_{};
  std::size_t out_count_ = 0;
};

} // namespace fieldcodec::master
