// CoE codecs (canopen/coe/mailbox.hpp, service.hpp, sdo.hpp): hand-checked mailbox bytes from
// the layouts of ETG.1000.6 (mailbox header 5.5; CoE header 5.6.1 Table 29; SDO 5.6.2;
// emergency 5.6.4; PDO 5.6.5) and every kind of bad input with its precise error.
#include <fieldcodec/canopen/coe/mailbox.hpp>
#include <fieldcodec/canopen/coe/sdo.hpp>
#include <fieldcodec/canopen/coe/service.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

namespace coe = fieldcodec::canopen::coe;
namespace sdo = fieldcodec::canopen::sdo;
namespace emcy = fieldcodec::canopen::emcy;
using fieldcodec::errc;
using bytes = std::vector<std::uint8_t>;

namespace {
constexpr coe::mailbox_options master{};

/// The bytes an encoder wrote into a 128-byte mailbox.
template <class F>
bytes written(F encode) {
  std::array<std::uint8_t, 128> out{};
  const auto n = encode(std::span<std::uint8_t>(out));
  REQUIRE(n.has_value());
  return {out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n.value())};
}
bytes sdo_bytes(std::uint8_t counter, const coe::sdo_message &m) {
  return written([&](std::span<std::uint8_t> o) { return coe::encode_sdo(o, counter, master, m); });
}
coe::sdo_message sdo_of(const bytes &b, sdo::direction d) {
  auto r = coe::decode_sdo(b, d);
  REQUIRE(r.has_value());
  return r.value().sdo;
}
} // namespace

// ETG.1000.6 5.5: length 10, address 0, channel 0, priority 0, type 3 (CoE), counter 3 in
// bits 4..6 of byte 5.
static_assert(coe::encode_header({10, 0, 0, 0, 3, 3}).value() ==
              std::array<std::uint8_t, 6>{0x0A, 0x00, 0x00, 0x00, 0x00, 0x33});
static_assert(coe::encode_header({0x1234, 0x1001, 5, 3, 15, 7}).value() ==
              std::array<std::uint8_t, 6>{0x34, 0x12, 0x01, 0x10, 0xC5, 0x7F});
static_assert(coe::decode_header(std::array<std::uint8_t, 6>{0x0A, 0, 0, 0, 0, 0x23}).value() ==
              coe::mailbox_header{10, 0, 0, 0, 3, 2});
// the reserved bit 7 of byte 5 is ignored
static_assert(coe::decode_header(std::array<std::uint8_t, 6>{0x0A, 0, 0, 0, 0, 0xA3}).value() ==
              coe::mailbox_header{10, 0, 0, 0, 3, 2});
static_assert(coe::next_counter(0) == 1 && coe::next_counter(1) == 2 && coe::next_counter(7) == 1);
static_assert(coe::is_repeat(3, 3) && !coe::is_repeat(0, 0) && !coe::is_repeat(4, 3));
// CoE header (ETG.1000.6 5.6.1, Table 29): number in bits 0..8, service in bits 12..15
static_assert(coe::encode_coe_header({0, coe::service::sdo_request}).value() ==
              std::array<std::uint8_t, 2>{0x00, 0x20});
static_assert(coe::encode_coe_header({0x1FF, coe::service::sdo_information}).value() ==
              std::array<std::uint8_t, 2>{0xFF, 0x81});
static_assert(coe::decode_coe_header(std::array<std::uint8_t, 2>{0x01, 0x7E}).value() ==
              coe::coe_header{0x001, coe::service::rxpdo_remote_request}); // bits 9..11 ignored
static_assert(coe::initiate_capacity(16) == 0 && coe::initiate_capacity(128) == 112 &&
              coe::initiate_capacity(1486) == 1470);
static_assert(coe::segment_capacity(16) == 7 && coe::segment_capacity(128) == 119 &&
              coe::segment_capacity(1486) == 1477 && coe::segment_capacity(15) == 0);

