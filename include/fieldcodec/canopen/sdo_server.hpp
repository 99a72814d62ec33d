// fieldcodec — a non-blocking SDO server transfer machine: expedited, segmented and block
// download and upload from an object store (canopen/object_store.hpp).
//
// The server answers requests on its channel (the predefined 0x600 + node / 0x580 + node, or
// the identifiers of an SDO server parameter object 1200h–127Fh). It moves values through a
// caller-owned buffer in parts, so an object larger than the buffer is still served: a
// download is passed to the store in parts (the store shows the value only when the last part
// arrived), an upload is read from the store in parts. A value that fits the buffer is written
// to the store in one part. Every call returns an sdo::step (frames, state, deadline).
//
//   sdo::server<Store> s(5, store, buffer);
//   for every received frame: for (const auto &f : s.on_frame(frame, now).send) transmit(f);
//   when the deadline passes: for (const auto &f : s.poll(now).send) transmit(f);
//
// or, with the frames a CAN driver took from its receive FIFO (several at once):
//
//   for (auto rx = fifo_frames; !rx.empty();) {
//     const auto r = s.on_frames(rx, now);      // stops at the first frame that answers
//     for (const auto &f : r.last.send) transmit(f);
//     rx = rx.subspan(r.consumed);
//   }
//
// Block transfer: the server offers CRC when asked, takes sub-blocks of up to min(127,
// buffer / 7) segments, and sends sub-blocks of the size the client asks for when that many
// segments fit its buffer (otherwise it aborts with 0x05040002). It answers a block upload of
// an object of at most the client's protocol switch threshold with a normal upload.
//
// A store may also want to know when a transfer of one of its objects ends unfinished (a store
// that streams an object to or from elsewhere, node::device's hooks), with the optional member
//
//   void abandoned(od::address a, sdo::abort_code why);
//
// called once for such a transfer: aborted by either side (`why`: the code sent or received,
// also when the store itself refused a part), timed out, or ended silently (`why` none: a new
// request on the channel, set_connection).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>

namespace fieldcodec::canopen::sdo {

/// What a server offers.
struct server_options {
  bool block = true; ///< answer block transfer requests (else abort 0x05040001)
  bool crc = true;   ///< support the CRC of block transfers
};

namespace detail {

/// Append `bytes` to `buf`, whose first `used` bytes are taken: when `buf` is full and bytes
/// remain, `flush()` (abort_code() noexcept) passes the full buffer on and `used` starts again
/// from 0. Returns none, out_of_memory (an empty buffer) or what flush() returned; on an error
/// the bytes before it stay appended. Copies runs of bytes, not one byte and one check at a
/// time (a block segment is 7 bytes; see docs/performance.md, "Services").
template <class Flush>
[[nodiscard]] constexpr abort_code append_parts(std::span<std::uint8_t> buf, std::size_t &used,
                                                std::span<const std::uint8_t> bytes,
                                                Flush flush) noexcept {
  std::size_t at = 0;
  while (at < bytes.size()) {
    if (used == buf.size()) {
      if (buf.empty()) return abort_code::out_of_memory;
      if (const abort_code c = flush(); c != abort_code::none) return c;
      used = 0;
    }
    const std::size_t room = buf.size() - used;
    const std::size_t left = bytes.size() - at;
    const std::size_t n = room < left ? room : left;
    if (n == 7U) { // a whole segment: a copy of constant length, inlined as a few moves
      fieldcodec::copy_bytes<7>(bytes.data() + at, buf.data() + used);
    } else {
      std::copy_n(bytes.begin() + static_cast<std::ptrdiff_t>(at), n,
                  buf.begin() + static_cast<std::ptrdiff_t>(used));
    }
    used += n;
    at += n;
  }
  return abort_code::none;
}

} // namespace detail

/// The server; `Crc` computes the CRC of block transfers (crc::ccitt16_no_table, the default,
/// or crc::ccitt16_with_table: a 512-byte table in flash for about half the instructions a
/// byte; core/crc.hpp).
template <object_store Store, class Crc = crc::ccitt16_no_table>
class server {
public:
  /// A server on `ch`. `store` and `buffer` are borrowed and must outlive the server.
  constexpr server(channel ch, Store &store, std::span<std::uint8_t> buffer,
                   std::uint32_t timeout_ms = 1000, server_options o = {}) noexcept
      : ch_(ch), store_(&store), buf_(buffer), core_(timeout_ms), options_(o) {}
  /// A server for `node` on the predefined channel; a node-ID outside 1..127 answers nothing.
  constexpr server(std::uint8_t node, Store &store, std::span<std::uint8_t> buffer,
                   std::uint32_t timeout_ms = 1000, server_options o = {}) noexcept
      : server(channel::default_for(node).value_or(channel{}), store, buffer, timeout_ms, o) {}

