// Benchmarks of CANopen SDO block transfer (issue 18) against hand-written equivalents: server
// upload, client download and server download of 889 bytes (per byte = Ir per transfer / 889),
// each over a dictionary_store.
//
// Every operation is one complete exchange, so that every call does the same work: a block
// transfer of 889 bytes (one sub-block of 127 segments) from the initiate request to the end
// response, with every frame the machine sends copied into the result (the transmit queue). The
// machines and the store live in globals (the lambdas are captureless); the inputs select which
// of several objects a call works on. The PDO engine is measured by codec_pdo_engine.cpp, a
// translation unit of its own so that one group's inlining does not move the other's rows.
#include "codec_harness.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <span>
#include <vector>

namespace {

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
using sdo::abort_code;

// ---------------------------------------------------------------------------------------------
// The hand-written block CRC: CRC-16/XMODEM by a 256-entry table, as CANopenNode's
// crc16-ccitt.c computes it.

constexpr std::array<std::uint16_t, 256> crc_table = [] {
  std::array<std::uint16_t, 256> t{};
  for (unsigned i = 0; i < 256U; ++i) {
    unsigned r = i << 8U;
    for (int k = 0; k < 8; ++k) r = (r & 0x8000U) != 0U ? (r << 1U) ^ 0x1021U : r << 1U;
    t[i] = static_cast<std::uint16_t>(r & 0xFFFFU);
  }
  return t;
}();

inline std::uint16_t hand_crc(const std::uint8_t *p, std::size_t n, std::uint16_t crc) {
  for (std::size_t i = 0; i < n; ++i) {
    crc = static_cast<std::uint16_t>((crc << 8U) ^ crc_table[((crc >> 8U) ^ p[i]) & 0xFFU]);
  }
  return crc;
}

// ---------------------------------------------------------------------------------------------
// SDO block transfer: 889 bytes = one sub-block of 127 segments

constexpr std::uint8_t sdo_node = 5;
constexpr std::size_t block_bytes = 127U * 7U; // 889
constexpr std::size_t value_count = 16; // uploads from 3000h..300Fh, downloads to 3010h..301Fh

/// Every frame one transfer sent, in order (the transmit queue), and how it ended.
struct transfer_out {
  std::array<co::can_frame, 130> tx{};
  std::size_t n = 0;
  bool done = false;
  bool operator==(const transfer_out &) const = default;
  void push(const co::can_frame &f) {
    if (n < tx.size()) tx[n++] = f;
  }
};

struct transfer_in {
  std::uint8_t object = 0; ///< 0..value_count-1: object 3000h + object
  bool operator==(const transfer_in &) const = default;
};

bench::inputs<transfer_in> g_transfers;

constexpr std::array<od::entry_spec, 2 * value_count> make_block_specs() {
  std::array<od::entry_spec, 2 * value_count> e{};
  for (std::size_t i = 0; i < e.size(); ++i) {
    e[i] = od::entry_spec{.index = static_cast<std::uint16_t>(0x3000U + i),
                          .type = od::data_type::domain,
                          .access_type = od::access::rw,
                          .size = block_bytes};
  }
  return e;
}
constexpr auto block_specs = make_block_specs();
constexpr auto block_entries = od::entries_of<block_specs>;
constexpr od::dictionary block_dict{block_entries};
constexpr auto block_layout = co::make_layout<2 * value_count>(block_dict);

using store_type = co::dictionary_store<>;

/// The values of the objects (the hand-written side reads them where the store keeps them).
std::vector<std::uint8_t> g_block_storage(block_layout.storage_size());
store_type g_block_store{block_dict, block_layout, g_block_storage};
std::array<std::uint8_t, block_bytes> g_server_buffer{};
/// A download's buffer: the server asks for sub-blocks of what fits the room left in it, so
/// with 2 × 889 bytes it takes 127 segments and asks for 127 more after them, as the
/// hand-written server does.
std::array<std::uint8_t, 2 * block_bytes> g_download_buffer{};
/// The data of a download (the client side), one per object.
std::array<std::array<std::uint8_t, block_bytes>, value_count> g_download_data{};

const std::uint8_t *stored_value(std::uint8_t object) {
  return g_block_storage.data() + block_layout.offsets[object] + co::length_prefix;
}

constexpr od::address object_address(std::uint8_t object) {
  return {static_cast<std::uint16_t>(0x3000U + object), 0};
}
/// The object a download of data `o` goes to.
constexpr od::address download_address(std::uint8_t o) {
  return {static_cast<std::uint16_t>(0x3000U + value_count + o), 0};
}

co::can_frame request(const sdo::payload &p) {
  return co::can_frame{static_cast<std::uint16_t>(0x600U + sdo_node), false, 8, p};
}
co::can_frame response(const sdo::payload &p) {
  return co::can_frame{static_cast<std::uint16_t>(0x580U + sdo_node), false, 8, p};
}

/// The requests of a client that reads object `o` with block upload (CRC as given, sub-blocks
/// of 127 segments), and the answers of a server to a block download.
struct upload_requests {
  co::can_frame initiate, start, ack, end_response;
};
std::array<upload_requests, value_count> g_upload_crc{};
std::array<upload_requests, value_count> g_upload_plain{};

struct download_responses {
  co::can_frame initiate, ack, end_response;
};
std::array<download_responses, value_count> g_download_crc{};
std::array<download_responses, value_count> g_download_plain{};

/// The frames of a client that writes g_download_data[o] to object `o` with block download:
/// initiate (size indicated), 127 segments, end (unused bytes, CRC).
struct download_requests {
  co::can_frame initiate;
  std::array<co::can_frame, 127> segments;
  co::can_frame end;
};
std::array<download_requests, value_count> g_server_download_crc{};
std::array<download_requests, value_count> g_server_download_plain{};
/// The frames of a server that sends object `o` (g_block_store's value of 3000h + o) with block
/// upload: initiate response (size indicated), 127 segments, end (unused bytes, CRC).
struct upload_responses {
  co::can_frame initiate;
  std::array<co::can_frame, 127> segments;
  co::can_frame end;
};
std::array<upload_responses, value_count> g_client_upload_crc{};
std::array<upload_responses, value_count> g_client_upload_plain{};
/// The client's receive buffer (the client and the hand-written one copy it into the result).
std::array<std::uint8_t, block_bytes> g_upload_buffer{};
/// The values the hand-written server stores (the fieldcodec server writes g_block_store).
std::array<std::array<std::uint8_t, block_bytes>, value_count> g_hand_values{};

void fill_sdo_inputs() {
  bench::rng r(18);
  for (std::size_t i = 0; i < value_count; ++i) {
    std::array<std::uint8_t, block_bytes> v{};
    for (auto &b : v) b = static_cast<std::uint8_t>(r.next());
    const auto o = static_cast<std::uint8_t>(i);
    if (g_block_store.set(object_address(o), v) != abort_code::none) std::abort();
    for (auto &b : g_download_data[i]) b = static_cast<std::uint8_t>(r.next());
    for (const bool crc : {true, false}) {
      auto &u = (crc ? g_upload_crc : g_upload_plain)[i];
      u.initiate = request(sdo::block_upload_initiate(object_address(o), 127, 0, crc).value());
      u.start = request(sdo::block_upload_start());
      u.ack = request(sdo::block_ack(127, 127).value());
      u.end_response = request(sdo::block_end_response());
      auto &d = (crc ? g_download_crc : g_download_plain)[i];
      d.initiate =
          response(sdo::block_download_initiate_response(object_address(o), 127, crc).value());
      d.ack = response(sdo::block_ack(127, 127).value());
      d.end_response = response(sdo::block_end_response());
      auto &w = (crc ? g_server_download_crc : g_server_download_plain)[i];
      w.initiate =
          request(sdo::block_download_initiate(download_address(o), block_bytes, true, crc));
      const auto &data = g_download_data[i];
      for (std::size_t k = 0; k < 127U; ++k) {
        w.segments[k] =
            request(sdo::encode_block_segment(
                        static_cast<std::uint8_t>(k + 1U),
                        std::span<const std::uint8_t>(data).subspan(7U * k, 7U), k == 126U)
                        .value());
      }
      w.end = request(
          sdo::block_end(0, crc ? fieldcodec::crc::ccitt16(data) : std::uint16_t{0}).value());
      auto &y = (crc ? g_client_upload_crc : g_client_upload_plain)[i];
      y.initiate =
          response(sdo::block_upload_initiate_response(object_address(o), block_bytes, true, crc));
      for (std::size_t k = 0; k < 127U; ++k) {
        y.segments[k] =
            response(sdo::encode_block_segment(static_cast<std::uint8_t>(k + 1U),
                                               std::span<const std::uint8_t>(v).subspan(7U * k, 7U),
                                               k == 126U)
                         .value());
      }
      y.end =
          response(sdo::block_end(0, crc ? fieldcodec::crc::ccitt16(v) : std::uint16_t{0}).value());
    }
  }
  for (std::size_t i = 0; i < bench::input_count; ++i) {
    g_transfers[i].object = static_cast<std::uint8_t>(r.below(value_count));
  }
}

/// The transmit queue takes a step's frames the way a driver with a queue would: as many as
/// fit, in one call (frames::copy_to: a burst's segments in one loop, straight into the queue).
void push_all(transfer_out &out, const co::frames &fs) {
  out.n += fs.copy_to(std::span<co::can_frame>(out.tx).subspan(out.n));
}

/// fieldcodec: sdo::server answering a block upload of 889 bytes from the store.
template <bool Crc, class CrcPolicy = fieldcodec::crc::ccitt16_no_table>
transfer_out server_block_upload(const transfer_in &in) {
  transfer_out out;
  const upload_requests &q = (Crc ? g_upload_crc : g_upload_plain)[in.object];
  sdo::server<store_type, CrcPolicy> s(sdo_node, g_block_store, g_server_buffer);
  push_all(out, s.on_frame(q.initiate, 0).send);
  push_all(out, s.on_frame(q.start, 0).send);
  push_all(out, s.on_frame(q.ack, 0).send);
  push_all(out, s.on_frame(q.end_response, 0).send);
  out.done = s.state() == sdo::transfer_state::done;
  return out;
}

/// Hand-written: a server that knows where the object's bytes are. It checks each request's
/// command byte (and the address and block size of the initiate), cuts the value into 127
/// segments (sequence number, | 0x80 on the last; 7 bytes, zero-padded) and computes the CRC
/// by table.
template <bool Crc>
transfer_out hand_block_upload(const transfer_in &in) {
  transfer_out out;
  const upload_requests &q = (Crc ? g_upload_crc : g_upload_plain)[in.object];
  const std::uint8_t *v = stored_value(in.object);
  const auto size = static_cast<std::uint32_t>(block_bytes);
  const auto rid = static_cast<std::uint16_t>(0x580U + sdo_node);
  const od::address a = object_address(in.object);
  // initiate: 0xA0 | crc << 2, index, sub, block size 1..127
  const auto &d0 = q.initiate.data;
  if (q.initiate.dlc != 8U || (d0[0] & 0xE3U) != 0xA0U || (d0[1] | (d0[2] << 8U)) != a.index ||
      d0[3] != a.sub || d0[4] < 1U || d0[4] > 127U) {
    return out;
  }
  const bool crc = Crc && (d0[0] & 0x04U) != 0U;
  const std::uint8_t blksize = d0[4];
  out.push({rid,
            false,
            8,
            {static_cast<std::uint8_t>(0xC2U | (crc ? 0x04U : 0U)), d0[1], d0[2], d0[3],
             static_cast<std::uint8_t>(size), static_cast<std::uint8_t>(size >> 8U),
             static_cast<std::uint8_t>(size >> 16U), static_cast<std::uint8_t>(size >> 24U)}});
  // start: 0xA3, then the sub-block
  if (q.start.dlc != 8U || q.start.data[0] != 0xA3U) return out;
  const std::uint32_t segments = (size + 6U) / 7U;
  const std::uint32_t count = segments < blksize ? segments : blksize;
  for (std::uint32_t k = 0; k < count; ++k) {
    co::can_frame f{rid, false, 8, {}};
    const std::uint32_t at = 7U * k;
    const std::uint32_t n = size - at < 7U ? size - at : 7U;
    f.data[0] = static_cast<std::uint8_t>((k + 1U) | (k + 1U == segments ? 0x80U : 0U));
    std::memcpy(&f.data[1], v + at, n);
    out.push(f);
  }
  // acknowledgement: 0xA2, all 127 received: the end with the CRC
  if (q.ack.dlc != 8U || q.ack.data[0] != 0xA2U || q.ack.data[1] != count) return out;
  const std::uint16_t c = crc ? hand_crc(v, size, 0) : std::uint16_t{0};
  const auto unused = static_cast<std::uint8_t>(7U * segments - size);
  out.push({rid,
            false,
            8,
            {static_cast<std::uint8_t>(0xC1U | (unused << 2U)), static_cast<std::uint8_t>(c),
             static_cast<std::uint8_t>(c >> 8U), 0, 0, 0, 0, 0}});
  // end response: 0xA1
  out.done = q.end_response.dlc == 8U && q.end_response.data[0] == 0xA1U;
  return out;
}

/// fieldcodec: sdo::client downloading 889 bytes with block transfer.
template <bool Crc, class CrcPolicy = fieldcodec::crc::ccitt16_no_table>
transfer_out client_block_download(const transfer_in &in) {
  transfer_out out;
  const download_responses &q = (Crc ? g_download_crc : g_download_plain)[in.object];
  sdo::basic_client<CrcPolicy> c(sdo_node);
  sdo::block_options o;
  o.crc = Crc;
  auto s = c.block_download(object_address(in.object), g_download_data[in.object], 0, o);
  if (!s) return out;
  push_all(out, s.value().send);
  push_all(out, c.on_frame(q.initiate, 0).send);
  push_all(out, c.on_frame(q.ack, 0).send);
  push_all(out, c.on_frame(q.end_response, 0).send);
  out.done = c.state() == sdo::transfer_state::done;
  return out;
}

/// Hand-written: the client side of the same download.
template <bool Crc>
transfer_out hand_block_download(const transfer_in &in) {
  transfer_out out;
  const download_responses &q = (Crc ? g_download_crc : g_download_plain)[in.object];
  const std::uint8_t *v = g_download_data[in.object].data();
  const auto size = static_cast<std::uint32_t>(block_bytes);
  const auto rid = static_cast<std::uint16_t>(0x600U + sdo_node);
  const od::address a = object_address(in.object);
  // initiate: 0xC2 | crc << 2 (size indicated), index, sub, size
  out.push({rid,
            false,
            8,
            {static_cast<std::uint8_t>(0xC2U | (Crc ? 0x04U : 0U)),
             static_cast<std::uint8_t>(a.index), static_cast<std::uint8_t>(a.index >> 8U), a.sub,
             static_cast<std::uint8_t>(size), static_cast<std::uint8_t>(size >> 8U),
             static_cast<std::uint8_t>(size >> 16U), static_cast<std::uint8_t>(size >> 24U)}});
  // initiate response: 0xA0 | crc << 2, the same address, block size 1..127
  const auto &d0 = q.initiate.data;
  if (q.initiate.dlc != 8U || (d0[0] & 0xFBU) != 0xA0U || (d0[1] | (d0[2] << 8U)) != a.index ||
      d0[3] != a.sub || d0[4] < 1U || d0[4] > 127U) {
    return out;
  }
  const bool crc = Crc && (d0[0] & 0x04U) != 0U;
  const std::uint32_t segments = (size + 6U) / 7U;
  const std::uint32_t count = segments < d0[4] ? segments : d0[4];
  for (std::uint32_t k = 0; k < count; ++k) {
    co::can_frame f{rid, false, 8, {}};
    const std::uint32_t at = 7U * k;
    const std::uint32_t n = size - at < 7U ? size - at : 7U;
    f.data[0] = static_cast<std::uint8_t>((k + 1U) | (k + 1U == segments ? 0x80U : 0U));
    std::memcpy(&f.data[1], v + at, n);
    out.push(f);
  }
  // acknowledgement of all 127: the end with the CRC
  if (q.ack.dlc != 8U || q.ack.data[0] != 0xA2U || q.ack.data[1] != count) return out;
  const std::uint16_t c = crc ? hand_crc(v, size, 0) : std::uint16_t{0};
  const auto unused = static_cast<std::uint8_t>(7U * segments - size);
  out.push({rid,
            false,
            8,
            {static_cast<std::uint8_t>(0xC1U | (unused << 2U)), static_cast<std::uint8_t>(c),
             static_cast<std::uint8_t>(c >> 8U), 0, 0, 0, 0, 0}});
  out.done = q.end_response.dlc == 8U && q.end_response.data[0] == 0xA1U;
  return out;
}

/// What a block download left behind: the frames the server sent and the stored value.
struct download_out {
  transfer_out frames;
  std::array<std::uint8_t, block_bytes> value{};
  bool operator==(const download_out &) const = default;
};

/// fieldcodec: sdo::server taking a block download of 889 bytes into the store.
template <bool Crc, class CrcPolicy = fieldcodec::crc::ccitt16_no_table>
download_out server_block_download(const transfer_in &in) {
  download_out out;
  const download_requests &q = (Crc ? g_server_download_crc : g_server_download_plain)[in.object];
  sdo::server<store_type, CrcPolicy> s(sdo_node, g_block_store, g_download_buffer);
  push_all(out.frames, s.on_frame(q.initiate, 0).send);
  for (const co::can_frame &f : q.segments) push_all(out.frames, s.on_frame(f, 0).send);
  push_all(out.frames, s.on_frame(q.end, 0).send);
  out.frames.done = s.state() == sdo::transfer_state::done;
  std::memcpy(out.value.data(), stored_value(static_cast<std::uint8_t>(value_count + in.object)),
              block_bytes);
  return out;
}

/// fieldcodec: the same download with the segments handed over the way a CAN driver drains its
/// receive FIFO: `Batch` frames at a time (127: the whole sub-block), each batch through
/// server::on_frames until it is used up (it stops at a frame that answers: the caller sends
/// the answer and goes on with the rest). The initiate and the end come alone (the client
/// waits for the answer before it sends on), through on_frame.
template <std::size_t Batch, bool Crc, class CrcPolicy = fieldcodec::crc::ccitt16_no_table>
download_out server_block_download_batch(const transfer_in &in) {
  download_out out;
  const download_requests &q = (Crc ? g_server_download_crc : g_server_download_plain)[in.object];
  sdo::server<store_type, CrcPolicy> s(sdo_node, g_block_store, g_download_buffer);
  push_all(out.frames, s.on_frame(q.initiate, 0).send);
  for (std::span<const co::can_frame> fifo(q.segments); !fifo.empty();) {
    std::span<const co::can_frame> rx = fifo.first(fifo.size() < Batch ? fifo.size() : Batch);
    fifo = fifo.subspan(rx.size());
    while (!rx.empty()) {
      const sdo::batch_step b = s.on_frames(rx, 0);
      push_all(out.frames, b.last.send);
      rx = rx.subspan(b.consumed);
    }
  }
  push_all(out.frames, s.on_frame(q.end, 0).send);
  out.frames.done = s.state() == sdo::transfer_state::done;
  std::memcpy(out.value.data(), stored_value(static_cast<std::uint8_t>(value_count + in.object)),
              block_bytes);
  return out;
}

/// The node around the server (round 6): node::device over the same store, one SDO server with
/// the download buffer's 2 × 889 bytes, started once in main (pre-operational: SDO served).
constexpr auto device_capacity = [] {
  auto c = co::node::capacity_for(block_dict);
  c.sdo_buffer = 2U * block_bytes;
  return c;
}();
using device_type = co::node::device<store_type, device_capacity>;
device_type g_device{g_block_store, sdo_node};

/// fieldcodec: the same download through node::device::on_frames, `Batch` frames a call as in
/// server_block_download_batch; the initiate and the end through device::on_frame. The device
/// routes each frame (NMT, SYNC, SDO servers, heartbeats, PDOs) and builds its own step.
/// Batch 0: every segment through device::on_frame (the device's path before round 6).
template <std::size_t Batch>
download_out device_block_download_batch(const transfer_in &in) {
  download_out out;
  const download_requests &q = g_server_download_plain[in.object];
  push_all(out.frames, g_device.on_frame(q.initiate, 0).send);
  if constexpr (Batch == 0U) {
    for (const co::can_frame &f : q.segments) push_all(out.frames, g_device.on_frame(f, 0).send);
  }
  for (std::span<const co::can_frame> fifo(Batch == 0U
                                               ? std::span<const co::can_frame>{}
                                               : std::span<const co::can_frame>(q.segments));
       !fifo.empty();) {
    std::span<const co::can_frame> rx = fifo.first(fifo.size() < Batch ? fifo.size() : Batch);
    fifo = fifo.subspan(rx.size());
    while (!rx.empty()) {
      const auto b = g_device.on_frames(rx, 0);
      push_all(out.frames, b.last.send);
      rx = rx.subspan(b.consumed);
    }
  }
  push_all(out.frames, g_device.on_frame(q.end, 0).send);
  out.frames.done = g_device.sdo().server(0).state() == sdo::transfer_state::done;
  std::memcpy(out.value.data(), stored_value(static_cast<std::uint8_t>(value_count + in.object)),
              block_bytes);
  return out;
}

/// What a block upload left behind: the frames the client sent and the value it received.
struct upload_out {
  transfer_out frames;
  std::array<std::uint8_t, block_bytes> value{};
  bool operator==(const upload_out &) const = default;
};

/// fieldcodec: sdo::client reading 889 bytes with block upload (sub-blocks of 127), each
/// received frame through on_frame.
template <bool Crc, class CrcPolicy = fieldcodec::crc::ccitt16_no_table>
upload_out client_block_upload(const transfer_in &in) {
  upload_out out;
  const upload_responses &q = (Crc ? g_client_upload_crc : g_client_upload_plain)[in.object];
  sdo::basic_client<CrcPolicy> c(sdo_node);
  sdo::block_options o;
  o.crc = Crc;
  auto s = c.block_upload(object_address(in.object), g_upload_buffer, 0, o);
  if (!s) return out;
  push_all(out.frames, s.value().send);
  push_all(out.frames, c.on_frame(q.initiate, 0).send);
  for (const co::can_frame &f : q.segments) push_all(out.frames, c.on_frame(f, 0).send);
  push_all(out.frames, c.on_frame(q.end, 0).send);
  out.frames.done = c.state() == sdo::transfer_state::done;
  const auto v = c.received();
  std::memcpy(out.value.data(), v.data(), v.size() < block_bytes ? v.size() : block_bytes);
  return out;
}

/// fieldcodec: the same upload with the segments handed over the way a CAN driver drains its
/// receive FIFO: `Batch` frames at a time (127: the whole sub-block), each batch through
/// client::on_frames until it is used up (it stops at a frame that answers: the caller sends
/// the answer and goes on with the rest). The initiate response and the end come alone (the
/// server waits for the client's answer before it sends on), through on_frame.
template <std::size_t Batch, bool Crc, class CrcPolicy = fieldcodec::crc::ccitt16_no_table>
upload_out client_block_upload_batch(const transfer_in &in) {
  upload_out out;
  const upload_responses &q = (Crc ? g_client_upload_crc : g_client_upload_plain)[in.object];
  sdo::basic_client<CrcPolicy> c(sdo_node);
  sdo::block_options o;
  o.crc = Crc;
  auto s = c.block_upload(object_address(in.object), g_upload_buffer, 0, o);
  if (!s) return out;
  push_all(out.frames, s.value().send);
  push_all(out.frames, c.on_frame(q.initiate, 0).send);
  for (std::span<const co::can_frame> fifo(q.segments); !fifo.empty();) {
    std::span<const co::can_frame> rx = fifo.first(fifo.size() < Batch ? fifo.size() : Batch);
    fifo = fifo.subspan(rx.size());
    while (!rx.empty()) {
      const sdo::batch_step b = c.on_frames(rx, 0);
      push_all(out.frames, b.last.send);
      rx = rx.subspan(b.consumed);
    }
  }
  push_all(out.frames, c.on_frame(q.end, 0).send);
  out.frames.done = c.state() == sdo::transfer_state::done;
  const auto v = c.received();
  std::memcpy(out.value.data(), v.data(), v.size() < block_bytes ? v.size() : block_bytes);
  return out;
}

/// Hand-written: the client side of the same upload into a buffer (CRC by table).
template <bool Crc>
upload_out hand_block_upload_client(const transfer_in &in) {
  upload_out out;
  const upload_responses &q = (Crc ? g_client_upload_crc : g_client_upload_plain)[in.object];
  std::uint8_t *v = g_upload_buffer.data();
  const auto rid = static_cast<std::uint16_t>(0x600U + sdo_node);
  const od::address a = object_address(in.object);
  // initiate: 0xA0 | crc << 2, index, sub, block size 127
  out.frames.push(
      {rid,
       false,
       8,
       {static_cast<std::uint8_t>(0xA0U | (Crc ? 0x04U : 0U)), static_cast<std::uint8_t>(a.index),
        static_cast<std::uint8_t>(a.index >> 8U), a.sub, 127, 0, 0, 0}});
  // initiate response: 0xC2 | crc << 2 (size indicated), the address, the size
  const auto &d0 = q.initiate.data;
  if (q.initiate.dlc != 8U || (d0[0] & 0xFBU) != 0xC2U || (d0[1] | (d0[2] << 8U)) != a.index ||
      d0[3] != a.sub) {
    return out;
  }
  const std::uint32_t size =
      static_cast<std::uint32_t>(d0[4]) | (static_cast<std::uint32_t>(d0[5]) << 8U) |
      (static_cast<std::uint32_t>(d0[6]) << 16U) | (static_cast<std::uint32_t>(d0[7]) << 24U);
  if (size != block_bytes) return out;
  const bool crc = Crc && (d0[0] & 0x04U) != 0U;
  out.frames.push({rid, false, 8, {0xA3, 0, 0, 0, 0, 0, 0, 0}}); // start
  // 127 segments in sequence, the last one flagged
  std::uint8_t seq = 0;
  for (const co::can_frame &f : q.segments) {
    if (f.dlc != 8U || (f.data[0] & 0x7FU) != seq + 1U) return out;
    seq = static_cast<std::uint8_t>(seq + 1U);
    std::memcpy(v + 7U * (seq - 1U), &f.data[1], 7);
  }
  out.frames.push({rid, false, 8, {0xA2, seq, 127, 0, 0, 0, 0, 0}});
  // end: 0xC1 | unused << 2, CRC
  const auto &e = q.end.data;
  if (q.end.dlc != 8U || (e[0] & 0xE3U) != 0xC1U || ((e[0] >> 2U) & 7U) != 0U) return out;
  if (crc && hand_crc(v, size, 0) != (e[1] | (e[2] << 8U))) return out;
  out.frames.push({rid, false, 8, {0xA1, 0, 0, 0, 0, 0, 0, 0}});
  out.frames.done = true;
  std::memcpy(out.value.data(), v, block_bytes);
  return out;
}

/// Hand-written: the server side of the same download into a value it knows (CRC by table).
template <bool Crc>
download_out hand_server_block_download(const transfer_in &in) {
  download_out out;
  const download_requests &q = (Crc ? g_server_download_crc : g_server_download_plain)[in.object];
  std::uint8_t *v = g_hand_values[in.object].data();
  const auto rid = static_cast<std::uint16_t>(0x580U + sdo_node);
  const od::address a = download_address(in.object);
  // initiate: 0xC2 | crc << 2 (size indicated), the address, the size
  const auto &d0 = q.initiate.data;
  if (q.initiate.dlc != 8U || (d0[0] & 0xFBU) != 0xC2U || (d0[1] | (d0[2] << 8U)) != a.index ||
      d0[3] != a.sub) {
    return out;
  }
  const std::uint32_t size =
      static_cast<std::uint32_t>(d0[4]) | (static_cast<std::uint32_t>(d0[5]) << 8U) |
      (static_cast<std::uint32_t>(d0[6]) << 16U) | (static_cast<std::uint32_t>(d0[7]) << 24U);
  if (size != block_bytes) return out;
  const bool crc = Crc && (d0[0] & 0x04U) != 0U;
  out.frames.push(
      {rid,
       false,
       8,
       {static_cast<std::uint8_t>(0xA0U | (crc ? 0x04U : 0U)), d0[1], d0[2], d0[3], 127, 0, 0, 0}});
  // 127 segments in sequence, the last one flagged
  std::array<std::uint8_t, block_bytes> staged{};
  std::uint8_t seq = 0;
  for (const co::can_frame &f : q.segments) {
    if (f.dlc != 8U || (f.data[0] & 0x7FU) != seq + 1U) return out;
    seq = static_cast<std::uint8_t>(seq + 1U);
    std::memcpy(staged.data() + 7U * (seq - 1U), &f.data[1], 7);
  }
  out.frames.push({rid, false, 8, {0xA2, seq, 127, 0, 0, 0, 0, 0}});
  // end: 0xC1 | unused << 2, CRC
  const auto &e = q.end.data;
  if (q.end.dlc != 8U || (e[0] & 0xE3U) != 0xC1U || ((e[0] >> 2U) & 7U) != 0U) return out;
  if (crc && hand_crc(staged.data(), size, 0) != (e[1] | (e[2] << 8U))) return out;
  std::memcpy(v, staged.data(), size);
  out.frames.push({rid, false, 8, {0xA1, 0, 0, 0, 0, 0, 0, 0}});
  out.frames.done = true;
  std::memcpy(out.value.data(), v, block_bytes);
  return out;
}

using with_table = fieldcodec::crc::ccitt16_with_table;

void add_sdo(bench::registry &reg) {
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, server, CRC",
      [](const transfer_in &in) { return server_block_upload<true>(in); },
      [](const transfer_in &in) { return hand_block_upload<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, server, no CRC",
      [](const transfer_in &in) { return server_block_upload<false>(in); },
      [](const transfer_in &in) { return hand_block_upload<false>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, client, CRC",
      [](const transfer_in &in) { return client_block_download<true>(in); },
      [](const transfer_in &in) { return hand_block_download<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, client, no CRC",
      [](const transfer_in &in) { return client_block_download<false>(in); },
      [](const transfer_in &in) { return hand_block_download<false>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, server, CRC",
      [](const transfer_in &in) { return server_block_download<true>(in); },
      [](const transfer_in &in) { return hand_server_block_download<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, server, no CRC",
      [](const transfer_in &in) { return server_block_download<false>(in); },
      [](const transfer_in &in) { return hand_server_block_download<false>(in); });
  // the machines with the opt-in CRC table (crc::ccitt16_with_table), as the baselines compute it
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, server, CRC table",
      [](const transfer_in &in) { return server_block_upload<true, with_table>(in); },
      [](const transfer_in &in) { return hand_block_upload<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, client, CRC table",
      [](const transfer_in &in) { return client_block_download<true, with_table>(in); },
      [](const transfer_in &in) { return hand_block_download<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, server, CRC table",
      [](const transfer_in &in) { return server_block_download<true, with_table>(in); },
      [](const transfer_in &in) { return hand_server_block_download<true>(in); });
  // the client's block upload (round 6): 127 segments into the client's buffer
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, client, no CRC",
      [](const transfer_in &in) { return client_block_upload<false>(in); },
      [](const transfer_in &in) { return hand_block_upload_client<false>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, client, CRC",
      [](const transfer_in &in) { return client_block_upload<true>(in); },
      [](const transfer_in &in) { return hand_block_upload_client<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, client, CRC table",
      [](const transfer_in &in) { return client_block_upload<true, with_table>(in); },
      [](const transfer_in &in) { return hand_block_upload_client<true>(in); });
  // the client's upload with the segments in batches (client::on_frames), as the server's
  // download below
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, client, no CRC, on_frames 127",
      [](const transfer_in &in) { return client_block_upload_batch<127, false>(in); },
      [](const transfer_in &in) { return hand_block_upload_client<false>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, client, CRC, on_frames 127",
      [](const transfer_in &in) { return client_block_upload_batch<127, true>(in); },
      [](const transfer_in &in) { return hand_block_upload_client<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, client, CRC table, on_frames 127",
      [](const transfer_in &in) { return client_block_upload_batch<127, true, with_table>(in); },
      [](const transfer_in &in) { return hand_block_upload_client<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, client, no CRC, on_frames 8",
      [](const transfer_in &in) { return client_block_upload_batch<8, false>(in); },
      [](const transfer_in &in) { return hand_block_upload_client<false>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, client, CRC, on_frames 8",
      [](const transfer_in &in) { return client_block_upload_batch<8, true>(in); },
      [](const transfer_in &in) { return hand_block_upload_client<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block upload 889 B, client, CRC table, on_frames 8",
      [](const transfer_in &in) { return client_block_upload_batch<8, true, with_table>(in); },
      [](const transfer_in &in) { return hand_block_upload_client<true>(in); });
  // the server download with the segments in batches (server::on_frames): the whole sub-block
  // of 127 frames in one call, and 8 at a time (a small receive FIFO)
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, server, no CRC, on_frames 127",
      [](const transfer_in &in) { return server_block_download_batch<127, false>(in); },
      [](const transfer_in &in) { return hand_server_block_download<false>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, server, CRC, on_frames 127",
      [](const transfer_in &in) { return server_block_download_batch<127, true>(in); },
      [](const transfer_in &in) { return hand_server_block_download<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, server, CRC table, on_frames 127",
      [](const transfer_in &in) { return server_block_download_batch<127, true, with_table>(in); },
      [](const transfer_in &in) { return hand_server_block_download<true>(in); });
  // the same through the node (node::device::on_frames): what the device adds over the server
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, device, no CRC",
      [](const transfer_in &in) { return device_block_download_batch<0>(in); },
      [](const transfer_in &in) { return hand_server_block_download<false>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, device, no CRC, on_frames 127",
      [](const transfer_in &in) { return device_block_download_batch<127>(in); },
      [](const transfer_in &in) { return hand_server_block_download<false>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, server, no CRC, on_frames 8",
      [](const transfer_in &in) { return server_block_download_batch<8, false>(in); },
      [](const transfer_in &in) { return hand_server_block_download<false>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, server, CRC, on_frames 8",
      [](const transfer_in &in) { return server_block_download_batch<8, true>(in); },
      [](const transfer_in &in) { return hand_server_block_download<true>(in); });
  bench::add<g_transfers>(
      reg, "sdo/block download 889 B, server, CRC table, on_frames 8",
      [](const transfer_in &in) { return server_block_download_batch<8, true, with_table>(in); },
      [](const transfer_in &in) { return hand_server_block_download<true>(in); });
}

bool complete_transfers() {
  const transfer_in in{};
  const transfer_out outs[] = {server_block_upload<true>(in),
                               server_block_upload<false>(in),
                               server_block_upload<true, with_table>(in),
                               client_block_download<true>(in),
                               client_block_download<false>(in),
                               client_block_download<true, with_table>(in)};
  for (const auto &o : outs) {
    if (!o.done || o.n != 129U) {
      std::fprintf(stderr, "codec_sdo_block: a block transfer did not complete (%zu frames)\n",
                   o.n);
      return false;
    }
  }
  // the server download: initiate response, one acknowledgement, end response, and the value
  for (const auto &d :
       {server_block_download<true>(in), server_block_download<false>(in),
        server_block_download<true, with_table>(in), server_block_download_batch<127, false>(in),
        server_block_download_batch<127, true>(in),
        server_block_download_batch<127, true, with_table>(in),
        server_block_download_batch<8, false>(in), server_block_download_batch<8, true>(in),
        server_block_download_batch<8, true, with_table>(in), device_block_download_batch<0>(in),
        device_block_download_batch<127>(in)}) {
    if (!d.frames.done || d.frames.n != 3U || d.value != g_download_data[in.object]) {
      std::fprintf(stderr, "codec_sdo_block: a block download did not complete\n");
      return false;
    }
  }
  // the client upload: initiate, start, acknowledgement, end response, and the value
  for (const auto &u :
       {client_block_upload<true>(in), client_block_upload<false>(in),
        client_block_upload<true, with_table>(in), client_block_upload_batch<127, false>(in),
        client_block_upload_batch<127, true>(in),
        client_block_upload_batch<127, true, with_table>(in),
        client_block_upload_batch<8, false>(in), client_block_upload_batch<8, true>(in),
        client_block_upload_batch<8, true, with_table>(in)}) {
    if (!u.frames.done || u.frames.n != 4U ||
        std::memcmp(u.value.data(), stored_value(in.object), block_bytes) != 0) {
      std::fprintf(stderr, "codec_sdo_block: a block upload (client) did not complete\n");
      return false;
    }
  }
  return true;
}

} // namespace

int main(int argc, char **argv) {
  if (!g_block_store.init_defaults(sdo_node)) return 2;
  if (!g_device.start(0)) return 2;
  fill_sdo_inputs();
  bench::registry reg;
  bench::add_harness<g_transfers>(reg);
  add_sdo(reg);
  if (!complete_transfers()) return 1;
  return bench::main(argc, argv, reg);
}
