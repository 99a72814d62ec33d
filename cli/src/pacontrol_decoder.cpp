// fieldcodec CLI — PA-CONTROL RS232 captures.
#include "pacontrol_decoder.hpp"

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/dictionaries/pacontrol_commands.hpp>
#include <fieldcodec/host/quoted_bytes.hpp>
#include <fieldcodec/pacontrol/codes.hpp>
#include <fieldcodec/pacontrol/command.hpp>
#include <fieldcodec/pacontrol/serial_decoder.hpp>
#include <fieldcodec/pacontrol/serial_frame.hpp>

#include <algorithm>
#include <optional>

namespace fieldcodec::cli {

namespace ser = pacontrol::serial;

namespace {

std::string value_text(const pacontrol::value &v) {
  return decimal_text(v.number) +
         (v.type == od::command_value::real ? std::string(" (real)") : std::string(" (integer)"));
}

/// The frame's parts: body between STX and ETX, check digits between ETX and EOT.
struct frame_parts {
  std::string body;
  std::string check;
};
std::optional<frame_parts> split_frame(std::span<const std::uint8_t> f) {
  if (f.size() < 4U || f[0] != ser::soh || f[1] != ser::stx || f.back() != ser::eot) {
    return std::nullopt;
  }
  frame_parts p;
  std::size_t i = 2;
  while (i + 1U < f.size() && f[i] != ser::etx) p.body += static_cast<char>(f[i++]);
  if (f[i] != ser::etx) return std::nullopt;
  for (++i; i + 1U < f.size(); ++i) p.check += static_cast<char>(f[i]);
  return p;
}

std::string check_text(const frame_parts &p, bool request, bool ok,
                       const ser::check_options &checks) {
  const auto body = std::span<const char>(p.body.data(), p.body.size());
  const unsigned plain = ser::compute_check(body, ser::check_rule::body);
  const unsigned with_etx = ser::compute_check(body, ser::check_rule::body_and_etx);
  if (p.check == "0") return "check 0 (not checked)";
  if (ok) {
    const ser::check_rule rule = request ? checks.request : checks.acknowledgement;
    const bool own_rule =
        std::to_string(rule == ser::check_rule::body ? plain : with_etx) == p.check;
    return "check " + p.check + " ok" +
           (own_rule ? std::string() : std::string(" (the other rule)"));
  }
  return "check " + p.check + " WRONG (body " + std::to_string(plain) + ", body+ETX " +
         std::to_string(with_etx) + ")";
}

} // namespace

bool looks_like_hex(std::string_view bytes) {
  bool any = false;
  bool comment = false;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const char c = bytes[i];
    if (comment) {
      if (c == '\n') comment = false;
      continue;
    }
    if (c == '#') {
      comment = true;
    } else if (ascii::hex_value(c) >= 0) {
      any = true;
    } else if (c == 'x' && i > 0 && bytes[i - 1] == '0') {
      continue;
    } else if (c != ' ' && c != '\t' && c != '\r' && c != '\n' && c != ',') {
      return false;
    }
  }
  return any;
}

bool parse_hex_capture(std::string_view text, std::vector<std::uint8_t> &out, std::string &error) {
  std::size_t line = 1;
  std::string token;
  auto flush = [&]() -> bool {
    if (token.empty()) return true;
    std::string t = token;
    token.clear();
    if (t.size() > 2U && t[0] == '0' && (t[1] == 'x' || t[1] == 'X')) t = t.substr(2);
    if (t.size() % 2U != 0U) {
      error = "line " + std::to_string(line) + ": odd number of hex digits in '" + t + "'";
      return false;
    }
    for (std::size_t i = 0; i < t.size(); i += 2U) {
      const int byte = ascii::hex_byte(t[i], t[i + 1U]);
      if (byte < 0) {
        error = "line " + std::to_string(line) + ": not hex: '" + t + "'";
        return false;
      }
      out.push_back(static_cast<std::uint8_t>(byte));
    }
    return true;
  };
  bool comment = false;
  for (const char c : text) {
    if (c == '\n') {
      if (!flush()) return false;
      comment = false;
      ++line;
      continue;
    }
    if (comment) continue;
    if (c == '#') {
      if (!flush()) return false;
      comment = true;
    } else if (c == ' ' || c == '\t' || c == '\r' || c == ',') {
      if (!flush()) return false;
    } else {
      token += c;
    }
  }
  return flush();
}

