// fieldcodec — an SDO server over CoE: the CiA 301 server machine (canopen/sdo_server.hpp)
// serving an object store through EtherCAT mailboxes.
//
// For EtherCAT slave firmware that reads its receive mailbox (SM0) and writes its send mailbox
// (SM1): the SDO server of a CANopen node, with the same store, the same checks and the same
// abort codes, answering CoE SDO requests.
//
//   std::array<std::uint8_t, 128> sm1;                  // the send mailbox (SM1) size
//   coe::sdo_server<Store> s(store, buffer, sm1, 128);  // SM0 size: the longest request
//   // for every mailbox read from SM0, and when the deadline passes:
//   auto t = s.on_mailbox(read_sm0(), now);             // or s.poll(now)
//   if (!t.send.empty()) write_sm1(t.send);
//
// Answers (ETG.1000.6 5.6.2): an upload of 1..4 bytes expedited; a larger value normal — the
// complete size and as much of the value as the send mailbox holds — then segments of the send
// mailbox's size as the client asks for them. Downloads are taken expedited, normal, or normal
// with segments of any size up to the receive mailbox. The machine inside sees the transfer
// as CAN messages (coe/sdo_transfer.hpp), so the store is written in parts and read in parts
// exactly as on CAN, and every abort code is the machine's or the store's.
// What the adapter answers itself:
// * a mailbox it cannot take gets a mailbox error reply (mailbox type 0) and refused() says
//   why: truncated (size too short), bad_length / too_long (length field disagreeing with the
//   bytes, longer than the receive mailbox, an SDO message of the wrong length: invalid size),
//   unknown_command (another mailbox type: unsupported protocol; a CoE service other than SDO
//   request: service not supported — route SDO information and PDOs elsewhere first); the
//   running transfer is not touched, as a CAN frame of the wrong length is not;
// * block transfer and command specifier 7 (no CoE commands): abort 0x05040001;
// * complete access (bit 4 of an initiate): abort 0x06010004 (not supported by this server),
//   refused() says access_denied, a running transfer goes on;
// * the toggle of CoE segments: a repeated toggle is the machine's toggle error (0x05030000);
// * repeated mailboxes (mailbox counter, coe/sdo_transfer.hpp): dropped, refused() says
//   unexpected_frame.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/coe/mailbox.hpp>
#include <fieldcodec/canopen/coe/sdo.hpp>
#include <fieldcodec/canopen/coe/sdo_transfer.hpp>
#include <fieldcodec/canopen/coe/service.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::coe {

template <canopen::object_store Store>
class sdo_server {
public:
  /// A server over `store` with the machine's `buffer` (both borrowed; see sdo::server), that
  /// writes its answers into `response_mailbox` (borrowed; its size is the send mailbox size,
  /// SM1) and takes requests of up to `request_size` bytes (the receive mailbox size, SM0).
  /// Both mailboxes must have at least 16 bytes: with a smaller one every SDO request is
  /// refused (invalid size).
  constexpr sdo_server(Store &store, std::span<std::uint8_t> buffer,
                       std::span<std::uint8_t> response_mailbox, std::size_t request_size,
                       std::uint32_t timeout_ms = 1000, mailbox_options o = {}) noexcept
      : out_(response_mailbox), request_size_(request_size), options_(o),
        inner_(detail::inner_channel, store, buffer, timeout_ms, {.block = false, .crc = false}) {}

