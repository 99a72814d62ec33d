// fieldcodec — what the CoE SDO adapters (coe/sdo_client.hpp, coe/sdo_server.hpp) share: the
// step they return, and how they carry the 8-byte messages of the CiA 301 SDO machines.
//
// The adapters run the existing SDO machines (canopen/sdo_client.hpp, sdo_server.hpp)
// unchanged: every CoE SDO mailbox is translated into the CAN messages the machine would have
// seen for the same transfer (one initiate, then 7-byte segments), and what the machine answers
// is translated back into mailboxes of the configured size. So the checks of a CoE transfer —
// object, sizes, toggles, abort codes, timeouts, the store's answers — are the CAN machines'
// own. The machines talk over an internal channel that never reaches a bus.
//
// Mailbox counter (decided here; ETG.1000.6 leaves the receiver's use of it open):
// * every new mailbox an adapter sends gets the next counter, 1, 2, …, 7, 1, …;
// * a received mailbox with the same non-zero counter as the one received before is a repeat
//   (the sender wrote it again because it saw no confirmation) and is dropped: no answer, the
//   transfer does not move, refused() says unexpected_frame; counter 0 ("not used") is never a
//   repeat;
// * a mailbox that was sent but not read (the master's read failed and it toggles the
//   SyncManager's repeat request) is sent again as it was: last_sent() keeps its bytes, counter
//   included, until the adapter sends the next one.
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/coe/mailbox.hpp>
#include <fieldcodec/canopen/coe/sdo.hpp>
#include <fieldcodec/canopen/coe/service.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_transfer.hpp>
#include <fieldcodec/core/result.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::canopen::coe {

/// What every call into a CoE SDO adapter returns: the mailbox to send (at most one: CoE SDO is
/// one request, one response), the transfer's state, and when to poll at the latest. `send`
/// points into the adapter's mailbox buffer and stays valid until the adapter sends the next
/// mailbox.
struct step {
  std::span<const std::uint8_t> send{};
  sdo::transfer_state state = sdo::transfer_state::idle;
  std::optional<std::uint32_t> deadline{};
};

namespace detail {

/// The channel the adapted machines talk over (internal: never on a bus).
inline constexpr sdo::channel inner_channel{0x601, 0x581};

/// Write the 8 bytes of a CiA 301 SDO message `p` as a CoE SDO mailbox: an SDO request unless
/// `response` (an abort is always a request, ETG.1000.6 5.6.2.7). Returns the bytes written.
[[nodiscard]] constexpr result<std::size_t>
write_payload(std::span<std::uint8_t> out, std::uint8_t counter, const mailbox_options &o,
              const sdo::payload &p, bool response) noexcept {
  const bool abort = (p[0] & 0xE0U) == 0x80U;
  const coe_header h{0, response && !abort ? service::sdo_response : service::sdo_request};
  FIELDCODEC_TRY(const std::span<std::uint8_t> body,
                 write_coe_header(out, counter, o, h, sdo_header_size));
  for (std::size_t i = 0; i < sdo_header_size; ++i) body[i] = p[i];
  return header_size + coe_header_size + sdo_header_size;
}

/// The first 8 bytes of an SDO body (zeros past its end).
[[nodiscard]] constexpr sdo::payload head_of(std::span<const std::uint8_t> body) noexcept {
  sdo::payload p{};
  for (std::size_t i = 0; i < sdo_header_size && i < body.size(); ++i) p[i] = body[i];
  return p;
}

/// The 8 bytes of the (only) frame of a machine's step, if it sent one.
[[nodiscard]] constexpr std::optional<sdo::payload> sent(const sdo::step &s) noexcept {
  if (s.send.empty()) return std::nullopt;
  return s.send[0].data;
}

/// Carries the bytes of a 7-byte segment that did not fit a mailbox (at most 6) to the next.
class carry {
public:
  [[nodiscard]] constexpr std::size_t size() const noexcept { return n_; }
  [[nodiscard]] constexpr std::span<const std::uint8_t> bytes() const noexcept {
    return std::span<const std::uint8_t>(b_).first(n_);
  }
  constexpr void clear() noexcept { n_ = 0; }
  /// Append `s` (the caller keeps the total at 7 bytes or fewer).
  constexpr void append(std::span<const std::uint8_t> s) noexcept {
    for (std::size_t i = 0; i < s.size() && n_ < b_.size(); ++i) b_[n_++] = s[i];
  }
  /// Remove the first `k` bytes.
  constexpr void drop(std::size_t k) noexcept {
    if (k >= n_) {
      n_ = 0;
      return;
    }
    for (std::size_t i = k; i < n_; ++i) b_[i - k] = b_[i];
    n_ -= k;
  }

private:
  std::array<std::uint8_t, 7> b_{};
  std::size_t n_ = 0;
};

/// Give the bytes carried over and then `data` to `take(segment, last)` as the 7-byte segments
/// of a CAN transfer: when `final`, all of them (the last one, of 0..7 bytes, marked last);
/// otherwise the whole ones, the rest (fewer than 7 bytes) kept in `c` for the next mailbox.
/// `take` returns false to stop (the machine aborted or ended): nothing more is given or kept.
template <class Take>
constexpr void give_segments(carry &c, std::span<const std::uint8_t> data, bool final,
                             Take take) noexcept {
  std::size_t at = 0;
  for (;;) {
    const std::size_t avail = c.size() + (data.size() - at);
    if (!final && avail < 7U) break;
    std::array<std::uint8_t, 7> chunk{};
    std::size_t n = 0;
    for (const std::uint8_t b : c.bytes()) chunk[n++] = b;
    c.clear();
    while (n < 7U && at < data.size()) chunk[n++] = data[at++];
    const bool last = final && avail <= 7U;
    if (!take(std::span<const std::uint8_t>(chunk).first(n), last) || last) return;
  }
  c.append(data.subspan(at));
}

} // namespace detail

} // namespace fieldcodec::canopen::coe
