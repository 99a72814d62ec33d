// fieldcodec — od::command, one row of a command table (a controller's list of numbered serial
// commands, each with a parameter and a date), and od::command_table, a constexpr view sorted by
// code with O(log n) lookup.
//
// A row says what a command's parameter and date may be: the date's type (`command_value`,
// also the type of a protocol's dates and acknowledgement dates), the printed ranges of the
// parameter and of an integer date, and whether the number is packed from smaller fields
// (`packing`), in which case every field is checked against the same field of the minimum
// and of the maximum. `check_parameter` and `check_date` apply all of that to any integer
// type (core/integer.hpp); the protocol's own field widths are the vendor module's business.
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/integer.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/detail/search.hpp>
#include <fieldcodec/od/number.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>

namespace fieldcodec::od {

/// The type of a command's date or acknowledgement date: none, an integer or a real number.
/// A device folder's own date values may carry it too (a protocol's type code on the wire
/// mapped to `integer` or `real`).
enum class command_value : std::uint8_t { none, integer, real };

[[nodiscard]] constexpr std::string_view name(command_value v) noexcept {
  switch (v) {
  case command_value::none: return "none";
  case command_value::integer: return "integer";
  case command_value::real: return "real";
  }
  return "";
}

/// How a parameter or an integer date is made of fields, most significant first. Each field
/// must lie between the same field of the minimum and of the maximum.
enum class packing : std::uint8_t {
  whole,          ///< one number, checked against minimum and maximum as a whole
  byte_byte,      ///< 16 bits: bits 15-8 | bits 7-0 (e.g. axis | axis parameter)
  byte_byte_word, ///< 32 bits: bits 31-24 | 23-16 | 15-0 (e.g. state | type | number)
};

[[nodiscard]] constexpr std::string_view name(packing p) noexcept {
  switch (p) {
  case packing::whole: return "whole";
  case packing::byte_byte: return "byte_byte";
  case packing::byte_byte_word: return "byte_byte_word";
  }
  return "";
}

namespace detail {

/// Splits a packed value into its fields (most significant first; unused slots are 0).
/// Errors: overflow (negative, or wider than the packing).
[[nodiscard]] constexpr result<std::array<std::uint32_t, 3>> split_fields(std::int64_t v,
                                                                          packing p) noexcept {
  std::array<std::uint32_t, 3> f{};
  if (p == packing::byte_byte) {
    auto w = checked_narrow<std::uint16_t>(v);
    if (!w) return w.error();
    const auto b = to_bytes<std::uint16_t>(w.value(), byte_order::big);
    f[0] = b[0];
    f[1] = b[1];
    return f;
  }
  auto w = checked_narrow<std::uint32_t>(v);
  if (!w) return w.error();
  const auto b = to_bytes<std::uint32_t>(w.value(), byte_order::big);
  f[0] = b[0];
  f[1] = b[1];
  f[2] = load<std::uint16_t>(std::span<const std::uint8_t>(b).subspan(2), byte_order::big).value();
  return f;
}

/// Checks `v` against [lo, hi] under a packing (an absent bound is not checked).
/// Errors: out_of_range, overflow (a packed value wider than its packing, or a bound that is
/// not a packed value of that width), type_mismatch (a fraction in a packed value).
[[nodiscard]] constexpr status check_packed(decimal v, const number &lo, const number &hi,
                                            packing p) noexcept {
  if (p == packing::whole) {
    if (auto l = lo.to_decimal(); l && compare(v, l.value()) < 0) return errc::out_of_range;
    if (auto h = hi.to_decimal(); h && compare(v, h.value()) > 0) return errc::out_of_range;
    return {};
  }
  auto whole = to_fixed(v, 0);
  if (!whole) return whole.is(errc::not_representable) ? errc::type_mismatch : whole.error();
  auto fields = split_fields(whole.value(), p);
  if (!fields) return fields.error();
  if (lo) {
    auto l = lo.to_int64();
    if (!l) return l.error();
    auto lf = split_fields(l.value(), p);
    if (!lf) return lf.error();
    for (std::size_t i = 0; i < 3U; ++i) {
      if (fields.value()[i] < lf.value()[i]) return errc::out_of_range;
    }
  }
  if (hi) {
    auto h = hi.to_int64();
    if (!h) return h.error();
    auto hf = split_fields(h.value(), p);
    if (!hf) return hf.error();
    for (std::size_t i = 0; i < 3U; ++i) {
      if (fields.value()[i] > hf.value()[i]) return errc::out_of_range;
    }
  }
  return {};
}

/// An integer argument as an exact decimal. Errors: overflow (beyond int64).
template <integer_argument T>
[[nodiscard]] constexpr result<decimal> integer_as_decimal(T v) noexcept {
  auto i = checked_narrow<std::int64_t>(v);
  if (!i) return i.error();
  return decimal{i.value(), 0};
}

} // namespace detail

struct command {
  std::uint16_t code = 0;  ///< e.g. 0x0A87 (printed as 4 hex digits, "0A87")
  std::string_view name{}; ///< as printed ("cmd_put_float_reg")
  std::string_view section{};
  std::string_view title{};
  std::string_view parameter{}; ///< meaning of the command parameter
  number parameter_min{};       ///< allowed range of the parameter (none: not given)
  number parameter_max{};
  packing parameter_packing = packing::whole;
  command_value date_type = command_value::none;
  std::string_view date{}; ///< meaning of the command date
  number date_min{};       ///< allowed range of the date (none: not given)
  number date_max{};
  packing date_packing = packing::whole;
  command_value reply_type = command_value::none;
  std::string_view reply{};
  std::string_view modes{}; ///< ';'-separated operating modes in which it is allowed
  std::string_view remark{};