std::optional<ser::check_options> parse_check_rule(std::string_view s) {
  ser::check_options o;
  if (s == "manual") return o;
  if (s == "either") {
    o.request_either_rule = true;
    o.acknowledgement_either_rule = true;
    return o;
  }
  if (s == "body" || s == "body+etx") {
    const auto r = s == "body" ? ser::check_rule::body : ser::check_rule::body_and_etx;
    o.request = r;
    o.acknowledgement = r;
    return o;
  }
  return std::nullopt;
}

ser::check_options default_decode_checks() { return parse_check_rule("either").value(); }

std::vector<decoded_line> decode_pacontrol(std::span<const std::uint8_t> capture,
                                           const ser::check_options &checks) {
  namespace cmds = dictionaries::pacontrol_commands;
  std::vector<decoded_line> out;
  ser::decoder dec({checks, ser::accept::any});
  std::vector<std::uint8_t> pending; // bytes since the last line
  std::size_t pending_at = 0;        // offset of pending[0]
  const od::command *last_command = nullptr;

  auto line_at = [](std::size_t offset, std::string function) {
    decoded_line l;
    l.id = "@" + std::to_string(offset);
    l.function = std::move(function);
    l.json.unum("offset", offset);
    return l;
  };
  // bytes before the last SOH of `pending` that belong to no frame
  auto emit_noise_before_frame = [&]() {
    std::size_t soh_at = pending.size();
    for (std::size_t i = pending.size(); i-- > 0;) {
      if (pending[i] == ser::soh) {
        soh_at = i;
        break;
      }
    }
    if (soh_at == 0U || soh_at == pending.size()) return;
    decoded_line l = line_at(pending_at, "NOISE");
    const auto noise = std::span<const std::uint8_t>(pending.data(), soh_at);
    l.text = std::to_string(noise.size()) + " bytes outside a frame: " + host::quoted_bytes(noise);
    l.problem = true;
    l.json.str("bytes", hex_bytes(noise, ""));
    out.push_back(std::move(l));
    pending.erase(pending.begin(), pending.begin() + static_cast<std::ptrdiff_t>(soh_at));
    pending_at += soh_at;
  };

  for (std::size_t pos = 0; pos < capture.size(); ++pos) {
    const std::uint8_t b = capture[pos];
    if (pending.empty()) pending_at = pos;
    pending.push_back(b);
    auto k = dec.push(b);
    if (k && k.value() == ser::frame_kind::none) continue;
    if (k && k.value() == ser::frame_kind::poll) {
      decoded_line l = line_at(pos, "POLL");
      l.text = "poll (EOT): the PA-CONTROL answers with its status";
      out.push_back(std::move(l));
      pending.clear();
      continue;
    }
    if (k) {
      emit_noise_before_frame();
      const auto parts = split_frame(pending);
      const bool request = k.value() == ser::frame_kind::request;
      decoded_line l = line_at(pending_at, request ? "REQUEST" : "ACK");
      if (request) {
        const ser::request &r = dec.request();
        const od::command *c = cmds::table.find(r.code);
        last_command = c;
        l.text = hex(r.code, 4).substr(2) + " " +
                 (c != nullptr ? std::string(c->name) + " (" + std::string(c->title) + ")"
                               : std::string("unknown command"));
        l.text += ": parameter " + std::to_string(r.parameter) + ", date " + value_text(r.date);
        if (c != nullptr) {
          if (auto s = c->check_parameter(r.parameter); !s) {
            l.text += ", parameter " + std::string(to_string(s.error()));
            l.problem = true;
          }
          if (c->date_type == od::command_value::none) {
            // no date: the master sends 0 (typed as the reply)
            if (r.date.number.mantissa != 0) {
              l.text += ", a date the command does not take";
              l.problem = true;
            }
          } else if (auto s = pacontrol::check_date(*c, r.date); !s) {
            l.text += ", date " + std::string(to_string(s.error()));
            l.problem = true;
          }
        } else {
          l.problem = true;
        }
        l.json.str("command", hex(r.code, 4).substr(2));
        if (c != nullptr) l.json.str("name", c->name);
        l.json.unum("parameter", r.parameter).dec("date", r.date.number);
      } else {
        const ser::acknowledgement &a = dec.acknowledgement();
        auto quit = pacontrol::describe_command_error(a.command_error_number);
        auto status = pacontrol::describe_operating_status(a.operating_status);
        auto err = pacontrol::describe_controller_error(a.controller_error_number);
        l.text = "QUIT " + std::to_string(a.command_error_number) + " (" +
                 std::string(quit ? quit.value() : "unknown command error") + "), BE " +
                 (a.end_of_processing ? "1 (done)" : "0 (running)") + ", STATUS " +
                 std::to_string(a.operating_status) + " (" +
                 std::string(status ? status.value() : "unknown status") + "), ERROR " +
                 std::to_string(a.controller_error_number) + " (" +
                 std::string(err ? err.value() : "unknown error") + "), reply " +
                 value_text(a.date);
        if (last_command != nullptr) {
          l.text += " for " + std::string(last_command->name);
          if (!pacontrol::reply_value(*last_command, a)) {
            l.text += " (reply type differs from the command's)";
            l.problem = true;
          }
        }
        l.problem = l.problem || a.command_error_number != 0U || a.controller_error_number != 0U;
        l.json.unum("quit", a.command_error_number)
            .boolean("end_of_processing", a.end_of_processing)
            .unum("status", a.operating_status)
            .unum("error", a.controller_error_number)
            .dec("reply", a.date.number);
        last_command = nullptr;
      }
      if (parts) {
        l.text += ", " + check_text(*parts, request, true, checks);
        l.json.str("check", parts->check);
      }
      out.push_back(std::move(l));
      pending.clear();
      continue;
    }
    // an error: the decoder dropped the frame in progress
    const errc e = k.error();
    if (e == errc::bad_syntax && pending.size() == 1U && b != ser::soh) {
      continue; // the first byte of noise between frames: shown with the next frame
    }
    const bool restarted = b == ser::soh && e == errc::truncated; // SOH began the next frame
    if (restarted) pending.pop_back();
    emit_noise_before_frame();
    decoded_line l = line_at(pending_at, "MALFORMED");
    l.problem = true;
    const auto parts = split_frame(pending);
    if (e == errc::bad_checksum && parts) {
      const bool request = std::count(parts->body.begin(), parts->body.end(), ';') == 3;
      l.function = request ? "REQUEST" : "ACK";
      l.text = (request ? "request " : "acknowledgement ") + json_string(parts->body) + ", " +
               check_text(*parts, request, false, checks);
      l.json.str("body", parts->body).str("check", parts->check).str("error", "bad checksum");
    } else {
      l.text = std::string(to_string(e)) + ": " + host::quoted_bytes(pending);
      l.json.str("error", to_string(e)).str("bytes", hex_bytes(pending, ""));
    }
    out.push_back(std::move(l));
    pending.clear();
    if (restarted) {
      pending_at = pos;
      pending.push_back(b);
    }
  }
  if (!pending.empty() && std::find(pending.begin(), pending.end(), ser::soh) == pending.end()) {
    decoded_line l = line_at(pending_at, "NOISE");
    l.problem = true;
    l.text =
        std::to_string(pending.size()) + " bytes outside a frame: " + host::quoted_bytes(pending);
    l.json.str("bytes", hex_bytes(pending, ""));
    out.push_back(std::move(l));
  } else if (!pending.empty()) {
    emit_noise_before_frame();
    decoded_line l = line_at(pending_at, "TRUNCATED");
    l.problem = true;
    l.text = "capture ends inside a frame: " + host::quoted_bytes(pending);
    l.json.str("error", "truncated").str("bytes", hex_bytes(pending, ""));
    out.push_back(std::move(l));
  }
  return out;
}

} // namespace fieldcodec::cli
