// The PA-CONTROL stream decoder of issue 18 (the body split and its XOR taken while the bytes
// arrive, one test for the usual body byte, integer dates and short counts read without the
// general parsers) returns what the decoder it replaced returned, byte for byte: the old
// decoder and body parsers are kept here as the reference and both are fed the same streams —
// valid frames of both kinds, frames with bytes flipped, cut or duplicated, and noise.
#include <fieldcodec/pacontrol/serial_decoder.hpp>

#include <doctest/doctest.h>

#include "xorshift.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace reference {
using namespace fieldcodec;
using namespace fieldcodec::pacontrol;
using fieldcodec::pacontrol::serial::accept;
using fieldcodec::pacontrol::serial::acknowledgement_fields;
using fieldcodec::pacontrol::serial::check_rule;
using fieldcodec::pacontrol::serial::compute_check;
using fieldcodec::pacontrol::serial::decoder_options;
using fieldcodec::pacontrol::serial::eot;
using fieldcodec::pacontrol::serial::etx;
using fieldcodec::pacontrol::serial::frame_kind;
using fieldcodec::pacontrol::serial::max_body_chars;
using fieldcodec::pacontrol::serial::max_check_chars;
using fieldcodec::pacontrol::serial::max_field_chars;
using fieldcodec::pacontrol::serial::other_rule;
using fieldcodec::pacontrol::serial::request_fields;
using fieldcodec::pacontrol::serial::separator;
using fieldcodec::pacontrol::serial::soh;
using fieldcodec::pacontrol::serial::stx;
namespace serial {
using fieldcodec::pacontrol::serial::acknowledgement;
using fieldcodec::pacontrol::serial::request;
} // namespace serial
using serial::acknowledgement;
using serial::request;

namespace detail {

/// Splits `body` at ';' into exactly `n` fields. Errors: bad_length (other count).
template <std::size_t N>
constexpr status split(std::string_view body, std::array<std::string_view, N> &fields) noexcept {
  std::size_t k = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= body.size(); ++i) {
    if (i == body.size() || body[i] == separator) {
      if (k == N) return errc::bad_length;
      fields[k++] = body.substr(start, i - start);
      start = i + 1U;
    }
  }
  if (k != N) return errc::bad_length;
  return {};
}

/// An unsigned decimal field of at most `max`. Errors: bad_syntax (empty), bad_sign
/// (leading '-'), bad_digit, overflow (> max).
constexpr result<std::uint64_t> parse_count(std::string_view f, std::uint64_t max) noexcept {
  if (!f.empty() && f.front() == '-') return errc::bad_sign;
  auto v = ascii::parse_unsigned(f);
  if (!v) return v.error();
  if (v.value() > max) return errc::overflow;
  return v;
}

/// A 0/1 field (BE, TYP). Errors: those of parse_count, out_of_range (> 1).
constexpr result<bool> parse_flag(std::string_view f) noexcept {
  auto v = parse_count(f, std::numeric_limits<std::uint64_t>::max());
  if (!v) return v.error();
  if (v.value() > 1U) return errc::out_of_range;
  return v.value() == 1U;
}

/// The date, real when `real` (TYP 1). Errors: bad_syntax, bad_digit, overflow (integer
/// outside int32), type_mismatch (a fraction in an integer date).
constexpr result<value> parse_value(bool real, std::string_view f) noexcept {
  auto d = parse_decimal(f);
  if (!d) return d.error();
  if (real) return value{od::command_value::real, d.value()};
  if (d.value().places != 0U) return errc::type_mismatch;
  return value::of_int(d.value().mantissa);
}

} // namespace detail

/// Parses the body of a request ("0A87;2;1;5552.0").
/// Errors: bad_length (not 4 fields, CMD not 4 characters), bad_syntax (empty field),
/// bad_digit (lower-case or non-hex CMD, letters in decimal fields), bad_sign, overflow,
/// out_of_range (TYP not 0/1), type_mismatch (a fraction with TYP 0).
[[nodiscard]] constexpr result<request> parse_request_body(std::string_view body) noexcept {
  std::array<std::string_view, request_fields> f{};
  FIELDCODEC_TRY_STATUS(detail::split(body, f));
  if (f[0].size() != 4U) return f[0].empty() ? errc::bad_syntax : errc::bad_length;
  auto cmd = ascii::parse_hex(f[0], ascii::hex_case::upper);
  if (!cmd) return cmd.error();
  auto par = detail::parse_count(f[1], std::numeric_limits<std::uint16_t>::max());
  if (!par) return par.error();
  auto typ = detail::parse_flag(f[2]);
  if (!typ) return typ.error();
  auto date = detail::parse_value(typ.value(), f[3]);
  if (!date) return date.error();
  return request{static_cast<std::uint16_t>(cmd.value()), static_cast<std::uint16_t>(par.value()),
                 date.value()};
}