  /// Take a mailbox read from the receive mailbox (the whole SyncManager area or the mailbox).
  [[nodiscard]] constexpr step on_mailbox(std::span<const std::uint8_t> bytes,
                                          std::uint32_t now) noexcept {
    refused_ = {};
    now_ = now;
    auto mb = decode(bytes);
    if (!mb) return refuse(mb.error());
    const mailbox_header &h = mb.value().header;
    if (header_size + h.length > request_size_) return refuse(errc::too_long);
    if (is_repeat(h.counter, in_counter_)) {
      refused_ = errc::unexpected_frame;
      return make();
    }
    in_counter_ = h.counter;
    if (h.type != static_cast<std::uint8_t>(mailbox_type::coe)) {
      return refuse(errc::unknown_command, mailbox_error::unsupported_protocol);
    }
    auto ch = decode_coe_header(mb.value().data);
    if (!ch) {
      return refuse(ch.error(), ch.error() == errc::truncated
                                    ? mailbox_error::size_too_short
                                    : mailbox_error::service_not_supported);
    }
    if (ch.value().svc != service::sdo_request) {
      return refuse(errc::unknown_command, mailbox_error::service_not_supported);
    }
    if (out_.size() < min_sdo_mailbox) return refuse(errc::invalid_argument);
    const auto body = mb.value().data.subspan(coe_header_size);
    const sdo::payload head = detail::head_of(body);
    const unsigned ccs = head[0] >> 5U;
    auto r = decode_sdo_body(body, sdo::direction::to_server);
    if (!r && r.error() == errc::unknown_command) {
      // block transfer or command specifier 7: the machine's own unknown-command abort
      sdo::payload p = head;
      p[0] = 0xE0;
      return reply(feed(p));
    }
    if ((ccs == 1U || ccs == 2U) && body.size() >= sdo_header_size &&
        (head[0] & complete_access_bit) != 0U) {
      return complete_access_refused(head);
    }
    if (!r) return refuse(r.error());
    const sdo_message &m = r.value();
    switch (m.type) {
    case sdo::message_type::initiate_download_request:
      carry_.clear();
      if (m.expedited) return reply(feed(head));
      return initiate_download(m);
    case sdo::message_type::download_segment_request:
      if (phase_ != phase::download_segments) break;
      if (m.toggle != coe_toggle_) { // the machine's own toggle error: 0x05030000
        return reply(feed(sdo::download_segment(!can_toggle_, zeros7, false).value_or(head)));
      }
      return download_segment(m);
    case sdo::message_type::initiate_upload_request: return initiate_upload(head);
    case sdo::message_type::upload_segment_request:
      if (phase_ != phase::upload_segments) break;
      if (m.toggle != coe_toggle_) {
        return reply(feed(sdo::upload_segment_request(!can_toggle_)));
      }
      return upload_segment(m);
    default: break;
    }
    // an abort, or a segment out of place: to the machine as it is
    return reply(feed(head));
  }

  /// Abort a transfer whose client went silent (0x05040000, error timeout).
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    now_ = now;
    return reply(inner_.poll(now));
  }

  [[nodiscard]] constexpr sdo::transfer_state state() const noexcept { return inner_.state(); }
  [[nodiscard]] constexpr bool busy() const noexcept { return inner_.busy(); }
  /// Why the last transfer failed, or why the last SDO request was refused (the machine's
  /// error); empty otherwise.
  [[nodiscard]] constexpr std::optional<sdo::transfer_error> error() const noexcept {
    return inner_.error();
  }
  /// Why the last mailbox given to on_mailbox was not taken (empty: it was taken).
  [[nodiscard]] constexpr status refused() const noexcept { return refused_; }
  /// When the running transfer times out; empty when idle.
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline() const noexcept {
    return inner_.deadline();
  }
  /// The last mailbox sent (for a repeat request), empty before the first.
  [[nodiscard]] constexpr std::span<const std::uint8_t> last_sent() const noexcept {
    return std::span<const std::uint8_t>(out_).first(last_size_);
  }

