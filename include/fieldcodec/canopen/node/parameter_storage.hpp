// fieldcodec — store and restore parameters (CiA 301, 1010h "store parameters" and 1011h
// "restore default parameters"): the node's side of the commands, the storage itself is the
// application's (firmware: a flash page; host: host::parameter_file).
//
//   node::storage_hook hook{&flash, save_to_flash, forget_flash};   // the application's
//   dev.set_storage(hook);                                          // capacity::storage
//
// Sub-indices (both objects): 1 all parameters, 2 communication parameters (1000h–1FFFh),
// 3 application parameters (6000h–9FFFh), 4..127 manufacturer-defined groups (this library:
// sub 4 = 2000h–5FFFh; further subs are the application's). Writing the signature "save"
// (65766173h, the bytes 's' 'a' 'v' 'e') to 1010h sub n asks the hook to save group n; "load"
// (64616F6Ch, 'l' 'o' 'a' 'd') to 1011h sub n asks it to discard group n's saved values, so
// that the defaults apply from the next reset (NMT reset node or reset communication, or
// power-on): the current values do not change. Nothing is written to the store.
// Refusals: another value (0800 0020h, data cannot be transferred or stored), no hook for the
// command (0800 0020h), the hook failed (0606 0000h, access failed due to a hardware error).
// Reading 1010h or 1011h sub 1.. over SDO gives what the node can do (not the store's value):
// bit 0 = it saves (1010h) or restores (1011h) on command (that hook function is set), bit 1 =
// it saves autonomously (never: the node saves only when asked).
#pragma once

#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>

#include <cstdint>

namespace fieldcodec::canopen::node {

namespace storage_signature {
inline constexpr std::uint32_t save = 0x6576'6173U; ///< "save" (1010h)
inline constexpr std::uint32_t load = 0x6461'6F6CU; ///< "load" (1011h)
} // namespace storage_signature

/// The parameter groups of 1010h/1011h (their sub-index).
namespace parameter_group {
inline constexpr std::uint8_t all = 1;
inline constexpr std::uint8_t communication = 2; ///< 1000h–1FFFh
inline constexpr std::uint8_t application = 3;   ///< 6000h–9FFFh
inline constexpr std::uint8_t manufacturer = 4;  ///< 2000h–5FFFh (this library's choice)
} // namespace parameter_group

/// The application's storage. Either function may be null: the node then refuses that
/// command (0800 0020h) and reads bit 0 of that object as 0.
struct storage_hook {
  void *context = nullptr;
  /// 1010h sub `group` got "save": store the current values of that group. false: failed.
  bool (*save)(void *context, std::uint8_t group) noexcept = nullptr;
  /// 1011h sub `group` got "load": discard the saved values of that group, so that the
  /// defaults apply from the next reset or power-on. false: failed.
  bool (*restore)(void *context, std::uint8_t group) noexcept = nullptr;
};

class parameter_storage {
public:
  static constexpr std::uint16_t store_index = 0x1010;
  static constexpr std::uint16_t restore_index = 0x1011;

  /// 1010h/1011h sub 1..: is this a command object?
  [[nodiscard]] static constexpr bool owns(od::address a) noexcept {
    return (a.index == store_index || a.index == restore_index) && a.sub != 0U;
  }
  /// The check of a written value (each_service): the signature and a hook for it.
  [[nodiscard]] constexpr abort_code check_write(od::address a, std::uint32_t v) const noexcept {
    if (!owns(a)) return abort_code::none;
    const bool store = a.index == store_index;
    if (v != (store ? storage_signature::save : storage_signature::load)) {
      return abort_code::cannot_store;
    }
    if ((store ? hook_.save : hook_.restore) == nullptr) return abort_code::cannot_store;
    return abort_code::none;
  }
  /// Carry out a command check_write accepted: the hook's answer.
  [[nodiscard]] constexpr abort_code command(od::address a) const noexcept {
    const bool ok = a.index == store_index ? hook_.save(hook_.context, a.sub)
                                           : hook_.restore(hook_.context, a.sub);
    return ok ? abort_code::none : abort_code::hardware_error;
  }
  /// What a read of `a` (owns(a)) shows: bit 0 = on command.
  [[nodiscard]] constexpr std::uint32_t capability(od::address a) const noexcept {
    return (a.index == store_index ? hook_.save : hook_.restore) != nullptr ? 1U : 0U;
  }
  constexpr void written(od::address, std::uint32_t, std::uint32_t) noexcept {}
  template <class Store>
  constexpr status load(const Store &, std::uint32_t) noexcept {
    return {};
  }
  constexpr void set_hook(storage_hook h) noexcept { hook_ = h; }
  [[nodiscard]] constexpr const storage_hook &hook() const noexcept { return hook_; }

private:
  storage_hook hook_{};
};

} // namespace fieldcodec::canopen::node
