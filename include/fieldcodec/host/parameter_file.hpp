// fieldcodec — host adapters: a node's saved parameters (CiA 301 1010h "store parameters" and
// 1011h "restore default parameters") in a file: the host's side of node::storage_hook.
//
//   host::parameter_file saved("node5.par", dict, dev);  // dev: a node::device (capacity::storage)
//   dev.set_storage(saved.hook());
//   if (auto r = saved.apply(dev); !r) std::puts(r.error().c_str());   // after power-on
//   ... on the device's reset_application event: saved.apply(dev)
//   ... on its reset_communication event:  saved.apply(dev, parameter_group::communication)
//
// Save (1010h sub n = "save") writes the current values of group n's parameters to the file,
// keeping the other groups' lines; restore (1011h sub n = "load") removes group n's lines, so that
// the dictionary's defaults stay after the next reset. Neither changes a current value (CiA 301).
// Groups: 1 all, 2 communication (1000h–1FFFh), 3 application (6000h–9FFFh), 4 manufacturer
// (2000h–5FFFh); another group is refused (the node answers 0606 0000h). A parameter is an entry
// the dictionary lets a client write (rw, wo, rwr, rww), but 1010h/1011h themselves and DOMAINs.
//
// The file is text, one parameter per line: the index and the sub-index in hex and the value's
// bytes in hex as they travel in an SDO (least significant byte first; a string's bytes), e.g.
// `1017 00 E803` (1017h = 1000 ms). Lines starting with '#' are comments. It is replaced whole
// (written beside it, then renamed): a crash while saving leaves the old file.
//
// apply() puts the saved values back through device::set, the node's own checks included, in the
// order CiA 301 asks for PDOs (COB-ID invalid, mapping count 0, entries, count, COB-ID) and with
// 1006h at 0 while 1019h is written; a value the node refuses, an object the dictionary lacks or a
// malformed line is an error naming the line (the values before and after it are still set).
// A node-ID-relative value is saved as the value for the node that saved it.
#pragma once

#include <fieldcodec/canopen/abort_code.hpp>
#include <fieldcodec/canopen/node/parameter_storage.hpp>
#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/dictionary.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fieldcodec::host {

class parameter_file {
public:
  /// Which object a saved line is for, and its bytes.
  using values = std::map<std::pair<std::uint16_t, std::uint8_t>, std::vector<std::uint8_t>>;

  /// The file at `path` for the parameters of `dict`, whose current values `device` gives
  /// (`device.value(address)`, e.g. a node::device). The device and the dictionary's tables must
  /// outlive this object.
  template <class Device>
  parameter_file(std::string path, od::dictionary dict, const Device &device)
      : path_(std::move(path)), dict_(dict),
        current_([&device](od::address a) -> result<std::vector<std::uint8_t>> {
          auto v = device.value(a);
          if (!v) return v.error();
          return std::vector<std::uint8_t>(v.value().begin(), v.value().end());
        }) {}

  /// The hook for device::set_storage (this object must outlive the device's use of it).
  [[nodiscard]] canopen::node::storage_hook hook() noexcept {
    return {this, &parameter_file::save_hook, &parameter_file::restore_hook};
  }

  /// Whether `index` belongs to parameter group `group` (1..4; another group holds nothing).
  [[nodiscard]] static constexpr bool in_group(std::uint8_t group, std::uint16_t index) noexcept {
    switch (group) {
    case canopen::node::parameter_group::all: return true;
    case canopen::node::parameter_group::communication: return index >= 0x1000U && index <= 0x1FFFU;
    case canopen::node::parameter_group::application: return index >= 0x6000U && index <= 0x9FFFU;
    case canopen::node::parameter_group::manufacturer: return index >= 0x2000U && index <= 0x5FFFU;
    default: return false;
    }
  }
  /// Whether an entry is a parameter the file keeps: a client may write it, it is not 1010h or
  /// 1011h, and it is not a DOMAIN.
  [[nodiscard]] static constexpr bool is_parameter(const od::entry &e) noexcept {
    return od::writable(e.access_type) && e.type != od::data_type::domain &&
           e.index != canopen::node::parameter_storage::store_index &&
           e.index != canopen::node::parameter_storage::restore_index;
  }

