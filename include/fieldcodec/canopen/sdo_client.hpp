// fieldcodec — a non-blocking SDO client transfer machine: expedited, segmented and block
// download and upload.
//
// The client turns "write / read index:sub" into request frames and consumes response frames
// on its channel (sdo::channel). It owns no memory: the data of a download and the buffer of an
// upload belong to the caller and must stay valid until the transfer is over. Time is the
// caller's millisecond counter (any monotonic counter; wrap-around is handled). Every call
// returns an sdo::step: the frames to send, the state, and the deadline of the timeout.
//
//   sdo::client c(5);                                   // the server of node 5 (0x605/0x585)
//   auto s = c.upload({0x1008, 0}, buffer, now);        // result<step>: bad_state when busy
//   for (const auto &f : s.value().send) transmit(f);
//
//   // for every received frame, and when the deadline passes:
//   auto t = c.on_frame(frame, now);                    // or c.poll(now)
//   for (const auto &f : t.send) transmit(f);
//
//   // c.state() == sdo::transfer_state::done: c.received() holds the value;
//   // failed: c.error() says why ({errc, abort code, address}).
//
// or, with the frames a CAN driver took from its receive FIFO (several at once):
//
//   for (auto rx = fifo_frames; !rx.empty();) {
//     const auto r = c.on_frames(rx, now);      // stops at the first frame that answers
//     for (const auto &f : r.last.send) transmit(f);
//     rx = rx.subspan(r.consumed);
//   }
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::sdo {

/// Options of a block transfer started by the client.
struct block_options {
  std::uint8_t block_size = max_block_size; ///< upload: segments per sub-block the client takes
  std::uint8_t switch_threshold = 0;        ///< upload: the server may answer with a normal upload
                                            ///< for objects of at most this many bytes (0: never)
  bool crc = true;                          ///< ask for the CRC (used when the server supports it)
};

/// The client; `Crc` computes the CRC of block transfers (crc::ccitt16_no_table, the default,
/// or crc::ccitt16_with_table: a 512-byte table in flash for about half the instructions a
/// byte; core/crc.hpp). `client` is the default.
template <class Crc = crc::ccitt16_no_table>
class basic_client {
public:
  /// A client on `ch`.
  constexpr explicit basic_client(channel ch, std::uint32_t timeout_ms = 1000) noexcept
      : ch_(ch), core_(timeout_ms) {}
  /// A client for the server of `node` on the predefined channel (0x600/0x580 + node). With a
  /// node-ID outside 1..127 every transfer is refused with invalid_argument.
  constexpr explicit basic_client(std::uint8_t node, std::uint32_t timeout_ms = 1000) noexcept
      : ch_(channel::default_for(node).value_or(channel{})), core_(timeout_ms) {}

  /// Start writing `data` to `a`: 1..4 bytes go expedited, 0 or more than 4 bytes segmented
  /// (with size indication). Errors: bad_state (a transfer is running), invalid_argument (no
  /// channel: node-ID not 1..127), too_long (more than 2^32 − 1 bytes).
  [[nodiscard]] constexpr result<step> download(od::address a, std::span<const std::uint8_t> data,
                                                std::uint32_t now) noexcept {
    FIELDCODEC_TRY_STATUS(can_start(data.size()));
    begin(a, now);
    tx_ = data;
    if (!data.empty() && data.size() <= 4U) {
      expect(&basic_client::download_expedited);
      return send(expedited_download(a, data).value());
    }
    expect(&basic_client::download_initiate<>);
    return send(initiate_download(a, static_cast<std::uint32_t>(data.size())));
  }

  /// Start reading `a` into `buffer`. Errors: bad_state, invalid_argument.
  [[nodiscard]] constexpr result<step> upload(od::address a, std::span<std::uint8_t> buffer,
                                              std::uint32_t now) noexcept {
    FIELDCODEC_TRY_STATUS(can_start(0));
    begin(a, now);
    rx_ = buffer;
    expect(&basic_client::upload_initiate<>);
    return send(initiate_upload(a));
  }

  /// Start reading `a` in parts (segmented, or expedited): the bytes go into `window` (at least
  /// 7 bytes); when the next segment would not fit, the transfer pauses with part_ready():
  /// received() is the part, next_part() goes on (the SDO timeout does not run meanwhile).
  /// The last part is received() once state() == done. An object of any size is read through
  /// one window. Errors: bad_state, invalid_argument (also: window shorter than 7 bytes).
  [[nodiscard]] constexpr result<step> upload_parts(od::address a, std::span<std::uint8_t> window,
                                                    std::uint32_t now) noexcept {
    if (window.size() < 7U) return errc::invalid_argument;
    auto s = upload(a, window, now);
    if (s) expect(&basic_client::upload_initiate<true>);
    return s;
  }
  /// Start writing `size` bytes to `a` in parts (segmented with size indication; expedited
  /// when `size` is 1..4 and `first` holds them all): `first` is the beginning of the value;
  /// when the next segment needs bytes beyond the part given, the transfer pauses with
  /// part_ready() and feed() gives the next part, starting at byte transferred(). Errors:
  /// bad_state, invalid_argument (also: `first` longer than `size`, or empty when `size` is
  /// not), too_long.
  [[nodiscard]] constexpr result<step> download_parts(od::address a, std::uint32_t size,
                                                      std::span<const std::uint8_t> first,
                                                      std::uint32_t now) noexcept {
    if (first.size() > size || (first.empty() && size != 0U)) return errc::invalid_argument;
    if (size <= 4U) {
      if (first.size() != size) return errc::invalid_argument;
      return download(a, first, now);
    }
    FIELDCODEC_TRY_STATUS(can_start(size));
    begin(a, now);
    tx_ = first;
    total_ = size;
    expect(&basic_client::download_initiate<true>);
    return send(initiate_download(a, size));
  }
  /// A part transfer is paused: an upload's part is in received(), a download needs feed().
  [[nodiscard]] constexpr bool part_ready() const noexcept { return paused_ && core_.busy(); }
  /// Go on with a paused upload: the window is free again. Errors: bad_state (no part ready,
  /// or a download).
  [[nodiscard]] constexpr result<step> next_part(std::uint32_t now) noexcept {
    if (!part_ready() || rx_.empty()) return errc::bad_state;
    paused_ = false;
    base_ = count_;
    core_.touch(now);
    return send(upload_segment_request(seg_rx_.toggle()));
  }
  /// Go on with a paused download: `part` holds the bytes from transferred() on (at least the
  /// next segment's, 7 or what is left). Errors: bad_state (no part ready, or an upload),
  /// invalid_argument (`part` too short, or beyond the size announced).
  [[nodiscard]] constexpr result<step> feed(std::span<const std::uint8_t> part,
                                            std::uint32_t now) noexcept {
    if (!part_ready() || !rx_.empty()) return errc::bad_state;
    if (part.size() < seg_tx_.next_length() || count_ + part.size() > total_) {
      return errc::invalid_argument;
    }
    paused_ = false;
    base_ = count_;
    tx_ = part;
    core_.touch(now);
    return next_download_segment<true>();
  }

  /// Start writing `data` to `a` with block transfer (size indicated).
  /// Errors: bad_state, invalid_argument, too_long.
  [[nodiscard]] constexpr result<step> block_download(od::address a,
                                                      std::span<const std::uint8_t> data,
                                                      std::uint32_t now,
                                                      block_options o = {}) noexcept {
    FIELDCODEC_TRY_STATUS(can_start(data.size()));
    begin(a, now);
    tx_ = data;
    options_ = o;
    expect(&basic_client::block_download_initiate);
    return send(
        sdo::block_download_initiate(a, static_cast<std::uint32_t>(data.size()), true, o.crc));
  }

  /// Start reading `a` into `buffer` with block transfer. The server may switch to a normal
  /// upload for an object of at most o.switch_threshold bytes. Errors: bad_state,
  /// invalid_argument (also: block size not 1..127).
  [[nodiscard]] constexpr result<step> block_upload(od::address a, std::span<std::uint8_t> buffer,
                                                    std::uint32_t now,
                                                    block_options o = {}) noexcept {
    FIELDCODEC_TRY_STATUS(can_start(0));
    auto p = sdo::block_upload_initiate(a, o.block_size, o.switch_threshold, o.crc);
    if (!p) return errc::invalid_argument;
    begin(a, now);
    rx_ = buffer;
    options_ = o;
    expect(&basic_client::block_upload_initiate);
    return send(p.value());
  }

  /// Consume a received frame. Frames on other identifiers and frames while no transfer runs
  /// are ignored (nothing to send, state unchanged). A frame that does not fit the transfer
  /// makes the client abort (the abort frame is sent) and fail with (error().code):
  /// aborted (the server sent an abort; error().abort holds its code), bad_toggle,
  /// unexpected_frame (wrong command specifier, index or sub-index, sequence number),
  /// unknown_command, bad_length (DLC; the data disagree with the announced size),
  /// buffer_too_small (upload larger than the buffer), bad_checksum (block CRC),
  /// out_of_range (block size).
  [[nodiscard]] constexpr step on_frame(const can_frame &f, std::uint32_t now) noexcept {
    if (!core_.busy() || !ch_.is_response(f)) return core_.make();
    // payload_of's check, reading the bytes in place (no copy of them through a result)
    if (const auto ok = expect_data(f, 8); !ok)
      return abort_with(ok.error(), abort_code::general_error);
    const payload &p = f.data;
    core_.touch(now);
    if (raw_ != nullptr) {
      if (auto s = (this->*raw_)(p)) return *s;
    }
    // A response is read in place by the state that takes it (no message is built for an
    // expedited or segmented transfer; a block transfer's states decode theirs): first what
    // every state refuses alike, byte 0 of no command, and an abort.
    if (!is_server_message(p[0])) {
      return abort_with(errc::unknown_command, abort_code::unknown_command);
    }
    if (detail::specifier(p[0]) == ccs_abort) {
      core_.fail(errc::aborted, static_cast<abort_code>(detail::get_u32(p)));
      return core_.make();
    }
    return (this->*handler_)(p);
  }

  /// Consume several received frames in order (what a CAN driver took from its receive FIFO),
  /// each exactly as on_frame(frame, now) takes it, all at the same `now`. It stops after the
  /// first frame that answers — its step has frames to send (the next request, an
  /// acknowledgement, an abort), or the state after it differs from the state before it (the
  /// transfer done or failed) — and returns {frames taken including that one, its step}: act
  /// on the step, then call again with the rest. When no frame answers, every frame is taken
  /// and `last` is the step on_frame gave for the last of them (nothing to send, the state and
  /// deadline after them); for an empty span, consumed is 0 and `last` the state and deadline
  /// as they are. Frames on other identifiers, remote frames on the response identifier and
  /// every frame while no transfer runs are taken and change nothing, as on_frame ignores them
  /// (a data frame on the response identifier with a DLC other than 8 fails the transfer, as
  /// on_frame does: it answers). Like on_frame it does not look at the deadline: call
  /// poll(now) for that. So the frames sent, the states, error() and the received bytes are
  /// those of on_frame called for each frame (tests/canopen/sdo_client_batch_test.cpp). The
  /// segments of a block upload are taken in runs (block_receiver::take_run: no step per
  /// segment, one CRC update per run); a program that never starts a block upload links none
  /// of it.
  [[nodiscard]] constexpr batch_step on_frames(std::span<const can_frame> fs,
                                               std::uint32_t now) noexcept {
    std::size_t i = 0;
    while (i < fs.size()) {
      if (runs_ && core_.busy()) {
        // the run of block upload segments in front that take_next would take one by one
        if (const std::size_t k = (this->*run_)(fs.subspan(i), now); k != 0U) {
          i += k;
          continue;
        }
      }
      const can_frame &f = fs[i++];
      if (!core_.busy() || !ch_.is_response(f)) continue; // on_frame changes nothing
      step s = on_frame(f, now);
      if (!s.send.empty() || s.state != transfer_state::busy) return {i, s};
    }
    return {i, core_.make()};
  }

  /// Check the timeout: abort 0x05040000, error timeout.
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    if (part_ready()) return {frames{}, core_.state(), std::nullopt}; // the caller's turn
    if (core_.timed_out(now)) return abort_with(errc::timeout, abort_code::timeout);
    return core_.make();
  }

  /// Abort the running transfer from the application side (e.g. on shutdown): error aborted
  /// with `code`.
  [[nodiscard]] constexpr step cancel(abort_code code = abort_code::general_error) noexcept {
    if (!core_.busy()) return core_.make();
    return abort_with(errc::aborted, code);
  }

  [[nodiscard]] constexpr transfer_state state() const noexcept { return core_.state(); }
  [[nodiscard]] constexpr bool busy() const noexcept { return core_.busy(); }
  /// Why the last transfer failed (see on_frame); empty otherwise.
  [[nodiscard]] constexpr std::optional<transfer_error> error() const noexcept {
    return core_.error();
  }
  /// The bytes uploaded so far (the value once state() == done); of a part transfer, the bytes
  /// of the current part; empty for a download (whose bytes transferred() counts).
  [[nodiscard]] constexpr std::span<const std::uint8_t> received() const noexcept {
    // an upload's count never passes its buffer; a download has none (rx_ is empty)
    const std::size_t n = count_ - base_;
    return std::span<const std::uint8_t>(rx_).first(n < rx_.size() ? n : rx_.size());
  }
  /// Bytes transferred so far (a block download counts acknowledged bytes).
  [[nodiscard]] constexpr std::size_t transferred() const noexcept { return count_; }
  /// When the running transfer times out (the deadline of the last step; empty when idle), for
  /// a caller that holds several machines and did not just call this one.
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline() const noexcept {
    return core_.make().deadline;
  }
  [[nodiscard]] constexpr const channel &connection() const noexcept { return ch_; }
  /// Use another channel (between transfers). Errors: bad_state.
  [[nodiscard]] constexpr status set_connection(channel ch) noexcept {
    if (core_.busy()) return errc::bad_state;
    ch_ = ch;
    return {};
  }

private:
  // Per-state transition functions: the running transfer's state is the function that takes
  // the next message (`handler_`), and for block segments, which carry no command specifier,
  // the function that sees the raw bytes first (`raw_`), and for on_frames the function that
  // takes a run of them (`run_`, when `runs_`). Firmware that never starts a block
  // transfer never references the block functions, so the linker drops them.
  using handler = step (basic_client::*)(const payload &);
  using raw_handler = std::optional<step> (basic_client::*)(const payload &);
  using run_handler = std::size_t (basic_client::*)(std::span<const can_frame>, std::uint32_t);
  constexpr void expect(handler h, raw_handler raw = nullptr) noexcept {
    handler_ = h;
    raw_ = raw;
    runs_ = false;
  }
  /// A state with a run handler. (`runs_` says whether run_ is set, instead of a comparison
  /// of run_ with nullptr: g++ 12 with -fsanitize=undefined cannot evaluate that in a constant
  /// expression, docs/od.md "Lookups in constant expressions".)
  constexpr void expect(handler h, raw_handler raw, run_handler run) noexcept {
    handler_ = h;
    raw_ = raw;
    run_ = run;
    runs_ = true;
  }

  [[nodiscard]] constexpr status can_start(std::size_t size) const noexcept {
    if (core_.busy()) return errc::bad_state;
    if (ch_.request_id == 0U && ch_.response_id == 0U) return errc::invalid_argument;
    if (size > 0xFFFF'FFFFU) return errc::too_long;
    return {};
  }
  constexpr void begin(od::address a, std::uint32_t now) noexcept {
    core_.begin(a, now);
    count_ = 0;
    tx_ = {};
    rx_ = {};
    base_ = 0;
    total_ = 0;
    paused_ = false;
  }
  [[nodiscard]] constexpr step send(const payload &p) const noexcept {
    return core_.make(frames(ch_.request(p)));
  }
  [[nodiscard]] constexpr step abort_with(errc e, abort_code code) noexcept {
    core_.fail(e, code);
    return core_.make(frames(ch_.request(abort(core_.address(), code))));
  }
  [[nodiscard]] constexpr step unexpected() noexcept {
    return abort_with(errc::unexpected_frame, abort_code::unknown_command);
  }
  [[nodiscard]] constexpr step done() noexcept {
    core_.finish();
    return core_.make();
  }
  // The command specifiers of the responses the states read in place (from the table, as
  // constants).
  static constexpr unsigned ccs_upload_segment =
      detail::specifier_of(message_type::upload_segment_response);
  static constexpr unsigned ccs_download_segment =
      detail::specifier_of(message_type::download_segment_response);
  static constexpr unsigned ccs_initiate_upload =
      detail::specifier_of(message_type::initiate_upload_response);
  static constexpr unsigned ccs_initiate_download =
      detail::specifier_of(message_type::initiate_download_response);
  static constexpr unsigned ccs_abort = detail::specifier_of(message_type::abort);

  /// An initiate response must have command specifier `ccs` and name the transfer's object.
  [[nodiscard]] constexpr std::optional<step> check_initiate(const payload &p,
                                                             unsigned ccs) noexcept {
    if (detail::specifier(p[0]) != ccs) return unexpected();
    return check_address(detail::get_address(p));
  }
  [[nodiscard]] constexpr std::optional<step> check_address(od::address a) noexcept {
    if (a != core_.address()) return abort_with(errc::unexpected_frame, abort_code::general_error);
    return std::nullopt;
  }
  /// A block transfer's response as a message (on_frame has refused bytes of no command).
  [[nodiscard]] static constexpr message decoded(const payload &p) noexcept {
    return decode(p, direction::to_client).value_or(message{});
  }
  /// The same for a block transfer's initiate response of type `t`.
  [[nodiscard]] constexpr std::optional<step> check_initiate(const message &m,
                                                             message_type t) noexcept {
    if (m.type != t) return unexpected();
    return check_address(m.address);
  }

  // ----- expedited and segmented download --------------------------------------------------

  [[nodiscard]] constexpr step download_expedited(const payload &p) noexcept {
    if (auto s = check_initiate(p, ccs_initiate_download)) return *s;
    count_ = tx_.size();
    return done();
  }
  // The part transfers (Parts = true: upload_parts, download_parts) share these states with
  // the whole ones; `if constexpr` keeps their pauses out of a program that never starts one.
  template <bool Parts = false>
  [[nodiscard]] constexpr step download_initiate(const payload &p) noexcept {
    if (auto s = check_initiate(p, ccs_initiate_download)) return *s;
    seg_tx_.start(Parts ? total_ : static_cast<std::uint32_t>(tx_.size()));
    return next_download_segment<Parts>();
  }
  template <bool Parts = false>
  [[nodiscard]] constexpr step next_download_segment() noexcept {
    expect(&basic_client::download_segment<Parts>);
    const std::size_t at = seg_tx_.offset() - base_;
    if constexpr (Parts) {
      if (at + seg_tx_.next_length() > tx_.size()) { // the caller feeds the next part
        paused_ = true;
        return {frames{}, core_.state(), std::nullopt};
      }
    }
    const auto chunk = tx_.subspan(at, seg_tx_.next_length());
    return send(seg_tx_.next(message_type::download_segment_request, chunk));
  }
  template <bool Parts = false>
  [[nodiscard]] constexpr step download_segment(const payload &p) noexcept {
    if (Parts && paused_) return unexpected(); // no segment was sent
    if (detail::specifier(p[0]) != ccs_download_segment) return unexpected();
    if (!seg_tx_.answer_matches(detail::segment_toggle(p[0]))) {
      return abort_with(errc::bad_toggle, abort_code::toggle_not_alternated);
    }
    count_ = seg_tx_.offset();
    if (seg_tx_.finished()) return done();
    return next_download_segment<Parts>();
  }

  // ----- expedited and segmented upload ----------------------------------------------------

  template <bool Parts = false>
  [[nodiscard]] constexpr step upload_initiate(const payload &p) noexcept {
    if (auto s = check_initiate(p, ccs_initiate_upload)) return *s;
    if (detail::initiate_expedited(p[0])) {
      const std::uint8_t n = detail::expedited_size(p[0]);
      if (n > rx_.size()) return abort_with(errc::buffer_too_small, abort_code::out_of_memory);
      for (std::size_t i = 0; i < 4U; ++i) { // not a copy of run-time length: no memcpy
        if (i < n) rx_[i] = p[4U + i];
      }
      count_ = n;
      return done();
    }
    const bool indicated = detail::initiate_size_indicated(p[0]);
    const std::uint32_t size = detail::get_u32(p);
    if (!Parts && indicated && size > rx_.size()) {
      return abort_with(errc::buffer_too_small, abort_code::out_of_memory);
    }
    seg_rx_.start(Parts ? std::size_t{0xFFFF'FFFFU} : rx_.size(),
                  indicated ? std::optional<std::uint32_t>(size) : std::nullopt);
    expect(&basic_client::upload_segment<Parts>);
    return send(upload_segment_request(seg_rx_.toggle()));
  }
  template <bool Parts = false>
  [[nodiscard]] constexpr step upload_segment(const payload &p) noexcept {
    if (Parts && paused_) return unexpected(); // nothing was requested: the window is the caller's
    if (detail::specifier(p[0]) != ccs_upload_segment) return unexpected();
    const std::size_t at = seg_rx_.count() - base_;
    const std::uint8_t n = detail::segment_size(p[0]);
    const bool last = detail::segment_last(p[0]);
    if (const auto code = seg_rx_.accept(detail::segment_toggle(p[0]), n, last);
        code != abort_code::none) {
      return local_abort(code);
    }
    for (std::size_t i = 0; i < 7U; ++i) { // not a copy of run-time length: no memcpy
      if (i < n) rx_[at + i] = p[1U + i];
    }
    count_ = seg_rx_.count();
    if (last) return done();
    if constexpr (Parts) {
      if (count_ - base_ + 7U > rx_.size()) { // the window is full: the caller's turn
        paused_ = true;
        return {frames{}, core_.state(), std::nullopt};
      }
    }
    return send(upload_segment_request(seg_rx_.toggle()));
  }
  /// A failure the receiving or sending core detected: the errc that goes with its code.
  [[nodiscard]] constexpr step local_abort(abort_code code) noexcept {
    switch (code) {
    case abort_code::toggle_not_alternated: return abort_with(errc::bad_toggle, code);
    case abort_code::out_of_memory: return abort_with(errc::buffer_too_small, code);
    case abort_code::length_too_high:
    case abort_code::length_too_low: return abort_with(errc::bad_length, code);
    case abort_code::invalid_sequence_number: return abort_with(errc::unexpected_frame, code);
    case abort_code::invalid_block_size: return abort_with(errc::out_of_range, code);
    case abort_code::crc_error: return abort_with(errc::bad_checksum, code);
    default: return abort_with(errc::unexpected_frame, code);
    }
  }

  // ----- block download ----------------------------------------------------------------------

  [[nodiscard]] constexpr step block_download_initiate(const payload &p) noexcept {
    const message m = decoded(p);
    if (auto s = check_initiate(m, message_type::block_download_initiate_response)) return *s;
    if (m.block_size < 1U || m.block_size > max_block_size) {
      return abort_with(errc::out_of_range, abort_code::invalid_block_size);
    }
    block_tx_.start(static_cast<std::uint32_t>(tx_.size()), options_.crc && m.crc, m.block_size);
    return next_burst();
  }
  [[nodiscard]] constexpr std::span<const std::uint8_t> burst_window() const noexcept {
    return tx_.subspan(block_tx_.offset(), block_tx_.burst_bytes());
  }
  [[nodiscard]] constexpr step next_burst() noexcept {
    expect(&basic_client::block_download_ack);
    window_ = burst_window();
    return core_.make(block_tx_.burst(ch_.request_id, window_));
  }
  [[nodiscard]] constexpr step block_download_ack(const payload &p) noexcept {
    const message m = decoded(p);
    if (m.type != message_type::block_ack) return unexpected();
    const auto r = block_tx_.on_ack(m, window_);
    count_ = block_tx_.acknowledged();
    if (r.abort != abort_code::none) return local_abort(r.abort);
    if (r.what == basic_block_sender<Crc>::next::burst) return next_burst();
    expect(&basic_client::block_download_end);
    return send(block_tx_.end());
  }
  [[nodiscard]] constexpr step block_download_end(const payload &p) noexcept {
    if (decoded(p).type != message_type::block_end_response) return unexpected();
    return done();
  }

  // ----- block upload ------------------------------------------------------------------------

  [[nodiscard]] constexpr step block_upload_initiate(const payload &p) noexcept {
    if (detail::specifier(p[0]) == ccs_initiate_upload) {
      // protocol switch: the server answers with a normal upload (only if we allowed it)
      if (options_.switch_threshold == 0U) return unexpected();
      expect(&basic_client::upload_initiate<>);
      return upload_initiate(p);
    }
    const message m = decoded(p);
    if (auto s = check_initiate(m, message_type::block_upload_initiate_response)) return *s;
    if (m.size_indicated && m.size > rx_.size()) {
      return abort_with(errc::buffer_too_small, abort_code::out_of_memory);
    }
    block_rx_.start(rx_.size(),
                    m.size_indicated ? std::optional<std::uint32_t>(m.size) : std::nullopt,
                    options_.crc && m.crc, options_.block_size);
    expect(&basic_client::unexpected_message, &basic_client::block_upload_segment,
           &basic_client::block_upload_run);
    return send(block_upload_start());
  }
  [[nodiscard]] constexpr step unexpected_message(const payload &) noexcept { return unexpected(); }
  /// During the segments of a sub-block every frame but an abort is a segment. The common one
  /// (in sequence, not the last of the transfer or of its sub-block, within the announced size
  /// and the buffer: block_receiver::take_next) is taken without a segment_result — as
  /// on_segment would take it, its 7 bytes at the old count —, the rest by on_segment.
  [[nodiscard]] constexpr std::optional<step> block_upload_segment(const payload &p) noexcept {
    if (p[0] == 0x80U) return std::nullopt; // an abort
    if (const std::size_t at = block_rx_.count(); block_rx_.take_next(p)) {
      // take_next's bound is min(announced size, rx_.size()): the 7 bytes fit
      fieldcodec::copy_bytes<7>(p.data() + 1, rx_.data() + at);
      count_ = block_rx_.count();
      return core_.make();
    }
    const auto r = block_rx_.on_segment(p); // sequence 0: invalid_sequence_number
    if (r.abort != abort_code::none) return local_abort(r.abort);
    for (std::size_t i = 0; i < r.bytes.size(); ++i) rx_[r.offset + i] = r.bytes[i];
    count_ = block_rx_.count();
    if (!r.acknowledge) return core_.make();
    if (block_rx_.final_received()) {
      expect(&basic_client::block_upload_end, &basic_client::block_upload_repeat);
    }
    return send(block_rx_.acknowledge(options_.block_size));
  }
  /// on_frames during the segments of a sub-block: the run of frames in front that
  /// block_upload_segment would take by take_next one by one (block_receiver::take_run: the
  /// same checks — on the response identifier, no remote frame, DLC 8 —, the same bytes at the
  /// same places, one CRC update), each touching the deadline as on_frame does. Returns how
  /// many it took (0: the next frame goes through on_frame).
  [[nodiscard]] constexpr std::size_t block_upload_run(std::span<const can_frame> fs,
                                                       std::uint32_t now) noexcept {
    // take_run wants a valid 11-bit identifier; with another one on_frame takes every frame
    if (ch_.response_id == 0U || ch_.response_id > max_can_id) return 0;
    // count_ == block_rx_.count() ≤ rx_.size() (take_next's bound is within the buffer)
    const std::size_t k = block_rx_.take_run(fs, ch_.response_id, rx_.subspan(count_));
    if (k != 0U) {
      core_.touch(now);
      count_ = block_rx_.count();
    }
    return k;
  }
  /// While the end is awaited: the last segment once more is ignored.
  [[nodiscard]] constexpr std::optional<step> block_upload_repeat(const payload &p) noexcept {
    if (block_rx_.is_repeat(p)) return core_.make();
    return std::nullopt;
  }
  [[nodiscard]] constexpr step block_upload_end(const payload &p) noexcept {
    const message m = decoded(p);
    if (m.type != message_type::block_end) return unexpected();
    const auto r = block_rx_.on_end(m);
    if (r.abort != abort_code::none) return local_abort(r.abort);
    for (std::size_t i = 0; i < r.bytes.size(); ++i) rx_[r.offset + i] = r.bytes[i];
    count_ = block_rx_.count();
    core_.finish();
    return send(block_end_response());
  }

  channel ch_;
  machine_core core_;
  handler handler_ = &basic_client::unexpected_message;
  raw_handler raw_ = nullptr;
  run_handler run_ = nullptr;
  bool runs_ = false; ///< run_ is set (on_frames calls it)
  block_options options_{};
  std::size_t count_ = 0;
  std::size_t base_ = 0;    ///< part transfers: bytes of the parts before the current one
  std::uint32_t total_ = 0; ///< part download: the size announced
  bool paused_ = false;     ///< a part is ready (upload) or needed (download)
  std::span<const std::uint8_t> tx_{};
  std::span<std::uint8_t> rx_{};
  std::span<const std::uint8_t> window_{};
  segment_sender seg_tx_{};
  segment_receiver seg_rx_{};
  basic_block_sender<Crc> block_tx_{};
  basic_block_receiver<Crc> block_rx_{};
};

/// The client with the CRC of block transfers computed without a table.
using client = basic_client<>;

} // namespace fieldcodec::canopen::sdo
