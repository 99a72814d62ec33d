// fieldcodec CLI — values as a person reads them.
#include "values.hpp"

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/ieee754.hpp>
#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/ds402/controlword.hpp>
#include <fieldcodec/ds402/modes.hpp>
#include <fieldcodec/ds402/statusword.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/value.hpp>

#include "dpq_places.hpp"

#include <cstdio>

namespace fieldcodec::cli {

namespace {

bool is_drive(device_family f) {
  return f == device_family::ds402 || f == device_family::xenax || f == device_family::generic;
}

/// Integer types shown in hex: identifiers and bit fields of the communication area.
bool shows_hex(const od::entry &e) {
  if (e.index < 0x1000U || e.index > 0x1FFFU) return false;
  if (e.type != od::data_type::unsigned32 && e.type != od::data_type::unsigned64) return false;
  return e.index != 0x1006 && e.index != 0x1007 && e.index != 0x100C && e.index != 0x1016 &&
         e.index != 0x1017;
}

std::string statusword_text(std::uint16_t sw) {
  std::string s;
  auto st = ds402::decode_state(sw);
  s = st ? std::string(ds402::to_string(st.value())) : std::string("no CiA 402 state");
  const auto f = ds402::decode_flags(sw);
  if (f.warning) s += ", warning";
  if (f.target_reached) s += ", target reached";
  if (f.internal_limit_active) s += ", internal limit active";
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

} // namespace

formatted_value format_value(const object_desc *d, od::address a,
                             std::span<const std::uint8_t> bytes, device_family family,
                             value_context &ctx) {
  const bool drive = is_drive(family);
  if (d == nullptr) {
    formatted_value v = raw_only(bytes);
    // CiA 402 objects are known without a dictionary
    if (a.index == 0x6040 && a.sub == 0 && bytes.size() == 2U && drive) {
      const auto cw = static_cast<std::uint16_t>(bytes[0] | (bytes[1] << 8U));
      const auto c = ds402::decode_command(cw, ctx.previous_controlword);
      ctx.previous_controlword = cw;
      v.text = hex(cw, 4) + " (" + std::string(ds402::to_string(c)) + ")";
      v.json.str("command", ds402::to_string(c));
    } else if (a.index == 0x6041 && a.sub == 0 && bytes.size() == 2U && drive) {
      const auto sw = static_cast<std::uint16_t>(bytes[0] | (bytes[1] << 8U));
      v.text = hex(sw, 4) + " (" + statusword_text(sw) + ")";
      v.json.str("state", statusword_text(sw));
    }
    return v;
  }
  const od::entry &e = d->core;
  formatted_value v;
  if (od::is_byte_string(e.type)) {
    v.json.str("raw", hex_bytes(bytes, ""));
    if (e.type == od::data_type::visible_string) {
      auto t = od::decode_bytes(e, bytes);
      if (t) {
        const std::string s(t.value().begin(), t.value().end());
        v.text = json_string(s);
        v.json.str("value", s);
        return v;
      }
    }
    v.text = bytes.empty() ? std::string("(empty)") : hex_bytes(bytes);
    return v;
  }
  const std::uint32_t width = e.width();
  if (width != 0U && bytes.size() != width) {
    v = raw_only(bytes);
    v.text += " (" + std::to_string(bytes.size()) + " bytes, " + std::string(od::name(e.type)) +
              " has " + std::to_string(width) + ")";
    v.json.str("error", "bad length");
    return v;
  }
  auto n = od::decode(e, bytes, byte_order::little, od::limits::ignore);
  if (!n) {
    v = raw_only(bytes);
    v.text += " (" + std::string(to_string(n.error())) + ")";
    v.json.str("error", to_string(n.error()));
    return v;
  }
  const od::number num = n.value();
  if (od::is_real(e.type)) {
    const double x = num.to_double();
    v.text = real_text(x);
    v.json.real("value", x);
  } else if (e.type == od::data_type::boolean) {
    const bool b = num.to_uint64().value_or(0) != 0U;
    v.text = b ? "true" : "false";
    v.json.boolean("value", b);
  } else if (od::is_integer(e.type)) {
    const bool is_signed = od::is_signed_integer(e.type);
    const std::int64_t raw = is_signed ? num.to_int64().value_or(0)
                                       : static_cast<std::int64_t>(num.to_uint64().value_or(0));
    const std::uint64_t uraw = num.to_uint64().value_or(static_cast<std::uint64_t>(raw));
    if (e.index == 0x6040 && e.sub == 0 && drive && e.type == od::data_type::unsigned16) {
      const auto cw = static_cast<std::uint16_t>(uraw);
      const auto c = ds402::decode_command(cw, ctx.previous_controlword);
      ctx.previous_controlword = cw;
      v.text = hex(cw, 4) + " (" + std::string(ds402::to_string(c)) + ")";
      v.json.unum("value", cw).str("command", ds402::to_string(c));
    } else if (e.index == 0x6041 && e.sub == 0 && drive && e.type == od::data_type::unsigned16) {
      const auto sw = static_cast<std::uint16_t>(uraw);
      v.text = hex(sw, 4) + " (" + statusword_text(sw) + ")";
      v.json.unum("value", sw).str("state", statusword_text(sw));
    } else if ((e.index == 0x6060 || e.index == 0x6061) && e.sub == 0 && drive &&
               e.type == od::data_type::integer8) {
      auto m = ds402::decode_mode(static_cast<std::int8_t>(raw));
      v.text = std::to_string(raw) + " (" +
               (m ? std::string(ds402::to_string(m.value()))
                  : std::string(ds402::is_manufacturer_mode(static_cast<std::int8_t>(raw))
                                    ? "manufacturer-specific mode"
                                    : "reserved mode")) +
               ")";
      v.json.num("value", raw);
      if (m) v.json.str("mode", ds402::to_string(m.value()));
    } else if (d->scale) {
      // DPQ: EU = raw / scale + offset, exact, at the places that read back to the same raw
      const unsigned places = dpq_round_trip_places(*d->scale);
      auto eu = scaling::to_eu_decimal(raw, *d->scale, places);
      if (eu) {
        v.text = decimal_text(eu.value());
        if (!d->unit.empty()) v.text += " " + d->unit;
        v.text += " (raw " + std::to_string(raw) + ")";
        v.json.dec("value", eu.value()).num("raw", raw);
      } else {
        v.text = std::to_string(raw) +
                 " (raw, scaling failed: " + std::string(to_string(eu.error())) + ")";
        v.json.num("raw", raw);
      }
    } else if (d->factor) {
      const decimal eu{raw * d->factor->mantissa, d->factor->places};
      v.text = decimal_text(eu) + " " + d->unit + " (raw " + std::to_string(raw) + ")";
      v.json.dec("value", eu).num("raw", raw);
    } else if (shows_hex(e)) {
      v.text = hex(uraw, static_cast<int>(2U * width));
      v.json.unum("value", uraw);
      const bool mapping =
          (e.index >= 0x1600U && e.index <= 0x17FFU) || (e.index >= 0x1A00U && e.index <= 0x1BFFU);
      if (mapping && e.sub >= 1U && e.type == od::data_type::unsigned32 && uraw != 0U) {
        const od::address m{static_cast<std::uint16_t>(uraw >> 16U),
                            static_cast<std::uint8_t>(uraw >> 8U)};
        v.text += " (" + address_text(m) + ", " + std::to_string(uraw & 0xFFU) + " bits)";
        v.json.str("maps", address_text(m)).unum("bits", uraw & 0xFFU);
      }
    } else {
      v.text = is_signed ? std::to_string(raw) : std::to_string(uraw);
      if (!d->unit.empty()) v.text += " " + d->unit;
      if (is_signed) {
        v.json.num("value", raw);
      } else {
        v.json.unum("value", uraw);
      }
    }
  } else {
    // TIME_OF_DAY / TIME_DIFFERENCE
    const std::uint64_t t = num.to_uint64().value_or(0);
    v.text = std::to_string(t & 0x0FFFFFFFU) + " ms, " + std::to_string(t >> 32U) + " days";
    v.json.unum("ms", t & 0x0FFFFFFFU).unum("days", t >> 32U);
  }
  if (!d->unit.empty()) v.json.str("unit", d->unit);
  return v;
}

parsed_value parse_value(const object_desc *d, std::string_view type_hint, std::string_view text) {
  parsed_value out;
  od::entry e{};
  if (d != nullptr) {
    e = d->core;
  } else {
    struct hint {
      std::string_view name;
      od::data_type type;
    };
    static constexpr hint hints[] = {
        {"u8", od::data_type::unsigned8},       {"u16", od::data_type::unsigned16},
        {"u32", od::data_type::unsigned32},     {"u64", od::data_type::unsigned64},
        {"i8", od::data_type::integer8},        {"i16", od::data_type::integer16},
        {"i32", od::data_type::integer32},      {"i64", od::data_type::integer64},
        {"f32", od::data_type::real32},         {"f64", od::data_type::real64},
        {"str", od::data_type::visible_string}, {"hex", od::data_type::octet_string},
        {"bool", od::data_type::boolean}};
    bool found = false;
    for (const auto &h : hints) {
      if (h.name == type_hint) {
        e.type = h.type;
        found = true;
      }
    }
    if (!found) {
      out.error = type_hint.empty() ? "no dictionary entry: give the type with --type "
                                      "(u8 u16 u32 u64 i8 i16 i32 i64 f32 f64 bool str hex)"
                                    : "unknown type '" + std::string(type_hint) + "'";
      return out;
    }
  }
  if (e.type == od::data_type::visible_string) {
    out.bytes.assign(text.begin(), text.end());
    out.ok = true;
    return out;
  }
  if (od::is_byte_string(e.type)) {
    std::string digits;
    for (const char c : text) {
      if (c != ' ' && c != '.' && c != ':') digits += c;
    }
    if (digits.size() % 2U != 0U) {
      out.error = "hex bytes need two digits each: '" + std::string(text) + "'";
      return out;
    }
    for (std::size_t i = 0; i < digits.size(); i += 2U) {
      std::uint64_t b = 0;
      if (!parse_uint("0x" + digits.substr(i, 2), 0xFF, b)) {
        out.error = "not hex bytes: '" + std::string(text) + "'";
        return out;
      }
      out.bytes.push_back(static_cast<std::uint8_t>(b));
    }
    out.ok = true;
    return out;
  }
  od::number n{};
  if (e.type == od::data_type::boolean) {
    if (text == "true" || text == "1") {
      n = od::number{od::number_kind::unsigned_, 0, 1};
    } else if (text == "false" || text == "0") {
      n = od::number{od::number_kind::unsigned_, 0, 0};
    } else {
      out.error = "not a boolean: '" + std::string(text) + "'";
      return out;
    }
  } else if (text.size() > 2U && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
    std::uint64_t u = 0;
    if (!parse_uint(text, ~std::uint64_t{0}, u)) {
      out.error = "not a number: '" + std::string(text) + "'";
      return out;
    }
    n = od::number{od::number_kind::unsigned_, 0, u};
  } else {
    auto dec = parse_decimal(text);
    if (!dec) {
      out.error =
          "not a number: '" + std::string(text) + "' (" + std::string(to_string(dec.error())) + ")";
      return out;
    }
    if (d != nullptr && d->scale && od::is_integer(e.type)) {
      // an engineering value: to raw through the scale (rounded half away from zero)
      auto field = e.raw_field();
      auto raw = scaling::to_raw(dec.value(), *d->scale, field.value());
      if (!raw) {
        out.error = "'" + std::string(text) + "' does not fit " + std::string(od::name(e.type)) +
                    " after scaling (" + std::string(to_string(raw.error())) + ")";
        return out;
      }
      n = od::number{od::number_kind::signed_, 0, static_cast<std::uint64_t>(raw.value())};
    } else if (od::is_real(e.type)) {
      n = od::number{od::number_kind::decimal_, dec.value().places,
                     static_cast<std::uint64_t>(dec.value().mantissa)};
    } else {
      if (dec.value().places != 0U) {
        out.error = "'" + std::string(text) + "' is not an integer";
        return out;
      }
      n = od::number{od::number_kind::signed_, 0, static_cast<std::uint64_t>(dec.value().mantissa)};
    }
  }
  std::array<std::uint8_t, 8> buf{};
  od::entry unchecked = e;
  unchecked.flags = static_cast<std::uint16_t>(e.flags & ~(od::flag::has_low | od::flag::has_high));
  auto w = od::encode(unchecked, n, buf);
  if (!w) {
    out.error = "'" + std::string(text) + "' cannot be a " + std::string(od::name(e.type)) + " (" +
                std::string(to_string(w.error())) + ")";
    return out;
  }
  out.bytes.assign(buf.begin(), buf.begin() + static_cast<std::ptrdiff_t>(w.value()));
  out.ok = true;
  return out;
}

} // namespace fieldcodec::cli
