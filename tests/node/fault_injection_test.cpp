// Fault injection (issue 15): two fieldcodec nodes on an in-memory bus that drops, duplicates
// and reorders frames and delays SDO responses past the timeouts. Node 2's SDO client runs
// thousands of transfers of every kind (expedited, segmented, block; download and upload)
// against node 3's server while PDOs (event-driven and synchronous), SYNC and heartbeats flow.
// SDO timeouts are 100 ms here (simulated time), so that the thousands of aborts pass quickly.
//
// Checked after every transfer, once the bus is quiet:
// * completed: exactly the bytes sent (download: the server's object; upload: the client's
//   buffer holds the object);
// * not completed: the client ended with an abort (its own, e.g. timeout, or the server's);
//   the server aborted too, or never saw a request of the transfer, or had finished its part
//   when its last answer was lost (SDO has no confirmation of the confirmation: a download is
//   then stored although the client failed); each case is counted apart;
// * the object holds its old value or exactly the new one, never a part; the server's final
//   state agrees with it;
// * no machine is left busy.
// Checked after every frame node 3 takes: its RPDO-written pair (2000h, 2001h) is consistent
// (2001h == low 16 bits of ~2000h: never half of one PDO and half of another), and its
// synchronous controlword (6040h) is a value node 2 really sent.
//
// Frames on the bus keep their order except for the injected swaps (neighbouring frames of one
// sender); delays past the timeouts hit only SDO responses (a late request or block segment
// reaching an idle server would be taken as a new request: SDO carries no transfer number, so a
// master must wait until the bus is quiet before it starts again after an abort).
#include "node_test_util.hpp"

#include <fieldcodec/canopen/sdo_client.hpp>

#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <vector>

using namespace test_node;
using sdo::transfer_state;

namespace {

struct counts {
  std::size_t transfers = 0, expedited = 0, segmented = 0, block = 0;
  std::size_t completed = 0, completed_server_timed_out = 0, aborted_both = 0, client_only = 0,
              answer_lost = 0;
  std::size_t frames = 0, dropped = 0, duplicated = 0, swapped = 0, delayed = 0;
  std::size_t tpdo_frames = 0, rpdo_checked = 0, sync_frames = 0, heartbeat_losses = 0;
};

enum class kind {
  expedited_down,
  expedited_up,
  segmented_down,
  segmented_up,
  block_down,
  block_up
};

class bus_sim {
public:
  explicit bus_sim(std::uint32_t seed) : rng_(seed) {}

  static node::options fast() {
    node::options o;
    o.sdo_timeout_ms = 100;
    return o;
  }
  rig<2> a{fast()};
  rig<3> b{fast()};
  counts n;
  std::uint32_t now = 0;
  std::set<std::uint16_t> sent_controlwords{0};