  /// Consume a frame. Frames on other identifiers and remote frames are not for the server;
  /// frames with a DLC other than 8 get no answer (error(): bad_length). A request that does
  /// not fit the running transfer is answered with an abort, and the transfer fails.
  [[nodiscard]] constexpr step on_frame(const can_frame &f, std::uint32_t now) noexcept {
    // A segment of a block download, the frame a server sees most (issue 18): taken by a short
    // path that the caller can inline, without the dispatch below (which would take it the
    // same way: the checks are the same, in the same order).
    if (phase_ == phase::block_download_segments && ch_.is_request(f) && expect_data(f, 8) &&
        f.data[0] != 0x80U) {
      if (core_.busy()) core_.touch(now);
      return block_download_segment(f.data);
    }
    return on_any_frame(f, now);
  }

  /// Consume several received frames in order (what a CAN driver took from its receive FIFO),
  /// each exactly as on_frame(frame, now) takes it, all at the same `now`. It stops after the
  /// first frame that answers — its step has frames to send, or the state after it differs
  /// from the state before it (a transfer done or failed), or it was refused (a frame on the
  /// request identifier with a DLC other than 8: error() says bad_length) — and returns
  /// {frames taken including that one, its step}: act on the step, then call again with the
  /// rest. When no frame answers, every frame is taken and `last` is the step on_frame gave
  /// for the last of them (nothing to send, the state and deadline after them); for an empty
  /// span, consumed is 0 and `last` the state and deadline as they are. Frames on other
  /// identifiers and remote frames are taken and change nothing, as on_frame ignores them.
  /// Like on_frame it does not look at the deadline: call poll(now) for that. So the frames
  /// sent, the states, error() and the stored bytes are those of on_frame called for each
  /// frame (tests/canopen/sdo_server_batch_test.cpp). The segments of a block download are
  /// taken in runs (block_receiver::take_run: no step per segment, one CRC update per run).
  [[nodiscard]] constexpr batch_step on_frames(std::span<const can_frame> fs,
                                               std::uint32_t now) noexcept {
    std::size_t i = 0;
    while (i < fs.size()) {
      if (phase_ == phase::block_download_segments && ch_.request_id != 0U &&
          ch_.request_id <= max_can_id) {
        // the run of segments in front that take_next would take one by one
        const std::size_t k = block_rx_.take_run(fs.subspan(i), ch_.request_id,
                                                 std::span<std::uint8_t>(buf_).subspan(used_));
        if (k != 0U) {
          if (core_.busy()) core_.touch(now);
          used_ += 7U * k;
          i += k;
          continue;
        }
      }
      const can_frame &f = fs[i++];
      if (!ch_.is_request(f)) continue; // not for the server: on_frame changes nothing
      const transfer_state before = core_.state();
      const bool refused = !expect_data(f, 8);
      step s = on_frame(f, now);
      if (refused || !s.send.empty() || s.state != before) return {i, s};
    }
    return {i, core_.make()};
  }

  /// Abort a transfer whose client went silent (0x05040000, error timeout).
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    if (core_.timed_out(now)) return fail(errc::timeout, abort_code::timeout);
    return core_.make();
  }

