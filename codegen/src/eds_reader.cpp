// fieldcodec-gen — CiA 306 EDS/DCF reader, lenient about what real files do
// (docs/generator.md, "Reading EDS/DCF files as they exist").
#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/core/ascii.hpp>
#include <fieldcodec/od/value.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <deque>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

namespace fieldcodec::gen {

namespace {

// Message building with views into the file text.
std::string operator+(std::string a, std::string_view b) { return a.append(b); }
std::string operator+(const char *a, std::string_view b) { return std::string(a).append(b); }

// [xxxx], [xxxxsubyy], and the per-sub-index sections of CompactSubObj objects and links.
enum class section_kind { other, object, sub, names, values, denotations, object_links };

// The keys the reader knows, found once per line (a section is searched by number, not text).
enum class key : std::uint8_t {
  other,
  // interpreted in object and sub-object sections
  parameter_name,
  object_type,
  data_type,
  access_type,
  default_value,
  pdo_mapping,
  low_limit,
  high_limit,
  sub_number,
  compact_sub_obj,
  obj_flags,
  parameter_value,
  denotation,
  size,
  // CiA 306 keys of object sections kept for the EDS export without being interpreted
  upload_file,
  download_file,
  count,
  srdo_mapping,
  inverted_srad,
  param_refd,
  refuse_read_on_scan,
  refuse_write_on_download,
  // keys of other sections
  node_id,
  node_name,
  supported_objects,
  nr_of_entries,
  object_links,
};

constexpr std::pair<std::string_view, key> key_names[] = {
    {"PARAMETERNAME", key::parameter_name},
    {"OBJECTTYPE", key::object_type},
    {"DATATYPE", key::data_type},
    {"ACCESSTYPE", key::access_type},
    {"DEFAULTVALUE", key::default_value},
    {"PDOMAPPING", key::pdo_mapping},
    {"LOWLIMIT", key::low_limit},
    {"HIGHLIMIT", key::high_limit},
    {"SUBNUMBER", key::sub_number},
    {"COMPACTSUBOBJ", key::compact_sub_obj},
    {"OBJFLAGS", key::obj_flags},
    {"PARAMETERVALUE", key::parameter_value},
    {"DENOTATION", key::denotation},
    {"SIZE", key::size},
    {"UPLOADFILE", key::upload_file},
    {"DOWNLOADFILE", key::download_file},
    {"COUNT", key::count},
    {"SRDOMAPPING", key::srdo_mapping},
    {"INVERTEDSRAD", key::inverted_srad},
    {"PARAMREFD", key::param_refd},
    {"REFUSEREADONSCAN", key::refuse_read_on_scan},
    {"REFUSEWRITEONDOWNLOAD", key::refuse_write_on_download},
    {"NODEID", key::node_id},
    {"NODENAME", key::node_name},
    {"SUPPORTEDOBJECTS", key::supported_objects},
    {"NROFENTRIES", key::nr_of_entries},
    {"OBJECTLINKS", key::object_links},
};

// The known keys by length: key_names positions of each length (the longest known key has 21
// characters), built at compile time from key_names.
constexpr std::size_t longest_key = 21;
constexpr std::size_t keys_per_length = 6;
struct key_buckets {
  std::uint8_t count[longest_key + 1] = {};
  std::uint8_t at[longest_key + 1][keys_per_length] = {};
};
constexpr key_buckets make_key_buckets() {
  key_buckets b;
  for (std::size_t i = 0; i < std::size(key_names); ++i) {
    const std::size_t n = key_names[i].first.size();
    b.at[n][b.count[n]++] = static_cast<std::uint8_t>(i);
  }
  return b;
}
constexpr key_buckets key_by_length = make_key_buckets();
static_assert([] {
  std::size_t longest = 0;
  for (const auto &k : key_names) longest = std::max(longest, k.first.size());
  for (std::size_t n = 0; n <= longest_key; ++n) {
    if (key_by_length.count[n] > keys_per_length) return false;
  }
  return longest == longest_key;
}());

// The known keys in lower case, NUL-padded to 24 bytes: compared eight bytes at a time. Every
// known key is letters only, so `c | 0x20` of a byte of the key as written equals the lower-case
// letter exactly when the byte is that letter in either case.
struct lower_key {
  char text[24] = {};
};
constexpr std::array<lower_key, std::size(key_names)> lower_keys = [] {
  std::array<lower_key, std::size(key_names)> out{};
  for (std::size_t i = 0; i < std::size(key_names); ++i) {
    const std::string_view k = key_names[i].first;
    for (std::size_t j = 0; j < k.size(); ++j) out[i].text[j] = static_cast<char>(k[j] | 0x20);
  }
  return out;
}();
static_assert([] {
  for (const auto &[k, id] : key_names) {
    for (const char c : k) {
      if (c < 'A' || c > 'Z') return false;
    }
  }
  return true;
}());

std::uint64_t load8(const char *p) noexcept {
  std::uint64_t w = 0;
  std::memcpy(&w, p, 8);
  return w;
}

// Runs for every line of a file, on the key as written (any case): only the known keys of the
// same length are candidates, compared eight letters at a time.
key key_of(std::string_view name) noexcept {
  const std::size_t n = name.size();
  if (n == 0U || n > longest_key) return key::other;
  constexpr std::uint64_t fold = 0x2020202020202020U;
  for (std::size_t c = 0; c < key_by_length.count[n]; ++c) {
    const std::size_t k = key_by_length.at[n][c];
    const char *const known = lower_keys[k].text;
    std::size_t i = 0;
    for (; i + 8U <= n; i += 8U) {
      if ((load8(name.data() + i) | fold) != load8(known + i)) break;
    }
    if (i + 8U <= n) continue;
    while (i < n && static_cast<char>(name[i] | 0x20) == known[i]) ++i;
    if (i == n) return key_names[k].second;
  }
  return key::other;
}

// Keys of object and sub-object sections the reader interprets.
bool interpreted_key(key k) noexcept { return k >= key::parameter_name && k <= key::size; }

// Keys of CiA 306 (and its DCF and safety extensions) the reader does not interpret: kept for
// the EDS export without a warning.
bool known_other_key(key k) noexcept {
  return k >= key::upload_file && k <= key::refuse_write_on_download;
}

struct ini_key {
  std::string_view name;  // as written (trimmed), points into the reader's text
  std::string_view value; // trimmed
  int line = 0;
  int value_col = 0;
  key id = key::other; // the key when the reader knows it
};

constexpr std::uint32_t key_bit(key id) noexcept {
  return std::uint32_t{1} << static_cast<unsigned>(id);
}
static_assert(static_cast<unsigned>(key::object_links) < 32U, "key_bit needs a wider mask");

// Key names compared without regard to ASCII case (as iequals), hashed alike: the names are
// views into the reader's text, so a map of them copies no text.
struct ci_hash {
  std::size_t operator()(std::string_view s) const noexcept {
    std::uint64_t h = 0xcbf29ce484222325U; // FNV-1a of the upper-case name
    for (char c : s) {
      if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
      h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3U;
    }
    return static_cast<std::size_t>(h);
  }
};
struct ci_equal {
  bool operator()(std::string_view a, std::string_view b) const noexcept { return iequals(a, b); }
};

/// The keys of a section: a range of the reader's key list (or of the section's own list).
struct key_range {
  const ini_key *first = nullptr;
  std::size_t count = 0;
  [[nodiscard]] const ini_key *begin() const noexcept { return first; }
  [[nodiscard]] const ini_key *end() const noexcept { return first + count; }
  [[nodiscard]] std::size_t size() const noexcept { return count; }
  [[nodiscard]] const ini_key &operator[](std::size_t i) const noexcept { return first[i]; }
  [[nodiscard]] std::reverse_iterator<const ini_key *> rbegin() const noexcept {
    return std::reverse_iterator<const ini_key *>(end());
  }
  [[nodiscard]] std::reverse_iterator<const ini_key *> rend() const noexcept {
    return std::reverse_iterator<const ini_key *>(begin());
  }
};

/// A section. Its keys follow each other in the file, so they are a range of one list of every
/// key of the file (`all`, one allocation for the file instead of one per section, referred to
/// by position: the list may grow); a section that gets the keys of a repeated section of the
/// same name (merged) moves its keys into a list of its own.
struct ini_section {
  explicit ini_section(std::vector<ini_key> &all) : list_(&all), first_(all.size()) {}