TEST_CASE("mailbox header: bad fields and lengths") {
  CHECK(coe::encode_header({0, 0, 64, 0, 3, 1}) == errc::out_of_range);
  CHECK(coe::encode_header({0, 0, 0, 4, 3, 1}) == errc::out_of_range);
  CHECK(coe::encode_header({0, 0, 0, 0, 16, 1}) == errc::out_of_range);
  CHECK(coe::encode_header({0, 0, 0, 0, 3, 8}) == errc::out_of_range);
  const bytes five{0x0A, 0, 0, 0, 0};
  CHECK(coe::decode_header(five) == errc::truncated);
  CHECK(coe::decode(five) == errc::truncated);
  // the length field says 10 bytes, 9 are there: the length disagrees with the mailbox
  const bytes short_mbx{0x0A, 0, 0, 0, 0, 0x13, 0, 0x20, 0x40, 0, 0x10, 0, 0, 0, 0};
  CHECK(coe::decode(short_mbx) == errc::bad_length);
  // padding after 6 + length is ignored (a whole SyncManager area)
  bytes padded{0x02, 0, 0, 0, 0, 0x13, 0x01, 0x70};
  padded.resize(128, 0xEE);
  const auto m = coe::decode(padded).value();
  CHECK(m.data.size() == 2);
  CHECK(m.header.counter == 1);
  // writing: the header and body must fit the mailbox buffer
  std::array<std::uint8_t, 16> out{};
  CHECK(coe::write_header(out, coe::mailbox_type::coe, 1, master, 10).value().size() == 10);
  CHECK(coe::write_header(out, coe::mailbox_type::coe, 1, master, 11) == errc::too_long);
  CHECK(coe::write_header(std::span(out).first(5), coe::mailbox_type::coe, 1, master, 0) ==
        errc::too_long);
  CHECK(coe::write_header(out, coe::mailbox_type::coe, 9, master, 0) == errc::out_of_range);
  std::vector<std::uint8_t> big(70000);
  CHECK(coe::write_header(big, coe::mailbox_type::coe, 1, master, 65536) == errc::too_long);
  CHECK(coe::write_header(big, coe::mailbox_type::coe, 1, master, 65535).has_value());
}

TEST_CASE("mailbox error reply (ETG.1000.6 5.5: type 0, type word 1, detail)") {
  const auto b = written([](std::span<std::uint8_t> o) {
    return coe::encode_error_reply(o, 2, master, coe::mailbox_error::unsupported_protocol);
  });
  CHECK(b == bytes{0x04, 0x00, 0x00, 0x00, 0x00, 0x20, 0x01, 0x00, 0x02, 0x00});
  const auto m = coe::decode(b).value();
  CHECK(coe::decode_error_reply(m) == coe::mailbox_error::unsupported_protocol);
  CHECK(coe::to_errc(coe::mailbox_error::unsupported_protocol) == errc::unknown_command);
  CHECK(coe::to_string(coe::mailbox_error::invalid_size) == "mailbox data length not valid");
  CHECK(coe::to_string(static_cast<coe::mailbox_error>(0x42)).empty());
  CHECK(coe::to_errc(static_cast<coe::mailbox_error>(0x42)) == errc::unknown_command);
  for (std::uint16_t d = 1; d <= 8; ++d) {
    CHECK(!coe::to_string(static_cast<coe::mailbox_error>(d)).empty());
  }
  // bad replies
  CHECK(coe::decode_error_reply(coe::decode(bytes{2, 0, 0, 0, 0, 0x03, 0, 0x20}).value()) ==
        errc::unexpected_frame);
  CHECK(coe::decode_error_reply(coe::decode(bytes{3, 0, 0, 0, 0, 0, 1, 0, 2}).value()) ==
        errc::truncated);
  CHECK(coe::decode_error_reply(coe::decode(bytes{5, 0, 0, 0, 0, 0, 1, 0, 2, 0, 0}).value()) ==
        errc::too_long);
  CHECK(coe::decode_error_reply(coe::decode(bytes{4, 0, 0, 0, 0, 0, 2, 0, 2, 0}).value()) ==
        errc::unknown_command);
}

