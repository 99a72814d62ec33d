// fieldcodec — the object store an SDO server reads and writes, and dictionary_store, a store
// over an od::dictionary with caller-owned storage.
//
// A store is anything with
//   sdo::abort_code read(std::uint16_t index, std::uint8_t sub, std::span<std::uint8_t> out,
//                        std::size_t &size);
//   sdo::abort_code write(std::uint16_t index, std::uint8_t sub, std::span<const std::uint8_t>);
// returning abort_code::none on success.
#pragma once

#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/value.hpp>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>

namespace fieldcodec::canopen::sdo {

template <class S>
concept object_store = requires(S &s, std::uint16_t index, std::uint8_t sub,
                                std::span<std::uint8_t> out, std::span<const std::uint8_t> in,
                                std::size_t &size) {
  { s.read(index, sub, out, size) } -> std::same_as<abort_code>;
  { s.write(index, sub, in) } -> std::same_as<abort_code>;
};

// ---------------------------------------------------------------------------------------------
// An object store over a dictionary

/// Stores the values of every entry of an od::dictionary in caller-owned bytes, one slot per
/// entry in dictionary order: width() bytes (little-endian) for fixed-size types, `size` bytes
/// for byte strings (which must declare a size). Checks on write: access type, length (exact for
/// fixed-size types, at most `size` for byte strings, whose unused tail is zeroed), limits, and
/// the rules of od::decode / od::decode_bytes.
class dictionary_store {
public:
  constexpr dictionary_store(od::dictionary dict, std::span<std::uint8_t> storage) noexcept
      : dict_(dict), storage_(storage) {}

  /// Bytes of storage the dictionary needs.
  [[nodiscard]] static constexpr std::size_t storage_size(od::dictionary dict) noexcept {
    std::size_t n = 0;
    for (const auto &e : dict) n += e.width();
    return n;
  }

  /// Fill every slot with the entry's default (node-ID relative defaults for `node`); entries
  /// without a numeric default get zeros, string defaults are copied from default_text.
  /// Errors: buffer_too_small (storage too small).
  [[nodiscard]] constexpr status init_defaults(std::uint8_t node) noexcept {
    if (storage_.size() < storage_size(dict_)) return errc::buffer_too_small;
    std::size_t off = 0;
    for (const auto &e : dict_) {
      auto slot = storage_.subspan(off, e.width());
      for (auto &b : slot) b = 0;
      if (od::is_byte_string(e.type)) {
        for (std::size_t i = 0; i < e.default_text.size() && i < slot.size(); ++i) {
          slot[i] = static_cast<std::uint8_t>(e.default_text[i]);
        }
      } else if (auto d = e.default_for(node)) {
        // an out-of-limit default stays zero; a scaled entry's limits need its descriptor
        if (auto desc = dict_.describe(e)) (void)od::encode(desc.value(), d.value(), slot);
      }
      off += e.width();
    }
    return {};
  }

  [[nodiscard]] constexpr abort_code read(std::uint16_t index, std::uint8_t sub,
                                          std::span<std::uint8_t> out,
                                          std::size_t &size) const noexcept {
    const od::entry *e = nullptr;
    std::span<std::uint8_t> slot;
    if (auto c = locate(index, sub, e, slot); c != abort_code::none) return c;
    if (!od::readable(e->access_type)) return abort_code::read_write_only;
    std::size_t n = slot.size();
    if (e->type == od::data_type::visible_string) {
      while (n > 0U && slot[n - 1U] == 0U) --n;
    }
    if (n > out.size()) return abort_code::out_of_memory;
    for (std::size_t i = 0; i < n; ++i) out[i] = slot[i];
    size = n;
    return abort_code::none;
  }

  [[nodiscard]] constexpr abort_code write(std::uint16_t index, std::uint8_t sub,
                                           std::span<const std::uint8_t> data) noexcept {
    const od::entry *e = nullptr;
    std::span<std::uint8_t> slot;
    if (auto c = locate(index, sub, e, slot); c != abort_code::none) return c;
    if (!od::writable(e->access_type)) return abort_code::write_read_only;
    if (od::is_byte_string(e->type)) {
      if (data.size() > slot.size()) return abort_code::length_too_high;
      auto v = od::decode_bytes(*e, data);
      if (!v)
        return v.error() == errc::too_long ? abort_code::length_too_high
                                           : abort_code::invalid_value;
      for (std::size_t i = 0; i < slot.size(); ++i) slot[i] = i < data.size() ? data[i] : 0U;
      return abort_code::none;
    }
    if (data.size() > slot.size()) return abort_code::length_too_high;
    if (data.size() < slot.size()) return abort_code::length_too_low;
    auto desc = dict_.describe(*e); // a scaled entry's limits need its scale
    if (!desc) return abort_code::general_error;
    auto v = od::decode(desc.value(), data, byte_order::little, od::limits::check);
    if (!v) {
      if (v.error() != errc::out_of_range) return abort_code::invalid_value;
      return out_of_range_code(*e, data);
    }
    for (std::size_t i = 0; i < slot.size(); ++i) slot[i] = data[i];
    return abort_code::none;
  }

  /// The stored bytes of index:sub (for the application side). Errors: unknown_object.
  [[nodiscard]] constexpr result<std::span<std::uint8_t>> slot(std::uint16_t index,
                                                               std::uint8_t sub) const noexcept {
    const od::entry *e = nullptr;
    std::span<std::uint8_t> s;
    if (locate(index, sub, e, s) != abort_code::none) return errc::unknown_object;
    return s;
  }

  [[nodiscard]] constexpr od::dictionary dictionary() const noexcept { return dict_; }

private:
  [[nodiscard]] constexpr abort_code locate(std::uint16_t index, std::uint8_t sub,
                                            const od::entry *&e,
                                            std::span<std::uint8_t> &slot) const noexcept {
    std::size_t off = 0;
    for (const auto &x : dict_) {
      if (x.index == index && x.sub == sub) {
        if (off + x.width() > storage_.size()) return abort_code::general_error;
        if (od::is_byte_string(x.type) && x.width() == 0U) return abort_code::unsupported_access;
        e = &x;
        slot = storage_.subspan(off, x.width());
        return abort_code::none;
      }
      off += x.width();
    }
    return dict_.object(index).empty() ? abort_code::no_object : abort_code::no_sub_index;
  }

  [[nodiscard]] static constexpr abort_code
  out_of_range_code(const od::entry &e, std::span<const std::uint8_t> data) noexcept {
    if (e.type == od::data_type::boolean || e.has(od::flag::scaled))
      return abort_code::invalid_value;
    auto raw = od::decode(e, data, byte_order::little, od::limits::ignore);
    if (!raw) return abort_code::invalid_value;
    auto v = raw.value().to_decimal();
    auto hi = e.high.to_decimal();
    if (v && hi && compare(v.value(), hi.value()) > 0) return abort_code::value_too_high;
    auto lo = e.low.to_decimal();
    if (v && lo && compare(v.value(), lo.value()) < 0) return abort_code::value_too_low;
    return abort_code::invalid_value;
  }

  od::dictionary dict_;
  std::span<std::uint8_t> storage_;
};

static_assert(object_store<dictionary_store>);

} // namespace fieldcodec::canopen::sdo
