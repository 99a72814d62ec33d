// The XENAX dictionaries as generated from dictionaries/xenax_*.eds: the corrections of issue 12
// #10 (string capacities, POWERLINK 1030h sub 4 and mapping ARRAYs, RXZP limits) as a store
// and the codecs see them. Manual: ../shared/seeds/003_*.txt (line numbers as in docs/xenax.md).
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat.hpp>
#include <fieldcodec/dictionaries/xenax_powerlink.hpp>
#include <fieldcodec/od/value.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;
namespace xecat = fieldcodec::dictionaries::xenax_ethercat;
namespace xpl = fieldcodec::dictionaries::xenax_powerlink;
using fieldcodec::errc;

namespace {
const od::dictionary *const all[] = {&xcan::dictionary, &xecat::dictionary, &xpl::dictionary};

std::vector<std::uint8_t> text(std::size_t n, char c = 'A') {
  return std::vector<std::uint8_t>(n, static_cast<std::uint8_t>(c));
}
} // namespace

TEST_CASE("5011h, 5012h, 5020h, 5021h carry their printed lengths (3.4.9-3.4.12, errata 32)") {
  // VISIBLE_STRING (30), (30), (100), (32), l. 1097-1115
  const std::pair<std::uint16_t, std::uint32_t> printed[] = {
      {0x5011, 30}, {0x5012, 30}, {0x5020, 100}, {0x5021, 32}};
  for (const od::dictionary *d : all) {
    for (const auto &row : printed) {
      const auto index = row.first; // a named variable: clang 14 cannot capture a binding
      const auto size = row.second;
      CAPTURE(index);
      const od::entry *e = d->find(index, 0);
      REQUIRE(e != nullptr);
      CHECK(e->type == od::data_type::visible_string);
      CHECK(e->capacity() == size);
      // a write of the printed length is accepted, one character more is refused
      std::array<std::uint8_t, 128> out{};
      CHECK(od::encode_bytes(*e, text(size), out).value() == size);
      CHECK(od::encode_bytes(*e, text(size + 1U), out) == errc::too_long);
    }
  }
}

TEST_CASE("a store over the CAN dictionary serves the strings with their capacity") {
  constexpr auto layout = co::make_layout<xcan::dictionary.size()>(xcan::dictionary);
  std::vector<std::uint8_t> storage(layout.storage_size());
  co::dictionary_store<> store{xcan::dictionary, layout, storage};
  REQUIRE(store.init_defaults(1).has_value());
  // 5020h TES keeps its printed default "no error" (l. 1110)
  const auto tes = store.value({0x5020, 0}).value();
  CHECK(std::string_view(reinterpret_cast<const char *>(tes.data()), tes.size()) == "no error");
  // 5021h SID, 32 characters: an SDO download of 33 announced bytes is refused before any data
  CHECK(store.begin_write({0x5021, 0}, 33U) == sdo::abort_code::length_too_high);
  CHECK(store.begin_write({0x5021, 0}, 32U) == sdo::abort_code::none);
  const auto sid = text(32, 'x');
  CHECK(store.write({0x5021, 0}, 0, sid, true) == sdo::abort_code::none);
  CHECK(store.value({0x5021, 0}).value().size() == 32);
  const auto too_long = text(33, 'y');
  CHECK(store.write({0x5021, 0}, 0, too_long, true) != sdo::abort_code::none);
  CHECK(store.value({0x5021, 0}).value().size() == 32); // the old value stays
  // 5020h is read-only
  CHECK(store.begin_write({0x5020, 0}, 8U) == sdo::abort_code::write_read_only);
}

TEST_CASE("POWERLINK 1030h sub 4 is UNSIGNED16, 1600h/1A00h are ARRAYs (errata 16, 31)") {
  const od::entry *mtu = xpl::dictionary.find(0x1030, 4);
  REQUIRE(mtu != nullptr);
  CHECK(mtu->type == od::data_type::unsigned16);
  CHECK(mtu->default_for(1).value().to_uint64().value() == 0x286); // l. 436
  for (const std::uint16_t index : {std::uint16_t{0x1600}, std::uint16_t{0x1A00}}) {
    const auto object = xpl::dictionary.object(index);
    REQUIRE(object.size() == 9);
    for (const od::entry &e : object) {
      CHECK(e.object == od::object_code::array);
      CHECK(e.type == (e.sub == 0 ? od::data_type::unsigned8 : od::data_type::unsigned64));
    }
  }
}

TEST_CASE("5003h sub 3Dh RXZP is writable beyond 0 (errata 29)") {
  for (const od::dictionary *d : all) {
    const od::entry *rxzp = d->find(0x5003, 0x3D);
    REQUIRE(rxzp != nullptr);
    CHECK(od::writable(rxzp->access_type));
    std::array<std::uint8_t, 4> out{};
    CHECK(od::encode(*rxzp, 60'000, out).has_value());
    CHECK(od::encode(*rxzp, 0, out).has_value());
    CHECK(od::encode(*rxzp, -1, out) == errc::out_of_range); // the printed low limit 0 stays
  }
}