  void setup() {
    a.now = b.now = 0;
    push(0, a.start());
    push(1, b.start());
    a_next_ = a.deadline;
    b_next_ = b.deadline;
    // node 2's client talks to node 3
    REQUIRE(a.set_u(0x1280, 1, 0x603, 4) == abort_code::none);
    REQUIRE(a.set_u(0x1280, 2, 0x583, 4) == abort_code::none);
    // node 2: heartbeat every 50 ms, TPDO 1 with an inhibit time of 2 ms
    REQUIRE(a.set_u(0x1017, 0, 50, 2) == abort_code::none);
    REQUIRE(a.set_u(0x1800, 1, 0x8000'0182U, 4) == abort_code::none);
    REQUIRE(a.set_u(0x1800, 3, 20, 2) == abort_code::none);
    REQUIRE(a.set_u(0x1800, 1, 0x182, 4) == abort_code::none);
    // node 3 receives node 2's TPDOs (the CiA 301 sequence: invalid, new COB-ID) and watches
    // its heartbeat (200 ms)
    REQUIRE(b.set_u(0x1400, 1, 0x8000'0203U, 4) == abort_code::none);
    REQUIRE(b.set_u(0x1400, 1, 0x182, 4) == abort_code::none);
    REQUIRE(b.set_u(0x1401, 1, 0x8000'0303U, 4) == abort_code::none);
    REQUIRE(b.set_u(0x1401, 1, 0x282, 4) == abort_code::none);
    REQUIRE(b.set_u(0x1016, 1, 0x0002'00C8, 4) == abort_code::none);
    // the NMT master starts everybody (no faults on this one)
    deliver_both(F(0, {0x01, 0}));
  }

  /// Run one transfer to its end and until the bus is quiet; check the outcome.
  void transfer(kind k) {
    ++n.transfers;
    auto &c = a.dev.client(0);
    const od::address obj = object_for(k);
    const auto before = value_of(obj);
    std::vector<std::uint8_t> data;
    std::vector<std::uint8_t> buffer(4096);
    fieldcodec::result<sdo::step> s = fieldcodec::errc::bad_state;
    sdo::block_options o;
    o.block_size = static_cast<std::uint8_t>(1U + next() % 127U);
    o.switch_threshold = static_cast<std::uint8_t>(next() % 3U == 0U ? 8U : 0U);
    switch (k) {
    case kind::expedited_down:
      ++n.expedited;
      data = random_bytes(obj.index == 0x2103 ? 1U : 4U);
      if (obj.index == 0x2103) data[0] = static_cast<std::uint8_t>(data[0] % 101U); // 0..100
      s = c.download(obj, data, now);
      break;
    case kind::expedited_up:
      ++n.expedited;
      s = c.upload(obj, buffer, now);
      break;
    case kind::segmented_down:
      ++n.segmented;
      data = random_bytes(next() % 300U);
      s = c.download(obj, data, now);
      break;
    case kind::segmented_up:
      ++n.segmented;
      s = c.upload(obj, buffer, now);
      break;
    case kind::block_down:
      ++n.block;
      data = random_bytes(next() % 2000U);
      s = c.block_download(obj, data, now, o);
      break;
    case kind::block_up:
      ++n.block;
      s = c.block_upload(obj, buffer, now, o);
      break;
    }
    REQUIRE(s);
    push(0, list(s.value().send));
    if (s.value().deadline) a_next_ = earliest(a_next_, *s.value().deadline);
    run_until_quiet();
    check(k, obj, before, data);
  }

  /// Let time pass with PDOs, SYNC and heartbeats only (no transfer).
  void idle(std::uint32_t ms) {
    const std::uint32_t end = now + ms;
    while (static_cast<std::int32_t>(end - now) > 0) advance(end);
  }

private:
  struct msg {
    int from; ///< 0 = node 2, 1 = node 3, 2 = the master (to both)
    co::can_frame f;
  };

  std::uint32_t next() { return static_cast<std::uint32_t>(rng_()); }
  std::vector<std::uint8_t> random_bytes(std::size_t len) {
    std::vector<std::uint8_t> v(len);
    for (auto &x : v) x = static_cast<std::uint8_t>(next());
    return v;
  }
  static std::optional<std::uint32_t> earliest(std::optional<std::uint32_t> x, std::uint32_t y) {
    if (!x || static_cast<std::int32_t>(y - *x) < 0) return y;
    return x;
  }

  od::address object_for(kind k) {
    switch (k) {
    case kind::expedited_down:
    case kind::expedited_up:
      return next() % 2U == 0U ? od::address{0x2008, 0} : od::address{0x2103, 0};
    default: return {0x2005, 0};
    }
  }
  std::vector<std::uint8_t> value_of(od::address obj) {
    auto v = b.store.value(obj).value();
    return {v.begin(), v.end()};
  }

  /// Frames a node produced go onto the bus, with faults.
  void push(int from, std::vector<co::can_frame> out) {
    if (out.empty()) return;
    std::vector<co::can_frame> sent;
    for (const auto &f : out) {
      ++n.frames;
      const std::uint32_t r = next() % 1000U;
      if (r < 25U) { // 2.5 %: lost
        ++n.dropped;
        continue;
      }
      sent.push_back(f);
      if (r < 45U) { // 2 %: repeated
        ++n.duplicated;
        sent.push_back(f);
      }
    }
    // 3 %: neighbouring frames of this burst swap places
    for (std::size_t i = 1; i < sent.size(); ++i) {
      if (next() % 100U < 3U) {
        std::swap(sent[i - 1], sent[i]);
        ++n.swapped;
      }
    }
    for (const auto &f : sent) {
      std::uint32_t at = now + 1;
      // 1 % of the SDO responses arrive after the client's timeout (100 ms)
      if (f.id == 0x583 && next() % 100U == 0U) {
        at = now + 100 + next() % 100U;
        ++n.delayed;
      }
      q_.emplace(at, msg{from, f});
    }
  }
  void deliver_both(const co::can_frame &f) {
    deliver(0, f);
    deliver(1, f);
  }
  /// A frame reaches node 2 (to = 0) or node 3 (to = 1).
  void deliver(int to, const co::can_frame &f) {
    a.now = b.now = now;
    if (to == 0) {
      push(0, a.feed(f));
      a_next_ = a.deadline;
      return;
    }
    if (f.id == 0x603 && f.data[0] != 0x80) ++requests_; // not the abort
    auto out = b.feed(f);
    b_next_ = b.deadline;
    count_losses();
    check_pdo_pair();
    push(1, out);
  }
  void count_losses() {
    for (const auto &e : b.dev.events()) {
      if (e.what == node::event::kind::heartbeat &&
          e.heartbeat.what == node::heartbeat_event::kind::lost) {
        ++n.heartbeat_losses;
      }
    }
  }

  /// One event: deliver what is due, poll who is due, or let time pass to the next event.
  void advance(std::uint32_t limit) {
    // deliver every frame due now
    while (!q_.empty() && reached_(q_.begin()->first)) {
      const msg m = q_.begin()->second;
      q_.erase(q_.begin());
      if (m.from != 0) deliver(0, m.f);
      if (m.from != 1) deliver(1, m.f);
    }
    // application and master activity
    if (reached_(next_pdo_)) {
      ++counter_;
      a.now = now;
      REQUIRE(a.set_u(0x2100, 0, counter_, 4) == abort_code::none);
      REQUIRE(a.set_u(0x2101, 0, ~counter_ & 0xFFFFU, 2) == abort_code::none);
      const auto cw = static_cast<std::uint16_t>(counter_ & 0xFFFFU);
      sent_controlwords.insert(cw);
      REQUIRE(a.set_u(0x6041, 0, cw, 2) == abort_code::none);
      next_pdo_ = now + 3;
      a_next_ = now; // the TPDO is due
    }
    if (reached_(next_sync_)) {
      ++n.sync_frames;
      std::vector<co::can_frame> one{F(0x80, {})};
      push(2, one); // to both, with faults
      next_sync_ = now + 10;
    }
    if (a_next_ && reached_(*a_next_)) {
      a.now = now;
      auto out = a.tick();
      for (const auto &f : out) {
        if (f.id == 0x182 || f.id == 0x282) ++n.tpdo_frames;
      }
      a_next_ = a.deadline;
      if (a_next_ && reached_(*a_next_)) ++stalls_; // a poll must make progress
      push(0, out);
    }
    if (b_next_ && reached_(*b_next_)) {
      b.now = now;
      auto out = b.tick();
      count_losses();
      b_next_ = b.deadline;
      if (b_next_ && reached_(*b_next_)) ++stalls_;
      push(1, out);
    }
    // the next event
    std::uint32_t t = limit;
    auto consider = [&](std::optional<std::uint32_t> x) {
      if (x && static_cast<std::int32_t>(*x - t) < 0) t = *x;
    };
    if (!q_.empty()) consider(q_.begin()->first);
    consider(a_next_);
    consider(b_next_);
    consider(next_pdo_);
    consider(next_sync_);
    if (static_cast<std::int32_t>(t - now) <= 0) t = now + 1;
    now = t;
  }
  bool reached_(std::uint32_t t) const { return co::reached(t, now); }

  bool sdo_in_flight() const {
    for (const auto &[at, m] : q_) {
      if (m.f.id == 0x603 || m.f.id == 0x583) return true;
    }
    return false;
  }
  void run_until_quiet() {
    for (int guard = 0; guard < 200000; ++guard) {
      const bool busy = a.dev.client(0).busy() || b.dev.sdo().server(0).busy() || sdo_in_flight();
      if (!busy) return;
      advance(now + 5000);
    }
    FAIL("a machine is stuck");
  }

  void check_pdo_pair() {
    const auto x = b.read_u(0x2000, 0);
    const auto y = b.read_u(0x2001, 0);
    ++n.rpdo_checked;
    if (x != 0 || y != 0) CHECK(y == (~x & 0xFFFFU));
    CHECK(sent_controlwords.count(static_cast<std::uint16_t>(b.read_u(0x6040, 0))) == 1);
  }

  void check(kind k, od::address obj, const std::vector<std::uint8_t> &before,
             const std::vector<std::uint8_t> &sent) {
    CAPTURE(static_cast<int>(k));
    CAPTURE(n.transfers);
    const auto &c = a.dev.client(0);
    const auto &srv = b.dev.sdo().server(0);
    CHECK_FALSE(c.busy());
    CHECK_FALSE(srv.busy());
    const auto after = value_of(obj);
    const bool download =
        k == kind::expedited_down || k == kind::segmented_down || k == kind::block_down;
    CHECK((after == before || (download && after == sent))); // never a part
    const bool reached_server = requests_ > 0;
    requests_ = 0;
    if (c.state() == transfer_state::done) {
      if (download) {
        CHECK(after == sent);
      } else {
        const auto got = c.received();
        CHECK(std::vector<std::uint8_t>(got.begin(), got.end()) == before);
      }
      // a block upload's end response lost, or a repeated request that restarted the server
      // after it had finished: the server then timed out on its own
      ++(srv.state() == transfer_state::failed ? n.completed_server_timed_out : n.completed);
      return;
    }
    REQUIRE(c.state() == transfer_state::failed);
    if (!reached_server) {
      ++n.client_only; // no request reached the server: nothing to abort there
    } else if (srv.state() == transfer_state::failed) {
      ++n.aborted_both;
    } else {
      // the server finished its part and its last answer was lost: the client timed out
      CHECK(srv.state() == transfer_state::done);
      if (download) CHECK(after == sent);
      ++n.answer_lost;
    }
  }

  std::mt19937 rng_;
  std::multimap<std::uint32_t, msg> q_;
  std::optional<std::uint32_t> a_next_{}, b_next_{};
  std::uint32_t next_pdo_ = 5, next_sync_ = 7;
  std::uint32_t counter_ = 0;
  std::size_t requests_ = 0; ///< client frames but aborts that reached the server this transfer

public:
  std::size_t stalls_ = 0; ///< polls that left a deadline in the past (never expected)
};

} // namespace

TEST_CASE("fault injection: thousands of SDO transfers and PDO traffic between two nodes") {
  bus_sim sim(20260115U);
  sim.setup();
  sim.idle(100);
  REQUIRE(sim.a.dev.state() == co::nmt::state::operational);
  REQUIRE(sim.b.dev.state() == co::nmt::state::operational);
  const kind kinds[] = {kind::expedited_down, kind::expedited_up, kind::segmented_down,
                        kind::segmented_up,   kind::block_down,   kind::block_up};
  for (int i = 0; i < 3000; ++i) sim.transfer(kinds[static_cast<std::size_t>(i) % 6U]);
  sim.idle(500);
  const counts &n = sim.n;
  MESSAGE("fault injection: " << n.transfers << " transfers (" << n.expedited << " expedited, "
                              << n.segmented << " segmented, " << n.block << " block): "
                              << n.completed << " completed, " << n.completed_server_timed_out
                              << " completed with the server timing out afterwards, "
                              << n.aborted_both << " aborted on both sides, " << n.answer_lost
                              << " finished by the server with its last answer lost, "
                              << n.client_only << " aborted by the client alone (no request "
                              << "reached the server); " << n.frames
                              << " frames, faults: " << n.dropped << " dropped, " << n.duplicated
                              << " duplicated, " << n.swapped << " swapped, " << n.delayed
                              << " delayed past the timeout; " << n.tpdo_frames << " TPDOs, "
                              << n.sync_frames << " SYNC, " << n.rpdo_checked << " RPDO checks, "
                              << n.heartbeat_losses << " heartbeat losses; " << sim.now
                              << " ms simulated");
  CHECK(n.transfers == 3000);
  CHECK(n.completed + n.completed_server_timed_out + n.aborted_both + n.answer_lost +
            n.client_only ==
        n.transfers);
  CHECK(n.completed > n.transfers / 3);
  CHECK(n.aborted_both > 0);
  CHECK(n.dropped > 100);
  CHECK(n.duplicated > 100);
  CHECK(n.swapped > 100);
  CHECK(n.delayed > 10);
  CHECK(n.tpdo_frames > 1000);
  CHECK(sim.stalls_ == 0);
  CHECK(sim.a.dev.lost() == 0);
  CHECK(sim.b.dev.lost() == 0);
}
