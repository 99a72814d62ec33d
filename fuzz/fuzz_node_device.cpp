// Fuzz harness for node::device (canopen/node/device.hpp), a CiA 301 node over a generated
// dictionary, fed arbitrary frames and times: NMT commands, SYNCs, RPDOs, heartbeats and
// guarding requests, SDO requests of any bytes, and SDO writes to the communication objects
// (1005h, 1006h, 1007h, 100Ch, 100Dh, 1014h–1017h, 1019h, the SDO and PDO parameters) with
// arbitrary values, through on_frame and on_frames, with poll(), set(), raise() and clear().
//
// Byte 0: bit 0 the dictionary (the XENAX CAN EDS, with limits; the I/O node of the Cortex-M
// example: heartbeat consumers, error history, an SDO client, 4 + 4 PDOs), bit 1 self start,
// bit 2 block transfer on the SDO server, bit 3 the application's hooks (capacity::hooks): on
// the I/O node 6401h computed at each read and TPDO (refused at every 7th), writes to 6411h and
// 6200h checked by a hook that refuses some; instead of the XENAX dictionary a small one whose
// DOMAINs 2005h (no capacity) and 2006h (300 bytes) are streamed to and from the application,
// which refuses a download past 5000 bytes and an upload part at every 11th call. Byte 1: the
// node-ID (1..127). Then operations (see `run`), each a byte and its arguments.
//
// Invariants, checked after every call:
// * every frame the node sends is on a COB-ID it owns at that moment (before or after the call:
//   0x700 + node, its EMCY COB-ID, its SDO servers' server→client and its SDO clients'
//   client→server COB-IDs, its valid TPDOs' COB-IDs, SYNC when 1005h says it produces one), a
//   valid base frame of DLC 0..8 that is not a remote frame unless a TPDO's;
// * every value in the store is within its entry's type and limits (od::decode with the
//   limits, node-ID relative limits for this node; byte strings within their capacity);
// * the NMT state is one of the four (initialising only in the boot-up message), and
//   pre-operational, operational or stopped once started;
// * the step's deadline is never in the past (at or after `now`, modulo 2^32);
// * nothing was lost (frames or events beyond the lists' sizes: a sizing error);
// * a write hook sees only values that passed the node's checks (their type and limits), a
//   read hook a span of the object's width; a stream's download parts come in order from
//   offset 0 (a transfer that ended unfinished was reported through `ended`), never past a
//   declared capacity, and an upload is asked for offsets within the contents.
#include "check.hpp"
#include "input.hpp"

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/node/device.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/value.hpp>

#include "../examples/firmware/io_node_dictionary.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

namespace co = fieldcodec::canopen;
namespace node = fieldcodec::canopen::node;
namespace sdo = fieldcodec::canopen::sdo;
namespace od = fieldcodec::od;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;
namespace io = fieldcodec::dictionaries::io_node;

