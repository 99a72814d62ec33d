// fieldcodec — CiA 301 data types (0x0001..0x001B), object codes, access types, PDO mapping.
//
// One table per idea: `data_types` (code, CiA name, C++ enumerator name, size, class),
// `access_types` (EDS name, enumerator name, readable, writable), `object_codes` and
// `pdo_mappings`. The predicates below, the generator's readers and writers and the emitted
// headers all read these tables; nothing else spells a type or access name.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string_view>

namespace fieldcodec::od {

/// CiA 301 static data types; the enumerator's value is the type's object index / code.
/// 0x000E and 0x0017 are not assigned.
enum class data_type : std::uint16_t {
  boolean = 0x0001,
  integer8 = 0x0002,
  integer16 = 0x0003,
  integer32 = 0x0004,
  unsigned8 = 0x0005,
  unsigned16 = 0x0006,
  unsigned32 = 0x0007,
  real32 = 0x0008,
  visible_string = 0x0009,
  octet_string = 0x000A,
  unicode_string = 0x000B,
  time_of_day = 0x000C,
  time_difference = 0x000D,
  domain = 0x000F,
  integer24 = 0x0010,
  real64 = 0x0011,
  integer40 = 0x0012,
  integer48 = 0x0013,
  integer56 = 0x0014,
  integer64 = 0x0015,
  unsigned24 = 0x0016,
  unsigned40 = 0x0018,
  unsigned48 = 0x0019,
  unsigned56 = 0x001A,
  unsigned64 = 0x001B,
};

/// What a data type's value is.
enum class type_class : std::uint8_t {
  boolean,          ///< BOOLEAN (one byte on the wire)
  signed_integer,   ///< INTEGER8..INTEGER64, two's complement
  unsigned_integer, ///< UNSIGNED8..UNSIGNED64
  real,             ///< REAL32, REAL64 (IEEE 754)
  byte_string,      ///< VISIBLE_STRING, OCTET_STRING, UNICODE_STRING, DOMAIN: size per entry
  time,             ///< TIME_OF_DAY, TIME_DIFFERENCE (28-bit ms, 4 reserved bits, 16-bit days)
  unassigned,       ///< a value of the enumeration that is no type (0x000E, 0x0017, > 0x001B)
};

/// One row of the data type table.
struct data_type_info {
  data_type type;
  std::string_view name;       ///< CiA 301 / CiA 306 name, upper case ("UNSIGNED16")
  std::string_view identifier; ///< the enumerator's C++ name ("unsigned16")
  std::uint8_t size;           ///< bytes on the wire; 0 for byte strings (size per entry)
  type_class kind;
};

/// The 25 basic data types, in code order.
inline constexpr std::array<data_type_info, 25> data_types{{
    {data_type::boolean, "BOOLEAN", "boolean", 1, type_class::boolean},
    {data_type::integer8, "INTEGER8", "integer8", 1, type_class::signed_integer},
    {data_type::integer16, "INTEGER16", "integer16", 2, type_class::signed_integer},
    {data_type::integer32, "INTEGER32", "integer32", 4, type_class::signed_integer},
    {data_type::unsigned8, "UNSIGNED8", "unsigned8", 1, type_class::unsigned_integer},
    {data_type::unsigned16, "UNSIGNED16", "unsigned16", 2, type_class::unsigned_integer},
    {data_type::unsigned32, "UNSIGNED32", "unsigned32", 4, type_class::unsigned_integer},
    {data_type::real32, "REAL32", "real32", 4, type_class::real},
    {data_type::visible_string, "VISIBLE_STRING", "visible_string", 0, type_class::byte_string},
    {data_type::octet_string, "OCTET_STRING", "octet_string", 0, type_class::byte_string},
    {data_type::unicode_string, "UNICODE_STRING", "unicode_string", 0, type_class::byte_string},
    {data_type::time_of_day, "TIME_OF_DAY", "time_of_day", 6, type_class::time},
    {data_type::time_difference, "TIME_DIFFERENCE", "time_difference", 6, type_class::time},
    {data_type::domain, "DOMAIN", "domain", 0, type_class::byte_string},
    {data_type::integer24, "INTEGER24", "integer24", 3, type_class::signed_integer},
    {data_type::real64, "REAL64", "real64", 8, type_class::real},
    {data_type::integer40, "INTEGER40", "integer40", 5, type_class::signed_integer},
    {data_type::integer48, "INTEGER48", "integer48", 6, type_class::signed_integer},
    {data_type::integer56, "INTEGER56", "integer56", 7, type_class::signed_integer},
    {data_type::integer64, "INTEGER64", "integer64", 8, type_class::signed_integer},
    {data_type::unsigned24, "UNSIGNED24", "unsigned24", 3, type_class::unsigned_integer},
    {data_type::unsigned40, "UNSIGNED40", "unsigned40", 5, type_class::unsigned_integer},
    {data_type::unsigned48, "UNSIGNED48", "unsigned48", 6, type_class::unsigned_integer},
    {data_type::unsigned56, "UNSIGNED56", "unsigned56", 7, type_class::unsigned_integer},
    {data_type::unsigned64, "UNSIGNED64", "unsigned64", 8, type_class::unsigned_integer},
}};

/// True for the 25 assigned codes 0x01..0x1B.
[[nodiscard]] constexpr bool is_data_type(std::uint16_t code) noexcept {
  return code >= 0x01U && code <= 0x1BU && code != 0x0EU && code != 0x17U;
}

namespace detail {
/// Row of an assigned code in `data_types` (codes in order, two gaps: 0x0E and 0x17).
[[nodiscard]] constexpr std::size_t data_type_row(std::uint16_t code) noexcept {
  return std::size_t{code} - 1U - (code > 0x0EU ? 1U : 0U) - (code > 0x17U ? 1U : 0U);
}
/// What info() answers for a value of the enumeration that is no type.
inline constexpr data_type_info unassigned_type{data_type::domain, "", "", 0,
                                                type_class::unassigned};
} // namespace detail

/// The table row of a data type (an empty row of class `unassigned` for a value of the
/// enumeration that is no type).
[[nodiscard]] constexpr const data_type_info &info(data_type t) noexcept {
  const auto code = static_cast<std::uint16_t>(t);
  return is_data_type(code) ? data_types[detail::data_type_row(code)] : detail::unassigned_type;
}

/// The row of a code as written in a file; nullptr when the code is not a basic type.
[[nodiscard]] constexpr const data_type_info *find_data_type(std::uint16_t code) noexcept {
  return is_data_type(code) ? &data_types[detail::data_type_row(code)] : nullptr;
}

/// The row of a CiA name ("UNSIGNED16", exact spelling); nullptr when there is none.
[[nodiscard]] constexpr const data_type_info *find_data_type(std::string_view name) noexcept {
  for (const auto &row : data_types) {
    if (row.name == name) return &row;
  }
  return nullptr;
}

namespace detail {
/// Class and size of every code 0x00..0x1B (class << 4 | size): the columns of data_types
/// without its names. The predicates below read this, so that an image that reads no type name
/// links none (data_types with its names takes 600 bytes on a Cortex-M, this 28). Checked
/// against data_types below.
inline constexpr std::uint8_t type_traits[0x1C] = {
    0x60,                                                                         // 0x00: no type
    0x01, 0x11, 0x12, 0x14, 0x21, 0x22, 0x24, 0x34, 0x40, 0x40, 0x40, 0x56, 0x56, // 0x01..0x0D
    0x60,                                                                         // 0x0E: no type
    0x40, 0x13, 0x38, 0x15, 0x16, 0x17, 0x18, 0x23,                               // 0x0F..0x16
    0x60,                                                                         // 0x17: no type
    0x25, 0x26, 0x27, 0x28,                                                       // 0x18..0x1B
};
[[nodiscard]] constexpr std::uint8_t traits_of(data_type t) noexcept {
  const auto code = static_cast<std::uint16_t>(t);
  return code < std::size(type_traits) ? type_traits[code] : std::uint8_t{0x60};
}
[[nodiscard]] constexpr type_class class_of(data_type t) noexcept {
  return static_cast<type_class>(traits_of(t) >> 4U);
}
} // namespace detail

/// Two's complement integers INTEGER8..INTEGER64.
[[nodiscard]] constexpr bool is_signed_integer(data_type t) noexcept {
  return detail::class_of(t) == type_class::signed_integer;
}
/// UNSIGNED8..UNSIGNED64.
[[nodiscard]] constexpr bool is_unsigned_integer(data_type t) noexcept {
  return detail::class_of(t) == type_class::unsigned_integer;
}
[[nodiscard]] constexpr bool is_integer(data_type t) noexcept {
  return is_signed_integer(t) || is_unsigned_integer(t);
}
[[nodiscard]] constexpr bool is_real(data_type t) noexcept {
  return detail::class_of(t) == type_class::real;
}
/// VISIBLE_STRING, OCTET_STRING, UNICODE_STRING and DOMAIN: byte strings of variable size.
[[nodiscard]] constexpr bool is_byte_string(data_type t) noexcept {
  return detail::class_of(t) == type_class::byte_string;
}
/// TIME_OF_DAY and TIME_DIFFERENCE (6 bytes: 28-bit milliseconds, 4 reserved bits, 16-bit days).
[[nodiscard]] constexpr bool is_time(data_type t) noexcept {
  return detail::class_of(t) == type_class::time;
}

/// Size in bytes of a value of fixed size; 0 for the byte-string types (size per entry).
/// BOOLEAN travels as one byte.
[[nodiscard]] constexpr std::uint8_t fixed_size(data_type t) noexcept {
  return static_cast<std::uint8_t>(detail::traits_of(t) & 0x0FU);
}

/// The CiA 301 name, upper case ("UNSIGNED16").
[[nodiscard]] constexpr std::string_view name(data_type t) noexcept { return info(t).name; }

// The table is in code order, its row function finds every type, and the predicates' table
// agrees with it (for every code 0x00..0x1B).
static_assert([] {
  for (std::uint16_t code = 0; code < std::size(detail::type_traits); ++code) {
    const data_type_info &row = info(static_cast<data_type>(code));
    if (detail::traits_of(static_cast<data_type>(code)) !=
        ((static_cast<unsigned>(row.kind) << 4U) | row.size)) {
      return false;
    }
  }
  for (std::size_t i = 0; i < data_types.size(); ++i) {
    const auto code = static_cast<std::uint16_t>(data_types[i].type);
    if (!is_data_type(code) || detail::data_type_row(code) != i) return false;
    if ((data_types[i].size == 0U) != (data_types[i].kind == type_class::byte_string) ||
        data_types[i].kind == type_class::unassigned) {
      return false;
    }
  }
  return true;
}());

/// CiA 306 object codes.
enum class object_code : std::uint8_t {
  null = 0x0,
  domain = 0x2,
  deftype = 0x5,
  defstruct = 0x6,
  var = 0x7,
  array = 0x8,
  record = 0x9,
};

/// One row of the object code table.
struct object_code_info {
  object_code code;
  std::string_view name;       ///< CiA 306 name ("VAR")
  std::string_view identifier; ///< the enumerator's C++ name ("var")
};

inline constexpr std::array<object_code_info, 7> object_codes{{
    {object_code::null, "NULL", "null"},
    {object_code::domain, "DOMAIN", "domain"},
    {object_code::deftype, "DEFTYPE", "deftype"},
    {object_code::defstruct, "DEFSTRUCT", "defstruct"},
    {object_code::var, "VAR", "var"},
    {object_code::array, "ARRAY", "array"},
    {object_code::record, "RECORD", "record"},
}};

namespace detail {
inline constexpr object_code_info unassigned_object_code{object_code::null, "", ""};
} // namespace detail

/// The table row of an object code (a row with empty names for a value of the enumeration that
/// is no code).
[[nodiscard]] constexpr const object_code_info &info(object_code c) noexcept {
  for (const auto &row : object_codes) {
    if (row.code == c) return row;
  }
  return detail::unassigned_object_code;
}
/// The row of a code as written in a file (0x0..0x9); nullptr when it is not assigned.
[[nodiscard]] constexpr const object_code_info *find_object_code(std::uint32_t code) noexcept {
  for (const auto &row : object_codes) {
    if (static_cast<std::uint32_t>(row.code) == code) return &row;
  }
  return nullptr;
}
/// The row of a CiA 306 name ("VAR", exact spelling); nullptr when there is none.
[[nodiscard]] constexpr const object_code_info *find_object_code(std::string_view name) noexcept {
  for (const auto &row : object_codes) {
    if (row.name == name) return &row;
  }
  return nullptr;
}

[[nodiscard]] constexpr std::string_view name(object_code c) noexcept { return info(c).name; }

/// Access type of a sub-object. rwr: read/write, read on process input (TPDO) side;
/// rww: read/write, written on process output (RPDO) side; constant: read only, never changes.
enum class access : std::uint8_t { ro, wo, rw, rwr, rww, constant };

/// One row of the access type table.
struct access_info {
  access value;
  std::string_view name;       ///< the EDS spelling, lower case ("const")
  std::string_view identifier; ///< the enumerator's C++ name ("constant")
  bool readable;
  bool writable;
};

/// In enumerator order.
inline constexpr std::array<access_info, 6> access_types{{
    {access::ro, "ro", "ro", true, false},
    {access::wo, "wo", "wo", false, true},
    {access::rw, "rw", "rw", true, true},
    {access::rwr, "rwr", "rwr", true, true},
    {access::rww, "rww", "rww", true, true},
    {access::constant, "const", "constant", true, false},
}};

static_assert([] {
  for (std::size_t i = 0; i < access_types.size(); ++i) {
    if (static_cast<std::size_t>(access_types[i].value) != i) return false;
  }
  return true;
}());

namespace detail {
inline constexpr access_info unassigned_access{access::ro, "", "", true, false};
} // namespace detail

/// The table row of an access type (a read-only row with empty names for a value of the
/// enumeration that is none).
[[nodiscard]] constexpr const access_info &info(access a) noexcept {
  const auto i = static_cast<std::size_t>(a);
  return i < access_types.size() ? access_types[i] : detail::unassigned_access;
}
/// The row of an EDS spelling ("ro", "wo", "rw", "rwr", "rww", "const"; lower case, exact);
/// nullptr when there is none.
[[nodiscard]] constexpr const access_info *find_access(std::string_view name) noexcept {
  for (const auto &row : access_types) {
    if (row.name == name) return &row;
  }
  return nullptr;
}

/// Without the table (whose names an image that reads none need not link); checked against it
/// below.
[[nodiscard]] constexpr bool readable(access a) noexcept { return a != access::wo; }
[[nodiscard]] constexpr bool writable(access a) noexcept {
  return a == access::wo || a == access::rw || a == access::rwr || a == access::rww;
}
static_assert([] {
  for (std::size_t i = 0; i <= access_types.size(); ++i) { // and one value past the enumeration
    const auto a = static_cast<access>(i);
    if (readable(a) != info(a).readable || writable(a) != info(a).writable) return false;
  }
  return true;
}());

/// The EDS spelling ("ro", "wo", "rw", "rwr", "rww", "const").
[[nodiscard]] constexpr std::string_view name(access a) noexcept { return info(a).name; }

/// PDO mappability. `rx`: only into receive PDOs (process output data, written by the master);
/// `tx`: only into transmit PDOs (process input data); `yes`: either direction.
enum class pdo_mapping : std::uint8_t { no, yes, rx, tx };

/// The names of the CSV `pdo_mapping` column and of the enumerators, in enumerator order.
inline constexpr std::array<std::string_view, 4> pdo_mapping_names{"no", "yes", "rx", "tx"};

[[nodiscard]] constexpr bool mappable_rx(pdo_mapping p) noexcept {
  return p == pdo_mapping::yes || p == pdo_mapping::rx;
}
[[nodiscard]] constexpr bool mappable_tx(pdo_mapping p) noexcept {
  return p == pdo_mapping::yes || p == pdo_mapping::tx;
}

[[nodiscard]] constexpr std::string_view name(pdo_mapping p) noexcept {
  const auto i = static_cast<std::size_t>(p);
  return i < pdo_mapping_names.size() ? pdo_mapping_names[i] : std::string_view{};
}

/// The mapping of a name ("no", "yes", "rx", "tx"); false when there is none.
[[nodiscard]] constexpr bool find_pdo_mapping(std::string_view name, pdo_mapping &out) noexcept {
  for (std::size_t i = 0; i < pdo_mapping_names.size(); ++i) {
    if (pdo_mapping_names[i] == name) {
      out = static_cast<pdo_mapping>(i);
      return true;
    }
  }
  return false;
}

} // namespace fieldcodec::od
