// Generated from xenax_ethercat.eds by fieldcodec-gen — do not edit.
// Regenerate with codegen/regenerate.sh (or the fieldcodec_generate_dictionary CMake function).
// clang-format off
#pragma once

#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/descriptor.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/object.hpp>
#include <fieldcodec/od/text.hpp>
#include <fieldcodec/od/value_kinds.hpp>

#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::dictionaries::xenax_ethercat {

using namespace std::string_view_literals;

inline constexpr const char *source_file = "xenax_ethercat.eds";

namespace detail {
inline constexpr od::entry entries[358]{
    {.index = 0x1000, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\222\001B\000\000\000\000\000\377\377\377\377"},
    {.index = 0x1001, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\377"},
    {.index = 0x1008, .type = od::data_type::visible_string, .access_type = od::access::ro, .flags = od::flag::has_size | od::flag::has_text, .extra = "\036\000\000\000\036\000\000\000Servocontroller XENAX Xvi xxVx"},
    {.index = 0x1009, .type = od::data_type::visible_string, .access_type = od::access::ro, .flags = od::flag::has_size | od::flag::has_text, .extra = "\026\000\000\000\026\000\000\000BUS Module HW Vxxx.xxx"},
    {.index = 0x100A, .type = od::data_type::visible_string, .access_type = od::access::ro, .flags = od::flag::has_size | od::flag::has_text, .extra = "\030\000\000\000\030\000\000\000BUS Protocol SW Vxxx.xxx"},
    {.index = 0x1018, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\004\001\004"},
    {.index = 0x1018, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377\377\377"},
    {.index = 0x1018, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377\377\377"},
    {.index = 0x1018, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\001\000\000\000\000\000\377\377\377\377"},
    {.index = 0x1018, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\000\000\000\000\377\377\377\377"},
    {.index = 0x1600, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\010"},
    {.index = 0x1600, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000@`\000\000\000\000\377\377\377\377"},
    {.index = 0x1601, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\002\000\010"},
    {.index = 0x1601, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000@`\000\000\000\000\377\377\377\377"},
    {.index = 0x1601, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000z`\000\000\000\000\377\377\377\377"},
    {.index = 0x1611, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\003\000\010"},
    {.index = 0x1611, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000@`\000\000\000\000\377\377\377\377"},
    {.index = 0x1611, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000z`\000\000\000\000\377\377\377\377"},
    {.index = 0x1611, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \001\376`\000\000\000\000\377\377\377\377"},
    {.index = 0x1612, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\011\000\011"},
    {.index = 0x1612, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000@`\000\000\000\000\377\377\377\377"},
    {.index = 0x1612, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000z`\000\000\000\000\377\377\377\377"},
    {.index = 0x1612, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\201`\000\000\000\000\377\377\377\377"},
    {.index = 0x1612, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\203`\000\000\000\000\377\377\377\377"},
    {.index = 0x1612, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\204`\000\000\000\000\377\377\377\377"},
    {.index = 0x1612, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\000 \000\000\000\000\377\377\377\377"},
    {.index = 0x1612, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000e`\000\000\000\000\377\377\377\377"},
    {.index = 0x1612, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000g`\000\000\000\000\377\377\377\377"},
    {.index = 0x1612, .sub = 9, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \001\376`\000\000\000\000\377\377\377\377"},
    {.index = 0x1613, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\005\000\010"},
    {.index = 0x1613, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000@`\000\000\000\000\377\377\377\377"},
    {.index = 0x1613, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\201`\000\000\000\000\377\377\377\377"},
    {.index = 0x1613, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\001 \000\000\000\000\377\377\377\377"},
    {.index = 0x1613, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\003 \000\000\000\000\377\377\377\377"},
    {.index = 0x1613, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \001\376`\000\000\000\000\377\377\377\377"},
    {.index = 0x1614, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\003\000\010"},
    {.index = 0x1614, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000@`\000\000\000\000\377\377\377\377"},
    {.index = 0x1614, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\002 \000\000\000\000\377\377\377\377"},
    {.index = 0x1614, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \001\376`\000\000\000\000\377\377\377\377"},
    {.index = 0x1615, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\005\000\010"},
    {.index = 0x1615, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000@`\000\000\000\000\377\377\377\377"},
    {.index = 0x1615, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000z`\000\000\000\000\377\377\377\377"},
    {.index = 0x1615, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000e`\000\000\000\000\377\377\377\377"},
    {.index = 0x1615, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000g`\000\000\000\000\377\377\377\377"},
    {.index = 0x1615, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000s`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A00, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\010"},
    {.index = 0x1A00, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000A`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A01, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\002\000\010"},
    {.index = 0x1A01, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000A`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A01, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000d`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A10, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\003\000\010"},
    {.index = 0x1A10, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000A`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A10, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000d`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A10, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\375`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A11, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\005\000\010"},
    {.index = 0x1A11, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000A`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A11, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000d`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A11, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\364`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A11, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000x`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A11, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\375`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A12, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\004\000\010"},
    {.index = 0x1A12, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000A`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A12, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000d`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A12, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\005 \000\000\000\000\377\377\377\377"},
    {.index = 0x1A12, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\375`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A13, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\005\000\010"},
    {.index = 0x1A13, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000A`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A13, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000d`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A13, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\364`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A13, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\020\000x`\000\000\000\000\377\377\377\377"},
    {.index = 0x1A13, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \000\006 \000\000\000\000\377\377\377\377"},
    {.index = 0x1C00, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\005\000 "},
    {.index = 0x1C00, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\004"},
    {.index = 0x1C00, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\002\000\004"},
    {.index = 0x1C00, .sub = 3, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\003\000\004"},
    {.index = 0x1C00, .sub = 4, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\004\000\004"},
    {.index = 0x1C00, .sub = 5, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\004"},
    {.index = 0x1C10, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000"},
    {.index = 0x1C11, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000"},
    {.index = 0x1C12, .object = od::object_code::array, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\006"},
    {.index = 0x1C12, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\026\000\026\377\027"},
    {.index = 0x1C13, .object = od::object_code::array, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\005"},
    {.index = 0x1C13, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\023\032\000\032\377\033"},
    {.index = 0x2000, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\024\000\000\000\001\000\000\000d\000\000\000"},
    {.index = 0x2001, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\377"},
    {.index = 0x2002, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\377"},
    {.index = 0x2003, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\377"},
    {.index = 0x2004, .type = od::data_type::integer8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\177"},
    {.index = 0x2005, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x2006, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x2007, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\350\003d\000\020'"},
    {.index = 0x2008, .type = od::data_type::visible_string, .access_type = od::access::ro, .flags = od::flag::has_size, .extra = " \000\000\000"},
    {.index = 0x2009, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x200A, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5000, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\377"},
    {.index = 0x5001, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "-"},
    {.index = 0x5001, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 15, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 16, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 17, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 18, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 19, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 20, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 21, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 22, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 23, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 24, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 25, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 26, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 27, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 28, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 29, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 30, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 31, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 32, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 33, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 34, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 35, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 36, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 37, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 38, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 39, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 40, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 41, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 42, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 43, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 44, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5001, .sub = 45, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5002, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\020"},
    {.index = 0x5002, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\010\000\000\000"},
    {.index = 0x5002, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5002, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\200\377\377\377\177"},
    {.index = 0x5002, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\0002\000\000\000"},
    {.index = 0x5002, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\077\000\000\000"},
    {.index = 0x5002, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\010\000\000\000"},
    {.index = 0x5002, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\000\000\000"},
    {.index = 0x5002, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000l\312\210\000\2245w"},
    {.index = 0x5002, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000l\312\210\000\2245w"},
    {.index = 0x5002, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\014\000\000\000"},
    {.index = 0x5002, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\014\000\000\000"},
    {.index = 0x5002, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\005\000\000\000"},
    {.index = 0x5002, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377\377\177"},
    {.index = 0x5002, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\012\000\000\000"},
    {.index = 0x5002, .sub = 15, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\320\007\000\000"},
    {.index = 0x5002, .sub = 16, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .flags = od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\020\000\000\000"},
    {.index = 0x5003, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "j"},
    {.index = 0x5003, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "@B\017\000\320\007\000\000\000\312\232;"},
    {.index = 0x5003, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\024\000\000\000\001\000\000\000d\000\000\000"},
    {.index = 0x5003, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\240\206\001\000\012\000\000\000\000\341\365\005"},
    {.index = 0x5003, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000l\312\210\000\2245w"},
    {.index = 0x5003, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " N\000\000\000l\312\210\000\2245w"},
    {.index = 0x5003, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\320\007\000\000\001\000\000\000@B\017\000"},
    {.index = 0x5003, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\005\000\000\000"},
    {.index = 0x5003, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "d\000\000\000\001\000\000\000\020'\000\000"},
    {.index = 0x5003, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\200\226\230\000\020'\000\000\000\312\232;"},
    {.index = 0x5003, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\017\000\000"},
    {.index = 0x5003, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\002\000\000\000"},
    {.index = 0x5003, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_low | od::flag::has_high, .extra = "\012\000\000\000\320\007\000\000"},
    {.index = 0x5003, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 15, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\015\000\000\000"},
    {.index = 0x5003, .sub = 16, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\000\341\365\005"},
    {.index = 0x5003, .sub = 17, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\334\005\000\000\005\000\000\000\210\023\000\000"},
    {.index = 0x5003, .sub = 18, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "2\000\000\000\001\000\000\000\210\023\000\000"},
    {.index = 0x5003, .sub = 19, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\260\004\000\000\012\000\000\000\320\007\000\000"},
    {.index = 0x5003, .sub = 20, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\0002\000\000\000"},
    {.index = 0x5003, .sub = 21, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\350\003\000\000\002\000\000\000@B\017\000"},
    {.index = 0x5003, .sub = 22, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\240\206\001\000\012\000\000\000\000\341\365\005"},
    {.index = 0x5003, .sub = 23, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000l\312\210\000\2245w"},
    {.index = 0x5003, .sub = 24, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\000\000\000"},
    {.index = 0x5003, .sub = 25, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\004\000\000\000"},
    {.index = 0x5003, .sub = 26, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\210\023\000\000\364\001\000\000\240\206\001\000"},
    {.index = 0x5003, .sub = 27, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\320\007\000\000"},
    {.index = 0x5003, .sub = 28, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\0002\000\000\000"},
    {.index = 0x5003, .sub = 29, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\010\000\000\000"},
    {.index = 0x5003, .sub = 30, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "d\000\000\000\000\000\000\000d\000\000\000"},
    {.index = 0x5003, .sub = 31, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 32, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\377\000\000\000\000\000\000\000\377\000\000\000"},
    {.index = 0x5003, .sub = 33, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "UU\000\000\000\000\000\000\377\377\000\000"},
    {.index = 0x5003, .sub = 34, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\030\374\377\377\350\003\000\000"},
    {.index = 0x5003, .sub = 35, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = " \241\007\000\020'\000\000@B\017\000"},
    {.index = 0x5003, .sub = 36, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\177"},
    {.index = 0x5003, .sub = 37, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\177"},
    {.index = 0x5003, .sub = 38, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 39, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000l\312\210\000\2245w"},
    {.index = 0x5003, .sub = 40, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000l\312\210\000\2245w"},
    {.index = 0x5003, .sub = 41, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\370\366\377\377\320\007\000\000"},
    {.index = 0x5003, .sub = 42, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\370\366\377\377\320\007\000\000"},
    {.index = 0x5003, .sub = 43, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 44, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 45, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000l\312\210\000\2245w"},
    {.index = 0x5003, .sub = 46, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "d\000\000\000\001\000\000\000\350\003\000\000"},
    {.index = 0x5003, .sub = 47, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\002\000\000\000"},
    {.index = 0x5003, .sub = 48, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\320\007\000\000"},
    {.index = 0x5003, .sub = 49, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\002\000\000\000"},
    {.index = 0x5003, .sub = 50, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\012\000\000\000"},
    {.index = 0x5003, .sub = 51, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\000\000"},
    {.index = 0x5003, .sub = 52, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\012\000\000\000"},
    {.index = 0x5003, .sub = 53, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\350\003\000\000\002\000\000\000@B\017\000"},
    {.index = 0x5003, .sub = 54, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\240\206\001\000\012\000\000\000\000\341\365\005"},
    {.index = 0x5003, .sub = 55, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\320\007\000\000"},
    {.index = 0x5003, .sub = 56, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 57, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\000\000\000\000\377\003\000\000"},
    {.index = 0x5003, .sub = 58, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 59, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 60, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 61, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low, .extra = "\000\000\000\000\000\000\000\000"},
    {.index = 0x5003, .sub = 62, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\002\000\000\000"},
    {.index = 0x5003, .sub = 63, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\003\000\000\000"},
    {.index = 0x5003, .sub = 64, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\210\023\000\000\364\001\000\000\240\206\001\000"},
    {.index = 0x5003, .sub = 65, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\320\007\000\000"},
    {.index = 0x5003, .sub = 66, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 67, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\350\003\000\000"},
    {.index = 0x5003, .sub = 68, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\350\003\000\000\002\000\000\000@B\017\000"},
    {.index = 0x5003, .sub = 69, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\240\206\001\000\012\000\000\000\000\341\365\005"},
    {.index = 0x5003, .sub = 70, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000l\312\210\000\2245w"},
    {.index = 0x5003, .sub = 71, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\002\000\000\000"},
    {.index = 0x5003, .sub = 72, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\316\377\377\3772\000\000\000"},
    {.index = 0x5003, .sub = 73, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\003\000\000\000\000\000\000\000\007\000\000\000"},
    {.index = 0x5003, .sub = 74, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 75, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\350\003\000\000"},
    {.index = 0x5003, .sub = 76, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\0002\000\000\000"},
    {.index = 0x5003, .sub = 77, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 78, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 79, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\320\007\000\000"},
    {.index = 0x5003, .sub = 80, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\0002\000\000\000"},
    {.index = 0x5003, .sub = 81, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\010\000\000\000"},
    {.index = 0x5003, .sub = 82, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\015\000\000\000"},
    {.index = 0x5003, .sub = 83, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\001\000\000\000\010\000\000\000"},
    {.index = 0x5003, .sub = 84, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\026\000\000\000"},
    {.index = 0x5003, .sub = 85, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 86, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 87, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 88, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 89, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 90, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 91, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5003, .sub = 92, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\002\000\000\000"},
    {.index = 0x5003, .sub = 93, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\364\001\000\000d\000\000\000\210\023\000\000"},
    {.index = 0x5003, .sub = 94, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\002\000\000\000"},
    {.index = 0x5003, .sub = 95, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 96, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 97, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\177"},
    {.index = 0x5003, .sub = 98, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 99, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 100, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\077\000\000\000"},
    {.index = 0x5003, .sub = 101, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\000\000"},
    {.index = 0x5003, .sub = 102, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 103, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 104, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 105, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5003, .sub = 106, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5004, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\013"},
    {.index = 0x5004, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000d\000\000\000"},
    {.index = 0x5004, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\300]\000\000\012\000\000\000\200\226\230\000"},
    {.index = 0x5004, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5004, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000g\001\000\000"},
    {.index = 0x5004, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\200\226\230\000"},
    {.index = 0x5004, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\341\365\005"},
    {.index = 0x5004, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\240\206\001\000"},
    {.index = 0x5004, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\240\206\001\000"},
    {.index = 0x5004, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\020'\000\000"},
    {.index = 0x5004, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\020'\000\000"},
    {.index = 0x5004, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\177"},
    {.index = 0x5005, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\015"},
    {.index = 0x5005, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5005, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5006, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\012"},
    {.index = 0x5006, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\002\250\300\000\000\000\200\377\377\377\177"},
    {.index = 0x5006, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "d\002\250\300\000\000\000\200\377\377\377\177"},
    {.index = 0x5006, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\374\377\377\000\000\000\200\377\377\377\177"},
    {.index = 0x5006, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5006, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5006, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\021'\000\000\001\000\000\000\377\377\000\000"},
    {.index = 0x5006, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5006, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\302\001\000\200%\000\000\000F\005\000"},
    {.index = 0x5006, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5006, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5010, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\016"},
    {.index = 0x5010, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x5010, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\364\001\000\000d\000\000\000\210\023\000\000"},
    {.index = 0x5010, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000@\015\003\000"},
    {.index = 0x5010, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000@\015\003\000"},
    {.index = 0x5010, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5010, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000@x}\001"},
    {.index = 0x5010, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\002\000\000\000"},
    {.index = 0x5010, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\002\000\000\000"},
    {.index = 0x5010, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\002\000\000\000"},
    {.index = 0x5010, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000@T\211\000"},
    {.index = 0x5010, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\001\000\000\000"},
    {.index = 0x5010, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\007\000\000\000"},
    {.index = 0x5010, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "2\000\000\000\001\000\000\000\350\003\000\000"},
    {.index = 0x5010, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\350\003\000\000\001\000\000\000\200\226\230\000"},
    {.index = 0x5011, .type = od::data_type::visible_string, .flags = od::flag::has_size, .extra = "\036\000\000\000"},
    {.index = 0x5012, .type = od::data_type::visible_string, .flags = od::flag::has_size, .extra = "\036\000\000\000"},
    {.index = 0x5020, .type = od::data_type::visible_string, .access_type = od::access::ro, .flags = od::flag::has_size | od::flag::has_text, .extra = "d\000\000\000\010\000\000\000no error"},
    {.index = 0x5021, .type = od::data_type::visible_string, .flags = od::flag::has_size, .extra = " \000\000\000"},
    {.index = 0x603F, .type = od::data_type::unsigned16, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377"},
    {.index = 0x6040, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377"},
    {.index = 0x6041, .type = od::data_type::unsigned16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377"},
    {.index = 0x6060, .type = od::data_type::integer8, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\376\012"},
    {.index = 0x6061, .type = od::data_type::integer8, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\376\012"},
    {.index = 0x6064, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x6065, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\320\007\000\000\001\000\000\000@B\017\000"},
    {.index = 0x6067, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "d\000\000\000\001\000\000\000\020'\000\000"},
    {.index = 0x6068, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\350\003"},
    {.index = 0x606C, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x6073, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\320\007"},
    {.index = 0x6078, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_low | od::flag::has_high, .extra = "\340\261 N"},
    {.index = 0x607A, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x607D, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\002\002\002"},
    {.index = 0x607D, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x607D, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\200\377\377\377\177"},
    {.index = 0x6081, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\240\206\001\000\012\000\000\000\000\341\365\005"},
    {.index = 0x6083, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "@B\017\000\320\007\000\000\000\312\232;"},
    {.index = 0x6084, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes},
    {.index = 0x6085, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\200\226\230\000\020'\000\000\000\312\232;"},
    {.index = 0x6098, .type = od::data_type::integer8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\001\017"},
    {.index = 0x6099, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\002\002\002"},
    {.index = 0x6099, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\350\003\000\000\000\000\000\000\220\320\003\000"},
    {.index = 0x6099, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\364\001\000\000\000\000\000\000\240\206\001\000"},
    {.index = 0x60B1, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\300\253v\377@T\211\000"},
    {.index = 0x60B2, .type = od::data_type::integer16, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\200\377\177"},
    {.index = 0x60C2, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\002\002\002"},
    {.index = 0x60C2, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\001\000\377"},
    {.index = 0x60C2, .sub = 2, .object = od::object_code::record, .type = od::data_type::integer8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\375\200\077"},
    {.index = 0x60F4, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\200\377\377\377\177"},
    {.index = 0x60FD, .type = od::data_type::unsigned32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\377"},
    {.index = 0x60FE, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\002\001\002"},
    {.index = 0x60FE, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\377"},
    {.index = 0x60FE, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\377"},
    {.index = 0x60FF, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\300\253v\377@T\211\000"},
    {.index = 0x6502, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\241\000\001\000\241\000\001\000\241\000\001\000"},
    {.index = 0x6505, .type = od::data_type::visible_string, .access_type = od::access::ro, .flags = od::flag::has_size | od::flag::has_text, .extra = "\032\000\000\000\032\000\000\000http://www.jennyscience.ch"},
};

inline constexpr od::entry_info infos[358]{
    {.name = {"Device Type", 11}},
    {.name = {"Error Register", 14}},
    {.name = {"Manufacturer Device Name", 24}},
    {.name = {"Manufacturer Hardware Version", 29}},
    {.name = {"Manufacturer Software Version", 29}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Vendor Id", 9}},
    {.name = {"Product Code", 12}},
    {.name = {"Revision Number", 15}},
    {.name = {"Serial Number", 13}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Controlword", 11}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Controlword", 11}},
    {.name = {"Target Position", 15}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Controlword", 11}},
    {.name = {"Target Position", 15}},
    {.name = {"Digital Outputs", 15}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Controlword", 11}},
    {.name = {"Target Position", 15}},
    {.name = {"Speed", 5}},
    {.name = {"Acceleration", 12}},
    {.name = {"Deceleration (reserved for future)", 34}},
    {.name = {"S-Curve", 7}},
    {.name = {"Following Position Error Window", 31}},
    {.name = {"Target Position Error Window", 28}},
    {.name = {"Digital Outputs", 15}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Controlword", 11}},
    {.name = {"Speed", 5}},
    {.name = {"Reserved for future 2001", 24}},
    {.name = {"Reserved for future 2003", 24}},
    {.name = {"Digital Outputs", 15}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Controlword", 11}},
    {.name = {"Reserved for future 2002", 24}},
    {.name = {"Digital Outputs", 15}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Controlword", 11}},
    {.name = {"Target Position", 15}},
    {.name = {"Following position error window", 31}},
    {.name = {"Target position error window", 28}},
    {.name = {"I Force Max", 11}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Statusword", 10}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Statusword", 10}},
    {.name = {"Actual Position", 15}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Statusword", 10}},
    {.name = {"Actual Position", 15}},
    {.name = {"Digital Inputs", 14}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Statusword", 10}},
    {.name = {"Actual Position", 15}},
    {.name = {"Actual Following position error", 31}},
    {.name = {"Actual Current", 14}},
    {.name = {"Digital Inputs", 14}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Statusword", 10}},
    {.name = {"Actual Position", 15}},
    {.name = {"I Force Actual", 14}},
    {.name = {"Digital Inputs", 14}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Statusword", 10}},
    {.name = {"Actual Position", 15}},
    {.name = {"Actual Following position error", 31}},
    {.name = {"Actual Current", 14}},
    {.name = {"Process Status Register", 23}},
    {.name = {"No of Used Sync Manager Channels", 32}},
    {.name = {"Com Type Sync Manager 1", 23}},
    {.name = {"Com Type Sync Manager 2", 23}},
    {.name = {"Com Type Sync Manager 3", 23}},
    {.name = {"Com Type Sync Manager 4", 23}},
    {.name = {"Com Type Sync Manager 5", 23}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Nbr of Entries", 14}},
    {.name = {"Nbr of Assigned RxPDO", 21}},
    {.name = {"PDO Mapping Index of Assigned RxPDOs", 36}},
    {.name = {"Nbr of Assigned TxPDO", 21}},
    {.name = {"PDO Mapping Index of Assigned TxPDOs", 36}},
    {.name = {"S-Curve Profile", 15}},
    {.name = {"Reserved 2001", 13}},
    {.name = {"Reserved 2002", 13}},
    {.name = {"Reserved 2003", 13}},
    {.name = {"XENAX Error Number", 18}},
    {.name = {"I_Force Actual", 14}},
    {.name = {"Process Status Register", 23}},
    {.name = {"PDO Cycle Time", 14}},
    {.name = {"Motor Type", 10}},
    {.name = {"Limit Force", 11}},
    {.name = {"Force Actual Value", 18}},
    {.name = {"Direct Commands", 15}},
    {.name = {"NumOfEntries", 12}},
    {.name = {"TS Tell Status", 14}},
    {.name = {"TE Tell Error Number", 20}},
    {.name = {"TP Tell Position", 16}},
    {.name = {"TT Tell Temperature", 19}},
    {.name = {"TOX Tell Output Hex", 19}},
    {.name = {"TIX Tell Input Hex", 18}},
    {.name = {"TMC Tell Motor Current", 22}},
    {.name = {"TMT Tell Motion Time", 20}},
    {.name = {"TCP Tell Captured Position 1", 28}},
    {.name = {"TCP Tell Captured Position 2", 28}},
    {.name = {"TCP Tell Captured Position 3", 28}},
    {.name = {"TCP Tell Captured Position 4", 28}},
    {.name = {"TCP Tell Captured Position 5", 28}},
    {.name = {"TCP Tell Captured Position 6", 28}},
    {.name = {"TCP Tell Captured Position 7", 28}},
    {.name = {"TCP Tell Captured Position 8", 28}},
    {.name = {"TH Tell Reference State", 23}},
    {.name = {"VER Version of Firmware", 23}},
    {.name = {"ACV Acceleration Variation (Jerk, scaled to 1000)", 49}},
    {.name = {"I2TM Limit Value (scaled to 10)", 31}},
    {.name = {"I2T Calculated Value (scaled to 10)", 35}},
    {.name = {"IFPK I_Force Peak (FTM = 0) FPK Force Peak (FTM = 1,2)", 54}},
    {.name = {"TESM Tell SMU Error", 19}},
    {.name = {"DGMSO Detected Gantry Master Slave Offset", 41}},
    {.name = {"SIFF Sector I_Force Curve Failed (FTM = 0) SFF Sector Force Curve Failed (FTM = 1,2) (binary notation, LSB = sector 1)", 118}},
    {.name = {"IFPKn I_Force Peak Sector (FTM = 0) FPKn Force Peak Sector (FTM = 1,2) (select sector over Object 0x5003/050)", 109}},
    {.name = {"FCV Force Calibration Valid", 27}},
    {.name = {"TV Tell Velocity", 16}},
    {.name = {"TPT Tell Process Time", 21}},
    {.name = {"VERL Version of Bootloader", 26}},
    {.name = {"TCPB Tell Capture Pos. Buffer 1", 31}},
    {.name = {"TCPB Tell Capture Pos. Buffer 2", 31}},
    {.name = {"TCPB Tell Capture Pos. Buffer 3", 31}},
    {.name = {"TCPB Tell Capture Pos. Buffer 4", 31}},
    {.name = {"TCPB Tell Capture Pos. Buffer 5", 31}},
    {.name = {"TCPB Tell Capture Pos. Buffer 6", 31}},
    {.name = {"TCPB Tell Capture Pos. Buffer 7", 31}},
    {.name = {"TCPB Tell Capture Pos. Buffer 8", 31}},
    {.name = {"TESMH Tell SMU Error History", 28}},
    {.name = {"GR Gear Ratio", 13}},
    {.name = {"TTPS Tell Temperature Power Stage (Xvi75V8S only)", 49}},
    {.name = {"TVPSM Tell voltage power supply motor in [mV]", 45}},
    {.name = {"LARES linear axis resolution in [inc/m]", 39}},
    {.name = {"LAST linear axis stroke in [inc]", 32}},
    {.name = {"TTGS Tell trajectory state", 26}},
    {.name = {"NumOfEntries", 12}},
    {.name = {"CO Clear Output Number", 22}},
    {.name = {"EVT Event Activation", 20}},
    {.name = {"G Go Immediately", 16}},
    {.name = {"IX Start Index Number", 21}},
    {.name = {"PG Start Program Number", 23}},
    {.name = {"SO Set Output Number", 20}},
    {.name = {"SOX Set Output Hex Mask", 23}},
    {.name = {"TGD Set Trigger Position Downward", 33}},
    {.name = {"TGU Set Trigger Position Upward", 31}},
    {.name = {"ETI Enable Track Input", 22}},
    {.name = {"DTI Disable Track Input", 23}},
    {.name = {"PRF Start Profile Number", 24}},
    {.name = {"CRDA Cogging Reference Drive Automatic", 38}},
    {.name = {"DIF Drive I_Force", 17}},
    {.name = {"CLIF Change Limit I_Force", 25}},
    {.name = {"DF Drive Force (Xvi75V8S only)", 30}},
    {.name = {"NumOfEntries", 12}},
    {.name = {"AC Acceleration", 15}},
    {.name = {"S-Curve Profile (in percent)", 28}},
    {.name = {"SP Speed", 8}},
    {.name = {"PO Position (absolute)", 22}},
    {.name = {"WA Way (relative)", 17}},
    {.name = {"DP Deviation Position", 21}},
    {.name = {"DRHR Direction Reference", 24}},
    {.name = {"DTP Deviation Target Position", 29}},
    {.name = {"ED Emergency Deceleration", 25}},
    {.name = {"ILAS Input Low Active Selective", 31}},
    {.name = {"ILA Input Low Active", 20}},
    {.name = {"IS Stop Current (Linear) Nominal Current (Rotative) scaled to 10mA", 66}},
    {.name = {"SLPP Software Limit Position Positive", 37}},
    {.name = {"SLPN Software Limit Position Negative", 37}},
    {.name = {"MD Mode", 7}},
    {.name = {"ML Mass Load (WebMotion: Payload / Inertia)", 43}},
    {.name = {"BWC Bandwidth Current Controller (WebMotion: GAIN CUR)", 54}},
    {.name = {"BWP Bandwidth Position Controller (WebMotion: GAIN POS)", 55}},
    {.name = {"IR Run Current (Linear) Torque Current (Rotative) scaled to 10mA", 64}},
    {.name = {"NIX Preselected Index Number", 28}},
    {.name = {"AIX Acceleration of selected Index", 34}},
    {.name = {"SIX Speed of selected Index", 27}},
    {.name = {"DIX Distance of selected Index (depends on absolute or relative index definition)", 81}},
    {.name = {"CI Card Identifier", 18}},
    {.name = {"GSID Gantry Slave Identifier", 28}},
    {.name = {"FQC Filter Quality Current", 26}},
    {.name = {"FFC Filter Frequency Current", 28}},
    {.name = {"ICP Increments per Puls", 23}},
    {.name = {"INH Input Home Sensor", 21}},
    {.name = {"OVRD Speed Override", 19}},
    {.name = {"PWRT Phasing Rotative w/o HALL", 30}},
    {.name = {"SOA Set Output Activity", 23}},
    {.name = {"SOT Set Output Type", 19}},
    {.name = {"SR Synchronous Ratio", 20}},
    {.name = {"CAB CAN Baud Rate", 17}},
    {.name = {"ROID Rotative Motor Identifier", 30}},
    {.name = {"Reserved", 8}},
    {.name = {"Reserved", 8}},
    {.name = {"SIFS Sector I_Force Start (FTM = 0) SFS Sector Force Start (FTM = 1,2)", 70}},
    {.name = {"SIFE Sector I_Force End (FTM = 0) SFE Sector Force End (FTM = 1,2)", 66}},
    {.name = {"IFL I_Force Low", 15}},
    {.name = {"IFH I_Force High", 16}},
    {.name = {"MLPN Mechanical Limit Position Negative", 39}},
    {.name = {"MLPP Mechanical Limit Position Positive", 39}},
    {.name = {"PGMSO Preset Gantry Master Slave Offset", 39}},
    {.name = {"BRKD Brake delay", 16}},
    {.name = {"Reserved", 8}},
    {.name = {"LIF Limit I_Force", 17}},
    {.name = {"TYIX Type of Index", 18}},
    {.name = {"NSEC Preselected Sector Number", 30}},
    {.name = {"STCX Sector Transition Configuration (Hex Mask)", 47}},
    {.name = {"NDIF Preselected Drive I_Force Number (FTM = 0) NDF Preselected Drive Force Number (FTM = 1,2)", 94}},
    {.name = {"ADIF Acceleration of selected Drive I_Force (FTM = 0) ADF Acceleration of selected Drive Force (FTM = 1,2)", 106}},
    {.name = {"SDIF Speed of selected Drive I_Force (FTM = 0) SDF Speed of selected Drive Force (FTM = 1,2)", 92}},
    {.name = {"IDIF I_Force Limit of selected Drive I_Force", 44}},
    {.name = {"DDIF Direction of selected Drive I_Force (FTM = 0) DDF Direction of selected Drive Force (FTM = 1,2)", 100}},
    {.name = {"SSEC Select Sectors (binary notation, LSB = sector 1)", 53}},
    {.name = {"SSO Set Sector Offset", 21}},
    {.name = {"ENCPD Encoder Plausibility Checking Disable", 43}},
    {.name = {"SPAD Set Point ACK disable", 26}},
    {.name = {"RXZP ROTAX Z-Position", 21}},
    {.name = {"DRH Dir Home", 12}},
    {.name = {"DRZ Z-Mark", 10}},
    {.name = {"FQS Filter Quality Speed", 24}},
    {.name = {"FFS Filter Frequency Speed", 26}},
    {.name = {"EBMD Enhanced Bandwidth Mode Disabled", 37}},
    {.name = {"Reserved", 8}},
    {.name = {"AIXD Acceleration of dynamically selected Index", 47}},
    {.name = {"SIXD Speed of dynamically selected Index", 40}},
    {.name = {"DIXD Distance of dynamically selected Index (depends on absolute or relative index definition)", 94}},
    {.name = {"TYIXD Type of dynamically selected Index", 40}},
    {.name = {"PPSD Pole Placement Stability Dynamics", 38}},
    {.name = {"IFDCS I_Force Drift Compensation Setting", 40}},
    {.name = {"Reserved", 8}},
    {.name = {"SORF Swing Out Reduction Frequency", 34}},
    {.name = {"SORD Swing Out Reduction Damping", 32}},
    {.name = {"Reserved", 8}},
    {.name = {"Reserved", 8}},
    {.name = {"AVF Filter Frequency for Current Shaper", 39}},
    {.name = {"AVD Damping Ratio for Current Shaper", 36}},
    {.name = {"NOF Preselected Output Function", 31}},
    {.name = {"TYOF Type of Output Function", 28}},
    {.name = {"NIF Preselected Input Function", 30}},
    {.name = {"TYIF Type of Input Function", 27}},
    {.name = {"PAIF Parameter A of Input Function", 34}},
    {.name = {"PBIF Parameter B of Input Function", 34}},
    {.name = {"PCIF Parameter C of Input Function", 34}},
    {.name = {"CLF Change Limit Force (Xvi75V8S only)", 38}},
    {.name = {"FD Force of selected Drive Force (Xvi75V8S only)", 48}},
    {.name = {"FH Force High (Xvi75V8S only)", 29}},
    {.name = {"FL Force Low (Xvi75V8S only)", 28}},
    {.name = {"FTM Forceteq Mode (Xvi75V8S only)", 33}},
    {.name = {"SQBW Signateq Bandwidth (Xvi75V8S only)", 39}},
    {.name = {"MM Motor Manufacturer (Xvi75V8S only)", 37}},
    {.name = {"AREF Automatic Reference", 24}},
    {.name = {"EGMSO Enable user defined gantry Master/Slave offset", 52}},
    {.name = {"VMTAE Virtual multiturn for rotative motors with absolute encoder", 65}},
    {.name = {"ENAR Enable absolute reference", 30}},
    {.name = {"CTAB Correction Table State", 27}},
    {.name = {"APSN number of program to auto start", 36}},
    {.name = {"APSD Automatic program start delay[ms]", 38}},
    {.name = {"PMHSD Profinet MC_Home support disable", 38}},
    {.name = {"FCSM Force Calibration Storage mode", 35}},
    {.name = {"SOD P402 Switch on at transition 3 disable", 42}},
    {.name = {"GCME Gantry Coupled Mode Enable", 31}},
    {.name = {"FBCM Force buffered CSP mode", 28}},
    {.name = {"NumOfEntries", 12}},
    {.name = {"POL Pole Pairs", 14}},
    {.name = {"ENC Encoder Increments (Rotative, 1 turn of motor shaft)", 56}},
    {.name = {"PHD Phase Direction", 19}},
    {.name = {"PHO Phase Offset", 16}},
    {.name = {"MAMO Slider Mass (LINAX / ELAX) Rotor Inertia (Rotative)", 56}},
    {.name = {"FCM Force Constant of Motor", 27}},
    {.name = {"LPH Inductance Phase-Phase", 26}},
    {.name = {"RPH Resistance Phase-Phase", 26}},
    {.name = {"FFDY Frictional Force Dynamic", 29}},
    {.name = {"FFST Frictional Force Static", 28}},
    {.name = {"DMLPP Detected Mechanical Limit Position Positive", 49}},
    {.name = {"NumOfEntries", 12}},
    {.name = {"VERS Version SMU", 16}},
    {.name = {"SLS Timeout", 11}},
    {.name = {"Speed Limit", 11}},
    {.name = {"Stop Timeout", 12}},
    {.name = {"Position Window", 15}},
    {.name = {"SFTRD Input Configuration SMU", 29}},
    {.name = {"TESM Tell SMU Error", 19}},
    {.name = {"SMU Master Error Bitfeld", 24}},
    {.name = {"SMU Slave Error Bitfeld", 23}},
    {.name = {"SMU Master Info Bitfeld", 23}},
    {.name = {"SMU Slave Info Bitfeld", 22}},
    {.name = {"SPC Safety Parameter CRC", 24}},
    {.name = {"SPCMAC Safety Parameter and MAC Adress CRC (Xvi75V8S only)", 58}},
    {.name = {"NumOfEntries", 12}},
    {.name = {"EGW Set Gateway Address", 23}},
    {.name = {"EIP Set IP Address", 18}},
    {.name = {"ENM Set Net Mask", 16}},
    {.name = {"EMAC Read MAC Address 3 high Bytes", 34}},
    {.name = {"EMAC Read MAC Address 3 low Bytes", 33}},
    {.name = {"EPRT Set Port Number", 20}},
    {.name = {"LICR Show Installed Licences", 28}},
    {.name = {"SERB Set Baud Rate on Serial Interface", 38}},
    {.name = {"WebMotion Version", 17}},
    {.name = {"WebMotion Boot Version", 22}},
    {.name = {"NumOfEntries", 12}},
    {.name = {"SQVER Signateq Firmware Version", 31}},
    {.name = {"SQBW Signateq Bandwidth", 23}},
    {.name = {"SQSNF Signateq Sensor Nominal Force", 35}},
    {.name = {"SQMRP Signateq Measurement Range", 32}},
    {.name = {"Reserved", 8}},
    {.name = {"SQSS Signateq Sensor Sensitivity", 32}},
    {.name = {"SQSFT Signateq Sensor Force Type", 32}},
    {.name = {"SQCM Signateq Calibration Mode", 30}},
    {.name = {"SQFD Signateq Force Direction", 29}},
    {.name = {"LFRMS Limit Force Reached Maximum Speed", 39}},
    {.name = {"CLFO Clear force offset", 23}},
    {.name = {"SQAC Signateq available calibrations", 36}},
    {.name = {"BWFP Bandwidth for forceteq pro controller", 42}},
    {.name = {"FTPES Forceteq Pro Elastic Spring Constant", 42}},
    {.name = {"Signateq Sensor Model Type (SQSMT)", 34}},
    {.name = {"Signateq Sensor Serial Number (SQSSN)", 37}},
    {.name = {"Tell Error String (TES)", 23}},
    {.name = {"Servo identification string (SID)", 33}},
    {.name = {"Error Code", 10}},
    {.name = {"Controlword", 11}},
    {.name = {"Statusword", 10}},
    {.name = {"Modes of Operation Requested", 28}},
    {.name = {"Modes of Operation Display", 26}},
    {.name = {"Position Actual Value", 21}},
    {.name = {"Following Position Error Window", 31}},
    {.name = {"Target Position Window", 22}},
    {.name = {"Position Window Time", 20}},
    {.name = {"Velocity Actual Value", 21}},
    {.name = {"Limit I_Force", 13}},
    {.name = {"Motor Current Actual Value", 26}},
    {.name = {"Target Position", 15}},
    {.name = {"Highest Sub-index Value", 23}},
    {.name = {"Software Position Limit Left", 28}},
    {.name = {"Software Position Limit Right", 29}},
    {.name = {"Speed", 5}},
    {.name = {"Acceleration", 12}},
    {.name = {"Deceleration (reserved for future)", 34}},
    {.name = {"Quick Stop Deceleration", 23}},
    {.name = {"Reference Methods", 17}},
    {.name = {"Highest Sub-index Value", 23}},
    {.name = {"Reference-Speed searching external Reference sensor", 51}},
    {.name = {"Z-Speed searching internal encoder Z-mark", 41}},
    {.name = {"Velocity Offset", 15}},
    {.name = {"Torque Offset", 13}},
    {.name = {"Highest Sub-index Value", 23}},
    {.name = {"Base value", 10}},
    {.name = {"10^EXPONENT", 11}},
    {.name = {"Actual Position Following Error", 31}},
    {.name = {"Digital Inputs", 14}},
    {.name = {"Highest Sub-index Value", 23}},
    {.name = {"Output Bit", 10}},
    {.name = {"Output Mask (not supported)", 27}},
    {.name = {"Target Velocity", 15}},
    {.name = {"Supported Modes of Operation", 28}},
    {.name = {"Product Website Address", 23}},
};
} // namespace detail

inline constexpr std::span<const od::entry, 358> entries{detail::entries};
inline constexpr std::span<const od::entry_info, 358> infos{detail::infos};

inline constexpr od::dictionary dictionary{entries, infos};
static_assert(dictionary.is_valid());

// The kinds of values in the entries (od/value_kinds.hpp).
inline constexpr od::value_kinds kinds{.strings = true, .real = false, .time = false, .wide = false, .limits = true, .node_limits = false, .scaled = false, .numbers = false};

// VAR objects: standalone descriptors (firmware that names one keeps only that one).
inline constexpr od::descriptor device_type{detail::entries[0], detail::infos[0]}; // 0x1000
inline constexpr od::descriptor error_register{detail::entries[1], detail::infos[1]}; // 0x1001
inline constexpr od::descriptor manufacturer_device_name{detail::entries[2], detail::infos[2]}; // 0x1008
inline constexpr od::descriptor manufacturer_hardware_version{detail::entries[3], detail::infos[3]}; // 0x1009
inline constexpr od::descriptor manufacturer_software_version{detail::entries[4], detail::infos[4]}; // 0x100A
inline constexpr od::descriptor s_curve_profile{detail::entries[83], detail::infos[83]}; // 0x2000
inline constexpr od::descriptor reserved_2001{detail::entries[84], detail::infos[84]}; // 0x2001
inline constexpr od::descriptor reserved_2002{detail::entries[85], detail::infos[85]}; // 0x2002
inline constexpr od::descriptor reserved_2003{detail::entries[86], detail::infos[86]}; // 0x2003
inline constexpr od::descriptor xenax_error_number{detail::entries[87], detail::infos[87]}; // 0x2004
inline constexpr od::descriptor i_force_actual{detail::entries[88], detail::infos[88]}; // 0x2005
inline constexpr od::descriptor process_status_register{detail::entries[89], detail::infos[89]}; // 0x2006
inline constexpr od::descriptor pdo_cycle_time{detail::entries[90], detail::infos[90]}; // 0x2007
inline constexpr od::descriptor motor_type{detail::entries[91], detail::infos[91]}; // 0x2008
inline constexpr od::descriptor limit_force{detail::entries[92], detail::infos[92]}; // 0x2009
inline constexpr od::descriptor force_actual_value{detail::entries[93], detail::infos[93]}; // 0x200A
inline constexpr od::descriptor direct_commands{detail::entries[94], detail::infos[94]}; // 0x5000
inline constexpr od::descriptor signateq_sensor_model_type_sqsmt{detail::entries[317], detail::infos[317]}; // 0x5011
inline constexpr od::descriptor signateq_sensor_serial_number_sqssn{detail::entries[318], detail::infos[318]}; // 0x5012
inline constexpr od::descriptor tell_error_string_tes{detail::entries[319], detail::infos[319]}; // 0x5020
inline constexpr od::descriptor servo_identification_string_sid{detail::entries[320], detail::infos[320]}; // 0x5021
inline constexpr od::descriptor error_code{detail::entries[321], detail::infos[321]}; // 0x603F
inline constexpr od::descriptor controlword{detail::entries[322], detail::infos[322]}; // 0x6040
inline constexpr od::descriptor statusword{detail::entries[323], detail::infos[323]}; // 0x6041
inline constexpr od::descriptor modes_of_operation_requested{detail::entries[324], detail::infos[324]}; // 0x6060
inline constexpr od::descriptor modes_of_operation_display{detail::entries[325], detail::infos[325]}; // 0x6061
inline constexpr od::descriptor position_actual_value{detail::entries[326], detail::infos[326]}; // 0x6064
inline constexpr od::descriptor following_position_error_window{detail::entries[327], detail::infos[327]}; // 0x6065
inline constexpr od::descriptor target_position_window{detail::entries[328], detail::infos[328]}; // 0x6067
inline constexpr od::descriptor position_window_time{detail::entries[329], detail::infos[329]}; // 0x6068
inline constexpr od::descriptor velocity_actual_value{detail::entries[330], detail::infos[330]}; // 0x606C
inline constexpr od::descriptor limit_i_force{detail::entries[331], detail::infos[331]}; // 0x6073
inline constexpr od::descriptor motor_current_actual_value{detail::entries[332], detail::infos[332]}; // 0x6078
inline constexpr od::descriptor target_position{detail::entries[333], detail::infos[333]}; // 0x607A
inline constexpr od::descriptor speed{detail::entries[337], detail::infos[337]}; // 0x6081
inline constexpr od::descriptor acceleration{detail::entries[338], detail::infos[338]}; // 0x6083
inline constexpr od::descriptor deceleration_reserved_for_future{detail::entries[339], detail::infos[339]}; // 0x6084
inline constexpr od::descriptor quick_stop_deceleration{detail::entries[340], detail::infos[340]}; // 0x6085
inline constexpr od::descriptor reference_methods{detail::entries[341], detail::infos[341]}; // 0x6098
inline constexpr od::descriptor velocity_offset{detail::entries[345], detail::infos[345]}; // 0x60B1
inline constexpr od::descriptor torque_offset{detail::entries[346], detail::infos[346]}; // 0x60B2
inline constexpr od::descriptor actual_position_following_error{detail::entries[350], detail::infos[350]}; // 0x60F4
inline constexpr od::descriptor digital_inputs{detail::entries[351], detail::infos[351]}; // 0x60FD
inline constexpr od::descriptor target_velocity{detail::entries[355], detail::infos[355]}; // 0x60FF
inline constexpr od::descriptor supported_modes_of_operation{detail::entries[356], detail::infos[356]}; // 0x6502
inline constexpr od::descriptor product_website_address{detail::entries[357], detail::infos[357]}; // 0x6505

// ARRAY and RECORD objects: views into the tables.
inline constexpr od::object identity_object{0x1018, od::object_code::record, "Identity Object"sv, dictionary.entries().subspan(5, 5), dictionary.infos().subspan(5, 5)};
inline constexpr od::descriptor identity_object_nbr_of_entries{detail::entries[5], detail::infos[5]}; // 0x1018 sub 0
inline constexpr od::descriptor identity_object_vendor_id{detail::entries[6], detail::infos[6]}; // 0x1018 sub 1
inline constexpr od::descriptor identity_object_product_code{detail::entries[7], detail::infos[7]}; // 0x1018 sub 2
inline constexpr od::descriptor identity_object_revision_number{detail::entries[8], detail::infos[8]}; // 0x1018 sub 3
inline constexpr od::descriptor identity_object_serial_number{detail::entries[9], detail::infos[9]}; // 0x1018 sub 4
inline constexpr od::object receive_pdo_1{0x1600, od::object_code::record, "Receive PDO 1"sv, dictionary.entries().subspan(10, 2), dictionary.infos().subspan(10, 2)};
inline constexpr od::descriptor receive_pdo_1_nbr_of_entries{detail::entries[10], detail::infos[10]}; // 0x1600 sub 0
inline constexpr od::descriptor receive_pdo_1_controlword{detail::entries[11], detail::infos[11]}; // 0x1600 sub 1
inline constexpr od::object receive_pdo_2{0x1601, od::object_code::record, "Receive PDO 2"sv, dictionary.entries().subspan(12, 3), dictionary.infos().subspan(12, 3)};
inline constexpr od::descriptor receive_pdo_2_nbr_of_entries{detail::entries[12], detail::infos[12]}; // 0x1601 sub 0
inline constexpr od::descriptor receive_pdo_2_controlword{detail::entries[13], detail::infos[13]}; // 0x1601 sub 1
inline constexpr od::descriptor receive_pdo_2_target_position{detail::entries[14], detail::infos[14]}; // 0x1601 sub 2
inline constexpr od::object receive_pdo_17{0x1611, od::object_code::record, "Receive PDO 17"sv, dictionary.entries().subspan(15, 4), dictionary.infos().subspan(15, 4)};
inline constexpr od::descriptor receive_pdo_17_nbr_of_entries{detail::entries[15], detail::infos[15]}; // 0x1611 sub 0
inline constexpr od::descriptor receive_pdo_17_controlword{detail::entries[16], detail::infos[16]}; // 0x1611 sub 1
inline constexpr od::descriptor receive_pdo_17_target_position{detail::entries[17], detail::infos[17]}; // 0x1611 sub 2
inline constexpr od::descriptor receive_pdo_17_digital_outputs{detail::entries[18], detail::infos[18]}; // 0x1611 sub 3
inline constexpr od::object receive_pdo_18{0x1612, od::object_code::record, "Receive PDO 18"sv, dictionary.entries().subspan(19, 10), dictionary.infos().subspan(19, 10)};
inline constexpr od::descriptor receive_pdo_18_nbr_of_entries{detail::entries[19], detail::infos[19]}; // 0x1612 sub 0
inline constexpr od::descriptor receive_pdo_18_controlword{detail::entries[20], detail::infos[20]}; // 0x1612 sub 1
inline constexpr od::descriptor receive_pdo_18_target_position{detail::entries[21], detail::infos[21]}; // 0x1612 sub 2
inline constexpr od::descriptor receive_pdo_18_speed{detail::entries[22], detail::infos[22]}; // 0x1612 sub 3
inline constexpr od::descriptor receive_pdo_18_acceleration{detail::entries[23], detail::infos[23]}; // 0x1612 sub 4
inline constexpr od::descriptor receive_pdo_18_deceleration_reserved_for_future{detail::entries[24], detail::infos[24]}; // 0x1612 sub 5
inline constexpr od::descriptor receive_pdo_18_s_curve{detail::entries[25], detail::infos[25]}; // 0x1612 sub 6
inline constexpr od::descriptor receive_pdo_18_following_position_error_window{detail::entries[26], detail::infos[26]}; // 0x1612 sub 7
inline constexpr od::descriptor receive_pdo_18_target_position_error_window{detail::entries[27], detail::infos[27]}; // 0x1612 sub 8
inline constexpr od::descriptor receive_pdo_18_digital_outputs{detail::entries[28], detail::infos[28]}; // 0x1612 sub 9
inline constexpr od::object receive_pdo_19_reserved_for_future{0x1613, od::object_code::record, "Receive PDO 19 (reserved for future)"sv, dictionary.entries().subspan(29, 6), dictionary.infos().subspan(29, 6)};
inline constexpr od::descriptor receive_pdo_19_reserved_for_future_nbr_of_entries{detail::entries[29], detail::infos[29]}; // 0x1613 sub 0
inline constexpr od::descriptor receive_pdo_19_reserved_for_future_controlword{detail::entries[30], detail::infos[30]}; // 0x1613 sub 1
inline constexpr od::descriptor receive_pdo_19_reserved_for_future_speed{detail::entries[31], detail::infos[31]}; // 0x1613 sub 2
inline constexpr od::descriptor receive_pdo_19_reserved_for_future_reserved_for_future_2001{detail::entries[32], detail::infos[32]}; // 0x1613 sub 3
inline constexpr od::descriptor receive_pdo_19_reserved_for_future_reserved_for_future_2003{detail::entries[33], detail::infos[33]}; // 0x1613 sub 4
inline constexpr od::descriptor receive_pdo_19_reserved_for_future_digital_outputs{detail::entries[34], detail::infos[34]}; // 0x1613 sub 5
inline constexpr od::object receive_pdo_20_reserved_for_future{0x1614, od::object_code::record, "Receive PDO 20 (reserved for future)"sv, dictionary.entries().subspan(35, 4), dictionary.infos().subspan(35, 4)};
inline constexpr od::descriptor receive_pdo_20_reserved_for_future_nbr_of_entries{detail::entries[35], detail::infos[35]}; // 0x1614 sub 0
inline constexpr od::descriptor receive_pdo_20_reserved_for_future_controlword{detail::entries[36], detail::infos[36]}; // 0x1614 sub 1
inline constexpr od::descriptor receive_pdo_20_reserved_for_future_reserved_for_future_2002{detail::entries[37], detail::infos[37]}; // 0x1614 sub 2
inline constexpr od::descriptor receive_pdo_20_reserved_for_future_digital_outputs{detail::entries[38], detail::infos[38]}; // 0x1614 sub 3
inline constexpr od::object receive_pdo_21{0x1615, od::object_code::record, "Receive PDO 21"sv, dictionary.entries().subspan(39, 6), dictionary.infos().subspan(39, 6)};
inline constexpr od::descriptor receive_pdo_21_nbr_of_entries{detail::entries[39], detail::infos[39]}; // 0x1615 sub 0
inline constexpr od::descriptor receive_pdo_21_controlword{detail::entries[40], detail::infos[40]}; // 0x1615 sub 1
inline constexpr od::descriptor receive_pdo_21_target_position{detail::entries[41], detail::infos[41]}; // 0x1615 sub 2
inline constexpr od::descriptor receive_pdo_21_following_position_error_window{detail::entries[42], detail::infos[42]}; // 0x1615 sub 3
inline constexpr od::descriptor receive_pdo_21_target_position_error_window{detail::entries[43], detail::infos[43]}; // 0x1615 sub 4
inline constexpr od::descriptor receive_pdo_21_i_force_max{detail::entries[44], detail::infos[44]}; // 0x1615 sub 5
inline constexpr od::object transmit_pdo_1{0x1A00, od::object_code::record, "Transmit PDO 1"sv, dictionary.entries().subspan(45, 2), dictionary.infos().subspan(45, 2)};
inline constexpr od::descriptor transmit_pdo_1_nbr_of_entries{detail::entries[45], detail::infos[45]}; // 0x1A00 sub 0
inline constexpr od::descriptor transmit_pdo_1_statusword{detail::entries[46], detail::infos[46]}; // 0x1A00 sub 1
inline constexpr od::object transmit_pdo_2{0x1A01, od::object_code::record, "Transmit PDO 2"sv, dictionary.entries().subspan(47, 3), dictionary.infos().subspan(47, 3)};
inline constexpr od::descriptor transmit_pdo_2_nbr_of_entries{detail::entries[47], detail::infos[47]}; // 0x1A01 sub 0
inline constexpr od::descriptor transmit_pdo_2_statusword{detail::entries[48], detail::infos[48]}; // 0x1A01 sub 1
inline constexpr od::descriptor transmit_pdo_2_actual_position{detail::entries[49], detail::infos[49]}; // 0x1A01 sub 2
inline constexpr od::object transmit_pdo_17{0x1A10, od::object_code::record, "Transmit PDO 17"sv, dictionary.entries().subspan(50, 4), dictionary.infos().subspan(50, 4)};
inline constexpr od::descriptor transmit_pdo_17_nbr_of_entries{detail::entries[50], detail::infos[50]}; // 0x1A10 sub 0
inline constexpr od::descriptor transmit_pdo_17_statusword{detail::entries[51], detail::infos[51]}; // 0x1A10 sub 1
inline constexpr od::descriptor transmit_pdo_17_actual_position{detail::entries[52], detail::infos[52]}; // 0x1A10 sub 2
inline constexpr od::descriptor transmit_pdo_17_digital_inputs{detail::entries[53], detail::infos[53]}; // 0x1A10 sub 3
inline constexpr od::object transmit_pdo_18{0x1A11, od::object_code::record, "Transmit PDO 18"sv, dictionary.entries().subspan(54, 6), dictionary.infos().subspan(54, 6)};
inline constexpr od::descriptor transmit_pdo_18_nbr_of_entries{detail::entries[54], detail::infos[54]}; // 0x1A11 sub 0
inline constexpr od::descriptor transmit_pdo_18_statusword{detail::entries[55], detail::infos[55]}; // 0x1A11 sub 1
inline constexpr od::descriptor transmit_pdo_18_actual_position{detail::entries[56], detail::infos[56]}; // 0x1A11 sub 2
inline constexpr od::descriptor transmit_pdo_18_actual_following_position_error{detail::entries[57], detail::infos[57]}; // 0x1A11 sub 3
inline constexpr od::descriptor transmit_pdo_18_actual_current{detail::entries[58], detail::infos[58]}; // 0x1A11 sub 4
inline constexpr od::descriptor transmit_pdo_18_digital_inputs{detail::entries[59], detail::infos[59]}; // 0x1A11 sub 5
inline constexpr od::object transmit_pdo_19_reserved_for_future{0x1A12, od::object_code::record, "Transmit PDO 19 (reserved for future)"sv, dictionary.entries().subspan(60, 5), dictionary.infos().subspan(60, 5)};
inline constexpr od::descriptor transmit_pdo_19_reserved_for_future_nbr_of_entries{detail::entries[60], detail::infos[60]}; // 0x1A12 sub 0
inline constexpr od::descriptor transmit_pdo_19_reserved_for_future_statusword{detail::entries[61], detail::infos[61]}; // 0x1A12 sub 1
inline constexpr od::descriptor transmit_pdo_19_reserved_for_future_actual_position{detail::entries[62], detail::infos[62]}; // 0x1A12 sub 2
inline constexpr od::descriptor transmit_pdo_19_reserved_for_future_i_force_actual{detail::entries[63], detail::infos[63]}; // 0x1A12 sub 3
inline constexpr od::descriptor transmit_pdo_19_reserved_for_future_digital_inputs{detail::entries[64], detail::infos[64]}; // 0x1A12 sub 4
inline constexpr od::object transmit_pdo_21{0x1A13, od::object_code::record, "Transmit PDO 21"sv, dictionary.entries().subspan(65, 6), dictionary.infos().subspan(65, 6)};
inline constexpr od::descriptor transmit_pdo_21_nbr_of_entries{detail::entries[65], detail::infos[65]}; // 0x1A13 sub 0
inline constexpr od::descriptor transmit_pdo_21_statusword{detail::entries[66], detail::infos[66]}; // 0x1A13 sub 1
inline constexpr od::descriptor transmit_pdo_21_actual_position{detail::entries[67], detail::infos[67]}; // 0x1A13 sub 2
inline constexpr od::descriptor transmit_pdo_21_actual_following_position_error{detail::entries[68], detail::infos[68]}; // 0x1A13 sub 3
inline constexpr od::descriptor transmit_pdo_21_actual_current{detail::entries[69], detail::infos[69]}; // 0x1A13 sub 4
inline constexpr od::descriptor transmit_pdo_21_process_status_register{detail::entries[70], detail::infos[70]}; // 0x1A13 sub 5
inline constexpr od::object sync_manager_communication_type{0x1C00, od::object_code::array, "Sync Manager Communication Type"sv, dictionary.entries().subspan(71, 6), dictionary.infos().subspan(71, 6)};
inline constexpr od::object sync_manager_pdo_assignment_0{0x1C10, od::object_code::array, "Sync Manager PDO Assignment 0"sv, dictionary.entries().subspan(77, 1), dictionary.infos().subspan(77, 1)};
inline constexpr od::object sync_manager_pdo_assignment_1{0x1C11, od::object_code::array, "Sync Manager PDO Assignment 1"sv, dictionary.entries().subspan(78, 1), dictionary.infos().subspan(78, 1)};
inline constexpr od::object sync_manager_pdo_assignment_2{0x1C12, od::object_code::array, "Sync Manager PDO Assignment 2"sv, dictionary.entries().subspan(79, 2), dictionary.infos().subspan(79, 2)};
inline constexpr od::object sync_manager_pdo_assignment_3{0x1C13, od::object_code::array, "Sync Manager PDO Assignment 3"sv, dictionary.entries().subspan(81, 2), dictionary.infos().subspan(81, 2)};
inline constexpr od::object read_parameter{0x5001, od::object_code::array, "Read Parameter"sv, dictionary.entries().subspan(95, 46), dictionary.infos().subspan(95, 46)};
inline constexpr od::object write_parameter{0x5002, od::object_code::array, "Write Parameter"sv, dictionary.entries().subspan(141, 17), dictionary.infos().subspan(141, 17)};
inline constexpr od::object read_write_parameter{0x5003, od::object_code::array, "Read Write Parameter"sv, dictionary.entries().subspan(158, 107), dictionary.infos().subspan(158, 107)};
inline constexpr od::object motor_parameter{0x5004, od::object_code::array, "Motor Parameter"sv, dictionary.entries().subspan(265, 12), dictionary.infos().subspan(265, 12)};
inline constexpr od::object smu_parameter{0x5005, od::object_code::array, "SMU Parameter"sv, dictionary.entries().subspan(277, 14), dictionary.infos().subspan(277, 14)};
inline constexpr od::object xvi75v8s_and_xvi48v8_parameter{0x5006, od::object_code::array, "Xvi75V8S and Xvi48V8 Parameter"sv, dictionary.entries().subspan(291, 11), dictionary.infos().subspan(291, 11)};
inline constexpr od::object forceteq_pro_parameter{0x5010, od::object_code::array, "Forceteq pro Parameter"sv, dictionary.entries().subspan(302, 15), dictionary.infos().subspan(302, 15)};
inline constexpr od::object soft_limit_positions{0x607D, od::object_code::array, "Soft-Limit Positions"sv, dictionary.entries().subspan(334, 3), dictionary.infos().subspan(334, 3)};
inline constexpr od::object reference_speeds{0x6099, od::object_code::array, "Reference Speeds"sv, dictionary.entries().subspan(342, 3), dictionary.infos().subspan(342, 3)};
inline constexpr od::object synchronous_cycle_time{0x60C2, od::object_code::record, "Synchronous Cycle Time"sv, dictionary.entries().subspan(347, 3), dictionary.infos().subspan(347, 3)};
inline constexpr od::descriptor synchronous_cycle_time_highest_sub_index_value{detail::entries[347], detail::infos[347]}; // 0x60C2 sub 0
inline constexpr od::descriptor synchronous_cycle_time_base_value{detail::entries[348], detail::infos[348]}; // 0x60C2 sub 1
inline constexpr od::descriptor synchronous_cycle_time_n_10_exponent{detail::entries[349], detail::infos[349]}; // 0x60C2 sub 2
inline constexpr od::object digital_outputs{0x60FE, od::object_code::array, "Digital Outputs"sv, dictionary.entries().subspan(352, 3), dictionary.infos().subspan(352, 3)};

} // namespace fieldcodec::dictionaries::xenax_ethercat
// clang-format on
