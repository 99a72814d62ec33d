// Fuzz harness for the SDO transfer machines (canopen/sdo_client.hpp, sdo_server.hpp) and the
// shared transfer core (sdo_transfer.hpp).
//
// Byte 0 selects the mode; then:
//   mode 0  client fed arbitrary frames: transfer setup (see client_mode), then 11-byte frames
//           (id low byte, flags, 8 data bytes, 1 spare: id = 0x585 unless the flags' bit 7 is
//           set, then 0x500 + low byte) and timer ticks; the setup also picks block transfer;
//           a second client gets the same frames through on_frames, the frames of one `now`
//           as one batch;
//   mode 1  server fed arbitrary frames: the same frame format towards 0x605; a second server
//           over a copy of the store gets the same frames through on_frames, the frames of
//           one `now` as one batch;
//   mode 2  loopback: a client and a server talk to each other (download, then upload) with
//           fuzzed data, buffer sizes and object; frames may be dropped or corrupted;
//   mode 3  the same with block transfer (fuzzed block size, CRC on or off, protocol switch
//           threshold).
//
// Properties:
// * Every frame a machine sends is a valid CAN frame on its COB-ID (client 0x600+node, server
//   0x580+node, DLC 8) that the peer's decoder accepts (a block segment: decode_block_segment):
//   a machine never sends a frame it cannot decode itself.
// * The client never reports more bytes than its buffer holds; an upload that completes with a
//   size indicated has exactly that size; after done/failed, frames change nothing; every abort
//   it sends carries the transfer's index/sub and the code error()->abort reports.
// * on_frames is on_frame frame by frame: the frames before the one it stops at answered
//   nothing, that one's step is on_frame's, and both servers and stores (both clients and
//   their received bytes) agree after each call.
// * The store's visible value changes only with the last part of a write (a value is never
//   half-visible); expedited upload responses carry exactly the stored bytes.
// * Loopback without corruption: a download stores exactly the data (or fails because the
//   object is too small, or the server has no buffer at all — a block download: not one
//   segment), and an upload of that object gives back exactly the stored bytes (or fails
//   because the client's buffer is too small, the server's buffer cannot hold one segment, or —
//   a block upload — the sub-block the client asks for). With corruption: no crash, both
//   sides end (no machine is left busy), and the object's value keeps within its capacity.
#include "check.hpp"
#include "sdo_store.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace fc = fieldcodec;
namespace co = fieldcodec::canopen;
namespace od = fieldcodec::od;
namespace sdo = fieldcodec::canopen::sdo;
using fc::errc;

