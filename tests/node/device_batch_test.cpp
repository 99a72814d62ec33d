// node::device::on_frames (round 6): several received frames at once, as a CAN driver drains
// its receive FIFO. Its promise is that nothing changes against on_frame: two devices over two
// stores get the same random streams — SDO transfers from a real client that follows the
// node's answers (block downloads with and without CRC, block uploads, expedited and segmented
// downloads, uploads; lost, repeated and corrupted frames), NMT commands (start, stop,
// pre-operational, reset communication, reset node; for the node, for all, for another node),
// SYNCs (of the right and a wrong length), RPDOs (of the right and wrong lengths), heartbeats of
// other nodes (one of them monitored), guarding requests, frames for other nodes, wrong DLCs,
// identifiers beyond 11 bits, time passing (timeouts, heartbeats) between the calls — one frame
// at a time through on_frame (the reference) and in random batches through on_frames. After
// every call of on_frames: the frames taken before the last one answered nothing (no frames, no
// events, the same NMT state), the last one's step and events are those on_frame gave, and both
// devices (state, SDO servers, deadline) and both stores (every byte, the staging area too)
// agree.
#include "node_test_util.hpp"

#include <fieldcodec/canopen/sdo_client.hpp>

#include "batch_stream.hpp"
#include "xorshift.hpp"

#include <deque>

using namespace test_node;
namespace fc = fieldcodec;

