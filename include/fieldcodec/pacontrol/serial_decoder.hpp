// fieldcodec — byte-at-a-time decoder for PA-CONTROL RS232 frames, for a receive interrupt.
//
// push() takes one received byte and says whether a frame ended with it. The decoder owns a
// fixed buffer (max_body_chars), never allocates, never writes past it, and recovers by
// itself: after any error it drops the bytes received so far and waits for the next SOH (an
// SOH inside a frame ends the broken frame and starts the new one at once).
//
// A lone EOT between frames is the poll command. An EOT that ends a run of garbage (for
// example the tail of a frame whose SOH was lost) only ends the garbage; it is not a poll.
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::pacontrol::serial {

/// What push() completed.
enum class frame_kind : std::uint8_t {
  none,            ///< no frame ended with this byte (more bytes needed, or skipped noise)
  request,         ///< request() holds it
  acknowledgement, ///< acknowledgement() holds it
  poll,            ///< a lone EOT
};

/// Which frames the receiver expects.
enum class accept : std::uint8_t {
  any,              ///< requests, polls and acknowledgements (a line monitor)
  requests,         ///< requests and polls (the PA-CONTROL side); acknowledgements are errors
  acknowledgements, ///< acknowledgements (the master side); requests and polls are errors
};

/// Check rules per direction and the meaning of CHECK "0".
struct check_options {
  check_rule request = check_rule::body;
  check_rule acknowledgement = check_rule::body_and_etx;
  /// CHECK "0" passes without a check (the manual allows "0" instead of the sum). When false,
  /// "0" must equal the computed check like any other value.
  bool zero_means_unchecked = true;
  /// Accept an acknowledgement whose CHECK matches either rule, `body` or `body_and_etx` (the
  /// manual's own acknowledgements mix them: 3.4.3 command 1 uses `body`, docs/errata.md).
  bool acknowledgement_either_rule = false;
  /// The same for requests.
  bool request_either_rule = false;
};

struct decoder_options {
  check_options check{};
  accept frames = accept::any;
};

class decoder {
public:
  constexpr decoder() noexcept = default;
  constexpr explicit decoder(decoder_options options) noexcept : options_(options) {}

  /// Feeds one byte.
  /// Returns the kind of frame this byte completed (frame_kind::none while incomplete), or the
  /// error that made the decoder drop the frame in progress:
  ///  * truncated        – SOH or EOT arrived before the frame was complete (frame cut short);
  ///                       an SOH also starts the next frame;
  ///  * bad_syntax       – a byte other than SOH/EOT between frames (reported once per run of
  ///                       noise), SOH not followed by STX, STX or ETX in the wrong place,
  ///                       empty CHECK, empty field;
  ///  * bad_character    – a control byte or a byte >= 0x7F inside a frame;
  ///  * too_long         – a field longer than max_field_chars, CHECK longer than 3 digits;
  ///  * bad_length       – more than 6 fields, or a field count that is neither 4 nor 6,
  ///                       CMD not 4 characters;
  ///  * bad_digit / bad_sign / overflow / out_of_range / type_mismatch – a field's content
  ///                       (see parse_request_body); bad_digit also for a non-digit in CHECK;
  ///  * out_of_range     – CHECK above 255;
  ///  * bad_checksum     – CHECK does not match the body under the direction's rule;
  ///  * unexpected_frame – a frame or poll the options do not accept.
  constexpr result<frame_kind> push(std::uint8_t b) noexcept {
    if (state_ == state::body) return on_body(b); // most bytes: one test, not a jump table
    switch (state_) {
    case state::idle: return on_idle(b);
    case state::hunting: return on_hunting(b);
    case state::after_soh: return on_after_soh(b);
    case state::body: return on_body(b);
    case state::check: return on_check(b);
    }
    return drop(errc::bad_syntax, state::hunting);
  }

  /// Feeds bytes until one completes a frame or fails; `consumed` tells how many were used.
  /// Returns frame_kind::none when all bytes were consumed without completing a frame.
  constexpr result<frame_kind> push(std::span<const std::uint8_t> bytes,
                                    std::size_t &consumed) noexcept {
    consumed = 0;
    while (consumed < bytes.size()) {
      auto r = push(bytes[consumed++]);
      if (!r || r.value() != frame_kind::none) return r;
    }
    return frame_kind::none;
  }

  /// The last request completed (valid after push() returned frame_kind::request).
  [[nodiscard]] constexpr const serial::request &request() const noexcept { return request_; }
  /// The last acknowledgement completed.
  [[nodiscard]] constexpr const serial::acknowledgement &acknowledgement() const noexcept {
    return acknowledgement_;
  }
  /// True between frames (not inside a frame and not skipping noise).
  [[nodiscard]] constexpr bool idle() const noexcept { return state_ == state::idle; }
  /// Forgets any partial frame.
  constexpr void reset() noexcept {
    state_ = state::idle;
    len_ = 0;
  }

private:
  enum class state : std::uint8_t { idle, hunting, after_soh, body, check };

  constexpr result<frame_kind> drop(errc e, state next) noexcept {
    state_ = next;
    len_ = 0;
    return e;
  }
  constexpr void start_frame() noexcept {
    state_ = state::after_soh;
    len_ = 0;
    fields_ = 1;
    field_start_ = 0;
    xor_ = 0;
    check_len_ = 0;
    check_value_ = 0;
  }

  constexpr result<frame_kind> on_idle(std::uint8_t b) noexcept {
    if (b == soh) {
      start_frame();
      return frame_kind::none;
    }
    if (b == eot) {
      if (options_.frames == accept::acknowledgements) return errc::unexpected_frame;
      return frame_kind::poll;
    }
    return drop(errc::bad_syntax, state::hunting);
  }

  constexpr result<frame_kind> on_hunting(std::uint8_t b) noexcept {
    if (b == soh) start_frame();
    if (b == eot) state_ = state::idle; // end of the noise, not a poll
    return frame_kind::none;
  }

  /// SOH or EOT inside a frame: the frame was cut short.
  constexpr result<frame_kind> cut(std::uint8_t b) noexcept {
    if (b == soh) {
      start_frame();
      return errc::truncated;
    }
    return drop(errc::truncated, state::idle);
  }

  constexpr result<frame_kind> on_after_soh(std::uint8_t b) noexcept {
    if (b == stx) {
      state_ = state::body;
      return frame_kind::none;
    }
    if (b == soh || b == eot) return cut(b);
    return drop(errc::bad_syntax, state::hunting);
  }

  constexpr result<frame_kind> on_body(std::uint8_t b) noexcept {
    // The usual byte first: printable and not a separator (control bytes are all below 0x20).
    if (b >= 0x20U && b < 0x7FU && b != static_cast<std::uint8_t>(separator)) {
      if (len_ - field_start_ >= max_field_chars) return drop(errc::too_long, state::hunting);
      xor_ = static_cast<std::uint8_t>(xor_ ^ b);
      body_[len_++] = static_cast<char>(b); // len_ < max_body_chars: fields and lengths bounded
      return frame_kind::none;
    }
    if (b == soh || b == eot) return cut(b);
    if (b == etx) {
      state_ = state::check;
      return frame_kind::none;
    }
    if (b == stx) return drop(errc::bad_syntax, state::hunting);
    if (b < 0x20U || b >= 0x7FU) return drop(errc::bad_character, state::hunting);
    // a separator: the body is split while it arrives
    if (fields_ == acknowledgement_fields) return drop(errc::bad_length, state::hunting);
    field_end_[fields_ - 1U] = static_cast<std::uint8_t>(len_);
    ++fields_;
    field_start_ = len_ + 1U;
    xor_ = static_cast<std::uint8_t>(xor_ ^ b);
    body_[len_++] = static_cast<char>(b);
    return frame_kind::none;
  }

  constexpr result<frame_kind> on_check(std::uint8_t b) noexcept {
    if (b == soh) return cut(b);
    if (b == eot) return finish();
    if (b == stx || b == etx) return drop(errc::bad_syntax, state::hunting);
    if (b < 0x20U || b >= 0x7FU) return drop(errc::bad_character, state::hunting);
    if (b < '0' || b > '9') return drop(errc::bad_digit, state::hunting);
    if (++check_len_ > max_check_chars) return drop(errc::too_long, state::hunting);
    check_value_ = static_cast<std::uint16_t>(check_value_ * 10U + (b - '0'));
    return frame_kind::none;
  }

  constexpr result<frame_kind> finish() noexcept {
    state_ = state::idle; // the frame ended cleanly: whatever follows starts afresh
    const std::string_view body(body_.data(), len_);
    len_ = 0;
    if (check_len_ == 0U) return errc::bad_syntax;
    if (check_value_ > 0xFFU) return errc::out_of_range;
    const bool is_request = fields_ == request_fields;
    if (!is_request && fields_ != acknowledgement_fields) return errc::bad_length;
    if (is_request && options_.frames == accept::acknowledgements) return errc::unexpected_frame;
    if (!is_request && options_.frames == accept::requests) return errc::unexpected_frame;
    const check_rule rule = is_request ? options_.check.request : options_.check.acknowledgement;
    const bool either = is_request ? options_.check.request_either_rule
                                   : options_.check.acknowledgement_either_rule;
    const bool unchecked = check_value_ == 0U && options_.check.zero_means_unchecked;
    // compute_check(body, rule), accumulated while the body arrived
    const auto check_of = [this](check_rule r) {
      return static_cast<std::uint8_t>(xor_ ^ (r == check_rule::body_and_etx ? etx : 0U));
    };
    if (!unchecked && check_of(rule) != check_value_ &&
        !(either && check_of(other_rule(rule)) == check_value_)) {
      return errc::bad_checksum;
    }
    // the fields between the separators recorded in on_body (what split() would find)
    const auto field = [this, body](std::size_t i) {
      const std::size_t start = i == 0U ? 0U : field_end_[i - 1U] + 1U;
      const std::size_t end = i + 1U == fields_ ? body.size() : field_end_[i];
      return body.substr(start, end - start);
    };
    if (is_request) {
      auto r = parse_request_fields({field(0), field(1), field(2), field(3)});
      if (!r) return r.error();
      request_ = r.value();
      return frame_kind::request;
    }
    auto a =
        parse_acknowledgement_fields({field(0), field(1), field(2), field(3), field(4), field(5)});
    if (!a) return a.error();
    acknowledgement_ = a.value();
    return frame_kind::acknowledgement;
  }

  decoder_options options_{};
  state state_ = state::idle;
  std::uint8_t fields_ = 0;
  std::size_t field_start_ = 0; ///< where the field in progress starts in body_
  std::uint8_t check_len_ = 0;
  std::uint16_t check_value_ = 0;
  std::uint8_t xor_ = 0;                                              ///< XOR of the body so far
  std::array<std::uint8_t, acknowledgement_fields - 1U> field_end_{}; ///< where each ';' is
  static_assert(max_body_chars <= 0xFFU, "field_end_ holds body positions");
  std::size_t len_ = 0;
  std::array<char, max_body_chars> body_{};
  serial::request request_{};
  serial::acknowledgement acknowledgement_{};
};

/// One frame decoded by decode_frame: `req` is valid for a request, `ack` for an
/// acknowledgement.
struct decoded_frame {
  frame_kind kind = frame_kind::none;
  request req{};
  acknowledgement ack{};
};

/// Decodes exactly one complete frame (or a lone EOT poll) from `bytes`.
/// Errors: those of decoder::push; truncated (the bytes end inside a frame or are empty);
/// bad_length (bytes follow the frame).
[[nodiscard]] constexpr result<decoded_frame> decode_frame(std::span<const std::uint8_t> bytes,
                                                           decoder_options options = {}) noexcept {
  decoder d(options);
  std::size_t used = 0;
  auto r = d.push(bytes, used);
  if (!r) return r.error();
  if (r.value() == frame_kind::none) return errc::truncated;
  if (used != bytes.size()) return errc::bad_length;
  return decoded_frame{r.value(), d.request(), d.acknowledgement()};
}

} // namespace fieldcodec::pacontrol::serial
