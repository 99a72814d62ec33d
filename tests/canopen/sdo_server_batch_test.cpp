// sdo::server::on_frames (round 6): several received frames at once, as a CAN driver drains its
// receive FIFO. Its promise is that nothing changes against on_frame: two servers over two
// stores get the same random streams — block downloads of random sizes with and without CRC
// (from a real client that follows the server's answers), lost, repeated, reordered and
// corrupted segments, frames of other COB-IDs, remote frames, wrong DLCs, other commands and
// aborts in between, sizes over the object's capacity and the buffer's, time passing (and
// timeouts) between the calls — one frame at a time through on_frame (the reference) and in
// random batches through on_frames. After every call of on_frames: the frames taken before the
// last one answered nothing, the last one's step is the one on_frame gave (frames, state,
// deadline), and both machines (state, error, deadline) and both stores (every byte, the
// staging area too) agree.
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry_spec.hpp>

#include <doctest/doctest.h>

#include "batch_stream.hpp"
#include "xorshift.hpp"

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

constexpr od::entry_spec batch_entries_spec[] = {
    {.index = 0x1000, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(7)},
    {.index = 0x2000, .type = od::data_type::domain, .size = 3000},
    {.index = 0x2001,
     .type = od::data_type::visible_string,
     .access_type = od::access::ro,
     .size = 32,
     .default_text = "read only"},
    {.index = 0x2002, .type = od::data_type::domain, .size = 300},
};
constexpr auto batch_entries = od::entries_of<batch_entries_spec>;
constexpr od::dictionary batch_dict{batch_entries};
constexpr auto batch_layout = co::make_layout<std::size(batch_entries)>(batch_dict);
constexpr std::uint8_t node = 5;
constexpr std::uint16_t request_id = 0x600U + node;
constexpr std::uint32_t timeout_ms = 100;

using store_type = co::dictionary_store<>;

/// One server with its own store and buffer.
template <class Crc>
struct side {
  std::vector<std::uint8_t> storage =
      std::vector<std::uint8_t>(store_type::storage_size(batch_dict));
  std::vector<std::uint8_t> staging = std::vector<std::uint8_t>(3000);
  store_type store{batch_dict, batch_layout, storage, staging};
  std::vector<std::uint8_t> buffer;
  sdo::server<store_type, Crc> server;

  side(std::size_t buffer_size, sdo::server_options o)
      : buffer(buffer_size), server(node, store, buffer, timeout_ms, o) {
    REQUIRE(store.init_defaults(node).has_value());
  }
};

std::vector<co::can_frame> list(const co::frames &fs) { return {fs.begin(), fs.end()}; }

/// The knobs of one stream.
struct stream_options {
  std::uint64_t seed = 1;
  std::size_t buffer = 889;
  bool server_crc = true;
  unsigned fault_per_mille = 0; ///< each frame of the client: lost, repeated or corrupted
  unsigned junk_percent = 0;    ///< each chunk: frames that are no part of the transfer
  unsigned pause_percent = 0;   ///< each chunk: time passes before it (sometimes a timeout)
  std::size_t chunks = 400;
};

/// What a stream exercised (so that a test cannot pass by exercising nothing).
struct stream_counts {
  std::size_t frames = 0, calls = 0, long_takes = 0, completed = 0, failed = 0, refused = 0;
};