namespace {

constexpr std::uint8_t N = 5;
constexpr std::uint16_t request_id = 0x600U + N;
constexpr std::uint16_t response_id = 0x580U + N;
constexpr std::uint32_t timeout_ms = 100;

/// The knobs of one stream.
struct stream_options {
  std::uint64_t seed = 1;
  bool server_crc = true;
  unsigned fault_per_mille = 0; ///< each frame of the client: lost, repeated or corrupted
  unsigned other_percent = 0;   ///< each chunk: frames of the other services
  unsigned pause_percent = 0;   ///< each chunk: time passes before it
  unsigned reset_per_mille = 0; ///< each NMT command among them: a stop or a reset
  std::size_t chunks = 400;
};

/// What a stream exercised (so that a test cannot pass by exercising nothing).
struct stream_counts {
  std::size_t frames = 0, calls = 0, long_takes = 0, completed = 0, failed = 0, events = 0,
              resets = 0, stops = 0, syncs = 0, rpdos = 0, heartbeats = 0, emcys = 0, bursts = 0;
};

std::vector<node::event> events_of(const device_type &d) {
  return {d.events().begin(), d.events().end()};
}

stream_counts run_stream(const stream_options &o) {
  fc::test::xorshift r(o.seed);
  const auto below = [&r](std::uint64_t n) { return static_cast<std::size_t>(r.next() % n); };
  node::options no;
  no.sdo_timeout_ms = timeout_ms;
  no.sdo = {.block = true, .crc = o.server_crc};
  rig<N> one(no);   // on_frame, frame by frame
  rig<N> batch(no); // on_frames, in batches
  sdo::client client(N, timeout_ms);
  std::vector<std::uint8_t> data;   // the running download's bytes (the client borrows them)
  std::vector<std::uint8_t> upload; // the running upload's buffer
  std::deque<co::can_frame> to_node;
  std::vector<co::can_frame> chunk;
  stream_counts n;

  const auto same_devices = [&]() {
    CHECK(one.dev.state() == batch.dev.state());
    for (std::size_t i = 0; i < device_type::sdo_type::server_capacity(); ++i) {
      CHECK(one.dev.sdo().server(i).state() == batch.dev.sdo().server(i).state());
      CHECK(one.dev.sdo().server(i).error() == batch.dev.sdo().server(i).error());
    }
    CHECK(one.dev.sdo().deadline(one.now) == batch.dev.sdo().deadline(batch.now));
    CHECK(one.dev.emcy().error_register() == batch.dev.emcy().error_register());
    CHECK(one.storage == batch.storage);
    CHECK(one.staging == batch.staging);
    CHECK(one.dev.lost() == 0U);
    CHECK(batch.dev.lost() == 0U);
  };
  const auto from_client = [&](const co::frames &fs) {
    // a corrupted sequence number or command
    fc::test::send_over_faulty_link(fs, to_node, o.fault_per_mille, r, [&](co::can_frame &g) {
      g.data[0] = static_cast<std::uint8_t>(r.next());
    });
  };
  // what the node sent: the client takes its responses, the counts take the rest
  const auto sent_by_node = [&](const std::vector<co::can_frame> &fs, std::uint32_t now) {
    for (const co::can_frame &f : fs) {
      if (f.id == response_id) {
        const sdo::transfer_state before = client.state();
        from_client(client.on_frame(f, now).send);
        if (client.state() != before && client.state() == sdo::transfer_state::done) ++n.completed;
        if (client.state() != before && client.state() == sdo::transfer_state::failed) ++n.failed;
      } else if (f.id == 0x80U + N) {
        ++n.emcys;
      }
    }
  };
  const auto count_events = [&](const std::vector<node::event> &es) {
    n.events += es.size();
    for (const node::event &e : es) {
      using k = node::event::kind;
      if (e.what == k::reset_application || e.what == k::reset_communication) ++n.resets;
      if (e.what == k::nmt_state && e.state == co::nmt::state::stopped) ++n.stops;
      if (e.what == k::sync) ++n.syncs;
      if (e.what == k::pdo) ++n.rpdos;
      if (e.what == k::heartbeat) ++n.heartbeats;
    }
  };
  // a frame of the other services (or of nobody)
  const auto other = [&]() {
    co::can_frame f{0x123, false, 8, {}};
    for (auto &b : f.data) b = static_cast<std::uint8_t>(r.next());
    switch (below(16)) {
    case 0: // NMT: mostly start or pre-operational; stop and resets rarely
      f = F(0, {0x01, N});
      if (below(4) == 0) f.data[0] = 0x80;
      if (below(1000) < o.reset_per_mille) {
        const std::uint8_t cmd[] = {0x02, 0x02, 0x82, 0x81};
        f.data[0] = cmd[below(4)];
      }
      if (below(5) == 0) f.data[1] = 0;                                 // all nodes
      if (below(8) == 0) f.data[1] = static_cast<std::uint8_t>(N + 1U); // another node
      if (below(16) == 0) f.dlc = static_cast<std::uint8_t>(below(8));  // malformed
      break;
    case 1:
    case 2: f = below(5) == 0 ? F(0x80, {static_cast<std::uint8_t>(r.next())}) : F(0x80, {}); break;
    case 3:
    case 4: // RPDO 1 (6 bytes; sometimes too short or too long)
      f = F(0x200U + N, {});
      f.dlc = below(6) == 0 ? static_cast<std::uint8_t>(below(9)) : 6U;
      for (auto &b : f.data) b = static_cast<std::uint8_t>(r.next());
      break;
    case 5: // RPDO 2 (synchronous controlword)
      f = F(0x300U + N, {static_cast<std::uint8_t>(r.next()), 0});
      break;
    case 6:
    case 7: { // heartbeats: node 7 (monitored after the SDO write of 1016h), others
      // (drawn one after the other: the order of a call's arguments is unspecified)
      const auto from = static_cast<std::uint16_t>(0x700U + (below(3) == 0 ? 1U + below(127) : 7U));
      const std::uint8_t hb_state = below(10) == 0 ? std::uint8_t{0} : std::uint8_t{0x05};
      f = F(from, {hb_state});
      break;
    }
    case 8: f = R(static_cast<std::uint16_t>(0x700U + N), 0); break;   // guarding
    case 9: f.id = static_cast<std::uint16_t>(0x600U + N + 1U); break; // another node's SDO
    case 10:
      f.id = request_id;
      f.dlc = static_cast<std::uint8_t>(below(8));
      break;                                                                // wrong DLC
    case 11: f.id = static_cast<std::uint16_t>(request_id | 0x800U); break; // beyond 11 bits
    case 12:
      f.id = request_id;
      f.rtr = true;
      f.dlc = 0;
      break; // a remote frame on the SDO ID
    case 13:
      f.id = static_cast<std::uint16_t>(0x180U + N);
      f.rtr = true;
      f.dlc = 0;
      break;
    case 14:
      f.dlc = 9;
      f.id = request_id;
      break; // a DLC beyond 8
    default: f.id = static_cast<std::uint16_t>(below(0x800)); break;
    }
    return f;
  };
  const auto new_transfer = [&](std::uint32_t now) {
    const std::size_t what = below(10);
    fc::result<sdo::step> s = fc::errc::bad_state;
    if (what < 4) { // block download
      const std::size_t size = below(4) == 0 ? below(4200) : below(1000);
      data.resize(size);
      for (auto &b : data) b = static_cast<std::uint8_t>(r.next());
      sdo::block_options bo;
      bo.crc = below(3) != 0;
      const od::address a{below(6) == 0 ? std::uint16_t{0x2006} : std::uint16_t{0x2005}, 0};
      s = client.block_download(a, data, now, bo);
    } else if (what < 5) { // block upload (the node's burst)
      upload.resize(4000);
      sdo::block_options bo;
      bo.crc = below(2) != 0;
      bo.block_size = static_cast<std::uint8_t>(1U + below(127));
      s = client.block_upload({0x2005, 0}, upload, now, bo);
    } else if (what < 8) { // expedited: configuration and application values
      std::uint32_t v = static_cast<std::uint32_t>(r.next());
      od::address a{0x2000, 0};
      switch (below(6)) {
      case 0: a = {0x1017, 0}, v = below(2) == 0 ? 0U : 30U; break;          // heartbeat
      case 1: a = {0x1016, 1}, v = below(4) == 0 ? 0U : 0x0007'0064U; break; // consumer
      case 2: a = {0x2008, 0}; break;
      case 3: a = {0x6040, 0}, v &= 0xFFFFU; break;
      case 4: a = {0x1005, 0}, v = 0x80U; break;
      default: break;
      }
      data.resize(a.index == 0x1017 || a.index == 0x6040 ? 2U : 4U);
      for (std::size_t i = 0; i < data.size(); ++i)
        data[i] = static_cast<std::uint8_t>(v >> (8U * i));
      s = client.download(a, data, now);
    } else if (what < 9) { // segmented download
      data.resize(below(40));
      for (auto &b : data) b = static_cast<std::uint8_t>(r.next());
      s = client.download({0x2006, 0}, data, now);
    } else { // upload
      upload.resize(64);
      s = client.upload(below(2) == 0 ? od::address{0x1008, 0} : od::address{0x2000, 0}, upload,
                        now);
    }
    REQUIRE(s.has_value());
    from_client(s.value().send);
  };

  const auto s0 = one.start();
  REQUIRE(s0 == batch.start());
  for (std::size_t c = 0; c < o.chunks; ++c) {
    // time passes (the client waits for an answer that was lost: past its timeout)
    const bool waiting = client.busy() && to_node.empty();
    if (waiting || below(100) < o.pause_percent) {
      const auto dt = static_cast<std::uint32_t>(waiting ? timeout_ms + 1U : below(2 * timeout_ms));
      const auto a = one.tick(dt);
      const auto b = batch.tick(dt);
      CHECK(a == b);
      CHECK(one.deadline == batch.deadline);
      CHECK(events_of(one.dev) == events_of(batch.dev));
      count_events(events_of(one.dev));
      same_devices();
      sent_by_node(a, one.now);
      from_client(client.poll(one.now).send);
    }
    if (!client.busy() && to_node.empty()) new_transfer(one.now);
    fc::test::take_chunk(to_node, chunk, r, 150, o.other_percent, 4, other, false);
    // the chunk in random batches (sometimes empty ones), at the same `now`
    fc::test::in_random_batches(chunk, r, [&](std::span<const co::can_frame> span) {
      const std::size_t take = span.size();
      const auto events_before = events_of(batch.dev);
      const auto b = batch.dev.on_frames(span, batch.now);
      ++n.calls;
      const auto b_sent = list(b.last.send);
      const auto b_events = events_of(batch.dev);
      if (take == 0U) {
        CHECK(b.consumed == 0U);
        CHECK(b_sent.empty());
        CHECK(b.last.state == one.dev.state());
        CHECK(b_events == events_before); // nothing changed
        same_devices();
        return std::size_t{0};
      }
      REQUIRE(b.consumed >= 1U);
      REQUIRE(b.consumed <= take);
      if (b.consumed > 1U) ++n.long_takes;
      if (b.last.send.is_burst()) ++n.bursts;
      for (std::size_t j = 0; j < b.consumed; ++j) {
        const co::nmt::state before = one.dev.state();
        const auto a = one.dev.on_frame(span[j], one.now);
        const auto sent = list(a.send);
        const auto es = events_of(one.dev);
        ++n.frames;
        const bool answered = !sent.empty() || !es.empty() || a.state != before;
        if (j + 1U < b.consumed) {
          CHECK_FALSE(answered); // on_frames went past a frame that answered
        } else {
          CHECK((answered || b.consumed == take)); // it stopped at a frame that did not
          CHECK(sent == b_sent);
          CHECK(es == b_events);
          CHECK(a.state == b.last.state);
          CHECK(a.deadline == b.last.deadline);
        }
        count_events(es);
        sent_by_node(sent, one.now);
      }
      same_devices();
      return b.consumed;
    });
  }
  return n;
}

} // namespace

