// fieldcodec — a non-blocking SDO server transfer machine.
//
// The server answers requests addressed to its node (COB-ID 0x600 + node) from an object
// store (canopen/object_store.hpp). Segmented transfers go through a caller-owned buffer
// (its size limits the largest value). Block transfer requests are answered with an abort
// (0x05040001).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::sdo {

template <object_store Store>
class server {
public:
  /// `store` and `buffer` are borrowed and must outlive the server.
  constexpr server(std::uint8_t node, Store &store, std::span<std::uint8_t> buffer,
                   std::uint32_t timeout_ms = 1000) noexcept
      : node_(node), store_(&store), buf_(buffer), timeout_ms_(timeout_ms) {}

  /// Consume a frame; returns the response to send, if any. Frames for other COB-IDs, remote
  /// frames and frames with DLC other than 8 get no response (last_error() tells bad_length).
  [[nodiscard]] constexpr std::optional<can_frame> on_frame(const can_frame &f,
                                                            std::uint32_t now) noexcept {
    if (f.id != cob_id::sdo_rx_base + node_ || f.rtr) return std::nullopt;
    auto r = decode_request(f);
    if (!r) {
      error_ = r.error();
      if (r.error() == errc::unknown_command) {
        return reply_abort(static_cast<std::uint16_t>(f.data[1] | (f.data[2] << 8U)), f.data[3],
                           abort_code::unknown_command);
      }
      return std::nullopt;
    }
    const message &m = r.value();
    last_ = now;
    switch (m.k) {
    case kind::initiate_download_request: return initiate_download(m);
    case kind::download_segment_request: return download_segment(m);
    case kind::initiate_upload_request: return initiate_upload(m);
    case kind::upload_segment_request: return upload_segment(m);
    case kind::abort:
      if (state_ == transfer_state::busy) {
        state_ = transfer_state::failed;
        error_ = errc::aborted;
      }
      return std::nullopt;
    case kind::block_upload_request:
    case kind::block_download_request:
      error_ = errc::unknown_command;
      return reply_abort(m.index, m.sub, abort_code::unknown_command);
    default: break;
    }
    error_ = errc::unexpected_frame;
    return reply_abort(m.index, m.sub, abort_code::unknown_command);
  }

  /// Abort a segmented transfer whose client went silent (0x05040000).
  [[nodiscard]] constexpr std::optional<can_frame> poll(std::uint32_t now) noexcept {
    if (state_ == transfer_state::busy && now - last_ >= timeout_ms_) {
      error_ = errc::timeout;
      return reply_abort(index_, sub_, abort_code::timeout);
    }
    return std::nullopt;
  }

  [[nodiscard]] constexpr transfer_state state() const noexcept { return state_; }
  [[nodiscard]] constexpr errc last_error() const noexcept { return error_; }

private:
  enum class mode : std::uint8_t { download, upload };

  [[nodiscard]] constexpr std::optional<can_frame>
  reply_abort(std::uint16_t index, std::uint8_t sub, abort_code code) noexcept {
    if (state_ == transfer_state::busy) state_ = transfer_state::failed;
    auto f = abort(direction::to_client, node_, index, sub, code);
    if (!f) return std::nullopt;
    return f.value();
  }
  [[nodiscard]] constexpr std::optional<can_frame> ok(result<can_frame> f) noexcept {
    if (!f) return std::nullopt;
    return f.value();
  }

  [[nodiscard]] constexpr std::optional<can_frame> initiate_download(const message &m) noexcept {
    state_ = transfer_state::idle; // a new initiate ends any running transfer
    if (m.expedited) {
      const auto code = store_->write(m.index, m.sub, m.bytes());
      if (code != abort_code::none) return reply_abort(m.index, m.sub, code);
      state_ = transfer_state::done;
      return ok(download_response(node_, m.index, m.sub));
    }
    if (m.size_indicated && m.size > buf_.size()) {
      return reply_abort(m.index, m.sub, abort_code::out_of_memory);
    }
    index_ = m.index;
    sub_ = m.sub;
    size_indicated_ = m.size_indicated;
    size_ = m.size;
    count_ = 0;
    toggle_ = false;
    mode_ = mode::download;
    state_ = transfer_state::busy;
    return ok(download_response(node_, m.index, m.sub));
  }

