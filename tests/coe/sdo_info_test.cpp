// SDO information (canopen/coe/sdo_info.hpp): requests and responses byte by byte from the
// layouts of ETG.1000.6 5.6.3, fragments cut and joined, and bad input.
#include <fieldcodec/canopen/coe/sdo_info.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <list>
#include <span>
#include <string_view>
#include <vector>

namespace coe = fieldcodec::canopen::coe;
namespace sdo = fieldcodec::canopen::sdo;
using fieldcodec::errc;
using bytes = std::vector<std::uint8_t>;

namespace {
constexpr coe::mailbox_options master{};
template <class F>
bytes written(F encode, std::size_t size = 128) {
  std::vector<std::uint8_t> out(size);
  const auto n = encode(std::span<std::uint8_t>(out));
  REQUIRE(n.has_value());
  out.resize(n.value());
  return out;
}
std::string_view text(std::span<const std::uint8_t> b) {
  return {reinterpret_cast<const char *>(b.data()), b.size()};
}
} // namespace

TEST_CASE("SDO information requests (ETG.1000.6 5.6.3): CoE service 8, then the info header") {
  // get OD list, all objects: length 2 + 4 + 2 = 8; opcode 1, fragments left 0, list type 1
  const auto l = written([](std::span<std::uint8_t> o) {
    return coe::encode_get_od_list(o, 1, master, coe::list_type::all);
  });
  CHECK(l ==
        bytes{0x08, 0x00, 0x00, 0x00, 0x00, 0x13, 0x00, 0x80, 0x01, 0x00, 0x00, 0x00, 0x01, 0x00});
  const auto lm = coe::decode_info(l).value();
  CHECK(lm.header == coe::info_header{coe::info_opcode::get_od_list_request, false, 0});
  CHECK(coe::decode_get_od_list(lm) == coe::list_type::all);
  // get object description of 1018h: opcode 3, length 8
  const auto od = written([](std::span<std::uint8_t> o) {
    return coe::encode_get_object_description(o, 2, master, 0x1018);
  });
  CHECK(od ==
        bytes{0x08, 0x00, 0x00, 0x00, 0x00, 0x23, 0x00, 0x80, 0x03, 0x00, 0x00, 0x00, 0x18, 0x10});
  CHECK(coe::decode_get_object_description(coe::decode_info(od).value()) == 0x1018);
  // get entry description of 1018h:02 with default, minimum and maximum: opcode 5, length 10
  const auto ed = written([](std::span<std::uint8_t> o) {
    return coe::encode_get_entry_description(
        o, 3, master, {0x1018, 2},
        coe::value_info::default_value | coe::value_info::minimum | coe::value_info::maximum);
  });
  CHECK(ed == bytes{0x0A, 0x00, 0x00, 0x00, 0x00, 0x33, 0x00, 0x80, 0x05, 0x00, 0x00, 0x00, 0x18,
                    0x10, 0x02, 0x70});
  CHECK(coe::decode_get_entry_description(coe::decode_info(ed).value()) ==
        coe::entry_request{{0x1018, 2}, 0x70});
  // SDO information error: opcode 7, the abort code
  const auto er = written([](std::span<std::uint8_t> o) {
    return coe::encode_info_error(o, 4, master, sdo::abort_code::no_object);
  });
  CHECK(er == bytes{0x0A, 0x00, 0x00, 0x00, 0x00, 0x43, 0x00, 0x80, 0x07, 0x00, 0x00, 0x00, 0x00,
                    0x00, 0x02, 0x06});
  CHECK(coe::decode_info_error(coe::decode_info(er).value()) == sdo::abort_code::no_object);
}

