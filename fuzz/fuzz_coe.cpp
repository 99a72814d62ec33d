// Fuzz harness for the CoE codecs (canopen/coe/mailbox.hpp, service.hpp, sdo.hpp,
// sdo_info.hpp) and the SDO adapters over mailboxes (coe/sdo_client.hpp, coe/sdo_server.hpp).
//
// Byte 0 selects the mode; then:
//   mode 0  decoders: the rest is one mailbox, read by every decoder (mailbox, error reply, CoE
//           header, emergency, PDO, SDO in both directions, SDO information and its request and
//           response decoders);
//   mode 1  server: mailbox size (1 byte + 16), then mailboxes (1 length byte, that many bytes)
//           and timer ticks (length 0xFF) fed to a coe::sdo_server over a small store;
//   mode 2  client: mailbox size, a transfer (upload or download, object, data, buffer size),
//           then mailboxes and ticks as in mode 1 fed to a coe::sdo_client;
//   mode 3  loopback: request and response mailbox sizes, data, and optionally one corrupted
//           byte of one mailbox; a client downloads then uploads through a server;
//   mode 4  SDO information fragments: mailboxes as in mode 1 fed to a reassembler.
//
// Properties:
// * Decoding never reads outside the input; what decodes re-encodes into the same message
//   (mailbox header: the same 6 bytes but the reserved bit; an SDO message: the same fields and
//   data; an SDO information header: the same fields and data).
// * Every mailbox an adapter sends fits its mailbox size and decodes: an SDO message for the
//   peer's direction, or (server) a mailbox error reply; every abort the client sends carries
//   the transfer's object; the client never reports more bytes than its buffer.
// * Loopback without corruption: the download stores exactly the data and the upload returns
//   it (or both fail because the object is too small); with corruption: no adapter is left
//   busy, and the object holds at most its capacity.
#include "check.hpp"
#include "sdo_store.hpp"

#include <fieldcodec/canopen/coe/mailbox.hpp>
#include <fieldcodec/canopen/coe/sdo.hpp>
#include <fieldcodec/canopen/coe/sdo_client.hpp>
#include <fieldcodec/canopen/coe/sdo_info.hpp>
#include <fieldcodec/canopen/coe/sdo_server.hpp>
#include <fieldcodec/canopen/coe/service.hpp>
#include <fieldcodec/canopen/object_store.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace fc = fieldcodec;
namespace coe = fieldcodec::canopen::coe;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;

