// Fuzz harness for the SDO transfer machines (canopen/sdo_client.hpp, sdo_server.hpp).
//
// Byte 0 selects the mode; then:
//   mode 0  client fed arbitrary frames: transfer setup (see client_mode), then 11-byte frames
//           (id low byte, flags, 8 data bytes, 1 spare: id = 0x585 unless the flags' bit 7 is
//           set, then 0x500 + low byte) and timer ticks;
//   mode 1  server fed arbitrary frames: the same frame format towards 0x605;
//   mode 2  loopback: a client and a server talk to each other (download, then upload) with
//           fuzzed data, buffer sizes and object; frames may be dropped or corrupted.
//
// Properties:
// * Every frame a machine sends is a valid CAN frame on its COB-ID (client 0x600+node, server
//   0x580+node, DLC 8) that the peer's decoder accepts: a machine never sends a frame it
//   cannot decode itself.
// * The client never reports more bytes than its buffer holds; an upload that completes with a
//   size indicated has exactly that size; after done/failed, frames change nothing; every abort
//   it sends carries the transfer's index/sub and the code abort_code_value() reports.
// * The server's store only ever sees writes whose length fits the server's buffer; expedited
//   upload responses carry exactly the stored bytes.
// * Loopback without corruption: a download stores exactly the data (or fails because the
//   server's buffer or the object is too small), and an upload of that object gives back
//   exactly the stored bytes (or fails because the client's buffer is too small). With
//   corruption: no crash, and whatever completes still has the right bytes.
#include "check.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
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
namespace sdo = fieldcodec::canopen::sdo;
using fc::errc;

