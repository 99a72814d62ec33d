// fieldcodec — a non-blocking SDO client transfer machine (expedited and segmented).
//
// The client turns "read / write index:sub" into request frames and consumes response frames.
// It owns no memory: the data of a download and the buffer of an upload belong to the caller
// and must stay valid until the transfer is over. Time is supplied by the caller in
// milliseconds (any monotonic counter; wrap-around is handled).
//
//   sdo::client c(5);
//   auto first = c.upload(0x1800, 5, buffer, now);      // send first.value()
//   ... for every received frame:  auto out = c.on_frame(frame, now); if (out.send)
//   send(*out.send);
//   ... every cycle:               auto out = c.poll(now);            if (out.send)
//   send(*out.send); c.state() == sdo::transfer_state::done -> c.received() holds the value
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/core/result.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::sdo {

enum class transfer_state : std::uint8_t { idle, busy, done, failed };

/// What a step of a transfer machine produced: a frame to send (if any) and the state after it.
struct output {
  std::optional<can_frame> send;
  transfer_state state;
};

class client {
public:
  /// A client for the server of `node` (default SDO, 0x600/0x580 + node).
  constexpr explicit client(std::uint8_t node, std::uint32_t timeout_ms = 1000) noexcept
      : node_(node), timeout_ms_(timeout_ms) {}

  /// Start writing `data` to index:sub; returns the first frame to send. 1..4 bytes go
  /// expedited, 0 or more than 4 bytes segmented (with size indication).
  /// Errors: bad_state (a transfer is running), invalid_argument (node-ID not 1..127).
  [[nodiscard]] constexpr result<can_frame> download(std::uint16_t index, std::uint8_t sub,
                                                     std::span<const std::uint8_t> data,
                                                     std::uint32_t now) noexcept {
    if (state_ == transfer_state::busy) return errc::bad_state;
    if (!is_node_id(node_)) return errc::invalid_argument;
    begin(index, sub, now);
    upload_ = false;
    tx_ = data;
    auto f = (!data.empty() && data.size() <= 4U)
                 ? expedited_download(node_, index, sub, data)
                 : initiate_download(node_, index, sub, static_cast<std::uint32_t>(data.size()));
    if (!f) return fail(f.error()), f;
    state_ = transfer_state::busy;
    step_ =
        data.empty() || data.size() > 4U ? step::await_initiate_segmented : step::await_initiate;
    return f;
  }

  /// Start reading index:sub into `buffer`; returns the first frame to send.
  /// Errors: bad_state, invalid_argument.
  [[nodiscard]] constexpr result<can_frame> upload(std::uint16_t index, std::uint8_t sub,
                                                   std::span<std::uint8_t> buffer,
                                                   std::uint32_t now) noexcept {
    if (state_ == transfer_state::busy) return errc::bad_state;
    if (!is_node_id(node_)) return errc::invalid_argument;
    begin(index, sub, now);
    upload_ = true;
    rx_ = buffer;
    auto f = initiate_upload(node_, index, sub);
    if (!f) return fail(f.error()), f;
    state_ = transfer_state::busy;
    step_ = step::await_initiate;
    return f;
  }

  /// Consume a received frame. Frames on other COB-IDs and frames while no transfer runs are
  /// ignored (nothing to send, state unchanged). A response that does not fit the transfer
  /// makes the client abort (the abort frame is in `send`) and fail with:
  /// aborted (server sent an abort; abort_code() holds it), bad_toggle, unexpected_frame (wrong
  /// command specifier, index or sub-index), unknown_command, bad_length (DLC, or the data
  /// disagree with the announced size), buffer_too_small (upload larger than the buffer).
  [[nodiscard]] constexpr output on_frame(const can_frame &f, std::uint32_t now) noexcept {
    if (state_ != transfer_state::busy || f.id != cob_id::sdo_tx_base + node_ || f.rtr) {
      return {std::nullopt, state_};
    }
    auto r = decode_response(f);
    if (!r) {
      return abort_with(r.error() == errc::bad_length ? abort_code::general_error
                                                      : abort_code::unknown_command,
                        r.error());
    }
    const message &m = r.value();
    if (m.k == kind::abort) {
      code_ = m.code;
      fail(errc::aborted);
      return {std::nullopt, state_};
    }
    last_ = now;
    return upload_ ? upload_step(m) : download_step(m);
  }

  /// Check the timeout. Errors via state: timeout (abort 0x05040000 in `send`).
  [[nodiscard]] constexpr output poll(std::uint32_t now) noexcept {
    if (state_ == transfer_state::busy && now - last_ >= timeout_ms_) {
      return abort_with(abort_code::timeout, errc::timeout);
    }
    return {std::nullopt, state_};
  }

  /// Abort the running transfer from the application side (e.g. on shutdown).
  [[nodiscard]] constexpr output cancel(abort_code code = abort_code::general_error) noexcept {
    if (state_ != transfer_state::busy) return {std::nullopt, state_};
    return abort_with(code, errc::aborted);
  }

  [[nodiscard]] constexpr transfer_state state() const noexcept { return state_; }
  [[nodiscard]] constexpr bool busy() const noexcept { return state_ == transfer_state::busy; }
  /// Why the last transfer failed (valid in state failed).
  [[nodiscard]] constexpr errc error() const noexcept { return error_; }
  /// The abort code sent or received with the last failure (0 if none).
  [[nodiscard]] constexpr std::uint32_t abort_code_value() const noexcept { return code_; }
  /// The bytes uploaded so far (the value once state() == done).
  [[nodiscard]] constexpr std::span<const std::uint8_t> received() const noexcept {
    return std::span<const std::uint8_t>(rx_).first(count_);
  }
  /// Bytes transferred so far.
  [[nodiscard]] constexpr std::size_t transferred() const noexcept { return count_; }
  [[nodiscard]] constexpr std::uint8_t node() const noexcept { return node_; }

private:
  enum class step : std::uint8_t { await_initiate, await_initiate_segmented, await_segment };

  constexpr void begin(std::uint16_t index, std::uint8_t sub, std::uint32_t now) noexcept {
    index_ = index;
    sub_ = sub;
    last_ = now;
    toggle_ = false;
    count_ = 0;
    code_ = 0;
    size_indicated_ = false;
    size_ = 0;
    error_ = errc::truncated;
    tx_ = {};
    rx_ = {};
  }
  constexpr void fail(errc e) noexcept {
    error_ = e;
    state_ = transfer_state::failed;
  }
  [[nodiscard]] constexpr output abort_with(abort_code code, errc e) noexcept {
    code_ = static_cast<std::uint32_t>(code);
    fail(e);
    auto f = abort(direction::to_server, node_, index_, sub_, code);
    return {f ? std::optional<can_frame>(f.value()) : std::nullopt, state_};
  }
  [[nodiscard]] constexpr output finish() noexcept {
    state_ = transfer_state::done;
    return {std::nullopt, state_};
  }
  [[nodiscard]] constexpr bool same_object(const message &m) const noexcept {
    return m.index == index_ && m.sub == sub_;
  }

  [[nodiscard]] constexpr output send_next_segment() noexcept {
    const std::size_t left = tx_.size() - count_;
    const std::size_t n = left < 7U ? left : 7U;
    const bool last = left <= 7U;
    auto f = download_segment(node_, toggle_, tx_.subspan(count_, n), last);
    if (!f) return abort_with(abort_code::general_error, f.error());
    count_ += n;
    step_ = step::await_segment;
    return {f.value(), state_};
  }

  [[nodiscard]] constexpr output download_step(const message &m) noexcept {
    switch (step_) {
    case step::await_initiate:
      if (m.k != kind::initiate_download_response) {
        return abort_with(abort_code::unknown_command, errc::unexpected_frame);
      }
      if (!same_object(m)) return abort_with(abort_code::general_error, errc::unexpected_frame);
      count_ = tx_.size();
      return finish();
    case step::await_initiate_segmented:
      if (m.k != kind::initiate_download_response) {
        return abort_with(abort_code::unknown_command, errc::unexpected_frame);
      }
      if (!same_object(m)) return abort_with(abort_code::general_error, errc::unexpected_frame);
      return send_next_segment();
    case step::await_segment:
      if (m.k != kind::download_segment_response) {
        return abort_with(abort_code::unknown_command, errc::unexpected_frame);
      }
      if (m.toggle != toggle_) {
        return abort_with(abort_code::toggle_not_alternated, errc::bad_toggle);
      }
      toggle_ = !toggle_;
      if (count_ == tx_.size()) return finish();
      return send_next_segment();
    }
    return abort_with(abort_code::general_error, errc::bad_state);
  }

  [[nodiscard]] constexpr output request_segment() noexcept {
    auto f = upload_segment_request(node_, toggle_);
    if (!f) return abort_with(abort_code::general_error, f.error());
    step_ = step::await_segment;
    return {f.value(), state_};
  }

  [[nodiscard]] constexpr output upload_step(const message &m) noexcept {
    if (step_ == step::await_initiate) {
      if (m.k != kind::initiate_upload_response) {
        return abort_with(abort_code::unknown_command, errc::unexpected_frame);
      }
      if (!same_object(m)) return abort_with(abort_code::general_error, errc::unexpected_frame);
      if (m.expedited) {
        if (m.data_size > rx_.size()) {
          return abort_with(abort_code::out_of_memory, errc::buffer_too_small);
        }
        for (std::size_t i = 0; i < m.data_size; ++i) rx_[i] = m.data[i];
        count_ = m.data_size;
        return finish();
      }
      size_indicated_ = m.size_indicated;
      size_ = m.size;
      if (size_indicated_ && size_ > rx_.size()) {
        return abort_with(abort_code::out_of_memory, errc::buffer_too_small);
      }
      return request_segment();
    }
    if (m.k != kind::upload_segment_response) {
      return abort_with(abort_code::unknown_command, errc::unexpected_frame);
    }
    if (m.toggle != toggle_) return abort_with(abort_code::toggle_not_alternated, errc::bad_toggle);
    if (count_ + m.data_size > rx_.size()) {
      return abort_with(abort_code::out_of_memory, errc::buffer_too_small);
    }
    if (size_indicated_ && count_ + m.data_size > size_) {
      return abort_with(abort_code::length_too_high, errc::bad_length);
    }
    for (std::size_t i = 0; i < m.data_size; ++i) rx_[count_ + i] = m.data[i];
    count_ += m.data_size;
    toggle_ = !toggle_;
    if (m.last) {
      if (size_indicated_ && count_ != size_) {
        return abort_with(abort_code::length_too_low, errc::bad_length);
      }
      return finish();
    }
    return request_segment();
  }

  std::uint8_t node_;
  std::uint32_t timeout_ms_;
  transfer_state state_ = transfer_state::idle;
  step step_ = step::await_initiate;
  bool upload_ = false;
  bool toggle_ = false;
  bool size_indicated_ = false;
  std::uint16_t index_ = 0;
  std::uint8_t sub_ = 0;
  std::uint32_t last_ = 0;
  std::uint32_t size_ = 0;
  std::uint32_t code_ = 0;
  errc error_ = errc::truncated;
  std::size_t count_ = 0;
  std::span<const std::uint8_t> tx_{};
  std::span<std::uint8_t> rx_{};
};

} // namespace fieldcodec::canopen::sdo
