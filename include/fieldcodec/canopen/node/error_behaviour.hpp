// fieldcodec — the error behaviour (CiA 301, 1029h): the NMT state a node enters when it finds
// a serious error of a class. Sub 1 is the communication error (a heartbeat consumer lost its
// node, life guarding lost its master, the CAN driver reports bus-off); further subs are the
// error classes of the device profile or the application.
//
//   node::error_behaviour<1> errors;                // 1029h sub 1
//   errors.written({0x1029, 1}, 2, now);            // stopped
//   errors.target(1, nmt::state::operational);      // nmt::state::stopped
//
// Each sub-index holds 0 (enter pre-operational, only from operational: the default, also for
// a class that 1029h does not have or when 1029h is absent), 1 (no state change) or 2 (enter
// stopped, from any state). 3..255 (reserved and manufacturer-specific reactions, none defined
// by this node) are refused with 0x06090030.
#pragma once

#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

namespace fieldcodec::canopen::node {

/// The reactions of 1029h.
enum class error_reaction : std::uint8_t {
  pre_operational = 0, ///< enter pre-operational (only from operational)
  no_change = 1,
  stopped = 2,
};

/// N: the sub-indices of 1029h served (1 = the communication error only).
template <std::size_t N>
class error_behaviour {
public:
  static constexpr std::uint16_t index = 0x1029;
  /// Sub-index of the communication error class.
  static constexpr std::uint8_t communication = 1;

  /// Would `v` be accepted for `a`? 1029h sub 1..255: 0, 1 or 2 (0x06090030 otherwise); none
  /// for every other object.
  [[nodiscard]] constexpr abort_code check_write(od::address a, std::uint32_t v) const noexcept {
    if (a.index != index || a.sub == 0U) return abort_code::none;
    return v <= static_cast<std::uint32_t>(error_reaction::stopped) ? abort_code::none
                                                                    : abort_code::invalid_value;
  }
  constexpr void written(od::address a, std::uint32_t v, std::uint32_t) noexcept {
    if (a.index == index && a.sub >= 1U && a.sub <= N && v <= 2U) {
      reaction_[a.sub - 1U] = static_cast<error_reaction>(v);
    }
  }
  /// Every class from 1029h in `store` (absent: the default). Errors: too_long (1029h has more
  /// sub-indices than N: those classes keep the default), invalid_argument (a stored value
  /// check_write refuses: that class keeps the default).
  template <class Store>
  constexpr status load(const Store &store, std::uint32_t now) noexcept {
    status st{};
    reaction_ = {};
    for (const auto &e : store.dictionary().object(index)) {
      if (e.sub == 0U) continue;
      if (e.sub > N) {
        st = errc::too_long;
        continue;
      }
      const auto v = read_u32(store, {index, e.sub});
      if (!v) continue;
      if (check_write({index, e.sub}, *v) != abort_code::none) {
        if (st) st = errc::invalid_argument;
        continue;
      }
      written({index, e.sub}, *v, now);
    }
    return st;
  }

  /// The reaction to an error of class `sub` (1 = communication).
  [[nodiscard]] constexpr error_reaction reaction(std::uint8_t sub) const noexcept {
    if (sub >= 1U && sub <= N) return reaction_[sub - 1U];
    return error_reaction::pre_operational;
  }
  /// The state a node in `s` enters on an error of class `sub`; nullopt: it stays.
  [[nodiscard]] constexpr std::optional<nmt::state> target(std::uint8_t sub,
                                                           nmt::state s) const noexcept {
    switch (reaction(sub)) {
    case error_reaction::pre_operational:
      if (s == nmt::state::operational) return nmt::state::pre_operational;
      return std::nullopt;
    case error_reaction::no_change: return std::nullopt;
    case error_reaction::stopped:
      if (s == nmt::state::stopped || s == nmt::state::boot_up) return std::nullopt;
      return nmt::state::stopped;
    }
    return std::nullopt;
  }

private:
  std::array<error_reaction, N> reaction_{};
};

} // namespace fieldcodec::canopen::node