namespace {

constexpr std::uint8_t node = 5;

/// Reads bytes from the input, zero when exhausted.
struct reader {
  std::span<const std::uint8_t> in;
  std::uint8_t byte() {
    if (in.empty()) return 0;
    const std::uint8_t b = in[0];
    in = in.subspan(1);
    return b;
  }
  std::uint16_t u16() { return static_cast<std::uint16_t>(byte() | (byte() << 8U)); }
  [[nodiscard]] bool empty() const { return in.empty(); }
};

/// Two objects; 0x2000:1 holds up to `capacity` bytes, 0x2001:0 exactly 4.
struct store {
  std::vector<std::uint8_t> value;
  std::size_t capacity = 0;
  std::array<std::uint8_t, 4> word{};
  std::size_t max_write = 0; ///< longest write seen
  sdo::abort_code read(std::uint16_t index, std::uint8_t sub, std::span<std::uint8_t> out,
                       std::size_t &size) {
    if (index == 0x2000 && sub == 1) {
      if (value.size() > out.size()) return sdo::abort_code::out_of_memory;
      std::copy(value.begin(), value.end(), out.begin());
      size = value.size();
      return sdo::abort_code::none;
    }
    if (index == 0x2001 && sub == 0) {
      if (out.size() < 4) return sdo::abort_code::out_of_memory;
      std::copy(word.begin(), word.end(), out.begin());
      size = 4;
      return sdo::abort_code::none;
    }
    return sdo::abort_code::no_object;
  }
  sdo::abort_code write(std::uint16_t index, std::uint8_t sub, std::span<const std::uint8_t> in) {
    max_write = std::max(max_write, in.size());
    if (index == 0x2000 && sub == 1) {
      if (in.size() > capacity) return sdo::abort_code::length_too_high;
      value.assign(in.begin(), in.end());
      return sdo::abort_code::none;
    }
    if (index == 0x2001 && sub == 0) {
      if (in.size() != 4) return sdo::abort_code::length_too_low;
      std::copy(in.begin(), in.end(), word.begin());
      return sdo::abort_code::none;
    }
    return sdo::abort_code::no_object;
  }
};
static_assert(sdo::object_store<store>);

void check_client_frame(const co::can_frame &f) {
  FUZZ_CHECK(f.is_valid() && !f.rtr && f.dlc == 8 && f.id == 0x600 + node);
  FUZZ_CHECK(sdo::decode_request(f).has_value());
}
void check_server_frame(const co::can_frame &f) {
  FUZZ_CHECK(f.is_valid() && !f.rtr && f.dlc == 8 && f.id == 0x580 + node);
  FUZZ_CHECK(sdo::decode_response(f).has_value());
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
  const std::uint16_t index = r.u16();
  const std::uint8_t sub = r.byte();
  std::uint32_t now = 0;
  const bool upload = (setup & 0x80U) != 0U;
  auto first = upload ? c.upload(index, sub, buffer, now) : c.download(index, sub, data, now);
  FUZZ_CHECK(first.has_value());
  check_client_frame(first.value());
  FUZZ_CHECK(c.busy());
  FUZZ_CHECK((upload ? c.upload(index, sub, buffer, now) : c.download(index, sub, data, now))
                 .is(errc::bad_state));
  std::optional<std::uint32_t> announced;
  while (!r.empty()) {
    const auto before = c.state();
    const auto f = frame_from(r, 0x580 + node);
    now += r.byte();
    sdo::output out = (f.data[7] == 0xEEU) ? c.poll(now) : c.on_frame(f, now);
    if (before != sdo::transfer_state::busy) {
      FUZZ_CHECK(!out.send && out.state == before && c.state() == before);
      continue;
    }
    FUZZ_CHECK(out.state == c.state());
    if (upload && f.id == 0x580 + node && !f.rtr) {
      auto m = sdo::decode_response(f);
      if (m && m.value().k == sdo::kind::initiate_upload_response && !m.value().expedited &&
          m.value().size_indicated) {
        announced = m.value().size;
      }
    }
    if (out.send) {
      check_client_frame(*out.send);
      auto m = sdo::decode_request(*out.send).value();
      if (m.k == sdo::kind::abort) {
        FUZZ_CHECK(c.state() == sdo::transfer_state::failed);
        FUZZ_CHECK(m.index == index && m.sub == sub && m.code == c.abort_code_value());
      }
    }
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
}

void server_mode(reader &r) {
  store s;
  s.capacity = r.byte() % 64U;
  s.value.resize(r.byte() % 64U);
  for (auto &b : s.value) b = r.byte();
  std::vector<std::uint8_t> buffer(r.byte() % 64U);
  sdo::server<store> srv(node, s, buffer, 100);
  std::uint32_t now = 0;
  while (!r.empty()) {
    const auto f = frame_from(r, 0x600 + node);
    now += r.byte();
    const auto value_before = s.value;
    auto out = (f.data[7] == 0xEEU) ? srv.poll(now) : srv.on_frame(f, now);
    FUZZ_CHECK(s.max_write <= buffer.size() || s.max_write <= 4U); // expedited: at most 4
    if (!out) continue;
    check_server_frame(*out);
    auto m = sdo::decode_response(*out).value();
    if (m.k == sdo::kind::initiate_upload_response && m.expedited && m.index == 0x2000 &&
        m.sub == 1) {
      FUZZ_CHECK(m.size_indicated);
      FUZZ_CHECK(
          std::equal(m.bytes().begin(), m.bytes().end(), value_before.begin(), value_before.end()));
    }
  }
}

/// Runs a client/server exchange; `corrupt` may drop or change frames. Returns the client's
/// final state.
sdo::transfer_state exchange(sdo::client &c, sdo::server<store> &srv, co::can_frame first,
                             reader &r, bool corrupt) {
  std::optional<co::can_frame> to_server = first;
  std::uint32_t now = 0;
  for (int guard = 0; guard < 200 && c.busy(); ++guard) {
    now += 1;
    if (!to_server) {
      auto o = c.poll(now + 1000); // a lost frame: the client times out and aborts
      FUZZ_CHECK(c.state() == sdo::transfer_state::failed);
      if (o.send) (void)srv.on_frame(*o.send, now);
      break;
    }
    check_client_frame(*to_server);
    if (corrupt && (r.byte() & 7U) == 0U) to_server->data[r.byte() & 7U] ^= r.byte();
    auto rsp = srv.on_frame(*to_server, now);
    if (rsp) check_server_frame(*rsp);
    if (!rsp) {
      to_server.reset();
      continue;
    }
    if (corrupt && (r.byte() & 7U) == 0U) rsp->data[r.byte() & 7U] ^= r.byte();
    auto out = c.on_frame(*rsp, now);
    to_server = out.send;
    if (out.send && !c.busy()) { // the client's abort goes to the server
      check_client_frame(*out.send);
      (void)srv.on_frame(*out.send, now);
      break;
    }
  }
  return c.state();
}

void loopback_mode(reader &r) {
  const std::uint8_t setup = r.byte();
  const bool corrupt = (setup & 0x80U) != 0U;
  const bool word = (setup & 0x40U) != 0U; // the 4-byte object instead of the variable one
  store s;
  s.capacity = r.byte() % 80U;
  std::vector<std::uint8_t> server_buffer(r.byte() % 80U);
  std::vector<std::uint8_t> client_buffer(r.byte() % 80U);
  std::vector<std::uint8_t> data(r.byte() % 80U);
  for (auto &b : data) b = r.byte();
  const std::uint16_t index = word ? 0x2001 : 0x2000;
  const std::uint8_t sub = word ? 0 : 1;

  sdo::server<store> srv(node, s, server_buffer, 100);
  sdo::client c(node, 100);
  auto first = c.download(index, sub, data, 0);
  FUZZ_CHECK(first.has_value());
  const auto st = exchange(c, srv, first.value(), r, corrupt);
  if (!corrupt) {
    const bool expedited = !data.empty() && data.size() <= 4U;
    const bool fits =
        word ? data.size() == 4U
             : data.size() <= s.capacity && (expedited || data.size() <= server_buffer.size());
    FUZZ_CHECK((st == sdo::transfer_state::done) == fits);
    if (fits) {
      if (word) {
        FUZZ_CHECK(std::equal(data.begin(), data.end(), s.word.begin(), s.word.end()));
      } else {
        FUZZ_CHECK(s.value == data);
      }
    }
  } else if (st == sdo::transfer_state::done && !word) {
    FUZZ_CHECK(s.value.size() <= s.capacity);
  }

  // Upload what the store holds now.
  std::vector<std::uint8_t> stored =
      word ? std::vector<std::uint8_t>(s.word.begin(), s.word.end()) : s.value;
  auto up = c.upload(index, sub, client_buffer, 0);
  FUZZ_CHECK(up.has_value());
  const auto ust = exchange(c, srv, up.value(), r, corrupt);
  if (!corrupt) {
    // The server reads the object through its buffer, also for an expedited answer.
    const bool fits =
        stored.size() <= client_buffer.size() && stored.size() <= server_buffer.size();
    FUZZ_CHECK((ust == sdo::transfer_state::done) == fits);
  }
  if (ust == sdo::transfer_state::done && !corrupt) {
    FUZZ_CHECK(std::equal(c.received().begin(), c.received().end(), stored.begin(), stored.end()));
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size == 0) return 0;
  reader r{std::span<const std::uint8_t>(data + 1, size - 1)};
  switch (data[0] % 3U) {
  case 0: client_mode(r); break;
  case 1: server_mode(r); break;
  case 2: loopback_mode(r); break;
  }
  return 0;
}