TEST_CASE("node::device::on_frames: the same frames, events, states and bytes as on_frame") {
  const stream_options cases[] = {
      {.seed = 11},
      {.seed = 12, .server_crc = false, .other_percent = 20},
      {.seed = 13, .fault_per_mille = 10, .other_percent = 40, .pause_percent = 10},
      {.seed = 14,
       .fault_per_mille = 30,
       .other_percent = 60,
       .pause_percent = 20,
       .reset_per_mille = 300},
      {.seed = 15,
       .server_crc = false,
       .fault_per_mille = 5,
       .other_percent = 80,
       .pause_percent = 30,
       .reset_per_mille = 100,
       .chunks = 1000},
      {.seed = 16, .other_percent = 100, .pause_percent = 50, .reset_per_mille = 400},
  };
  stream_counts total;
  for (const auto &o : cases) {
    CAPTURE(o.seed);
    const stream_counts n = run_stream(o);
    total.frames += n.frames;
    total.calls += n.calls;
    total.long_takes += n.long_takes;
    total.completed += n.completed;
    total.failed += n.failed;
    total.events += n.events;
    total.resets += n.resets;
    total.stops += n.stops;
    total.syncs += n.syncs;
    total.rpdos += n.rpdos;
    total.heartbeats += n.heartbeats;
    total.emcys += n.emcys;
    total.bursts += n.bursts;
    CHECK(n.completed > 5U); // the stream moved data, not only aborts
  }
  // the streams are not vacuous: every kind of traffic happened, and batches were long
  CHECK(total.long_takes > 1000U);
  CHECK(total.failed > 20U);
  CHECK(total.resets > 5U);
  CHECK(total.stops > 5U);
  CHECK(total.syncs > 50U);
  CHECK(total.rpdos > 50U);
  CHECK(total.heartbeats > 5U);
  CHECK(total.emcys > 5U);
  CHECK(total.bursts > 5U);
  MESSAGE("frames ", total.frames, ", calls ", total.calls, ", long ", total.long_takes,
          ", completed ", total.completed, ", failed ", total.failed, ", events ", total.events,
          ", resets ", total.resets, ", stops ", total.stops, ", syncs ", total.syncs, ", rpdos ",
          total.rpdos, ", heartbeats ", total.heartbeats, ", emcys ", total.emcys, ", bursts ",
          total.bursts);
}