private:
  enum class phase : std::uint8_t { idle, download_segments, upload_segments };
  static constexpr std::array<std::uint8_t, 7> zeros7{};

  [[nodiscard]] constexpr step make(std::span<const std::uint8_t> send = {}) const noexcept {
    return step{send, inner_.state(), inner_.deadline()};
  }
  [[nodiscard]] constexpr step sent(result<std::size_t> n) noexcept {
    last_size_ = n.value_or(0U); // cannot fail: every answer is sized for the mailbox
    return make(last_sent());
  }
  /// Refuse a mailbox with a mailbox error reply (the detail that goes with `e` unless given).
  [[nodiscard]] constexpr step refuse(errc e,
                                      std::optional<mailbox_error> detail = std::nullopt) noexcept {
    refused_ = e;
    const mailbox_error d = detail                 ? *detail
                            : e == errc::truncated ? mailbox_error::size_too_short
                                                   : mailbox_error::invalid_size;
    counter_ = next_counter(counter_);
    return sent(encode_error_reply(out_, counter_, options_, d));
  }
  /// Feed the machine a request; returns its step.
  [[nodiscard]] constexpr sdo::step feed(const sdo::payload &p) noexcept {
    return inner_.on_frame(can_frame{detail::inner_channel.request_id, false, 8, p}, now_);
  }
  /// The machine's answer as a mailbox (nothing when it answered nothing).
  [[nodiscard]] constexpr step reply(const sdo::step &s) noexcept {
    const auto p = detail::sent(s);
    if (!inner_.busy()) {
      phase_ = phase::idle;
      carry_.clear();
    }
    if (!p) return make();
    counter_ = next_counter(counter_);
    return sent(detail::write_payload(out_, counter_, options_, *p, true));
  }
  [[nodiscard]] constexpr step send(const sdo_message &m) noexcept {
    counter_ = next_counter(counter_);
    return sent(encode_sdo(out_, counter_, options_, m));
  }
  /// The machine's answer when it is an abort (the step to return), nothing otherwise.
  [[nodiscard]] constexpr std::optional<step> aborted(const sdo::step &s) noexcept {
    const auto p = detail::sent(s);
    if (p && (*p)[0] == 0x80U) return reply(s);
    if (!p && !inner_.busy() && inner_.state() == sdo::transfer_state::failed) return reply(s);
    return std::nullopt;
  }

  /// Complete access is not served: abort 0x06010004, refused() access_denied; the machine
  /// (and a transfer it runs) is not touched.
  [[nodiscard]] constexpr step complete_access_refused(const sdo::payload &head) noexcept {
    refused_ = errc::access_denied;
    counter_ = next_counter(counter_);
    return sent(detail::write_payload(
        out_, counter_, options_,
        sdo::abort(sdo::detail::get_address(head), sdo::abort_code::complete_access_unsupported),
        true));
  }

  // ----- download: the mailbox's bytes go to the machine as 7-byte segments --------------

  [[nodiscard]] constexpr step initiate_download(const sdo_message &m) noexcept {
    if (auto s = aborted(feed(sdo::initiate_download(m.address, m.size)))) return *s;
    can_toggle_ = false;
    coe_toggle_ = false;
    address_ = m.address;
    const bool final = m.data.size() >= m.size;
    if (auto s = give(m.data, final)) return *s;
    if (!final) phase_ = phase::download_segments;
    return send({.type = sdo::message_type::initiate_download_response, .address = m.address});
  }
  [[nodiscard]] constexpr step download_segment(const sdo_message &m) noexcept {
    if (auto s = give(m.data, m.last)) return *s;
    coe_toggle_ = !coe_toggle_;
    if (m.last) phase_ = phase::idle;
    return send({.type = sdo::message_type::download_segment_response, .toggle = m.toggle});
  }
  /// Give the machine `data` (after the bytes carried over) as 7-byte segments, the last of
  /// the transfer when `final`; keep a short rest for the next mailbox. Returns the abort step
  /// when the machine aborted.
  [[nodiscard]] constexpr std::optional<step> give(std::span<const std::uint8_t> data,
                                                   bool final) noexcept {
    std::optional<step> stop;
    detail::give_segments(carry_, data, final, [&](std::span<const std::uint8_t> seg, bool last) {
      const auto p = sdo::download_segment(can_toggle_, seg, last).value_or(sdo::payload{});
      stop = aborted(feed(p));
      can_toggle_ = !can_toggle_;
      return !stop;
    });
    return stop;
  }

  // ----- upload: the machine's 7-byte segments fill mailboxes -----------------------------

  [[nodiscard]] constexpr step initiate_upload(const sdo::payload &head) noexcept {
    carry_.clear();
    const sdo::step s = feed(head);
    const auto p = detail::sent(s);
    if (!p || (*p)[0] == 0x80U || !inner_.busy()) return reply(s); // an abort, expedited
    // a segmented upload on CAN: its size, then as much of the value as the mailbox holds
    const auto m = sdo::decode(*p, sdo::direction::to_client);
    if (!m) return reply(s);
    address_ = m.value().address;
    size_ = m.value().size;
    placed_ = 0;
    last_taken_ = false;
    can_toggle_ = false;
    coe_toggle_ = false;
    const std::size_t offset = header_size + coe_header_size + sdo_header_size;
    FIELDCODEC_TRY(const std::size_t n, fill(offset, initiate_capacity(out_.size())));
    if (!last_taken_ || carry_.size() != 0U) phase_ = phase::upload_segments;
    return send({.type = sdo::message_type::initiate_upload_response,
                 .address = address_,
                 .size = size_,
                 .data = std::span<const std::uint8_t>(out_).subspan(offset, n)});
  }
  [[nodiscard]] constexpr step upload_segment(const sdo_message &m) noexcept {
    const std::size_t offset = header_size + coe_header_size + 1U;
    FIELDCODEC_TRY(const std::size_t n, fill(offset, segment_capacity(out_.size())));
    const bool last = last_taken_ && carry_.size() == 0U;
    coe_toggle_ = !coe_toggle_;
    if (last) phase_ = phase::idle;
    return send({.type = sdo::message_type::upload_segment_response,
                 .toggle = m.toggle,
                 .last = last,
                 .data = std::span<const std::uint8_t>(out_).subspan(offset, n)});
  }
  /// Collect up to `room` bytes of the value into the mailbox buffer at `offset` (the bytes
  /// carried over first, then the machine's segments; what does not fit is carried over). The
  /// data land where encode_sdo puts them, so encoding copies them onto themselves. Returns the
  /// bytes collected, or the abort step.
  [[nodiscard]] constexpr result<std::size_t, step> fill(std::size_t offset,
                                                         std::size_t room) noexcept {
    std::size_t n = 0;
    const auto put = [&](std::span<const std::uint8_t> b) noexcept {
      const std::size_t k = b.size() < room - n ? b.size() : room - n;
      for (std::size_t i = 0; i < k; ++i) out_[offset + n + i] = b[i];
      n += k;
      placed_ += k;
      return k;
    };
    const std::size_t from_carry = put(carry_.bytes());
    carry_.drop(from_carry);
    // the machine's last segment is fetched even when nothing is left to place (a value of 0
    // bytes, or one that ends exactly at the end of a mailbox)
    while (!last_taken_ && carry_.size() == 0U && (n < room || placed_ == size_)) {
      const sdo::step s = feed(sdo::upload_segment_request(can_toggle_));
      const auto p = detail::sent(s);
      if (!p || (*p)[0] == 0x80U) return result<std::size_t, step>(unexpect, reply(s));
      const auto seg = sdo::decode(*p, sdo::direction::to_client);
      if (!seg || seg.value().type != sdo::message_type::upload_segment_response) {
        return result<std::size_t, step>(unexpect, reply(s));
      }
      can_toggle_ = !can_toggle_;
      last_taken_ = seg.value().last;
      const auto bytes = seg.value().bytes();
      carry_.append(bytes.subspan(put(bytes)));
    }
    return n;
  }

  std::span<std::uint8_t> out_;
  std::size_t request_size_;
  mailbox_options options_;
  sdo::server<Store> inner_;
  std::uint32_t now_ = 0;
  std::size_t last_size_ = 0;
  std::uint8_t counter_ = 0;
  std::uint8_t in_counter_ = 0;
  phase phase_ = phase::idle;
  bool coe_toggle_ = false;
  bool can_toggle_ = false;
  bool last_taken_ = false;
  status refused_{};
  od::address address_{};
  std::uint32_t size_ = 0; ///< upload: the value's size
  std::size_t placed_ = 0; ///< upload: bytes put into mailboxes
  detail::carry carry_{};
};

} // namespace fieldcodec::canopen::coe
