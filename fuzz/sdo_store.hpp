// What the SDO fuzz harnesses (fuzz_canopen_sdo.cpp, fuzz_coe.cpp) share: a reader of the
// fuzzer's input and a small object store.
#pragma once

#include "check.hpp"
#include "input.hpp"

#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/od/address.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace fuzz_sdo {

namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;

/// Reads bytes from the input, zero when exhausted (fuzz/input.hpp).
using reader = fuzz_input::reader;

/// Two objects; 0x2000:1 holds up to `capacity` bytes, 0x2001:0 exactly 4. Parts are staged
/// and the value changes only with the last part.
struct store {
  std::vector<std::uint8_t> value;
  std::size_t capacity = 0;
  std::array<std::uint8_t, 4> word{};
  std::vector<std::uint8_t> staging;
  std::size_t completed = 0; ///< writes that completed

  [[nodiscard]] static sdo::abort_code known(od::address a) {
    if ((a.index == 0x2000 && a.sub == 1) || (a.index == 0x2001 && a.sub == 0)) {
      return sdo::abort_code::none;
    }
    return sdo::abort_code::no_object;
  }
  sdo::abort_code read(od::address a, std::size_t offset, std::span<std::uint8_t> out,
                       std::size_t &total) const {
    if (auto c = known(a); c != sdo::abort_code::none) return c;
    const std::span<const std::uint8_t> v =
        a.index == 0x2000 ? std::span<const std::uint8_t>(value) : std::span(word);
    FUZZ_CHECK(offset <= v.size());
    const std::size_t n = std::min(out.size(), v.size() - offset);
    std::copy_n(v.begin() + static_cast<std::ptrdiff_t>(offset), n, out.begin());
    total = v.size();
    return sdo::abort_code::none;
  }
  sdo::abort_code begin_write(od::address a, std::optional<std::uint32_t>) {
    staging.clear();
    return known(a);
  }
  sdo::abort_code write(od::address a, std::size_t offset, std::span<const std::uint8_t> in,
                        bool last) {
    if (auto c = known(a); c != sdo::abort_code::none) return c;
    if (offset == 0) staging.clear();
    FUZZ_CHECK(offset == staging.size()); // parts arrive in order
    staging.insert(staging.end(), in.begin(), in.end());
    if (!last) return sdo::abort_code::none;
    if (a.index == 0x2000) {
      if (staging.size() > capacity) return sdo::abort_code::length_too_high;
      value = staging;
    } else {
      if (staging.size() != 4) return sdo::abort_code::length_too_low;
      std::copy(staging.begin(), staging.end(), word.begin());
    }
    ++completed;
    return sdo::abort_code::none;
  }
};
static_assert(fieldcodec::canopen::object_store<store>);

} // namespace fuzz_sdo