template <class Crc>
stream_counts run_stream(const stream_options &o) {
  fc::test::xorshift r(o.seed);
  const auto below = [&r](std::uint64_t n) { return static_cast<std::size_t>(r.next() % n); };
  side<Crc> one(o.buffer, {.block = true, .crc = o.server_crc});   // on_frame, frame by frame
  side<Crc> batch(o.buffer, {.block = true, .crc = o.server_crc}); // on_frames, in batches
  sdo::client client(node, timeout_ms);
  std::vector<std::uint8_t> data;      // the running download's bytes (the client borrows them)
  std::deque<co::can_frame> to_server; // what the client sent, after the faults
  std::vector<co::can_frame> chunk;
  std::uint32_t now = 1000;
  stream_counts n;

  const auto from_client = [&](const co::frames &fs) {
    // a corrupted sequence number or command
    fc::test::send_over_faulty_link(fs, to_server, o.fault_per_mille, r, [&](co::can_frame &g) {
      g.data[0] = static_cast<std::uint8_t>(r.next());
    });
  };
  const auto to_client = [&](const std::vector<co::can_frame> &fs) {
    for (const co::can_frame &f : fs) from_client(client.on_frame(f, now).send);
  };
  const auto junk = [&]() {
    co::can_frame f{request_id, false, 8, {}};
    for (auto &b : f.data) b = static_cast<std::uint8_t>(r.next());
    switch (below(8)) {
    case 0: f.id = static_cast<std::uint16_t>(0x80U + below(0x780)); break; // another COB-ID
    case 1: f.id = 0x585; break;                                            // the response ID
    case 2: // a remote frame on the request ID
      f.rtr = true;
      f.data = {};
      break;
    case 3: f.dlc = static_cast<std::uint8_t>(below(8)); break; // a wrong DLC
    case 4: f.data = sdo::initiate_upload({0x1000, 0}); break;  // another command
    case 5: f.data = sdo::abort({0x2000, 0}, sdo::abort_code::general_error); break;
    case 6: f.id = static_cast<std::uint16_t>(request_id | 0x800U); break; // beyond 11 bits
    default: break; // 8 random bytes on the request ID
    }
    return f;
  };
  const auto same_machines = [&]() {
    CHECK(one.server.state() == batch.server.state());
    CHECK(one.server.error() == batch.server.error());
    CHECK(one.server.deadline() == batch.server.deadline());
    CHECK(one.storage == batch.storage);
    CHECK(one.staging == batch.staging);
  };

  for (std::size_t c = 0; c < o.chunks; ++c) {
    // time passes (the client waits for an answer that was lost: past its timeout): both
    // servers and the client look at it
    const bool waiting = client.busy() && to_server.empty();
    if (waiting || below(100) < o.pause_percent) {
      now += static_cast<std::uint32_t>(waiting ? timeout_ms + 1U : below(2 * timeout_ms));
      const co::frames a = one.server.poll(now).send; // a copy: poll is a call into the machine
      const auto sent = list(a);
      CHECK(sent == list(batch.server.poll(now).send));
      same_machines();
      to_client(sent);
      from_client(client.poll(now).send);
    }
    if (!client.busy() && to_server.empty()) { // a new block download
      const std::size_t size = below(4) == 0 ? below(3200) : below(1000);
      data.resize(size);
      for (auto &b : data) b = static_cast<std::uint8_t>(r.next());
      const od::address a{below(6) == 0 ? std::uint16_t{0x2002} : std::uint16_t{0x2000}, 0};
      sdo::block_options bo;
      bo.crc = below(3) != 0;
      const auto s = client.block_download(a, data, now, bo);
      REQUIRE(s.has_value());
      from_client(s.value().send);
    }
    fc::test::take_chunk(to_server, chunk, r, 60, o.junk_percent, 3, junk, true);
    // the chunk in random batches (sometimes empty ones), at the same `now`
    fc::test::in_random_batches(chunk, r, [&](std::span<const co::can_frame> span) {
      const std::size_t take = span.size();
      const sdo::batch_step b = batch.server.on_frames(span, now);
      ++n.calls;
      const auto b_sent = list(b.last.send);
      if (take == 0U) {
        CHECK(b.consumed == 0U);
        CHECK(b_sent.empty());
        CHECK(b.last.state == one.server.state());
        CHECK(b.last.deadline == one.server.deadline());
        same_machines();
        return std::size_t{0};
      }
      REQUIRE(b.consumed >= 1U);
      REQUIRE(b.consumed <= take);
      if (b.consumed > 1U) ++n.long_takes;
      for (std::size_t j = 0; j < b.consumed; ++j) {
        const co::can_frame &f = span[j];
        const transfer_state before = one.server.state();
        const sdo::step a = one.server.on_frame(f, now);
        const auto sent = list(a.send);
        ++n.frames;
        const bool refused = f.id == request_id && !f.rtr && f.dlc != 8U;
        const bool answered = !sent.empty() || a.state != before || refused;
        if (refused) ++n.refused;
        if (a.state != before && a.state == transfer_state::done) ++n.completed;
        if (a.state != before && a.state == transfer_state::failed) ++n.failed;
        if (j + 1U < b.consumed) {
          CHECK_FALSE(answered); // on_frames went past a frame that answered
        } else {
          CHECK((answered || b.consumed == take)); // it stopped at a frame that did not
          CHECK(sent == b_sent);
          CHECK(a.state == b.last.state);
          CHECK(a.deadline == b.last.deadline);
        }
        to_client(sent);
      }
      same_machines();
      return b.consumed;
    });
  }
  return n;
}

