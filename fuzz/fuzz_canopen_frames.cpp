// Fuzz harness for the CANopen frame decoders (canopen/): COB-ID classification, NMT,
// heartbeat / boot-up, node guarding, EMCY, SYNC, TIME and every SDO frame.
//
// The input is a sequence of 11-byte CAN frames: id (2 bytes, little-endian, not masked: ids
// above 0x7FF must be refused) | flags (bit 0 RTR, bits 1-4 DLC 0..15) | 8 data bytes. Every
// frame goes through every decoder; a guard monitor and responder also see the sequence.
//
// Property: what decodes re-encodes (with the module's own encoder) to the canonical frame, and
// that decodes to the same value. Canonical frame: the same id, RTR and DLC, the data bytes
// beyond the DLC cleared (all of them for a remote frame). For SDO frames, additionally (CiA
// 301 bit fields the decoder ignores): reserved bits of byte 0 cleared (bit 4 of initiate /
// abort / block-less commands, bits 0-3 of segment requests without data, the n bits when e = 0
// or s = 0), and bytes that carry nothing cleared (bytes 4-7 of an initiate upload request /
// initiate download response / initiate without size, expedited bytes beyond the size, segment
// bytes beyond the data). A non-last segment with fewer than 7 data bytes decodes (the machines
// accept it) but has no canonical form: the segment encoders refuse it with bad_length. Block
// transfer frames are decoded only as far as their multiplexer. On Linux the frames also go
// through the SocketCAN conversions (see check_socketcan).
#include "check.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sync.hpp>
#include <fieldcodec/canopen/time_stamp.hpp>
#include <fieldcodec/host/socketcan.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace fc = fieldcodec;
namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
using fc::errc;

namespace {

co::can_frame canonical(const co::can_frame &f) {
  co::can_frame c = f;
  for (std::size_t i = f.rtr ? 0U : f.dlc; i < c.data.size(); ++i) c.data[i] = 0;
  return c;
}

template <class R>
void same_frame(const R &encoded, const co::can_frame &canon) {
  FUZZ_CHECK(encoded.has_value());
  FUZZ_CHECK(encoded.value() == canon);
  FUZZ_CHECK(encoded.value().is_valid());
}

void check_classify(const co::can_frame &f) {
  auto c = co::classify(f.id);
  if (f.id > co::max_can_id) {
    FUZZ_CHECK(c.is(errc::invalid_argument));
    return;
  }
  FUZZ_CHECK(c.has_value());
  const auto [fn, node] = c.value();
  using co::function;
  std::optional<fc::result<std::uint16_t>> id;
  switch (fn) {
  case function::emcy: id = co::cob_id::emcy(node); break;
  case function::tpdo1: id = co::cob_id::tpdo(1, node); break;
  case function::rpdo1: id = co::cob_id::rpdo(1, node); break;
  case function::tpdo2: id = co::cob_id::tpdo(2, node); break;
  case function::rpdo2: id = co::cob_id::rpdo(2, node); break;
  case function::tpdo3: id = co::cob_id::tpdo(3, node); break;
  case function::rpdo3: id = co::cob_id::rpdo(3, node); break;
  case function::tpdo4: id = co::cob_id::tpdo(4, node); break;
  case function::rpdo4: id = co::cob_id::rpdo(4, node); break;
  case function::sdo_tx: id = co::cob_id::sdo_tx(node); break;
  case function::sdo_rx: id = co::cob_id::sdo_rx(node); break;
  case function::nmt_error: id = co::cob_id::nmt_error(node); break;
  case function::nmt: FUZZ_CHECK(f.id == co::cob_id::nmt && node == 0); break;
  case function::sync: FUZZ_CHECK(f.id == co::cob_id::sync && node == 0); break;
  case function::time: FUZZ_CHECK(f.id == co::cob_id::time && node == 0); break;
  case function::unassigned: FUZZ_CHECK(node == 0); break;
  }
  if (id) FUZZ_CHECK(id->has_value() && id->value() == f.id);
  FUZZ_CHECK(co::to_string(fn).size() > 0);
}

void check_nmt(const co::can_frame &f, const co::can_frame &canon) {
  if (auto m = co::nmt::decode(f)) {
    same_frame(co::nmt::encode(m.value().cs, m.value().node), canon);
    FUZZ_CHECK(co::nmt::decode(canon).value() == m.value());
  }
  if (auto h = co::nmt::decode_heartbeat(f)) {
    const auto &v = h.value();
    same_frame(v.is_boot_up() ? co::nmt::encode_boot_up(v.node)
                              : co::nmt::encode_heartbeat(v.node, v.s),
               canon);
    FUZZ_CHECK(co::nmt::decode_heartbeat(canon).value() == v);
  }
  if (auto n = co::nmt::decode_guard_request(f)) {
    // A remote frame carries no data, and the request is accepted with any DLC (masters send
    // DLC 0 or 1): the encoder's canonical form is id, RTR, DLC 1.
    co::can_frame request = canon;
    request.dlc = 1;
    same_frame(co::nmt::encode_guard_request(n.value()), request);
  }
  if (auto g = co::nmt::decode_guard_response(f)) {
    const auto &v = g.value();
    same_frame(co::nmt::encode_guard_response(v.node, v.s, v.toggle), canon);
    FUZZ_CHECK(co::nmt::decode_guard_response(canon).value() == v);
  }
}

void check_emcy_sync_time(const co::can_frame &f, const co::can_frame &canon) {
  if (auto e = co::emcy::decode(f)) {
    same_frame(co::emcy::encode(e.value().node, e.value().m), canon);
    FUZZ_CHECK(co::emcy::decode(canon).value() == e.value());
    (void)co::emcy::classify(e.value().m.error_code);
  }
  if (auto s = co::sync::decode(f)) {
    if (s.value()) {
      same_frame(co::sync::encode(*s.value()), canon);
    } else {
      FUZZ_CHECK(co::sync::encode() == canon);
    }
  }
  if (auto t = co::time_stamp::decode(f)) {
    same_frame(co::time_stamp::encode(t.value()), canon);
    const auto back = co::time_stamp::decode(canon).value();
    FUZZ_CHECK(back.ms == t.value().ms && back.days == t.value().days);
  }
}

/// The canonical form of an SDO frame (see the header comment).
co::can_frame sdo_canonical(const co::can_frame &canon, const sdo::message &m) {
  co::can_frame c = canon;
  auto &d = c.data;
  const auto clear = [&d](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) d[i] = 0;
  };
  using t = sdo::message_type;
  switch (m.type) {
  case t::initiate_download_request:
  case t::initiate_upload_response: {
    const auto ccs = static_cast<std::uint8_t>(d[0] & 0xE0U);
    if (m.expedited) {
      d[0] = static_cast<std::uint8_t>(ccs | (m.size_indicated ? ((4U - m.size) << 2U) | 3U : 2U));
      clear(4U + m.size, 8);
    } else {
      d[0] = static_cast<std::uint8_t>(ccs | (m.size_indicated ? 1U : 0U));
      if (!m.size_indicated) clear(4, 8);
    }
    break;
  }
  case t::download_segment_request:
  case t::upload_segment_response:
    d[0] =
        static_cast<std::uint8_t>((d[0] & 0xF0U) | ((7U - m.data_size) << 1U) | (m.last ? 1U : 0U));
    clear(1U + m.data_size, 8);
    break;
  case t::initiate_upload_request:
  case t::initiate_download_response:
    d[0] = static_cast<std::uint8_t>(d[0] & 0xE0U);
    clear(4, 8);
    break;
  case t::upload_segment_request:
  case t::download_segment_response:
    d[0] = static_cast<std::uint8_t>(d[0] & 0xF0U);
    clear(1, 8);
    break;
  case t::abort: d[0] = 0x80U; break;
  default: break;
  }
  return c;
}