/// Parses the body of an acknowledgement ("0;0;31;0;1;1516.950").
/// Errors: as parse_request_body (bad_length for not 6 fields; out_of_range for BE not 0/1).
[[nodiscard]] constexpr result<acknowledgement>
parse_acknowledgement_body(std::string_view body) noexcept {
  std::array<std::string_view, acknowledgement_fields> f{};
  FIELDCODEC_TRY_STATUS(detail::split(body, f));
  constexpr auto max16 = std::numeric_limits<std::uint16_t>::max();
  auto quit = detail::parse_count(f[0], max16);
  if (!quit) return quit.error();
  auto be = detail::parse_flag(f[1]);
  if (!be) return be.error();
  auto st = detail::parse_count(f[2], max16);
  if (!st) return st.error();
  auto err = detail::parse_count(f[3], max16);
  if (!err) return err.error();
  auto typ = detail::parse_flag(f[4]);
  if (!typ) return typ.error();
  auto date = detail::parse_value(typ.value(), f[5]);
  if (!date) return date.error();
  return acknowledgement{static_cast<std::uint16_t>(quit.value()), be.value(),
                         static_cast<std::uint16_t>(st.value()),
                         static_cast<std::uint16_t>(err.value()), date.value()};
}

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
    field_len_ = 0;
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
    if (b == soh || b == eot) return cut(b);
    if (b == etx) {
      state_ = state::check;
      return frame_kind::none;
    }
    if (b == stx) return drop(errc::bad_syntax, state::hunting);
    if (b < 0x20U || b >= 0x7FU) return drop(errc::bad_character, state::hunting);
    if (b == static_cast<std::uint8_t>(separator)) {
      if (fields_ == acknowledgement_fields) return drop(errc::bad_length, state::hunting);
      ++fields_;
      field_len_ = 0;
    } else if (++field_len_ > max_field_chars) {
      return drop(errc::too_long, state::hunting);
    }
    body_[len_++] = static_cast<char>(b); // len_ < max_body_chars: fields and lengths bounded
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
    if (!unchecked && compute_check(body, rule) != check_value_ &&
        !(either && compute_check(body, other_rule(rule)) == check_value_)) {
      return errc::bad_checksum;
    }
    if (is_request) {
      auto r = parse_request_body(body);
      if (!r) return r.error();
      request_ = r.value();
      return frame_kind::request;
    }
    auto a = parse_acknowledgement_body(body);
    if (!a) return a.error();
    acknowledgement_ = a.value();
    return frame_kind::acknowledgement;
  }

  decoder_options options_{};
  state state_ = state::idle;
  std::uint8_t fields_ = 0;
  std::uint8_t field_len_ = 0;
  std::uint8_t check_len_ = 0;
  std::uint16_t check_value_ = 0;
  std::size_t len_ = 0;
  std::array<char, max_body_chars> body_{};
  serial::request request_{};
  serial::acknowledgement acknowledgement_{};
};

} // namespace reference