  /// 1010h sub `group` = "save": the current values of the group's parameters into the file, the
  /// other groups' lines kept. Returns how many were saved. Errors (also in last_error()): an
  /// unknown group, a file that cannot be read back (malformed: it is not overwritten) or written,
  /// a value the device cannot give.
  result<std::size_t, std::string> save(std::uint8_t group) {
    if (group < 1U || group > 4U) return failed("group " + std::to_string(group) + " is unknown");
    auto kept = read();
    if (!kept) return failed(kept.error());
    values v = std::move(kept.value());
    std::erase_if(v, [group](const auto &kv) { return in_group(group, kv.first.first); });
    std::size_t saved = 0;
    for (const od::entry &e : dict_.entries()) {
      if (!is_parameter(e) || !in_group(group, e.index)) continue;
      auto bytes = current_({e.index, e.sub});
      if (!bytes) {
        return failed(address_text(e.index, e.sub) + ": the device gives no value (" +
                      std::string(to_string(bytes.error())) + ")");
      }
      v[{e.index, e.sub}] = std::move(bytes.value());
      ++saved;
    }
    if (auto w = write(v); !w) return w.error();
    return saved;
  }

  /// 1011h sub `group` = "load": the group's lines out of the file (none: nothing to do).
  /// Returns how many lines went. Errors: as save.
  result<std::size_t, std::string> restore(std::uint8_t group) {
    if (group < 1U || group > 4U) return failed("group " + std::to_string(group) + " is unknown");
    auto kept = read();
    if (!kept) return failed(kept.error());
    values v = std::move(kept.value());
    const std::size_t before = v.size();
    std::erase_if(v, [group](const auto &kv) { return in_group(group, kv.first.first); });
    if (v.size() == before) return std::size_t{0};
    if (auto w = write(v); !w) return w.error();
    return before - v.size();
  }

