// fieldcodec — the master's PDO configuration helper: "map these objects into RPDO n / TPDO n of
// node k" as the SDO sequence that does it (CiA 301: COB-ID invalid, communication parameters,
// mapping count 0, mapping entries, mapping count, COB-ID valid), checked against the device's
// dictionary before anything is sent.
//
//   constexpr pdo::mapping_entry rx[] = {{0x6040, 0, 16}, {0x607A, 0, 32}};
//   master::pdo_sequence seq;                                   // caller-owned storage
//   auto r = master::plan_pdo(xcan::dictionary, {.dir = pdo::direction::rpdo, .number = 1,
//                                                .node = 5, .entries = rx}, seq);
//   if (!r) r.error() names the problem, the entry and the object;
//   else configurator.start(seq.list(), now) writes it.
#pragma once

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/master/config.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/dictionary.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fieldcodec::master {

/// What to configure.
struct pdo_request {
  canopen::pdo::direction dir = canopen::pdo::direction::rpdo;
  std::uint16_t number = 1; ///< 1..512
  std::uint8_t node = 0;    ///< the device's node-ID, for the predefined COB-ID of PDO 1..4
  std::span<const canopen::pdo::mapping_entry> entries{};
  std::optional<std::uint16_t> cob_id{}; ///< default: predefined connection set (PDO 1..4)
  std::uint8_t transmission_type = 255;
  std::uint16_t inhibit_time = 0; ///< sub 3 (100 µs); written when the device has it
  std::uint16_t event_timer = 0;  ///< sub 5 (ms); written when the device has it
};

/// Why a request was refused.
struct pdo_error {
  errc code = errc::invalid_argument;
  canopen::pdo::mapping_problem problem = canopen::pdo::mapping_problem::none; ///< entry checks
  std::size_t entry = 0; ///< the offending entry (entry checks)
  od::address object{};  ///< the object concerned (the mapped object, or the PDO parameter)
  [[nodiscard]] constexpr bool is(errc e) const noexcept { return code == e; }
};

/// Storage for one PDO's sequence: at most 64 mapping entries + 7 other writes. Not copyable
/// (the configuration points into it).
class pdo_sequence {
public:
  static constexpr std::size_t capacity = canopen::pdo::max_entries + 7U;
  constexpr pdo_sequence() noexcept = default;
  pdo_sequence(const pdo_sequence &) = delete;
  pdo_sequence &operator=(const pdo_sequence &) = delete;

  /// The writes as a configuration list (no identity, node-ID-free: values are absolute).
  [[nodiscard]] constexpr configuration list() const noexcept {
    return {std::span<const config_item>(items_.data(), count_), {}, 0};
  }
  [[nodiscard]] constexpr std::span<const config_item> items() const noexcept {
    return {items_.data(), count_};
  }

private:
  friend constexpr result<std::size_t, pdo_error>
  plan_pdo(const od::dictionary &, const pdo_request &, pdo_sequence &) noexcept;

  constexpr void clear() noexcept { count_ = 0; }
  constexpr void add(const od::dictionary &d, od::address a, std::uint32_t v,
                     std::uint8_t size) noexcept {
    auto &bytes = values_[count_];
    for (std::size_t i = 0; i < 4U; ++i) bytes[i] = static_cast<std::uint8_t>(v >> (8U * i));
    // by position, not find() != nullptr (constant evaluation under g++ -fsanitize=undefined,
    // docs/od.md)
    const std::size_t i = d.position(a);
    items_[count_] = {a, std::span<const std::uint8_t>(bytes.data(), size), 0,
                      i < d.size() ? d.info(d.entries()[i]).name.view() : std::string_view{}};
    ++count_;
  }

  std::array<config_item, capacity> items_{};
  std::array<std::array<std::uint8_t, 4>, capacity> values_{};
  std::size_t count_ = 0;
};

/// Checks `r` against the device's dictionary and writes the sequence into `out`. Returns the
/// number of writes. Errors (nothing written to `out` that could be sent):
/// * invalid_argument: number not 1..512; no COB-ID given for PDO 5.. or a node not 1..127;
///   COB-ID above 0x7FF;
/// * unknown_object: the device has no communication or mapping parameter for the PDO
///   (`object` names it), or a mapped object it does not have (`problem` no_object);
/// * access_denied: a mapped object that is not mappable in this direction (not_mappable) or
///   whose access does not allow it (no_access: an RPDO of a read-only object, a TPDO of a
///   write-only one); the mapping count or COB-ID not writable (a static mapping);
/// * bad_length: an entry's length does not fit its object's type;
/// * too_long: more than 64 bits, or more entries than the device's mapping object has;
/// * out_of_range: a reserved transmission type, an RTR type for an RPDO.
[[nodiscard]] constexpr result<std::size_t, pdo_error>
plan_pdo(const od::dictionary &device, const pdo_request &r, pdo_sequence &out) noexcept {
  namespace pdo = canopen::pdo;
  out.clear();
  if (r.number < 1U || r.number > 512U) return pdo_error{errc::invalid_argument};
  const bool rx = r.dir == pdo::direction::rpdo;
  const auto comm = static_cast<std::uint16_t>((rx ? 0x1400U : 0x1800U) + r.number - 1U);
  const auto map = static_cast<std::uint16_t>(comm + 0x200U);
  // the COB-ID
  std::uint16_t cob = 0;
  if (r.cob_id) {
    cob = *r.cob_id;
  } else {
    if (r.number > 4U || r.node < 1U || r.node > 127U) {
      return pdo_error{errc::invalid_argument, {}, 0, {comm, 1}};
    }
    cob = static_cast<std::uint16_t>((rx ? 0x200U : 0x180U) + 0x100U * (r.number - 1U) + r.node);
  }
  const pdo::comm_params cp{
      {cob, true, true}, r.transmission_type, r.inhibit_time, r.event_timer, 0};
  if (auto s = pdo::check(cp, r.dir); !s) return pdo_error{s.error(), {}, 0, {comm, 2}};
  // the parameter objects
  const auto writable = [&device](od::address a) {
    const std::size_t i = device.position(a);
    return i < device.size() && od::writable(device.entries()[i].access_type);
  };
  for (const od::address a : {od::address{comm, 1}, od::address{map, 0}}) {
    if (!device.contains(a)) return pdo_error{errc::unknown_object, {}, 0, a};
    if (!writable(a)) return pdo_error{errc::access_denied, {}, 0, a};
  }
  // the entries
  const auto report = pdo::check_mapping(device, r.dir, r.entries);
  if (!report.ok()) {
    const auto &e = r.entries[report.entry < r.entries.size() ? report.entry : 0];
    return pdo_error{pdo::to_errc(report.problem), report.problem, report.entry, {e.index, e.sub}};
  }
  for (std::size_t i = 0; i < r.entries.size(); ++i) {
    const od::address slot{map, static_cast<std::uint8_t>(i + 1U)};
    if (!device.contains(slot)) {
      return pdo_error{errc::too_long, pdo::mapping_problem::too_many_entries, i, slot};
    }
  }
  // optional communication parameters the caller asked for
  const bool want_transmission = device.contains(comm, 2);
  if (want_transmission && !writable({comm, 2})) {
    return pdo_error{errc::access_denied, {}, 0, {comm, 2}};
  }
  if (r.inhibit_time != 0U && !writable({comm, 3})) {
    return pdo_error{errc::access_denied, {}, 0, {comm, 3}};
  }
  if (r.event_timer != 0U && !writable({comm, 5})) {
    return pdo_error{errc::access_denied, {}, 0, {comm, 5}};
  }
  // the sequence
  const std::uint32_t cob_valid = cob;
  out.add(device, {comm, 1}, cob_valid | pdo::cob_id_invalid_bit, 4);
  if (want_transmission) out.add(device, {comm, 2}, r.transmission_type, 1);
  if (!rx && writable({comm, 3})) out.add(device, {comm, 3}, r.inhibit_time, 2);
  if (writable({comm, 5})) out.add(device, {comm, 5}, r.event_timer, 2);
  out.add(device, {map, 0}, 0, 1);
  for (std::size_t i = 0; i < r.entries.size(); ++i) {
    out.add(device, {map, static_cast<std::uint8_t>(i + 1U)}, r.entries[i].to_u32(), 4);
  }
  if (!r.entries.empty())
    out.add(device, {map, 0}, static_cast<std::uint32_t>(r.entries.size()), 1);
  out.add(device, {comm, 1}, cob_valid, 4);
  return out.count_;
}

} // namespace fieldcodec::master