TEST_CASE("CoE header and mailbox: services, truncation, other mailbox types") {
  CHECK(coe::encode_coe_header({0x200, coe::service::txpdo}) == errc::out_of_range);
  CHECK(coe::encode_coe_header({0, static_cast<coe::service>(9)}) == errc::invalid_argument);
  CHECK(coe::encode_coe_header({0, static_cast<coe::service>(0)}) == errc::invalid_argument);
  CHECK(coe::decode_coe_header(bytes{0x00}) == errc::truncated);
  CHECK(coe::decode_coe_header(bytes{0x00, 0x00}) == errc::unknown_command); // service 0
  CHECK(coe::decode_coe_header(bytes{0x00, 0x90}) == errc::unknown_command); // service 9
  CHECK(coe::decode_coe_header(bytes{0x00, 0xF0}) == errc::unknown_command); // service 15
  // an EoE mailbox is not CoE
  CHECK(coe::decode_coe(bytes{2, 0, 0, 0, 0, 0x12, 0, 0x20}) == errc::unexpected_frame);
  // a CoE mailbox of one data byte: no room for the CoE header
  CHECK(coe::decode_coe(bytes{1, 0, 0, 0, 0, 0x13, 0}) == errc::truncated);
  std::array<std::uint8_t, 8> out{};
  CHECK(coe::write_coe_header(out, 1, master, {0, coe::service::txpdo}, 0).value().empty());
  CHECK(coe::write_coe_header(out, 1, master, {0, coe::service::txpdo}, 1) == errc::too_long);
}

TEST_CASE("emergency (ETG.1000.6 5.6.4): the 8 bytes of a CiA 301 EMCY after the CoE header") {
  const emcy::message m{0x8130, 0x11, {1, 2, 3, 4, 5}}; // heartbeat/guarding error
  const auto b =
      written([&](std::span<std::uint8_t> o) { return coe::encode_emergency(o, 4, master, m); });
  CHECK(b ==
        bytes{0x0A, 0x00, 0x00, 0x00, 0x00, 0x43, 0x00, 0x10, 0x30, 0x81, 0x11, 1, 2, 3, 4, 5});
  const auto c = coe::decode_coe(b).value();
  CHECK(c.coe == coe::coe_header{0, coe::service::emergency});
  CHECK(coe::decode_emergency(c) == m);
  // the same bytes as the CAN EMCY of node 1
  CHECK(emcy::encode(1, m).value().data == emcy::encode_payload(m));
  // bad emergencies
  CHECK(coe::decode_emergency(
            coe::decode_coe(bytes{9, 0, 0, 0, 0, 3, 0, 0x10, 1, 2, 3, 4, 5, 6, 7}).value()) ==
        errc::truncated);
  CHECK(
      coe::decode_emergency(
          coe::decode_coe(bytes{11, 0, 0, 0, 0, 3, 0, 0x10, 1, 2, 3, 4, 5, 6, 7, 8, 9}).value()) ==
      errc::too_long);
  CHECK(coe::decode_emergency(
            coe::decode_coe(bytes{10, 0, 0, 0, 0, 3, 0, 0x20, 1, 2, 3, 4, 5, 6, 7, 8}).value()) ==
        errc::unexpected_frame);
}

