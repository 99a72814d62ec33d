// A scripted CANopen device for the master tests: the SDO server over the generated XENAX CAN
// dictionary, with NMT, boot-up and faults to order (abort a request, stay silent, change a
// value behind the master's back, answer with another identity).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <vector>

namespace sim {

namespace co = fieldcodec::canopen;
namespace csdo = fieldcodec::canopen::sdo;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;

inline constexpr auto xcan_layout = co::make_layout<xcan::dictionary.size()>(xcan::dictionary);

struct device {
  std::uint8_t node;
  std::vector<std::uint8_t> storage = std::vector<std::uint8_t>(xcan_layout.storage_size());
  co::dictionary_store<> store{xcan::dictionary, xcan_layout, storage};
  std::array<std::uint8_t, 256> buffer{};
  csdo::server<co::dictionary_store<>> server{node, store, buffer};
  co::nmt::state nmt = co::nmt::state::pre_operational;

  // misbehaviour
  std::optional<fieldcodec::od::address> abort_at{}; ///< abort requests on this object
  csdo::abort_code abort_code = csdo::abort_code::general_error;
  int aborts = 0;                                     ///< how many times (then it accepts)
  int silent = 0;                                     ///< requests not answered
  std::optional<fieldcodec::od::address> tamper_at{}; ///< after a write, the device changes it
  bool boots_on_reset = true;
  std::vector<co::can_frame> seen{}; ///< every frame the device received
  /// UNSIGNED32 objects the XENAX dictionary lacks (1020h, 1F56h, 1011h ...), expedited only.
  std::map<fieldcodec::od::address, std::uint32_t> extra{};
  bool answers_guarding = false; ///< node guarding requests are answered
  co::nmt::guard_responder guard{node};
  int resets = 0; ///< NMT reset node / reset communication received

  explicit device(std::uint8_t n) : node(n) { REQUIRE(store.init_defaults(node).has_value()); }

  void set_u32(fieldcodec::od::address a, std::uint32_t v) {
    std::array<std::uint8_t, 4> b{};
    for (std::size_t i = 0; i < 4U; ++i) b[i] = static_cast<std::uint8_t>(v >> (8U * i));
    const auto n = store.value(a).value().size();
    REQUIRE(store.set(a, std::span<const std::uint8_t>(b).first(n)) == csdo::abort_code::none);
  }
  std::uint64_t get(fieldcodec::od::address a) {
    const auto v = store.value(a).value();
    std::uint64_t r = 0;
    for (std::size_t i = 0; i < v.size() && i < 8U; ++i) r |= std::uint64_t{v[i]} << (8U * i);
    return r;
  }

  /// The device's answers to one frame.
  std::vector<co::can_frame> receive(const co::can_frame &f) {
    seen.push_back(f);
    std::vector<co::can_frame> out;
    if (f.id == 0x000U && f.dlc == 2U && (f.data[1] == node || f.data[1] == 0U)) {
      if (f.data[0] == 0x01U) nmt = co::nmt::state::operational;
      if (f.data[0] == 0x80U) nmt = co::nmt::state::pre_operational;
      if (f.data[0] == 0x81U || f.data[0] == 0x82U) {
        ++resets;
        guard.reset();
      }
      if ((f.data[0] == 0x81U || f.data[0] == 0x82U) && boots_on_reset) {
        nmt = co::nmt::state::pre_operational;
        out.push_back(co::nmt::encode_boot_up(node).value());
      }
      return out;
    }
    if (f.rtr && f.id == 0x700U + node) {
      if (answers_guarding) out.push_back(guard.respond(f, nmt).value());
      return out;
    }
    if (f.id != 0x600U + node) return out;
    if (silent > 0) {
      --silent;
      return out;
    }
    const auto m = csdo::decode(f, csdo::direction::to_server);
    if (m && extra.count(m.value().address) != 0U) {
      const auto a = m.value().address;
      std::array<std::uint8_t, 8> b{0x60, static_cast<std::uint8_t>(a.index),
                                    static_cast<std::uint8_t>(a.index >> 8U), a.sub};
      if (m.value().type == csdo::message_type::initiate_upload_request) {
        b[0] = 0x43; // expedited, 4 bytes
        for (std::size_t i = 0; i < 4U; ++i)
          b[4 + i] = static_cast<std::uint8_t>(extra[a] >> (8U * i));
      } else {
        std::uint32_t v = 0;
        for (std::size_t i = 0; i < 4U; ++i) v |= std::uint32_t{f.data[4 + i]} << (8U * i);
        extra[a] = v;
      }
      out.push_back(co::make_frame(static_cast<std::uint16_t>(0x580U + node), b).value());
      return out;
    }
    const bool initiate = m && (m.value().type == csdo::message_type::initiate_download_request ||
                                m.value().type == csdo::message_type::initiate_upload_request);
    if (initiate && abort_at && m.value().address == *abort_at && aborts > 0) {
      --aborts;
      out.push_back(co::make_frame(static_cast<std::uint16_t>(0x580U + node),
                                   csdo::abort(*abort_at, abort_code))
                        .value());
      return out;
    }
    const auto r = server.on_frame(f, 0);
    for (const auto &g : r.send) out.push_back(g);
    if (tamper_at && server.state() == csdo::transfer_state::done &&
        m.value().address == *tamper_at &&
        m.value().type == csdo::message_type::initiate_download_request) {
      set_u32(*tamper_at, static_cast<std::uint32_t>(get(*tamper_at) + 1U));
    }
    return out;
  }
};

} // namespace sim