namespace {

using fuzz_input::reader;

using store_type = co::dictionary_store<>;

/// The communication objects an SDO write targets (sub-indices beyond an object's own are
/// refused by the store, which is worth feeding too).
constexpr std::array<od::address, 34> comm_objects{{
    {0x1005, 0}, {0x1006, 0}, {0x1007, 0}, {0x100C, 0}, {0x100D, 0}, {0x1014, 0}, {0x1015, 0},
    {0x1016, 1}, {0x1016, 2}, {0x1017, 0}, {0x1019, 0}, {0x1003, 0}, {0x1010, 1}, {0x1011, 1},
    {0x1200, 1}, {0x1200, 2}, {0x1201, 1}, {0x1201, 2}, {0x1201, 3}, {0x1280, 1}, {0x1280, 2},
    {0x1280, 3}, {0x1400, 1}, {0x1400, 2}, {0x1400, 5}, {0x1600, 0}, {0x1600, 1}, {0x1800, 1},
    {0x1800, 2}, {0x1800, 3}, {0x1800, 5}, {0x1800, 6}, {0x1A00, 0}, {0x1A00, 1},
}};

/// The application's hooks of the I/O node (byte 0 bit 3).
struct fuzz_app {
  od::dictionary dict;
  std::uint8_t node = 1;
  std::uint16_t reads = 0;
  static sdo::abort_code read(void *c, od::address a, std::span<std::uint8_t> v) noexcept {
    auto &s = *static_cast<fuzz_app *>(c);
    const od::entry *e = s.dict.find(a);
    FUZZ_CHECK(e != nullptr && v.size() == od::fixed_size(e->type));
    if (++s.reads % 7U == 0U) return sdo::abort_code::no_data;
    for (std::size_t i = 0; i < v.size(); ++i) {
      v[i] = static_cast<std::uint8_t>((s.reads * 0x9E37U) >> (4U * i));
    }
    return sdo::abort_code::none;
  }
  static sdo::abort_code write(void *c, od::address a, std::span<const std::uint8_t> v) noexcept {
    auto &s = *static_cast<fuzz_app *>(c);
    const od::entry *e = s.dict.find(a);
    FUZZ_CHECK(e != nullptr);
    FUZZ_CHECK(od::decode(*e, v, fieldcodec::byte_order::little, od::limits::check, s.node));
    return !v.empty() && v[0] == 0xFFU ? sdo::abort_code::cannot_store_device_state
                                       : sdo::abort_code::none;
  }
};

/// The streamed DOMAINs of the small dictionary (byte 0 bits 0 and 3: 00001xx0).
struct fuzz_stream {
  static constexpr std::size_t contents = 1000; ///< what an upload serves
  std::size_t received = 0;                     ///< the running download's bytes so far
  std::size_t calls = 0;
  static sdo::abort_code upload(void *c, od::address, std::size_t offset,
                                std::span<std::uint8_t> out, std::size_t &total) noexcept {
    auto &s = *static_cast<fuzz_stream *>(c);
    FUZZ_CHECK(offset <= contents);
    if (++s.calls % 11U == 0U) return sdo::abort_code::hardware_error;
    total = contents;
    for (std::size_t i = 0; i < out.size() && offset + i < contents; ++i) {
      out[i] = static_cast<std::uint8_t>((offset + i) * 7U);
    }
    return sdo::abort_code::none;
  }
  static sdo::abort_code download(void *c, od::address a, std::size_t offset,
                                  std::span<const std::uint8_t> part, bool last) noexcept {
    auto &s = *static_cast<fuzz_stream *>(c);
    if (offset == 0U) s.received = 0;
    FUZZ_CHECK(offset == s.received);
    if (a.index == 0x2006U) FUZZ_CHECK(offset + part.size() <= 300U);
    s.received += part.size();
    if (s.received > 5000U) return sdo::abort_code::length_too_high;
    if (last) s.received = 0;
    return sdo::abort_code::none;
  }
  static void ended(void *c, od::address, sdo::abort_code) noexcept {
    static_cast<fuzz_stream *>(c)->received = 0;
  }
};

/// The small dictionary with the streamed DOMAINs.
constexpr od::entry_spec u32_var(std::uint16_t index, std::uint8_t sub, od::access a,
                                 std::uint64_t v) {
  return {.index = index,
          .sub = sub,
          .type = od::data_type::unsigned32,
          .access_type = a,
          .default_value = {od::number_kind::unsigned_, 0, v}};
}
inline constexpr std::array<od::entry_spec, 6> stream_specs{{
    u32_var(0x1000, 0, od::access::ro, 0),
    {.index = 0x1017,
     .type = od::data_type::unsigned16,
     .access_type = od::access::rw,
     .default_value = {od::number_kind::unsigned_, 0, 0}},
    {.index = 0x1018,
     .type = od::data_type::unsigned8,
     .access_type = od::access::ro,
     .default_value = {od::number_kind::unsigned_, 0, 1}},
    u32_var(0x1018, 1, od::access::ro, 0x0F1C),
    {.index = 0x2005, .type = od::data_type::domain, .access_type = od::access::rw},
    {.index = 0x2006, .type = od::data_type::domain, .access_type = od::access::rw, .size = 300},
}};

template <class Device>
class rig {
public:
  template <std::size_t N>
  rig(od::dictionary dict, const co::store_layout<N> &layout, std::span<std::uint8_t> storage,
      std::uint8_t n, node::options o)
      : dict_(dict), store_(dict, layout, storage), node_(n), dev_(init(store_, n), n, o) {
    // the entries that hold COB-IDs the node sends on: SDO server -> client, SDO client ->
    // server, TPDOs
    for (const od::entry &e : dict_.entries()) {
      if ((e.index >= 0x1200U && e.index <= 0x127FU && e.sub == 2U) ||
          (e.index >= 0x1280U && e.index <= 0x12FFU && e.sub == 1U) ||
          (e.index >= 0x1800U && e.index <= 0x19FFU && e.sub == 1U)) {
        cob_id_entries_.push_back({e.index, e.sub});
      }
    }
    if constexpr (Device::capacities().hooks > 0U) {
      if (dict.contains(0x2005, 0)) { // the small dictionary: its DOMAINs streamed
        node::object_hook h;
        h.context = &stream_;
        h.upload = &fuzz_stream::upload;
        h.download = &fuzz_stream::download;
        h.ended = &fuzz_stream::ended;
        h.first = {0x2005, 0};
        h.last = {0x2006, 0};
        FUZZ_CHECK(dev_.add_hook(h));
        return;
      }
      app_.dict = dict;
      app_.node = n;
      node::object_hook computed;
      computed.first = {0x6401, 1};
      computed.last = {0x6401, 0xFF};
      computed.context = &app_;
      computed.read = &fuzz_app::read;
      FUZZ_CHECK(dev_.add_hook(computed));
      node::object_hook checked = computed;
      checked.read = nullptr;
      checked.write = &fuzz_app::write;
      for (const std::uint16_t index : {std::uint16_t{0x6200}, std::uint16_t{0x6411}}) {
        checked.first = {index, 0};
        checked.last = {index, 0xFF};
        FUZZ_CHECK(dev_.add_hook(checked));
      }
    }
  }