TEST_CASE("SDO information responses: OD list, object and entry description") {
  // list type 1 with three indices
  const std::array<std::uint16_t, 3> idx{0x1000, 0x1018, 0x6040};
  std::array<std::uint8_t, 16> data{};
  const auto n = coe::encode_od_list(coe::list_type::all, idx, data).value();
  CHECK(n == 8);
  CHECK(bytes(data.begin(), data.begin() + 8) ==
        bytes{0x01, 0x00, 0x00, 0x10, 0x18, 0x10, 0x40, 0x60});
  const auto list = coe::decode_od_list(std::span(data).first(n)).value();
  CHECK(list.type == coe::list_type::all);
  REQUIRE(list.size() == 3);
  CHECK(list[2] == 0x6040);
  // list type 0: the five lengths
  const std::array<std::uint16_t, 5> lengths{40, 3, 5, 0, 2};
  std::array<std::uint8_t, 12> l0{};
  CHECK(coe::encode_od_list(coe::list_type::lengths, lengths, l0).value() == 12);
  CHECK(coe::decode_od_list(l0).value()[0] == 40);
  // object description of 1018h: UNSIGNED8 (data type of sub 0... here the record's 0x0023
  // IDENTITY), max sub 4, RECORD (9), name
  const std::string_view name = "Identity";
  const coe::object_description o{
      0x1018, 0x0023, 4, 9,
      std::span(reinterpret_cast<const std::uint8_t *>(name.data()), name.size())};
  std::array<std::uint8_t, 32> ob{};
  const auto on = coe::encode_object_description(o, ob).value();
  CHECK(bytes(ob.begin(), ob.begin() + 6) == bytes{0x18, 0x10, 0x23, 0x00, 0x04, 0x09});
  const auto od = coe::decode_object_description(std::span(ob).first(on)).value();
  CHECK(od.index == 0x1018);
  CHECK(od.data_type == 0x0023);
  CHECK(od.max_sub == 4);
  CHECK(od.object_code == 9);
  CHECK(text(od.name) == "Identity");
  // entry description of 6040h (UNSIGNED16, 16 bits, rw in every state, RxPDO-mappable) with
  // default 0, minimum 0, maximum FFFFh, then the name
  const bytes e{0x40, 0x60, 0x00, 0x70, 0x06, 0x00, 0x10, 0x00, 0x7F, 0x00, 0x00, 0x00,
                0x00, 0x00, 0xFF, 0xFF, 'C',  'o',  'n',  't',  'r',  'o',  'l'};
  const auto ent = coe::decode_entry_description(e).value();
  CHECK(ent.address == fieldcodec::od::address{0x6040, 0});
  CHECK(ent.data_type == 0x0006);
  CHECK(ent.bit_length == 16);
  CHECK(ent.access == (coe::object_access::read | coe::object_access::write |
                       coe::object_access::rxpdo_mappable));
  const auto v = ent.values().value();
  CHECK(bytes(v.maximum.begin(), v.maximum.end()) == bytes{0xFF, 0xFF});
  CHECK(v.default_value.size() == 2);
  CHECK(text(v.name) == "Control");
  std::array<std::uint8_t, 32> eb{};
  CHECK(bytes(eb.begin(), eb.begin() + static_cast<std::ptrdiff_t>(
                                           coe::encode_entry_description(ent, eb).value())) == e);
  // without value info: the name right after the fixed part
  const bytes e0{0x40, 0x60, 0x00, 0x00, 0x06, 0x00, 0x10, 0x00, 0x3F, 0x00, 'C', 'W'};
  CHECK(text(coe::decode_entry_description(e0).value().values().value().name) == "CW");
  // a unit type present: its width is not fixed by the sources, left to the caller
  bytes e8 = e0;
  e8[3] = coe::value_info::unit_type;
  CHECK(coe::decode_entry_description(e8).value().values() == errc::not_representable);
  // values shorter than the bit length says
  bytes et = e0;
  et[3] = 0x70;
  et.resize(13);
  CHECK(coe::decode_entry_description(et).value().values() == errc::truncated);
}