void check_sdo(const co::can_frame &f, const co::can_frame &canon) {
  auto req = sdo::decode(f, sdo::direction::to_server);
  auto rsp = sdo::decode(f, sdo::direction::to_client);
  if (f.rtr && f.id <= co::max_can_id && f.dlc <= co::max_dlc) {
    FUZZ_CHECK(req.is(errc::unexpected_frame) && rsp.is(errc::unexpected_frame));
  }
  auto a = sdo::decode(f);
  if (!a) {
    FUZZ_CHECK(a.error() == errc::unexpected_frame || a.error() == errc::bad_length ||
               a.error() == errc::unknown_command);
    return;
  }
  const auto &m = a.value().m;
  const bool to_server = a.value().dir == sdo::direction::to_server;
  FUZZ_CHECK(m.data_size <= 7U);
  FUZZ_CHECK(m == (to_server ? req : rsp).value());
  const auto ch = sdo::channel::default_for(a.value().node).value();
  // Re-encoded with the one encoder (the same command table as the decoder).
  auto enc = sdo::encode(m);
  using t = sdo::message_type;
  const bool short_segment =
      (m.type == t::download_segment_request || m.type == t::upload_segment_response) && !m.last &&
      m.data_size != 7U;
  if (short_segment) {
    FUZZ_CHECK(enc.is(errc::bad_length));
    return;
  }
  const bool bad_block_field = // block sizes and sequence numbers the decoder reports as sent
      ((m.type == t::block_download_initiate_response || m.type == t::block_upload_initiate ||
        m.type == t::block_ack) &&
       (m.block_size == 0U || m.block_size > 127U)) ||
      (m.type == t::block_ack && m.sequence > 127U);
  if (bad_block_field) {
    FUZZ_CHECK(enc.is(errc::out_of_range));
    return;
  }
  FUZZ_CHECK(enc.has_value());
  const auto frame = to_server ? ch.request(enc.value()) : ch.response(enc.value());
  FUZZ_CHECK(frame.is_valid());
  const bool block = m.type == t::block_download_initiate || m.type == t::block_upload_initiate ||
                     m.type == t::block_upload_start ||
                     m.type == t::block_download_initiate_response ||
                     m.type == t::block_upload_initiate_response || m.type == t::block_ack ||
                     m.type == t::block_end || m.type == t::block_end_response;
  if (!block) FUZZ_CHECK(frame == sdo_canonical(canon, m));
  // block messages: their canonical form is what the encoder writes; it decodes to the same
  // message and encodes to itself
  auto back = sdo::decode(frame);
  FUZZ_CHECK(back.has_value() && back.value().node == a.value().node &&
             back.value().dir == a.value().dir && back.value().m == m);
  FUZZ_CHECK(sdo::encode(back.value().m).value() == enc.value());
}