  void run(reader &in) {
    check(dev_.start(now_).value(), {});
    for (int ops = 0; ops < 200 && !in.empty(); ++ops) {
      const std::uint8_t op = in.byte();
      const auto before = owned();
      switch (op % 9U) {
      case 0: { // any frame, mostly on the COB-IDs the node listens to
        const co::can_frame f = frame(in);
        check(dev_.on_frame(f, now_), before);
        break;
      }
      case 1: { // an SDO write to a communication object (expedited, 1..4 bytes)
        const od::address a = comm_objects[in.byte() % comm_objects.size()];
        const std::uint32_t v = in.u32();
        const std::size_t size = 1U + in.byte() % 4U;
        const std::array<std::uint8_t, 4> bytes{
            static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v >> 8U),
            static_cast<std::uint8_t>(v >> 16U), static_cast<std::uint8_t>(v >> 24U)};
        const auto m = sdo::expedited_download(a, std::span(bytes).first(size));
        if (m) check(dev_.on_frame(channel().request(m.value()), now_), before);
        break;
      }
      case 2: // time passes
        now_ += in.u16() % 3000U;
        check(dev_.poll(now_), before);
        break;
      case 3: { // several frames at once (a receive FIFO)
        std::array<co::can_frame, 8> fs{};
        const std::size_t count = 1U + in.byte() % fs.size();
        for (std::size_t i = 0; i < count; ++i) fs[i] = frame(in);
        std::span<const co::can_frame> rest(fs.data(), count);
        while (!rest.empty()) {
          const auto r = dev_.on_frames(rest, now_);
          FUZZ_CHECK(r.consumed >= 1U && r.consumed <= rest.size());
          check(r.last, before);
          rest = rest.subspan(r.consumed);
        }
        break;
      }
      case 4: { // the application sets a value of any entry
        const auto entries = dict_.entries();
        const od::entry &e = entries[in.u16() % entries.size()];
        std::array<std::uint8_t, 8> bytes{};
        const std::size_t size = in.byte() % 9U;
        for (std::size_t i = 0; i < size; ++i) bytes[i] = in.byte();
        (void)dev_.set({e.index, e.sub}, std::span(bytes).first(size));
        check_values();
        break;
      }
      case 5: { // an application error comes or goes
        const std::uint16_t code = in.u16();
        if ((code & 1U) == 0U) {
          if (auto s = dev_.raise(code, now_)) check(s.value(), before);
        } else if (auto s = dev_.clear(code & 0xFFFEU, now_)) {
          check(s.value(), before);
        }
        break;
      }
      case 6: { // an NMT command for this node or all
        const std::array<std::uint8_t, 5> cmds{0x01, 0x02, 0x80, 0x81, 0x82};
        const std::uint8_t target = (in.byte() & 1U) != 0U ? node_ : std::uint8_t{0};
        check(
            dev_.on_frame(co::make_frame(0, {cmds[in.byte() % cmds.size()], target}).value(), now_),
            before);
        break;
      }
      case 7: { // an SDO request of any bytes (segments, block transfers, aborts, junk)
        co::can_frame f = co::make_frame(static_cast<std::uint16_t>(0x600U + node_), {}).value();
        f.dlc = 8;
        for (auto &b : f.data) b = in.byte();
        check(dev_.on_frame(f, now_), before);
        break;
      }
      default: { // a short time passes and a frame comes
        now_ += in.byte();
        check(dev_.on_frame(frame(in), now_), before);
        break;
      }
      }
    }
  }

private:
  static store_type &init(store_type &s, std::uint8_t n) {
    FUZZ_CHECK(s.init_defaults(n).has_value());
    return s;
  }
  sdo::channel channel() const { return sdo::channel::default_for(node_).value(); }