TEST_CASE("PDOs over the mailbox (ETG.1000.6 5.6.5)") {
  const std::array<std::uint8_t, 3> data{0x0F, 0x00, 0x08};
  const auto b = written([&](std::span<std::uint8_t> o) {
    return coe::encode_pdo(o, 1, master, {coe::service::rxpdo, 1, data});
  });
  CHECK(b == bytes{0x05, 0x00, 0x00, 0x00, 0x00, 0x13, 0x01, 0x50, 0x0F, 0x00, 0x08});
  const auto p = coe::decode_pdo(coe::decode_coe(b).value()).value();
  CHECK(p.svc == coe::service::rxpdo);
  CHECK(p.number == 1);
  CHECK(bytes(p.data.begin(), p.data.end()) == bytes{0x0F, 0x00, 0x08});
  // remote request of TxPDO 2: nothing after the CoE header
  const auto r = written([&](std::span<std::uint8_t> o) {
    return coe::encode_pdo(o, 2, master, {coe::service::txpdo_remote_request, 2, {}});
  });
  CHECK(r == bytes{0x02, 0x00, 0x00, 0x00, 0x00, 0x23, 0x02, 0x60});
  CHECK(coe::decode_pdo(coe::decode_coe(r).value()).value().data.empty());
  // bad input
  std::array<std::uint8_t, 64> out{};
  CHECK(coe::encode_pdo(out, 1, master, {coe::service::rxpdo_remote_request, 1, data}) ==
        errc::invalid_argument);
  CHECK(coe::encode_pdo(out, 1, master, {coe::service::sdo_request, 1, data}) ==
        errc::invalid_argument);
  CHECK(coe::encode_pdo(out, 1, master, {coe::service::txpdo, 512, data}) == errc::out_of_range);
  CHECK(coe::decode_pdo(coe::decode_coe(bytes{3, 0, 0, 0, 0, 3, 2, 0x60, 9}).value()) ==
        errc::too_long);
  CHECK(coe::decode_pdo(coe::decode_coe(bytes{2, 0, 0, 0, 0, 3, 0, 0x20}).value()) ==
        errc::unexpected_frame);
}

