// fieldcodec — the application's hooks on single objects of a node (node::device with
// capacity::hooks; docs/canopen.md, "Application hooks"): a value computed when it is read, a
// write the application checks and follows, and DOMAIN contents streamed to and from the
// application in parts.
//
//   node::object_hook h;
//   h.first = h.last = {0x2106, 0};                 // one object, or a range of index/sub
//   h.context = &app;
//   h.read = [](void *app, od::address a, std::span<std::uint8_t> value) noexcept { ... };
//   (void)dev.add_hook(h);                          // before dev.start()
//
// A hook serves the objects of the dictionary from `first` to `last` (by index, then
// sub-index). What each function does:
//   read      the object is read (SDO upload, TPDO sampling): write its value into `value`
//             (width() bytes, little-endian as CANopen sends it, holding the stored value) or
//             answer an abort code (it goes to the SDO client; a TPDO is not sent). The node
//             stores the computed value with the store's checks (canopen::dictionary_store::set:
//             length, type, limits) and then serves it; a value the store refuses is answered
//             with 0800 0000h (general error). Objects of fixed size (not byte strings) from
//             2000h on: the communication area 1000h–1FFFh belongs to the node's services.
//   write     a complete new value (SDO download, RPDO) passed every check of the node (the
//             owning service's CiA 301 rule, access, length, type, limits): answer an abort
//             code to refuse it (the old value stays, the code goes to the SDO client) or none
//             to accept it, after which it is stored and followed — nothing after the hook
//             refuses it. Values up to the SDO server's buffer (capacity::sdo_buffer) arrive
//             whole; a longer one is refused with 0504 0005h (out of memory).
//   upload    a DOMAIN's contents, read in parts (SDO upload: expedited, segmented or block):
//             copy min(out.size(), total − offset) bytes from `offset` into `out` and set
//             `total` to the contents' length (the same on every call of one transfer), or
//             answer an abort code. Offsets usually grow from 0; a block transfer that repeats
//             a sub-block asks for earlier ones again.
//   download  a DOMAIN's contents, written in parts in order from offset 0 (segmented, block,
//             expedited); `last` marks the end (a 0-byte download is one call: offset 0, empty,
//             last). Answer an abort code to stop the transfer (it goes to the client).
//   ended     a transfer of a streamed object ended unfinished: the client aborted it, it timed
//             out, the node or the application refused a part (`why`: the abort code sent or
//             received), or it ended silently (`why` none: NMT stopped or reset, a new request
//             on the channel). Drop what the transfer collected.
// A streamed object (upload or download set) is a DOMAIN whose contents the store never holds
// (declare no capacity for it: the node keeps no buffer of its size); the direction without a
// function answers 0601 0000h (unsupported access). A download longer than a capacity the
// dictionary declares is refused with 0607 0012h (length too high) before the application sees
// the part that would pass it. The node's checks stay: no object (0602 0000h), no sub-index
// (0609 0011h), access (0601 0001h / 0601 0002h). The application's own set() and value()
// see the store as it is: no hook is called.
#pragma once

#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/dictionary.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::canopen::node {

/// The application's functions for the objects `first`..`last` (see above). Every function may
/// be null; a hook has at least one, and either read / write or upload / download.
struct object_hook {
  od::address first{}; ///< the first object served
  od::address last{};  ///< the last (inclusive; `first` for one object)
  void *context = nullptr;
  abort_code (*read)(void *context, od::address a,
                     std::span<std::uint8_t> value) noexcept = nullptr;
  abort_code (*write)(void *context, od::address a,
                      std::span<const std::uint8_t> value) noexcept = nullptr;
  abort_code (*upload)(void *context, od::address a, std::size_t offset,
                       std::span<std::uint8_t> out, std::size_t &total) noexcept = nullptr;
  abort_code (*download)(void *context, od::address a, std::size_t offset,
                         std::span<const std::uint8_t> part, bool last) noexcept = nullptr;
  void (*ended)(void *context, od::address a, abort_code why) noexcept = nullptr;

  [[nodiscard]] constexpr bool covers(od::address a) const noexcept {
    return first <= a && a <= last;
  }
  /// Are the objects streamed (upload or download)?
  [[nodiscard]] constexpr bool streams() const noexcept {
    return upload != nullptr || download != nullptr;
  }
};

/// A fixed table of up to N hooks (node::device keeps one of capacity::hooks).
template <std::size_t N>
class object_hooks {
public:
  /// Add `h` for the objects of `dict` it covers. Errors: invalid_argument (no function, both
  /// value and stream functions, first after last, a range overlapping an added hook),
  /// unknown_object (no object of `dict` in the range), type_mismatch (a read hook on a byte
  /// string or in 1000h–1FFFh, a stream on an object that is no DOMAIN), too_long (N hooks
  /// added already).
  [[nodiscard]] constexpr status add(const object_hook &h, od::dictionary dict) noexcept {
    const bool value = h.read != nullptr || h.write != nullptr;
    if ((!value && !h.streams()) || (value && h.streams()) || h.last < h.first) {
      return errc::invalid_argument;
    }
    for (std::size_t i = 0; i < count_; ++i) {
      if (!(h.last < hooks_[i].first || hooks_[i].last < h.first)) return errc::invalid_argument;
    }
    bool any = false;
    for (const od::entry &e : dict) {
      const od::address a{e.index, e.sub};
      if (!h.covers(a)) continue;
      any = true;
      if (h.read != nullptr && (od::fixed_size(e.type) == 0U || e.index < 0x2000U)) {
        return errc::type_mismatch;
      }
      if (h.streams() && e.type != od::data_type::domain) return errc::type_mismatch;
    }
    if (!any) return errc::unknown_object;
    if (count_ == N) return errc::too_long;
    hooks_[count_++] = h;
    return {};
  }
  /// The hook that serves `a`, or null.
  [[nodiscard]] constexpr const object_hook *find(od::address a) const noexcept {
    for (std::size_t i = 0; i < count_; ++i) {
      if (hooks_[i].covers(a)) return &hooks_[i];
    }
    return nullptr;
  }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return count_; }

private:
  std::array<object_hook, N> hooks_{};
  std::size_t count_ = 0;
};

} // namespace fieldcodec::canopen::node
