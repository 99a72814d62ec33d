// SDO codec speed-ups of issue 18 (O(1) command lookup, expedited data as one word, the
// expedited constructors written directly, frames built in place, decode_expedited_write,
// expedited initiates decoded before the table, frames decoded without copying the payload;
// round 4: a message carries expedited data as a number, `value`, instead of in the segment
// bytes) change no result: each is compared with the code it replaced, kept here as the
// reference. The references build messages of the shape before round 4 (expedited data in
// data/data_size); `round4` moves that data into `value`, which is the only difference.
#include <fieldcodec/canopen/sdo.hpp>

#include <doctest/doctest.h>

#include "xorshift.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <span>

namespace fc = fieldcodec;
namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;

namespace {

// The command lookup before issue 18: the position of the first command of the table that
// matches, std::size(commands) when none does.
std::size_t reference_command_for(sdo::direction d, std::uint8_t byte0) {
  std::size_t i = 0;
  while (i < std::size(sdo::detail::commands) &&
         !(sdo::detail::commands[i].dir == d &&
           (byte0 & sdo::detail::commands[i].mask) == sdo::detail::commands[i].bits)) {
    ++i;
  }
  return i;
}

// decode(payload, direction) before issue 18, verbatim but for the names.
fc::result<sdo::message> reference_decode(const sdo::payload &p, sdo::direction d) {
  const std::size_t ci = reference_command_for(d, p[0]);
  if (ci == std::size(sdo::detail::commands)) return fc::errc::unknown_command;
  const sdo::detail::command *c = &sdo::detail::commands[ci];
  sdo::message m;
  m.type = c->type;
  const unsigned b0 = p[0];
  switch (c->lay) {
  case sdo::detail::layout::segment:
    m.toggle = (b0 & sdo::detail::toggle_bit) != 0U;
    m.last = (b0 & 0x01U) != 0U;
    m.data_size = static_cast<std::uint8_t>(7U - ((b0 >> 1U) & 7U));
    for (std::size_t i = 0; i < m.data_size; ++i) m.data[i] = p[1U + i];
    break;
  case sdo::detail::layout::toggle: m.toggle = (b0 & sdo::detail::toggle_bit) != 0U; break;
  case sdo::detail::layout::initiate:
    m.address = sdo::detail::get_address(p);
    m.expedited = (b0 & 0x02U) != 0U;
    m.size_indicated = (b0 & 0x01U) != 0U;
    if (m.expedited) {
      const unsigned n = m.size_indicated ? (b0 >> 2U) & 3U : 0U;
      m.data_size = static_cast<std::uint8_t>(4U - n);
      m.size = m.data_size;
      for (std::size_t i = 0; i < m.data_size; ++i) m.data[i] = p[4U + i];
    } else if (m.size_indicated) {
      m.size = sdo::detail::get_u32(p);
    }
    break;
  case sdo::detail::layout::address: m.address = sdo::detail::get_address(p); break;
  case sdo::detail::layout::abort:
    m.address = sdo::detail::get_address(p);
    m.abort = static_cast<sdo::abort_code>(sdo::detail::get_u32(p));
    break;
  case sdo::detail::layout::block_initiate:
    m.address = sdo::detail::get_address(p);
    m.crc = (b0 & 0x04U) != 0U;
    m.size_indicated = (b0 & 0x02U) != 0U;
    if (m.size_indicated) m.size = sdo::detail::get_u32(p);
    break;
  case sdo::detail::layout::block_response:
  case sdo::detail::layout::block_upload:
    m.address = sdo::detail::get_address(p);
    m.crc = (b0 & 0x04U) != 0U;
    m.block_size = p[4];
    if (c->lay == sdo::detail::layout::block_upload) m.switch_threshold = p[5];
    break;
  case sdo::detail::layout::block_ack:
    m.sequence = p[1];
    m.block_size = p[2];
    break;
  case sdo::detail::layout::block_end:
    m.unused = static_cast<std::uint8_t>((b0 >> 2U) & 7U);
    m.checksum = fc::from_bytes<std::uint16_t>({p[1], p[2]}, fc::byte_order::little);
    break;
  case sdo::detail::layout::command_only: break;
  }
  return m;
}

// A message of the shape before round 4 in the shape of round 4: an expedited initiate's data
// bytes (data/data_size) become `value` (little-endian; size is the number of bytes).
sdo::message round4(sdo::message m) {
  const bool initiate = m.type == sdo::message_type::initiate_download_request ||
                        m.type == sdo::message_type::initiate_upload_response;
  if (!initiate || !m.expedited) return m;
  m.value = 0;
  for (std::size_t i = m.data_size < 4U ? m.data_size : 4U; i-- > 0;) {
    m.value = (m.value << 8U) | m.data[i];
  }
  m.size = m.data_size;
  m.data = {};
  m.data_size = 0;
  return m;
}
fc::result<sdo::message> round4(const fc::result<sdo::message> &r) {
  if (!r) return r.error();
  return round4(r.value());
}

// encode(message) of an expedited initiate before round 4, verbatim but for the names (the
// other layouts did not change).
fc::result<sdo::payload> reference_encode_expedited(const sdo::message &m) {
  sdo::payload p{};
  unsigned b0 = m.type == sdo::message_type::initiate_download_request ? 0x20U : 0x40U;
  sdo::detail::put_address(p, m.address);
  if (m.data_size == 0U) return fc::errc::bad_length;
  if (m.data_size > 4U) return fc::errc::too_long;
  if (!m.size_indicated && m.data_size != 4U) return fc::errc::bad_length;
  b0 |= m.size_indicated ? ((4U - m.data_size) << 2U) | 0x03U : 0x02U;
  for (std::size_t i = 0; i < m.data_size; ++i) p[4U + i] = m.data[i];
  p[0] = static_cast<std::uint8_t>(b0);
  return p;
}

// The message the constructors before issue 18 built from `bytes` (at most `max` of them; one
// more in data_size when there were more, so that encode refused them).
sdo::message with_bytes(sdo::message m, std::span<const std::uint8_t> bytes, std::size_t max) {
  m.data_size = static_cast<std::uint8_t>(bytes.size() > max ? max + 1U : bytes.size());
  for (std::size_t i = 0; i < bytes.size() && i < max; ++i) m.data[i] = bytes[i];
  return m;
}

// The expedited constructors before issue 18: a message through encode().
fc::result<sdo::payload> reference_expedited(sdo::message_type t, fc::od::address a,
                                             std::span<const std::uint8_t> bytes,
                                             bool size_indicated) {
  if (bytes.size() > 4U) return fc::errc::too_long;
  sdo::message m;
  m.type = t;
  m.address = a;
  m.expedited = true;
  m.size_indicated = size_indicated;
  return reference_encode_expedited(with_bytes(m, bytes, 4));
}

struct rng : fieldcodec::test::xorshift {
  rng() : xorshift(0x0123'4567'89AB'CDEFULL) {}
};

template <class T>
bool same(const fc::result<T> &a, const fc::result<T> &b) {
  if (a.has_value() != b.has_value()) return false;
  return a.has_value() ? a.value() == b.value() : a.error() == b.error();
}

} // namespace

TEST_CASE("sdo: the O(1) command lookup finds what the table scan found, for every byte") {
  for (unsigned d = 0; d < 3U; ++d) { // 2 is no direction: nothing matches
    for (unsigned b = 0; b < 256U; ++b) {
      const auto dir = static_cast<sdo::direction>(d);
      const auto byte0 = static_cast<std::uint8_t>(b);
      INFO("direction ", d, " byte 0 = ", b);
      CHECK(sdo::detail::command_for(dir, byte0) == reference_command_for(dir, byte0));
    }
  }
}

TEST_CASE("sdo: decode gives the reference's message for every command byte") {
  // also the expedited initiates decode now takes before the table (issue 18), and a direction
  // value that is none (2: unknown_command for every byte, as the table gave)
  rng g;
  for (unsigned d = 0; d < 3U; ++d) {
    for (unsigned b = 0; b < 256U; ++b) {
      for (int k = 0; k < 64; ++k) {
        sdo::payload p{};
        const std::uint64_t r = g.next();
        for (std::size_t i = 0; i < 8U; ++i) p[i] = static_cast<std::uint8_t>(r >> (8U * i));
        p[0] = static_cast<std::uint8_t>(b);
        const auto dir = static_cast<sdo::direction>(d);
        INFO("direction ", d, " byte 0 = ", b);
        CHECK(same(sdo::decode(p, dir), round4(reference_decode(p, dir))));
        // the table alone gives the same (decode takes expedited initiates before it)
        CHECK(same(sdo::detail::decode_by_table(p, dir), round4(reference_decode(p, dir))));
      }
    }
  }
}

TEST_CASE("sdo: decode of a frame gives payload_of and the reference's decode, errors too") {
  // decode(frame, d) no longer copies the bytes through payload_of's result (issue 18)
  rng g;
  for (int k = 0; k < 20000; ++k) {
    const std::uint64_t r = g.next();
    co::can_frame f;
    f.id = static_cast<std::uint16_t>(r & 0xFFFU); // sometimes over 0x7FF
    f.rtr = ((r >> 12U) & 7U) == 0U;
    f.dlc = ((r >> 15U) & 3U) == 0U ? static_cast<std::uint8_t>((r >> 17U) & 15U) : 8U;
    const std::uint64_t bytes = g.next();
    for (std::size_t i = 0; i < 8U; ++i) f.data[i] = static_cast<std::uint8_t>(bytes >> (8U * i));
    if (k % 4 == 0)
      f.data[0] = static_cast<std::uint8_t>(0x22U | ((r >> 21U) & 0x0DU)); // expedited
    if (k % 4 == 1) f.data[0] = static_cast<std::uint8_t>(0x42U | ((r >> 21U) & 0x0DU));
    for (const auto dir : {sdo::direction::to_server, sdo::direction::to_client}) {
      const auto p = sdo::payload_of(f);
      const auto want =
          p ? round4(reference_decode(p.value(), dir)) : fc::result<sdo::message>(p.error());
      INFO("id ", f.id, " rtr ", f.rtr, " dlc ", int{f.dlc}, " byte 0 ", int{f.data[0]});
      CHECK(same(sdo::decode(f, dir), want));
    }
  }
}

TEST_CASE("sdo: the expedited constructors give encode()'s payload and errors") {
  rng g;
  const std::array<std::uint8_t, 5> data{0x11, 0x22, 0x33, 0x44, 0x55};
  for (int k = 0; k < 2000; ++k) {
    const std::uint64_t r = g.next();
    const fc::od::address a{static_cast<std::uint16_t>(r), static_cast<std::uint8_t>(r >> 16U)};
    const std::size_t n = (r >> 24U) % 6U; // 0..5 bytes: too short and too long included
    const auto bytes = std::span<const std::uint8_t>(data).first(n);
    using t = sdo::message_type;
    CHECK(same(sdo::expedited_download(a, bytes),
               reference_expedited(t::initiate_download_request, a, bytes, true)));
    CHECK(same(sdo::expedited_download_unsized(a, bytes),
               reference_expedited(t::initiate_download_request, a, bytes, false)));
    CHECK(same(sdo::expedited_upload_response(a, bytes),
               reference_expedited(t::initiate_upload_response, a, bytes, true)));
    CHECK(same(sdo::expedited_upload_response_unsized(a, bytes),
               reference_expedited(t::initiate_upload_response, a, bytes, false)));
  }
}

TEST_CASE("sdo: decode_expedited_write reads what decode reads, and refuses everything else") {
  rng g;
  for (unsigned b = 0; b < 256U; ++b) {
    for (int k = 0; k < 32; ++k) {
      const std::uint64_t r = g.next();
      co::can_frame f;
      f.id = 0x605;
      f.dlc = 8;
      for (std::size_t i = 0; i < 8U; ++i) f.data[i] = static_cast<std::uint8_t>(r >> (8U * i));
      f.data[0] = static_cast<std::uint8_t>(b);
      if (k == 1) f.dlc = 7;    // bad_length, as decode
      if (k == 2) f.rtr = true; // unexpected_frame, as decode
      const auto w = sdo::decode_expedited_write(f);
      const auto m = sdo::decode(f, sdo::direction::to_server);
      INFO("byte 0 = ", b, " dlc ", int{f.dlc}, " rtr ", f.rtr);
      if (!m) {
        REQUIRE(!w);
        CHECK((w.error() == m.error() || (m.error() == fc::errc::unknown_command &&
                                          w.error() == fc::errc::unexpected_frame)));
        continue;
      }
      const bool expedited_write =
          m.value().type == sdo::message_type::initiate_download_request && m.value().expedited;
      REQUIRE(w.has_value() == expedited_write);
      if (!expedited_write) {
        CHECK(w.error() == fc::errc::unexpected_frame);
        continue;
      }
      const auto &msg = m.value();
      CHECK(w.value().address == msg.address);
      CHECK(w.value().size == msg.size);
      CHECK(w.value().size_indicated == msg.size_indicated);
      CHECK(w.value().value == msg.value);
      // and both are what the decoder before issue 18 read as bytes
      const auto old = reference_decode(f.data, sdo::direction::to_server).value();
      CHECK(w.value().value ==
            fc::load_unsigned(old.bytes(), old.data_size, fc::byte_order::little).value());
    }
  }
  // CiA 301 example: write 0x00000064 (4 bytes, 0x23) to 6040h sub 0 at node 5.
  constexpr co::can_frame f{0x605, false, 8, {0x23, 0x40, 0x60, 0x00, 0x64, 0x00, 0x00, 0x00}};
  static_assert(sdo::decode_expedited_write(f).value() ==
                sdo::expedited_write{{0x6040, 0}, 4, true, 0x64});
  // 0x2F: one byte; the bytes after it are not data
  constexpr co::can_frame g1{0x605, false, 8, {0x2F, 0x60, 0x60, 0x00, 0x08, 0xAA, 0xBB, 0xCC}};
  static_assert(sdo::decode_expedited_write(g1).value() ==
                sdo::expedited_write{{0x6060, 0}, 1, true, 0x08});
}

TEST_CASE("sdo: encode of an expedited message gives the bytes and errors of the encoder before "
          "round 4") {
  // the old shape (data/data_size) through the old encoder against the same message in the new
  // shape (value/size) through encode: every size 0..5, with and without size indication, both
  // directions, random bytes and addresses; and decode of the result gives the message back
  rng g;
  for (int k = 0; k < 20000; ++k) {
    const std::uint64_t r = g.next();
    sdo::message old;
    old.type = (r & 1U) != 0U ? sdo::message_type::initiate_download_request
                              : sdo::message_type::initiate_upload_response;
    old.address = {static_cast<std::uint16_t>(r >> 8U), static_cast<std::uint8_t>(r >> 24U)};
    old.expedited = true;
    old.size_indicated = ((r >> 1U) & 3U) != 0U;
    old.data_size = static_cast<std::uint8_t>((r >> 32U) % 6U);
    for (std::size_t i = 0; i < old.data_size && i < 7U; ++i) {
      old.data[i] = static_cast<std::uint8_t>(r >> (40U + 4U * i));
    }
    const sdo::message now = round4(old);
    INFO("data_size ", int{old.data_size}, " indicated ", old.size_indicated);
    const auto want = reference_encode_expedited(old);
    const auto got = sdo::encode(now);
    CHECK(same(got, want));
    if (got) {
      const auto dir = old.type == sdo::message_type::initiate_download_request
                           ? sdo::direction::to_server
                           : sdo::direction::to_client;
      CHECK(sdo::decode(got.value(), dir).value() == now);
    }
  }
}
