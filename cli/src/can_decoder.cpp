// fieldcodec CLI — the CANopen traffic decoder.
#include "can_decoder.hpp"

#include <fieldcodec/canopen/cob_id.hpp>
#include <fieldcodec/canopen/emcy.hpp>
#include <fieldcodec/canopen/lss.hpp>
#include <fieldcodec/canopen/nmt.hpp>
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sync.hpp>
#include <fieldcodec/canopen/time_stamp.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/dpq/emergency.hpp>
#include <fieldcodec/ds402/error_code.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/value_text.hpp>
#include <fieldcodec/xenax/error_code.hpp>

#include <cstdio>

namespace fieldcodec::cli {

namespace sdo = canopen::sdo;

namespace {

std::string time_text(const host::timestamp &t) { return host::candump::format_time(t); }

std::string_view nmt_command_text(canopen::nmt::command c) {
  switch (c) {
  case canopen::nmt::command::start: return "start";
  case canopen::nmt::command::stop: return "stop";
  case canopen::nmt::command::enter_pre_operational: return "enter pre-operational";
  case canopen::nmt::command::reset_node: return "reset node";
  case canopen::nmt::command::reset_communication: return "reset communication";
  }
  return "?";
}

std::string_view nmt_state_text(std::uint8_t s) {
  switch (s) {
  case 0x00: return "boot-up";
  case 0x04: return "stopped";
  case 0x05: return "operational";
  case 0x7F: return "pre-operational";
  default: return {};
  }
}

/// CiA 301's named EMCY codes.
std::string_view emcy_code_text(std::uint16_t c) {
  namespace k = canopen::emcy::code;
  switch (c) {
  case k::error_reset: return "error reset or no error";
  case k::generic: return "generic error";
  case k::communication: return "communication";
  case k::can_overrun: return "CAN overrun (objects lost)";
  case k::can_error_passive: return "CAN in error passive mode";
  case k::life_guard_error: return "life guard or heartbeat error";
  case k::recovered_from_bus_off: return "recovered from bus off";
  case k::can_id_collision: return "CAN-ID collision";
  case k::pdo_length_error: return "PDO not processed due to length error";
  case k::pdo_length_exceeded: return "PDO length exceeded";
  case k::dam_mpdo_not_processed: return "DAM MPDO not processed, destination object not available";
  case k::unexpected_sync_length: return "unexpected SYNC data length";
  case k::rpdo_timeout: return "RPDO timeout";
  case k::external: return "external error";
  case k::device_specific: return "device specific";
  default: return {};
  }
}

std::string register_text(std::uint8_t r) {
  static constexpr std::string_view bits[] = {"generic",     "current",       "voltage",
                                              "temperature", "communication", "device profile",
                                              "reserved",    "manufacturer"};
  std::string s;
  for (unsigned i = 0; i < 8U; ++i) {
    if ((r & (1U << i)) == 0U) continue;
    if (!s.empty()) s += ", ";
    s += bits[i];
  }
  return s;
}

std::string_view message_name(sdo::message_type t) {
  switch (t) {
  case sdo::message_type::initiate_download_request: return "initiate download";
  case sdo::message_type::download_segment_request: return "download segment";
  case sdo::message_type::initiate_upload_request: return "initiate upload";
  case sdo::message_type::upload_segment_request: return "upload segment request";
  case sdo::message_type::block_download_initiate: return "block download initiate";
  case sdo::message_type::block_upload_initiate: return "block upload initiate";
  case sdo::message_type::block_upload_start: return "block upload start";
  case sdo::message_type::initiate_download_response: return "download response";
  case sdo::message_type::download_segment_response: return "download segment response";
  case sdo::message_type::initiate_upload_response: return "upload response";
  case sdo::message_type::upload_segment_response: return "upload segment";
  case sdo::message_type::block_download_initiate_response: return "block download response";
  case sdo::message_type::block_upload_initiate_response: return "block upload response";
  case sdo::message_type::block_ack: return "block acknowledge";
  case sdo::message_type::block_end: return "block end";
  case sdo::message_type::block_end_response: return "block end response";
  case sdo::message_type::block_segment: return "block segment";
  case sdo::message_type::abort: return "abort";
  }
  return "?";
}

std::string abort_text(sdo::abort_code c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%08Xh", static_cast<unsigned>(c));
  const std::string_view t = sdo::to_string(c);
  return std::string(buf) + " " +
         (t.empty() ? std::string("(not a CiA 301 abort code)") : std::string(t));
}

/// A PDO's number 1..512 and direction from its communication or mapping parameter index.
struct pdo_param {
  bool rpdo;
  bool mapping;
  std::size_t n; ///< 0..511
};
std::optional<pdo_param> pdo_param_of(std::uint16_t index) {
  if (index >= 0x1400 && index <= 0x15FF) return pdo_param{true, false, index - 0x1400U};
  if (index >= 0x1600 && index <= 0x17FF) return pdo_param{true, true, index - 0x1600U};
  if (index >= 0x1800 && index <= 0x19FF) return pdo_param{false, false, index - 0x1800U};
  if (index >= 0x1A00 && index <= 0x1BFF) return pdo_param{false, true, index - 0x1A00U};
  return std::nullopt;
}

} // namespace

std::string render_text(const decoded_line &l) {
  std::string s;
  if (l.time.known()) s += time_text(l.time) + " ";
  if (!l.iface.empty()) s += std::string(l.iface.view()) + " ";
  std::string id = l.id.empty() ? std::string("-") : l.id;
  if (id.size() < 3U) id.append(3U - id.size(), ' ');
  s += id + " ";
  std::string fn = l.function;
  if (fn.size() < 9U) fn.append(9U - fn.size(), ' ');
  s += fn + " ";
  if (l.node >= 0) s += "node " + std::to_string(l.node) + ": ";
  s += l.text;
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

std::string render_json(const decoded_line &l) {
  json_object o;
  if (l.line_no != 0U) o.unum("line", l.line_no);
  if (l.time.known()) o.str("time", time_text(l.time));
  if (!l.iface.empty()) o.str("iface", l.iface.view());
  if (!l.id.empty()) o.str("id", l.id);
  o.str("function", l.function);
  if (l.node >= 0) o.num("node", l.node);
  std::string out = o.text();
  if (!l.json.empty()) {
    out.pop_back();
    out += "," + l.json.text().substr(1);
  }
  out.pop_back();
  out += "," + json_string("text").append(":") + json_string(l.text) + "}";
  return out;
}

can_decoder::can_decoder(std::map<std::uint8_t, node_dictionary> dicts,
                         std::map<std::uint8_t, device_family> families, options o)
    : dicts_(std::move(dicts)), families_(std::move(families)), options_(o) {
  std::vector<std::uint8_t> given;
  for (const auto &[n, d] : dicts_) {
    if (n != 0U) given.push_back(n);
  }
  for (const std::uint8_t n : given) (void)node({"", n}); // their PDOs are known from the start
}

can_decoder::node_state &can_decoder::node(const node_key &key) {
  auto it = nodes_.find(key);
  if (it != nodes_.end()) return it->second;
  const std::uint8_t n = key.node;
  node_state &s = nodes_[key];
  pdo_dirty_ = true;
  auto d = dicts_.find(n);
  if (d == dicts_.end()) d = dicts_.find(0);
  if (d != dicts_.end()) s.family = d->second.family();
  if (auto f = families_.find(n); f != families_.end()) s.family = f->second;
  if (d != dicts_.end()) {
    // node-ID-relative values resolved for n, the vendor units of its family applied
    s.dict = &built_.insert_or_assign(n, d->second.for_node(n, s.family)).first->second;
  }
  // PDO communication and mapping as configured in the dictionary (DCF values, else defaults);
  // without a dictionary: the predefined COB-IDs of PDO 1..4, mappings unknown
  for (std::size_t k = 0; k < 4U; ++k) {
    s.tpdo[k].cob_id = static_cast<std::uint32_t>(0x180U + 0x100U * k + n);
    s.rpdo[k].cob_id = static_cast<std::uint32_t>(0x200U + 0x100U * k + n);
  }
  if (s.dict != nullptr) {
    for (const object_desc &o : s.dict->objects()) {
      const auto p = pdo_param_of(o.d.index);
      // PDO parameters are UNSIGNED8/32: a value outside 32 bits is not one (never narrowed)
      if (!p || !o.configured || *o.configured < 0 || *o.configured > 0xFFFFFFFF) continue;
      pdo_config &c = p->rpdo ? s.rpdo[p->n] : s.tpdo[p->n];
      const auto v = static_cast<std::uint32_t>(*o.configured);
      if (!p->mapping && o.d.sub == 1) {
        c.cob_id = v;
      } else if (p->mapping && o.d.sub == 0) {
        c.count = static_cast<std::uint8_t>(v);
        c.mapping_known = true;
      } else if (p->mapping && o.d.sub <= 64) {
        c.map[o.d.sub - 1U] = v;
      }
    }
  }
  return s;
}

const object_desc *can_decoder::desc(const node_key &k, od::address a) {
  const node_state &s = node(k);
  return s.dict != nullptr ? s.dict->find(a) : nullptr;
}

void can_decoder::apply_write(const node_key &k, od::address a,
                              std::span<const std::uint8_t> bytes) {
  const auto p = pdo_param_of(a.index);
  if (!p || bytes.empty() || bytes.size() > 4U) return;
  node_state &s = node(k);
  pdo_dirty_ = true;
  pdo_config &c = p->rpdo ? s.rpdo[p->n] : s.tpdo[p->n];
  const auto v = static_cast<std::uint32_t>(
      load_unsigned(bytes, static_cast<unsigned>(bytes.size()), byte_order::little).value_or(0));
  if (!p->mapping && a.sub == 1) {
    c.cob_id = v;
  } else if (p->mapping && a.sub == 0) {
    c.count = static_cast<std::uint8_t>(v);
    c.mapping_known = true;
  } else if (p->mapping && a.sub >= 1 && a.sub <= 64) {
    c.map[a.sub - 1U] = v;
    c.mapping_known = true;
  }
}

void can_decoder::malformed(std::string_view text, const host::candump::line_error &e,
                            std::size_t line_no, std::vector<decoded_line> &out) {
  decoded_line l;
  l.function = "MALFORMED";
  l.line_no = line_no;
  l.problem = true;
  const std::string reason =
      *e.reason != '\0' ? std::string(e.reason) : std::string(to_string(e.code));
  const std::string shown = capped(text);
  l.text = "line " + std::to_string(line_no) + ": " + reason + " at column " +
           std::to_string(e.column + 1U) + ": " + json_string(shown);
  l.json.str("error", to_string(e.code))
      .str("reason", reason)
      .unum("column", e.column + 1U)
      .str("input", shown);
  out.push_back(std::move(l));
}

void can_decoder::note(std::string_view text, std::size_t line_no, std::vector<decoded_line> &out) {
  decoded_line l;
  l.function = "NOTE";
  l.line_no = line_no;
  l.text = "candump: " + capped(text);
  l.json.str("input", capped(text));
  out.push_back(std::move(l));
}

void can_decoder::feed(const host::frame_record &r, std::size_t line_no,
                       std::vector<decoded_line> &out) {
  decoded_line l;
  l.time = r.time;
  l.iface = r.iface;
  l.line_no = line_no;
  const std::string frame = host::candump::format_frame(r);
  l.id = frame.substr(0, frame.find('#'));
  if (r.error) {
    l.function = "CAN-ERROR";
    l.problem = true;
    const auto e = host::decode_error(r).value();
    l.text = host::describe(e);
    l.json.str("error", l.text)
        .boolean("bus_off", e.is_bus_off())
        .boolean("error_passive", e.is_error_passive());
    out.push_back(std::move(l));
    return;
  }
  if (r.extended) {
    l.function = "EXTENDED";
    l.text = "29-bit frame (not CANopen) " + hex_bytes(r.payload());
    l.json.str("data", hex_bytes(r.payload(), ""));
    out.push_back(std::move(l));
    return;
  }
  auto f = host::to_canopen(r).value();
  const auto info = canopen::classify(f.id).value();
  const auto data = f.payload();
  const node_key key{std::string(r.iface.view()), info.node};
  l.json.str("data", hex_bytes(data, ""));
  switch (info.fn) {
  case canopen::function::nmt: {
    l.function = "NMT";
    auto m = canopen::nmt::decode(f);
    if (!m) {
      l.problem = true;
      l.text = "malformed (" + std::string(to_string(m.error())) + "): " + hex_bytes(data);
      l.json.str("error", to_string(m.error()));
      break;
    }
    const std::string_view cmd = nmt_command_text(m.value().cs);
    l.text = std::string(cmd) + (m.value().node == 0 ? std::string(" all nodes")
                                                     : " node " + std::to_string(m.value().node));
    l.json.str("command", cmd).num("target", m.value().node);
    break;
  }
  case canopen::function::sync: {
    l.function = "SYNC";
    auto c = canopen::sync::decode(f);
    if (!c) {
      l.problem = true;
      l.text = "malformed (" + std::string(to_string(c.error())) + "): " + hex_bytes(data);
      l.json.str("error", to_string(c.error()));
    } else if (c.value()) {
      l.text = "counter " + std::to_string(*c.value());
      l.json.num("counter", *c.value());
    }
    break;
  }
  case canopen::function::time: {
    l.function = "TIME";
    auto t = canopen::time_stamp::decode(f);
    if (!t) {
      l.problem = true;
      l.text = "malformed (" + std::string(to_string(t.error())) + "): " + hex_bytes(data);
      l.json.str("error", to_string(t.error()));
    } else {
      // a TIME_OF_DAY value: the date and time as od's value text writes them
      od::descriptor time_of_day{};
      time_of_day.type = od::data_type::time_of_day;
      const auto date = host::format_value(time_of_day, data).value();
      const auto ms = t.value().ms;
      l.text = date + " (day " + std::to_string(t.value().days) + " after 1984-01-01, " +
               std::to_string(ms) + " ms after midnight)";
      l.json.str("date", date).unum("ms", ms).unum("days", t.value().days);
    }
    break;
  }
  case canopen::function::emcy: {
    l.function = "EMCY";
    l.node = info.node;
    auto e = canopen::emcy::decode(f);
    if (!e) {
      l.problem = true;
      l.text = "malformed (" + std::string(to_string(e.error())) + "): " + hex_bytes(data);
      l.json.str("error", to_string(e.error()));
      break;
    }
    const auto &m = e.value().m;
    const node_state &s = node(key);
    std::string what;
    if (s.family == device_family::dpq) what = std::string(dpq::describe_emcy(m.error_code));
    if (what.empty()) what = std::string(emcy_code_text(m.error_code));
    if (what.empty() && s.family != device_family::dpq) {
      // a drive's error codes: CiA 402's table, the XENAX's own numbers (FF01h..FF63h)
      what = std::string(ds402::describe_error_code(m.error_code));
      if (what.empty() && s.family == device_family::xenax) {
        if (auto n = xenax::decode_error_code(m.error_code); n && n.value() != 0U) {
          const std::string_view t = xenax::error_text(n.value());
          what = "XENAX error " + std::to_string(n.value()) +
                 (t.empty() ? std::string(" (text in 5020h TES)") : ": " + std::string(t));
        }
      }
    }
    const std::string cls(canopen::emcy::to_string(canopen::emcy::classify(m.error_code)));
    char code[8];
    std::snprintf(code, sizeof code, "%04Xh", static_cast<unsigned>(m.error_code));
    const bool no_error =
        canopen::emcy::classify(m.error_code) == canopen::emcy::error_class::no_error;
    l.text = std::string(code) + " " +
             (what.empty() ? cls : (no_error ? what : what + " (" + cls + ")"));
    char reg[8];
    std::snprintf(reg, sizeof reg, "%02Xh", static_cast<unsigned>(m.error_register));
    l.text += ", error register " + std::string(reg);
    if (m.error_register != 0U) l.text += " (" + register_text(m.error_register) + ")";
    bool manufacturer = false;
    for (const auto b : m.manufacturer) manufacturer = manufacturer || b != 0U;
    if (manufacturer) l.text += ", manufacturer data " + hex_bytes(m.manufacturer);
    l.json.unum("code", m.error_code).str("class", cls).unum("register", m.error_register);
    if (!what.empty()) l.json.str("meaning", what);
    l.json.str("manufacturer", hex_bytes(m.manufacturer, ""));
    l.problem = m.error_code != 0U;
    break;
  }
  case canopen::function::sdo_tx:
  case canopen::function::sdo_rx:
    on_sdo(r, key, info.fn == canopen::function::sdo_rx, std::move(l), out);
    return;
  case canopen::function::nmt_error: {
    l.node = info.node;
    node_state &s = node(key);
    if (f.rtr) {
      l.function = "GUARD";
      l.text = "node guarding request";
      s.guarded = true;
      break;
    }
    if (f.dlc != 1U) {
      l.function = "HEARTBEAT";
      l.problem = true;
      l.text = "malformed (bad length, DLC " + std::to_string(f.dlc) + "): " + hex_bytes(data);
      l.json.str("error", "bad length");
      break;
    }
    const std::uint8_t b = f.data[0];
    const std::string_view st = nmt_state_text(static_cast<std::uint8_t>(b & 0x7FU));
    if (b == 0U) {
      l.function = "BOOT-UP";
      l.text = "boot-up";
      l.json.str("state", "boot-up");
      break;
    }
    if ((b & 0x80U) != 0U || s.guarded) {
      // a node guarding response: toggle bit 7
      l.function = "GUARD";
      const std::uint8_t t = static_cast<std::uint8_t>(b >> 7U);
      l.text =
          "guarding response: " + (st.empty() ? std::string("unknown state") : std::string(st)) +
          ", toggle " + std::to_string(t);
      if (s.last_toggle != 2 && s.last_toggle == t) {
        l.text += " (toggle did not alternate)";
        l.problem = true;
      }
      s.last_toggle = t;
      l.json.str("state", st).num("toggle", t);
      break;
    }
    l.function = "HEARTBEAT";
    if (st.empty()) {
      l.problem = true;
      l.text = "unknown state " + hex(b, 2);
      l.json.str("error", "unknown state");
    } else {
      l.text = std::string(st);
      l.json.str("state", st);
    }
    break;
  }
  default:
    if (on_pdo(r, l, out)) return;
    if (f.id == canopen::lss::master_id || f.id == canopen::lss::slave_id) {
      on_lss(r, std::move(l), out);
      return;
    }
    if (info.fn == canopen::function::unassigned) {
      l.function = "FRAME";
      l.text = f.rtr ? "remote frame, DLC " + std::to_string(f.dlc) : hex_bytes(data);
    } else {
      l.function = std::string(canopen::to_string(info.fn));
      l.node = info.node;
      l.text =
          f.rtr ? "remote request" : (data.empty() ? std::string("(no data)") : hex_bytes(data));
      if (!f.rtr) l.text += " (mapping unknown)";
    }
    break;
  }
  out.push_back(std::move(l));
}

void can_decoder::on_lss(const host::frame_record &r, decoded_line l,
                         std::vector<decoded_line> &out) {
  namespace lss = canopen::lss;
  l.function = "LSS";
  const auto f = host::to_canopen(r).value();
  auto m = lss::decode(f);
  const char *side = f.id == lss::master_id ? "master" : "slave";
  if (!m) {
    l.problem = true;
    l.text = std::string(side) + ": malformed (" + std::string(to_string(m.error())) +
             "): " + hex_bytes(f.payload());
    l.json.str("error", to_string(m.error()));
    out.push_back(std::move(l));
    return;
  }
  const lss::message &x = m.value();
  std::string text = std::string(side) + ": " + std::string(lss::to_string(x.cs));
  l.json.str("from", side).str("service", lss::to_string(x.cs));
  const auto code = static_cast<std::uint8_t>(x.cs);
  if (x.from_master) {
    switch (x.cs) {
    case lss::command::switch_global:
      text += x.b1 == 0U   ? ": waiting"
              : x.b1 == 1U ? ": configuration"
                           : ": mode " + std::to_string(x.b1) + " (reserved)";
      l.json.unum("mode", x.b1);
      break;
    case lss::command::configure_node_id:
      text += " " + (x.b1 == 0xFFU ? std::string("FFh (unconfigured)") : std::to_string(x.b1));
      l.json.unum("node_id", x.b1);
      break;
    case lss::command::configure_bit_timing: {
      text += ": table " + std::to_string(x.b1) + ", index " + std::to_string(x.b2);
      const auto kbit = lss::standard_bit_rate(x.b2);
      if (x.b1 == 0U && kbit == 0xFFFFU) text += " (automatic bit rate detection)";
      if (x.b1 == 0U && kbit != 0U && kbit != 0xFFFFU) {
        text += " (" + std::to_string(kbit) + " kbit/s)";
      }
      l.json.unum("table", x.b1).unum("index", x.b2);
      break;
    }
    case lss::command::activate_bit_timing:
      text += " after " + std::to_string(x.value) + " ms";
      l.json.unum("delay_ms", x.value);
      break;
    case lss::command::fastscan:
      text += ": IDNumber " + hex(x.value, 8) + ", " +
              (x.bit_checked == 0x80U ? std::string("reset")
                                      : "bit checked " + std::to_string(x.bit_checked)) +
              ", LSS sub " + std::to_string(x.lss_sub) + ", next " + std::to_string(x.lss_next);
      l.json.unum("id_number", x.value)
          .unum("bit_checked", x.bit_checked)
          .unum("lss_sub", x.lss_sub)
          .unum("lss_next", x.lss_next);
      break;
    default:
      if (code >= 0x40U && code <= 0x4BU) {
        text += " " + hex(x.value, 8);
        l.json.unum("value", x.value);
      }
      break;
    }
  } else {
    switch (x.cs) {
    case lss::command::configure_node_id:
    case lss::command::configure_bit_timing:
    case lss::command::store_configuration:
      text += x.b1 == 0U      ? std::string(": ok")
              : x.b1 == 0xFFU ? ": manufacturer error " + std::to_string(x.b2)
                              : ": error " + std::to_string(x.b1);
      if (x.b1 != 0U) l.problem = true;
      l.json.unum("error", x.b1);
      if (x.b1 == 0xFFU) l.json.unum("manufacturer_error", x.b2);
      break;
    case lss::command::inquire_node_id:
      text += " = " + std::to_string(x.b1);
      l.json.unum("node_id", x.b1);
      break;
    case lss::command::inquire_vendor:
    case lss::command::inquire_product:
    case lss::command::inquire_revision:
    case lss::command::inquire_serial:
      text += " = " + hex(x.value, 8);
      l.json.unum("value", x.value);
      break;
    default: break;
    }
  }
  l.text = text;
  out.push_back(std::move(l));
}

bool can_decoder::on_pdo(const host::frame_record &r, decoded_line l,
                         std::vector<decoded_line> &out) {
  // the PDO whose valid COB-ID is this identifier, of any node seen or configured; a node
  // not seen yet has the predefined PDO 1..4 (or those of the dictionary for every node)
  if (r.extended || r.id > 0x7FFU) return false;
  const auto info = canopen::classify(static_cast<std::uint16_t>(r.id)).value();
  const std::string iface(r.iface.view());
  if (info.node != 0U) (void)node({iface, info.node});
  if (pdo_dirty_) {
    pdo_index_.clear();
    for (auto &[key, st] : nodes_) {
      for (int dir = 0; dir < 2; ++dir) {
        const auto &table = dir == 0 ? st.tpdo : st.rpdo;
        for (std::size_t k = 0; k < table.size(); ++k) {
          const std::uint32_t id = table[k].cob_id;
          if ((id & 0xA0000000U) != 0U) continue; // not valid, or 29-bit
          pdo_index_.emplace(std::pair{key.iface, id & 0x7FFU}, pdo_ref{key, dir, k});
        }
      }
    }
    pdo_dirty_ = false;
  }
  auto found = pdo_index_.find({iface, r.id});
  if (found == pdo_index_.end()) found = pdo_index_.find({std::string(), r.id});
  if (found == pdo_index_.end()) return false;
  {
    {
      const node_key key = found->second.node;
      const std::uint8_t n = key.node;
      const int dir = found->second.dir;
      const std::size_t k = found->second.k;
      node_state &s = node(key);
      {
        const pdo_config &c = (dir == 0 ? s.tpdo : s.rpdo)[k];
        l.function = std::string(dir == 0 ? "TPDO" : "RPDO") + std::to_string(k + 1U);
        l.node = n;
        if (r.rtr) {
          l.text = "remote request";
          out.push_back(std::move(l));
          return true;
        }
        const auto data = r.payload();
        if (!c.mapping_known || c.count == 0U) {
          l.text = (data.empty() ? std::string("(no data)") : hex_bytes(data)) +
                   (c.mapping_known ? " (nothing mapped)" : " (mapping unknown)");
          out.push_back(std::move(l));
          return true;
        }
        std::size_t offset = 0;
        std::string text;
        std::string values = "[";
        bool short_frame = false;
        std::size_t needed_bits = 0;
        for (std::size_t i = 0; i < c.count && i < 64U; ++i) {
          needed_bits += canopen::pdo::mapping_entry::from_u32(c.map[i]).bits;
        }
        for (std::size_t i = 0; i < c.count && i < 64U; ++i) {
          const auto e = canopen::pdo::mapping_entry::from_u32(c.map[i]);
          if (offset + e.bits > 8U * data.size()) {
            short_frame = true;
            break;
          }
          const auto raw = canopen::pdo::unpack(data, offset, e.bits).value_or(0);
          offset += e.bits;
          if (e.index >= 1U && e.index <= 7U) continue; // dummy entry
          std::array<std::uint8_t, 8> bytes{};
          for (std::size_t b = 0; b < 8U; ++b)
            bytes[b] = static_cast<std::uint8_t>(raw >> (8U * b));
          const od::address a{e.index, e.sub};
          const object_desc *d = desc(key, a);
          const std::size_t nbytes = (e.bits + 7U) / 8U;
          auto v = format_value(d, a, std::span<const std::uint8_t>(bytes.data(), nbytes), s.family,
                                s.values);
          if (!text.empty()) text += ", ";
          text += (d != nullptr ? d->name : address_text(a)) + " = " + v.text;
          json_object item;
          item.unum("index", a.index).unum("sub", a.sub);
          if (d != nullptr) item.str("name", d->name);
          std::string obj = item.text();
          if (!v.json.empty()) {
            obj.pop_back();
            obj += "," + v.json.text().substr(1);
          }
          if (values.size() > 1U) values += ",";
          values += obj;
        }
        values += "]";
        if (short_frame) {
          text += std::string(text.empty() ? "" : ", ") + "frame too short for the mapping (" +
                  std::to_string(data.size()) + " of " + std::to_string((needed_bits + 7U) / 8U) +
                  " bytes)";
          l.json.str("error", "too short");
          l.problem = true;
        }
        l.text = text;
        l.json.raw("values", values);
        out.push_back(std::move(l));
        return true;
      }
    }
  }
  return false;
}

void can_decoder::on_sdo(const host::frame_record &r, const node_key &key, bool to_server,
                         decoded_line l, std::vector<decoded_line> &out) {
  l.function = "SDO";
  l.node = key.node;
  sdo_track &t = sdo_[key];
  t.last_time = r.time;
  t.iface = r.iface;
  const auto data = r.payload();
  const char *side = to_server ? "client" : "server";
  if (r.rtr || data.size() != 8U) {
    l.problem = true;
    l.text = std::string(side) + ": malformed frame (" +
             (r.rtr ? std::string("remote frame") : "DLC " + std::to_string(data.size())) +
             ", SDO frames have 8 bytes): " + hex_bytes(data);
    l.json.str("error", "bad length");
    out.push_back(std::move(l));
    return;
  }
  sdo::payload p{};
  for (std::size_t i = 0; i < 8U; ++i) p[i] = data[i];
  const bool segment_phase = t.in_burst && ((t.k == sdo_track::kind::block_download && to_server) ||
                                            (t.k == sdo_track::kind::block_upload && !to_server));
  auto frame_line = [&](std::string what) {
    if (!options_.sdo_frames) return;
    decoded_line f = l;
    f.function = "SDO-FRAME";
    f.text = std::string(side) + ": " + what;
    out.push_back(std::move(f));
  };
  if (segment_phase) {
    const std::uint8_t seq = p[0] & 0x7FU;
    const bool last = (p[0] & 0x80U) != 0U;
    frame_line("block segment " + std::to_string(seq) + (last ? " (last)" : ""));
    if (seq == t.expected_seq && seq != 0U) {
      std::array<std::uint8_t, 7> seg{};
      for (std::size_t i = 0; i < 7U; ++i) seg[i] = p[1U + i];
      t.burst.push_back(seg);
      if (last) t.burst_last = static_cast<int>(t.burst.size()) - 1;
      ++t.expected_seq;
    } else if (t.problem.find("block segments out of sequence") == std::string::npos) {
      t.problem += std::string(t.problem.empty() ? "" : ", ") + "block segments out of sequence";
    }
    return;
  }
  auto m = sdo::decode(p, to_server ? sdo::direction::to_server : sdo::direction::to_client);
  if (!m) {
    l.problem = true;
    l.text =
        std::string(side) + ": unknown command specifier " + hex(p[0], 2) + ": " + hex_bytes(data);
    l.json.str("error", to_string(m.error()));
    out.push_back(std::move(l));
    if (t.k != sdo_track::kind::none) t.problem += "unknown command specifier";
    return;
  }
  const sdo::message &msg = m.value();
  frame_line(std::string(message_name(msg.type)) +
             (msg.type == sdo::message_type::initiate_download_request ||
                      msg.type == sdo::message_type::initiate_upload_request ||
                      msg.type == sdo::message_type::block_download_initiate ||
                      msg.type == sdo::message_type::block_upload_initiate
                  ? " " + address_text(msg.address)
                  : std::string()));
  using K = sdo_track::kind;
  auto start = [&](K k) {
    if (t.k != K::none) {
      // a transfer that never finished: said once, then replaced (as servers do)
      decoded_line gone = l;
      gone.problem = true;
      gone.text = std::string(t.k == K::download || t.k == K::block_download ? "write " : "read ") +
                  address_text(t.a) + ": transfer interrupted by a new request";
      gone.json.str("error", "interrupted");
      out.push_back(std::move(gone));
    }
    t = sdo_track{};
    t.k = k;
    t.a = msg.address;
    t.last_time = l.time;
    t.iface = l.iface;
  };
  auto unexpected = [&](std::string_view what) {
    decoded_line u = l;
    u.problem = true;
    u.text = std::string(side) + ": " + std::string(what) + " outside a transfer";
    u.json.str("error", "unexpected frame");
    out.push_back(std::move(u));
  };
  auto toggle_check = [&](bool toggle) {
    if (toggle != t.toggle && t.problem.find("toggle") == std::string::npos) {
      t.problem += std::string(t.problem.empty() ? "" : ", ") +
                   "toggle bit did not alternate at segment " + std::to_string(t.segments + 1U);
    }
  };
  auto commit = [&](std::uint8_t ackseq) {
    const std::size_t n_ok = ackseq <= t.burst.size() ? ackseq : t.burst.size();
    for (std::size_t i = 0; i < n_ok; ++i) {
      t.data.insert(t.data.end(), t.burst[i].begin(), t.burst[i].end());
    }
    t.segments += n_ok;
    if (t.burst_last >= 0 && static_cast<std::size_t>(t.burst_last) < n_ok) {
      t.final_committed = true;
    }
    t.burst.clear();
    t.burst_last = -1;
    t.expected_seq = 1;
    t.in_burst = !t.final_committed;
  };
  switch (msg.type) {
  case sdo::message_type::abort:
    if (t.k == K::none) t.a = msg.address;
    l.text.clear();
    t.abort = msg.abort;
    t.aborted_by = side;
    sdo_done(t, key, l, true);
    out.push_back(std::move(l));
    t = sdo_track{};
    return;
  case sdo::message_type::initiate_download_request:
    start(K::download);
    t.expedited = msg.expedited;
    t.size_indicated = msg.size_indicated;
    t.size = msg.size;
    if (msg.expedited) {
      const auto b = msg.value_bytes();
      t.data.assign(b.begin(), b.begin() + msg.size);
    }
    return;
  case sdo::message_type::download_segment_request:
    if (t.k != K::download || t.expedited) return unexpected("download segment");
    toggle_check(msg.toggle);
    t.toggle = !msg.toggle;
    t.data.insert(t.data.end(), msg.bytes().begin(), msg.bytes().end());
    ++t.segments;
    t.last_sent = msg.last;
    return;
  case sdo::message_type::initiate_download_response:
    if (t.k != K::download || t.a != msg.address) return unexpected("download response");
    if (t.expedited) break;
    t.toggle = false;
    return;
  case sdo::message_type::download_segment_response:
    if (t.k != K::download) return unexpected("download segment response");
    if (msg.toggle == t.toggle && t.problem.find("toggle") == std::string::npos) {
      t.problem += std::string(t.problem.empty() ? "" : ", ") +
                   "server answered with the wrong toggle at segment " + std::to_string(t.segments);
    }
    if (!t.last_sent) return;
    break;
  case sdo::message_type::initiate_upload_request: start(K::upload); return;
  case sdo::message_type::initiate_upload_response:
    if ((t.k != K::upload && t.k != K::block_upload) || t.a != msg.address) {
      return unexpected("upload response");
    }
    t.k = K::upload; // also the protocol switch of a block upload
    t.expedited = msg.expedited;
    t.size_indicated = msg.size_indicated;
    t.size = msg.size;
    if (msg.expedited) {
      const auto b = msg.value_bytes();
      t.data.assign(b.begin(), b.begin() + msg.size);
      break;
    }
    t.toggle = false;
    return;
  case sdo::message_type::upload_segment_request:
    if (t.k != K::upload) return unexpected("upload segment request");
    toggle_check(msg.toggle);
    return;
  case sdo::message_type::upload_segment_response:
    if (t.k != K::upload) return unexpected("upload segment");
    toggle_check(msg.toggle);
    t.toggle = !msg.toggle;
    t.data.insert(t.data.end(), msg.bytes().begin(), msg.bytes().end());
    ++t.segments;
    if (!msg.last) return;
    break;
  case sdo::message_type::block_download_initiate:
    start(K::block_download);
    t.crc = msg.crc;
    t.size_indicated = msg.size_indicated;
    t.size = msg.size;
    return;
  case sdo::message_type::block_download_initiate_response:
    if (t.k != K::block_download) return unexpected("block download response");
    t.crc = t.crc && msg.crc;
    t.in_burst = true;
    t.expected_seq = 1;
    return;
  case sdo::message_type::block_upload_initiate:
    start(K::block_upload);
    t.crc = msg.crc;
    return;
  case sdo::message_type::block_upload_initiate_response:
    if (t.k != K::block_upload) return unexpected("block upload response");
    t.crc = t.crc && msg.crc;
    t.size_indicated = msg.size_indicated;
    t.size = msg.size;
    return;
  case sdo::message_type::block_upload_start:
    if (t.k != K::block_upload) return unexpected("block upload start");
    t.in_burst = true;
    t.expected_seq = 1;
    return;
  case sdo::message_type::block_ack:
    if (t.k != K::block_download && t.k != K::block_upload) return unexpected("block acknowledge");
    commit(msg.sequence);
    return;
  case sdo::message_type::block_end:
    if (t.k != K::block_download && t.k != K::block_upload) return unexpected("block end");
    t.unused = msg.unused;
    t.checksum = msg.checksum;
    t.end_seen = true;
    return;
  case sdo::message_type::block_end_response:
    if ((t.k != K::block_download && t.k != K::block_upload) || !t.end_seen) {
      return unexpected("block end response");
    }
    if (t.unused <= t.data.size()) t.data.resize(t.data.size() - t.unused);
    if (t.crc && crc::ccitt16(t.data) != t.checksum) {
      t.problem += std::string(t.problem.empty() ? "" : ", ") + "CRC mismatch";
    }
    break;
  case sdo::message_type::block_segment: return;
  }
  // a transfer ended
  sdo_done(t, key, l, false);
  out.push_back(std::move(l));
  t = sdo_track{};
}

/// The bytes of an expedited transfer whose size the frame did not indicate (command 0x22,
/// upload answer 0x42): CiA 301 lets the object's type decide, so a 2-byte object comes as the
/// first 2 of the 4 bytes. Returns the note when the bytes beyond it are not zero.
std::string can_decoder::trim_unindicated(sdo_track &t, const object_desc *d) {
  if (!t.expedited || t.size_indicated || t.data.size() != 4U) return {};
  std::uint32_t width = 0;
  std::string type;
  if (d != nullptr) {
    width = od::fixed_size(d->d.type);
    type = std::string(od::name(d->d.type));
  } else if (t.a.sub == 0 && (t.a.index == 0x6040 || t.a.index == 0x6041)) {
    width = 2; // CiA 402 control- and statusword, known without a dictionary
    type = "UNSIGNED16";
  } else if (t.a.sub == 0 && (t.a.index == 0x6060 || t.a.index == 0x6061)) {
    width = 1;
    type = "INTEGER8";
  }
  if (width == 0U || width >= 4U) return {};
  const std::vector<std::uint8_t> beyond(t.data.begin() + width, t.data.end());
  t.data.resize(width);
  for (const auto b : beyond) {
    if (b != 0U) {
      return "size not indicated; the bytes beyond the " + std::to_string(width) + " of " + type +
             " are not zero: " + hex_bytes(beyond);
    }
  }
  return {};
}

void can_decoder::sdo_done(sdo_track &t, const node_key &key, decoded_line &l, bool aborted) {
  using K = sdo_track::kind;
  const bool write = t.k == K::download || t.k == K::block_download;
  const bool block = t.k == K::block_download || t.k == K::block_upload;
  const object_desc *d = desc(key, t.a);
  std::string head =
      t.k == K::none ? std::string("transfer of ") : std::string(write ? "write " : "read ");
  head += address_text(t.a);
  if (d != nullptr) head += " " + d->name;
  json_object j;
  j.str("service", t.k == K::none ? "abort" : (write ? "write" : "read"))
      .unum("index", t.a.index)
      .unum("sub", t.a.sub);
  if (d != nullptr) j.str("name", d->name);
  if (aborted) {
    l.problem = true;
    l.text = head + ": ABORT by " + t.aborted_by + ": " + abort_text(t.abort) +
             (t.problem.empty() ? "" : " (" + t.problem + ")");
    j.str("abort_code", hex(static_cast<std::uint32_t>(t.abort), 8).substr(2))
        .str("abort_text", sdo::to_string(t.abort))
        .str("aborted_by", t.aborted_by);
    if (!t.problem.empty()) j.str("error", t.problem);
    l.json.raw("sdo", j.text());
    return;
  }
  node_state &s = node(key);
  const std::string unindicated = trim_unindicated(t, d);
  auto v = format_value(d, t.a, t.data, s.family, s.values);
  l.text = head + " = " + v.text;
  if (!t.expedited) {
    l.text += " [" + std::string(block ? (t.crc ? "block, CRC" : "block") : "segmented") + ", " +
              std::to_string(t.data.size()) + " bytes]";
  }
  if (t.size_indicated && !t.expedited && t.size != t.data.size()) {
    t.problem += std::string(t.problem.empty() ? "" : ", ") + "announced " +
                 std::to_string(t.size) + " bytes";
  }
  if (!unindicated.empty()) {
    t.problem += std::string(t.problem.empty() ? "" : ", ") + unindicated;
  }
  if (!t.problem.empty()) {
    l.text += " (" + t.problem + ")";
    l.problem = true;
  }
  l.problem = l.problem || v.problem;
  std::string text = j.text();
  if (!v.json.empty()) {
    text.pop_back();
    text += "," + v.json.text().substr(1);
  }
  json_object tail;
  tail.str("transfer", t.expedited ? "expedited" : (block ? "block" : "segmented"))
      .unum("size", t.data.size());
  if (t.expedited && !t.size_indicated) tail.boolean("size_indicated", false);
  if (!t.problem.empty()) tail.str("error", t.problem);
  text.pop_back();
  text += "," + tail.text().substr(1);
  l.json = json_object{};
  l.json.raw("sdo", text);
  if (write) apply_write(key, t.a, t.data);
}

void can_decoder::finish(std::vector<decoded_line> &out) {
  for (auto &[key, t] : sdo_) {
    if (t.k == sdo_track::kind::none) continue;
    decoded_line l;
    l.time = t.last_time;
    l.iface = t.iface;
    l.function = "SDO";
    l.node = key.node;
    l.problem = true;
    const bool write = t.k == sdo_track::kind::download || t.k == sdo_track::kind::block_download;
    l.text = std::string(write ? "write " : "read ") + address_text(t.a) +
             ": incomplete, the log ended (" + std::to_string(t.data.size()) + " bytes seen)";
    json_object j;
    j.str("service", write ? "write" : "read")
        .unum("index", t.a.index)
        .unum("sub", t.a.sub)
        .str("error", "incomplete")
        .unum("size", t.data.size());
    l.json.raw("sdo", j.text());
    out.push_back(std::move(l));
    t = sdo_track{};
  }
}

} // namespace fieldcodec::cli