namespace {
namespace fc = fieldcodec;
namespace pac = fieldcodec::pacontrol;
namespace ser = fieldcodec::pacontrol::serial;

struct rng : fieldcodec::test::xorshift {
  rng() : xorshift(0xC0FF'EE00'1234'4321ULL) {}
  std::uint64_t below(std::uint64_t n) { return next() % n; }
};

pac::value any_value(rng &g) {
  const std::uint64_t r = g.next();
  switch (r % 5U) {
  case 0: return pac::value::of_int(static_cast<std::int32_t>(r >> 32U)).value();
  case 1: return pac::value::of_int(static_cast<std::int32_t>((r >> 32U) % 2000U) - 1000).value();
  case 2:
    return pac::value{fc::od::command_value::real,
                      fc::decimal{static_cast<std::int64_t>(r >> 8U) / 1000,
                                  static_cast<std::uint8_t>((r >> 2U) % 19U)}};
  case 3: return pac::value{fc::od::command_value::integer, fc::decimal{0, 0}};
  default:
    return pac::value{fc::od::command_value::real,
                      fc::decimal{static_cast<std::int64_t>(r) >> (r % 64U), 3}};
  }
}

// A frame of either kind, then (sometimes) damaged.
void append_frame(rng &g, std::vector<std::uint8_t> &s) {
  std::array<std::uint8_t, ser::max_frame_size> b{};
  fc::result<std::size_t> n = fc::errc::invalid_argument;
  const auto rule = g.below(2) == 0U ? ser::check_rule::body : ser::check_rule::body_and_etx;
  const auto mode = g.below(5) == 0U ? ser::check_mode::unchecked : ser::check_mode::computed;
  if (g.below(2) == 0U) {
    const ser::request q{static_cast<std::uint16_t>(g.next()),
                         static_cast<std::uint16_t>(g.below(3) == 0U ? g.next() : g.below(10)),
                         any_value(g)};
    n = ser::encode_request(q, b, rule, mode);
  } else {
    const ser::acknowledgement a{static_cast<std::uint16_t>(g.below(300)), g.below(2) == 0U,
                                 static_cast<std::uint16_t>(g.next()),
                                 static_cast<std::uint16_t>(g.below(1000)), any_value(g)};
    n = ser::encode_acknowledgement(a, b, rule, mode);
  }
  if (!n) return;
  std::vector<std::uint8_t> f(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n.value()));
  static constexpr std::uint8_t interesting[] = {0x01, 0x02, 0x03, 0x04, ';', '-',  '.',  '0',
                                                 '1',  '9',  'A',  'a',  ' ', 0x7F, 0x80, 0x1F};
  switch (g.below(8)) {
  case 0: f[g.below(f.size())] = interesting[g.below(std::size(interesting))]; break;
  case 1: f[g.below(f.size())] = static_cast<std::uint8_t>(g.next()); break;
  case 2: f.resize(g.below(f.size())); break; // cut
  case 3: {                                   // a byte duplicated (long fields, long CHECK)
    const std::size_t i = g.below(f.size());
    for (auto k = g.below(25); k > 0; --k)
      f.insert(f.begin() + static_cast<std::ptrdiff_t>(i), f[i]);
    break;
  }
  case 4: f.erase(f.begin() + static_cast<std::ptrdiff_t>(g.below(f.size()))); break;
  default: break; // intact
  }
  s.insert(s.end(), f.begin(), f.end());
  if (g.below(10) == 0U) { // noise between frames
    for (auto k = g.below(6); k > 0; --k) s.push_back(interesting[g.below(std::size(interesting))]);
  }
  if (g.below(10) == 0U) s.push_back(ser::eot); // a poll
}

bool same(const fc::result<ser::frame_kind> &a, const fc::result<ser::frame_kind> &b) {
  if (a.has_value() != b.has_value()) return false;
  return a.has_value() ? a.value() == b.value() : a.error() == b.error();
}
} // namespace

TEST_CASE("pacontrol decoder: every push returns what the replaced decoder returned") {
  rng g;
  long completed = 0;
  long errors = 0;
  for (int run = 0; run < 48; ++run) {
    ser::decoder_options o;
    o.frames = static_cast<ser::accept>(run % 3);
    o.check.zero_means_unchecked = (run / 3) % 2 == 0;
    o.check.request_either_rule = (run / 6) % 2 == 0;
    o.check.acknowledgement_either_rule = (run / 12) % 2 == 0;
    if ((run / 24) % 2 != 0) o.check.request = ser::check_rule::body_and_etx;
    ser::decoder now(o);
    reference::decoder ref(o);
    std::vector<std::uint8_t> stream;
    for (int k = 0; k < 400; ++k) append_frame(g, stream);
    for (std::size_t i = 0; i < stream.size(); ++i) {
      const auto a = now.push(stream[i]);
      const auto b = ref.push(stream[i]);
      if (!same(a, b)) {
        INFO("run ", run, " byte ", i, " = ", int{stream[i]});
        REQUIRE(same(a, b));
      }
      if (!a) ++errors;
      if (a && a.value() == ser::frame_kind::request) {
        ++completed;
        REQUIRE(now.request() == ref.request());
        CHECK(now.request().date.same_text(ref.request().date));
      }
      if (a && a.value() == ser::frame_kind::acknowledgement) {
        ++completed;
        REQUIRE(now.acknowledgement() == ref.acknowledgement());
        CHECK(now.acknowledgement().date.same_text(ref.acknowledgement().date));
      }
      REQUIRE(now.idle() == ref.idle());
    }
  }
  MESSAGE("frames completed: ", completed, ", errors: ", errors);
  CHECK(completed > 1000);
  CHECK(errors > 1000);
}

TEST_CASE("pacontrol body parsers: the same results as the replaced ones") {
  rng g;
  static constexpr char alphabet[] = "0123456789;;;--..AFaf x";
  for (int k = 0; k < 200000; ++k) {
    std::array<char, 40> text{};
    const std::size_t n = g.below(text.size());
    for (std::size_t i = 0; i < n; ++i) text[i] = alphabet[g.below(sizeof(alphabet) - 1U)];
    const std::string_view body(text.data(), n);
    const auto a = ser::parse_request_body(body);
    const auto b = reference::parse_request_body(body);
    INFO("body \"", body, "\"");
    REQUIRE(a.has_value() == b.has_value());
    if (a) CHECK(a.value() == b.value());
    if (!a) CHECK(a.error() == b.error());
    const auto c = ser::parse_acknowledgement_body(body);
    const auto d = reference::parse_acknowledgement_body(body);
    REQUIRE(c.has_value() == d.has_value());
    if (c) CHECK(c.value() == d.value());
    if (!c) CHECK(c.error() == d.error());
  }
}
