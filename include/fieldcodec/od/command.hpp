// fieldcodec — od::command, one row of a command table (PA-CONTROL style command lists), and
// od::command_table, a constexpr view sorted by code with O(log n) lookup.
#pragma once

#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/detail/search.hpp>
#include <fieldcodec/od/number.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::od {

/// Type of a command's date (argument) or of its acknowledgement date.
enum class command_value : std::uint8_t { none, integer, floating };

[[nodiscard]] constexpr std::string_view name(command_value v) noexcept {
  switch (v) {
  case command_value::none: return "none";
  case command_value::integer: return "integer";
  case command_value::floating: return "float";
  }
  return "";
}

struct command {
  std::uint16_t code = 0;  ///< e.g. 0x0A87 (printed as 4 hex digits, "0A87")
  std::string_view name{}; ///< as printed ("cmd_put_float_reg")
  std::string_view section{};
  std::string_view title{};
  std::string_view parameter{}; ///< meaning of the command parameter
  number parameter_min{};       ///< allowed range of the parameter (none: not given)
  number parameter_max{};
  command_value date_type = command_value::none;
  std::string_view date{};
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

  /// Errors: out_of_range when `p` lies outside [parameter_min, parameter_max].
  [[nodiscard]] constexpr status check_parameter(std::int64_t p) const noexcept {
    if (auto lo = parameter_min.to_int64(); lo && p < lo.value()) return errc::out_of_range;
    if (auto hi = parameter_max.to_int64(); hi && p > hi.value()) return errc::out_of_range;
    return {};
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
    return detail::find(commands_, code, [](const command &c) { return c.code; });
  }
  /// Errors: unknown_command.
  [[nodiscard]] constexpr result<const command *> lookup(std::uint16_t code) const noexcept {
    const command *c = find(code);
    if (c == nullptr) return errc::unknown_command;
    return c;
  }

private:
  std::span<const command> commands_{};
};

} // namespace fieldcodec::od
