// fieldcodec CLI — values as a person reads and types them, through od's value path.
#include "values.hpp"

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/ds402/controlword.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/host/value_text.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/value.hpp>

namespace fieldcodec::cli {

namespace {

bool is_drive(device_family f) {
  return f == device_family::ds402 || f == device_family::xenax || f == device_family::generic;
}

/// Integers shown in hex: identifiers and bit fields of the communication area (not its times
/// and counts), the CiA 402 control- and statusword and error code.
bool shows_hex(const od::entry &e) {
  if (e.type == od::data_type::unsigned16 && e.sub == 0 &&
      (e.index == 0x6040 || e.index == 0x6041 || e.index == 0x603F)) {
    return true;
  }
  if (e.index < 0x1000U || e.index > 0x1FFFU) return false;
  if (e.type != od::data_type::unsigned32 && e.type != od::data_type::unsigned64) return false;
  return e.index != 0x1006 && e.index != 0x1007 && e.index != 0x100C && e.index != 0x1016 &&
         e.index != 0x1017;
}

std::string statusword_text(std::uint16_t sw, const value_context &ctx) {
  std::string s;
  auto st = ds402::decode_state(sw);
  s = st ? std::string(ds402::to_string(st.value())) : std::string("no CiA 402 state");
  const auto f = ds402::decode_flags(sw);
  if (f.warning) s += ", warning";
  if (f.target_reached) s += ", target reached";
  if (f.internal_limit_active) s += ", internal limit active";
  const auto names = ctx.mode ? ds402::mode_bits(*ctx.mode) : ds402::mode_bit_names{};
  if (f.bit12) s += names.bit12.empty() ? std::string(", bit 12") : ", " + std::string(names.bit12);
  if (f.bit13) s += names.bit13.empty() ? std::string(", bit 13") : ", " + std::string(names.bit13);
  return s;
}

formatted_value raw_only(std::span<const std::uint8_t> bytes) {
  formatted_value v;
  if (bytes.size() >= 1U && bytes.size() <= 4U) {
    const auto u = load_unsigned(bytes, static_cast<unsigned>(bytes.size()), byte_order::little);
    v.text = hex(u.value_or(0), static_cast<int>(2U * bytes.size())) + " (" +
             std::to_string(u.value_or(0)) + ")";
    v.json.unum("value", u.value_or(0));
  } else {
    v.text = bytes.empty() ? std::string("(no data)") : hex_bytes(bytes);
  }
  v.json.str("raw", hex_bytes(bytes, ""));
  return v;
}

std::string mode_text(std::int8_t raw) {
  auto m = ds402::decode_mode(raw);
  if (m) return std::string(ds402::to_string(m.value()));
  return ds402::is_manufacturer_mode(raw) ? "manufacturer-specific mode" : "reserved mode";
}

/// The CiA 402 words and modes, known without a dictionary; true when `a` is one of them.
bool drive_words(od::address a, std::span<const std::uint8_t> bytes, value_context &ctx,
                 formatted_value &v) {
  if (a.sub != 0) return false;
  if ((a.index == 0x6040 || a.index == 0x6041) && bytes.size() == 2U) {
    const auto w = static_cast<std::uint16_t>(bytes[0] | (bytes[1] << 8U));
    if (a.index == 0x6040) {
      const auto c = ds402::decode_command(w, ctx.previous_controlword);
      ctx.previous_controlword = w;
      v.text += " (" + std::string(ds402::to_string(c)) + ")";
      v.json.str("command", ds402::to_string(c));
    } else {
      v.text += " (" + statusword_text(w, ctx) + ")";
      v.json.str("state", statusword_text(w, ctx));
    }
    return true;
  }
  if ((a.index == 0x6060 || a.index == 0x6061) && bytes.size() == 1U) {
    const auto m = static_cast<std::int8_t>(bytes[0]);
    ctx.mode = m; // the mode requested (6060h) or shown (6061h): names statusword bits 12, 13
    v.text += " (" + mode_text(m) + ")";
    if (auto k = ds402::decode_mode(m)) v.json.str("mode", ds402::to_string(k.value()));
    return true;
  }
  return false;
}

} // namespace

od::value_options display_options(const od::descriptor &d, std::uint8_t node, bool raw) {
  od::value_options o;
  o.node = node;
  o.unit = raw ? od::value_unit::raw : od::value_unit::engineering;
  if (shows_hex(d)) o.integers = od::radix::hex;
  return o;
}

formatted_value format_value(const object_desc *d, od::address a,
                             std::span<const std::uint8_t> bytes, device_family family,
                             value_context &ctx, bool raw) {
  const bool drive = is_drive(family);
  if (d == nullptr) {
    formatted_value v = raw_only(bytes);
    if (drive && (a.index == 0x6040 || a.index == 0x6041) && bytes.size() == 2U) {
      v.text = hex(static_cast<std::uint16_t>(bytes[0] | (bytes[1] << 8U)), 4);
    }
    if (drive) (void)drive_words(a, bytes, ctx, v);
    return v;
  }
  const od::descriptor &e = d->d;
  const od::value_options o = display_options(e, 0, raw);
  formatted_value v;
  auto text = host::format_value(e, bytes, o);
  if (!text) {
    v = raw_only(bytes);
    v.problem = true;
    const std::uint32_t width = e.width();
    if (width != 0U && bytes.size() != width) {
      v.text += " (" + std::to_string(bytes.size()) + " bytes, " + std::string(od::name(e.type)) +
                " has " + std::to_string(width) + ")";
      v.json.str("error", "bad length");
    } else {
      v.text += " (" + std::string(to_string(text.error())) + ")";
      v.json.str("error", to_string(text.error()));
    }
    return v;
  }
  v.text = text.value();
  if (od::is_byte_string(e.type)) {
    v.json.str("raw", hex_bytes(bytes, ""));
    if (e.type == od::data_type::visible_string) {
      std::size_t n = bytes.size();
      while (n > 0U && bytes[n - 1U] == 0U) --n;
      v.json.str("value", std::string_view(reinterpret_cast<const char *>(bytes.data()), n));
    } else {
      v.json.str("value", v.text);
    }
    return v;
  }
  const auto n = od::decode_value(e, bytes, o).value(); // format_value decoded it already
  switch (n.kind) {
  case od::number_kind::decimal_:
    v.json.dec("value", decimal{static_cast<std::int64_t>(n.bits), n.places});
    break;
  case od::number_kind::signed_: v.json.num("value", static_cast<std::int64_t>(n.bits)); break;
  case od::number_kind::unsigned_:
    if (e.type == od::data_type::boolean) {
      v.json.boolean("value", n.bits != 0U);
    } else if (od::is_time(e.type)) {
      v.json.str("value", v.text);
    } else {
      v.json.unum("value", n.bits);
    }
    break;
  case od::number_kind::real: v.json.real("value", n.to_double()); break;
  case od::number_kind::none: break;
  }
  if (od::is_scaled(e) && !raw) {
    const auto r =
        od::decode(static_cast<const od::entry &>(e), bytes, byte_order::little, od::limits::ignore)
            .value();
    const std::string rt = r.kind == od::number_kind::signed_
                               ? std::to_string(static_cast<std::int64_t>(r.bits))
                               : std::to_string(r.bits);
    v.text += " (raw " + rt + ")";
    v.json.raw("raw", rt);
  }
  if (drive) {
    (void)drive_words(a, bytes, ctx, v);
  }
  const bool mapping =
      (e.index >= 0x1600U && e.index <= 0x17FFU) || (e.index >= 0x1A00U && e.index <= 0x1BFFU);
  if (mapping && e.sub >= 1U && e.type == od::data_type::unsigned32 && n.bits != 0U) {
    const od::address m{static_cast<std::uint16_t>(n.bits >> 16U),
                        static_cast<std::uint8_t>(n.bits >> 8U)};
    v.text += " (" + address_text(m) + ", " + std::to_string(n.bits & 0xFFU) + " bits)";
    v.json.str("maps", address_text(m)).unum("bits", n.bits & 0xFFU);
  }
  if (!e.info.unit.empty()) v.json.str("unit", e.info.unit.view());
  return v;
}

parsed_value parse_value(const object_desc &d, std::string_view text, std::uint8_t node, bool raw) {
  parsed_value out;
  const od::value_options o = display_options(d.d, node, raw);
  auto r = host::parse_value(d.d, text, o);
  if (!r) {
    out.error = "'" + std::string(text) + "': " + host::describe(r.error(), d.d, o);
    return out;
  }
  out.ok = true;
  out.bytes = std::move(r.value());
  return out;
}

std::optional<object_desc> type_entry(std::string_view hint, od::address a) {
  struct named {
    std::string_view name;
    od::data_type type;
  };
  static constexpr named hints[] = {
      {"u8", od::data_type::unsigned8},       {"u16", od::data_type::unsigned16},
      {"u32", od::data_type::unsigned32},     {"u64", od::data_type::unsigned64},
      {"i8", od::data_type::integer8},        {"i16", od::data_type::integer16},
      {"i32", od::data_type::integer32},      {"i64", od::data_type::integer64},
      {"f32", od::data_type::real32},         {"f64", od::data_type::real64},
      {"str", od::data_type::visible_string}, {"hex", od::data_type::octet_string},
      {"bool", od::data_type::boolean}};
  for (const auto &h : hints) {
    if (h.name != hint) continue;
    object_desc o;
    o.d.index = a.index;
    o.d.sub = a.sub;
    o.d.type = h.type;
    return o;
  }
  return std::nullopt;
}

} // namespace fieldcodec::cli
