// The byte-0 readers of the SDO codec that the client's expedited and segmented states read a
// response with in place (sdo.hpp: is_server_message, detail::specifier, segment_*,
// initiate_*): for every value of byte 0 they say what decode(…, direction::to_client) says, so
// the client reads the same message with or without building it.
#include <fieldcodec/canopen/sdo.hpp>

#include <doctest/doctest.h>

#include <cstdint>

namespace sdo = fieldcodec::canopen::sdo;
namespace detail = fieldcodec::canopen::sdo::detail;

static_assert(detail::specifier_of(sdo::message_type::upload_segment_response) == 0U);
static_assert(detail::specifier_of(sdo::message_type::download_segment_response) == 1U);
static_assert(detail::specifier_of(sdo::message_type::initiate_upload_response) == 2U);
static_assert(detail::specifier_of(sdo::message_type::initiate_download_response) == 3U);
static_assert(detail::specifier_of(sdo::message_type::abort) == 4U);
static_assert(sdo::is_server_message(0x43) && !sdo::is_server_message(0xA3) &&
              !sdo::is_server_message(0xE0));

TEST_CASE("SDO byte 0 read in place says what decode says, for every byte 0") {
  for (unsigned b = 0; b < 256U; ++b) {
    CAPTURE(b);
    const auto b0 = static_cast<std::uint8_t>(b);
    const sdo::payload p{b0, 0x17, 0x10, 0x02, 0x11, 0x22, 0x33, 0x44};
    const auto m = sdo::decode(p, sdo::direction::to_client);
    CHECK(sdo::is_server_message(b0) == m.has_value());
    if (!m) {
      CHECK(m.error() == fieldcodec::errc::unknown_command);
      continue;
    }
    const auto &v = m.value();
    CHECK(detail::specifier(b0) == detail::specifier_of(v.type));
    switch (v.type) {
    case sdo::message_type::upload_segment_response:
      CHECK(detail::segment_toggle(b0) == v.toggle);
      CHECK(detail::segment_size(b0) == v.data_size);
      CHECK(detail::segment_last(b0) == v.last);
      break;
    case sdo::message_type::download_segment_response:
      CHECK(detail::segment_toggle(b0) == v.toggle);
      break;
    case sdo::message_type::initiate_upload_response:
      CHECK(detail::initiate_expedited(b0) == v.expedited);
      CHECK(detail::initiate_size_indicated(b0) == v.size_indicated);
      if (v.expedited) CHECK(detail::expedited_size(b0) == v.size);
      break;
    default: break;
    }
  }
}
