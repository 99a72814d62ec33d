// The fieldcodec side of the interoperability test (tests/interop/, docs/canopen.md
// "Interoperability"): the library's CANopen node (canopen/node/device.hpp) and SDO client,
// speaking candump-style frames on standard input and output so that a python-can virtual bus
// (python canopen, tests/interop/interop_peer.py) can carry them.
//
// usage: interop_node DICTIONARY NODE      DICTIONARY: xenax | corpus
//                                         NODE: 1..127, or 255 (no node-ID: waits for LSS)
// (interop_node_crc_table: the same program, its SDO servers computing the block transfer CRC by
// table, node::capacity::sdo_crc_table)
//
// Standard input, one line each:
//   ID#DATA, ID#R, ID#R<dlc>                      a frame from the bus
//   !upload NODE INDEX SUB MODE                   the SDO client reads an object of NODE
//   !download NODE INDEX SUB HEX MODE             … and writes one (HEX may be "-": 0 bytes)
//        MODE: normal | block | block-nocrc | block-switch (protocol switch threshold 255)
//   !value INDEX SUB                              this node's store: the value of an object
//   !set INDEX SUB HEX                            … the application writes a value
//   !start                                        power-on: boot-up, pre-operational
//   !state                                        the NMT state
//   !last sync|time|emcy                          what the bridge decoded last from others
//   !last node-time                               the node's TIME consumer (1012h bit 31): its
//                                                 `time` events so far and the last time
//   !time MS DAYS                                 the node produces TIME (1012h bit 30)
//   !storage ok|fail                              the bridge's 1010h/1011h storage hook works
//                                                 or fails (it keeps nothing: it notes calls)
//   !last storage                                 the hook's calls so far: s<group> / r<group>
//   !emcy CODE REGISTER-BITS [MANUFACTURER-HEX]   an application error (EMCY, 1001h)
//   !emcy-clear CODE                              the error is gone
//   !tpdo N                                       the application's event for TPDO N
//   !pack MAPPINGS VALUES                         pdo::pack_all (mappings hex, values decimal)
//   !lss                                          the LSS slave: MODE ACTIVE PENDING (node-IDs
//                                                 decimal), then STORED (what the store hook
//                                                 got: NODE/TABLE.INDEX, or -) and ACTIVATED
//                                                 (the last activate bit timing: INDEX/DELAY,
//                                                 or -)
//   !lss-store ok|fail                            the store hook answers 0, or 2 (media error)
//   !hooks                                        before !start (corpus): the application's
//                                                 hooks (node::object_hook): 2106h computed at
//                                                 each read (1000h, 1001h, …), 2120h:06 refuses
//                                                 odd values (0800 0022h), 2122h streamed to
//                                                 and from the bridge's own bytes
//   !hooks-stop OFFSET                            the stream refuses a part at or past OFFSET
//                                                 (0800 0020h; "-": never)
//   !last hooks                                   READS WRITTEN(a,b,…|-) RECEIVED(bytes of the
//                                                 last complete download) COMPLETED ENDED
//                                                 (the `ended` codes, hex, or -)
//   !quit
// Standard output: frames to the bus (ID#DATA) and one answer per command line:
//   = ok HEX            = error ERRC ABORT(8 hex digits)
//
// `node_glue` puts the commands on the node (node::device) and notes what the node does not
// consume (TIME, other nodes' EMCY) for `!last`.
//
// With the environment variable FIELDCODEC_INTEROP_BATCH set, the frames that arrive on
// standard input until it is quiet for 1 ms (or up to the next command line) go to the node
// together, through node::device::on_frames, as a CAN driver hands over what it drained from
// its receive FIFO (the tests interop_*_batch); without it, frame by frame through on_frame.
#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/canopen/sync.hpp>
#include <fieldcodec/canopen/time_stamp.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/clock.hpp>
#include <fieldcodec/host/frame_record.hpp>
#ifdef FIELDCODEC_INTEROP_CORPUS
#include <fieldcodec/dictionaries/interop_corpus.hpp>
#endif

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace {

namespace co = fieldcodec::canopen;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;

std::uint32_t now_ms() {
  static const fieldcodec::host::steady_ms clock;
  return clock.now();
}

void put_line(const std::string &s) {
  std::fputs(s.c_str(), stdout);
  std::fputc('\n', stdout);
  std::fflush(stdout);
}

void transmit(const co::can_frame &f) {
  put_line(fieldcodec::host::candump::format_frame(fieldcodec::host::to_record(f)));
}

template <class Frames>
void transmit_all(const Frames &fs) {
  for (const co::can_frame f : fs) transmit(f);
}

std::string hex(std::span<const std::uint8_t> bytes) {
  static constexpr char digits[] = "0123456789ABCDEF";
  std::string out;
  for (const std::uint8_t b : bytes) {
    out += digits[b >> 4U];
    out += digits[b & 0xFU];
  }
  return out;
}

std::optional<std::vector<std::uint8_t>> unhex(std::string_view s) {
  if (s == "-") return std::vector<std::uint8_t>{};
  if (s.size() % 2U != 0U) return std::nullopt;
  std::vector<std::uint8_t> out;
  for (std::size_t i = 0; i < s.size(); i += 2U) {
    unsigned v = 0;
    for (std::size_t k = 0; k < 2U; ++k) {
      const char c = s[i + k];
      v <<= 4U;
      if (c >= '0' && c <= '9') {
        v |= static_cast<unsigned>(c - '0');
      } else if (c >= 'A' && c <= 'F') {
        v |= static_cast<unsigned>(c - 'A' + 10);
      } else if (c >= 'a' && c <= 'f') {
        v |= static_cast<unsigned>(c - 'a' + 10);
      } else {
        return std::nullopt;
      }
    }
    out.push_back(static_cast<std::uint8_t>(v));
  }
  return out;
}

std::string abort_hex(sdo::abort_code c) {
  char buf[9];
  std::snprintf(buf, sizeof buf, "%08X", static_cast<unsigned>(c));
  return buf;
}

void answer_error(fieldcodec::errc e, sdo::abort_code c) {
  put_line("= error " + std::string(fieldcodec::to_string(e)) + " " + abort_hex(c));
}

/// The SDO client of the bridge: one transfer at a time, started by a command line, answered
/// when it ends.
class client_side {
public:
  void start(const std::vector<std::string> &w, std::uint32_t now) {
    // !upload NODE INDEX SUB MODE  /  !download NODE INDEX SUB HEX MODE
    const bool upload = w[0] == "!upload";
    if (w.size() != (upload ? 5U : 6U)) return answer_error(fieldcodec::errc::bad_syntax, {});
    const auto node = static_cast<std::uint8_t>(std::stoul(w[1], nullptr, 10));
    const od::address a{static_cast<std::uint16_t>(std::stoul(w[2], nullptr, 16)),
                        static_cast<std::uint8_t>(std::stoul(w[3], nullptr, 16))};
    const std::string &mode = w.back();
    sdo::block_options opt;
    opt.crc = mode != "block-nocrc";
    if (mode == "block-switch") opt.switch_threshold = 255; // the server may answer normally
    const bool block = mode != "normal";
    client_.emplace(node, 2000);
    upload_ = upload;
    fieldcodec::result<sdo::step> s = fieldcodec::errc::bad_state;
    if (upload) {
      buffer_.assign(4096, 0);
      s = block ? client_->block_upload(a, buffer_, now, opt) : client_->upload(a, buffer_, now);
    } else {
      auto data = unhex(w[4]);
      if (!data) return answer_error(fieldcodec::errc::bad_digit, {});
      buffer_ = *data;
      s = block ? client_->block_download(a, buffer_, now, opt)
                : client_->download(a, buffer_, now);
    }
    if (!s) {
      client_.reset();
      return answer_error(s.error(), {});
    }
    transmit_all(s.value().send);
    check_end();
  }
  void on_frame(const co::can_frame &f, std::uint32_t now) {
    if (!client_) return;
    transmit_all(client_->on_frame(f, now).send);
    check_end();
  }
  void poll(std::uint32_t now) {
    if (!client_) return;
    transmit_all(client_->poll(now).send);
    check_end();
  }

private:
  void check_end() {
    if (!client_) return;
    const auto st = client_->state();
    if (st == sdo::transfer_state::done) {
      put_line("= ok " + (upload_ ? hex(client_->received()) : std::string()));
      client_.reset();
    } else if (st == sdo::transfer_state::failed) {
      const auto e = client_->error().value_or(sdo::transfer_error{});
      answer_error(e.code, e.abort);
      client_.reset();
    }
  }
  std::optional<sdo::client> client_;
  std::vector<std::uint8_t> buffer_;
  bool upload_ = false;
};

/// What the node received from others (python's SYNC, TIME and EMCY producers), for `!last`.
struct received_log {
  std::size_t node_times = 0; ///< the node's `time` events
  std::size_t syncs = 0;
  std::optional<std::uint8_t> sync_counter;
  std::optional<fieldcodec::od::time_value> time;
  std::optional<co::emcy::received> emcy;
};

/// The application behind the hooks of `!hooks` (node::object_hook): a computed counter, a
/// check of writes, and a DOMAIN streamed to and from its own bytes (the node keeps none).
struct hook_app {
  std::uint32_t reads = 0;
  std::vector<std::uint16_t> written;
  std::vector<std::uint8_t> contents; ///< what uploads serve: the last complete download
  std::vector<std::uint8_t> incoming;
  std::size_t completed = 0;
  std::size_t stop_at = ~std::size_t{0};
  std::vector<sdo::abort_code> ended;

  static sdo::abort_code read(void *c, od::address, std::span<std::uint8_t> v) noexcept {
    const std::uint32_t x = 0x1000U + static_cast<hook_app *>(c)->reads++;
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::uint8_t>(x >> (8U * i));
    return sdo::abort_code::none;
  }
  static sdo::abort_code write(void *c, od::address, std::span<const std::uint8_t> v) noexcept {
    const auto x = static_cast<std::uint16_t>(v[0] | (v[1] << 8U)); // 2120h:06 is UNSIGNED16
    if ((x & 1U) != 0U) return sdo::abort_code::cannot_store_device_state;
    static_cast<hook_app *>(c)->written.push_back(x);
    return sdo::abort_code::none;
  }
  static sdo::abort_code upload(void *c, od::address, std::size_t offset,
                                std::span<std::uint8_t> out, std::size_t &total) noexcept {
    const auto &s = *static_cast<hook_app *>(c);
    if (offset >= s.stop_at) return sdo::abort_code::cannot_store;
    total = s.contents.size();
    for (std::size_t i = 0; i < out.size() && offset + i < total; ++i) {
      out[i] = s.contents[offset + i];
    }
    return sdo::abort_code::none;
  }
  static sdo::abort_code download(void *c, od::address, std::size_t offset,
                                  std::span<const std::uint8_t> part, bool last) noexcept {
    auto &s = *static_cast<hook_app *>(c);
    if (offset + part.size() > s.stop_at) return sdo::abort_code::cannot_store;
    if (offset == 0U) s.incoming.clear();
    s.incoming.insert(s.incoming.end(), part.begin(), part.end());
    if (last) {
      s.contents = s.incoming;
      ++s.completed;
    }
    return sdo::abort_code::none;
  }
  static void end(void *c, od::address, sdo::abort_code why) noexcept {
    static_cast<hook_app *>(c)->ended.push_back(why);
  }
  [[nodiscard]] std::string text() const {
    // appended piece by piece: g++ 12 at -O3 warns (-Wrestrict, a false positive of its
    // libstdc++) on `"text" + std::string` in a user's build (.ci/steps/users_build.sh)
    std::string w;
    for (const std::uint16_t x : written) {
      if (!w.empty()) w += ',';
      w += std::to_string(x);
    }
    std::string e;
    for (const auto c : ended) {
      if (!e.empty()) e += ',';
      e += abort_hex(c);
    }
    std::string out = "= ok ";
    for (const std::string &part :
         {std::to_string(reads), w.empty() ? std::string("-") : w, std::to_string(contents.size()),
          std::to_string(completed), e.empty() ? std::string("-") : e}) {
      if (out.size() > 5U) out += ' ';
      out += part;
    }
    return out;
  }
};

/// The library's node (canopen/node/device.hpp) behind the bridge's commands. What the node
/// does not consume (TIME, other nodes' EMCY) is decoded here for `!last`.
/// What the LSS slave's store hook got (`!lss`), and how it answers (`!lss-store`).
struct lss_storage {
  std::optional<std::uint8_t> node;
  std::optional<co::node::lss_bit_timing> timing;
  std::uint8_t answer = co::lss::error_code::none;
  static co::node::lss_store_result store(void *self, std::uint8_t node,
                                          std::optional<co::node::lss_bit_timing> t) noexcept {
    auto *s = static_cast<lss_storage *>(self);
    if (s->answer == co::lss::error_code::none) {
      s->node = node;
      s->timing = t;
    }
    return {s->answer, 0};
  }
};

template <class Store, co::node::capacity C>
class node_glue {
public:
  node_glue(std::uint8_t node, Store &store) : node_(node), dev_(store, node, {}, lss_options()) {
    if constexpr (C.storage) {
      dev_.set_storage(
          co::node::storage_hook{&params_, &storage_calls::save, &storage_calls::restore});
    }
  }
  void storage_works(bool on) { params_.works = on; }
  [[nodiscard]] std::string storage() const {
    if constexpr (C.storage) {
      return "= ok " + (params_.calls.empty() ? std::string("-") : params_.calls);
    } else {
      return "= error unknown_object 00000000";
    }
  }

  void start(std::uint32_t now) {
    if (auto s = dev_.start(now)) transmit_all(s.value().send);
  }
  void on_frame(const co::can_frame &f, std::uint32_t now) {
    note(f);
    transmit_all(dev_.on_frame(f, now).send);
    note_events();
  }
  /// Several frames at once (FIELDCODEC_INTEROP_BATCH): device::on_frames until all are taken.
  void on_frames(std::span<const co::can_frame> fs, std::uint32_t now) {
    for (const co::can_frame &f : fs) note(f);
    while (!fs.empty()) {
      const auto r = dev_.on_frames(fs, now);
      transmit_all(r.last.send);
      note_events();
      fs = fs.subspan(r.consumed);
    }
  }
  /// `!lss`: the LSS slave's state and what the application got from it.
  [[nodiscard]] std::string lss_text() const {
    const auto &l = dev_.lss();
    char buf[128];
    std::string stored = "-";
    if (storage_.node) {
      stored = std::to_string(*storage_.node) + "/";
      stored += storage_.timing ? std::to_string(storage_.timing->table) + "." +
                                      std::to_string(storage_.timing->index)
                                : std::string("-");
    }
    std::string activated = "-";
    if (activated_) {
      activated =
          std::to_string(activated_->timing.index) + "/" + std::to_string(activated_->delay_ms);
    }
    std::snprintf(buf, sizeof buf, "= ok %s %u %u %s %s",
                  l.mode() == co::node::lss_mode::waiting ? "waiting" : "configuration",
                  unsigned{l.active_node()}, unsigned{l.pending_node()}, stored.c_str(),
                  activated.c_str());
    return buf;
  }
  void lss_store_answer(std::uint8_t code) { storage_.answer = code; }
  /// `!hooks`: the application's hooks on the corpus dictionary (before start).
  [[nodiscard]] std::optional<fieldcodec::errc> add_hooks() {
    co::node::object_hook counter;
    counter.first = counter.last = {0x2106, 0};
    counter.context = &app_;
    counter.read = &hook_app::read;
    co::node::object_hook even;
    even.first = even.last = {0x2120, 6};
    even.context = &app_;
    even.write = &hook_app::write;
    co::node::object_hook domain;
    domain.first = domain.last = {0x2122, 0};
    domain.context = &app_;
    domain.upload = &hook_app::upload;
    domain.download = &hook_app::download;
    domain.ended = &hook_app::end;
    for (const auto &h : {counter, even, domain}) {
      if (const auto st = dev_.add_hook(h); !st) return st.error();
    }
    return std::nullopt;
  }
  [[nodiscard]] hook_app &app() { return app_; }
  void poll(std::uint32_t now) { transmit_all(dev_.poll(now).send); }

  [[nodiscard]] sdo::abort_code set(od::address a, std::span<const std::uint8_t> v,
                                    std::uint32_t now) {
    const auto s = dev_.set(a, v, now);
    if (!s) return s.error();
    transmit_all(s.value().send);
    return sdo::abort_code::none;
  }
  [[nodiscard]] bool raise(std::uint16_t code, std::uint8_t bits,
                           const std::array<std::uint8_t, 5> &manufacturer, std::uint32_t now) {
    auto s = dev_.raise(code, now, bits, manufacturer);
    if (s) transmit_all(s.value().send);
    return s.has_value();
  }
  [[nodiscard]] bool clear(std::uint16_t code, std::uint32_t now) {
    auto s = dev_.clear(code, now);
    if (s) transmit_all(s.value().send);
    return s.has_value();
  }
  /// The application's event for TPDO n: the node sends it at its next poll.
  [[nodiscard]] bool send_tpdo(std::uint16_t n, std::uint32_t now) {
    if (!dev_.request_tpdo(n)) return false;
    poll(now);
    return true;
  }
  /// The node produces TIME (device::produce_time): nullopt, or why not.
  [[nodiscard]] std::optional<fieldcodec::errc> produce_time(od::time_value t, std::uint32_t now) {
    if constexpr (C.time) {
      auto s = dev_.produce_time(t, now);
      if (!s) return s.error();
      transmit_all(s.value().send);
      return std::nullopt;
    } else {
      (void)t;
      (void)now;
      return fieldcodec::errc::unknown_object;
    }
  }
  /// `!last node-time`: the node's `time` events and the last time its consumer took.
  [[nodiscard]] std::string node_time() const {
    if constexpr (C.time) {
      std::string out = "= ok " + std::to_string(log_.node_times);
      if (const auto t = dev_.time().received()) {
        out += " " + std::to_string(t->ms) + " " + std::to_string(t->days);
      } else {
        out += " -";
      }
      return out;
    } else {
      return "= error unknown_object 00000000";
    }
  }
  [[nodiscard]] co::nmt::state state() const { return dev_.state(); }
  [[nodiscard]] const received_log &log() const { return log_; }

private:
  /// The bridge's storage for 1010h/1011h: it notes what it was asked.
  struct storage_calls {
    std::string calls;
    bool works = true;
    static bool note(void *c, char what, std::uint8_t group) noexcept {
      auto &s = *static_cast<storage_calls *>(c);
      if (!s.calls.empty()) s.calls += ' ';
      s.calls += what;
      s.calls += std::to_string(group);
      return s.works;
    }
    static bool save(void *c, std::uint8_t group) noexcept { return note(c, 's', group); }
    static bool restore(void *c, std::uint8_t group) noexcept { return note(c, 'r', group); }
  };
  storage_calls params_;
  co::node::lss_options lss_options() {
    co::node::lss_options o;
    o.store = &lss_storage::store;
    o.context = &storage_;
    return o;
  }
  void note_events() {
    for (const auto &e : dev_.events()) {
      if (e.what == co::node::event::kind::time) ++log_.node_times;
      if (e.what == co::node::event::kind::lss &&
          dev_.lss().last_event().what == co::node::lss_event::kind::activate_bit_timing) {
        activated_ = dev_.lss().last_event();
      }
    }
  }
  void note(const co::can_frame &f) {
    if (f.id == co::cob_id::sync && !f.rtr) {
      if (auto c = co::sync::decode(f)) {
        ++log_.syncs;
        log_.sync_counter = c.value();
      }
    } else if (f.id == co::cob_id::time && !f.rtr) {
      if (auto t = co::time_stamp::decode(f)) log_.time = t.value();
    } else if (f.id > co::cob_id::emcy_base && f.id <= co::cob_id::emcy_base + 127U &&
               f.id != co::cob_id::emcy_base + node_) {
      if (auto e = co::emcy::decode(f)) log_.emcy = e.value();
    }
  }
  std::uint8_t node_;
  hook_app app_;
  lss_storage storage_; // before dev_: the device's options point at it
  co::node::device<Store, C> dev_;
  received_log log_;
  std::optional<co::node::lss_event> activated_;
};

/// `!last sync|time|emcy`: what the node decoded last from python's producers.
void last(const received_log &log, const std::string &what) {
  char buf[96];
  if (what == "sync") {
    if (log.sync_counter) {
      std::snprintf(buf, sizeof buf, "= ok %zu %u", log.syncs, unsigned{*log.sync_counter});
    } else {
      std::snprintf(buf, sizeof buf, "= ok %zu -", log.syncs);
    }
  } else if (what == "time" && log.time) {
    std::snprintf(buf, sizeof buf, "= ok %u %u", static_cast<unsigned>(log.time->ms),
                  unsigned{log.time->days});
  } else if (what == "emcy" && log.emcy) {
    const auto &m = log.emcy->m;
    std::snprintf(buf, sizeof buf, "= ok %u %04X %02X %s", unsigned{log.emcy->node},
                  unsigned{m.error_code}, unsigned{m.error_register}, hex(m.manufacturer).c_str());
  } else {
    std::snprintf(buf, sizeof buf, "= error unknown_object 00000000");
  }
  put_line(buf);
}

std::vector<std::string> split(const std::string &s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  for (const char c : s) {
    if (c == sep) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

/// `!pack MAPPINGS VALUES`: the PDO bytes of a mapping (comma-separated 32-bit mapping values in
/// hex) holding the values (comma-separated, decimal, signed).
void pack_command(const std::string &mappings, const std::string &values) {
  std::vector<co::pdo::mapping_entry> map;
  for (const auto &m : split(mappings, ',')) {
    map.push_back(
        co::pdo::mapping_entry::from_u32(static_cast<std::uint32_t>(std::stoul(m, nullptr, 16))));
  }
  std::vector<std::int64_t> raws;
  for (const auto &v : split(values, ',')) raws.push_back(std::stoll(v, nullptr, 10));
  std::array<std::uint8_t, 8> data{};
  auto n = co::pdo::pack_all(map, raws, data);
  if (!n) return answer_error(n.error(), {});
  put_line("= ok " + hex(std::span<const std::uint8_t>(data).first(n.value())));
}

std::vector<std::string> words(const std::string &line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

template <class Glue, class Store>
int run(Store &store, std::uint8_t node) {
  static Glue glue(node, store);
  client_side client;
  std::string pending;
  const bool batch = std::getenv("FIELDCODEC_INTEROP_BATCH") != nullptr;
  std::vector<co::can_frame> rx; // batch: the frames of this read so far
  for (;;) {
    pollfd p{STDIN_FILENO, POLLIN, 0};
    // batch: frames wait while more arrive within 1 ms (a sub-block's segments come together)
    const int ready = ::poll(&p, 1, rx.empty() ? 5 : 1);
    const std::uint32_t now = now_ms();
    const auto flush = [&]() {
      if (rx.empty()) return;
      glue.on_frames(rx, now);
      for (const co::can_frame &f : rx) client.on_frame(f, now);
      rx.clear();
    };
    if (ready > 0) {
      char buf[4096];
      const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
      if (n <= 0) return 0;
      pending.append(buf, static_cast<std::size_t>(n));
      std::size_t nl;
      while ((nl = pending.find('\n')) != std::string::npos) {
        const std::string line = pending.substr(0, nl);
        pending.erase(0, nl + 1U);
        if (line.empty()) continue;
        if (line[0] != '!') {
          auto r = fieldcodec::host::candump::parse_frame(line);
          if (!r) {
            std::fprintf(stderr, "interop_node: bad frame line '%s'\n", line.c_str());
            return 2;
          }
          auto f = fieldcodec::host::to_canopen(r.value());
          if (!f) continue;
          if (batch) {
            rx.push_back(f.value());
            continue;
          }
          glue.on_frame(f.value(), now);
          client.on_frame(f.value(), now);
          continue;
        }
        flush(); // the frames before a command are taken before it
        const auto w = words(line);
        if (w[0] == "!quit") return 0;
        if (w[0] == "!start") {
          glue.start(now);
          put_line("= ok ");
        } else if (w[0] == "!state") {
          put_line("= ok " + std::string(co::nmt::to_string(glue.state())));
        } else if (w[0] == "!last" && w.size() == 2U && w[1] == "node-time") {
          put_line(glue.node_time());
        } else if (w[0] == "!last" && w.size() == 2U && w[1] == "hooks") {
          put_line(glue.app().text());
        } else if (w[0] == "!last" && w.size() == 2U && w[1] == "storage") {
          put_line(glue.storage());
        } else if (w[0] == "!storage" && w.size() == 2U && (w[1] == "ok" || w[1] == "fail")) {
          glue.storage_works(w[1] == "ok");
          put_line("= ok ");
        } else if (w[0] == "!last" && w.size() == 2U) {
          last(glue.log(), w[1]);
        } else if (w[0] == "!time" && w.size() == 3U) {
          const unsigned long ms = std::stoul(w[1], nullptr, 10);
          const unsigned long days = std::stoul(w[2], nullptr, 10);
          if (ms > 0xFFFF'FFFFUL || days > 0xFFFFUL) {
            answer_error(fieldcodec::errc::out_of_range, {});
          } else if (const auto e =
                         glue.produce_time(od::time_value{static_cast<std::uint32_t>(ms),
                                                          static_cast<std::uint16_t>(days)},
                                           now)) {
            answer_error(*e, {});
          } else {
            put_line("= ok ");
          }
        } else if (w[0] == "!emcy" && w.size() >= 3U) {
          // !emcy CODE REGISTER-BITS [MANUFACTURER-HEX]: an application error appears
          std::array<std::uint8_t, 5> manufacturer{};
          if (w.size() > 3U) {
            const auto bytes = unhex(w[3]).value_or(std::vector<std::uint8_t>{});
            for (std::size_t i = 0; i < bytes.size() && i < 5U; ++i) manufacturer[i] = bytes[i];
          }
          const bool done = glue.raise(static_cast<std::uint16_t>(std::stoul(w[1], nullptr, 16)),
                                       static_cast<std::uint8_t>(std::stoul(w[2], nullptr, 16)),
                                       manufacturer, now);
          put_line(done ? "= ok " : "= error bad_state 00000000");
        } else if (w[0] == "!emcy-clear" && w.size() == 2U) {
          // !emcy-clear CODE: the error is gone
          const bool done =
              glue.clear(static_cast<std::uint16_t>(std::stoul(w[1], nullptr, 16)), now);
          put_line(done ? "= ok " : "= error bad_state 00000000");
        } else if (w[0] == "!tpdo" && w.size() == 2U) {
          if (glue.send_tpdo(static_cast<std::uint16_t>(std::stoul(w[1])), now)) {
            put_line("= ok ");
          } else {
            answer_error(fieldcodec::errc::bad_state, {});
          }
        } else if (w[0] == "!hooks" && w.size() == 1U) {
          if (const auto e = glue.add_hooks()) {
            answer_error(*e, {});
          } else {
            put_line("= ok ");
          }
        } else if (w[0] == "!hooks-stop" && w.size() == 2U) {
          glue.app().stop_at = w[1] == "-" ? ~std::size_t{0} : std::stoul(w[1], nullptr, 10);
          put_line("= ok ");
        } else if (w[0] == "!lss" && w.size() == 1U) {
          put_line(glue.lss_text());
        } else if (w[0] == "!lss-store" && w.size() == 2U) {
          glue.lss_store_answer(w[1] == "ok" ? co::lss::error_code::none
                                             : co::lss::error_code::storage_access);
          put_line("= ok ");
        } else if (w[0] == "!pack" && w.size() == 3U) {
          pack_command(w[1], w[2]);
        } else if (w[0] == "!upload" || w[0] == "!download") {
          client.start(w, now); // one `now` per round: machines need time that never goes back
        } else if ((w[0] == "!value" || w[0] == "!set") && w.size() >= 3U) {
          const od::address a{static_cast<std::uint16_t>(std::stoul(w[1], nullptr, 16)),
                              static_cast<std::uint8_t>(std::stoul(w[2], nullptr, 16))};
          if (w[0] == "!value") {
            auto v = store.value(a);
            if (v) {
              put_line("= ok " + hex(v.value()));
            } else {
              answer_error(v.error(), {});
            }
          } else {
            auto data = unhex(w.size() > 3U ? w[3] : "-");
            const auto c = data ? glue.set(a, *data, now) : sdo::abort_code::general_error;
            if (c == sdo::abort_code::none) {
              put_line("= ok ");
            } else {
              answer_error(fieldcodec::errc::aborted, c);
            }
          }
        } else {
          answer_error(fieldcodec::errc::bad_syntax, {});
        }
      }
      if (!rx.empty()) continue; // taken when the bus is quiet, or before the next command
    } else if (ready < 0) {
      return 2;
    }
    flush();
    glue.poll(now);
    client.poll(now);
  }
}

/// The capacity the dictionary needs; built with FIELDCODEC_INTEROP_CRC_TABLE (the executable
/// interop_node_crc_table), the SDO servers compute the block transfer CRC by table.
template <const od::dictionary &Dict>
constexpr co::node::capacity capacity() {
  co::node::capacity c = co::node::capacity_for(Dict);
  c.lss = true; // the LSS slave (interop_peer.py lss); it answers nothing but 7E5h
  c.hooks = 3;  // the application's hooks, added by `!hooks` only (interop_peer.py hooks)
#ifdef FIELDCODEC_INTEROP_CRC_TABLE
  c.sdo_crc_table = true;
#endif
  return c;
}

template <const od::dictionary &Dict, std::size_t N>
int serve(std::uint8_t node) {
  static constexpr auto layout = co::make_layout<N>(Dict);
  static std::vector<std::uint8_t> storage(layout.storage_size());
  static std::vector<std::uint8_t> staging(65536);
  static co::dictionary_store<> store{Dict, layout, storage, staging};
  if (auto s = store.init_defaults(node); !s) {
    std::fprintf(stderr, "interop_node: init_defaults: %s\n",
                 std::string(fieldcodec::to_string(s.error())).c_str());
    return 2;
  }
  return run<node_glue<decltype(store), capacity<Dict>()>>(store, node);
}

} // namespace

int main(int argc, char **argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: interop_node xenax|corpus NODE\n");
    return 2;
  }
  const std::string dict = argv[1];
  const auto node = static_cast<std::uint8_t>(std::atoi(argv[2]));
  namespace d = fieldcodec::dictionaries;
  if (dict == "xenax")
    return serve<d::xenax_canopen::dictionary, d::xenax_canopen::dictionary.size()>(node);
#ifdef FIELDCODEC_INTEROP_CORPUS
  if (dict == "corpus")
    return serve<d::interop_corpus::dictionary, d::interop_corpus::dictionary.size()>(node);
#endif
  std::fprintf(stderr, "interop_node: unknown dictionary '%s'\n", dict.c_str());
  return 2;
}