TEST_CASE("SDO in a mailbox: the messages of ETG.1000.6 5.6.2, byte by byte") {
  using t = sdo::message_type;
  // 5.6.2.4 SDO upload expedited request, 1018h:01 (identity, vendor ID): the CiA 301 bytes
  // 40 18 10 01 00 00 00 00 after the CoE header 00 20 (SDO request)
  coe::sdo_message up{.type = t::initiate_upload_request, .address = {0x1018, 1}};
  const bytes upload_request{0x0A, 0x00, 0x00, 0x00, 0x00, 0x13, 0x00, 0x20,
                             0x40, 0x18, 0x10, 0x01, 0x00, 0x00, 0x00, 0x00};
  CHECK(sdo_bytes(1, up) == upload_request);
  CHECK(sdo_of(upload_request, sdo::direction::to_server).address ==
        fieldcodec::od::address{0x1018, 1});
  // 5.6.2.4 expedited response with 4 bytes: 43, SDO response 00 30
  coe::sdo_message upr{.type = t::initiate_upload_response,
                       .expedited = true,
                       .size_indicated = true,
                       .address = {0x1018, 1},
                       .size = 4,
                       .value = 0x00000002};
  const bytes upload_response{0x0A, 0x00, 0x00, 0x00, 0x00, 0x23, 0x00, 0x30,
                              0x43, 0x18, 0x10, 0x01, 0x02, 0x00, 0x00, 0x00};
  CHECK(sdo_bytes(2, upr) == upload_response);
  const auto r = sdo_of(upload_response, sdo::direction::to_client);
  CHECK(r.expedited);
  CHECK(r.size == 4);
  CHECK(r.value == 2);
  // 5.6.2.1 expedited download of 2 bytes, 6040h = 000Fh: 2B
  coe::sdo_message dl{.type = t::initiate_download_request,
                      .expedited = true,
                      .size_indicated = true,
                      .address = {0x6040, 0},
                      .size = 2,
                      .value = 0x000F};
  CHECK(sdo_bytes(3, dl) == bytes{0x0A, 0x00, 0x00, 0x00, 0x00, 0x33, 0x00, 0x20, 0x2B, 0x40, 0x60,
                                  0x00, 0x0F, 0x00, 0x00, 0x00});
  // 5.6.2.2 download normal request: 21, complete size 6, then the 6 bytes: length 2 + 8 + 6
  const std::array<std::uint8_t, 6> abcdef{'A', 'B', 'C', 'D', 'E', 'F'};
  coe::sdo_message normal{
      .type = t::initiate_download_request, .address = {0x2000, 1}, .size = 6, .data = abcdef};
  const bytes normal_bytes{0x10, 0x00, 0x00, 0x00, 0x00, 0x43, 0x00, 0x20, 0x21, 0x00, 0x20,
                           0x01, 0x06, 0x00, 0x00, 0x00, 'A',  'B',  'C',  'D',  'E',  'F'};
  CHECK(sdo_bytes(4, normal) == normal_bytes);
  const auto n = sdo_of(normal_bytes, sdo::direction::to_server);
  CHECK(!n.expedited);
  CHECK(n.size == 6);
  CHECK(bytes(n.data.begin(), n.data.end()) == bytes(abcdef.begin(), abcdef.end()));
  // the first part of a segmented download: complete size 300, 2 bytes here
  coe::sdo_message part{.type = t::initiate_download_request,
                        .address = {0x2000, 1},
                        .size = 300,
                        .data = std::span(abcdef).first(2)};
  CHECK(sdo_bytes(5, part) == bytes{0x0C, 0x00, 0x00, 0x00, 0x00, 0x53, 0x00, 0x20, 0x21, 0x00,
                                    0x20, 0x01, 0x2C, 0x01, 0x00, 0x00, 'A', 'B'});
  // the download response: 60
  coe::sdo_message dr{.type = t::initiate_download_response, .address = {0x2000, 1}};
  CHECK(sdo_bytes(6, dr) == bytes{0x0A, 0x00, 0x00, 0x00, 0x00, 0x63, 0x00, 0x30, 0x60, 0x00, 0x20,
                                  0x01, 0x00, 0x00, 0x00, 0x00});
  // 5.6.2.3 download segment, toggle 1, last, 3 bytes: padded to 7, 4 unused: 10 | 08 | 01
  coe::sdo_message seg{.type = t::download_segment_request,
                       .toggle = true,
                       .last = true,
                       .data = std::span(abcdef).first(3)};
  const bytes seg_bytes{0x0A, 0x00, 0x00, 0x00, 0x00, 0x73, 0x00, 0x20,
                        0x19, 'A',  'B',  'C',  0x00, 0x00, 0x00, 0x00};
  CHECK(sdo_bytes(7, seg) == seg_bytes);
  const auto s = sdo_of(seg_bytes, sdo::direction::to_server);
  CHECK(s.toggle);
  CHECK(s.last);
  CHECK(s.data.size() == 3);
  // a segment of 20 bytes: the command byte says nothing unused, the length says 20
  std::array<std::uint8_t, 20> twenty{};
  for (std::size_t i = 0; i < twenty.size(); ++i) twenty[i] = static_cast<std::uint8_t>(i);
  coe::sdo_message useg{.type = t::upload_segment_response, .data = twenty};
  const auto ub = sdo_bytes(1, useg);
  CHECK(ub.size() == 6 + 2 + 1 + 20);
  CHECK(ub[0] == 23);
  CHECK(ub[6] == 0x00);
  CHECK(ub[7] == 0x30); // an upload segment is a response
  CHECK(ub[8] == 0x00);
  CHECK(sdo_of(ub, sdo::direction::to_client).data.size() == 20);
  // a segment of exactly 7 bytes, and one of none (last, all 7 unused: 0E | 01)
  coe::sdo_message seven{
      .type = t::upload_segment_response, .last = true, .data = std::span(twenty).first(7)};
  CHECK(sdo_bytes(1, seven)[8] == 0x01);
  coe::sdo_message none{.type = t::download_segment_request, .last = true};
  const auto nb = sdo_bytes(1, none);
  CHECK(nb[8] == 0x0F);
  CHECK(nb.size() == 16);
  CHECK(sdo_of(nb, sdo::direction::to_server).data.empty());
  // upload segment request 60 / 70 and download segment response 20 / 30
  CHECK(sdo_bytes(1, {.type = t::upload_segment_request, .toggle = true})[8] == 0x70);
  CHECK(sdo_bytes(1, {.type = t::download_segment_response, .toggle = true})[8] == 0x30);
  CHECK(sdo_bytes(1, {.type = t::download_segment_response})[7] == 0x30);
  // 5.6.2.7 abort: a request (service 2) from either side, code 06020000h little-endian
  coe::sdo_message ab{
      .type = t::abort, .address = {0x6000, 0}, .abort = sdo::abort_code::no_object};
  const bytes abort_bytes{0x0A, 0x00, 0x00, 0x00, 0x00, 0x13, 0x00, 0x20,
                          0x80, 0x00, 0x60, 0x00, 0x00, 0x00, 0x02, 0x06};
  CHECK(sdo_bytes(1, ab) == abort_bytes);
  CHECK(sdo_of(abort_bytes, sdo::direction::to_client).abort == sdo::abort_code::no_object);
  CHECK(sdo_of(abort_bytes, sdo::direction::to_server).abort == sdo::abort_code::no_object);
  // an abort sent as an SDO response is taken too
  bytes abort_as_response = abort_bytes;
  abort_as_response[7] = 0x30;
  CHECK(sdo_of(abort_as_response, sdo::direction::to_client).type == t::abort);
}