template <class Crc>
void run_streams() {
  // clean transfers, then faults, junk and pauses; buffers smaller than a sub-block, exactly
  // one, and large enough for the biggest object (the store then gets the value in one part)
  const stream_options cases[] = {
      {.seed = 1, .buffer = 889},
      {.seed = 2, .buffer = 2 * 889, .server_crc = false},
      {.seed = 3, .buffer = 100, .fault_per_mille = 10, .junk_percent = 10},
      {.seed = 4, .buffer = 889, .fault_per_mille = 30, .junk_percent = 30, .pause_percent = 10},
      {.seed = 5, .buffer = 3200, .fault_per_mille = 5, .junk_percent = 5, .pause_percent = 20},
      {.seed = 6,
       .buffer = 7,
       .fault_per_mille = 10,
       .junk_percent = 10,
       .pause_percent = 5,
       .chunks = 1500},
      {.seed = 7,
       .buffer = 64,
       .server_crc = false,
       .fault_per_mille = 50,
       .junk_percent = 50,
       .pause_percent = 30},
      {.seed = 8, .buffer = 0, .junk_percent = 20},
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
    total.refused += n.refused;
    if (o.buffer != 0U) CHECK(n.completed > 5U); // the stream moved data, not only aborts
  }
  CHECK(total.long_takes > 1000U);
  CHECK(total.failed > 50U);
  CHECK(total.refused > 10U);
  MESSAGE("frames ", total.frames, ", calls ", total.calls, ", completed ", total.completed,
          ", failed ", total.failed);
}

} // namespace

TEST_CASE("sdo::server::on_frames: the same frames, states, errors and bytes as on_frame") {
  run_streams<fc::crc::ccitt16_no_table>();
}

TEST_CASE("sdo::server::on_frames with the CRC table: the same as on_frame") {
  run_streams<fc::crc::ccitt16_with_table>();
}

TEST_CASE("sdo::server::on_frames: the contract on hand-made frames") {
  side<fc::crc::ccitt16_no_table> s(889, {});
  auto &server = s.server;
  const co::can_frame other{0x181, false, 8, {1, 2, 3, 4, 5, 6, 7, 8}};
  const co::can_frame remote{request_id, true, 0, {}};
  const co::can_frame request{request_id, false, 8, sdo::initiate_upload({0x1000, 0})};

  // an empty span: nothing taken, the state as it is
  auto b = server.on_frames({}, 0);
  CHECK(b.consumed == 0U);
  CHECK(b.last.send.empty());
  CHECK(b.last.state == transfer_state::idle);
  CHECK_FALSE(b.last.deadline.has_value());

  // frames that are not for the server are taken and change nothing
  const std::array<co::can_frame, 2> ignored{other, remote};
  b = server.on_frames(ignored, 0);
  CHECK(b.consumed == 2U);
  CHECK(b.last.send.empty());
  CHECK(b.last.state == transfer_state::idle);
  CHECK_FALSE(server.error().has_value());

  // the first frame that answers ends the call: the rest waits for the next one
  const std::array<co::can_frame, 4> mixed{other, request, request, other};
  b = server.on_frames(mixed, 10);
  CHECK(b.consumed == 2U);
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].id == 0x585U);
  CHECK(
      b.last.send[0].data ==
      sdo::expedited_upload_response({0x1000, 0}, std::array<std::uint8_t, 4>{7, 0, 0, 0}).value());
  CHECK(b.last.state == transfer_state::done);
  b = server.on_frames(std::span(mixed).subspan(2), 10);
  CHECK(b.consumed == 1U); // the same answer again: the state stays done, but a frame is sent
  CHECK(b.last.send.size() == 1U);

  // a wrong DLC on the request ID is refused: no answer, but error() tells, so it ends the call
  co::can_frame short_frame = request;
  short_frame.dlc = 7;
  const std::array<co::can_frame, 2> refused{short_frame, other};
  b = server.on_frames(refused, 20);
  CHECK(b.consumed == 1U);
  CHECK(b.last.send.empty());
  REQUIRE(server.error().has_value());
  CHECK(server.error()->code == fc::errc::bad_length);

  // a block download in one call up to the acknowledgement, then the end in a second one
  std::array<std::uint8_t, 21> value{};
  for (std::size_t i = 0; i < value.size(); ++i) value[i] = static_cast<std::uint8_t>(i + 1U);
  const std::uint16_t crc = fc::crc::ccitt16(value);
  const co::can_frame initiate{request_id, false, 8,
                               sdo::block_download_initiate({0x2000, 0}, 21, true, true)};
  b = server.on_frames(std::span(&initiate, 1), 30);
  CHECK(b.consumed == 1U);
  CHECK(b.last.state == transfer_state::busy);
  REQUIRE(b.last.send.size() == 1U);
  std::vector<co::can_frame> rx;
  rx.push_back(other);
  for (std::uint8_t k = 0; k < 3U; ++k) {
    rx.push_back({request_id, false, 8,
                  sdo::encode_block_segment(
                      static_cast<std::uint8_t>(k + 1U),
                      std::span<const std::uint8_t>(value).subspan(7U * k, 7U), k == 2U)
                      .value()});
  }
  rx.push_back({request_id, false, 8, sdo::block_end(0, crc).value()});
  b = server.on_frames(rx, 40);
  CHECK(b.consumed == 4U); // the third segment, the last of the transfer, is acknowledged
  REQUIRE(b.last.send.size() == 1U);
  // the next sub-block: what fits the 889-byte buffer after 14 bytes, (889 − 14) / 7 segments
  CHECK(b.last.send[0].data == sdo::block_ack(3, 125).value());
  CHECK(b.last.deadline == 40U + timeout_ms);
  b = server.on_frames(std::span(rx).subspan(4), 41);
  CHECK(b.consumed == 1U);
  CHECK(b.last.state == transfer_state::done);
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].data == sdo::block_end_response());
  std::array<std::uint8_t, 32> stored{};
  std::size_t total = 0;
  CHECK(s.store.read({0x2000, 0}, 0, stored, total) == sdo::abort_code::none);
  CHECK(total == 21U);
  CHECK(std::equal(value.begin(), value.end(), stored.begin()));
}

