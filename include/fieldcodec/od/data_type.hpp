// fieldcodec — CiA 301 data types (0x0001..0x001B), object codes, access types, PDO mapping.
#pragma once

#include <cstdint>
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

/// True for the 25 assigned codes 0x01..0x1B.
[[nodiscard]] constexpr bool is_data_type(std::uint16_t code) noexcept {
  return code >= 0x01U && code <= 0x1BU && code != 0x0EU && code != 0x17U;
}

/// Two's complement integers INTEGER8..INTEGER64.
[[nodiscard]] constexpr bool is_signed_integer(data_type t) noexcept {
  switch (t) {
  case data_type::integer8:
  case data_type::integer16:
  case data_type::integer24:
  case data_type::integer32:
  case data_type::integer40:
  case data_type::integer48:
  case data_type::integer56:
  case data_type::integer64: return true;
  default: return false;
  }
}

/// UNSIGNED8..UNSIGNED64.
[[nodiscard]] constexpr bool is_unsigned_integer(data_type t) noexcept {
  switch (t) {
  case data_type::unsigned8:
  case data_type::unsigned16:
  case data_type::unsigned24:
  case data_type::unsigned32:
  case data_type::unsigned40:
  case data_type::unsigned48:
  case data_type::unsigned56:
  case data_type::unsigned64: return true;
  default: return false;
  }
}

[[nodiscard]] constexpr bool is_integer(data_type t) noexcept {
  return is_signed_integer(t) || is_unsigned_integer(t);
}
[[nodiscard]] constexpr bool is_real(data_type t) noexcept {
  return t == data_type::real32 || t == data_type::real64;
}
/// VISIBLE_STRING, OCTET_STRING, UNICODE_STRING and DOMAIN: byte strings of variable size.
[[nodiscard]] constexpr bool is_byte_string(data_type t) noexcept {
  return t == data_type::visible_string || t == data_type::octet_string ||
         t == data_type::unicode_string || t == data_type::domain;
}
/// TIME_OF_DAY and TIME_DIFFERENCE (6 bytes: 28-bit milliseconds, 4 reserved bits, 16-bit days).
[[nodiscard]] constexpr bool is_time(data_type t) noexcept {
  return t == data_type::time_of_day || t == data_type::time_difference;
}

/// Size in bytes of a value of fixed size; 0 for the byte-string types (size per entry).
/// BOOLEAN travels as one byte.
[[nodiscard]] constexpr std::uint8_t fixed_size(data_type t) noexcept {
  switch (t) {
  case data_type::boolean:
  case data_type::integer8:
  case data_type::unsigned8: return 1;
  case data_type::integer16:
  case data_type::unsigned16: return 2;
  case data_type::integer24:
  case data_type::unsigned24: return 3;
  case data_type::integer32:
  case data_type::unsigned32:
  case data_type::real32: return 4;
  case data_type::integer40:
  case data_type::unsigned40: return 5;
  case data_type::integer48:
  case data_type::unsigned48:
  case data_type::time_of_day:
  case data_type::time_difference: return 6;
  case data_type::integer56:
  case data_type::unsigned56: return 7;
  case data_type::integer64:
  case data_type::unsigned64:
  case data_type::real64: return 8;
  case data_type::visible_string:
  case data_type::octet_string:
  case data_type::unicode_string:
  case data_type::domain: return 0;
  }
  return 0;
}

/// The CiA 301 name, upper case ("UNSIGNED16").
[[nodiscard]] constexpr std::string_view name(data_type t) noexcept {
  switch (t) {
  case data_type::boolean: return "BOOLEAN";
  case data_type::integer8: return "INTEGER8";
  case data_type::integer16: return "INTEGER16";
  case data_type::integer24: return "INTEGER24";
  case data_type::integer32: return "INTEGER32";
  case data_type::integer40: return "INTEGER40";
  case data_type::integer48: return "INTEGER48";
  case data_type::integer56: return "INTEGER56";
  case data_type::integer64: return "INTEGER64";
  case data_type::unsigned8: return "UNSIGNED8";
  case data_type::unsigned16: return "UNSIGNED16";
  case data_type::unsigned24: return "UNSIGNED24";
  case data_type::unsigned32: return "UNSIGNED32";
  case data_type::unsigned40: return "UNSIGNED40";
  case data_type::unsigned48: return "UNSIGNED48";
  case data_type::unsigned56: return "UNSIGNED56";
  case data_type::unsigned64: return "UNSIGNED64";
  case data_type::real32: return "REAL32";
  case data_type::real64: return "REAL64";
  case data_type::visible_string: return "VISIBLE_STRING";
  case data_type::octet_string: return "OCTET_STRING";
  case data_type::unicode_string: return "UNICODE_STRING";
  case data_type::time_of_day: return "TIME_OF_DAY";
  case data_type::time_difference: return "TIME_DIFFERENCE";
  case data_type::domain: return "DOMAIN";
  }
  return "";
}

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

[[nodiscard]] constexpr std::string_view name(object_code c) noexcept {
  switch (c) {
  case object_code::null: return "NULL";
  case object_code::domain: return "DOMAIN";
  case object_code::deftype: return "DEFTYPE";
  case object_code::defstruct: return "DEFSTRUCT";
  case object_code::var: return "VAR";
  case object_code::array: return "ARRAY";
  case object_code::record: return "RECORD";
  }
  return "";
}

/// Access type of a sub-object. rwr: read/write, read on process input (TPDO) side;
/// rww: read/write, written on process output (RPDO) side; constant: read only, never changes.
enum class access : std::uint8_t { ro, wo, rw, rwr, rww, constant };

[[nodiscard]] constexpr bool readable(access a) noexcept { return a != access::wo; }
[[nodiscard]] constexpr bool writable(access a) noexcept {
  return a == access::wo || a == access::rw || a == access::rwr || a == access::rww;
}

/// The EDS spelling ("ro", "wo", "rw", "rwr", "rww", "const").
[[nodiscard]] constexpr std::string_view name(access a) noexcept {
  switch (a) {
  case access::ro: return "ro";
  case access::wo: return "wo";
  case access::rw: return "rw";
  case access::rwr: return "rwr";
  case access::rww: return "rww";
  case access::constant: return "const";
  }
  return "";
}

/// PDO mappability. `rx`: only into receive PDOs (process output data, written by the master);
/// `tx`: only into transmit PDOs (process input data); `yes`: either direction.
enum class pdo_mapping : std::uint8_t { no, yes, rx, tx };

[[nodiscard]] constexpr bool mappable_rx(pdo_mapping p) noexcept {
  return p == pdo_mapping::yes || p == pdo_mapping::rx;
}
[[nodiscard]] constexpr bool mappable_tx(pdo_mapping p) noexcept {
  return p == pdo_mapping::yes || p == pdo_mapping::tx;
}

[[nodiscard]] constexpr std::string_view name(pdo_mapping p) noexcept {
  switch (p) {
  case pdo_mapping::no: return "no";
  case pdo_mapping::yes: return "yes";
  case pdo_mapping::rx: return "rx";
  case pdo_mapping::tx: return "tx";
  }
  return "";
}

} // namespace fieldcodec::od