  [[nodiscard]] constexpr std::optional<can_frame> download_segment(const message &m) noexcept {
    if (state_ != transfer_state::busy || mode_ != mode::download) {
      error_ = errc::unexpected_frame;
      return reply_abort(index_, sub_, abort_code::unknown_command);
    }
    if (m.toggle != toggle_) {
      error_ = errc::bad_toggle;
      return reply_abort(index_, sub_, abort_code::toggle_not_alternated);
    }
    if (count_ + m.data_size > buf_.size()) {
      error_ = errc::buffer_too_small;
      return reply_abort(index_, sub_, abort_code::out_of_memory);
    }
    if (size_indicated_ && count_ + m.data_size > size_) {
      error_ = errc::bad_length;
      return reply_abort(index_, sub_, abort_code::length_too_high);
    }
    for (std::size_t i = 0; i < m.data_size; ++i) buf_[count_ + i] = m.data[i];
    count_ += m.data_size;
    const bool t = toggle_;
    toggle_ = !toggle_;
    if (m.last) {
      if (size_indicated_ && count_ != size_) {
        error_ = errc::bad_length;
        return reply_abort(index_, sub_, abort_code::length_too_low);
      }
      const auto code =
          store_->write(index_, sub_, std::span<const std::uint8_t>(buf_).first(count_));
      if (code != abort_code::none) return reply_abort(index_, sub_, code);
      state_ = transfer_state::done;
    }
    return ok(download_segment_response(node_, t));
  }

  [[nodiscard]] constexpr std::optional<can_frame> initiate_upload(const message &m) noexcept {
    state_ = transfer_state::idle;
    std::size_t n = 0;
    const auto code = store_->read(m.index, m.sub, buf_, n);
    if (code != abort_code::none) return reply_abort(m.index, m.sub, code);
    if (n >= 1U && n <= 4U) {
      state_ = transfer_state::done;
      return ok(expedited_upload_response(node_, m.index, m.sub,
                                          std::span<const std::uint8_t>(buf_).first(n)));
    }
    index_ = m.index;
    sub_ = m.sub;
    size_ = static_cast<std::uint32_t>(n);
    count_ = 0;
    toggle_ = false;
    mode_ = mode::upload;
    state_ = transfer_state::busy;
    return ok(upload_response(node_, m.index, m.sub, size_));
  }

  [[nodiscard]] constexpr std::optional<can_frame> upload_segment(const message &m) noexcept {
    if (state_ != transfer_state::busy || mode_ != mode::upload) {
      error_ = errc::unexpected_frame;
      return reply_abort(index_, sub_, abort_code::unknown_command);
    }
    if (m.toggle != toggle_) {
      error_ = errc::bad_toggle;
      return reply_abort(index_, sub_, abort_code::toggle_not_alternated);
    }
    const std::size_t left = size_ - count_;
    const std::size_t n = left < 7U ? left : 7U;
    const bool last = left <= 7U;
    auto f = sdo::upload_segment(node_, toggle_,
                                 std::span<const std::uint8_t>(buf_).subspan(count_, n), last);
    count_ += n;
    toggle_ = !toggle_;
    if (last) state_ = transfer_state::done;
    return ok(f);
  }

  std::uint8_t node_;
  Store *store_;
  std::span<std::uint8_t> buf_;
  std::uint32_t timeout_ms_;
  transfer_state state_ = transfer_state::idle;
  mode mode_ = mode::download;
  errc error_ = errc::truncated;
  bool toggle_ = false;
  bool size_indicated_ = false;
  std::uint16_t index_ = 0;
  std::uint8_t sub_ = 0;
  std::uint32_t size_ = 0;
  std::uint32_t last_ = 0;
  std::size_t count_ = 0;
};

} // namespace fieldcodec::canopen::sdo
