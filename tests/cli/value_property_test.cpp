// The property of issue 26, section 1, over every entry of every shipped dictionary and of the
// EDS corpus (../shared/eds-corpus): what `sdo read` prints for a value, `sdo write` accepts
// and sends as the same bytes; every value outside the entry's limits is refused, naming the
// limit. The two commands' own functions are used (cli::format_value / cli::display_options
// for read, cli::parse_value for write); the transport around them is tested in values_test.cpp.
#include "cli_support.hpp"

#include "dictionary.hpp"
#include "skip.hpp"
#include "values.hpp"

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/host/value_text.hpp>
#include <fieldcodec/od/engineering.hpp>
#include <fieldcodec/od/value.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace cli = fieldcodec::cli;
namespace od = fieldcodec::od;
using fieldcodec::byte_order;
using fieldcodec::errc;

namespace {

using bytes = std::vector<std::uint8_t>;
constexpr std::uint8_t node_id = 5;

struct tally {
  std::size_t dictionaries = 0;
  std::size_t entries = 0;
  std::size_t values = 0;
  std::size_t accepted = 0;
  std::size_t refused_limits = 0;
  std::size_t refused_other = 0;
};

/// A small deterministic generator (the same values on every run and machine).
struct lcg {
  std::uint64_t s = 0x9E3779B97F4A7C15ULL;
  std::uint64_t next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return s >> 11U;
  }
};

