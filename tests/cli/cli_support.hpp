// Support for the CLI tests: running the CLI in-process, candump logs made with the library
// (an SDO client and server exchanging frames, every frame logged with a time), golden files.
#pragma once

#include "app.hpp"
#include "util.hpp"

#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/core/utf8.hpp>
#include <fieldcodec/host/candump.hpp>

#include <doctest/doctest.h>

#include <cctype>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace fieldcodec::test {

/// What one run of the CLI printed.
struct cli_result {
  int code = -1;
  std::string out, err;
};

inline cli_result run_cli(std::vector<std::string> args, const std::string &input = {}) {
  std::istringstream in(input);
  std::ostringstream out, err;
  cli_result r;
  r.code = cli::run(args, in, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

inline std::string read_text(const std::string &path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

inline void write_text(const std::string &path, const std::string &text) {
  std::ofstream f(path, std::ios::binary);
  f << text;
}

/// Compares `actual` with the golden file tests/cli/golden/NAME (the tests run in tests/);
/// FIELDCODEC_UPDATE_GOLDEN=1 writes it instead.
inline void check_golden(const std::string &name, const std::string &actual) {
  const std::string path = "cli/golden/" + name;
  const char *update = std::getenv("FIELDCODEC_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    write_text(path, actual);
    return;
  }
  const std::string expected = read_text(path);
  INFO("golden file " << path << " (FIELDCODEC_UPDATE_GOLDEN=1 rewrites it)");
  CHECK(actual == expected);
}

/// Whether `s` is one JSON value (RFC 8259) in valid UTF-8: what every --json line must be.
inline bool valid_json(std::string_view s) {
  std::size_t i = 0;
  auto ws = [&] {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
  };
  auto literal = [&](std::string_view w) {
    if (s.substr(i, w.size()) != w) return false;
    i += w.size();
    return true;
  };
  std::function<bool()> value;
  auto string = [&]() -> bool {
    if (i >= s.size() || s[i] != '"') return false;
    ++i;
    while (i < s.size() && s[i] != '"') {
      const auto c = static_cast<unsigned char>(s[i]);
      if (c < 0x20U) return false;
      if (c == '\\') {
        ++i;
        if (i >= s.size()) return false;
        if (s[i] == 'u') {
          for (std::size_t k = 1; k <= 4U; ++k) {
            if (i + k >= s.size() || std::isxdigit(static_cast<unsigned char>(s[i + k])) == 0) {
              return false;
            }
          }
          i += 5;
        } else if (std::string_view("\"\\/bfnrt").find(s[i]) != std::string_view::npos) {
          ++i;
        } else {
          return false;
        }
      } else if (c >= 0x80U) {
        if (!fieldcodec::utf8::next(s, i)) return false;
      } else {
        ++i;
      }
    }
    if (i >= s.size()) return false;
    ++i;
    return true;
  };
  auto number = [&]() -> bool {
    const std::size_t start = i;
    if (i < s.size() && s[i] == '-') ++i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) != 0) ++i;
    if (i < s.size() && s[i] == '.') {
      ++i;
      while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) != 0) ++i;
    }
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
      ++i;
      if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
      while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) != 0) ++i;
    }
    return i > start && std::isdigit(static_cast<unsigned char>(s[i - 1])) != 0;
  };
  value = [&]() -> bool {
    ws();
    if (i >= s.size()) return false;
    bool ok = false;
    if (s[i] == '{') {
      ++i;
      ws();
      if (i < s.size() && s[i] == '}') {
        ++i;
        ok = true;
      } else {
        for (;;) {
          ws();
          if (!string()) return false;
          ws();
          if (i >= s.size() || s[i] != ':') return false;
          ++i;
          if (!value()) return false;
          ws();
          if (i < s.size() && s[i] == ',') {
            ++i;
            continue;
          }
          if (i < s.size() && s[i] == '}') {
            ++i;
            ok = true;
          }
          break;
        }
      }
    } else if (s[i] == '[') {
      ++i;
      ws();
      if (i < s.size() && s[i] == ']') {
        ++i;
        ok = true;
      } else {
        for (;;) {
          if (!value()) return false;
          ws();
          if (i < s.size() && s[i] == ',') {
            ++i;
            continue;
          }
          if (i < s.size() && s[i] == ']') {
            ++i;
            ok = true;
          }
          break;
        }
      }
    } else if (s[i] == '"') {
      ok = string();
    } else if (s[i] == 't' || s[i] == 'f' || s[i] == 'n') {
      ok = literal("true") || literal("false") || literal("null");
    } else {
      ok = number();
    }
    ws();
    return ok;
  };
  return value() && i == s.size();
}

/// Every line of `out` is valid JSON.
inline void check_json_lines(const std::string &out) {
  for (const auto l : cli::split_lines(out)) {
    CAPTURE(l);
    CHECK(valid_json(l));
  }
}

/// A candump log being written: every frame gets a time 250 µs after the last.
struct log_maker {
  std::int64_t t_us = 1700000000000000;
  host::interface_name iface = host::interface_name::make("can0").value();
  std::string text;

  void add(const canopen::can_frame &f) {
    t_us += 250;
    text += host::candump::format_line(
                host::to_record(f, host::timestamp::from_microseconds(t_us), iface)) +
            "\n";
  }
  void add(const result<canopen::can_frame> &f) { add(f.value()); }
  /// A frame given in candump notation (also what no can_frame holds: 29-bit, error frames).
  void frame(const std::string &notation) {
    t_us += 250;
    const auto t = host::timestamp::from_microseconds(t_us);
    std::string frac = std::to_string(t.fraction);
    frac.insert(0, 6U - frac.size(), '0');
    text += "(" + std::to_string(t.seconds) + "." + frac + ") can0 " + notation + "\n";
  }
  void line(const std::string &l) { text += l + "\n"; }
};

/// Runs an SDO transfer between a client and a server, logging every frame.
template <class Server>
void exchange(log_maker &log, canopen::sdo::client &c, Server &s,
              result<canopen::sdo::step> start) {
  REQUIRE(start);
  std::deque<std::pair<canopen::can_frame, bool>> queue; // frame, to the server
  std::uint32_t now = 0;
  for (const auto &f : start.value().send) queue.emplace_back(f, true);
  while (!queue.empty()) {
    const auto [f, to_server] = queue.front();
    queue.pop_front();
    log.add(f);
    const auto step = to_server ? s.on_frame(f, now) : c.on_frame(f, now);
    for (const auto &g : step.send) queue.emplace_back(g, !to_server);
  }
}

} // namespace fieldcodec::test