  [[nodiscard]] constexpr transfer_state state() const noexcept { return core_.state(); }
  [[nodiscard]] constexpr bool busy() const noexcept { return core_.busy(); }
  /// Why the last transfer failed, or why the last frame was refused; empty otherwise.
  [[nodiscard]] constexpr std::optional<transfer_error> error() const noexcept {
    return core_.error();
  }
  /// When the running transfer times out (the deadline of the last step; empty when idle), for
  /// a caller that holds several machines and did not just call this one.
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline() const noexcept {
    return core_.make().deadline;
  }
  [[nodiscard]] constexpr const channel &connection() const noexcept { return ch_; }
  /// Follow a new SDO server parameter (1200h sub 1/2); ends a running transfer silently.
  constexpr void set_connection(channel ch) noexcept {
    ch_ = ch;
    if (core_.busy()) abandon(abort_code::none);
    core_.stop();
    phase_ = phase::idle;
  }

private:
  /// Every frame but a block download segment (see on_frame).
  FIELDCODEC_SDO_OUT_OF_LINE [[nodiscard]] constexpr step on_any_frame(const can_frame &f,
                                                                       std::uint32_t now) noexcept {
    if (!ch_.is_request(f)) return core_.make();
    // payload_of's check, reading the bytes in place (no copy of them through a result)
    if (const auto ok = expect_data(f, 8); !ok) {
      core_.refuse(ok.error(), {});
      return core_.make();
    }
    const payload &p = f.data;
    if (core_.busy()) core_.touch(now);
    if (phase_ == phase::block_download_end && block_rx_.is_repeat(p)) {
      return core_.make(); // the last segment once more
    }
    // The request is read in place (no `message` is built): its type from the codec's table
    // (the client → server half), its fields through the codec's layout readers (sdo.hpp).
    const message_type t = detail::type_of<direction::to_server>(p[0]);
    if (t == detail::no_type) {
      return reply_abort(detail::get_address(p), abort_code::unknown_command,
                         errc::unknown_command);
    }
    switch (t) {
    case message_type::initiate_download_request:
    case message_type::initiate_upload_request:
    case message_type::block_download_initiate:
    case message_type::block_upload_initiate: return initiate(t, p, now);
    case message_type::abort:
      if (core_.busy()) {
        const abort_code code = detail::abort_of(p);
        abandon(code);
        core_.fail(errc::aborted, code);
      }
      phase_ = phase::idle;
      return core_.make();
    default: break;
    }
    // every other request continues a transfer: the one its phase awaits, or none (idle)
    if (t != awaited[static_cast<std::size_t>(phase_)]) return unexpected();
    switch (phase_) {
    case phase::download_segments: return download_segment(p);
    case phase::upload_segments: return upload_segment(p);
    case phase::block_download_end: return block_download_end(p);
    case phase::block_upload_start: return next_burst();
    case phase::block_upload_ack: return block_upload_ack(p);
    case phase::block_upload_end:
      core_.finish();
      phase_ = phase::idle;
      return core_.make();
    case phase::idle:
    case phase::block_download_segments: break;
    }
    return unexpected();
  }

  enum class phase : std::uint8_t {
    idle,
    download_segments,
    upload_segments,
    block_download_segments,
    block_download_end,
    block_upload_start,
    block_upload_ack,
    block_upload_end,
  };
  /// The request each phase takes (no_type: none but the initiates and abort).
  static constexpr message_type awaited[] = {
      detail::no_type,                        // idle
      message_type::download_segment_request, // download_segments
      message_type::upload_segment_request,   // upload_segments
      detail::no_type,                        // block_download_segments (segments: on_frame)
      message_type::block_end,                // block_download_end
      message_type::block_upload_start,       // block_upload_start
      message_type::block_ack,                // block_upload_ack
      message_type::block_end_response,       // block_upload_end
  };

  // ----- answers and failures ------------------------------------------------------------

  [[nodiscard]] constexpr step send(const payload &p) const noexcept {
    return core_.make(frames(ch_.response(p)));
  }
  /// Fail the running transfer (if any) with `e` and answer with an abort about `a`.
  [[nodiscard]] constexpr step reply_abort(od::address a, abort_code code, errc e) noexcept {
    if (core_.busy()) {
      abandon(code);
      core_.fail(e, code);
    } else {
      core_.refuse(e, a);
    }
    phase_ = phase::idle;
    return send(abort(a, code));
  }
  [[nodiscard]] constexpr step fail(errc e, abort_code code) noexcept {
    return reply_abort(core_.address(), code, e);
  }
  [[nodiscard]] constexpr step store_refused(abort_code code) noexcept {
    return fail(errc::aborted, code);
  }
  [[nodiscard]] constexpr step unexpected() noexcept {
    return reply_abort(core_.address(), abort_code::unknown_command, errc::unexpected_frame);
  }
  [[nodiscard]] constexpr step local_abort(abort_code code) noexcept {
    switch (code) {
    case abort_code::toggle_not_alternated: return fail(errc::bad_toggle, code);
    case abort_code::out_of_memory: return fail(errc::buffer_too_small, code);
    case abort_code::length_too_high:
    case abort_code::length_too_low: return fail(errc::bad_length, code);
    case abort_code::invalid_sequence_number: return fail(errc::unexpected_frame, code);
    case abort_code::invalid_block_size: return fail(errc::out_of_range, code);
    case abort_code::crc_error: return fail(errc::bad_checksum, code);
    default: return fail(errc::unexpected_frame, code);
    }
  }