  co::can_frame frame(reader &in) {
    const std::uint8_t kind = in.byte();
    static constexpr std::array<std::uint16_t, 12> bases{0x000, 0x080, 0x100, 0x180, 0x200, 0x300,
                                                         0x400, 0x500, 0x600, 0x700, 0x080, 0x000};
    std::uint16_t id = bases[kind % bases.size()];
    if (kind >= 0xC0U) {
      id = static_cast<std::uint16_t>(in.u16() & 0x7FFU);
    } else if (id != 0U && !(kind % bases.size() == 1U)) {
      id = static_cast<std::uint16_t>(id + ((kind & 0x20U) != 0U ? in.byte() & 0x7FU : node_));
    }
    co::can_frame f;
    f.id = id;
    f.rtr = (kind & 0x10U) != 0U && (kind & 0x08U) != 0U;
    f.dlc = static_cast<std::uint8_t>(in.byte() % 9U);
    if (!f.rtr) {
      for (std::size_t i = 0; i < f.dlc; ++i) f.data[i] = in.byte();
    }
    return f;
  }

  std::optional<std::uint32_t> u32_value(od::address a) const {
    const auto v = dev_.value(a);
    if (!v || v.value().size() != 4U) return std::nullopt;
    const auto b = v.value();
    std::uint32_t u = 0;
    for (std::size_t i = 4; i-- > 0;) u = u << 8U | b[i];
    return u;
  }
  /// A COB-ID object's identifier when valid (bit 31 clear, 11-bit frame).
  void add_valid(std::vector<std::uint16_t> &ids, od::address a) const {
    if (auto v = u32_value(a)) {
      if ((*v & 0x80000000U) == 0U && (*v & 0x20000000U) == 0U) {
        ids.push_back(static_cast<std::uint16_t>(*v & 0x7FFU));
      }
    }
  }
  /// The COB-IDs the node may send on now.
  std::vector<std::uint16_t> owned() const {
    std::vector<std::uint16_t> ids{static_cast<std::uint16_t>(0x700U + node_),
                                   static_cast<std::uint16_t>(0x580U + node_)};
    if (auto e = u32_value({0x1014, 0})) {
      if ((*e & 0x80000000U) == 0U) ids.push_back(static_cast<std::uint16_t>(*e & 0x7FFU));
    } else {
      ids.push_back(static_cast<std::uint16_t>(0x80U + node_)); // no 1014h: the default
    }
    if (auto s = u32_value({0x1005, 0}); s && (*s & 0x40000000U) != 0U) {
      ids.push_back(static_cast<std::uint16_t>(*s & 0x7FFU));
    }
    for (const od::address a : cob_id_entries_) add_valid(ids, a);
    return ids;
  }

