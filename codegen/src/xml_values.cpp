// fieldcodec-gen — values of the XML device descriptions (xml_values.hpp).
#include "xml_values.hpp"

#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/core/decimal.hpp>

namespace fieldcodec::gen {

namespace {

struct slot {
  od::number entry::*number;
  bool entry::*nodeid;
  rare_text entry::*text; // nullptr: a limit
};

slot slot_of(value_role r) {
  switch (r) {
  case value_role::default_value:
    return {&entry::default_value, &entry::default_nodeid, &entry::default_text};
  case value_role::actual_value:
    return {&entry::parameter_value, &entry::parameter_nodeid, &entry::parameter_text};
  case value_role::low_limit: return {&entry::low, &entry::low_nodeid, nullptr};
  case value_role::high_limit: break;
  }
  return {&entry::high, &entry::high_nodeid, nullptr};
}

xml::position column_at(const xml_place &p, std::string_view whole, std::string_view part,
                        std::size_t pos) {
  xml::position at = p.at;
  if (part.data() >= whole.data() && part.data() <= whole.data() + whole.size()) {
    at.column += static_cast<int>(static_cast<std::size_t>(part.data() - whole.data()) + pos);
  }
  return at;
}

void error(const xml_place &p, xml::position at, const std::string &msg) {
  p.diag.error(p.file, at.line, at.column, msg + " in " + p.what);
}
void warning(const xml_place &p, xml::position at, const std::string &msg) {
  p.diag.warning(p.file, at.line, at.column, msg + " (" + p.what + ")");
}

bool integer_value(const xml_place &p, std::string_view whole, std::string_view v,
                   od::data_type type, od::number &out) {
  const int_parse n = parse_int(v, int_syntax::xml);
  if (!n.ok) {
    // a decimal fraction for an integer type: kept exactly, with a warning (as the EDS reader)
    if (auto d = parse_decimal(v); d && v.find('.') != std::string_view::npos) {
      warning(p, column_at(p, whole, v, 0), "expected an integer, got '" + std::string(v) + "'");
      out = od::decimal_number(d.value());
      return true;
    }
    error(p, column_at(p, whole, v, n.error_pos), n.error);
    return false;
  }
  out = integer_for_type(n.value, type);
  if ((od::is_integer(type) || type == od::data_type::boolean) && !fits(type, out)) {
    warning(p, column_at(p, whole, v, 0),
            "value '" + std::string(v) + "' does not fit " + std::string(od::name(type)));
  }
  return true;
}

} // namespace

bool read_xml_value(const xml_place &p, std::string_view text, entry &e, value_role role) {
  const slot s = slot_of(role);
  if (od::is_byte_string(e.type)) {
    if (s.text == nullptr) {
      if (!trim(text).empty()) {
        warning(p, p.at, "ignored: a " + std::string(od::name(e.type)) + " has no limits");
      }
      return true;
    }
    if (text.empty()) return true;
    if (e.type == od::data_type::visible_string) {
      e.*s.text = text;
      return true;
    }
    if (auto bytes = byte_string_value(e.type, text)) {
      e.*s.text = *bytes;
    } else {
      warning(p, p.at,
              "value '" + std::string(text) + "' ignored: " + std::string(od::name(e.type)) +
                  " values are written as hex digits, two per byte");
    }
    return true;
  }
  const std::string_view v = trim(text);
  if (v.empty()) return true;
  od::number &out = e.*s.number;
  bool &nodeid = e.*s.nodeid;
  nodeid = false;
  const nodeid_expr x = split_nodeid(v);
  if (x.present) {
    if (!x.ok) {
      error(p, column_at(p, text, v, 0),
            "expected '$NODEID+<number>' or '<number>+$NODEID', got '" + std::string(v) + "'");
      return false;
    }
    nodeid = true;
    if (!integer_value(p, text, x.operand.empty() ? std::string_view("0") : x.operand, e.type,
                       out)) {
      return false;
    }
    if (od::is_integer(e.type)) {
      for (const std::uint8_t node : {std::uint8_t{1}, std::uint8_t{127}}) {
        const auto at = plus_node(out, node);
        if (!at || !fits(e.type, *at)) {
          warning(p, column_at(p, text, v, 0),
                  "value '" + std::string(v) + "' does not fit " + std::string(od::name(e.type)) +
                      " for node-ID " + std::to_string(node));
          break;
        }
      }
    }
    return true;
  }
  if (e.type == od::data_type::boolean) {
    if (iequals(v, "true") || iequals(v, "false")) {
      out = od::signed_number(iequals(v, "true") ? 1 : 0); // as the EDS reader reads 1 and 0
      return true;
    }
    return integer_value(p, text, v, e.type, out);
  }
  if (od::is_real(e.type)) {
    const real_parse r = parse_real_value(v, e.type);
    if (!r.ok) {
      error(p, column_at(p, text, v, r.error_pos), r.error);
      return false;
    }
    out = od::real_number(r.value);
    return true;
  }
  return integer_value(p, text, v, e.type, out);
}

bool check_value_range(const xml_place &p, const entry &e) {
  if (od::is_byte_string(e.type)) return true;
  const auto lo = e.low.to_decimal();
  const auto hi = e.high.to_decimal();
  const bool plain_lo = e.low.has_value() && !e.low_nodeid && lo;
  const bool plain_hi = e.high.has_value() && !e.high_nodeid && hi;
  if (plain_lo && plain_hi && compare(lo.value(), hi.value()) > 0) {
    warning(p, p.at,
            "low limit " + entry_number(e, e.low, false) + " is above the high limit " +
                entry_number(e, e.high, false) + ": every value is out of range");
    return true;
  }
  const std::pair<const od::number *, bool> values[] = {{&e.default_value, e.default_nodeid},
                                                        {&e.parameter_value, e.parameter_nodeid}};
  for (const auto &[n, nodeid] : values) {
    if (!n->has_value() || nodeid) continue;
    const auto d = n->to_decimal();
    if (!d) continue;
    if ((plain_lo && compare(d.value(), lo.value()) < 0) ||
        (plain_hi && compare(d.value(), hi.value()) > 0)) {
      warning(p, p.at,
              std::string(n == &e.default_value ? "default" : "actual") + " value " +
                  entry_number(e, *n, false) + " is outside the limits " +
                  (plain_lo ? entry_number(e, e.low, false) : std::string("…")) + ".." +
                  (plain_hi ? entry_number(e, e.high, false) : std::string("…")));
    }
  }
  return true;
}

const xml::element *pick_label(const xml::element &parent, std::string_view language,
                               std::string_view element_name, std::string_view language_attribute,
                               std::vector<std::string> &other_languages) {
  const xml::element *first = nullptr;
  const xml::element *chosen = nullptr;
  for (const auto &c : parent.children) {
    if (c.local != element_name) continue;
    if (first == nullptr) first = &c;
    const xml::attribute *lang = c.find_attribute(language_attribute);
    if (chosen == nullptr && lang != nullptr && iequals(lang->value, language)) chosen = &c;
  }
  if (chosen == nullptr) chosen = first;
  for (const auto &c : parent.children) {
    if (c.local != element_name || &c == chosen) continue;
    const xml::attribute *lang = c.find_attribute(language_attribute);
    other_languages.push_back(lang != nullptr ? lang->value : std::string("?"));
  }
  return chosen;
}

} // namespace fieldcodec::gen