/// Raw integers to try for `d`: the type's ends, 0 and ±1, the raw limits and one beyond each,
/// the default, a few spread over the type.
std::vector<std::int64_t> raw_candidates(const od::descriptor &d, lcg &g) {
  const auto f = d.raw_field().value();
  std::vector<std::int64_t> v = {f.min(), f.max(), 0, 1, -1, f.min() + 1, f.max() - 1};
  for (const bool high : {false, true}) {
    auto end = od::detail::raw_end(d, high, node_id);
    if (!end) continue;
    const auto w = end.value();
    if (w.negative ||
        w.mag <= static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      const std::int64_t x =
          w.negative ? -static_cast<std::int64_t>(w.mag) : static_cast<std::int64_t>(w.mag);
      v.push_back(x);
      if (x > std::numeric_limits<std::int64_t>::min()) v.push_back(x - 1);
      if (x < std::numeric_limits<std::int64_t>::max()) v.push_back(x + 1);
    }
  }
  if (auto def = d.default_for(node_id)) {
    if (auto i = def.value().to_int64()) v.push_back(i.value());
  }
  for (int k = 0; k < 6; ++k) {
    const auto span = static_cast<std::uint64_t>(f.max()) - static_cast<std::uint64_t>(f.min());
    const std::uint64_t r = span == ~std::uint64_t{0} ? g.next() : g.next() % (span + 1U);
    v.push_back(static_cast<std::int64_t>(static_cast<std::uint64_t>(f.min()) + r));
  }
  v.erase(std::remove_if(v.begin(), v.end(),
                         [&](std::int64_t x) { return x < f.min() || x > f.max(); }),
          v.end());
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

std::vector<bytes> candidates(const od::descriptor &d, lcg &g) {
  std::vector<bytes> out;
  const std::uint32_t w = od::fixed_size(d.type);
  auto le = [&](std::uint64_t v, std::uint32_t n) {
    bytes b(n);
    for (std::uint32_t i = 0; i < n; ++i) b[i] = static_cast<std::uint8_t>(v >> (8U * i));
    return b;
  };
  if (od::is_integer(d.type)) {
    for (const std::int64_t x : raw_candidates(d, g))
      out.push_back(le(static_cast<std::uint64_t>(x), w));
    if (d.type == od::data_type::unsigned64) out.push_back(bytes(8, 0xFF)); // beyond INT64_MAX
  } else if (d.type == od::data_type::boolean) {
    out = {{0}, {1}};
  } else if (d.type == od::data_type::real32) {
    for (const float f :
         {0.0f, -0.0f, 1.5f, -2.25f, 0.1f, 1e30f, 1e-30f, 3.4028235e38f,
          std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
      out.push_back(le(std::bit_cast<std::uint32_t>(f), 4));
    }
    for (int k = 0; k < 4; ++k) out.push_back(le(g.next() & 0xFFFFFFFFU, 4));
  } else if (d.type == od::data_type::real64) {
    for (const double f :
         {0.0, -0.0, 1.5, 0.1, 1e300, 5e-324, 0.30000000000000004,
          std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
      out.push_back(le(std::bit_cast<std::uint64_t>(f), 8));
    }
    for (int k = 0; k < 4; ++k) out.push_back(le(g.next(), 8));
  } else if (od::is_time(d.type)) {
    out = {le(0, 6), le(0x0FFFFFFFU, 6), le((std::uint64_t{14731} << 32U) | 45296789U, 6),
           le(std::uint64_t{0xFFFF} << 32U, 6)};
  } else if (d.type == od::data_type::visible_string) {
    const std::size_t cap = d.capacity() != 0U ? d.capacity() : 40U;
    out = {{},
           {'a', 'b', 'c'},
           {'"', '\\', 'x'},
           bytes(cap, 'Z'),
           bytes(cap + 1U, 'Z'),
           {'a', 0x01, 'b'},
           {'a', 0xC3, 0xA9},
           {'p', 'a', 'd', 0, 0}};
  } else if (d.type == od::data_type::unicode_string) {
    out = {{}, {'A', 0, 0xE9, 0}, {'"', 0, '\\', 0}, {0x3D, 0xD8, 0x00, 0xDE}};
  } else { // OCTET_STRING, DOMAIN
    bytes r(d.capacity() != 0U ? d.capacity() : 16U);
    for (auto &b : r) b = static_cast<std::uint8_t>(g.next());
    out = {{}, {0x00}, r};
    if (d.capacity() != 0U) out.push_back(bytes(d.capacity() + 1U, 0xAB));
  }
  return out;
}

/// Whether the value of `b` lies within the entry's limits for node_id, in the unit of `o`:
/// engineering limits on the engineering value of a scaled entry, raw limits otherwise; and a
/// string within its capacity. (The definition the property refers to.)
bool within(const od::descriptor &d, const bytes &b, const od::value_options &o) {
  if (od::is_byte_string(d.type)) return d.capacity() == 0U || b.size() <= d.capacity();
  auto n = od::decode_value(d, b, o);
  if (!n) return false;
  if (od::is_scaled(d) && o.unit == od::value_unit::engineering) {
    const auto eu = n.value().to_decimal().value();
    for (const bool high : {false, true}) {
      auto lim = od::detail::checked_limit(d, high, node_id);
      if (!lim) continue;
      auto l = lim.value().to_decimal();
      if (!l) continue;
      const int c = fieldcodec::compare(eu, l.value());
      if ((high && c > 0) || (!high && c < 0)) return false;
    }
    return true;
  }
  auto raw =
      od::decode(static_cast<const od::entry &>(d), b, byte_order::little, od::limits::ignore);
  if (!raw) return false;
  return static_cast<bool>(od::check_limits(d, raw.value(), node_id));
}

/// What a VISIBLE_STRING written back holds (trailing NULs are padding, not value).
bytes value_bytes(const od::descriptor &d, bytes b) {
  if (d.type == od::data_type::visible_string) {
    while (!b.empty() && b.back() == 0U) b.pop_back();
  }
  return b;
}

bool writable_value(const od::descriptor &d, const bytes &b) {
  if (d.type == od::data_type::visible_string) {
    for (const auto c : value_bytes(d, b)) {
      if (c < 0x20U || c > 0x7EU) return false;
    }
  }
  if (od::is_real(d.type)) {
    const double x = d.type == od::data_type::real32
                         ? static_cast<double>(std::bit_cast<float>(static_cast<std::uint32_t>(
                               fieldcodec::load_unsigned(b, 4, byte_order::little).value())))
                         : std::bit_cast<double>(static_cast<std::uint64_t>(
                               fieldcodec::load_unsigned(b, 8, byte_order::little).value()));
    if (!std::isfinite(x)) return false; // od refuses NaN and infinity on the way out
  }
  return true;
}

void check_entry(const cli::object_desc &o, lcg &g, tally &t) {
  const od::descriptor &d = o.d;
  CAPTURE(o.name);
  CAPTURE(d.index);
  CAPTURE(d.sub);
  ++t.entries;
  for (const bool raw : {false, true}) {
    if (raw && !od::is_scaled(d)) continue;
    const od::value_options opt = cli::display_options(d, node_id, raw);
    for (const bytes &b : candidates(d, g)) {
      ++t.values;
      // what `sdo read` prints for the value (the text before its annotations)
      auto text = fieldcodec::host::format_value(d, b, opt);
      if (!text) {
        // shown as raw bytes, not as a value: an UNSIGNED64 above INT64_MAX of a scaled entry
        // (no engineering value), a NaN or infinity (od refuses them both ways)
        CAPTURE(fieldcodec::to_string(text.error()));
        CHECK(((od::is_scaled(d) && !raw && text.error() == errc::overflow) ||
               (od::is_real(d.type) && !writable_value(d, b) &&
                text.error() == errc::not_representable)));
        ++t.refused_other;
        continue;
      }
      CAPTURE(text.value());
      const auto parsed = cli::parse_value(o, text.value(), node_id, raw);
      const bool in = within(d, b, opt) && writable_value(d, b);
      if (in) {
        CHECK_MESSAGE(parsed.ok, parsed.error);
        if (parsed.ok) CHECK(parsed.bytes == value_bytes(d, b));
        ++t.accepted;
        continue;
      }
      CHECK_FALSE(parsed.ok);
      if (!within(d, b, opt)) {
        // refused naming the limit (or the capacity)
        const bool named = parsed.error.find("limit") != std::string::npos ||
                           parsed.error.find("bytes the object holds") != std::string::npos;
        CHECK_MESSAGE(named, parsed.error);
        ++t.refused_limits;
      } else {
        ++t.refused_other;
      }
    }
  }
}

tally check_dictionary(const std::filesystem::path &path, std::size_t &unreadable) {
  tally t;
  std::string error;
  auto loaded = cli::node_dictionary::load(path.string(), error);
  if (!loaded) {
    ++unreadable;
    MESSAGE("not readable, left out: " << path.string() << ": " << error);
    return t;
  }
  lcg g;
  // the CLI's view of the node (its family's vendor units), and the plain dictionary
  std::vector<cli::device_family> families = {loaded->family()};
  if (loaded->family() != cli::device_family::generic)
    families.push_back(cli::device_family::generic);
  for (const auto f : families) {
    const auto dict = loaded->for_node(node_id, f);
    ++t.dictionaries;
    for (const auto &o : dict.objects()) check_entry(o, g, t);
  }
  return t;
}

void add(tally &a, const tally &b) {
  a.dictionaries += b.dictionaries;
  a.entries += b.entries;
  a.values += b.values;
  a.accepted += b.accepted;
  a.refused_limits += b.refused_limits;
  a.refused_other += b.refused_other;
}

} // namespace

TEST_CASE("property: what read prints, write sends back as the same bytes (shipped dictionaries)") {
  tally all;
  std::size_t unreadable = 0;
  for (const auto &e : std::filesystem::directory_iterator("../dictionaries")) {
    const auto ext = e.path().extension();
    if (ext != ".eds" && ext != ".csv") continue;
    if (e.path().filename() == "pacontrol_commands.csv") continue; // a command table
    add(all, check_dictionary(e.path(), unreadable));
  }
  CHECK(unreadable == 0);
  MESSAGE("shipped dictionaries: " << all.dictionaries << " dictionary views, " << all.entries
                                   << " entries, " << all.values << " values: " << all.accepted
                                   << " written back, " << all.refused_limits
                                   << " refused for a limit or capacity, " << all.refused_other
                                   << " refused otherwise (not a visible string, NaN)");
  CHECK(all.entries > 4000);
  CHECK(all.refused_limits > 0);
}

TEST_CASE("property: what read prints, write sends back as the same bytes (EDS corpus)") {
  const std::filesystem::path corpus = std::string(FIELDCODEC_SHARED_DIR) + "/eds-corpus";
  if (!std::filesystem::is_directory(corpus)) {
    FIELDCODEC_SKIP_TEST("corpus", corpus.string() << " is absent");
  }
  tally all;
  std::size_t files = 0;
  std::size_t unreadable = 0;
  for (const auto &e : std::filesystem::directory_iterator(corpus)) {
    const auto ext = e.path().extension();
    if (ext != ".eds" && ext != ".dcf") continue;
    ++files;
    add(all, check_dictionary(e.path(), unreadable));
  }
  MESSAGE("EDS corpus: " << files << " files (" << unreadable << " not readable), "
                         << all.dictionaries << " dictionary views, " << all.entries << " entries, "
                         << all.values << " values: " << all.accepted << " written back, "
                         << all.refused_limits << " refused for a limit or capacity, "
                         << all.refused_other << " refused otherwise");
  CHECK(files >= 40);
  CHECK(all.entries > 10000);
}