TEST_CASE("node::device::on_frames: the contract on hand-made frames") {
  rig<N> t;
  // before start(): every frame is taken and ignored
  const co::can_frame nmt_start = F(0, {0x01, N});
  const co::can_frame upload_1000 = F(request_id, {0x40, 0x00, 0x10, 0, 0, 0, 0, 0});
  const co::can_frame other = F(0x181, {1, 2, 3});
  auto b = t.dev.on_frames({}, 0);
  CHECK(b.consumed == 0U);
  CHECK(b.last.send.empty());
  CHECK(b.last.state == co::nmt::state::boot_up);
  CHECK_FALSE(b.last.deadline.has_value());
  const std::array<co::can_frame, 2> early{nmt_start, upload_1000};
  b = t.dev.on_frames(early, 0);
  CHECK(b.consumed == 2U);
  CHECK(b.last.send.empty());
  CHECK(t.dev.events().empty());

  (void)t.start();
  REQUIRE(t.dev.state() == co::nmt::state::pre_operational);
  // an empty span changes nothing, not even the events of the last call
  REQUIRE_FALSE(t.dev.events().empty());
  b = t.dev.on_frames({}, 0);
  CHECK(b.consumed == 0U);
  CHECK_FALSE(t.dev.events().empty());

  // frames that answer nothing are taken; an NMT start answers with an event and ends the call
  const std::array<co::can_frame, 4> mixed{other, nmt_start, upload_1000, other};
  b = t.dev.on_frames(mixed, 10);
  CHECK(b.consumed == 2U);
  CHECK(b.last.send.empty());
  CHECK(b.last.state == co::nmt::state::operational);
  REQUIRE(t.dev.events().size() == 1U);
  CHECK(t.dev.events()[0].what == node::event::kind::nmt_state);
  // the SDO request answers with its response
  b = t.dev.on_frames(std::span(mixed).subspan(2), 10);
  CHECK(b.consumed == 1U);
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].id == response_id);
  CHECK(t.dev.events().empty());
  b = t.dev.on_frames(std::span(mixed).subspan(3), 10);
  CHECK(b.consumed == 1U);
  CHECK(b.last.send.empty());

  // a block download: the sub-block in one call up to the acknowledgement, then the end
  std::array<std::uint8_t, 21> value{};
  for (std::size_t i = 0; i < value.size(); ++i) value[i] = static_cast<std::uint8_t>(i + 1U);
  const co::can_frame initiate{request_id, false, 8,
                               sdo::block_download_initiate({0x2005, 0}, 21, true, false)};
  b = t.dev.on_frames(std::span(&initiate, 1), 20);
  CHECK(b.consumed == 1U);
  REQUIRE(b.last.send.size() == 1U);
  std::vector<co::can_frame> rx{other};
  for (std::uint8_t k = 0; k < 3U; ++k) {
    rx.push_back({request_id, false, 8,
                  sdo::encode_block_segment(
                      static_cast<std::uint8_t>(k + 1U),
                      std::span<const std::uint8_t>(value).subspan(7U * k, 7U), k == 2U)
                      .value()});
  }
  rx.push_back(F(0x80, {})); // a SYNC after the sub-block
  rx.push_back({request_id, false, 8, sdo::block_end(0, 0).value()});
  b = t.dev.on_frames(rx, 30);
  CHECK(b.consumed == 4U); // the last segment of the transfer is acknowledged
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].id == response_id);
  CHECK(b.last.send[0].data[0] == 0xA2U);
  CHECK(b.last.deadline.has_value());
  b = t.dev.on_frames(std::span(rx).subspan(4), 31);
  CHECK(b.consumed == 1U); // the SYNC: an event and the synchronous TPDO
  REQUIRE(t.dev.events().size() == 1U);
  CHECK(t.dev.events()[0].what == node::event::kind::sync);
  b = t.dev.on_frames(std::span(rx).subspan(5), 32);
  CHECK(b.consumed == 1U);
  REQUIRE(b.last.send.size() == 1U);
  CHECK(b.last.send[0].data == sdo::block_end_response());
  CHECK(t.dev.sdo().server(0).state() == sdo::transfer_state::done);
  const auto stored = t.store.value({0x2005, 0}).value();
  CHECK(std::equal(value.begin(), value.end(), stored.begin(), stored.end()));
}