TEST_CASE("SDO complete access (bit 4 of an initiate): sub-index 0 included or not") {
  using t = sdo::message_type;
  // upload of 1C12h with sub-index 0 included: 50 12 1C 00
  coe::sdo_message ca{
      .type = t::initiate_upload_request, .complete_access = true, .address = {0x1C12, 0}};
  const auto b = sdo_bytes(1, ca);
  CHECK(bytes(b.begin() + 8, b.end()) == bytes{0x50, 0x12, 0x1C, 0x00, 0, 0, 0, 0});
  CHECK(sdo_of(b, sdo::direction::to_server).complete_access);
  // sub-index 0 excluded: sub-index 1
  ca.address.sub = 1;
  CHECK(sdo_bytes(1, ca)[11] == 0x01);
  // a normal download with complete access: 31
  const std::array<std::uint8_t, 4> v{0x02, 0x00, 0x00, 0x16};
  coe::sdo_message cd{.type = t::initiate_download_request,
                      .complete_access = true,
                      .address = {0x1C12, 0},
                      .size = 4,
                      .data = v};
  const auto db = sdo_bytes(1, cd);
  CHECK(db[8] == 0x31);
  CHECK(db.size() == 20);
  const auto d = sdo_of(db, sdo::direction::to_server);
  CHECK(d.complete_access);
  CHECK(d.size == 4);
  // the response keeps the bit
  CHECK(sdo_bytes(1, {.type = t::initiate_download_response,
                      .complete_access = true,
                      .address = {0x1C12, 0}})[8] == 0x70);
  // complete access names sub-index 0 or 1 only
  std::array<std::uint8_t, 32> out{};
  ca.address.sub = 2;
  CHECK(coe::encode_sdo(out, 1, master, ca) == errc::out_of_range);
  bytes bad = b;
  bad[11] = 2;
  CHECK(coe::decode_sdo(bad, sdo::direction::to_server) == errc::out_of_range);
  // and belongs to initiates only
  CHECK(coe::encode_sdo(out, 1, master,
                        {.type = t::upload_segment_request, .complete_access = true}) ==
        errc::invalid_argument);
}