  /// The transfer is complete.
  constexpr void done() noexcept {
    core_.finish();
    phase_ = phase::idle;
  }
  [[nodiscard]] constexpr step finish(const payload &p) noexcept {
    done();
    return send(p);
  }
  constexpr void start(od::address a, std::uint32_t now, phase ph) noexcept {
    if (core_.busy()) abandon(abort_code::none); // a new request ends the running transfer
    core_.begin(a, now);
    phase_ = ph;
    used_ = 0;
    flushed_ = 0;
  }

  /// Tell the store that the running transfer ends unfinished (its optional abandoned()).
  constexpr void abandon(abort_code why) noexcept {
    if constexpr (requires(Store & s, od::address a) { s.abandoned(a, why); }) {
      store_->abandoned(core_.address(), why);
    } else {
      (void)why;
    }
  }

  /// A request that starts a transfer (`t`: one of the four initiates) on the object its bytes
  /// 1..3 name; it ends any running transfer.
  [[nodiscard]] constexpr step initiate(message_type t, const payload &p,
                                        std::uint32_t now) noexcept {
    const od::address a = detail::get_address(p);
    start(a, now, phase::idle);
    if (t == message_type::initiate_download_request) return initiate_download(p, a);
    if (t == message_type::initiate_upload_request) {
      if (const auto c = open_upload(a); c != abort_code::none) return store_refused(c);
      return normal_upload_response();
    }
    if (!options_.block) return reply_abort(a, abort_code::unknown_command, errc::unknown_command);
    if (t == message_type::block_download_initiate) return block_download_initiate(p, a);
    return block_upload_initiate(p, a);
  }

  // ----- the download side: the buffer fills, full buffers go to the store ----------------

  /// Append received bytes; a full buffer goes to the store as a part.
  [[nodiscard]] constexpr abort_code append(std::span<const std::uint8_t> bytes) noexcept {
    return detail::append_parts(buf_, used_, bytes, [this]() noexcept { return flush(); });
  }
  /// Pass the bytes in the buffer to the store as a part (not the last); the buffer is then
  /// empty.
  [[nodiscard]] constexpr abort_code flush() noexcept {
    const auto c = store_->write(core_.address(), flushed_,
                                 std::span<const std::uint8_t>(buf_).first(used_), false);
    if (c == abort_code::none) {
      flushed_ += used_;
      used_ = 0;
    }
    return c;
  }
  /// The last part: the value becomes visible (or is refused).
  [[nodiscard]] constexpr abort_code complete_download() noexcept {
    return store_->write(core_.address(), flushed_,
                         std::span<const std::uint8_t>(buf_).first(used_), true);
  }

  /// An initiate download request (layout::initiate): expedited data (bytes 4.., 1..4 of
  /// them) or the announced size of the segments to come.
  [[nodiscard]] constexpr step initiate_download(const payload &p, od::address a) noexcept {
    const bool expedited = detail::initiate_expedited(p[0]);
    const std::uint8_t n = detail::expedited_size(p[0]);
    std::optional<std::uint32_t> size;
    if (detail::initiate_size_indicated(p[0])) size = expedited ? n : detail::get_u32(p);
    if (const auto c = store_->begin_write(a, size); c != abort_code::none) {
      return store_refused(c);
    }
    if (expedited) { // the value in bytes 4.., done
      const auto c = store_->write(a, 0, std::span<const std::uint8_t>(p).subspan(4, n), true);
      if (c != abort_code::none) return store_refused(c);
      done();
    } else {
      seg_rx_.start(~std::size_t{0}, size);
      phase_ = phase::download_segments;
    }
    return send(download_response(a));
  }

  /// A download segment request (layout::segment).
  [[nodiscard]] constexpr step download_segment(const payload &p) noexcept {
    const bool toggle = detail::segment_toggle(p[0]);
    const bool last = detail::segment_last(p[0]);
    const std::uint8_t n = detail::segment_size(p[0]);
    if (const auto c = seg_rx_.accept(toggle, n, last); c != abort_code::none) {
      return local_abort(c);
    }
    return take(std::span<const std::uint8_t>(p).subspan(1, n), last,
                download_segment_response(toggle));
  }
  /// Received bytes into the buffer (a full buffer goes to the store as a part); when they are
  /// the `last`, the value goes to the store and the transfer is done. Then `answer`.
  [[nodiscard]] constexpr step take(std::span<const std::uint8_t> bytes, bool last,
                                    const payload &answer) noexcept {
    if (const auto c = append(bytes); c != abort_code::none) return store_refused(c);
    if (last) {
      if (const auto c = complete_download(); c != abort_code::none) return store_refused(c);
      done();
    }
    return send(answer);
  }

