// fieldcodec — finding a DPQ parameter by its printed name or its manual section, and checking
// whether the card accepts a write in its present state (manual RE 30146-02-Z, chapter 4: each
// parameter's "Value acceptance").
//
//   dpq::find_by_name(p::dictionary, "Inj. P Limit 1")        → the descriptor of 2023h
//   dpq::find_by_name(p::dictionary, "inj.  p limit 1", dpq::name_match::normalised)
//   dpq::find_by_section(p::dictionary, "4.100")
//   dpq::check_acceptance(p::dpq_columns, p::inj_p_limit_1, dpq::enabling::active)
//       → ok or bad_state
//
// The functions take any od::dictionary (the generated dpq_parameters one in practice) and
// answer with od::descriptor, the one scaling surface; the acceptance is the DPQ's own column,
// generated beside the dictionary as `dpq_columns` (dpq/columns.hpp).
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/dpq/columns.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/dictionary.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::dpq {

// ---------------------------------------------------------------------------------------------
// Lookup

/// How find_by_name compares names.
///   exact:      byte for byte, as the manual prints the name ("BackP: Decomp Rate 2").
///   normalised: ASCII letters compared without case, leading and trailing white space ignored
///               and every run of white space (space, tab) equal to one space; punctuation is
///               kept ("Decompres.: Limit-" and "Decompres.: Limit+" are two parameters).
enum class name_match : std::uint8_t { exact, normalised };

namespace detail {
[[nodiscard]] constexpr bool is_blank(char c) noexcept { return c == ' ' || c == '\t'; }
[[nodiscard]] constexpr char fold(char c) noexcept {
  return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}
[[nodiscard]] constexpr std::string_view trim_blanks(std::string_view s) noexcept {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}
/// `a` and `b` equal under name_match::normalised.
[[nodiscard]] constexpr bool normalised_equal(std::string_view a, std::string_view b) noexcept {
  a = trim_blanks(a);
  b = trim_blanks(b);
  std::size_t i = 0;
  std::size_t j = 0;
  while (i < a.size() && j < b.size()) {
    const bool a_blank = is_blank(a[i]);
    if (a_blank != is_blank(b[j])) return false;
    if (a_blank) { // a run of blanks matches a run of blanks (trimmed: never at the end)
      while (i < a.size() && is_blank(a[i])) ++i;
      while (j < b.size() && is_blank(b[j])) ++j;
      continue;
    }
    if (fold(a[i]) != fold(b[j])) return false;
    ++i;
    ++j;
  }
  return i == a.size() && j == b.size();
}
[[nodiscard]] constexpr bool name_equal(std::string_view a, std::string_view b,
                                        name_match how) noexcept {
  return how == name_match::exact ? a == b : normalised_equal(a, b);
}
} // namespace detail

/// The parameter named `name`. Errors: unknown_object (no such name), invalid_argument (more
/// than one parameter matches; cannot happen with `exact` in a dictionary of unique names,
/// tests/dpq/lookup_test.cpp checks the DPQ's 221 names are unique under both rules).
[[nodiscard]] constexpr result<od::descriptor>
find_by_name(const od::dictionary &d, std::string_view name,
             name_match how = name_match::exact) noexcept {
  const auto infos = d.infos();
  std::size_t found = infos.size();
  for (std::size_t i = 0; i < infos.size(); ++i) {
    if (!detail::name_equal(infos[i].name, name, how)) continue;
    if (found != infos.size()) return errc::invalid_argument;
    found = i;
  }
  if (found == infos.size()) return errc::unknown_object;
  return d.describe(d.entries()[found]);
}

/// The parameter of manual section `section` ("4.100", exactly as printed in chapter 4).
/// Errors: unknown_object (no such section), invalid_argument (two entries share the section).
[[nodiscard]] constexpr result<od::descriptor> find_by_section(const od::dictionary &d,
                                                               std::string_view section) noexcept {
  const auto infos = d.infos();
  std::size_t found = infos.size();
  for (std::size_t i = 0; i < infos.size(); ++i) {
    if (section.empty() || infos[i].section != section) continue;
    if (found != infos.size()) return errc::invalid_argument;
    found = i;
  }
  if (found == infos.size()) return errc::unknown_object;
  return d.describe(d.entries()[found]);
}

// ---------------------------------------------------------------------------------------------
// Value acceptance

/// The acceptance of a parameter (its row of `table`, a generated `dpq_columns`); unknown when
/// it has none.
[[nodiscard]] constexpr acceptance acceptance_of(std::span<const parameter_columns> table,
                                                 const od::entry &p) noexcept {
  return columns_of(table, p).value_acceptance;
}

/// The card's enabling (the caller knows it from the card's status).
enum class enabling : std::uint8_t { inactive, active };

/// May `p` be written while the card's enabling is `state`? Errors: access_denied (read-only
/// parameter), bad_state (accepted only with deactivated enabling, and enabling is active),
/// invalid_argument (the parameter has no acceptance in `table`, a generated `dpq_columns`: a
/// communication object, or not a DPQ parameter).
[[nodiscard]] constexpr status check_acceptance(std::span<const parameter_columns> table,
                                                const od::entry &p, enabling state) noexcept {
  if (!od::writable(p.access_type)) return errc::access_denied;
  switch (acceptance_of(table, p)) {
  case acceptance::also_when_enabled: return {};
  case acceptance::only_when_disabled:
    if (state == enabling::active) return errc::bad_state;
    return {};
  case acceptance::unknown: break;
  }
  return errc::invalid_argument;
}

} // namespace fieldcodec::dpq