TEST_CASE("SDO in a mailbox: bad input gets a precise error") {
  using t = sdo::message_type;
  const auto d = [](std::initializer_list<std::uint8_t> body, sdo::direction dir,
                    std::uint8_t svc = 0x20) {
    bytes b{static_cast<std::uint8_t>(2 + body.size()), 0, 0, 0, 0, 0x13, 0x00, svc};
    b.insert(b.end(), body);
    return coe::decode_sdo(b, dir);
  };
  constexpr auto S = sdo::direction::to_server;
  constexpr auto C = sdo::direction::to_client;
  // truncated: no SDO byte, a header of 7 bytes, a segment of 1 + 6
  CHECK(d({}, S) == errc::truncated);
  CHECK(d({0x40, 0x00, 0x10, 0x00, 0, 0, 0}, S) == errc::truncated);
  CHECK(d({0x00, 1, 2, 3, 4, 5, 6}, S) == errc::truncated);
  // too long: messages of 8 bytes with more
  CHECK(d({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0, 9}, S) == errc::too_long);
  CHECK(d({0x2B, 0x40, 0x60, 0x00, 0x0F, 0, 0, 0, 9}, S) == errc::too_long);
  CHECK(d({0x60, 0, 0, 0, 0, 0, 0, 0, 9}, S) == errc::too_long);
  CHECK(d({0x80, 0, 0x10, 0, 0, 0, 0, 0, 9}, S) == errc::too_long);
  CHECK(d({0x60, 0x00, 0x10, 0x00, 0, 0, 0, 0, 9}, C, 0x30) == errc::too_long);
  // a normal initiate without its size, or with more data than its size
  CHECK(d({0x20, 0x00, 0x20, 0x01, 0, 0, 0, 0, 1}, S) == errc::bad_length);
  CHECK(d({0x21, 0x00, 0x20, 0x01, 1, 0, 0, 0, 1, 2}, S) == errc::bad_length);
  CHECK(d({0x41, 0x00, 0x20, 0x01, 1, 0, 0, 0, 1, 2}, C, 0x30) == errc::bad_length);
  // a long segment whose command byte says bytes are unused
  CHECK(d({0x02, 1, 2, 3, 4, 5, 6, 7, 8}, S) == errc::bad_length);
  // block transfer and command specifier 7 do not exist in CoE
  CHECK(d({0xC6, 0x00, 0x20, 0x01, 20, 0, 0, 0}, S) == errc::unknown_command);
  CHECK(d({0xA4, 0x00, 0x20, 0x01, 0x7F, 0, 0, 0}, S) == errc::unknown_command);
  CHECK(d({0xE0, 0x00, 0x20, 0x01, 0, 0, 0, 0}, S) == errc::unknown_command);
  // the wrong service for the direction
  CHECK(d({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}, S, 0x30) == errc::unexpected_frame);
  CHECK(d({0x60, 0x00, 0x10, 0x00, 0, 0, 0, 0}, C, 0x20) == errc::unexpected_frame);
  CHECK(d({0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}, S, 0x10) == errc::unexpected_frame); // EMCY
  // encoding: messages that do not fit, data where none belongs
  std::array<std::uint8_t, 16> small{};
  const std::array<std::uint8_t, 2> two{1, 2};
  CHECK(
      coe::encode_sdo(
          small, 1, master,
          {.type = t::initiate_download_request, .address = {0x2000, 1}, .size = 2, .data = two}) ==
      errc::too_long);
  CHECK(coe::encode_sdo(small, 1, master,
                        {.type = t::initiate_download_request, .address = {0x2000, 1}, .size = 2})
            .value() == 16); // no data: the initiate of a segmented download in a 16-byte mailbox
  std::array<std::uint8_t, 64> out{};
  CHECK(
      coe::encode_sdo(
          out, 1, master,
          {.type = t::initiate_download_request, .address = {0x2000, 1}, .size = 1, .data = two}) ==
      errc::bad_length);
  CHECK(coe::encode_sdo(out, 1, master, {.type = t::initiate_upload_request, .data = two}) ==
        errc::invalid_argument);
  CHECK(coe::encode_sdo(out, 1, master,
                        {.type = t::initiate_download_request, .expedited = true, .data = two}) ==
        errc::invalid_argument);
  CHECK(coe::encode_sdo(out, 1, master, {.type = t::block_ack}) == errc::invalid_argument);
  CHECK(coe::encode_sdo(out, 1, master,
                        {.type = t::initiate_download_request,
                         .expedited = true,
                         .size_indicated = true,
                         .size = 5}) == errc::too_long); // sdo::encode's check
  CHECK(coe::encode_sdo(out, 9, master, {.type = t::initiate_upload_request}) ==
        errc::out_of_range); // counter
}