  void check(const typename Device::step &s, const std::vector<std::uint16_t> &before) {
    const auto after = owned();
    const auto owns = [&](std::uint16_t id) {
      for (const auto x : before) {
        if (x == id) return true;
      }
      for (const auto x : after) {
        if (x == id) return true;
      }
      return false;
    };
    for (const co::can_frame &f : s.send) {
      FUZZ_CHECK(f.id <= 0x7FFU && f.dlc <= 8U);
      FUZZ_CHECK(owns(f.id));
      if (f.rtr) FUZZ_CHECK(f.id != 0x700U + node_ && f.id != 0x580U + node_);
    }
    const co::nmt::state st = dev_.state();
    FUZZ_CHECK(co::nmt::is_state(static_cast<std::uint8_t>(st)));
    FUZZ_CHECK(st != co::nmt::state::boot_up);
    FUZZ_CHECK(s.state == st);
    if (s.deadline) FUZZ_CHECK(!co::reached(*s.deadline, now_) || *s.deadline == now_);
    FUZZ_CHECK(dev_.lost() == 0U);
    check_values();
  }

  void check_values() const {
    for (const od::entry &e : dict_.entries()) {
      if (e.object != od::object_code::var && e.object != od::object_code::array &&
          e.object != od::object_code::record) {
        continue;
      }
      const auto v = dev_.value({e.index, e.sub});
      if (!v) continue; // no value (write-only, not stored)
      if (od::is_byte_string(e.type)) {
        FUZZ_CHECK(e.capacity() == 0U || v.value().size() <= e.capacity());
        continue;
      }
      const auto n =
          od::decode(e, v.value(), fieldcodec::byte_order::little, od::limits::check, node_);
      if (!n) {
        std::fprintf(stderr, "%04X:%02X holds", e.index, e.sub);
        for (const std::uint8_t b : v.value()) std::fprintf(stderr, " %02X", b);
        std::fprintf(stderr, ": %s\n", std::string(fieldcodec::to_string(n.error())).c_str());
      }
      FUZZ_CHECK(n.has_value());
    }
  }

  od::dictionary dict_;
  std::vector<od::address> cob_id_entries_;
  store_type store_;
  std::uint8_t node_;
  Device dev_;
  fuzz_app app_{};
  fuzz_stream stream_{};
  std::uint32_t now_ = 1000;
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  if (size < 2) return 0;
  reader in{std::span<const std::uint8_t>(data + 2, size - 2)};
  const auto n = static_cast<std::uint8_t>(1U + data[1] % 127U);
  node::options o;
  o.self_start = (data[0] & 2U) != 0U;
  o.sdo_timeout_ms = 500;
  o.sdo.block = (data[0] & 4U) != 0U;
  if ((data[0] & 9U) == 8U) {
    static constexpr auto entries = od::entries_of<stream_specs>;
    static constexpr od::dictionary dict{entries};
    static_assert(dict.is_valid());
    static constexpr auto layout = co::make_layout<entries.size()>(dict);
    static std::array<std::uint8_t, layout.storage_size()> storage;
    storage.fill(0);
    rig<node::device<store_type, node::capacity_for(dict, {.hooks = 1})>> r(dict, layout, storage,
                                                                            n, o);
    r.run(in);
  } else if ((data[0] & 1U) == 0U) {
    static constexpr auto layout = co::make_layout<xcan::dictionary.size()>(xcan::dictionary);
    static std::array<std::uint8_t, layout.storage_size()> storage;
    storage.fill(0);
    rig<node::device<store_type, node::capacity_for(xcan::dictionary)>> r(xcan::dictionary, layout,
                                                                          storage, n, o);
    r.run(in);
  } else {
    static constexpr od::dictionary dict{io::entries};
    static constexpr auto layout = co::make_layout<io::entries.size()>(dict);
    static std::array<std::uint8_t, layout.storage_size()> storage;
    storage.fill(0);
    if ((data[0] & 8U) != 0U) {
      rig<node::device<store_type, node::capacity_for(dict, {.hooks = 3})>> r(dict, layout, storage,
                                                                              n, o);
      r.run(in);
    } else {
      rig<node::device<store_type, node::capacity_for(dict)>> r(dict, layout, storage, n, o);
      r.run(in);
    }
  }
  return 0;
}