namespace {

using fuzz_sdo::reader;
using fuzz_sdo::store;

bool same(const coe::sdo_message &a, const coe::sdo_message &b) {
  return a.type == b.type && a.complete_access == b.complete_access && a.expedited == b.expedited &&
         a.size_indicated == b.size_indicated && a.toggle == b.toggle && a.last == b.last &&
         a.address == b.address && a.size == b.size && a.value == b.value && a.abort == b.abort &&
         std::equal(a.data.begin(), a.data.end(), b.data.begin(), b.data.end());
}

void decoders(std::span<const std::uint8_t> in) {
  if (const auto h = coe::decode_header(in)) {
    const auto e = coe::encode_header(h.value()).value();
    FUZZ_CHECK(std::equal(e.begin(), e.begin() + 5, in.begin()));
    FUZZ_CHECK(e[5] == (in[5] & 0x7FU));
  }
  const auto mb = coe::decode(in);
  if (!mb) return;
  FUZZ_CHECK(mb.value().data.size() == mb.value().header.length);
  (void)coe::decode_error_reply(mb.value());
  const auto c = coe::decode_coe(in);
  if (!c) return;
  (void)coe::decode_emergency(c.value());
  (void)coe::decode_pdo(c.value());
  std::vector<std::uint8_t> out(in.size() + 16);
  for (const auto d : {sdo::direction::to_server, sdo::direction::to_client}) {
    const auto m = coe::decode_sdo(in, d);
    if (!m) continue;
    const auto n = coe::encode_sdo(out, m.value().mailbox.counter, {}, m.value().sdo);
    FUZZ_CHECK(n.has_value());
    const auto again = coe::decode_sdo(std::span(out).first(n.value()), d);
    FUZZ_CHECK(again.has_value());
    FUZZ_CHECK(same(again.value().sdo, m.value().sdo));
  }
  const auto info = coe::decode_info(in);
  if (!info) return;
  const auto n = coe::encode_info(out, 1, {}, info.value().header, info.value().data);
  FUZZ_CHECK(n.has_value());
  const auto again = coe::decode_info(std::span(out).first(n.value()));
  FUZZ_CHECK(again.has_value() && again.value().header == info.value().header);
  FUZZ_CHECK(std::equal(again.value().data.begin(), again.value().data.end(),
                        info.value().data.begin(), info.value().data.end()));
  (void)coe::decode_get_od_list(info.value());
  (void)coe::decode_get_object_description(info.value());
  (void)coe::decode_get_entry_description(info.value());
  (void)coe::decode_info_error(info.value());
  if (const auto l = coe::decode_od_list(info.value().data)) {
    for (std::size_t i = 0; i < l.value().size(); ++i) (void)l.value()[i];
  }
  (void)coe::decode_object_description(info.value().data);
  if (const auto e = coe::decode_entry_description(info.value().data)) (void)e.value().values();
}

void check_server_mailbox(std::span<const std::uint8_t> m, std::size_t size) {
  if (m.empty()) return;
  FUZZ_CHECK(m.size() <= size);
  const auto mb = coe::decode(m);
  FUZZ_CHECK(mb.has_value());
  if (mb.value().header.type == 0) {
    FUZZ_CHECK(coe::decode_error_reply(mb.value()).has_value());
    return;
  }
  FUZZ_CHECK(coe::decode_sdo(m, sdo::direction::to_client).has_value());
}
void check_client_mailbox(std::span<const std::uint8_t> m, std::size_t size, od::address a) {
  if (m.empty()) return;
  FUZZ_CHECK(m.size() <= size);
  const auto s = coe::decode_sdo(m, sdo::direction::to_server);
  FUZZ_CHECK(s.has_value());
  if (s.value().sdo.type == sdo::message_type::abort) FUZZ_CHECK(s.value().sdo.address == a);
}

/// The next mailbox of the input (nullopt: a timer tick).
std::optional<std::vector<std::uint8_t>> next_mailbox(reader &r) {
  const std::uint8_t n = r.byte();
  if (n == 0xFF) return std::nullopt;
  return r.bytes(n);
}

void server_mode(reader &r) {
  const std::size_t size = 16U + r.byte();
  store st;
  st.capacity = r.byte();
  st.value = r.bytes(r.byte() % 64U);
  std::vector<std::uint8_t> buffer(1U + r.byte() % 64U);
  std::vector<std::uint8_t> sm1(size);
  coe::sdo_server<store> s(st, buffer, sm1, size, 100);
  std::uint32_t now = 0;
  while (!r.empty()) {
    const auto m = next_mailbox(r);
    if (!m) {
      now += 60;
      check_server_mailbox(s.poll(now).send, size);
      continue;
    }
    check_server_mailbox(s.on_mailbox(*m, now).send, size);
    FUZZ_CHECK(st.value.size() <= std::max<std::size_t>(st.capacity, 64U));
  }
}

void client_mode(reader &r) {
  const std::size_t size = 16U + r.byte();
  const std::uint8_t setup = r.byte();
  std::vector<std::uint8_t> sm0(size);
  coe::sdo_client c(sm0, size, 100);
  std::vector<std::uint8_t> buffer(setup & 0x3FU);
  const auto data = r.bytes(r.byte() % 200U);
  const od::address a{r.u16(), static_cast<std::uint8_t>(r.byte() & 1U)};
  const bool ca = (setup & 0x40U) != 0U;
  std::uint32_t now = 0;
  auto first = (setup & 0x80U) != 0U ? c.upload(a, buffer, now, ca) : c.download(a, data, now, ca);
  FUZZ_CHECK(first.has_value());
  check_client_mailbox(first.value().send, size, a);
  while (!r.empty()) {
    const auto m = next_mailbox(r);
    coe::step s = m ? c.on_mailbox(*m, now) : c.poll(now += 60);
    check_client_mailbox(s.send, size, a);
    FUZZ_CHECK(c.received().size() <= buffer.size());
    if (c.error()) FUZZ_CHECK(c.error()->address == a);
  }
}

void loopback_mode(reader &r) {
  const std::size_t req = 16U + r.byte() % 128U;
  const std::size_t resp = 16U + r.byte() % 128U;
  store st;
  st.capacity = r.byte() * 4U;
  const auto data = r.bytes(r.u16() % 1200U);
  const std::uint8_t corrupt_k = r.byte();
  const std::uint8_t corrupt_at = r.byte();
  const bool corrupt = (corrupt_k & 0x80U) != 0U;
  std::vector<std::uint8_t> buffer(1U + r.byte());
  std::vector<std::uint8_t> sm0(req), sm1(resp);
  coe::sdo_server<store> s(st, buffer, sm1, req, 100);
  coe::sdo_client c(sm0, resp, 100);
  std::size_t count = 0;
  const auto run = [&](coe::step first) {
    std::vector<std::uint8_t> to_server(first.send.begin(), first.send.end());
    std::vector<std::uint8_t> to_client;
    std::uint32_t now = 0;
    for (int guard = 0; guard < 20000; ++guard) {
      const auto hurt = [&](std::vector<std::uint8_t> &b) {
        if (corrupt && count++ == (corrupt_k & 0x7FU) && !b.empty()) {
          b[corrupt_at % b.size()] ^= 0xA5;
        }
      };
      if (!to_server.empty()) {
        hurt(to_server);
        const auto a = s.on_mailbox(to_server, now);
        check_server_mailbox(a.send, resp);
        to_client.assign(a.send.begin(), a.send.end());
        to_server.clear();
      } else if (!to_client.empty()) {
        hurt(to_client);
        const auto q = c.on_mailbox(to_client, now);
        to_server.assign(q.send.begin(), q.send.end());
        to_client.clear();
      } else if (c.busy() || s.busy()) {
        now += 60;
        const auto q = c.poll(now);
        to_server.assign(q.send.begin(), q.send.end());
        const auto a = s.poll(now);
        if (!a.send.empty()) to_client.assign(a.send.begin(), a.send.end());
      } else {
        return;
      }
    }
    FUZZ_CHECK(false); // never settled
  };
  run(c.download({0x2000, 1}, data, 0).value());
  FUZZ_CHECK(!c.busy() && !s.busy());
  FUZZ_CHECK(st.value.size() <= st.capacity || st.value.empty());
  if (!corrupt) {
    const bool fits = data.size() <= st.capacity;
    FUZZ_CHECK((c.state() == sdo::transfer_state::done) == fits);
    if (fits) FUZZ_CHECK(st.value == data);
  }
  std::vector<std::uint8_t> back(1300);
  run(c.upload({0x2000, 1}, back, 0).value());
  FUZZ_CHECK(!c.busy() && !s.busy());
  if (!corrupt) {
    // the server's buffer must hold one CAN segment (or the whole value when it is shorter)
    const bool fits = buffer.size() >= std::min<std::size_t>(7U, st.value.size());
    FUZZ_CHECK((c.state() == sdo::transfer_state::done) == fits);
    if (fits) {
      FUZZ_CHECK(
          std::equal(st.value.begin(), st.value.end(), c.received().begin(), c.received().end()));
    }
  }
}

void info_mode(reader &r) {
  std::vector<std::uint8_t> buf(r.byte());
  coe::reassembler re(buf);
  while (!r.empty()) {
    const auto m = next_mailbox(r);
    if (!m) {
      re.reset();
      continue;
    }
    const auto info = coe::decode_info(*m);
    if (!info) continue;
    const auto t = re.take(info.value());
    FUZZ_CHECK(re.data().size() <= buf.size());
    if (t && t.value()) (void)coe::decode_od_list(re.data());
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  reader r{std::span<const std::uint8_t>(data, size)};
  switch (r.byte() % 5U) {
  case 0: decoders(r.in); break;
  case 1: server_mode(r); break;
  case 2: client_mode(r); break;
  case 3: loopback_mode(r); break;
  default: info_mode(r); break;
  }
  return 0;
}
