// sdo::client::on_frames (round 6): several received frames at once, as a CAN driver drains its
// receive FIFO. Its promise is that nothing changes against on_frame: two clients get the same
// random streams from a real server — block uploads of random sizes, sub-block sizes and
// protocol switch thresholds with and without CRC, segmented and expedited uploads, downloads
// of every kind (which also give the uploaded object a random size) — with lost, repeated and
// corrupted frames of the server, frames of other COB-IDs, remote frames, wrong DLCs, aborts and
// random bytes in between, buffers too small, and time passing (and timeouts) between the
// calls: one frame at a time through on_frame (the reference, whose requests the server
// answers) and in random batches through on_frames. After every call of on_frames: the frames
// taken before the last one answered nothing, the last one's step is the one on_frame gave
// (frames, state, deadline), and both clients (state, error, deadline, bytes transferred, every
// received byte) agree.
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include "batch_stream.hpp"
#include "xorshift.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

namespace fc = fieldcodec;
namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
using sdo::transfer_state;

namespace {

constexpr od::entry_spec client_entries_spec[] = {
    {.index = 0x1000, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(7)},
    {.index = 0x2000, .type = od::data_type::domain, .size = 3000},
    {.index = 0x2001,
     .type = od::data_type::visible_string,
     .access_type = od::access::ro,
     .size = 32,
     .default_text = "read only"},
};
constexpr auto client_entries = od::entries_of<client_entries_spec>;
constexpr od::dictionary client_dict{client_entries};
constexpr auto client_layout = co::make_layout<std::size(client_entries)>(client_dict);
constexpr std::uint8_t node = 5;
constexpr std::uint16_t response_id = 0x580U + node;
constexpr std::uint32_t timeout_ms = 100;

using store_type = co::dictionary_store<>;

std::vector<co::can_frame> list(const co::frames &fs) { return {fs.begin(), fs.end()}; }

/// The knobs of one stream.
struct stream_options {
  std::uint64_t seed = 1;
  std::size_t server_buffer = 889;
  bool server_crc = true;
  unsigned fault_per_mille = 0; ///< each frame of the server: lost, repeated or corrupted
  unsigned junk_percent = 0;    ///< each chunk: frames that are no part of the transfer
  unsigned pause_percent = 0;   ///< each chunk: time passes before it (sometimes a timeout)
  std::size_t chunks = 400;
};

/// What a stream exercised (so that a test cannot pass by exercising nothing).
struct stream_counts {
  std::size_t frames = 0, calls = 0, long_takes = 0, completed = 0, failed = 0,
              block_uploads_done = 0;
};

/// One client with its own upload buffer.
template <class Crc>
struct client_side {
  sdo::basic_client<Crc> client{node, timeout_ms};
  std::vector<std::uint8_t> buffer;
};

template <class Crc>
stream_counts run_stream(const stream_options &o) {
  fc::test::xorshift r(o.seed);
  const auto below = [&r](std::uint64_t n) { return static_cast<std::size_t>(r.next() % n); };
  std::vector<std::uint8_t> storage(store_type::storage_size(client_dict));
  std::vector<std::uint8_t> staging(3000);
  store_type store{client_dict, client_layout, storage, staging};
  REQUIRE(store.init_defaults(node).has_value());
  std::vector<std::uint8_t> server_buffer(o.server_buffer);
  sdo::server<store_type, Crc> server(node, store, server_buffer, timeout_ms,
                                      {.block = true, .crc = o.server_crc});
  client_side<Crc> one;                // on_frame, frame by frame (the server answers it)
  client_side<Crc> batch;              // on_frames, in batches
  std::vector<std::uint8_t> data;      // the running download's bytes (the clients borrow them)
  std::deque<co::can_frame> to_client; // what the server sent, after the faults
  std::vector<co::can_frame> chunk;
  std::uint32_t now = 1000;
  bool block_upload = false; // the running transfer is a block upload
  stream_counts n;

  const auto from_server = [&](const co::frames &fs) {
    // a corrupted byte (often the first)
    fc::test::send_over_faulty_link(fs, to_client, o.fault_per_mille, r, [&](co::can_frame &g) {
      g.data[below(2) == 0 ? 0U : below(8)] = static_cast<std::uint8_t>(r.next());
    });
  };
  const auto to_server = [&](const std::vector<co::can_frame> &fs) {
    for (const co::can_frame &f : fs) from_server(server.on_frame(f, now).send);
  };
  const auto junk = [&]() {
    co::can_frame f{response_id, false, 8, {}};
    for (auto &b : f.data) b = static_cast<std::uint8_t>(r.next());
    switch (below(9)) {
    case 0: f.id = static_cast<std::uint16_t>(0x80U + below(0x780)); break; // another COB-ID
    case 1: f.id = 0x605; break;                                            // the request ID
    case 2: // a remote frame on the response ID
      f.rtr = true;
      f.data = {};
      break;
    case 3: f.dlc = static_cast<std::uint8_t>(below(8)); break; // a wrong DLC
    case 4: f.data = sdo::abort({0x2000, 0}, sdo::abort_code::general_error); break;
    case 5: f.id = static_cast<std::uint16_t>(response_id | 0x800U); break; // beyond 11 bits
    case 6: f.data[0] = static_cast<std::uint8_t>(1U + below(127)); break;  // a block segment
    default: break; // 8 random bytes on the response ID
    }
    return f;
  };
  const auto same_clients = [&]() {
    CHECK(one.client.state() == batch.client.state());
    CHECK(one.client.error() == batch.client.error());
    CHECK(one.client.deadline() == batch.client.deadline());
    CHECK(one.client.transferred() == batch.client.transferred());
    const auto a = one.client.received();
    const auto b = batch.client.received();
    CHECK(std::equal(a.begin(), a.end(), b.begin(), b.end()));
  };
  // start the same transfer on both clients; the reference's request goes to the server
  const auto start = [&]() {
    const std::size_t kind = below(10);
    block_upload = kind < 5U;
    if (kind < 7U) { // an upload: block (with a random sub-block size, threshold, CRC) or not
      const std::size_t size = below(4) == 0 ? below(1000) : 3200;
      one.buffer.assign(size, 0);
      batch.buffer.assign(size, 0);
      const od::address a{below(8) == 0   ? std::uint16_t{0x1000}
                          : below(8) == 0 ? std::uint16_t{0x2001}
                                          : std::uint16_t{0x2000},
                          0};
      sdo::block_options bo;
      bo.block_size = static_cast<std::uint8_t>(below(3) == 0 ? 1U + below(127) : 127U);
      bo.switch_threshold = static_cast<std::uint8_t>(below(4) == 0 ? below(40) : 0U);
      bo.crc = below(3) != 0;
      const auto s = block_upload ? one.client.block_upload(a, one.buffer, now, bo)
                                  : one.client.upload(a, one.buffer, now);
      const auto t = block_upload ? batch.client.block_upload(a, batch.buffer, now, bo)
                                  : batch.client.upload(a, batch.buffer, now);
      REQUIRE(s.has_value());
      REQUIRE(t.has_value());
      CHECK(list(s.value().send) == list(t.value().send));
      to_server(list(s.value().send));
      return;
    }
    // a download of random bytes to 2000h (the size of the next uploads) or 1000h
    const std::size_t size = below(4) == 0 ? below(3200) : below(1000);
    data.resize(kind == 9U && below(2) == 0 ? 1U + below(4) : size);
    for (auto &b : data) b = static_cast<std::uint8_t>(r.next());
    const od::address a{data.size() == 4U ? std::uint16_t{0x1000} : std::uint16_t{0x2000}, 0};
    sdo::block_options bo;
    bo.crc = below(3) != 0;
    const auto s = kind == 7U ? one.client.block_download(a, data, now, bo)
                              : one.client.download(a, data, now);
    const auto t = kind == 7U ? batch.client.block_download(a, data, now, bo)
                              : batch.client.download(a, data, now);
    REQUIRE(s.has_value());
    REQUIRE(t.has_value());
    CHECK(list(s.value().send) == list(t.value().send));
    to_server(list(s.value().send));
  };

  for (std::size_t c = 0; c < o.chunks; ++c) {
    // time passes (the client waits for an answer that was lost: past its timeout): both
    // clients and the server look at it
    const bool waiting = one.client.busy() && to_client.empty();
    if (waiting || below(100) < o.pause_percent) {
      now += static_cast<std::uint32_t>(waiting ? timeout_ms + 1U : below(2 * timeout_ms));
      from_server(server.poll(now).send);
      const auto sent = list(one.client.poll(now).send);
      CHECK(sent == list(batch.client.poll(now).send));
      same_clients();
      if (one.client.state() == transfer_state::failed && sent.size() == 1U) ++n.failed;
      to_server(sent);
    }
    if (!one.client.busy() && to_client.empty()) start();
    // a few rounds of what is queued (a segmented transfer has one frame in flight)
    for (std::size_t round = 1U + below(16); round > 0U; --round) {
      if (round > 1U && to_client.empty()) continue;
      fc::test::take_chunk(to_client, chunk, r, 60, o.junk_percent, 3, junk, true);
      // the chunk in random batches (sometimes empty ones), at the same `now`
      fc::test::in_random_batches(chunk, r, [&](std::span<const co::can_frame> span) {
        const std::size_t take = span.size();
        const sdo::batch_step b = batch.client.on_frames(span, now);
        ++n.calls;
        const auto b_sent = list(b.last.send);
        if (take == 0U) {
          CHECK(b.consumed == 0U);
          CHECK(b_sent.empty());
          CHECK(b.last.state == one.client.state());
          CHECK(b.last.deadline == one.client.deadline());
          same_clients();
          return std::size_t{0};
        }
        REQUIRE(b.consumed >= 1U);
        REQUIRE(b.consumed <= take);
        if (b.consumed > 1U) ++n.long_takes;
        for (std::size_t j = 0; j < b.consumed; ++j) {
          const transfer_state before = one.client.state();
          const sdo::step a = one.client.on_frame(span[j], now);
          const auto sent = list(a.send);
          ++n.frames;
          const bool answered = !sent.empty() || a.state != before;
          if (a.state != before && a.state == transfer_state::done) {
            ++n.completed;
            if (block_upload) ++n.block_uploads_done;
          }
          if (a.state != before && a.state == transfer_state::failed) ++n.failed;
          if (j + 1U < b.consumed) {
            CHECK_FALSE(answered); // on_frames went past a frame that answered
          } else {
            CHECK((answered || b.consumed == take)); // it stopped at a frame that did not
            CHECK(sent == b_sent);
            CHECK(a.state == b.last.state);
            CHECK(a.deadline == b.last.deadline);
          }
          to_server(sent);
        }
        same_clients();
        return b.consumed;
      });
    }
  }
  return n;
}

template <class Crc>
void run_streams() {
  // clean transfers, then faults, junk and pauses; server buffers that limit the sub-blocks
  const stream_options cases[] = {
      {.seed = 1},
      {.seed = 2, .server_buffer = 2 * 889, .server_crc = false},
      {.seed = 3, .server_buffer = 100, .fault_per_mille = 10, .junk_percent = 10},
      {.seed = 4, .fault_per_mille = 30, .junk_percent = 30, .pause_percent = 10},
      {.seed = 5,
       .server_buffer = 3200,
       .fault_per_mille = 5,
       .junk_percent = 5,
       .pause_percent = 20},
      {.seed = 6,
       .server_buffer = 1000,
       .fault_per_mille = 10,
       .junk_percent = 10,
       .pause_percent = 5,
       .chunks = 1500},
      {.seed = 7,
       .server_buffer = 64,
       .server_crc = false,
       .fault_per_mille = 50,
       .junk_percent = 50,
       .pause_percent = 30},
  };
  stream_counts total;
  for (const auto &o : cases) {
    CAPTURE(o.seed);
    const stream_counts n = run_stream<Crc>(o);
    total.frames += n.frames;
    total.calls += n.calls;
    total.long_takes += n.long_takes;
    total.completed += n.completed;
    total.failed += n.failed;
    total.block_uploads_done += n.block_uploads_done;
    CHECK(n.block_uploads_done > 3U); // the stream moved data, not only aborts
  }
  CHECK(total.long_takes > 1000U);
  CHECK(total.failed > 50U);
  MESSAGE("frames ", total.frames, ", calls ", total.calls, ", completed ", total.completed,
          " (block uploads ", total.block_uploads_done, "), failed ", total.failed);
}

constexpr co::can_frame response(const sdo::payload &p) { return {response_id, false, 8, p}; }

/// on_frames in a constant expression: a segmented upload of 10 bytes, the initiate response,
/// both segments and a frame of another COB-ID in one span (the first segment answers with the
/// next request, the second ends the transfer). (A block upload's segments go through
/// on_frame's `raw_ != nullptr`, which g++ 12 with -fsanitize=undefined cannot evaluate in a
/// constant expression; the run itself, take_run, is tested so in
/// sdo_server_batch_test.cpp.)
constexpr bool segmented_upload_in_constant_evaluation() {
  std::array<std::uint8_t, 10> bytes{};
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(3U * i + 1U);
  std::array<std::uint8_t, 16> buffer{};
  sdo::client c(node, timeout_ms);
  if (!c.upload({0x2000, 0}, buffer, 0).has_value()) return false;
  const auto first =
      sdo::upload_segment(false, std::span<const std::uint8_t>(bytes).first(7), false);
  const auto second =
      sdo::upload_segment(true, std::span<const std::uint8_t>(bytes).subspan(7), true);
  if (!first || !second) return false;
  const std::array<co::can_frame, 4> rx{response(sdo::upload_response({0x2000, 0}, 10)),
                                        co::can_frame{0x181, false, 8, {}}, response(first.value()),
                                        response(second.value())};
  auto b = c.on_frames(rx, 1); // the initiate response answers with the first request
  if (b.consumed != 1U || b.last.send.size() != 1U) return false;
  b = c.on_frames(std::span<const co::can_frame>(rx).subspan(1), 2);
  if (b.consumed != 2U || b.last.send.size() != 1U) return false; // the next request
  b = c.on_frames(std::span<const co::can_frame>(rx).subspan(3), 3);
  if (b.consumed != 1U || b.last.state != transfer_state::done) return false;
  const auto got = c.received();
  return got.size() == 10U && std::equal(got.begin(), got.end(), bytes.begin());
}
static_assert(segmented_upload_in_constant_evaluation());

} // namespace