  [[nodiscard]] constexpr std::uint8_t download_block_size() const noexcept {
    const std::size_t n = (buf_.size() - used_) / 7U;
    return static_cast<std::uint8_t>(n > max_block_size ? max_block_size : n);
  }

  /// A block download initiate (layout::block_initiate).
  [[nodiscard]] constexpr step block_download_initiate(const payload &p, od::address a) noexcept {
    const std::optional<std::uint32_t> size = detail::block_size_indicated(p[0])
                                                  ? std::optional<std::uint32_t>(detail::get_u32(p))
                                                  : std::nullopt;
    if (const auto c = store_->begin_write(a, size); c != abort_code::none) {
      return store_refused(c);
    }
    const std::uint8_t n = download_block_size();
    if (n == 0U) return fail(errc::buffer_too_small, abort_code::out_of_memory);
    const bool crc = options_.crc & detail::block_crc(p[0]); // both (`&`: no branch)
    block_rx_.start(~std::size_t{0}, size, crc, n);
    phase_ = phase::block_download_segments;
    // n is 1..127: the writer without the check
    return send(detail::put_block_size(
        detail::bits_of<message_type::block_download_initiate_response> | (crc ? 0x04U : 0U), a, n,
        0));
  }

  /// A segment of a block download (on_frame's short path). The common case — with room for 7
  /// bytes in the buffer, a segment block_receiver::take_next takes (in sequence, not the last
  /// of the transfer or its sub-block) — is finished here (what `append` would do: no flush is
  /// due) and answers nothing; everything else goes through on_segment and
  /// block_download_segment_rest, out of line.
  [[nodiscard]] constexpr step block_download_segment(const payload &p) noexcept {
    if (buf_.size() - used_ >= 7U && block_rx_.take_next(p)) {
      fieldcodec::copy_bytes<7>(p.data() + 1, buf_.data() + used_);
      used_ += 7U;
      return core_.make();
    }
    return block_download_segment_rest(p);
  }
  FIELDCODEC_SDO_OUT_OF_LINE [[nodiscard]] constexpr step
  block_download_segment_rest(const payload &p) noexcept {
    const auto r = block_rx_.on_segment(p); // sequence 0: invalid_sequence_number
    if (r.abort != abort_code::none) return local_abort(r.abort);
    if (const auto c = append(r.bytes); c != abort_code::none) return store_refused(c);
    if (!r.acknowledge) return core_.make();
    if (block_rx_.final_received()) phase_ = phase::block_download_end;
    // room for the next sub-block: send the collected bytes to the store when it is short
    if (download_block_size() == 0U && used_ > 0U) {
      if (const auto c = flush(); c != abort_code::none) return store_refused(c);
    }
    const std::uint8_t n = download_block_size();
    return send(block_rx_.acknowledge(n == 0U ? 1U : n));
  }

  /// A block download end (layout::block_end).
  [[nodiscard]] constexpr step block_download_end(const payload &p) noexcept {
    const auto r = block_rx_.on_end(detail::end_unused(p[0]), detail::end_checksum(p));
    if (r.abort != abort_code::none) return local_abort(r.abort);
    return take(r.bytes, true, block_end_response());
  }

  // ----- the upload side: the buffer is a window over the value --------------------------

