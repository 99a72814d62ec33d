// fieldcodec — od::value_kinds, which kinds of values a dictionary has, so that code over a known
// dictionary links only the checks and conversions those need (an integer-only dictionary: no
// floating point, no 64-bit division, limit checks as integer comparisons).
//
//   namespace io = fieldcodec::dictionaries::io_node;
//   io::kinds                         → what the generator found (.real = false, .limits = false…)
//   od::kinds_of(io::entries)         → the same, computed (constexpr)
//   od::covers(io::kinds, od::kinds_of(other_entries))   → may code made for io::kinds serve them?
//
// Code that takes a value_kinds as a template argument (canopen::dictionary_store, od::check_value)
// compiles the paths of the kinds that are true only; it refuses a dictionary that has a kind it
// was not made for (covers() is false), rather than skipping a check. od::all_kinds (every member
// true) is what the run-time dictionaries and the plain od::encode / od::decode serve.
#pragma once

#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/entry.hpp>

#include <span>

namespace fieldcodec::od {

struct value_kinds {
  bool strings = true;     ///< VISIBLE_STRING, OCTET_STRING, UNICODE_STRING or DOMAIN entries
  bool real = true;        ///< REAL32 / REAL64 entries
  bool time = true;        ///< TIME_OF_DAY / TIME_DIFFERENCE entries
  bool wide = true;        ///< integers wider than 32 bits (INTEGER40..64, UNSIGNED40..64)
  bool limits = true;      ///< an entry with a low or a high limit
  bool node_limits = true; ///< a node-ID-relative limit ("$NODEID+…")
  bool scaled = true;      ///< a scaled entry (limits in engineering units)
  /// A default or limit packed as an od::number (flag::default_number / limits_number): a
  /// fraction, a value beyond the entry's field, a scaled entry's engineering limits, a REAL
  /// that is no float of the entry's type. Their checks use decimal arithmetic.
  bool numbers = true;

  friend constexpr bool operator==(const value_kinds &, const value_kinds &) noexcept = default;
};

/// Every kind: what code for a dictionary it does not know serves.
inline constexpr value_kinds all_kinds{};

/// The kinds of `e`.
[[nodiscard]] constexpr value_kinds kinds_of(const entry &e) noexcept {
  value_kinds k{false, false, false, false, false, false, false, false};
  k.strings = is_byte_string(e.type);
  k.real = is_real(e.type);
  k.time = is_time(e.type);
  k.wide = is_integer(e.type) && fixed_size(e.type) > 4U;
  k.limits = e.has(flag::has_low) || e.has(flag::has_high);
  k.node_limits = (e.has(flag::has_low) && e.has(flag::low_nodeid)) ||
                  (e.has(flag::has_high) && e.has(flag::high_nodeid));
  k.scaled = e.has(flag::scaled);
  k.numbers = (e.has(flag::has_default) && e.has(flag::default_number)) ||
              (k.limits && e.has(flag::limits_number));
  return k;
}

/// The kinds of a dictionary's entries (none of them: every member false).
[[nodiscard]] constexpr value_kinds kinds_of(std::span<const entry> entries) noexcept {
  value_kinds k{false, false, false, false, false, false, false, false};
  for (const entry &e : entries) {
    const value_kinds x = kinds_of(e);
    k.strings = k.strings || x.strings;
    k.real = k.real || x.real;
    k.time = k.time || x.time;
    k.wide = k.wide || x.wide;
    k.limits = k.limits || x.limits;
    k.node_limits = k.node_limits || x.node_limits;
    k.scaled = k.scaled || x.scaled;
    k.numbers = k.numbers || x.numbers;
  }
  return k;
}

/// Whether code made for `have` serves values of the kinds `need` (every kind needed is had).
[[nodiscard]] constexpr bool covers(value_kinds have, value_kinds need) noexcept {
  return (have.strings || !need.strings) && (have.real || !need.real) &&
         (have.time || !need.time) && (have.wide || !need.wide) && (have.limits || !need.limits) &&
         (have.node_limits || !need.node_limits) && (have.scaled || !need.scaled) &&
         (have.numbers || !need.numbers);
}

} // namespace fieldcodec::od