#ifdef FIELDCODEC_HAS_SOCKETCAN
/// SocketCAN conversions: a valid frame goes to a struct can_frame and back to its canonical
/// form; a struct read from the input converts only if it is a base frame, and then back to
/// the same identifier, RTR flag, length and data (F10, fixed: identifier bits 11..28 of a
/// struct without CAN_EFF_FLAG are refused, not dropped).
void check_socketcan(const co::can_frame &f, const co::can_frame &canon, const std::uint8_t *p) {
  auto s = fieldcodec::host::to_socketcan(f);
  if (f.id > co::max_can_id) {
    FUZZ_CHECK(s.is(errc::invalid_argument));
  } else if (f.dlc > co::max_dlc) {
    FUZZ_CHECK(s.is(errc::bad_length));
  } else {
    FUZZ_CHECK(s.has_value());
    auto back = fieldcodec::host::from_socketcan(s.value());
    FUZZ_CHECK(back.has_value() && back.value() == canon);
  }
  ::can_frame raw{};
  raw.can_id = static_cast<canid_t>(p[0]) | static_cast<canid_t>(p[1]) << 8U |
               static_cast<canid_t>(p[3]) << 16U | static_cast<canid_t>(p[4]) << 24U;
  raw.can_dlc = static_cast<std::uint8_t>(p[2] >> 1U);
  for (std::size_t i = 0; i < 8; ++i) raw.data[i] = p[3 + i];
  auto g = fieldcodec::host::from_socketcan(raw);
  if (!g) return;
  FUZZ_CHECK((raw.can_id & (CAN_EFF_FLAG | CAN_ERR_FLAG)) == 0U && raw.can_dlc <= 8U);
  FUZZ_CHECK((raw.can_id & CAN_EFF_MASK & ~CAN_SFF_MASK) == 0U);
  auto again = fieldcodec::host::to_socketcan(g.value());
  FUZZ_CHECK(again.has_value());
  FUZZ_CHECK(again.value().can_id == raw.can_id);
  FUZZ_CHECK(again.value().can_dlc == raw.can_dlc);
  if (!g.value().rtr) {
    FUZZ_CHECK(std::equal(raw.data, raw.data + raw.can_dlc, again.value().data));
  }
}
#endif

struct guards {
  co::nmt::guard_monitor monitor{5};
  co::nmt::guard_responder responder{5};

  void step(const co::can_frame &f) {
    const bool before = monitor.expected_toggle();
    auto s = monitor.accept(f);
    auto g = co::nmt::decode_guard_response(f);
    if (s) {
      FUZZ_CHECK(g && g.value().node == 5 && g.value().toggle == before);
      FUZZ_CHECK(monitor.expected_toggle() == !before);
    } else {
      FUZZ_CHECK(monitor.expected_toggle() == before);
    }
    // The responder answers requests to node 5 with alternating toggles the monitor accepts.
    if (auto r = responder.respond(f, co::nmt::state::operational)) {
      co::nmt::guard_monitor m2 = monitor;
      auto t = m2.accept(r.value());
      FUZZ_CHECK(t.has_value() || t.is(errc::bad_toggle));
    }
  }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  guards g;
  for (std::size_t at = 0; at + 11 <= size; at += 11) {
    const std::uint8_t *p = data + at;
    co::can_frame f;
    f.id = static_cast<std::uint16_t>(p[0] | (p[1] << 8U));
    if ((p[1] & 0x80U) == 0U) f.id &= 0x7FFU; // mostly valid identifiers
    f.rtr = (p[2] & 1U) != 0U;
    f.dlc = static_cast<std::uint8_t>((p[2] >> 1U) & 0x0FU);
    for (std::size_t i = 0; i < 8; ++i) f.data[i] = p[3 + i];
    const auto canon = canonical(f);
    check_classify(f);
    check_nmt(f, canon);
    check_emcy_sync_time(f, canon);
    check_sdo(f, canon);
#ifdef FIELDCODEC_HAS_SOCKETCAN
    check_socketcan(f, canon, p);
#endif
    g.step(f);
  }
  return 0;
}