TEST_CASE("SDO information: bad input") {
  CHECK(coe::decode_info(bytes{5, 0, 0, 0, 0, 0x13, 0x00, 0x80, 0x01, 0x00, 0x00}) ==
        errc::truncated);
  CHECK(coe::decode_info(bytes{6, 0, 0, 0, 0, 0x13, 0x00, 0x80, 0x00, 0, 0, 0}) ==
        errc::unknown_command);
  CHECK(coe::decode_info(bytes{6, 0, 0, 0, 0, 0x13, 0x00, 0x80, 0x08, 0, 0, 0}) ==
        errc::unknown_command);
  CHECK(coe::decode_info(bytes{10, 0, 0, 0, 0, 0x13, 0x00, 0x20, 0x40, 0, 0x10, 0, 0, 0, 0, 0}) ==
        errc::unexpected_frame);
  // decode_info() returns a view into its input: each request keeps its bytes alive here.
  std::list<bytes> keep;
  const auto req = [&keep](std::initializer_list<std::uint8_t> body) {
    bytes &b = keep.emplace_back(
        bytes{static_cast<std::uint8_t>(2 + body.size()), 0, 0, 0, 0, 0x13, 0x00, 0x80});
    b.insert(b.end(), body);
    return coe::decode_info(b).value();
  };
  CHECK(coe::decode_get_od_list(req({0x01, 0, 0, 0, 0x01})) == errc::truncated);
  CHECK(coe::decode_get_od_list(req({0x01, 0, 0, 0, 0x01, 0, 0})) == errc::too_long);
  CHECK(coe::decode_get_od_list(req({0x01, 0, 0, 0, 0x06, 0})) == errc::out_of_range);
  CHECK(coe::decode_get_od_list(req({0x81, 0, 1, 0, 0x01, 0})) == errc::bad_length);
  CHECK(coe::decode_get_od_list(req({0x03, 0, 0, 0, 0x01, 0})) == errc::unexpected_frame);
  CHECK(coe::decode_get_entry_description(req({0x05, 0, 0, 0, 0x00, 0x10, 0})) == errc::truncated);
  CHECK(coe::decode_info_error(req({0x07, 0, 0, 0, 0, 0, 2})) == errc::truncated);
  CHECK(coe::decode_od_list(bytes{0x01}) == errc::truncated);
  CHECK(coe::decode_od_list(bytes{0x01, 0x00, 0x00}) == errc::bad_length);
  CHECK(coe::decode_od_list(bytes{0x06, 0x00}) == errc::out_of_range);
  CHECK(coe::decode_od_list(bytes{0x00, 0x00, 1, 0}) == errc::bad_length);
  CHECK(coe::decode_object_description(bytes{0x18, 0x10, 0x23, 0x00, 0x04}) == errc::truncated);
  CHECK(coe::decode_entry_description(bytes{0x40, 0x60, 0, 0, 6, 0, 16, 0, 0x3F}) ==
        errc::truncated);
  std::array<std::uint8_t, 64> out{};
  CHECK(coe::encode_get_od_list(out, 1, master, static_cast<coe::list_type>(6)) ==
        errc::out_of_range);
  CHECK(coe::encode_info(out, 1, master, {static_cast<coe::info_opcode>(0), false, 0}, {}) ==
        errc::invalid_argument);
  std::array<std::uint8_t, 3> tiny{};
  const std::array<std::uint16_t, 1> one{0x1000};
  CHECK(coe::encode_od_list(coe::list_type::all, one, tiny) == errc::buffer_too_small);
  CHECK(coe::encode_od_list(static_cast<coe::list_type>(9), one, out) == errc::out_of_range);
}