  std::string name;
  std::string upper;
  int line = 0;
  section_kind kind = section_kind::other; // set when the sections are indexed

  [[nodiscard]] key_range keys() const noexcept { return {list_->data() + first_, count_}; }

  /// The last occurrence of a known key.
  [[nodiscard]] const ini_key *find(key id) const {
    if ((known_ & key_bit(id)) == 0U) return nullptr;
    const key_range k = keys();
    for (auto it = k.rbegin(); it != k.rend(); ++it) {
      if (it->id == id) return &*it;
    }
    return nullptr;
  }
  /// The first occurrence of the key `id` / `name` (known or not; an unknown key's name is
  /// compared without regard to case). Object lists and comments have hundreds of keys: past a
  /// few, the names of unknown keys are looked up in a map instead of compared one by one.
  [[nodiscard]] const ini_key *find_first(key id, std::string_view key_name) {
    const key_range keys = this->keys();
    if (id != key::other) {
      if ((known_ & key_bit(id)) == 0U) return nullptr;
      for (const auto &x : keys) {
        if (x.id == id) return &x;
      }
      return nullptr;
    }
    if (keys.size() >= 16U) {
      if (!others_) {
        others_ = std::make_unique<other_map>();
        for (std::size_t i = 0; i < keys.size(); ++i) {
          if (keys[i].id == key::other) others_->emplace(keys[i].name, i);
        }
      }
      auto it = others_->find(key_name);
      return it == others_->end() ? nullptr : &keys[it->second];
    }
    for (const auto &x : keys) {
      if (x.id == key::other && iequals(x.name, key_name)) return &x;
    }
    return nullptr;
  }
  /// Appends a key (keeps the map of unknown names, once there is one, up to date).
  void add(const ini_key &k) {
    if (others_ && k.id == key::other) others_->emplace(k.name, count_);
    known_ |= key_bit(k.id);
    if (first_ + count_ != list_->size()) { // a merge: the keys of another section follow
      own_ = std::make_unique<std::vector<ini_key>>(keys().begin(), keys().end());
      list_ = own_.get();
      first_ = 0;
    }
    list_->push_back(k);
    ++count_;
  }

private:
  // name (any case) -> first position
  using other_map = std::unordered_map<std::string_view, std::size_t, ci_hash, ci_equal>;
  std::vector<ini_key> *list_; // the reader's list of every key, or own_
  std::size_t first_;
  std::size_t count_ = 0;
  std::unique_ptr<std::vector<ini_key>> own_; // after a merge
  std::unique_ptr<other_map> others_;
  std::uint32_t known_ = 0; // key_bit of every key present
};

struct classified {
  section_kind kind = section_kind::other;
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
};

/// 1..max upper-case hex digits (the section name is upper-cased first).
bool hex_digits(std::string_view s, std::size_t max, std::uint32_t &v) {
  if (s.size() > max) return false;
  const auto r = ascii::parse_hex(s, ascii::hex_case::upper);
  if (!r) return false;
  v = static_cast<std::uint32_t>(r.value());
  return true;
}

classified classify(const std::string &upper) {
  classified c;
  std::uint32_t v = 0;
  if (hex_digits(upper, 4, v)) {
    c.kind = section_kind::object;
    c.index = static_cast<std::uint16_t>(v);
    return c;
  }
  const auto sub = upper.find("SUB");
  if (sub != std::string::npos && sub > 0U) {
    std::uint32_t s = 0;
    if (hex_digits(upper.substr(0, sub), 4, v) && hex_digits(upper.substr(sub + 3U), 2, s)) {
      c.kind = section_kind::sub;
      c.index = static_cast<std::uint16_t>(v);
      c.sub = static_cast<std::uint8_t>(s);
      return c;
    }
  }
  for (auto [suffix, kind] :
       {std::pair{std::string_view("NAME"), section_kind::names},
        std::pair{std::string_view("VALUE"), section_kind::values},
        std::pair{std::string_view("DENOTATION"), section_kind::denotations},
        std::pair{std::string_view("OBJECTLINKS"), section_kind::object_links}}) {
    if (upper.size() > suffix.size() && upper.ends_with(suffix) &&
        hex_digits(upper.substr(0, upper.size() - suffix.size()), 4, v)) {
      c.kind = kind;
      c.index = static_cast<std::uint16_t>(v);
      return c;
    }
  }
  return c;
}

// Sections of tools and modular devices: kept for the EDS export without a warning.
bool known_other_section(const std::string &u) {
  static const std::set<std::string> names{
      "TOOLS",          "TOOLINFOS", "DYNAMICCHANNELS", "SUPPORTEDMODULES", "CONNECTEDMODULES",
      "TYPEDEFINITIONS"};
  if (names.count(u) != 0U) return true;
  if (u.starts_with("TOOL") && u.size() > 4U &&
      std::all_of(u.begin() + 4, u.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return true;
  }
  // modular devices: [M1ModuleInfo], [M1FixedObjects], [M1SubExtends], [M1Comments], ...
  if (u.size() > 1U && u[0] == 'M' && u[1] >= '0' && u[1] <= '9') return true;
  // what an XDD holds beyond CiA 306 ([XDD.GeneralFeatures], ...; the XDD reader's sections,
  // which the XDD writer writes back)
  return u.starts_with("XDD.");
}

// Sections the reader interprets.
bool interpreted_section(const std::string &u) {
  static const std::set<std::string> names{
      "FILEINFO",           "DEVICEINFO",      "DUMMYUSAGE",          "COMMENTS",
      "MANDATORYOBJECTS",   "OPTIONALOBJECTS", "MANUFACTUREROBJECTS", "DEVICECOMISSIONING",
      "DEVICECOMMISSIONING"};
  return names.count(u) != 0U;
}

// The value keys of an entry: where a key's number, node-ID flag and text go.
struct value_slot {
  key id;
  od::number entry::*number;
  bool entry::*nodeid;
  rare_text entry::*text; // nullptr: a limit (byte strings have none)
};
constexpr value_slot value_slots[] = {
    {key::default_value, &entry::default_value, &entry::default_nodeid, &entry::default_text},
    {key::parameter_value, &entry::parameter_value, &entry::parameter_nodeid,
     &entry::parameter_text},
    {key::low_limit, &entry::low, &entry::low_nodeid, nullptr},
    {key::high_limit, &entry::high, &entry::high_nodeid, nullptr},
};

class eds_reader {
public:
  eds_reader(const std::string &file, diagnostics &diag) : file_(file), diag_(diag) {}

  std::optional<dictionary> read(std::string_view bytes) {
    bool converted = false;
    text_ = as_utf8(bytes, converted_, converted); // `bytes` outlive the reader
    if (!split(text_)) return std::nullopt;
    if (sections_.empty()) {
      // a file whose only section header was bad has had its error: it is not "empty"
      if (!header_failed_) {
        diag_.error(file_, 1, 1,
                    trim(text_).empty()
                        ? "expected a section such as '[FileInfo]', got an empty file"
                        : "expected a section such as '[FileInfo]', got none");
      }
      return std::nullopt;
    }
    index_sections();
    dict_.entries.reserve(expected_entries());
    header_sections();
    objects();
    if (diag_.too_many()) return std::nullopt;
    object_lists();
    check_pdo_pairs(dict_, file_, diag_);
    if (diag_.has_errors()) return std::nullopt;
    // Objects are read in index order, so the entries are sorted already unless the file has
    // sub-objects out of order; sorting moves whole entries, so look first.
    const auto by_address = [](const entry &a, const entry &b) {
      return a.index != b.index ? a.index < b.index : a.sub < b.sub;
    };
    if (!std::is_sorted(dict_.entries.begin(), dict_.entries.end(), by_address)) {
      std::sort(dict_.entries.begin(), dict_.entries.end(), by_address);
    }
    return std::move(dict_);
  }

private:
  // ---- lexing ----------------------------------------------------------------------------
  // Splits the text into sections of keys. Returns false when reading stops (a NUL byte, too
  // many errors).
  bool split(std::string_view text) {
    // The list of keys reserved for a key per 16 bytes (real files have one per 20..30 bytes;
    // the list grows should a file have more, ini_section refers to its keys by position).
    keys_.reserve(text.size() / 16U + 16U);
    int line_no = 0;
    std::size_t pos = 0;
    ini_section *current = nullptr;
    while (pos < text.size()) {
      // The line ends at the first CR or LF; other bytes below 0x20 except TAB are reported.
      // Eight bytes at a time: (w - 0x20..) & ~w & 0x80.. flags the first byte below 0x20.
      std::size_t end = pos;
      bool control = false;
      for (;;) {
        while (end + 8U <= text.size()) {
          std::uint64_t w = 0;
          std::memcpy(&w, text.data() + end, 8);
          if (((w - 0x2020202020202020U) & ~w & 0x8080808080808080U) != 0U) break;
          end += 8U;
        }
        while (end < text.size() && static_cast<unsigned char>(text[end]) >= 0x20U) ++end;
        if (end >= text.size() || text[end] == '\n' || text[end] == '\r') break;
        if (text[end] != '\t') control = true;
        ++end;
      }
      const std::string_view line(text.data() + pos, end - pos);
      ++line_no;
      if (end < text.size() && text[end] == '\r' && end + 1U < text.size() &&
          text[end + 1U] == '\n') {
        pos = end + 2U;
      } else {
        pos = end + 1U;
      }
      if (control) {
        if (control_character(line, line_no) == 0) return false;
        if (diag_.too_many()) return false;
        continue;
      }
      std::size_t lead = 0;
      while (lead < line.size() && (line[lead] == ' ' || line[lead] == '\t')) ++lead;
      const std::string_view t = trim(line);
      if (t.empty() || t.front() == ';' || t.front() == '#') continue;
      if (t.front() == '[') {
        current = section_header(t, lead, line_no);
      } else {
        key_line(line, t, lead, line_no, current);
      }
      if (diag_.too_many()) return false;
    }
    return true;
  }

  // 1: no control character; -1: one was reported (the line is skipped); 0: a NUL byte (binary
  // data, reading stops).
  int control_character(std::string_view line, int line_no) {
    for (std::size_t i = 0; i < line.size(); ++i) {
      const auto c = static_cast<unsigned char>(line[i]);
      if (c < 0x20U && c != '\t') {
        diag_.error(file_, line_no, static_cast<int>(i) + 1,
                    "unexpected control character 0x" + hex(c, 2) +
                        (c == 0U ? " (binary data, not a text file); reading stopped" : ""));
        return c == 0U ? 0 : -1;
      }
    }
    return 1;
  }

  // "[name]" (t is the trimmed line, `lead` its indentation). Returns the new section, or
  // nullptr after an error (the keys that follow are skipped).
  ini_section *section_header(std::string_view t, std::size_t lead, int line_no) {
    const auto close = t.find(']');
    if (close == std::string_view::npos) {
      diag_.error(file_, line_no, static_cast<int>(lead + t.size()) + 1,
                  "expected ']' to end section name '" + std::string(t.substr(1)) +
                      "' (the section header is not closed)");
      header_failed_ = true;
      return nullptr;
    }
    const std::string_view rest = trim(t.substr(close + 1U));
    if (!rest.empty() && rest.front() != ';') {
      diag_.warning(file_, line_no, static_cast<int>(lead + close) + 2,
                    "text after ']' ignored: '" + rest + "'");
    }
    const std::string name(trim(t.substr(1, close - 1U)));
    if (name.empty()) {
      diag_.error(file_, line_no, static_cast<int>(lead) + 2, "expected a section name");
      header_failed_ = true;
      return nullptr;
    }
    ini_section &section = sections_.emplace_back(keys_);
    section.name = name;
    section.upper = to_upper(name);
    section.line = line_no;
    return &section;
  }

  void key_line(std::string_view line, std::string_view t, std::size_t lead, int line_no,
                ini_section *current) {
    const auto eq = line.find('=');
    if (eq == std::string_view::npos) {
      diag_.error(file_, line_no, static_cast<int>(lead) + 1,
                  "expected 'key=value', got '" + std::string(t) + "'");
      return;
    }
    if (current == nullptr) {
      if (sections_.empty() && !header_failed_) {
        diag_.error(file_, line_no, static_cast<int>(lead) + 1,
                    "expected a section header such as '[FileInfo]' before the first key");
      }
      return; // keys of a section whose header was bad: already reported
    }
    const std::string_view name = trim(line.substr(0, eq));
    std::size_t vstart = eq + 1U;
    while (vstart < line.size() && (line[vstart] == ' ' || line[vstart] == '\t')) ++vstart;
    if (name.empty()) {
      diag_.error(file_, line_no, static_cast<int>(lead) + 1, "expected a key before '='");
      return;
    }
    const key id = key_of(name);
    if (const ini_key *first = current->find_first(id, name)) {
      diag_.warning(file_, line_no, static_cast<int>(lead) + 1,
                    "key '" + name + "' appears again in [" + current->name + "] (first at line " +
                        std::to_string(first->line) + "); the last value is used");
    }
    current->add({name, trim(line.substr(eq + 1U)), line_no, static_cast<int>(vstart) + 1, id});
  }

  void index_sections() {
    for (auto &s : sections_) {
      const classified c = classify(s.upper);
      s.kind = c.kind;
      switch (c.kind) {
      case section_kind::object: {
        auto [it, fresh] = objects_.emplace(c.index, &s);
        if (!fresh) {
          diag_.error(file_, s.line, 2,
                      "duplicate object 0x" + hex(c.index, 4) + " (first defined at line " +
                          std::to_string(it->second->line) + ")");
        }
        break;
      }
      case section_kind::sub: {
        auto [it, fresh] = subs_[c.index].emplace(c.sub, &s);
        if (!fresh) {
          diag_.error(file_, s.line, 2,
                      "duplicate sub-object 0x" + hex(c.index, 4) + " sub-index 0x" +
                          hex(c.sub, 2) + " (first defined at line " +
                          std::to_string(it->second->line) + ")");
        }
        break;
      }
      case section_kind::names: per_object(names_, c.index, s); break;
      case section_kind::values: per_object(values_, c.index, s); break;
      case section_kind::denotations: per_object(denotations_, c.index, s); break;
      case section_kind::object_links: per_object(links_, c.index, s); break;
      case section_kind::other: {
        auto [it, fresh] = others_.emplace(s.upper, &s);
        if (!fresh) {
          diag_.warning(file_, s.line, 2,
                        "section [" + s.name + "] appears again (first at line " +
                            std::to_string(it->second->line) + "); keys are merged");
          for (const auto &k : s.keys()) it->second->add(k);
        }
        break;
      }
      }
    }
  }

  // At most one entry per section, and the sub-objects of CompactSubObj objects (they have no
  // sections): reserved at once, entries are never moved (moving one costs its strings).
  std::size_t expected_entries() const {
    std::size_t n = sections_.size();
    for (const auto &[index, s] : objects_) {
      for (const auto &k : s->keys()) {
        if (k.id != key::compact_sub_obj) continue;
        const int_parse p = parse_int(trim(k.value.substr(0, k.value.find(';'))));
        auto c = p.value.to_uint64();
        if (p.ok && c && c.value() <= 0xFEU) n += static_cast<std::size_t>(c.value()) + 1U;
      }
    }
    return n;
  }

  // [xxxxName], [xxxxValue], [xxxxDenotation], [xxxxObjectLinks]: one per object.
  void per_object(std::map<std::uint16_t, const ini_section *> &sections, std::uint16_t index,
                  const ini_section &s) {
    auto [it, fresh] = sections.emplace(index, &s);
    if (!fresh) {
      diag_.error(file_, s.line, 2,
                  "duplicate section [" + s.name + "] (first defined at line " +
                      std::to_string(it->second->line) + ")");
    }
  }

  const ini_section *other(std::string_view upper) const {
    auto it = others_.find(std::string(upper));
    return it == others_.end() ? nullptr : it->second;
  }

  static void copy_keys(const ini_section *s, key_list &out) {
    if (s == nullptr) return;
    for (const auto &k : s->keys()) out.emplace_back(k.name, k.value);
  }

  void header_sections() {
    const ini_section *fi = other("FILEINFO");
    const ini_section *di = other("DEVICEINFO");
    if (fi == nullptr) diag_.warning(file_, 1, 1, "missing section [FileInfo]");
    if (di == nullptr) diag_.warning(file_, 1, 1, "missing section [DeviceInfo]");
    copy_keys(fi, dict_.file_info);
    copy_keys(di, dict_.device_info);
    copy_keys(other("DUMMYUSAGE"), dict_.dummy_usage);
    if (const ini_section *c = other("COMMENTS")) {
      for (const auto &k : c->keys()) {
        if (k.name.size() >= 4U && iequals(k.name.substr(0, 4), "LINE") &&
            !iequals(k.name, "LINES")) {
          dict_.comments.emplace_back(k.value);
        }
      }
    }
    commissioning();
    for (const auto &s : sections_) {
      if (s.kind != section_kind::other || interpreted_section(s.upper)) continue;
      if (others_.find(s.upper)->second != &s) continue; // merged into the first one
      if (!known_other_section(s.upper)) {
        diag_.warning(file_, s.line, 2,
                      "unknown section [" + s.name + "] not interpreted (kept in the EDS export)");
      }
      other_section o;
      o.name = s.name;
      copy_keys(&s, o.keys);
      dict_.other_sections.push_back(std::move(o));
    }
  }

  void commissioning() {
    const ini_section *dc = other("DEVICECOMISSIONING");
    if (dc == nullptr) dc = other("DEVICECOMMISSIONING");
    if (dc == nullptr) return;
    dict_.is_dcf = true;
    copy_keys(dc, dict_.commissioning);
    if (const ini_key *k = dc->find(key::node_id); k != nullptr && !k->value.empty()) {
      const std::string_view v = value_of(*dc, *k);
      const int_parse p = parse_int(v);
      auto id = p.value.to_int64();
      if (!p.ok || !id || id.value() < 1 || id.value() > 127) {
        diag_.warning(file_, k->line, k->value_col,
                      "expected a node-ID 1..127, got '" + v + "'; ignored");
      } else {
        dict_.node_id = static_cast<int>(id.value());
      }
    }
    if (const ini_key *k = dc->find(key::node_name)) dict_.node_name = k->value;
  }

  // ---- values ----------------------------------------------------------------------------
  static int column(const ini_key &k, std::string_view v, std::size_t pos) {
    return k.value_col +
           static_cast<int>(static_cast<std::size_t>(v.data() - k.value.data()) + pos);
  }

  void bad_value(const ini_section &s, const ini_key &k, const std::string &what,
                 std::string_view v, std::size_t pos) {
    diag_.error(file_, k.line, column(k, v, pos), what + " in " + k.name + " of [" + s.name + "]");
  }

  // The value of a key that holds a number or a keyword: text from a ';' on is a comment
  // (`DefaultValue=0x3ED ; prevent homing`), ignored with a warning (an error under --strict).
  std::string_view value_of(const ini_section &s, const ini_key &k) {
    const auto semi = k.value.find(';');
    if (semi == std::string_view::npos) return k.value;
    diag_.warning(file_, k.line, k.value_col + static_cast<int>(semi),
                  "comment after the value of " + k.name + " in [" + s.name + "] ignored: '" +
                      k.value.substr(semi) + "'");
    return trim(k.value.substr(0, semi));
  }

  // A number of an entry's type in `v` (the value of `k` without its comment): an integer, a
  // real, a TIME value or a $NODEID expression. Returns false after reporting an error.
  bool number_value(const ini_section &s, const ini_key &k, std::string_view v, od::data_type type,
                    od::number &out, bool &nodeid) {
    nodeid = false;
    const nodeid_expr x = split_nodeid(v);
    if (x.present) {
      nodeid = true;
      return nodeid_value(s, k, v, x, type, out);
    }
    if (od::is_time(type) && v.find(' ') != std::string_view::npos) return time_value(s, k, v, out);
    if (od::is_real(type)) {
      const real_parse r = parse_real_value(v, type);
      if (!r.ok) {
        bad_value(s, k, r.error, v, r.error_pos);
        return false;
      }
      out = od::real_number(r.value);
      return true;
    }
    return integer_value(s, k, v, type, out);
  }

  // `$NODEID+<number>` / `<number>+$NODEID` / `$NODEID`: the number is kept, node-ID relative.
  bool nodeid_value(const ini_section &s, const ini_key &k, std::string_view v,
                    const nodeid_expr &x, od::data_type type, od::number &out) {
    if (!x.ok) {
      bad_value(s, k, "expected '$NODEID+<number>' or '<number>+$NODEID', got '" + v + "'", v, 0);
      return false;
    }
    const int_parse p = parse_int(x.operand.empty() ? std::string_view("0") : x.operand);
    if (!p.ok) {
      bad_value(s, k, p.error, v, x.operand_pos + p.error_pos);
      return false;
    }
    out = p.value;
    if (od::is_unsigned_integer(type) && out.kind == od::number_kind::signed_ &&
        static_cast<std::int64_t>(out.bits) >= 0) {
      out = od::unsigned_number(out.bits);
    }
    if (od::is_integer(type)) {
      for (const std::uint8_t node : {std::uint8_t{1}, std::uint8_t{127}}) {
        auto at = plus_node(out, node);
        if (!at || !fits(type, *at)) {
          diag_.warning(file_, k.line, k.value_col,
                        "value '" + v + "' does not fit " + std::string(od::name(type)) +
                            " for node-ID " + std::to_string(node) + " (" + k.name + " of [" +
                            s.name + "])");
          break;
        }
      }
    }
    return true;
  }

  // "<days> <milliseconds>" as lely writes TIME_OF_DAY / TIME_DIFFERENCE.
  bool time_value(const ini_section &s, const ini_key &k, std::string_view v, od::number &out) {
    const auto sp = v.find(' ');
    const int_parse days = parse_int(v.substr(0, sp));
    const int_parse ms = parse_int(v.substr(sp + 1U));
    auto dv = days.value.to_uint64();
    auto mv = ms.value.to_uint64();
    if (!days.ok || !ms.ok || !dv || !mv || dv.value() > 0xFFFFU || mv.value() > od::time_ms_max) {
      bad_value(s, k, "expected '<days 0..65535> <milliseconds 0..268435455>', got '" + v + "'", v,
                0);
      return false;
    }
    out = od::to_number(od::time_value{static_cast<std::uint32_t>(mv.value()),
                                       static_cast<std::uint16_t>(dv.value())});
    return true;
  }

  bool integer_value(const ini_section &s, const ini_key &k, std::string_view v, od::data_type type,
                     od::number &out) {
    int_parse p = parse_int(v);
    if (!p.ok) {
      // a decimal fraction for an integer type ("0.0"): keep it exactly, warn
      if (auto d = parse_decimal(v); d && v.find('.') != std::string_view::npos) {
        diag_.warning(file_, k.line, column(k, v, 0),
                      "expected an integer, got '" + v + "' in " + k.name + " of [" + s.name + "]");
        out = od::decimal_number(d.value());
        return true;
      }
      bad_value(s, k, p.error, v, p.error_pos);
      return false;
    }
    if (p.suffix) {
      diag_.warning(file_, k.line, column(k, v, 0),
                    "C integer suffix in '" + v + "' ignored (" + k.name + " of [" + s.name + "])");
    }
    p.value = integer_for_type(p.value, type);
    if (od::is_integer(type) || type == od::data_type::boolean) {
      if (!fits(type, p.value)) {
        diag_.warning(file_, k.line, column(k, v, 0),
                      "value '" + v + "' does not fit " + std::string(od::name(type)) + " (" +
                          k.name + " of [" + s.name + "])");
      }
    }
    out = p.value;
    return true;
  }

  // A count or code key (ObjectType, SubNumber, CompactSubObj, Size, ObjFlags): 0..max.
  struct counted {
    bool ok = true;       ///< false after an error was reported
    bool present = false; ///< the key has a value
    std::uint32_t value = 0;
    const ini_key *key = nullptr;
    std::string_view text; ///< the value without its comment
  };
  counted count_key(const ini_section &s, key id, std::uint32_t max, std::uint32_t absent = 0) {
    counted c;
    c.value = absent;
    c.key = s.find(id);
    if (c.key == nullptr || c.key->value.empty()) return c;
    c.text = value_of(s, *c.key);
    if (c.text.empty()) return c;
    const int_parse p = parse_int(c.text);
    auto n = p.value.to_uint64();
    if (!p.ok || !n || n.value() > max) {
      bad_value(s, *c.key,
                p.ok ? "expected a number 0.." + std::to_string(max) + ", got '" + c.text + "'"
                     : p.error,
                c.text, p.error_pos);
      c.ok = false;
      return c;
    }
    c.value = static_cast<std::uint32_t>(n.value());
    c.present = true;
    return c;
  }

  // ---- keys of a VAR-like section ---------------------------------------------------------
  void unknown_key(const ini_section &s, const ini_key &k) {
    diag_.warning(file_, k.line, 1,
                  "unknown key '" + k.name + "' in [" + s.name +
                      "] not interpreted (kept in the EDS export)");
  }

  // Keys of a VAR-like section the reader does not interpret go to `out` (kept for the EDS
  // export); unknown ones are reported.
  void other_keys(const ini_section &s, key_list &out) {
    for (const auto &k : s.keys()) {
      if (interpreted_key(k.id)) continue;
      if (!known_other_key(k.id)) unknown_key(s, k);
      out.emplace_back(k.name, k.value);
    }
  }

  // The same for the object section of an ARRAY / RECORD / DEFSTRUCT with sub-object sections:
  // everything but its name, code, sub-object count and ObjFlags is kept as written (a DataType
  // or DefaultValue there describes no entry).
  void container_keys(const ini_section &s, key_list &out) {
    for (const auto &k : s.keys()) {
      if (k.id == key::parameter_name || k.id == key::object_type || k.id == key::sub_number ||
          k.id == key::compact_sub_obj || k.id == key::obj_flags) {
        continue;
      }
      if (!interpreted_key(k.id) && !known_other_key(k.id)) unknown_key(s, k);
      out.emplace_back(k.name, k.value);
    }
  }

  std::string parameter_name(const ini_section &s) {
    if (const ini_key *k = s.find(key::parameter_name)) return std::string(k->value);
    diag_.warning(file_, s.line, 2, "missing ParameterName in [" + s.name + "]");
    return s.name;
  }

  bool data_type_key(const ini_section &s, entry &e) {
    const ini_key *k = s.find(key::data_type);
    if (k == nullptr || k->value.empty()) {
      diag_.error(file_, s.line, 2, "missing DataType in [" + s.name + "]");
      return false;
    }
    const std::string_view v = value_of(s, *k);
    const int_parse p = parse_int(v);
    auto code = p.value.to_uint64();
    if (!p.ok || !code || code.value() == 0U || code.value() > 0xFFFFU) { // 0: no type (fuzz F6)
      bad_value(s, *k, p.ok ? "expected a data type 0x0001..0xFFFF" : p.error, v, p.error_pos);
      return false;
    }
    e.type_code = static_cast<std::uint16_t>(code.value());
    if (const od::data_type_info *t = od::find_data_type(e.type_code)) {
      e.type = t->type;
    } else {
      e.type = od::data_type::domain;
      diag_.warning(file_, k->line, k->value_col,
                    "data type 0x" + hex(e.type_code, 4) + " of [" + s.name +
                        "] is not a basic type (0x0001..0x001B); its value is kept as DOMAIN");
    }
    return true;
  }

  bool access_key(const ini_section &s, entry &e) {
    const ini_key *k = s.find(key::access_type);
    if (k == nullptr || k->value.empty()) {
      diag_.warning(file_, s.line, 2, "missing AccessType in [" + s.name + "]; taken as ro");
      e.access = od::access::ro;
      return true;
    }
    const std::string_view v = value_of(s, *k);
    if (const od::access_info *a = od::find_access(to_lower(v))) {
      e.access = a->value;
      return true;
    }
    bad_value(s, *k, "expected ro, wo, rw, rwr, rww or const, got '" + v + "'", v, 0);
    return false;
  }

  bool pdo_mapping_key(const ini_section &s, entry &e) {
    const ini_key *k = s.find(key::pdo_mapping);
    if (k == nullptr || k->value.empty()) return true;
    const std::string_view v = value_of(s, *k);
    const int_parse p = parse_int(v);
    auto n = p.value.to_uint64();
    if (!p.ok || !n || n.value() > 1U) {
      bad_value(s, *k, "expected 0 or 1, got '" + v + "'", v, 0);
      return false;
    }
    e.pdo = n.value() == 1U ? od::pdo_mapping::yes : od::pdo_mapping::no;
    return true;
  }

  bool obj_flags_key(const ini_section &s, std::uint32_t &flags, bool &present) {
    const counted c = count_key(s, key::obj_flags, 0xFFFF'FFFFU);
    flags = c.value;
    present = c.present;
    return c.ok;
  }

  // Size=<bytes>: the capacity of a byte string (fieldcodec's extension, docs/dictionary-
  // formats.md); for any other type it must agree with the type's size.
  bool size_key(const ini_section &s, entry &e) {
    const counted c = count_key(s, key::size, 0xFFFF'FFFFU);
    if (!c.ok || !c.present) return c.ok;
    const ini_key *k = c.key;
    const std::string_view v = c.text;
    const std::uint32_t size = c.value;
    if (size == 0U) {
      bad_value(s, *k, "expected a size 1..4294967295 bytes, got '" + v + "'", v, 0);
      return false;
    }
    if (od::is_byte_string(e.type)) {
      e.size = size;
      e.size_declared = true;
      return true;
    }
    if (size != od::fixed_size(e.type)) {
      bad_value(s, *k,
                "size " + v + " disagrees with " + std::string(od::name(e.type)) + " (" +
                    std::to_string(od::fixed_size(e.type)) + " bytes)",
                v, 0);
      return false;
    }
    return true;
  }

  // One value key of `slot` from `k` (a key of section `s`) into `e`.
  bool value_key(const ini_section &s, const ini_key &k, const value_slot &slot, entry &e) {
    if (k.value.empty()) return true;
    if (!od::is_byte_string(e.type)) {
      const std::string_view v = value_of(s, k);
      if (v.empty()) return true;
      return number_value(s, k, v, e.type, e.*slot.number, e.*slot.nodeid);
    }
    if (slot.text == nullptr) {
      diag_.warning(file_, k.line, k.value_col,
                    std::string(k.name) + " of [" + s.name + "] ignored: a " +
                        std::string(od::name(e.type)) + " has no limits");
      return true;
    }
    // a VISIBLE_STRING / UNICODE_STRING is text (a ';' in it is a character); an OCTET_STRING or
    // DOMAIN is hex digits, which a comment may follow
    const bool text =
        e.type == od::data_type::visible_string || e.type == od::data_type::unicode_string;
    const std::string_view v = text ? k.value : value_of(s, k);
    if (auto bytes = byte_string_value(e.type, v)) {
      e.*slot.text = std::move(*bytes);
    } else {
      diag_.warning(file_, k.line, k.value_col,
                    std::string(k.name) + " '" + v + "' of [" + s.name +
                        "] ignored: " + std::string(od::name(e.type)) +
                        " values are written as hex digits, two per byte");
    }
    return true;
  }

  // The capacity of a byte string without a declared size is the length of its longest value;
  // a declared size must hold both values. `value` is the key of the DCF value when it is not
  // the section's ParameterValue ([xxxxValue] of a CompactSubObj object).
  bool capacity(const ini_section &s, entry &e, const ini_key *value = nullptr) {
    if (!od::is_byte_string(e.type)) return true;
    const std::size_t longest = std::max(e.default_text.size(), e.parameter_text.size());
    if (!e.size_declared) {
      e.size = static_cast<std::uint32_t>(std::min<std::size_t>(longest, 0xFFFF'FFFFU));
      return true;
    }
    if (longest <= e.size) return true;
    const bool dflt = e.default_text.size() == longest;
    const ini_key *k = dflt               ? s.find(key::default_value)
                       : value != nullptr ? value
                                          : s.find(key::parameter_value);
    diag_.error(file_, k != nullptr ? k->line : s.line, k != nullptr ? k->value_col : 2,
                (k != nullptr ? std::string(k->name) : std::string("the value")) + " of [" +
                    s.name + "] is " + std::to_string(longest) +
                    " bytes, more than its Size=" + std::to_string(e.size));
    return false;
  }

  // Fills `e` from the keys of a VAR-like section (a VAR object, a sub-object, or the object
  // section of a CompactSubObj object). Returns false when an error was reported.
  bool var_keys(const ini_section &s, entry &e) {
    other_keys(s, e.other_keys);
    e.name = parameter_name(s);
    const bool typed = data_type_key(s, e);
    bool ok = access_key(s, e) && typed;
    ok = pdo_mapping_key(s, e) && ok;
    ok = obj_flags_key(s, e.obj_flags, e.has_obj_flags) && ok;
    if (typed) { // the values and the size are read as the data type says
      ok = size_key(s, e) && ok;
      for (const auto &slot : value_slots) {
        if (const ini_key *k = s.find(slot.id)) ok = value_key(s, *k, slot, e) && ok;
      }
      ok = capacity(s, e) && ok;
    }
    if (const ini_key *k = s.find(key::denotation)) e.denotation = k->value;
    if (!e.parameter_text.empty() || e.parameter_value.has_value() || !e.denotation.empty()) {
      dict_.is_dcf = true;
    }
    return ok;
  }

  // ---- objects ---------------------------------------------------------------------------
  void objects() {
    for (const auto &[index, subs] : subs_) {
      if (objects_.count(index) == 0U) {
        const ini_section *first = subs.begin()->second;
        diag_.error(file_, first->line, 2,
                    "sub-object section [" + first->name + "] without object section [" +
                        hex(index, 4) + "]");
      }
    }
    for (const auto *sections : {&names_, &values_, &denotations_, &links_}) {
      for (const auto &[index, s] : *sections) {
        if (objects_.count(index) == 0U) {
          diag_.warning(file_, s->line, 2,
                        "section [" + s->name + "] without object section [" + hex(index, 4) +
                            "] ignored");
        }
      }
    }
    for (const auto &[index, s] : objects_) {
      if (diag_.too_many()) return;
      object(index, *s);
    }
  }

  bool object_code_key(const ini_section &s, object_info &info) {
    const counted c = count_key(s, key::object_type, 0xFF, 7); // no ObjectType: a VAR
    if (!c.ok) return false;
    // 0x0 (NULL) is refused like the other undefined codes: it has no data type, so the writer
    // could not write it back readably (fuzz F11).
    const od::object_code_info *code = od::find_object_code(c.value);
    if (code == nullptr || code->code == od::object_code::null) {
      bad_value(s, *c.key,
                "expected object type 0x2, 0x5, 0x6, 0x7, 0x8 or 0x9, got '" + c.text + "'", c.text,
                0);
      return false;
    }
    info.code = code->code;
    return true;
  }

  void object(std::uint16_t index, const ini_section &s) {
    object_info info;
    info.index = index;
    info.line = s.line;
    if (!object_code_key(s, info)) return;
    info.name = parameter_name(s);
    const counted sub_count = count_key(s, key::sub_number, 0xFF);
    const counted compact_count = count_key(s, key::compact_sub_obj, 0xFE);
    if (!sub_count.ok || !compact_count.ok) return;
    const std::uint32_t sub_number = sub_count.value;
    const std::uint32_t compact = compact_count.value;
    const bool has_sub_number = sub_count.present;
    const bool has_compact = compact_count.present;
    const bool composite = info.code == od::object_code::array ||
                           info.code == od::object_code::record ||
                           info.code == od::object_code::defstruct ||
                           (has_sub_number && sub_number > 0U) || (has_compact && compact > 0U);
    const auto sub_it = subs_.find(index);
    const bool has_subs = sub_it != subs_.end();
    bool ok = false;
    if (has_compact && compact > 0U) {
      ok = compact_object(index, s, info, compact, has_subs);
    } else {
      if (!composite && has_subs) {
        diag_.warning(file_, sub_it->second.begin()->second->line, 2,
                      "sub-object sections of [" + s.name + "] (object type " +
                          std::string(od::name(info.code)) + ", no SubNumber) ignored");
      }
      if (composite && !has_sub_number && !has_subs) {
        // an ARRAY/RECORD written like a VAR: keep its one value
        diag_.warning(file_, s.line, 2,
                      "[" + s.name + "] (object type " + std::string(od::name(info.code)) +
                          ") has no SubNumber, CompactSubObj or sub-object sections; read as one "
                          "entry at sub-index 0");
      }
      if (composite && (has_sub_number || has_subs)) {
        ok = sub_objects(index, s, info, has_sub_number, sub_number);
      } else {
        ok = var_object(index, s, info);
      }
      per_sub_sections_unused(index, s);
    }
    if (!ok) return;
    object_links(index, dict_.objects[index]);
  }

  // A VAR (or an object read as one entry at sub-index 0).
  bool var_object(std::uint16_t index, const ini_section &s, object_info &info) {
    // built in place: moving an entry costs its strings
    entry &e = dict_.entries.emplace_back();
    e.index = index;
    e.object = info.code;
    e.line = s.line;
    if (!var_keys(s, e)) {
      dict_.entries.pop_back();
      return false;
    }
    dict_.objects[index] = std::move(info);
    return true;
  }

  // An ARRAY / RECORD / DEFSTRUCT with sub-object sections.
  bool sub_objects(std::uint16_t index, const ini_section &s, object_info &info,
                   bool has_sub_number, std::uint32_t sub_number) {
    bool ok = obj_flags_key(s, info.obj_flags, info.has_obj_flags);
    container_keys(s, info.other_keys);
    std::size_t count = 0;
    if (auto sub_it = subs_.find(index); sub_it != subs_.end()) {
      for (const auto &[sub, ss] : sub_it->second) {
        ++count;
        if (has_sub_number && count == sub_number + 1U) {
          diag_.warning(file_, ss->line, 2,
                        "sub-index 0x" + hex(sub, 2) + " of [" + ss->name +
                            "] is sub-object number " + std::to_string(count) + " but [" + s.name +
                            "] has SubNumber=" + std::to_string(sub_number) +
                            " (SubNumber counts sub-objects); all " +
                            std::to_string(sub_it->second.size()) + " are kept");
        }
        entry &e = dict_.entries.emplace_back(); // built in place
        e.index = index;
        e.sub = sub;
        e.object = info.code;
        e.line = ss->line;
        if (!var_keys(*ss, e)) {
          dict_.entries.pop_back();
          ok = false;
          continue;
        }
      }
    }
    if (!has_sub_number) {
      diag_.warning(file_, s.line, 2,
                    "missing SubNumber in [" + s.name + "]; " + std::to_string(count) +
                        " sub-object sections found");
    } else if (count < sub_number) {
      const ini_key *k = s.find(key::sub_number);
      diag_.warning(file_, k->line, k->value_col,
                    "[" + s.name + "] has SubNumber=" + std::to_string(sub_number) + " but " +
                        std::to_string(count) + " sub-object section" + (count == 1U ? "" : "s"));
    }
    info.sub_number = static_cast<std::uint8_t>(count);
    dict_.objects[index] = std::move(info);
    return ok;
  }

  // [xxxxName], [xxxxValue], [xxxxDenotation] belong to CompactSubObj objects only.
  void per_sub_sections_unused(std::uint16_t index, const ini_section &s) {
    for (const auto *sections : {&names_, &values_, &denotations_}) {
      if (auto it = sections->find(index); it != sections->end()) {
        diag_.warning(file_, it->second->line, 2,
                      "section [" + it->second->name + "] ignored: [" + s.name +
                          "] has no CompactSubObj");
      }
    }
  }

  // The keys "1".."n" of a per-sub-index section ([xxxxName], [xxxxValue], [xxxxDenotation]).
  std::map<std::uint32_t, const ini_key *>
  indexed_keys(const std::map<std::uint16_t, const ini_section *> &sections, std::uint16_t index,
               std::uint32_t compact) {
    std::map<std::uint32_t, const ini_key *> out;
    auto it = sections.find(index);
    if (it == sections.end()) return out;
    for (const auto &k : it->second->keys()) {
      if (k.id == key::nr_of_entries) continue;
      const int_parse p = parse_int(k.name);
      auto n = p.value.to_uint64();
      if (!p.ok || !n || n.value() < 1U || n.value() > compact) {
        diag_.warning(file_, k.line, 1,
                      "key '" + k.name + "' in [" + it->second->name + "] is not a sub-index 1.." +
                          std::to_string(compact) + "; ignored");
        continue;
      }
      out[static_cast<std::uint32_t>(n.value())] = &k;
    }
    return out;
  }

  // An ARRAY written with CompactSubObj=n: sub-index 0 (NrOfObjects) and n sub-objects from the
  // object's keys, named from [xxxxName], with DCF values from [xxxxValue] and [xxxxDenotation].
  bool compact_object(std::uint16_t index, const ini_section &s, object_info info,
                      std::uint32_t compact, bool has_subs) {
    if (has_subs) {
      diag_.warning(file_, subs_[index].begin()->second->line, 2,
                    "[" + s.name + "] has CompactSubObj; its sub-object sections are ignored");
    }
    info.compact_sub = static_cast<std::uint8_t>(compact);
    info.sub_number = static_cast<std::uint8_t>(compact + 1U);
    entry proto;
    proto.index = index;
    proto.object = info.code;
    proto.line = s.line;
    if (!var_keys(s, proto)) return false;
    // What the object section says about the object itself stays with the object.
    info.obj_flags = proto.obj_flags;
    info.has_obj_flags = proto.has_obj_flags;
    info.other_keys = std::move(proto.other_keys);
    proto.other_keys.clear();
    for (const key id : {key::parameter_value, key::denotation}) {
      if (const ini_key *k = s.find(id)) info.other_keys.emplace_back(k->name, k->value);
    }
    proto.parameter_value = {};
    proto.parameter_nodeid = false;
    proto.parameter_text.clear();
    proto.denotation.clear();
    proto.has_obj_flags = false;
    proto.obj_flags = 0;
    if (!proto.size_declared) proto.size = static_cast<std::uint32_t>(proto.default_text.size());

    entry sub0;
    sub0.index = index;
    sub0.object = info.code;
    sub0.line = s.line;
    sub0.name = "NrOfObjects";
    sub0.type_code = 0x0005;
    sub0.type = od::data_type::unsigned8;
    sub0.access = od::access::ro;
    sub0.default_value = od::unsigned_number(compact);
    dict_.entries.push_back(sub0);

    const auto names = indexed_keys(names_, index, compact);
    const auto values = indexed_keys(values_, index, compact);
    const auto denotations = indexed_keys(denotations_, index, compact);
    if (!values.empty() || !denotations.empty()) dict_.is_dcf = true;
    bool ok = true;
    for (std::uint32_t i = 1; i <= compact; ++i) {
      entry &e = dict_.entries.emplace_back(proto); // built in place
      e.sub = static_cast<std::uint8_t>(i);
      auto n = names.find(i);
      e.name = n != names.end() ? std::string(n->second->value) : proto.name + std::to_string(i);
      if (auto v = values.find(i); v != values.end()) {
        const ini_section &vs = *values_.find(index)->second;
        ok = value_key(vs, *v->second, value_slots[1], e) && ok;
        ok = capacity(vs, e, v->second) && ok;
      }
      if (auto d = denotations.find(i); d != denotations.end()) e.denotation = d->second->value;
    }
    dict_.objects[index] = std::move(info);
    return ok;
  }

  // [xxxxObjectLinks]: ObjectLinks=<n>, 1=<index>, ...
  void object_links(std::uint16_t index, object_info &info) {
    auto it = links_.find(index);
    if (it == links_.end()) return;
    const ini_section &s = *it->second;
    for (const auto &k : s.keys()) {
      if (k.id == key::object_links) continue;
      const std::string_view v = value_of(s, k);
      const int_parse p = parse_int(v);
      auto n = p.value.to_uint64();
      if (!p.ok || !n || n.value() > 0xFFFFU) {
        bad_value(s, k, p.ok ? "expected an object index 0x0000..0xFFFF, got '" + v + "'" : p.error,
                  v, p.error_pos);
        continue;
      }
      info.object_links.push_back(static_cast<std::uint16_t>(n.value()));
    }
  }

  void object_lists() {
    const std::pair<const char *, object_list> lists[] = {
        {"MANDATORYOBJECTS", object_list::mandatory},
        {"OPTIONALOBJECTS", object_list::optional},
        {"MANUFACTUREROBJECTS", object_list::manufacturer}};
    std::set<std::uint16_t> listed;
    bool any_list = false;
    for (const auto &[name, which] : lists) {
      const ini_section *s = other(name);
      if (s == nullptr) continue;
      any_list = true;
      for (const auto &k : s->keys()) {
        if (k.id == key::supported_objects) continue;
        const std::string_view v = value_of(*s, k);
        const int_parse p = parse_int(v);
        auto n = p.value.to_uint64();
        if (!p.ok || !n || n.value() > 0xFFFFU) {
          bad_value(*s, k, p.ok ? "expected an object index 0x0000..0xFFFF" : p.error, v,
                    p.error_pos);
          continue;
        }
        const auto index = static_cast<std::uint16_t>(n.value());
        listed.insert(index);
        if (objects_.count(index) == 0U) {
          diag_.warning(file_, k.line, k.value_col,
                        "object '" + v + "' listed in [" + s->name + "] has no section [" +
                            hex(index, 4) + "]");
          continue;
        }
        if (auto it = dict_.objects.find(index); it != dict_.objects.end()) it->second.list = which;
      }
    }
    if (!any_list) {
      diag_.warning(file_, 1, 1, "missing section [MandatoryObjects]");
      return;
    }
    for (const auto &[index, s] : objects_) {
      if (listed.count(index) == 0U && index >= 0x1000U) {
        diag_.warning(file_, s->line, 2,
                      "object [" + s->name +
                          "] is not listed in [MandatoryObjects], "
                          "[OptionalObjects] or [ManufacturerObjects]");
        if (auto it = dict_.objects.find(index); it != dict_.objects.end()) {
          it->second.list = default_list(index);
        }
      }
    }
  }

  const std::string &file_;
  diagnostics &diag_;
  bool header_failed_ = false;       // a "[…" line was refused: its keys are skipped silently
  std::string_view text_;            // the file as UTF-8; keys and values are views into it
  std::string converted_;            // the text when the file was not UTF-8
  std::vector<ini_key> keys_;        // every key of the file, in file order (ini_section::keys)
  std::deque<ini_section> sections_; // deque: pointers stay valid
  std::map<std::uint16_t, const ini_section *> objects_;
  std::map<std::uint16_t, std::map<std::uint8_t, const ini_section *>> subs_;
  std::map<std::uint16_t, const ini_section *> names_, values_, denotations_, links_;
  std::map<std::string, ini_section *> others_;
  dictionary dict_;
};

} // namespace

std::optional<dictionary> read_eds(std::string_view text, const std::string &file,
                                   diagnostics &diag) {
  eds_reader r(file, diag);
  return r.read(text);
}

} // namespace fieldcodec::gen