  /// Make the window cover [offset, offset + n) of the value. Returns none or an abort code.
  [[nodiscard]] constexpr abort_code window(std::size_t offset, std::size_t n) noexcept {
    if (offset >= win_ && offset + n <= win_ + used_) return abort_code::none;
    std::size_t total = 0;
    const auto c = store_->read(core_.address(), offset, buf_, total);
    if (c != abort_code::none) return c;
    if (total != size_) return abort_code::general_error; // the value changed meanwhile
    win_ = offset;
    used_ = total - offset < buf_.size() ? total - offset : buf_.size();
    if (n > used_) return abort_code::out_of_memory;
    return abort_code::none;
  }
  [[nodiscard]] constexpr std::span<const std::uint8_t> view(std::size_t offset,
                                                             std::size_t n) const noexcept {
    return std::span<const std::uint8_t>(buf_).subspan(offset - win_, n);
  }
  /// Read the start of `a`; size_ is its length. Returns none or an abort code.
  [[nodiscard]] constexpr abort_code open_upload(od::address a) noexcept {
    std::size_t total = 0;
    const auto c = store_->read(a, 0, buf_, total);
    if (c != abort_code::none) return c;
    if (total > 0xFFFF'FFFFU) return abort_code::length_too_high;
    size_ = total;
    win_ = 0;
    used_ = total < buf_.size() ? total : buf_.size();
    return abort_code::none;
  }

  /// The answer to an initiate upload (also after a protocol switch).
  [[nodiscard]] constexpr step normal_upload_response() noexcept {
    if (size_ >= 1U && size_ <= 4U) {
      if (used_ < size_) return fail(errc::buffer_too_small, abort_code::out_of_memory);
      // 1..4 bytes, size indicated: the writer without the checks
      return finish(detail::put_expedited(message_type::initiate_upload_response, core_.address(),
                                          view(0, size_), true));
    }
    seg_tx_.start(static_cast<std::uint32_t>(size_));
    phase_ = phase::upload_segments;
    return send(upload_response(core_.address(), static_cast<std::uint32_t>(size_)));
  }

  /// An upload segment request (layout::toggle).
  [[nodiscard]] constexpr step upload_segment(const payload &p) noexcept {
    if (detail::segment_toggle(p[0]) != seg_tx_.toggle()) {
      return fail(errc::bad_toggle, abort_code::toggle_not_alternated);
    }
    const std::size_t at = seg_tx_.offset();
    const std::size_t n = seg_tx_.next_length();
    if (const auto c = window(at, n); c != abort_code::none) return store_refused(c);
    const payload seg = seg_tx_.next(message_type::upload_segment_response, view(at, n));
    if (seg_tx_.finished()) done();
    return send(seg);
  }

  /// A block upload initiate (layout::block_upload).
  [[nodiscard]] constexpr step block_upload_initiate(const payload &p, od::address a) noexcept {
    const std::uint8_t block_size = detail::initiate_block_size(p);
    if (!detail::valid_block_size(block_size)) {
      return fail(errc::out_of_range, abort_code::invalid_block_size);
    }
    if (const auto c = open_upload(a); c != abort_code::none) return store_refused(c);
    const std::uint8_t threshold = detail::switch_threshold(p);
    if (threshold != 0U && size_ <= threshold) return normal_upload_response();
    const bool crc = options_.crc & detail::block_crc(p[0]); // both (`&`: no branch)
    block_tx_.start(static_cast<std::uint32_t>(size_), crc, block_size);
    phase_ = phase::block_upload_start;
    return send(block_upload_initiate_response(a, static_cast<std::uint32_t>(size_), true, crc));
  }

  [[nodiscard]] constexpr step next_burst() noexcept {
    const std::size_t at = block_tx_.offset();
    const std::size_t n = block_tx_.burst_bytes();
    if (n > buf_.size()) { // the client asks for more segments than the buffer holds
      return fail(errc::out_of_range, abort_code::invalid_block_size);
    }
    if (const auto c = window(at, n); c != abort_code::none) return store_refused(c);
    phase_ = phase::block_upload_ack;
    burst_ = view(at, n);
    return core_.make(block_tx_.burst(ch_.response_id, burst_));
  }

  /// A block acknowledgement (layout::block_ack).
  [[nodiscard]] constexpr step block_upload_ack(const payload &p) noexcept {
    const auto r = block_tx_.on_ack(detail::ack_sequence(p), detail::ack_block_size(p), burst_);
    if (r.abort != abort_code::none) return local_abort(r.abort);
    if (r.what == basic_block_sender<Crc>::next::burst) return next_burst();
    phase_ = phase::block_upload_end;
    return send(block_tx_.end());
  }

  channel ch_;
  Store *store_;
  std::span<std::uint8_t> buf_;
  machine_core core_;
  server_options options_;
  phase phase_ = phase::idle;
  std::size_t used_ = 0;    ///< download: bytes in the buffer; upload: bytes of the window
  std::size_t flushed_ = 0; ///< download: bytes passed to the store as parts
  std::size_t win_ = 0;     ///< upload: offset of the window in the value
  std::size_t size_ = 0;    ///< upload: length of the value
  std::span<const std::uint8_t> burst_{};
  segment_sender seg_tx_{};
  segment_receiver seg_rx_{};
  basic_block_sender<Crc> block_tx_{};
  basic_block_receiver<Crc> block_rx_{};
};

} // namespace fieldcodec::canopen::sdo