  /// True when `mode` is one of the ';'-separated `modes` (exact match).
  [[nodiscard]] constexpr bool allowed_in(std::string_view mode) const noexcept {
    std::string_view rest = modes;
    while (!rest.empty()) {
      const std::size_t semi = rest.find(';');
      if (rest.substr(0, semi) == mode) return true;
      if (semi == std::string_view::npos) break;
      rest.remove_prefix(semi + 1U);
    }
    return false;
  }

  /// Checks a parameter against the table: its range and, when packed, every field.
  /// Errors: out_of_range, overflow (wider than the packing, or beyond int64).
  template <integer_argument T>
  [[nodiscard]] constexpr status check_parameter(T p) const noexcept {
    auto d = detail::integer_as_decimal(p);
    if (!d) return d.error();
    return detail::check_packed(d.value(), parameter_min, parameter_max, parameter_packing);
  }

  /// Checks a date against the table's range and packing (not its type: see date_type).
  /// Errors: out_of_range, overflow (wider than the packing, or beyond int64), type_mismatch
  /// (a fraction in a packed date).
  template <integer_argument T>
  [[nodiscard]] constexpr status check_date(T d) const noexcept {
    auto v = detail::integer_as_decimal(d);
    if (!v) return v.error();
    return check_date(v.value());
  }
  [[nodiscard]] constexpr status check_date(decimal d) const noexcept {
    return detail::check_packed(d, date_min, date_max, date_packing);
  }
};

class command_table {
public:
  using const_iterator = std::span<const command>::iterator;

  constexpr command_table() noexcept = default;
  constexpr explicit command_table(std::span<const command> commands) noexcept
      : commands_(commands) {}

  /// Strictly increasing codes.
  [[nodiscard]] constexpr bool is_valid() const noexcept {
    for (std::size_t i = 1; i < commands_.size(); ++i) {
      if (commands_[i - 1U].code >= commands_[i].code) return false;
    }
    return true;
  }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return commands_.size(); }
  [[nodiscard]] constexpr const_iterator begin() const noexcept { return commands_.begin(); }
  [[nodiscard]] constexpr const_iterator end() const noexcept { return commands_.end(); }

  [[nodiscard]] constexpr const command *find(std::uint16_t code) const noexcept {
    return detail::find(commands_, code, key);
  }
  /// Errors: unknown_command.
  [[nodiscard]] constexpr result<const command *> lookup(std::uint16_t code) const noexcept {
    const std::size_t i = detail::position(commands_, code, key);
    if (i == commands_.size()) return errc::unknown_command;
    return commands_.data() + i;
  }

private:
  static constexpr std::uint16_t key(const command &c) noexcept { return c.code; }
  std::span<const command> commands_{};
};

} // namespace fieldcodec::od