namespace {

constexpr std::uint8_t node = 5;
constexpr sdo::channel channel = sdo::channel::default_for(node).value();

using fuzz_sdo::reader;
using fuzz_sdo::store;

void check_client_frame(const co::can_frame &f, bool segment) {
  FUZZ_CHECK(f.is_valid() && !f.rtr && f.dlc == 8 && f.id == channel.request_id);
  if (segment) {
    FUZZ_CHECK(sdo::decode_block_segment(f.data).has_value());
  } else {
    FUZZ_CHECK(sdo::decode(f, sdo::direction::to_server).has_value());
  }
}
void check_server_frame(const co::can_frame &f, bool segment) {
  FUZZ_CHECK(f.is_valid() && !f.rtr && f.dlc == 8 && f.id == channel.response_id);
  if (segment) {
    FUZZ_CHECK(sdo::decode_block_segment(f.data).has_value());
  } else {
    FUZZ_CHECK(sdo::decode(f, sdo::direction::to_client).has_value());
  }
}
void check_client_step(const sdo::step &s) {
  for (const auto &f : s.send) check_client_frame(f, s.send.is_burst());
}
void check_server_step(const sdo::step &s) {
  for (const auto &f : s.send) check_server_frame(f, s.send.is_burst());
}

co::can_frame frame_from(reader &r, std::uint16_t default_id) {
  co::can_frame f;
  const std::uint8_t lo = r.byte();
  const std::uint8_t flags = r.byte();
  f.id = (flags & 0x80U) != 0U ? static_cast<std::uint16_t>(0x500U + lo) : default_id;
  f.rtr = (flags & 0x40U) != 0U;
  f.dlc = (flags & 0x20U) != 0U ? static_cast<std::uint8_t>(flags & 0x0FU) : std::uint8_t{8};
  for (auto &b : f.data) b = r.byte();
  if (!f.rtr) {
    for (std::size_t i = f.dlc; i < 8; ++i) f.data[i] = 0;
  }
  return f;
}

void client_mode(reader &r) {
  sdo::client c(node, 100);
  const std::uint8_t setup = r.byte();
  std::vector<std::uint8_t> buffer(setup & 0x3FU);
  std::vector<std::uint8_t> data(r.byte() % 40U);
  for (auto &b : data) b = r.byte();
  const od::address a{r.u16(), r.byte()};
  std::uint32_t now = 0;
  const bool upload = (setup & 0x80U) != 0U;
  const bool block = (setup & 0x40U) != 0U;
  sdo::block_options o;
  o.block_size = static_cast<std::uint8_t>(1U + data.size() % 127U);
  o.switch_threshold = static_cast<std::uint8_t>(setup & 0x07U);
  // the same frames through on_frames: the frames of one `now` (up to a poll) as one batch
  sdo::client batch(node, 100);
  std::vector<std::uint8_t> buffer2(buffer.size());
  auto start_on = [&](sdo::client &m, std::vector<std::uint8_t> &b) {
    if (block) return upload ? m.block_upload(a, b, now, o) : m.block_download(a, data, now);
    return upload ? m.upload(a, b, now) : m.download(a, data, now);
  };
  auto start = [&] { return start_on(c, buffer); };
  auto first = start();
  FUZZ_CHECK(first.has_value());
  {
    const auto first2 = start_on(batch, buffer2);
    FUZZ_CHECK(first2.has_value());
    FUZZ_CHECK(std::vector<co::can_frame>(first2.value().send.begin(), first2.value().send.end()) ==
               std::vector<co::can_frame>(first.value().send.begin(), first.value().send.end()));
  }
  struct seen {
    co::can_frame f;
    std::vector<co::can_frame> sent;
    bool answered;
    sdo::transfer_state state;
    std::optional<std::uint32_t> deadline;
  };
  std::vector<seen> pending;
  std::vector<co::can_frame> frames;
  std::uint32_t pending_now = 0;
  const auto flush = [&] {
    frames.clear();
    for (const auto &p : pending) frames.push_back(p.f);
    for (std::size_t at = 0; at < frames.size();) {
      const sdo::batch_step b = batch.on_frames(std::span(frames).subspan(at), pending_now);
      FUZZ_CHECK(b.consumed >= 1U && b.consumed <= frames.size() - at);
      for (std::size_t j = at; j + 1U < at + b.consumed; ++j) FUZZ_CHECK(!pending[j].answered);
      const seen &last = pending[at + b.consumed - 1U];
      FUZZ_CHECK(last.answered || at + b.consumed == frames.size());
      FUZZ_CHECK(std::vector<co::can_frame>(b.last.send.begin(), b.last.send.end()) == last.sent);
      FUZZ_CHECK(b.last.state == last.state && b.last.deadline == last.deadline);
      at += b.consumed;
    }
    pending.clear();
    FUZZ_CHECK(batch.state() == c.state() && batch.error() == c.error());
    FUZZ_CHECK(batch.deadline() == c.deadline() && batch.transferred() == c.transferred());
    FUZZ_CHECK(std::ranges::equal(batch.received(), c.received()));
  };
  check_client_step(first.value());
  FUZZ_CHECK(c.busy());
  FUZZ_CHECK(first.value().deadline.has_value());
  FUZZ_CHECK(start().is(errc::bad_state));
  std::optional<std::uint32_t> announced;
  while (!r.empty()) {
    const auto before = c.state();
    const auto f = frame_from(r, channel.response_id);
    now += r.byte();
    if (!pending.empty() && (f.data[7] == 0xEEU || now != pending_now)) flush();
    const sdo::step out = (f.data[7] == 0xEEU) ? c.poll(now) : c.on_frame(f, now);
    if (f.data[7] == 0xEEU) {
      const auto b = batch.poll(now);
      FUZZ_CHECK(std::vector<co::can_frame>(b.send.begin(), b.send.end()) ==
                 std::vector<co::can_frame>(out.send.begin(), out.send.end()));
    } else {
      seen x{f, {out.send.begin(), out.send.end()}, false, out.state, out.deadline};
      x.answered = !x.sent.empty() || out.state != before;
      pending.push_back(x);
      pending_now = now;
    }
    if (before != sdo::transfer_state::busy) {
      FUZZ_CHECK(out.send.empty() && out.state == before && c.state() == before);
      continue;
    }
    FUZZ_CHECK(out.state == c.state());
    FUZZ_CHECK(out.deadline.has_value() == c.busy());
    if (upload && channel.is_response(f)) {
      auto m = sdo::decode(f, sdo::direction::to_client);
      if (m &&
          (m.value().type == sdo::message_type::initiate_upload_response ||
           m.value().type == sdo::message_type::block_upload_initiate_response) &&
          !m.value().expedited && m.value().size_indicated) {
        announced = m.value().size;
      }
    }
    check_client_step(out);
    if (!out.send.empty() && !out.send.is_burst()) {
      auto m = sdo::decode(out.send[0], sdo::direction::to_server).value();
      if (m.type == sdo::message_type::abort) {
        FUZZ_CHECK(c.state() == sdo::transfer_state::failed);
        FUZZ_CHECK(m.address == a && c.error().has_value() && m.abort == c.error()->abort);
      }
    }
    if (c.state() == sdo::transfer_state::failed) FUZZ_CHECK(c.error().has_value());
    FUZZ_CHECK(c.transferred() <= (upload ? buffer.size() : data.size()));
    if (c.state() == sdo::transfer_state::done) {
      if (upload) {
        FUZZ_CHECK(c.received().size() == c.transferred());
        if (announced) FUZZ_CHECK(c.received().size() == *announced);
      } else {
        FUZZ_CHECK(c.transferred() == data.size());
      }
    }
  }
  flush();
}

void server_mode(reader &r) {
  store s;
  s.capacity = r.byte() % 64U;
  s.value.resize(r.byte() % 64U);
  for (auto &b : s.value) b = r.byte();
  std::vector<std::uint8_t> buffer(r.byte() % 64U);
  sdo::server<store> srv(node, s, buffer, 100);
  // the same frames through on_frames: the frames of one `now` (up to a poll) as one batch
  store s2 = s;
  std::vector<std::uint8_t> buffer2(buffer.size());
  sdo::server<store> batch(node, s2, buffer2, 100);
  struct seen {
    co::can_frame f;
    std::vector<co::can_frame> sent;
    bool answered;
    sdo::transfer_state state;
    std::optional<std::uint32_t> deadline;
  };
  std::vector<seen> pending;
  std::vector<co::can_frame> frames;
  std::uint32_t pending_now = 0;
  const auto flush = [&] {
    frames.clear();
    for (const auto &p : pending) frames.push_back(p.f);
    for (std::size_t at = 0; at < frames.size();) {
      const sdo::batch_step b = batch.on_frames(std::span(frames).subspan(at), pending_now);
      FUZZ_CHECK(b.consumed >= 1U && b.consumed <= frames.size() - at);
      for (std::size_t j = at; j + 1U < at + b.consumed; ++j) FUZZ_CHECK(!pending[j].answered);
      const seen &last = pending[at + b.consumed - 1U];
      FUZZ_CHECK(last.answered || at + b.consumed == frames.size());
      FUZZ_CHECK(std::vector<co::can_frame>(b.last.send.begin(), b.last.send.end()) == last.sent);
      FUZZ_CHECK(b.last.state == last.state && b.last.deadline == last.deadline);
      at += b.consumed;
    }
    pending.clear();
    FUZZ_CHECK(batch.state() == srv.state() && batch.error() == srv.error());
    FUZZ_CHECK(batch.deadline() == srv.deadline());
    FUZZ_CHECK(s2.value == s.value && s2.word == s.word && s2.completed == s.completed);
  };
  std::uint32_t now = 0;
  while (!r.empty()) {
    const auto f = frame_from(r, channel.request_id);
    now += r.byte();
    const auto value_before = s.value;
    const auto completed_before = s.completed;
    if (!pending.empty() && (f.data[7] == 0xEEU || now != pending_now)) flush();
    const auto state_before = srv.state();
    auto out = (f.data[7] == 0xEEU) ? srv.poll(now) : srv.on_frame(f, now);
    if (f.data[7] == 0xEEU) {
      const auto b = batch.poll(now);
      FUZZ_CHECK(std::vector<co::can_frame>(b.send.begin(), b.send.end()) ==
                 std::vector<co::can_frame>(out.send.begin(), out.send.end()));
    } else {
      seen x{f, {out.send.begin(), out.send.end()}, false, out.state, out.deadline};
      x.answered = !x.sent.empty() || out.state != state_before ||
                   (f.id == channel.request_id && !f.rtr && f.dlc != 8U);
      pending.push_back(x);
      pending_now = now;
    }
    if (s.value != value_before) FUZZ_CHECK(s.completed == completed_before + 1);
    FUZZ_CHECK(out.deadline.has_value() == srv.busy());
    check_server_step(out);
    if (out.send.empty() || out.send.is_burst()) continue;
    auto m = sdo::decode(out.send[0], sdo::direction::to_client).value();
    if (m.type == sdo::message_type::initiate_upload_response && m.expedited &&
        m.address == od::address{0x2000, 1}) {
      FUZZ_CHECK(m.size_indicated);
      const auto b = m.value_bytes();
      FUZZ_CHECK(
          std::equal(b.begin(), b.begin() + m.size, value_before.begin(), value_before.end()));
    }
  }
  flush();
}

/// Runs a client/server exchange; `corrupt` may drop or change frames. Returns the client's
/// final state; both machines end idle, done or failed.
sdo::transfer_state exchange(sdo::client &c, sdo::server<store> &srv, const sdo::step &first,
                             reader &r, bool corrupt) {
  std::vector<co::can_frame> to_server(first.send.begin(), first.send.end());
  check_client_step(first);
  std::uint32_t now = 0;
  for (int guard = 0; guard < 2000 && (c.busy() || srv.busy()); ++guard) {
    now += 1;
    if (to_server.empty()) {
      // nothing in flight: the deadlines pass, both sides time out
      now += 1000;
      auto o = c.poll(now);
      check_client_step(o);
      auto p = srv.poll(now);
      check_server_step(p);
      for (const auto &f : o.send) (void)srv.on_frame(f, now);
      FUZZ_CHECK(!c.busy() && !srv.busy());
      break;
    }
    std::vector<co::can_frame> to_client;
    for (auto f : to_server) {
      if (corrupt && (r.byte() & 7U) == 0U) {
        if ((r.byte() & 1U) == 0U) continue; // lost
        f.data[r.byte() & 7U] ^= r.byte();
      }
      auto rsp = srv.on_frame(f, now);
      check_server_step(rsp);
      to_client.insert(to_client.end(), rsp.send.begin(), rsp.send.end());
    }
    to_server.clear();
    for (auto f : to_client) {
      if (corrupt && (r.byte() & 7U) == 0U) {
        if ((r.byte() & 1U) == 0U) continue;
        f.data[r.byte() & 7U] ^= r.byte();
      }
      auto out = c.on_frame(f, now);
      check_client_step(out);
      to_server.insert(to_server.end(), out.send.begin(), out.send.end());
    }
  }
  FUZZ_CHECK(!c.busy());
  return c.state();
}

void loopback_mode(reader &r, bool block) {
  const std::uint8_t setup = r.byte();
  const bool corrupt = (setup & 0x80U) != 0U;
  const bool word = (setup & 0x40U) != 0U; // the 4-byte object instead of the variable one
  sdo::block_options o;
  o.crc = (setup & 0x20U) == 0U;
  o.switch_threshold = static_cast<std::uint8_t>(setup & 0x0FU);
  o.block_size = static_cast<std::uint8_t>(1U + r.byte() % 127U);
  store s;
  s.capacity = r.byte() % 200U;
  std::vector<std::uint8_t> server_buffer(r.byte() % 200U);
  std::vector<std::uint8_t> client_buffer(r.byte() % 200U);
  std::vector<std::uint8_t> data(r.byte() % 200U);
  for (auto &b : data) b = r.byte();
  const od::address a = word ? od::address{0x2001, 0} : od::address{0x2000, 1};

  sdo::server<store> srv(node, s, server_buffer, 100);
  sdo::client c(node, 100);
  auto first = block ? c.block_download(a, data, 0, o) : c.download(a, data, 0);
  FUZZ_CHECK(first.has_value());
  const auto st = exchange(c, srv, first.value(), r, corrupt);
  // With corruption the bytes are not compared: a corrupted data byte of a segmented transfer
  // is invisible to the protocol, and even block transfer's CRC can be switched off on the way
  // (its negotiation bits are not protected).
  const bool checked = !corrupt;
  if (!corrupt) {
    const bool fits = word ? data.size() == 4U : data.size() <= s.capacity;
    // the server collects a download in its buffer and passes full buffers to the store: any
    // buffer takes a segmented download, a block download needs room for one segment
    const bool expedited = !block && !data.empty() && data.size() <= 4U;
    const bool buffer_ok =
        block ? server_buffer.size() >= 7U : expedited || data.empty() || !server_buffer.empty();
    FUZZ_CHECK((st == sdo::transfer_state::done) == (fits && buffer_ok));
  }
  if (st == sdo::transfer_state::done && checked) {
    if (word) {
      FUZZ_CHECK(std::equal(data.begin(), data.end(), s.word.begin(), s.word.end()));
    } else {
      FUZZ_CHECK(s.value == data);
    }
  }
  if (!word) FUZZ_CHECK(s.value.size() <= s.capacity);

  // Upload what the store holds now.
  const std::vector<std::uint8_t> stored =
      word ? std::vector<std::uint8_t>(s.word.begin(), s.word.end()) : s.value;
  auto up = block ? c.block_upload(a, client_buffer, 0, o) : c.upload(a, client_buffer, 0);
  FUZZ_CHECK(up.has_value());
  const auto ust = exchange(c, srv, up.value(), r, corrupt);
  if (!corrupt) {
    bool fits = stored.size() <= client_buffer.size();
    const bool switched = block && o.switch_threshold != 0U && stored.size() <= o.switch_threshold;
    if (stored.size() >= 1U && stored.size() <= 4U && (!block || switched)) {
      fits = fits && server_buffer.size() >= stored.size(); // expedited: one read of the value
    } else if (block && !switched) {
      // the server's buffer holds a whole sub-block (or the rest of the value)
      const std::size_t burst = std::min<std::size_t>(7U * o.block_size, stored.size());
      fits = fits && server_buffer.size() >= burst;
    } else {
      // segmented: each segment is read from the store into the server's buffer
      fits = fits && server_buffer.size() >= std::min<std::size_t>(7U, stored.size());
    }
    FUZZ_CHECK((ust == sdo::transfer_state::done) == fits);
  }
  if (ust == sdo::transfer_state::done && checked) {
    FUZZ_CHECK(std::equal(c.received().begin(), c.received().end(), stored.begin(), stored.end()));
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  reader r{std::span<const std::uint8_t>(data + 1, size - 1)};
  switch (data[0] % 4U) {
  case 0: client_mode(r); break;
  case 1: server_mode(r); break;
  case 2: loopback_mode(r, false); break;
  case 3: loopback_mode(r, true); break;
  }
  return 0;
}