TEST_CASE("sdo::client::on_frames: the same frames, states, errors and bytes as on_frame") {
  run_streams<fc::crc::ccitt16_no_table>();
}

TEST_CASE("sdo::client::on_frames with the CRC table: the same as on_frame") {
  run_streams<fc::crc::ccitt16_with_table>();
}

TEST_CASE("sdo::client::on_frames: the contract on hand-made frames") {
  sdo::client c(node, timeout_ms);
  const co::can_frame other{0x181, false, 8, {1, 2, 3, 4, 5, 6, 7, 8}};
  const co::can_frame remote{response_id, true, 0, {}};
  const co::can_frame expedited = response(
      sdo::expedited_upload_response({0x1000, 0}, std::array<std::uint8_t, 4>{7, 0, 0, 0}).value());

  // an empty span: nothing taken, the state as it is
  auto b = c.on_frames({}, 0);
  CHECK(b.consumed == 0U);
  CHECK(b.last.send.empty());
  CHECK(b.last.state == transfer_state::idle);
  CHECK_FALSE(b.last.deadline.has_value());

  // while no transfer runs every frame is taken and changes nothing, even a response
  const std::array<co::can_frame, 3> idle{other, expedited, remote};
  b = c.on_frames(idle, 0);
  CHECK(b.consumed == 3U);
  CHECK(b.last.send.empty());
  CHECK(b.last.state == transfer_state::idle);

  // the first frame that answers ends the call: here the state change to done
  std::array<std::uint8_t, 4> value{};
  REQUIRE(c.upload({0x1000, 0}, value, 5).has_value());
  const std::array<co::can_frame, 4> mixed{other, remote, expedited, other};
  b = c.on_frames(mixed, 10);
  CHECK(b.consumed == 3U);
  CHECK(b.last.send.empty());
  CHECK(b.last.state == transfer_state::done);
  CHECK(c.received().size() == 4U);
  CHECK(value[0] == 7U);
  b = c.on_frames(std::span(mixed).subspan(3), 10);
  CHECK(b.consumed == 1U);
  CHECK(b.last.state == transfer_state::done);

  // a wrong DLC on the response ID fails the transfer with an abort, as on_frame does
  REQUIRE(c.upload({0x1000, 0}, value, 20).has_value());
  co::can_frame short_frame = expedited;
  short_frame.dlc = 7;
  const std::array<co::can_frame, 2> refused{short_frame, expedited};
  b = c.on_frames(refused, 20);
  CHECK(b.consumed == 1U);
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].id == 0x605U);
  CHECK(b.last.state == transfer_state::failed);
  REQUIRE(c.error().has_value());
  CHECK(c.error()->code == fc::errc::bad_length);

  // a block upload of 21 bytes with CRC, sub-blocks of 2 segments: the first sub-block in one
  // call up to the acknowledgement, the second one and the end in the next two
  std::array<std::uint8_t, 21> bytes{};
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(i + 1U);
  std::array<std::uint8_t, 32> buffer{};
  sdo::block_options bo;
  bo.block_size = 2;
  REQUIRE(c.block_upload({0x2000, 0}, buffer, 30, bo).has_value());
  b = c.on_frames(
      std::array{response(sdo::block_upload_initiate_response({0x2000, 0}, 21, true, true))}, 31);
  CHECK(b.consumed == 1U);
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].data == sdo::block_upload_start());
  std::vector<co::can_frame> rx;
  for (std::uint8_t k = 0; k < 3U; ++k) {
    rx.push_back(response(
        sdo::encode_block_segment(static_cast<std::uint8_t>(k % 2U + 1U),
                                  std::span<const std::uint8_t>(bytes).subspan(7U * k, 7U), k == 2U)
            .value()));
    if (k == 0U) rx.push_back(other);
  }
  rx.push_back(rx.back()); // the last segment once more: ignored while the end is awaited
  rx.push_back(response(sdo::block_end(0, fc::crc::ccitt16(bytes)).value()));
  b = c.on_frames(rx, 40);
  CHECK(b.consumed == 3U); // segment 1, another COB-ID, segment 2: acknowledged
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].data == sdo::block_ack(2, 2).value());
  CHECK(b.last.deadline == 40U + timeout_ms);
  CHECK(c.transferred() == 14U);
  b = c.on_frames(std::span(rx).subspan(3), 41);
  CHECK(b.consumed == 1U); // the last segment: acknowledged
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].data == sdo::block_ack(1, 2).value());
  b = c.on_frames(std::span(rx).subspan(4), 42);
  CHECK(b.consumed == 2U); // the repeat, then the end: done, the end response sent
  CHECK(b.last.state == transfer_state::done);
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].data == sdo::block_end_response());
  CHECK(std::equal(bytes.begin(), bytes.end(), c.received().begin(), c.received().end()));
}