namespace {

co::can_frame segment_frame(std::uint8_t first_byte, fc::test::xorshift &r) {
  co::can_frame f{request_id, false, 8, {}};
  f.data[0] = first_byte;
  for (std::size_t i = 1; i < 8U; ++i) f.data[i] = static_cast<std::uint8_t>(r.next());
  return f;
}

/// take_run in a constant expression (the byte loop there): three segments taken, the fourth
/// is the last of the transfer and left for on_segment; the CRC of the run is the CRC of the
/// bytes.
constexpr bool take_run_in_constant_evaluation() {
  sdo::block_receiver rx;
  rx.start(100, 28, true, 127);
  std::array<co::can_frame, 4> fs{};
  std::array<std::uint8_t, 28> value{};
  for (std::size_t k = 0; k < 4U; ++k) {
    fs[k] = {request_id, false, 8, {}};
    fs[k].data[0] = static_cast<std::uint8_t>((k + 1U) | (k == 3U ? 0x80U : 0U));
    for (std::size_t i = 0; i < 7U; ++i) {
      value[7U * k + i] = static_cast<std::uint8_t>(3U * k + i);
      fs[k].data[1U + i] = value[7U * k + i];
    }
  }
  std::array<std::uint8_t, 28> out{};
  if (rx.take_run(fs, request_id, out) != 3U || rx.count() != 21U) return false;
  for (std::size_t i = 0; i < 21U; ++i) {
    if (out[i] != value[i]) return false;
  }
  if (!rx.on_segment(fs[3].data).acknowledge || !rx.final_received()) return false;
  sdo::message end{};
  end.checksum = fc::crc::ccitt16(value);
  return rx.on_end(end).abort == sdo::abort_code::none && rx.count() == 28U;
}
static_assert(take_run_in_constant_evaluation());

} // namespace

