// fieldcodec — an SDO client over CoE: the CiA 301 client machine (canopen/sdo_client.hpp)
// reading and writing a slave's objects through EtherCAT mailboxes.
//
// For an EtherCAT master (or any program) that has raw mailbox access to a slave — writing the
// slave's receive mailbox (SM0), reading its send mailbox (SM1) — this is the same checked SDO
// as on CAN: typed values through od's encode with the entry's limits, the abort codes, the
// timeout, the machine's states and errors.
//
//   std::array<std::uint8_t, 128> mbx;                   // the slave's SM0 size
//   coe::sdo_client c(mbx, 128);                          // SM1 size: the longest response
//   auto s = c.write(my_drive::target_position, 10000, now);  // od::encode, checked
//   write_sm0(s.value().send);                            // the mailbox to send
//   // for every mailbox read from SM1, and when the deadline passes:
//   auto t = c.on_mailbox(read_sm1(), now);               // or c.poll(now)
//   if (!t.send.empty()) write_sm0(t.send);
//   // c.state() == done: c.value<std::int32_t>(entry) after a read; failed: c.error()
//
// Transfers (ETG.1000.6 5.6.2): 1..4 bytes go expedited; other values go normal — the complete
// size and as much of the value as the request mailbox holds in the initiate — and, when the
// value does not fit, in segments of the request mailbox's size. Uploads take what the slave
// sends: expedited, normal, or normal followed by segments of any size up to the response
// mailbox. Complete access (the whole object from sub-index 0 or 1) is asked for by a flag.
// The machine inside sees the transfer as CAN messages (coe/sdo_transfer.hpp); its checks are
// the checks of the transfer. What the adapter itself checks, and how it fails:
// * a mailbox it cannot read while a transfer runs (truncated: truncated; a length field that
//   disagrees with the bytes: bad_length; longer than the response mailbox: too_long; an SDO
//   part that is not a valid CoE SDO message: its decode error) ends the transfer with that
//   error and an abort (0x05040001 for an unknown command, 0x08000000 otherwise);
// * a mailbox error reply (mailbox type 0) ends it with the errc of its detail, without abort;
// * the toggle of CoE segments: a repeated toggle is the machine's toggle error (0x05030000);
// * mailboxes that are no SDO (emergency, PDO, SDO information, other mailbox types) and
//   repeated mailboxes (mailbox counter, coe/sdo_transfer.hpp) are left alone: refused() says
//   unexpected_frame and the transfer goes on; route them elsewhere first.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/coe/mailbox.hpp>
#include <fieldcodec/canopen/coe/sdo.hpp>
#include <fieldcodec/canopen/coe/sdo_transfer.hpp>
#include <fieldcodec/canopen/coe/service.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/value.hpp>

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::coe {

class sdo_client {
public:
  /// A client that writes its requests into `request_mailbox` (borrowed; its size is the
  /// slave's receive mailbox size, SM0, at least 16 bytes) and takes responses of up to
  /// `response_size` bytes (the slave's send mailbox size, SM1, at least 16). A smaller mailbox
  /// makes every transfer fail to start with invalid_argument.
  constexpr sdo_client(std::span<std::uint8_t> request_mailbox, std::size_t response_size,
                       std::uint32_t timeout_ms = 1000, mailbox_options o = {}) noexcept
      : out_(request_mailbox), response_size_(response_size), options_(o),
        inner_(detail::inner_channel, timeout_ms) {}

  /// Start writing `data` to `a` (borrowed until the transfer ends). With complete_access the
  /// whole object is written, starting at sub-index a.sub (0: sub-index 0 included, 1:
  /// excluded). Errors: bad_state (a transfer runs), invalid_argument (a mailbox under 16
  /// bytes; complete access with a sub-index other than 0 or 1), too_long (more than
  /// 2^32 − 1 bytes).
  [[nodiscard]] constexpr result<step> download(od::address a, std::span<const std::uint8_t> data,
                                                std::uint32_t now,
                                                bool complete_access = false) noexcept {
    FIELDCODEC_TRY_STATUS(can_start(a, complete_access));
    FIELDCODEC_TRY(const sdo::step s, inner_.download(a, data, now));
    begin(a, complete_access);
    tx_ = data;
    const std::size_t cap = initiate_capacity(out_.size());
    if (!data.empty() && data.size() <= 4U && (!complete_access || data.size() > cap)) {
      // expedited, as the machine asks; with complete access only when a normal initiate
      // cannot hold the 1..4 bytes (a mailbox of 16..19 bytes): then with bit 4 set
      phase_ = phase::expedited_download;
      sdo::payload p = detail::sent(s).value_or(sdo::payload{});
      if (complete_access) p[0] = static_cast<std::uint8_t>(p[0] | complete_access_bit);
      return send_payload(p);
    }
    // a normal initiate: the complete size and as much of the value as fits (complete access
    // of 1..4 bytes goes this way too, as masters do: the machine's expedited state takes the
    // download response all the same)
    sent_ = tx_.size() < cap ? tx_.size() : cap;
    phase_ = phase::initiate_download;
    return send({.type = sdo::message_type::initiate_download_request,
                 .complete_access = complete_access,
                 .address = a,
                 .size = static_cast<std::uint32_t>(tx_.size()),
                 .data = tx_.first(sent_)});
  }

  /// Start reading `a` into `buffer` (borrowed until the transfer ends); complete_access as for
  /// download. Errors: bad_state, invalid_argument.
  [[nodiscard]] constexpr result<step> upload(od::address a, std::span<std::uint8_t> buffer,
                                              std::uint32_t now,
                                              bool complete_access = false) noexcept {
    FIELDCODEC_TRY_STATUS(can_start(a, complete_access));
    FIELDCODEC_TRY(const sdo::step s, inner_.upload(a, buffer, now));
    begin(a, complete_access);
    phase_ = phase::initiate_upload;
    sdo::payload p = detail::sent(s).value_or(sdo::payload{});
    if (complete_access) p[0] = static_cast<std::uint8_t>(p[0] | complete_access_bit);
    return send_payload(p);
  }

  /// Start writing `value` to entry `e` (an od::entry or od::descriptor of a fixed-size type):
  /// encoded by od::encode with the entry's type, field and limits (node-ID-relative limits for
  /// `node`), so nothing narrows or wraps. Errors: access_denied (read-only or constant),
  /// type_mismatch (a byte-string entry: write_bytes), those of od::encode and download.
  template <class E, od::value_type T>
  requires std::derived_from<E, od::entry>
  [[nodiscard]] constexpr result<step> write(const E &e, T value, std::uint32_t now,
                                             std::uint8_t node = od::any_node) noexcept {
    if (!od::writable(e.access_type)) return errc::access_denied;
    if (od::fixed_size(e.type) == 0U) return errc::type_mismatch;
    if (busy()) return errc::bad_state;
    FIELDCODEC_TRY(const std::size_t n, od::encode(e, value, value_, byte_order::little, node));
    return download({e.index, e.sub}, std::span<const std::uint8_t>(value_).first(n), now);
  }
  /// Start writing the bytes of a byte-string entry (VISIBLE_STRING, OCTET_STRING,
  /// UNICODE_STRING, DOMAIN), checked as od::decode_bytes checks them (capacity, characters,
  /// even length). `bytes` is borrowed until the transfer ends. Errors: access_denied,
  /// type_mismatch, too_long, bad_character, bad_length, those of download.
  [[nodiscard]] constexpr result<step>
  write_bytes(const od::entry &e, std::span<const std::uint8_t> bytes, std::uint32_t now) noexcept {
    if (!od::writable(e.access_type)) return errc::access_denied;
    FIELDCODEC_TRY_STATUS(od::decode_bytes(e, bytes));
    return download({e.index, e.sub}, bytes, now);
  }
  /// Start reading entry `e` of a fixed-size type into the client's own 8 bytes; value<T>(e)
  /// reads it when done. Errors: access_denied (write-only), type_mismatch (a byte-string
  /// entry: upload into a buffer of yours), those of upload.
  [[nodiscard]] constexpr result<step> read(const od::entry &e, std::uint32_t now) noexcept {
    if (!od::readable(e.access_type)) return errc::access_denied;
    if (od::fixed_size(e.type) == 0U) return errc::type_mismatch;
    return upload({e.index, e.sub}, value_, now);
  }
  /// The value read from `e` as a T (never narrowed: od::decode<T>, limits not checked — the
  /// device reports what it has). Errors: bad_state (no upload done), those of od::decode.
  template <od::value_type T, class E>
  requires std::derived_from<E, od::entry>
  [[nodiscard]] constexpr result<T> value(const E &e) const noexcept {
    if (inner_.state() != sdo::transfer_state::done || phase_ != phase::upload_done) {
      return errc::bad_state;
    }
    return od::decode<T>(e, received(), byte_order::little, od::limits::ignore);
  }

  /// Take a mailbox read from the slave's send mailbox (the whole SyncManager area or just the
  /// mailbox). See the top of this file for what is checked and what is left alone.
  [[nodiscard]] constexpr step on_mailbox(std::span<const std::uint8_t> bytes,
                                          std::uint32_t now) noexcept {
    refused_ = {};
    auto mb = decode(bytes);
    if (!mb) return unreadable(mb.error());
    const mailbox_header &h = mb.value().header;
    if (header_size + h.length > response_size_) return unreadable(errc::too_long);
    if (is_repeat(h.counter, in_counter_)) return refuse(errc::unexpected_frame);
    in_counter_ = h.counter;
    if (h.type == static_cast<std::uint8_t>(mailbox_type::error)) {
      if (!busy()) return refuse(errc::unexpected_frame);
      const auto e = decode_error_reply(mb.value());
      return fail(e ? to_errc(e.value()) : e.error(), sdo::abort_code::none, false);
    }
    if (h.type != static_cast<std::uint8_t>(mailbox_type::coe)) {
      return refuse(errc::unexpected_frame);
    }
    auto ch = decode_coe_header(mb.value().data);
    if (!ch) return unreadable(ch.error());
    const service svc = ch.value().svc;
    if (svc != service::sdo_request && svc != service::sdo_response) {
      return refuse(errc::unexpected_frame);
    }
    if (!busy()) return refuse(errc::unexpected_frame);
    const auto body = mb.value().data.subspan(coe_header_size);
    auto r = decode_sdo_body(body, sdo::direction::to_client);
    if (!r) return unreadable(r.error());
    const sdo_message &m = r.value();
    if (svc != service::sdo_response && m.type != sdo::message_type::abort) {
      return unreadable(errc::unexpected_frame);
    }
    now_ = now;
    switch (phase_) {
    case phase::initiate_download:
      if (m.type != sdo::message_type::initiate_download_response) break;
      if (auto s = feed(detail::head_of(body))) return *s; // the machine checks the object
      acked_ = sent_;
      coe_toggle_ = false;
      return advance_download();
    case phase::download_segment:
      if (m.type != sdo::message_type::download_segment_response) break;
      if (m.toggle != coe_toggle_) { // the machine's own toggle error: 0x05030000
        return after(feed_frame(sdo::download_segment_response(!seg_toggle_)));
      }
      coe_toggle_ = !coe_toggle_;
      acked_ = sent_;
      return advance_download();
    case phase::initiate_upload:
      if (m.type != sdo::message_type::initiate_upload_response || m.expedited) break;
      // normal: the machine checks object and size (its buffer), then asks for segments
      if (auto s = feed(detail::head_of(body))) return *s;
      coe_toggle_ = false;
      return take_upload(m.data, m.data.size() >= m.size);
    case phase::upload_segment:
      if (m.type != sdo::message_type::upload_segment_response) break;
      if (m.toggle != coe_toggle_) { // a segment with the toggle the machine does not expect
        return after(feed_frame(
            sdo::upload_segment(!request_toggle_, zeros7, false).value_or(sdo::payload{})));
      }
      coe_toggle_ = !coe_toggle_;
      return take_upload(m.data, m.last);
    default: break;
    }
    // anything else goes to the machine as the CAN message it is: an abort, an expedited
    // response, or a message that does not fit its state (its unexpected-frame abort)
    return after(feed_frame(detail::head_of(body)));
  }

  /// Check the timeout: the machine's abort 0x05040000, error timeout.
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    now_ = now;
    return after(inner_.poll(now));
  }
  /// Abort the running transfer from the application side: error aborted with `code`.
  [[nodiscard]] constexpr step
  cancel(sdo::abort_code code = sdo::abort_code::general_error) noexcept {
    return after(inner_.cancel(code));
  }

  [[nodiscard]] constexpr sdo::transfer_state state() const noexcept { return inner_.state(); }
  [[nodiscard]] constexpr bool busy() const noexcept { return inner_.busy(); }
  /// Why the last transfer failed ({errc, abort code, object}); empty otherwise.
  [[nodiscard]] constexpr std::optional<sdo::transfer_error> error() const noexcept {
    return local_error_ ? local_error_ : inner_.error();
  }
  /// Why the last mailbox given to on_mailbox was not taken (empty: it was taken).
  [[nodiscard]] constexpr status refused() const noexcept { return refused_; }
  /// The bytes uploaded (the value once state() == done).
  [[nodiscard]] constexpr std::span<const std::uint8_t> received() const noexcept {
    return inner_.received();
  }
  /// Bytes transferred so far. A download counts the bytes the slave confirmed.
  [[nodiscard]] constexpr std::size_t transferred() const noexcept {
    return phase_ == phase::initiate_download || phase_ == phase::download_segment
               ? acked_
               : inner_.transferred();
  }
  /// When the running transfer times out; empty when idle.
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline() const noexcept {
    return inner_.deadline();
  }
  /// The last mailbox sent (for a repeat request), empty before the first.
  [[nodiscard]] constexpr std::span<const std::uint8_t> last_sent() const noexcept {
    return std::span<const std::uint8_t>(out_).first(last_size_);
  }

private:
  enum class phase : std::uint8_t {
    idle,
    expedited_download,
    initiate_download,
    download_segment,
    initiate_upload,
    upload_segment,
    upload_done,
  };
  static constexpr std::array<std::uint8_t, 7> zeros7{};

  [[nodiscard]] constexpr status can_start(od::address a, bool complete_access) const noexcept {
    if (inner_.busy()) return errc::bad_state;
    if (out_.size() < min_sdo_mailbox || response_size_ < min_sdo_mailbox) {
      return errc::invalid_argument;
    }
    if (complete_access && a.sub > 1U) return errc::invalid_argument;
    return {};
  }
  constexpr void begin(od::address a, bool complete_access) noexcept {
    address_ = a;
    complete_access_ = complete_access;
    local_error_.reset();
    tx_ = {};
    sent_ = 0;
    acked_ = 0;
    inner_off_ = 0;
    have_segment_ = false;
    carry_.clear();
  }
  [[nodiscard]] constexpr step make(std::span<const std::uint8_t> send = {}) const noexcept {
    return step{send, inner_.state(), inner_.deadline()};
  }
  /// Send `m` as the next mailbox.
  [[nodiscard]] constexpr step send(const sdo_message &m) noexcept {
    counter_ = next_counter(counter_);
    // cannot fail: the adapter sizes every message for the mailbox
    last_size_ = encode_sdo(out_, counter_, options_, m).value_or(0U);
    return make(last_sent());
  }
  [[nodiscard]] constexpr step send_payload(const sdo::payload &p) noexcept {
    counter_ = next_counter(counter_);
    last_size_ = detail::write_payload(out_, counter_, options_, p, false).value_or(0U);
    return make(last_sent());
  }
  [[nodiscard]] constexpr step refuse(errc e) noexcept {
    refused_ = e;
    return make();
  }
  /// A mailbox that cannot be read: the transfer fails with `e` (when one runs).
  [[nodiscard]] constexpr step unreadable(errc e) noexcept {
    refused_ = e;
    if (!busy()) return make();
    return fail(e,
                e == errc::unknown_command || e == errc::unexpected_frame
                    ? sdo::abort_code::unknown_command
                    : sdo::abort_code::general_error,
                true);
  }
  /// End the transfer with `e`; the machine's abort with `code` is sent when `abort`.
  [[nodiscard]] constexpr step fail(errc e, sdo::abort_code code, bool abort) noexcept {
    local_error_ = sdo::transfer_error{e, code, address_};
    const sdo::step s =
        inner_.cancel(code == sdo::abort_code::none ? sdo::abort_code::general_error : code);
    phase_ = phase::idle;
    if (!abort) return make();
    return after(s);
  }

  /// Feed the machine a response from the slave.
  [[nodiscard]] constexpr sdo::step feed_frame(const sdo::payload &p) noexcept {
    return inner_.on_frame(can_frame{detail::inner_channel.response_id, false, 8, p}, now_);
  }
  /// Feed it a message that should move it on: the step to return when it did not (it aborted
  /// or ended), nothing when it asks for more (its request is recorded).
  [[nodiscard]] constexpr std::optional<step> feed(const sdo::payload &p) noexcept {
    const sdo::step s = feed_frame(p);
    const auto out = detail::sent(s);
    if (!out || (*out)[0] == 0x80U || !inner_.busy()) return after(s);
    record(*out);
    return std::nullopt;
  }
  /// What the machine asked for next: a download segment or an upload segment request.
  constexpr void record(const sdo::payload &p) noexcept {
    const auto m = sdo::decode(p, sdo::direction::to_server);
    if (!m) return;
    if (m.value().type == sdo::message_type::download_segment_request) {
      seg_off_ = inner_off_;
      seg_len_ = m.value().data_size;
      seg_toggle_ = m.value().toggle;
      inner_off_ += seg_len_;
      have_segment_ = true;
    } else if (m.value().type == sdo::message_type::upload_segment_request) {
      request_toggle_ = m.value().toggle;
    }
  }
  /// The step after the machine's step `s`: its abort as a mailbox, or nothing to send.
  [[nodiscard]] constexpr step after(const sdo::step &s) noexcept {
    if (!inner_.busy()) {
      phase_ = inner_.state() == sdo::transfer_state::done &&
                       (phase_ == phase::initiate_upload || phase_ == phase::upload_segment)
                   ? phase::upload_done
                   : phase::idle;
    }
    const auto out = detail::sent(s);
    if (out && (*out)[0] == 0x80U) return send_payload(*out);
    return make();
  }

  /// Confirm to the machine every segment the slave has taken, then send the next part.
  [[nodiscard]] constexpr step advance_download() noexcept {
    while (inner_.busy() && have_segment_ && seg_off_ + seg_len_ <= acked_) {
      have_segment_ = false;
      if (auto s = feed(sdo::download_segment_response(seg_toggle_))) return *s;
    }
    if (!inner_.busy()) return make();
    // the machine's current segment reaches past what the slave has: the next CoE segment
    const std::size_t cap = segment_capacity(out_.size());
    const std::size_t n = tx_.size() - acked_ < cap ? tx_.size() - acked_ : cap;
    sent_ = acked_ + n;
    phase_ = phase::download_segment;
    return send({.type = sdo::message_type::download_segment_request,
                 .toggle = coe_toggle_,
                 .last = sent_ == tx_.size(),
                 .data = tx_.subspan(acked_, n)});
  }

  /// Give the machine the bytes of a normal upload response or an upload segment as 7-byte
  /// segments (the last of the transfer when `final`); keep a short rest for the next mailbox.
  [[nodiscard]] constexpr step take_upload(std::span<const std::uint8_t> data,
                                           bool final) noexcept {
    std::optional<step> stop;
    detail::give_segments(carry_, data, final, [&](std::span<const std::uint8_t> seg, bool last) {
      const auto p = sdo::upload_segment(request_toggle_, seg, last).value_or(sdo::payload{});
      stop = feed(p);
      return !stop;
    });
    if (stop) return *stop;
    if (!inner_.busy()) return make();
    phase_ = phase::upload_segment;
    return send({.type = sdo::message_type::upload_segment_request, .toggle = coe_toggle_});
  }

  std::span<std::uint8_t> out_;
  std::size_t response_size_;
  mailbox_options options_;
  sdo::client inner_;
  std::uint32_t now_ = 0;
  std::size_t last_size_ = 0;
  std::uint8_t counter_ = 0;
  std::uint8_t in_counter_ = 0;
  phase phase_ = phase::idle;
  bool complete_access_ = false;
  bool coe_toggle_ = false;
  bool have_segment_ = false;
  bool seg_toggle_ = false;
  bool request_toggle_ = false;
  od::address address_{};
  std::optional<sdo::transfer_error> local_error_{};
  status refused_{};
  std::span<const std::uint8_t> tx_{};
  std::size_t sent_ = 0;  ///< download: bytes put into mailboxes
  std::size_t acked_ = 0; ///< download: bytes the slave confirmed
  std::size_t inner_off_ = 0;
  std::size_t seg_off_ = 0;
  std::size_t seg_len_ = 0;
  detail::carry carry_{};
  std::array<std::uint8_t, 8> value_{};
};

} // namespace fieldcodec::canopen::coe