  /// The saved values (none when the file does not exist). Errors: the line that is malformed
  /// ("PATH:LINE: what"), or a file that cannot be read.
  [[nodiscard]] result<values, std::string> read() const {
    std::ifstream in(path_, std::ios::binary);
    values v;
    if (!in) {
      std::FILE *probe = std::fopen(path_.c_str(), "rb");
      if (probe == nullptr) return v; // no file: nothing saved
      std::fclose(probe);
      return path_ + ": cannot be read";
    }
    std::string line;
    std::size_t n = 0;
    while (std::getline(in, line)) {
      ++n;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty() || line.front() == '#') continue;
      auto parsed = parse_line(line);
      if (!parsed) return path_ + ":" + std::to_string(n) + ": " + parsed.error();
      auto &[key, bytes] = parsed.value();
      if (v.count(key) != 0U) {
        return path_ + ":" + std::to_string(n) + ": " + address_text(key.first, key.second) +
               " is saved twice";
      }
      v.emplace(key, std::move(bytes));
    }
    if (in.bad()) return path_ + ": cannot be read";
    return v;
  }

  /// The saved values of `group` (all: every line) put back into `device` with device::set.
  /// Returns how many were set. Errors: every line refused ("PATH: 1017 00: why", one per line
  /// of the message); the others are set all the same.
  template <class Device>
  result<std::size_t, std::string> apply(Device &device,
                                         std::uint8_t group = canopen::node::parameter_group::all) {
    auto saved = read();
    if (!saved) return saved.error();
    values pending;
    for (auto &[key, bytes] : saved.value()) {
      if (in_group(group, key.first)) pending.emplace(key, bytes);
    }
    std::string problems;
    std::size_t set = 0;
    auto put = [&](std::uint16_t index, std::uint8_t sub, std::span<const std::uint8_t> b) {
      const canopen::sdo::abort_code c = device.set(od::address{index, sub}, b);
      if (c == canopen::sdo::abort_code::none) return true;
      problems += path_ + ": " + address_text(index, sub) + ": " + std::string(to_string(c)) +
                  " (0x" + hex(static_cast<std::uint32_t>(c), 8) + ")\n";
      return false;
    };
    auto take = [&](std::uint16_t index, std::uint8_t sub) {
      auto it = pending.find({index, sub});
      if (it == pending.end()) return;
      if (dict_.find(od::address{index, sub}) == nullptr) {
        problems += path_ + ": " + address_text(index, sub) + ": not in the dictionary\n";
      } else if (put(index, sub, it->second)) {
        ++set;
      }
      pending.erase(it);
    };
    auto current_u32 = [&](std::uint16_t index, std::uint8_t sub) -> std::uint32_t {
      auto b = current_({index, sub});
      if (!b) return 0;
      return static_cast<std::uint32_t>(
          load_le(b.value().data(), std::min<std::size_t>(b.value().size(), 4U)));
    };
    // PDOs in CiA 301's order: COB-ID invalid, mapping count 0, the communication parameters,
    // the mapping entries, the count, the COB-ID last
    for (const std::uint16_t comm_base : {std::uint16_t{0x1400}, std::uint16_t{0x1800}}) {
      for (std::uint16_t p = 0; p < 512U; ++p) {
        const auto comm = static_cast<std::uint16_t>(comm_base + p);
        const auto map = static_cast<std::uint16_t>(comm + 0x200U);
        const bool any = has_index(pending, comm) || has_index(pending, map);
        if (!any) continue;
        const std::uint32_t cob = current_u32(comm, 1);
        if ((cob & 0x8000'0000U) == 0U && dict_.find(od::address{comm, 1}) != nullptr) {
          (void)put(comm, 1, le4(cob | 0x8000'0000U));
        }
        const bool remap = has_index(pending, map);
        if (remap && pending.count({map, 0}) != 0U)
          (void)put(map, 0, std::array<std::uint8_t, 1>{0});
        for (std::uint16_t s = 2; s < 256U; ++s) take(comm, static_cast<std::uint8_t>(s));
        for (std::uint16_t s = 1; s < 256U; ++s) take(map, static_cast<std::uint8_t>(s));
        take(map, 0);
        take(comm, 0);
        if (pending.count({comm, 1}) != 0U) {
          take(comm, 1);
        } else if ((cob & 0x8000'0000U) == 0U && dict_.find(od::address{comm, 1}) != nullptr) {
          (void)put(comm, 1, le4(cob)); // valid again, as it was
        }
      }
    }
    // 1019h (SYNC counter overflow) only while 1006h (communication cycle period) is 0
    if (pending.count({0x1019, 0}) != 0U) {
      const std::uint32_t period = current_u32(0x1006, 0);
      if (period != 0U) (void)put(0x1006, 0, le4(0));
      take(0x1019, 0);
      if (pending.count({0x1006, 0}) == 0U && period != 0U) (void)put(0x1006, 0, le4(period));
    }
    while (!pending.empty()) take(pending.begin()->first.first, pending.begin()->first.second);
    if (!problems.empty()) {
      problems.pop_back();
      return problems;
    }
    return set;
  }

  /// Why the last save or restore failed (empty after one that worked).
  [[nodiscard]] const std::string &last_error() const noexcept { return last_error_; }
  [[nodiscard]] const std::string &path() const noexcept { return path_; }

private:
  // The node's hook is noexcept: an exception (out of memory) is a failed command, which the
  // node answers with 0606 0000h (a build without exceptions has none to catch).
  template <class F>
  static bool guarded(F f) noexcept {
#if defined(__cpp_exceptions)
    try {
      return f();
    } catch (...) {
      return false;
    }
#else
    return f();
#endif
  }
  static bool save_hook(void *self, std::uint8_t group) noexcept {
    return guarded([&] { return static_cast<parameter_file *>(self)->save(group).has_value(); });
  }
  static bool restore_hook(void *self, std::uint8_t group) noexcept {
    return guarded([&] { return static_cast<parameter_file *>(self)->restore(group).has_value(); });
  }

  result<std::size_t, std::string> failed(std::string why) {
    last_error_ = why;
    return why;
  }

  static std::string hex(std::uint32_t v, std::size_t digits) {
    std::array<char, 16> buf{};
    const std::size_t n = ascii::format_hex(v, digits, buf).value_or(0);
    return std::string(buf.data(), n);
  }
  static std::string address_text(std::uint16_t index, std::uint8_t sub) {
    return hex(index, 4) + " " + hex(sub, 2);
  }
  static std::array<std::uint8_t, 4> le4(std::uint32_t v) noexcept {
    std::array<std::uint8_t, 4> b{};
    store_le(b.data(), v, b.size());
    return b;
  }
  static bool has_index(const values &v, std::uint16_t index) {
    auto it = v.lower_bound({index, 0});
    return it != v.end() && it->first.first == index;
  }

  /// "IIII SS BYTES": 4 hex digits, a space, 2 hex digits, then (after a space) an even number
  /// of hex digits, possibly none.
  static result<std::pair<std::pair<std::uint16_t, std::uint8_t>, std::vector<std::uint8_t>>,
                std::string>
  parse_line(std::string_view l) {
    const std::string shape = "expected 'INDEX SUB BYTES' (e.g. '1017 00 E803')";
    if (l.size() < 7U || l[4] != ' ' || (l.size() > 7U && l[7] != ' ')) return shape;
    auto index = ascii::parse_hex(l.substr(0, 4));
    auto sub = ascii::parse_hex(l.substr(5, 2));
    if (!index || !sub) return shape + ": bad hex digit in the address";
    std::string_view data = l.size() > 8U ? l.substr(8) : std::string_view{};
    if (data.size() % 2U != 0U) return "odd number of hex digits in the value";
    std::vector<std::uint8_t> bytes;
    for (std::size_t i = 0; i < data.size(); i += 2U) {
      const int byte = ascii::hex_byte(data[i], data[i + 1U]);
      if (byte < 0) return "bad hex digit in the value";
      bytes.push_back(static_cast<std::uint8_t>(byte));
    }
    return std::pair{std::pair{static_cast<std::uint16_t>(index.value()),
                               static_cast<std::uint8_t>(sub.value())},
                     std::move(bytes)};
  }

  /// The file replaced by `v`: how many lines it has.
  result<std::size_t, std::string> write(const values &v) {
    const std::string tmp = path_ + ".new";
    {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      if (!out) return failed(tmp + ": cannot be written");
      out << "# fieldcodec parameter file: INDEX SUB BYTES (hex; bytes as an SDO carries them)\n";
      for (const auto &[key, bytes] : v) {
        out << address_text(key.first, key.second);
        if (!bytes.empty()) out << ' ';
        for (const std::uint8_t b : bytes) out << hex(b, 2);
        out << '\n';
      }
      out.flush();
      if (!out) {
        std::remove(tmp.c_str());
        return failed(tmp + ": cannot be written");
      }
    }
    if (std::rename(tmp.c_str(), path_.c_str()) != 0) {
      std::remove(tmp.c_str());
      return failed(path_ + ": cannot be replaced");
    }
    last_error_.clear();
    return v.size();
  }

  std::string path_;
  od::dictionary dict_;
  std::function<result<std::vector<std::uint8_t>>(od::address)> current_;
  std::string last_error_;
};

} // namespace fieldcodec::host