TEST_CASE("SDO information: a long OD list in fragments, cut and joined") {
  // 200 indices: 402 bytes of service data; a 64-byte mailbox holds 52 per fragment: 8 fragments
  std::vector<std::uint16_t> idx(200);
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<std::uint16_t>(0x2000 + i);
  std::vector<std::uint8_t> data(402);
  REQUIRE(coe::encode_od_list(coe::list_type::all, idx, data).value() == 402);
  const coe::fragmenter f(coe::info_opcode::get_od_list_response, data, 64);
  CHECK(coe::info_capacity(64) == 52);
  REQUIRE(f.count() == 8);
  std::vector<std::uint8_t> joined(1024);
  coe::reassembler r(joined);
  std::uint8_t counter = 0;
  for (std::size_t k = 0; k < f.count(); ++k) {
    counter = coe::next_counter(counter);
    std::array<std::uint8_t, 64> mbx{};
    const auto n = f.write(k, mbx, counter, {0x1001, 0, 0}).value();
    CHECK(n == (k + 1 < f.count() ? 64U : 12U + 402U - 7U * 52U));
    const auto m = coe::decode_info(std::span(mbx).first(n)).value();
    CHECK(m.header.fragments_left == f.count() - 1 - k);
    CHECK(m.header.incomplete == (k + 1 < f.count()));
    CHECK(m.mailbox.address == 0x1001);
    CHECK(r.take(m) == (k + 1 == f.count()));
  }
  CHECK(r.opcode() == coe::info_opcode::get_od_list_response);
  const auto list = coe::decode_od_list(r.data()).value();
  REQUIRE(list.size() == 200);
  CHECK(list[0] == 0x2000);
  CHECK(list[199] == 0x20C7);
  CHECK(r.take(coe::decode_info(bytes{8, 0, 0, 0, 0, 0x13, 0, 0x80, 2, 0, 0, 0, 1, 0}).value()) ==
        errc::bad_state);
  CHECK(f.write(8, std::span(joined).first(64), 1, master) == errc::out_of_range);
  // a fragment missing, the opcode changing, the flag disagreeing, the buffer too small
  const auto frag = [&](std::size_t k) {
    std::array<std::uint8_t, 64> mbx{};
    const auto n = f.write(k, mbx, 1, master).value();
    return bytes(mbx.begin(), mbx.begin() + static_cast<std::ptrdiff_t>(n));
  };
  coe::reassembler gap(joined);
  CHECK(gap.take(coe::decode_info(frag(0)).value()) == false);
  CHECK(gap.take(coe::decode_info(frag(2)).value()) == errc::unexpected_frame);
  coe::reassembler flag(joined);
  auto b = frag(0);
  b[8] = 0x02; // incomplete cleared while 7 fragments are left
  CHECK(flag.take(coe::decode_info(b).value()) == errc::bad_length);
  coe::reassembler opc(joined);
  CHECK(opc.take(coe::decode_info(frag(0)).value()) == false);
  b = frag(1);
  b[8] = 0x84; // another response's opcode
  CHECK(opc.take(coe::decode_info(b).value()) == errc::unexpected_frame);
  std::array<std::uint8_t, 60> small{};
  coe::reassembler tight(small);
  CHECK(tight.take(coe::decode_info(frag(0)).value()) == false);
  CHECK(tight.take(coe::decode_info(frag(1)).value()) == errc::buffer_too_small);
  coe::reassembler req(joined);
  CHECK(req.take(coe::decode_info(bytes{8, 0, 0, 0, 0, 0x13, 0, 0x80, 1, 0, 0, 0, 1, 0}).value()) ==
        errc::unexpected_frame); // a request is no response
  // an SDO information error ends it with the abort code
  coe::reassembler err(joined);
  CHECK(err.take(coe::decode_info(frag(0)).value()) == false);
  CHECK(err.take(coe::decode_info(
                     bytes{10, 0, 0, 0, 0, 0x13, 0, 0x80, 7, 0, 0, 0, 0x00, 0x00, 0x02, 0x06})
                     .value()) == errc::aborted);
  CHECK(err.abort() == sdo::abort_code::no_object);
  err.reset();
  CHECK(err.data().empty());
  CHECK(err.abort() == sdo::abort_code::none);
  // an empty response is one fragment; no room at all for data: no fragments
  CHECK(coe::fragmenter(coe::info_opcode::get_object_description_response, {}, 12).count() == 1);
  CHECK(coe::fragmenter(coe::info_opcode::get_object_description_response, data, 12).count() == 0);
}