TEST_CASE("block_receiver::take_run: where take_next, frame by frame, leaves the receiver") {
  fc::test::xorshift r(61);
  const auto below = [&r](std::uint64_t n) { return static_cast<std::size_t>(r.next() % n); };
  std::size_t taken = 0, completed = 0;
  for (int t = 0; t < 4000; ++t) {
    const std::size_t capacity = below(1200);
    const std::optional<std::uint32_t> announced =
        below(3) == 0 ? std::nullopt : std::optional<std::uint32_t>(below(1200));
    const bool crc = below(2) == 0;
    const auto block_size = static_cast<std::uint8_t>(1U + below(127));
    sdo::block_receiver one, run;    // take_next frame by frame, take_run
    std::vector<std::uint8_t> bytes; // what `one` took, for the right CRC
    one.start(capacity, announced, crc, block_size);
    run.start(capacity, announced, crc, block_size);
    // both somewhere in the sub-block first
    for (std::size_t k = below(4) == 0 ? below(block_size) : 0; k > 0U; --k) {
      const auto s = segment_frame(static_cast<std::uint8_t>(block_size - k), r);
      if (!one.take_next(s.data)) break;
      REQUIRE(run.take_next(s.data));
      bytes.insert(bytes.end(), s.data.begin() + 1, s.data.end());
    }
    // a run: mostly the next segments, sometimes another identifier, a remote frame, another
    // DLC, a sequence number out of line or the last flag
    std::vector<co::can_frame> fs;
    // (the next sequence number: the one take_next accepts, tried on a copy)
    std::uint8_t next = 1;
    for (std::uint8_t s = 1; s < 128U; ++s) {
      auto probe = one;
      if (probe.take_next(segment_frame(s, r).data)) {
        next = s;
        break;
      }
    }
    for (std::size_t k = 1U + below(140); k > 0U; --k) {
      co::can_frame f = segment_frame(next++, r);
      switch (below(40)) {
      case 0: f.id = static_cast<std::uint16_t>(request_id + 1U); break;
      case 1: f.rtr = true; break;
      case 2: f.dlc = 7; break;
      case 3: f.data[0] = static_cast<std::uint8_t>(r.next()); break;
      case 4: f.data[0] |= 0x80U; break;
      default: break;
      }
      fs.push_back(f);
    }
    std::vector<std::uint8_t> out_one(below(1000)), out_run(out_one.size());
    std::size_t j = 0;
    while (j < fs.size() && 7U * (j + 1U) <= out_one.size() && fs[j].id == request_id &&
           !fs[j].rtr && fs[j].dlc == 8U && one.take_next(fs[j].data)) {
      std::copy_n(fs[j].data.begin() + 1, 7, out_one.begin() + static_cast<std::ptrdiff_t>(7U * j));
      ++j;
    }
    const std::size_t k = run.take_run(fs, request_id, out_run);
    CHECK(k == j);
    CHECK(out_one == out_run);
    CHECK(one.count() == run.count());
    CHECK(one.final_received() == run.final_received());
    if (!fs.empty())
      CHECK(one.is_repeat(fs[j == 0U ? 0U : j - 1U].data) ==
            run.is_repeat(fs[j == 0U ? 0U : j - 1U].data));
    taken += k;
    // what follows: the next frame through on_segment, then an end with a random or the
    // right CRC: the same results (the CRC of the run is the CRC of its bytes)
    bytes.insert(bytes.end(), out_one.begin(),
                 out_one.begin() + static_cast<std::ptrdiff_t>(7U * j));
    sdo::message end{};
    end.unused = static_cast<std::uint8_t>(below(7));
    if (j < fs.size()) {
      const bool was_final = one.final_received();
      const auto a = one.on_segment(fs[j].data);
      const auto b = run.on_segment(fs[j].data);
      CHECK(a.abort == b.abort);
      CHECK(a.acknowledge == b.acknowledge);
      CHECK(std::equal(a.bytes.begin(), a.bytes.end(), b.bytes.begin(), b.bytes.end()));
      bytes.insert(bytes.end(), a.bytes.begin(), a.bytes.end());
      if (!was_final && one.final_received()) { // the last segment: its bytes come with the end
        bytes.insert(bytes.end(), fs[j].data.begin() + 1, fs[j].data.end() - end.unused);
      }
    }
    end.checksum = below(2) == 0 ? fc::crc::ccitt16(bytes) : static_cast<std::uint16_t>(r.next());
    const auto end_one = one.on_end(end);
    CHECK(end_one.abort == run.on_end(end).abort);
    CHECK(one.count() == run.count());
    if (end_one.abort == sdo::abort_code::none) ++completed;
  }
  CHECK(taken > 10000U);
  CHECK(completed > 100U); // ends with the right CRC were taken by both
}
