// Generated from dpq_parameters.csv by fieldcodec-gen — do not edit.
// Regenerate with codegen/regenerate.sh (or the fieldcodec_generate_dictionary CMake function).
// clang-format off
#pragma once

#include <fieldcodec/core/scaling.hpp>
#include <fieldcodec/dpq/columns.hpp>
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

namespace fieldcodec::dictionaries::dpq_parameters {

using namespace std::string_view_literals;

inline constexpr const char *source_file = "dpq_parameters.csv";

namespace detail {
inline constexpr od::entry entries[240]{
    {.index = 0x1001, .type = od::data_type::unsigned8, .access_type = od::access::ro},
    {.index = 0x1003, .object = od::object_code::array, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\004"},
    {.index = 0x1003, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro},
    {.index = 0x1003, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro},
    {.index = 0x1003, .sub = 3, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro},
    {.index = 0x1003, .sub = 4, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro},
    {.index = 0x100C, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377"},
    {.index = 0x100D, .type = od::data_type::unsigned8, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\377"},
    {.index = 0x1016, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_low | od::flag::has_high, .extra = "\001\177"},
    {.index = 0x1016, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\000\000\000\000\377\377\377\000"},
    {.index = 0x1017, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377"},
    {.index = 0x1800, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_low | od::flag::has_high, .extra = "\005\006"},
    {.index = 0x1800, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377"},
    {.index = 0x1801, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_low | od::flag::has_high, .extra = "\005\006"},
    {.index = 0x1801, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377"},
    {.index = 0x1802, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_low | od::flag::has_high, .extra = "\005\006"},
    {.index = 0x1802, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377"},
    {.index = 0x1803, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_low | od::flag::has_high, .extra = "\005\006"},
    {.index = 0x1803, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\377\377"},
    {.index = 0x200D, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000d\000\000\000"},
    {.index = 0x200E, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x200F, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2010, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2011, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2012, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2013, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2014, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2015, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2017, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2018, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x201F, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2023, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2025, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2026, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2027, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2028, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x202F, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2030, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2031, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2032, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2033, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2036, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2037, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2039, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x203A, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x203C, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x203D, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x203E, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x203F, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2040, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2041, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2114, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2130, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2131, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2132, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2133, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2136, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2137, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x213A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2167, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2169, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x216A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x216B, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x216C, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2180, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2181, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2182, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2183, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2184, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2195, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2196, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2197, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2198, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2199, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x219C, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x219D, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x21A0, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\210\023"},
    {.index = 0x2201, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000A\000"},
    {.index = 0x2301, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\017'\000\000\000\000\000\000"},
    {.index = 0x2323, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\017'\000\000\000\000\000\000"},
    {.index = 0x2336, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\017'\000\000\000\000\000\000"},
    {.index = 0x2337, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\017'\000\000\000\000\000\000"},
    {.index = 0x233A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\017'\000\000\000\000\000\000"},
    {.index = 0x2423, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\0000u"},
    {.index = 0x2436, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\0000u"},
    {.index = 0x2437, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\0000u"},
    {.index = 0x243A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\0000u"},
    {.index = 0x2701, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\200\002"},
    {.index = 0x2723, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\200\002"},
    {.index = 0x2736, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\200\002"},
    {.index = 0x2737, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\200\002"},
    {.index = 0x273A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\200\002"},
    {.index = 0x2923, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\001\000"},
    {.index = 0x2936, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\001\000"},
    {.index = 0x2937, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\001\000"},
    {.index = 0x293A, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\001\000"},
    {.index = 0x2A01, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377\210\023\000\000"},
    {.index = 0x2A03, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377\210\023\000\000"},
    {.index = 0x2A04, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377\210\023\000\000"},
    {.index = 0x2A05, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377\210\023\000\000"},
    {.index = 0x2A06, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377\210\023\000\000"},
    {.index = 0x2A14, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2A15, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2A17, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2A1A, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377\210\023\000\000"},
    {.index = 0x2A1B, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377\210\023\000\000"},
    {.index = 0x2A1C, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377\210\023\000\000"},
    {.index = 0x2A1D, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377\210\023\000\000"},
    {.index = 0x2A64, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::index_anomaly | od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2B2F, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\237\206\001\000\000\000\000\000"},
    {.index = 0x2B30, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\237\206\001\000\000\000\000\000"},
    {.index = 0x2B31, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\237\206\001\000\000\000\000\000"},
    {.index = 0x2B32, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\237\206\001\000\000\000\000\000"},
    {.index = 0x2B33, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\237\206\001\000\000\000\000\000"},
    {.index = 0x2C67, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2C68, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2C69, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2C78, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2D02, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\200\002"},
    {.index = 0x2D04, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\001\377\011\000\000\000\000\000\000"},
    {.index = 0x2D05, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\001\000\000\000\000\000\000\000\000\000\004\002\017'\000\000\000\000\000\000"},
    {.index = 0x2D0E, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2D0F, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2D17, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000<\000"},
    {.index = 0x2D3B, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2D3C, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2D3D, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2D3E, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2D71, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D72, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D73, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D74, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D75, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D76, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D7C, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D7D, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D7E, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D7F, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D80, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D81, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2D87, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D88, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D89, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D8A, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D8B, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D8C, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D92, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D93, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D94, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D95, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D96, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D97, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "j\377\226\000"},
    {.index = 0x2D9D, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2D9E, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2D9F, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2DA0, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2DA1, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2DC1, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\001\000\031\000"},
    {.index = 0x2DC4, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\377\177"},
    {.index = 0x2DC5, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2DCB, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2DCC, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\377\177"},
    {.index = 0x2E21, .type = od::data_type::integer16, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\004\001\031\374\377\377\377\377\377\377\004\001\347\003\000\000\000\000\000\000"},
    {.index = 0x2E2A, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2E2D, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2E2E, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\000\000"},
    {.index = 0x2F03, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2F04, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\350\003\000\000"},
    {.index = 0x2F07, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\350\003\000\000"},
    {.index = 0x2F09, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\030\374\377\377\350\003\000\000"},
    {.index = 0x2F0B, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\310\000\000\000"},
    {.index = 0x2F0E, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\310\000\000\000"},
    {.index = 0x2F0F, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\310\000\000\000"},
    {.index = 0x2F10, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\310\000\000\000"},
    {.index = 0x2F11, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\310\000\000\000"},
    {.index = 0x2F13, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "8\377\377\377\310\000\000\000"},
    {.index = 0x2F19, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\320\007\000\000"},
    {.index = 0x2F1A, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\350\003\000\000"},
    {.index = 0x2F1F, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2F20, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2F21, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x2F25, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000 \000"},
    {.index = 0x2F26, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F27, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F28, .type = od::data_type::unsigned16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000 \000"},
    {.index = 0x2F34, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F6D, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F72, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2F78, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\000\000\000\000\210\023\000\000"},
    {.index = 0x2F7F, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F80, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\004\001\031\374\377\377\377\377\377\377\004\001\347\003\000\000\000\000\000\000"},
    {.index = 0x2F81, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F82, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F87, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\000\000"},
    {.index = 0x2F91, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F92, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\004\001\031\374\377\377\377\377\377\377\004\001\347\003\000\000\000\000\000\000"},
    {.index = 0x2F93, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F94, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2F99, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\000\000"},
    {.index = 0x2FA3, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2FA4, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\004\001\031\374\377\377\377\377\377\377\004\001\347\003\000\000\000\000\000\000"},
    {.index = 0x2FA5, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2FA6, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377d\000"},
    {.index = 0x2FAB, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\000\000"},
    {.index = 0x3116, .type = od::data_type::integer16, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high | od::flag::limits_number, .extra = "\004\001\301\376\377\377\377\377\377\377\004\001\077\001\000\000\000\000\000\000"},
    {.index = 0x3501, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3503, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3504, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3505, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3506, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x350E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x350F, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3510, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3511, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3512, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3518, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x351B, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x351C, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x351D, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x351E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x351F, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3571, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3601, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3602, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3603, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3604, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3605, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3606, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x360D, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x360E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x360F, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3610, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3611, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x3617, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x361A, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x361B, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x361C, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x361D, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x361E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
    {.index = 0x362E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled | od::flag::has_low | od::flag::has_high, .extra = "\234\377\377\377d\000\000\000"},
};

inline constexpr od::entry_info infos[240]{
    {.name = {"Error Register", 14}, .section = {"3.5", 3}},
    {.name = {"Error History", 13}, .section = {"3.5", 3}, .remark = {"number of errors; writing 0 clears the history", 46}},
    {.name = {"Error Code 1", 12}, .section = {"3.5", 3}, .remark = {"bits 0-15 EMCY code, bits 16-31 manufacturer-specific", 53}},
    {.name = {"Error Code 2", 12}, .section = {"3.5", 3}, .remark = {"bits 0-15 EMCY code, bits 16-31 manufacturer-specific", 53}},
    {.name = {"Error Code 3", 12}, .section = {"3.5", 3}, .remark = {"bits 0-15 EMCY code, bits 16-31 manufacturer-specific", 53}},
    {.name = {"Error Code 4", 12}, .section = {"3.5", 3}, .remark = {"bits 0-15 EMCY code, bits 16-31 manufacturer-specific", 53}},
    {.name = {"Guard Time", 10}, .unit = {"ms", 2}, .section = {"3.1", 3}, .remark = {"Life Time = Guard Time x Life Time Factor", 41}},
    {.name = {"Life Time Factor", 16}, .section = {"3.1", 3}},
    {.name = {"Consumer Heartbeat Time", 23}, .section = {"3.1", 3}, .remark = {"number of entries; not printed (CiA 301: 1..127)", 48}},
    {.name = {"Consumer Heartbeat Time Interval", 32}, .section = {"3.1", 3}, .remark = {"bits 0-15 time in ms, bits 16-23 producer node-ID", 49}},
    {.name = {"Producer Heartbeat Time Interval", 32}, .unit = {"ms", 2}, .section = {"3.1", 3}, .remark = {"not 0: heartbeat instead of node guarding", 41}},
    {.name = {"Tx-PDO1 Communication Parameter", 31}, .section = {"3.4", 3}, .remark = {"highest sub-index supported; not printed", 40}},
    {.name = {"Tx-PDO1 Event Timer", 19}, .unit = {"ms", 2}, .section = {"3.4", 3}, .remark = {"0: the PDO is not sent", 22}},
    {.name = {"Tx-PDO2 Communication Parameter", 31}, .section = {"3.4", 3}, .remark = {"highest sub-index supported; not printed", 40}},
    {.name = {"Tx-PDO2 Event Timer", 19}, .unit = {"ms", 2}, .section = {"3.4", 3}, .remark = {"0: the PDO is not sent", 22}},
    {.name = {"Tx-PDO3 Communication Parameter", 31}, .section = {"3.4", 3}, .remark = {"highest sub-index supported; not printed", 40}},
    {.name = {"Tx-PDO3 Event Timer", 19}, .unit = {"ms", 2}, .section = {"3.4", 3}, .remark = {"0: the PDO is not sent", 22}},
    {.name = {"Tx-PDO4 Communication Parameter", 31}, .section = {"3.4", 3}, .remark = {"highest sub-index supported; not printed", 40}},
    {.name = {"Tx-PDO4 Event Timer", 19}, .unit = {"ms", 2}, .section = {"3.4", 3}, .remark = {"0: the PDO is not sent", 22}},
    {.name = {"Holding: Vel.Limit 1", 20}, .section = {"4.92", 4}, .remark = {"signed although the printed range is not negative: Holding: Vel.Limit 2..5 are -100..100 (docs/dpq.md)", 102}},
    {.name = {"Holding: Vel.Limit 2", 20}, .section = {"4.93", 4}},
    {.name = {"Holding: Vel.Limit 3", 20}, .section = {"4.94", 4}},
    {.name = {"Holding: Vel.Limit 4", 20}, .section = {"4.95", 4}},
    {.name = {"Holding: Vel.Limit 5", 20}, .section = {"4.96", 4}},
    {.name = {"JogMode:Vel.Forward", 19}, .unit = {"%", 1}, .section = {"4.141", 5}, .remark = {"name follows the Name line; the table of contents prints \"Jog Mode: Vel. Forward\"", 81}},
    {.name = {"JogMode:Vel.Backward", 20}, .unit = {"%", 1}, .section = {"4.140", 5}, .remark = {"name follows the Name line; the table of contents prints \"Jog Mode: Vel. Backward\"", 82}},
    {.name = {"Screw Speed 2", 13}, .section = {"4.199", 5}},
    {.name = {"Screw Speed 3", 13}, .section = {"4.200", 5}},
    {.name = {"Pre.Decomp: Velocity", 20}, .section = {"4.172", 5}},
    {.name = {"Screw Speed 4", 13}, .section = {"4.201", 5}},
    {.name = {"Post.Decomp: Velocit", 20}, .section = {"4.170", 5}},
    {.name = {"Inj. P Limit 1", 14}, .section = {"4.100", 5}},
    {.name = {"Inj. P Limit 2", 14}, .section = {"4.102", 5}},
    {.name = {"Inj. P Limit 3", 14}, .section = {"4.103", 5}},
    {.name = {"Inj. P Limit 4", 14}, .section = {"4.104", 5}},
    {.name = {"Inj. P Limit 5", 14}, .section = {"4.105", 5}},
    {.name = {"Holding: Pressure 1", 19}, .section = {"4.82", 4}},
    {.name = {"Holding: Pressure 2", 19}, .section = {"4.83", 4}},
    {.name = {"Holding: Pressure 3", 19}, .section = {"4.84", 4}},
    {.name = {"Holding: Pressure 4", 19}, .section = {"4.85", 4}},
    {.name = {"Holding: Pressure 5", 19}, .section = {"4.86", 4}},
    {.name = {"BackPress: Press 2", 18}, .section = {"4.20", 4}},
    {.name = {"BackPress: Press 3", 18}, .section = {"4.21", 4}},
    {.name = {"Press: PreDecompress", 20}, .unit = {"bar", 3}, .section = {"4.191", 5}},
    {.name = {"BackPress: Press 4", 18}, .section = {"4.22", 4}},
    {.name = {"Inj. P Limit 6", 14}, .section = {"4.106", 5}},
    {.name = {"Inj. P Limit 7", 14}, .section = {"4.107", 5}},
    {.name = {"Inj. P Limit 8", 14}, .section = {"4.108", 5}},
    {.name = {"Inj. P Limit 9", 14}, .section = {"4.109", 5}},
    {.name = {"Inj. P Limit 10", 15}, .section = {"4.101", 5}},
    {.name = {"Press: PostDecompres", 20}, .unit = {"bar", 3}, .section = {"4.190", 5}, .remark = {"name follows the Name line; the table of contents prints \"Press: PostDecompress\"", 80}},
    {.name = {"BackP: Vel. Ramp 2", 18}, .unit = {"%/sec", 5}, .section = {"4.17", 4}},
    {.name = {"PaH: Press Rate 2", 17}, .section = {"4.158", 5}},
    {.name = {"PaH: Press Rate 3", 17}, .section = {"4.159", 5}},
    {.name = {"PaH: Press Rate 4", 17}, .section = {"4.160", 5}},
    {.name = {"PaH: Press Rate 5", 17}, .unit = {"bar/sec", 7}, .section = {"4.161", 5}},
    {.name = {"BackP: Press Rate 2", 19}, .section = {"4.14", 4}},
    {.name = {"BackP: Press Rate 3", 19}, .section = {"4.15", 4}},
    {.name = {"BackP: Press Rate 4", 19}, .unit = {"bar/sec", 7}, .section = {"4.16", 4}},
    {.name = {"Inj. Velocity 1", 15}, .section = {"4.119", 5}},
    {.name = {"Inj. Velocity 2", 15}, .section = {"4.121", 5}},
    {.name = {"Inj. Velocity 3", 15}, .section = {"4.122", 5}},
    {.name = {"Inj. Velocity 4", 15}, .section = {"4.123", 5}},
    {.name = {"Inj. Velocity 5", 15}, .section = {"4.124", 5}},
    {.name = {"Inj. Velocity 6", 15}, .section = {"4.125", 5}},
    {.name = {"Inj. Velocity 7", 15}, .section = {"4.126", 5}},
    {.name = {"Inj. Velocity 8", 15}, .section = {"4.127", 5}},
    {.name = {"Inj. Velocity 9", 15}, .section = {"4.128", 5}},
    {.name = {"Inj. Velocity 10", 16}, .section = {"4.120", 5}},
    {.name = {"PaH: Decomp Rate 1", 18}, .section = {"4.153", 5}},
    {.name = {"PaH: Decomp Rate 2", 18}, .section = {"4.154", 5}},
    {.name = {"PaH: Decomp Rate 3", 18}, .section = {"4.155", 5}},
    {.name = {"PaH: Decomp Rate 4", 18}, .section = {"4.156", 5}},
    {.name = {"PaH: Decomp Rate 5", 18}, .unit = {"bar/sec", 7}, .section = {"4.157", 5}},
    {.name = {"BackP: Decomp Rate 2", 20}, .section = {"4.2", 3}},
    {.name = {"BackP: Decomp Rate 3", 20}, .section = {"4.3", 3}},
    {.name = {"BackP: Decomp Rate 4", 20}, .unit = {"bar/sec", 7}, .section = {"4.4", 3}},
    {.name = {"Inj. Accel.Ramp", 15}, .unit = {"[s]", 3}, .section = {"4.99", 4}},
    {.name = {"Inj.: Velocity P", 16}, .section = {"4.131", 5}},
    {.name = {"PaH: Pressure P", 15}, .section = {"4.164", 5}},
    {.name = {"BackP: Press P 2", 16}, .section = {"4.11", 4}},
    {.name = {"BackP: Press P 3", 16}, .section = {"4.12", 4}},
    {.name = {"BackP: Press P 4", 16}, .section = {"4.13", 4}},
    {.name = {"PaH: Pressure I", 15}, .unit = {"ms", 2}, .section = {"4.163", 5}},
    {.name = {"BackP: Press I 2", 16}, .section = {"4.8", 3}},
    {.name = {"BackP: Press I 3", 16}, .section = {"4.9", 3}},
    {.name = {"BackP: Press I 4", 16}, .unit = {"ms", 2}, .section = {"4.10", 4}},
    {.name = {"Inj.: Velocity D", 16}, .unit = {"Hz", 2}, .section = {"4.130", 5}},
    {.name = {"PaH: Pressure D", 15}, .unit = {"Hz", 2}, .section = {"4.162", 5}},
    {.name = {"BackP: Press D 2", 16}, .section = {"4.5", 3}},
    {.name = {"BackP: Press D 3", 16}, .section = {"4.6", 3}},
    {.name = {"BackP: Press D 4", 16}, .unit = {"Hz", 2}, .section = {"4.7", 3}},
    {.name = {"FWD: Inject", 11}, .section = {"4.46", 4}},
    {.name = {"FWD: BackPress 1", 16}, .section = {"4.43", 4}},
    {.name = {"FWD: BackPress 2", 16}, .section = {"4.44", 4}},
    {.name = {"FWD: BackPress 3", 16}, .section = {"4.45", 4}},
    {.name = {"Inj. Position 2", 15}, .section = {"4.111", 5}},
    {.name = {"Inj. Position 3", 15}, .section = {"4.112", 5}},
    {.name = {"Inj. Position 4", 15}, .section = {"4.113", 5}},
    {.name = {"Inj. Position 5", 15}, .section = {"4.114", 5}},
    {.name = {"Inj. Position 6", 15}, .section = {"4.115", 5}},
    {.name = {"BackPress: Position3", 20}, .section = {"4.18", 4}},
    {.name = {"BackPress: Position4", 20}, .section = {"4.19", 4}},
    {.name = {"Pre.Decomp: Position", 20}, .section = {"4.171", 5}},
    {.name = {"Inj. Position 7", 15}, .section = {"4.116", 5}},
    {.name = {"Inj. Position 8", 15}, .section = {"4.117", 5}},
    {.name = {"Inj. Position 9", 15}, .section = {"4.118", 5}},
    {.name = {"Inj. Position 10", 16}, .section = {"4.110", 5}},
    {.name = {"Post.Decomp: Positio", 20}, .section = {"4.169", 5}, .remark = {"index_anomaly: Pre/Post pairs differ by 8 (0x2017/0x201F, 0x2039/0x2041) and Pre.Decomp: Position is 0x2A17, so 0x2A1F would be expected; as printed, see docs/errata.md", 168}},
    {.name = {"Holding: Time 1", 15}, .section = {"4.87", 4}},
    {.name = {"Holding: Time 2", 15}, .section = {"4.88", 4}},
    {.name = {"Holding: Time 3", 15}, .section = {"4.89", 4}},
    {.name = {"Holding: Time 4", 15}, .section = {"4.90", 4}},
    {.name = {"Holding: Time 5", 15}, .section = {"4.91", 4}},
    {.name = {"Trigger", 7}, .section = {"4.212", 5}},
    {.name = {"Status", 6}, .section = {"4.207", 5}},
    {.name = {"Analog Vel Max", 14}, .unit = {"mm/s", 4}, .section = {"4.1", 3}},
    {.name = {"Set SSI/INCR to zero", 20}, .section = {"4.202", 5}},
    {.name = {"PaH: act.Damp. Freq.", 20}, .unit = {"Hz", 2}, .section = {"4.151", 5}, .remark = {"name follows the Name line; the table of contents prints \"PaH: act.Damp. Freq\"", 78}},
    {.name = {"Inj.: Vel.ActiveDamp", 20}, .section = {"4.129", 5}},
    {.name = {"PaH: act.Damp. Gain", 19}, .section = {"4.152", 5}},
    {.name = {"Shot Size Position", 18}, .section = {"4.203", 5}},
    {.name = {"DO7: At Press Level", 19}, .unit = {"bar", 3}, .section = {"4.42", 4}},
    {.name = {"DO7: At Press Delay", 19}, .unit = {"sec", 3}, .section = {"4.41", 4}},
    {.name = {"Transfer Position", 17}, .unit = {"mm", 2}, .section = {"4.211", 5}},
    {.name = {"Transfer Cavity Pres", 20}, .unit = {"bar", 3}, .section = {"4.208", 5}},
    {.name = {"Transfer Hydr.Press", 19}, .unit = {"bar", 3}, .section = {"4.210", 5}},
    {.name = {"Transfer Hydr.Pos.", 18}, .unit = {"mm", 2}, .section = {"4.209", 5}, .remark = {"name follows the Name line; the table of contents prints \"Transfer Hydr.Pos\" (a trailing dot cannot be told apart from the dot leader)", 134}},
    {.name = {"Press CMD Min", 13}, .section = {"4.177", 5}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}},
    {.name = {"Press FB #1 Min", 15}, .section = {"4.182", 5}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}},
    {.name = {"Cavity Press Min", 16}, .section = {"4.26", 4}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}},
    {.name = {"Press FB #2 Min", 15}, .section = {"4.187", 5}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}},
    {.name = {"Cyl Pos FB Min", 14}, .section = {"4.32", 4}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}},
    {.name = {"Vel. CMD Min", 12}, .section = {"4.219", 5}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}},
    {.name = {"Press CMD Max", 13}, .section = {"4.174", 5}},
    {.name = {"Press FB #1 Max", 15}, .section = {"4.179", 5}},
    {.name = {"Cavity Press Max", 16}, .section = {"4.23", 4}},
    {.name = {"Press FB #2 Max", 15}, .section = {"4.184", 5}},
    {.name = {"Cyl Pos FB Max", 14}, .section = {"4.30", 4}},
    {.name = {"Vel. CMD Max", 12}, .section = {"4.217", 5}},
    {.name = {"Press CMD Min Fau", 17}, .unit = {"bar", 3}, .section = {"4.178", 5}},
    {.name = {"Press FB #1 Min Fau", 19}, .unit = {"bar", 3}, .section = {"4.183", 5}},
    {.name = {"Cavity Press Min Fau", 20}, .unit = {"bar", 3}, .section = {"4.27", 4}},
    {.name = {"Press FB #2 Min Fau", 19}, .unit = {"bar", 3}, .section = {"4.188", 5}},
    {.name = {"Cyl Pos FB Min Fau", 18}, .unit = {"mm", 2}, .section = {"4.33", 4}},
    {.name = {"Vel. CMD Min Fau", 16}, .unit = {"mm/s", 4}, .section = {"4.220", 5}},
    {.name = {"Press CMD Max Fau", 17}, .unit = {"bar", 3}, .section = {"4.175", 5}},
    {.name = {"Press FB #1 Max Fau", 19}, .unit = {"bar", 3}, .section = {"4.180", 5}},
    {.name = {"Cavity Press Max Fau", 20}, .unit = {"bar", 3}, .section = {"4.24", 4}},
    {.name = {"Press FB #2 Max Fau", 19}, .unit = {"bar", 3}, .section = {"4.185", 5}},
    {.name = {"Cyl Pos FB Max Fau", 18}, .unit = {"mm", 2}, .section = {"4.31", 4}},
    {.name = {"Vel. CMD Max Fau", 16}, .unit = {"mm/s", 4}, .section = {"4.218", 5}},
    {.name = {"Press CMD Max Uni", 17}, .unit = {"bar", 3}, .section = {"4.176", 5}},
    {.name = {"Press FB #1 Max Uni", 19}, .unit = {"bar", 3}, .section = {"4.181", 5}},
    {.name = {"Cavity Press Max Uni", 20}, .unit = {"bar", 3}, .section = {"4.25", 4}},
    {.name = {"Press FB #2 Max Uni", 19}, .unit = {"bar", 3}, .section = {"4.186", 5}},
    {.name = {"Cyl Pos CMD Max Uni", 19}, .unit = {"mm", 2}, .section = {"4.29", 4}},
    {.name = {"SSI: Nb. of bits", 16}, .section = {"4.204", 5}},
    {.name = {"SSI: Resolution", 15}, .unit = {"count/mm", 8}, .section = {"4.206", 5}},
    {.name = {"SSI: Offset", 11}, .unit = {"mm", 2}, .section = {"4.205", 5}},
    {.name = {"INCR: Home Offset", 17}, .unit = {"mm", 2}, .section = {"4.97", 4}},
    {.name = {"INCR: Resolution", 16}, .unit = {"count/mm", 8}, .section = {"4.98", 4}},
    {.name = {"Injection: Scale", 16}, .section = {"4.135", 5}, .remark = {"index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 273}},
    {.name = {"Injection: Limit+", 17}, .unit = {"%", 1}, .section = {"4.133", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow; index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 384}},
    {.name = {"Injection: Limit-", 17}, .unit = {"%", 1}, .section = {"4.132", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow; index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 384}},
    {.name = {"OUT2: Inject Limit-", 19}, .unit = {"%", 1}, .section = {"4.144", 5}, .remark = {"printed range gives raw -32770..0, outside INTEGER16; the encoder refuses such values with errc::overflow; index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 380}},
    {.name = {"Velocity CMD AI6:", 17}, .unit = {"[mm/s]", 6}, .section = {"4.221", 5}},
    {.name = {"Vel Loop CMD :", 14}, .unit = {"[mm]", 4}, .section = {"4.216", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md); unit printed [mm] although this is a velocity command", 142}},
    {.name = {"Position FB :", 13}, .unit = {"[mm]", 4}, .section = {"4.168", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}},
    {.name = {"Position Error :", 16}, .unit = {"[mm]", 4}, .section = {"4.167", 5}},
    {.name = {"Pressure CMD AI1:", 17}, .unit = {"[bar]", 5}, .section = {"4.192", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}},
    {.name = {"Press Loop CMD :", 16}, .unit = {"[bar]", 5}, .section = {"4.189", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}},
    {.name = {"Pressure FB#1 AI2:", 18}, .unit = {"[bar]", 5}, .section = {"4.195", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}},
    {.name = {"Pressure FB#2 AI4:", 18}, .unit = {"[bar]", 5}, .section = {"4.196", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}},
    {.name = {"Pressure FB :", 13}, .unit = {"[bar]", 5}, .section = {"4.194", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}},
    {.name = {"Pressure Error :", 16}, .unit = {"[bar]", 5}, .section = {"4.193", 5}},
    {.name = {"Cavity Pressure AI3:", 20}, .unit = {"[bar]", 5}, .section = {"4.28", 4}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}},
    {.name = {"Position AI5:", 13}, .unit = {"[mm]", 4}, .section = {"4.166", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}},
    {.name = {"Valve Output 1 :", 16}, .unit = {"[%]", 3}, .section = {"4.213", 5}},
    {.name = {"Valve Output 2 :", 16}, .unit = {"[%]", 3}, .section = {"4.214", 5}},
    {.name = {"Valve Output 3 :", 16}, .unit = {"[%]", 3}, .section = {"4.215", 5}},
    {.name = {"Program Block", 13}, .section = {"4.197", 5}, .remark = {"offset 1: printed minimum 0 is raw -1", 37}},
    {.name = {"Discrete Outputs", 16}, .section = {"4.40", 4}},
    {.name = {"Discrete Inputs", 15}, .section = {"4.39", 4}},
    {.name = {"Output Mode", 11}, .section = {"4.146", 5}},
    {.name = {"Program Status", 14}, .section = {"4.198", 5}},
    {.name = {"Injection: Offset", 17}, .unit = {"%", 1}, .section = {"4.134", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow; index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 384}},
    {.name = {"Pos Max Length", 14}, .unit = {"mm", 2}, .section = {"4.165", 5}},
    {.name = {"Pres Max Inject", 15}, .unit = {"bar", 3}, .section = {"4.173", 5}},
    {.name = {"Jog Mode: Offset", 16}, .unit = {"%", 1}, .section = {"4.138", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}},
    {.name = {"Jog Mode: Scale", 15}, .section = {"4.139", 5}},
    {.name = {"Jog Mode: Limit-", 16}, .unit = {"%", 1}, .section = {"4.136", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}},
    {.name = {"Jog Mode: Limit+", 16}, .unit = {"%", 1}, .section = {"4.137", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}},
    {.name = {"OUT2: Jog Limit-", 16}, .unit = {"%", 1}, .section = {"4.145", 5}, .remark = {"printed range gives raw -32770..0, outside INTEGER16; the encoder refuses such values with errc::overflow", 105}},
    {.name = {"PaH/BackPres: Offset", 20}, .unit = {"%", 1}, .section = {"4.149", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}},
    {.name = {"PaH/BackPres: Scale", 19}, .section = {"4.150", 5}},
    {.name = {"PaH/BackPres: Limit-", 20}, .unit = {"%", 1}, .section = {"4.147", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}},
    {.name = {"PaH/BackPres: Limit+", 20}, .unit = {"%", 1}, .section = {"4.148", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}},
    {.name = {"OUT2: BackPress Lim-", 20}, .unit = {"%", 1}, .section = {"4.142", 5}, .remark = {"printed range gives raw -32770..0, outside INTEGER16; the encoder refuses such values with errc::overflow", 105}},
    {.name = {"Decompres.: Offset", 18}, .unit = {"%", 1}, .section = {"4.37", 4}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}},
    {.name = {"Decompres.: Scale", 17}, .section = {"4.38", 4}},
    {.name = {"Decompres.: Limit-", 18}, .unit = {"%", 1}, .section = {"4.35", 4}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}},
    {.name = {"Decompres.: Limit+", 18}, .unit = {"%", 1}, .section = {"4.36", 4}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}},
    {.name = {"OUT2: Decomp Limit-", 19}, .unit = {"%", 1}, .section = {"4.143", 5}, .remark = {"printed range gives raw -32770..0, outside INTEGER16; the encoder refuses such values with errc::overflow", 105}},
    {.name = {"Cyl. Area Ratio", 15}, .section = {"4.34", 4}},
    {.name = {"Hist. Time 1", 12}, .section = {"4.66", 4}},
    {.name = {"Hist. Time 3", 12}, .section = {"4.77", 4}},
    {.name = {"Hist. Time 4", 12}, .section = {"4.79", 4}},
    {.name = {"Hist. Time 5", 12}, .section = {"4.80", 4}},
    {.name = {"Hist. Time 6", 12}, .section = {"4.81", 4}},
    {.name = {"Hist. Time 13", 13}, .section = {"4.67", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 14", 13}, .section = {"4.68", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 15", 13}, .section = {"4.69", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 16", 13}, .section = {"4.70", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 17", 13}, .section = {"4.71", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 23", 13}, .section = {"4.72", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 26", 13}, .section = {"4.73", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 27", 13}, .section = {"4.74", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 28", 13}, .section = {"4.75", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 29", 13}, .section = {"4.76", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Time 30", 13}, .section = {"4.78", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}},
    {.name = {"Hist. Pres CMD 13", 17}, .section = {"4.64", 4}},
    {.name = {"Hist. Pos.FB 1", 14}, .section = {"4.48", 4}},
    {.name = {"Hist. Pos.FB 2", 14}, .section = {"4.54", 4}},
    {.name = {"Hist. Pos.FB 3", 14}, .section = {"4.59", 4}},
    {.name = {"Hist. Pos.FB 4", 14}, .section = {"4.61", 4}},
    {.name = {"Hist. Pos.FB 5", 14}, .section = {"4.62", 4}},
    {.name = {"Hist. Pos.FB 6", 14}, .section = {"4.63", 4}},
    {.name = {"Hist. Pos. FB 13", 16}, .section = {"4.47", 4}, .remark = {"spelled \"Pos. FB\" with a space, unlike the other Hist. Pos.FB entries (same in TOC, heading and Name line)", 106}},
    {.name = {"Hist. Pos.FB 14", 15}, .section = {"4.49", 4}},
    {.name = {"Hist. Pos.FB 15", 15}, .section = {"4.50", 4}},
    {.name = {"Hist. Pos.FB 16", 15}, .section = {"4.51", 4}},
    {.name = {"Hist. Pos.FB 17", 15}, .section = {"4.52", 4}},
    {.name = {"Hist. Pos.FB 18", 15}, .section = {"4.53", 4}, .remark = {"index_anomaly: every other Hist. Pos.FB n is at 0x3600+n, so 18 would be 0x3612; as printed, see docs/errata.md", 111}},
    {.name = {"Hist. Pos.FB 26", 15}, .section = {"4.55", 4}},
    {.name = {"Hist. Pos.FB 27", 15}, .section = {"4.56", 4}},
    {.name = {"Hist. Pos.FB 28", 15}, .section = {"4.57", 4}},
    {.name = {"Hist. Pos.FB 29", 15}, .section = {"4.58", 4}},
    {.name = {"Hist. Pos.FB 30", 15}, .section = {"4.60", 4}},
    {.name = {"Hist. Pres.FB 13", 16}, .section = {"4.65", 4}},
};

inline constexpr scaling::linear scales[240]{
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{105, 1}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{163835, 1}, {0, 0}},
    {{163835, 1}, {0, 0}},
    {{163835, 1}, {0, 0}},
    {{163835, 1}, {0, 0}},
    {{163835, 1}, {0, 0}},
    {{163835, 1}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{16383, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{1, 0}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{1, 0}, {1, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{128, 0}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{3277, 1}, {0, 0}},
    {{102401, 2}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{500, 0}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
    {{32767, 2}, {0, 0}},
};
} // namespace detail

inline constexpr std::span<const od::entry, 240> entries{detail::entries};
inline constexpr std::span<const od::entry_info, 240> infos{detail::infos};
inline constexpr std::span<const scaling::linear, 240> scales{detail::scales};

inline constexpr od::dictionary dictionary{entries, infos, scales};
static_assert(dictionary.is_valid());

// DPQ columns of the parameters that have them (dpq/columns.hpp).
inline constexpr dpq::parameter_columns dpq_columns[221]{
    {.index = 0x200D, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x200E, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x200F, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2010, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2011, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2012, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2013, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2014, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2015, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2017, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2018, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x201F, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2023, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2025, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2026, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2027, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2028, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x202F, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2030, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2031, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2032, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2033, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2036, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2037, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2039, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x203A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x203C, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x203D, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x203E, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x203F, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2040, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2041, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2114, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2130, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2131, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2132, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2133, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2136, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2137, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x213A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2167, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2169, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x216A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x216B, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x216C, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2180, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2181, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2182, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2183, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2184, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2195, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2196, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2197, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2198, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2199, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x219C, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x219D, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x21A0, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2201, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2301, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2323, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2336, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2337, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x233A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2423, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2436, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2437, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x243A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2701, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2723, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2736, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2737, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x273A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2923, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2936, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2937, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x293A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2A01, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A03, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A04, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A05, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A06, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A14, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A15, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A17, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A1A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A1B, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A1C, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A1D, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2A64, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2B2F, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2B30, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2B31, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2B32, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2B33, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2C67, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2C68, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2C69, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2C78, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2D02, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2D04, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2D05, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2D0E, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2D0F, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D17, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D3B, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2D3C, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2D3D, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2D3E, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::available},
    {.index = 0x2D71, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D72, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D73, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D74, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D75, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D76, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D7C, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D7D, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D7E, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D7F, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D80, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D81, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D87, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D88, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D89, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D8A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D8B, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D8C, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D92, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D93, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D94, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D95, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D96, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D97, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D9D, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D9E, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2D9F, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2DA0, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2DA1, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2DC1, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2DC4, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2DC5, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2DCB, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2DCC, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2E21, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2E2A, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2E2D, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2E2E, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F03, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F04, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F07, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F09, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F0B, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F0E, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F0F, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F10, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F11, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F13, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F19, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F1A, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F1F, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F20, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F21, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F25, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F26, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F27, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F28, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F34, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::available},
    {.index = 0x2F6D, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F72, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F78, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F7F, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F80, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F81, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F82, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F87, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F91, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F92, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F93, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F94, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2F99, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2FA3, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2FA4, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2FA5, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2FA6, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x2FAB, .value_acceptance = dpq::acceptance::also_when_enabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3116, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3501, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3503, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3504, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3505, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3506, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x350E, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x350F, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3510, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3511, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3512, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3518, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x351B, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x351C, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x351D, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x351E, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x351F, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3571, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3601, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3602, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3603, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3604, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3605, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3606, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x360D, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x360E, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x360F, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3610, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3611, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x3617, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x361A, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x361B, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x361C, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x361D, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x361E, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
    {.index = 0x362E, .value_acceptance = dpq::acceptance::only_when_disabled, .bus = dpq::bus_manager::not_available},
};

// The kinds of values in the entries (od/value_kinds.hpp).
inline constexpr od::value_kinds kinds{.strings = false, .real = false, .time = false, .wide = false, .limits = true, .node_limits = false, .scaled = true, .numbers = true};

// VAR objects: standalone descriptors (firmware that names one keeps only that one).
inline constexpr od::descriptor error_register{detail::entries[0], detail::infos[0], detail::scales[0]}; // 0x1001
inline constexpr od::descriptor guard_time{detail::entries[6], detail::infos[6], detail::scales[6]}; // 0x100C
inline constexpr od::descriptor life_time_factor{detail::entries[7], detail::infos[7], detail::scales[7]}; // 0x100D
inline constexpr od::descriptor producer_heartbeat_time_interval{detail::entries[10], detail::infos[10], detail::scales[10]}; // 0x1017
inline constexpr od::descriptor holding_vel_limit_1{detail::entries[19], detail::infos[19], detail::scales[19]}; // 0x200D
inline constexpr od::descriptor holding_vel_limit_2{detail::entries[20], detail::infos[20], detail::scales[20]}; // 0x200E
inline constexpr od::descriptor holding_vel_limit_3{detail::entries[21], detail::infos[21], detail::scales[21]}; // 0x200F
inline constexpr od::descriptor holding_vel_limit_4{detail::entries[22], detail::infos[22], detail::scales[22]}; // 0x2010
inline constexpr od::descriptor holding_vel_limit_5{detail::entries[23], detail::infos[23], detail::scales[23]}; // 0x2011
inline constexpr od::descriptor jogmode_vel_forward{detail::entries[24], detail::infos[24], detail::scales[24]}; // 0x2012
inline constexpr od::descriptor jogmode_vel_backward{detail::entries[25], detail::infos[25], detail::scales[25]}; // 0x2013
inline constexpr od::descriptor screw_speed_2{detail::entries[26], detail::infos[26], detail::scales[26]}; // 0x2014
inline constexpr od::descriptor screw_speed_3{detail::entries[27], detail::infos[27], detail::scales[27]}; // 0x2015
inline constexpr od::descriptor pre_decomp_velocity{detail::entries[28], detail::infos[28], detail::scales[28]}; // 0x2017
inline constexpr od::descriptor screw_speed_4{detail::entries[29], detail::infos[29], detail::scales[29]}; // 0x2018
inline constexpr od::descriptor post_decomp_velocit{detail::entries[30], detail::infos[30], detail::scales[30]}; // 0x201F
inline constexpr od::descriptor inj_p_limit_1{detail::entries[31], detail::infos[31], detail::scales[31]}; // 0x2023
inline constexpr od::descriptor inj_p_limit_2{detail::entries[32], detail::infos[32], detail::scales[32]}; // 0x2025
inline constexpr od::descriptor inj_p_limit_3{detail::entries[33], detail::infos[33], detail::scales[33]}; // 0x2026
inline constexpr od::descriptor inj_p_limit_4{detail::entries[34], detail::infos[34], detail::scales[34]}; // 0x2027
inline constexpr od::descriptor inj_p_limit_5{detail::entries[35], detail::infos[35], detail::scales[35]}; // 0x2028
inline constexpr od::descriptor holding_pressure_1{detail::entries[36], detail::infos[36], detail::scales[36]}; // 0x202F
inline constexpr od::descriptor holding_pressure_2{detail::entries[37], detail::infos[37], detail::scales[37]}; // 0x2030
inline constexpr od::descriptor holding_pressure_3{detail::entries[38], detail::infos[38], detail::scales[38]}; // 0x2031
inline constexpr od::descriptor holding_pressure_4{detail::entries[39], detail::infos[39], detail::scales[39]}; // 0x2032
inline constexpr od::descriptor holding_pressure_5{detail::entries[40], detail::infos[40], detail::scales[40]}; // 0x2033
inline constexpr od::descriptor backpress_press_2{detail::entries[41], detail::infos[41], detail::scales[41]}; // 0x2036
inline constexpr od::descriptor backpress_press_3{detail::entries[42], detail::infos[42], detail::scales[42]}; // 0x2037
inline constexpr od::descriptor press_predecompress{detail::entries[43], detail::infos[43], detail::scales[43]}; // 0x2039
inline constexpr od::descriptor backpress_press_4{detail::entries[44], detail::infos[44], detail::scales[44]}; // 0x203A
inline constexpr od::descriptor inj_p_limit_6{detail::entries[45], detail::infos[45], detail::scales[45]}; // 0x203C
inline constexpr od::descriptor inj_p_limit_7{detail::entries[46], detail::infos[46], detail::scales[46]}; // 0x203D
inline constexpr od::descriptor inj_p_limit_8{detail::entries[47], detail::infos[47], detail::scales[47]}; // 0x203E
inline constexpr od::descriptor inj_p_limit_9{detail::entries[48], detail::infos[48], detail::scales[48]}; // 0x203F
inline constexpr od::descriptor inj_p_limit_10{detail::entries[49], detail::infos[49], detail::scales[49]}; // 0x2040
inline constexpr od::descriptor press_postdecompres{detail::entries[50], detail::infos[50], detail::scales[50]}; // 0x2041
inline constexpr od::descriptor backp_vel_ramp_2{detail::entries[51], detail::infos[51], detail::scales[51]}; // 0x2114
inline constexpr od::descriptor pah_press_rate_2{detail::entries[52], detail::infos[52], detail::scales[52]}; // 0x2130
inline constexpr od::descriptor pah_press_rate_3{detail::entries[53], detail::infos[53], detail::scales[53]}; // 0x2131
inline constexpr od::descriptor pah_press_rate_4{detail::entries[54], detail::infos[54], detail::scales[54]}; // 0x2132
inline constexpr od::descriptor pah_press_rate_5{detail::entries[55], detail::infos[55], detail::scales[55]}; // 0x2133
inline constexpr od::descriptor backp_press_rate_2{detail::entries[56], detail::infos[56], detail::scales[56]}; // 0x2136
inline constexpr od::descriptor backp_press_rate_3{detail::entries[57], detail::infos[57], detail::scales[57]}; // 0x2137
inline constexpr od::descriptor backp_press_rate_4{detail::entries[58], detail::infos[58], detail::scales[58]}; // 0x213A
inline constexpr od::descriptor inj_velocity_1{detail::entries[59], detail::infos[59], detail::scales[59]}; // 0x2167
inline constexpr od::descriptor inj_velocity_2{detail::entries[60], detail::infos[60], detail::scales[60]}; // 0x2169
inline constexpr od::descriptor inj_velocity_3{detail::entries[61], detail::infos[61], detail::scales[61]}; // 0x216A
inline constexpr od::descriptor inj_velocity_4{detail::entries[62], detail::infos[62], detail::scales[62]}; // 0x216B
inline constexpr od::descriptor inj_velocity_5{detail::entries[63], detail::infos[63], detail::scales[63]}; // 0x216C
inline constexpr od::descriptor inj_velocity_6{detail::entries[64], detail::infos[64], detail::scales[64]}; // 0x2180
inline constexpr od::descriptor inj_velocity_7{detail::entries[65], detail::infos[65], detail::scales[65]}; // 0x2181
inline constexpr od::descriptor inj_velocity_8{detail::entries[66], detail::infos[66], detail::scales[66]}; // 0x2182
inline constexpr od::descriptor inj_velocity_9{detail::entries[67], detail::infos[67], detail::scales[67]}; // 0x2183
inline constexpr od::descriptor inj_velocity_10{detail::entries[68], detail::infos[68], detail::scales[68]}; // 0x2184
inline constexpr od::descriptor pah_decomp_rate_1{detail::entries[69], detail::infos[69], detail::scales[69]}; // 0x2195
inline constexpr od::descriptor pah_decomp_rate_2{detail::entries[70], detail::infos[70], detail::scales[70]}; // 0x2196
inline constexpr od::descriptor pah_decomp_rate_3{detail::entries[71], detail::infos[71], detail::scales[71]}; // 0x2197
inline constexpr od::descriptor pah_decomp_rate_4{detail::entries[72], detail::infos[72], detail::scales[72]}; // 0x2198
inline constexpr od::descriptor pah_decomp_rate_5{detail::entries[73], detail::infos[73], detail::scales[73]}; // 0x2199
inline constexpr od::descriptor backp_decomp_rate_2{detail::entries[74], detail::infos[74], detail::scales[74]}; // 0x219C
inline constexpr od::descriptor backp_decomp_rate_3{detail::entries[75], detail::infos[75], detail::scales[75]}; // 0x219D
inline constexpr od::descriptor backp_decomp_rate_4{detail::entries[76], detail::infos[76], detail::scales[76]}; // 0x21A0
inline constexpr od::descriptor inj_accel_ramp{detail::entries[77], detail::infos[77], detail::scales[77]}; // 0x2201
inline constexpr od::descriptor inj_velocity_p{detail::entries[78], detail::infos[78], detail::scales[78]}; // 0x2301
inline constexpr od::descriptor pah_pressure_p{detail::entries[79], detail::infos[79], detail::scales[79]}; // 0x2323
inline constexpr od::descriptor backp_press_p_2{detail::entries[80], detail::infos[80], detail::scales[80]}; // 0x2336
inline constexpr od::descriptor backp_press_p_3{detail::entries[81], detail::infos[81], detail::scales[81]}; // 0x2337
inline constexpr od::descriptor backp_press_p_4{detail::entries[82], detail::infos[82], detail::scales[82]}; // 0x233A
inline constexpr od::descriptor pah_pressure_i{detail::entries[83], detail::infos[83], detail::scales[83]}; // 0x2423
inline constexpr od::descriptor backp_press_i_2{detail::entries[84], detail::infos[84], detail::scales[84]}; // 0x2436
inline constexpr od::descriptor backp_press_i_3{detail::entries[85], detail::infos[85], detail::scales[85]}; // 0x2437
inline constexpr od::descriptor backp_press_i_4{detail::entries[86], detail::infos[86], detail::scales[86]}; // 0x243A
inline constexpr od::descriptor inj_velocity_d{detail::entries[87], detail::infos[87], detail::scales[87]}; // 0x2701
inline constexpr od::descriptor pah_pressure_d{detail::entries[88], detail::infos[88], detail::scales[88]}; // 0x2723
inline constexpr od::descriptor backp_press_d_2{detail::entries[89], detail::infos[89], detail::scales[89]}; // 0x2736
inline constexpr od::descriptor backp_press_d_3{detail::entries[90], detail::infos[90], detail::scales[90]}; // 0x2737
inline constexpr od::descriptor backp_press_d_4{detail::entries[91], detail::infos[91], detail::scales[91]}; // 0x273A
inline constexpr od::descriptor fwd_inject{detail::entries[92], detail::infos[92], detail::scales[92]}; // 0x2923
inline constexpr od::descriptor fwd_backpress_1{detail::entries[93], detail::infos[93], detail::scales[93]}; // 0x2936
inline constexpr od::descriptor fwd_backpress_2{detail::entries[94], detail::infos[94], detail::scales[94]}; // 0x2937
inline constexpr od::descriptor fwd_backpress_3{detail::entries[95], detail::infos[95], detail::scales[95]}; // 0x293A
inline constexpr od::descriptor inj_position_2{detail::entries[96], detail::infos[96], detail::scales[96]}; // 0x2A01
inline constexpr od::descriptor inj_position_3{detail::entries[97], detail::infos[97], detail::scales[97]}; // 0x2A03
inline constexpr od::descriptor inj_position_4{detail::entries[98], detail::infos[98], detail::scales[98]}; // 0x2A04
inline constexpr od::descriptor inj_position_5{detail::entries[99], detail::infos[99], detail::scales[99]}; // 0x2A05
inline constexpr od::descriptor inj_position_6{detail::entries[100], detail::infos[100], detail::scales[100]}; // 0x2A06
inline constexpr od::descriptor backpress_position3{detail::entries[101], detail::infos[101], detail::scales[101]}; // 0x2A14
inline constexpr od::descriptor backpress_position4{detail::entries[102], detail::infos[102], detail::scales[102]}; // 0x2A15
inline constexpr od::descriptor pre_decomp_position{detail::entries[103], detail::infos[103], detail::scales[103]}; // 0x2A17
inline constexpr od::descriptor inj_position_7{detail::entries[104], detail::infos[104], detail::scales[104]}; // 0x2A1A
inline constexpr od::descriptor inj_position_8{detail::entries[105], detail::infos[105], detail::scales[105]}; // 0x2A1B
inline constexpr od::descriptor inj_position_9{detail::entries[106], detail::infos[106], detail::scales[106]}; // 0x2A1C
inline constexpr od::descriptor inj_position_10{detail::entries[107], detail::infos[107], detail::scales[107]}; // 0x2A1D
inline constexpr od::descriptor post_decomp_positio{detail::entries[108], detail::infos[108], detail::scales[108]}; // 0x2A64
inline constexpr od::descriptor holding_time_1{detail::entries[109], detail::infos[109], detail::scales[109]}; // 0x2B2F
inline constexpr od::descriptor holding_time_2{detail::entries[110], detail::infos[110], detail::scales[110]}; // 0x2B30
inline constexpr od::descriptor holding_time_3{detail::entries[111], detail::infos[111], detail::scales[111]}; // 0x2B31
inline constexpr od::descriptor holding_time_4{detail::entries[112], detail::infos[112], detail::scales[112]}; // 0x2B32
inline constexpr od::descriptor holding_time_5{detail::entries[113], detail::infos[113], detail::scales[113]}; // 0x2B33
inline constexpr od::descriptor trigger{detail::entries[114], detail::infos[114], detail::scales[114]}; // 0x2C67
inline constexpr od::descriptor status{detail::entries[115], detail::infos[115], detail::scales[115]}; // 0x2C68
inline constexpr od::descriptor analog_vel_max{detail::entries[116], detail::infos[116], detail::scales[116]}; // 0x2C69
inline constexpr od::descriptor set_ssi_incr_to_zero{detail::entries[117], detail::infos[117], detail::scales[117]}; // 0x2C78
inline constexpr od::descriptor pah_act_damp_freq{detail::entries[118], detail::infos[118], detail::scales[118]}; // 0x2D02
inline constexpr od::descriptor inj_vel_activedamp{detail::entries[119], detail::infos[119], detail::scales[119]}; // 0x2D04
inline constexpr od::descriptor pah_act_damp_gain{detail::entries[120], detail::infos[120], detail::scales[120]}; // 0x2D05
inline constexpr od::descriptor shot_size_position{detail::entries[121], detail::infos[121], detail::scales[121]}; // 0x2D0E
inline constexpr od::descriptor do7_at_press_level{detail::entries[122], detail::infos[122], detail::scales[122]}; // 0x2D0F
inline constexpr od::descriptor do7_at_press_delay{detail::entries[123], detail::infos[123], detail::scales[123]}; // 0x2D17
inline constexpr od::descriptor transfer_position{detail::entries[124], detail::infos[124], detail::scales[124]}; // 0x2D3B
inline constexpr od::descriptor transfer_cavity_pres{detail::entries[125], detail::infos[125], detail::scales[125]}; // 0x2D3C
inline constexpr od::descriptor transfer_hydr_press{detail::entries[126], detail::infos[126], detail::scales[126]}; // 0x2D3D
inline constexpr od::descriptor transfer_hydr_pos{detail::entries[127], detail::infos[127], detail::scales[127]}; // 0x2D3E
inline constexpr od::descriptor press_cmd_min{detail::entries[128], detail::infos[128], detail::scales[128]}; // 0x2D71
inline constexpr od::descriptor press_fb_1_min{detail::entries[129], detail::infos[129], detail::scales[129]}; // 0x2D72
inline constexpr od::descriptor cavity_press_min{detail::entries[130], detail::infos[130], detail::scales[130]}; // 0x2D73
inline constexpr od::descriptor press_fb_2_min{detail::entries[131], detail::infos[131], detail::scales[131]}; // 0x2D74
inline constexpr od::descriptor cyl_pos_fb_min{detail::entries[132], detail::infos[132], detail::scales[132]}; // 0x2D75
inline constexpr od::descriptor vel_cmd_min{detail::entries[133], detail::infos[133], detail::scales[133]}; // 0x2D76
inline constexpr od::descriptor press_cmd_max{detail::entries[134], detail::infos[134], detail::scales[134]}; // 0x2D7C
inline constexpr od::descriptor press_fb_1_max{detail::entries[135], detail::infos[135], detail::scales[135]}; // 0x2D7D
inline constexpr od::descriptor cavity_press_max{detail::entries[136], detail::infos[136], detail::scales[136]}; // 0x2D7E
inline constexpr od::descriptor press_fb_2_max{detail::entries[137], detail::infos[137], detail::scales[137]}; // 0x2D7F
inline constexpr od::descriptor cyl_pos_fb_max{detail::entries[138], detail::infos[138], detail::scales[138]}; // 0x2D80
inline constexpr od::descriptor vel_cmd_max{detail::entries[139], detail::infos[139], detail::scales[139]}; // 0x2D81
inline constexpr od::descriptor press_cmd_min_fau{detail::entries[140], detail::infos[140], detail::scales[140]}; // 0x2D87
inline constexpr od::descriptor press_fb_1_min_fau{detail::entries[141], detail::infos[141], detail::scales[141]}; // 0x2D88
inline constexpr od::descriptor cavity_press_min_fau{detail::entries[142], detail::infos[142], detail::scales[142]}; // 0x2D89
inline constexpr od::descriptor press_fb_2_min_fau{detail::entries[143], detail::infos[143], detail::scales[143]}; // 0x2D8A
inline constexpr od::descriptor cyl_pos_fb_min_fau{detail::entries[144], detail::infos[144], detail::scales[144]}; // 0x2D8B
inline constexpr od::descriptor vel_cmd_min_fau{detail::entries[145], detail::infos[145], detail::scales[145]}; // 0x2D8C
inline constexpr od::descriptor press_cmd_max_fau{detail::entries[146], detail::infos[146], detail::scales[146]}; // 0x2D92
inline constexpr od::descriptor press_fb_1_max_fau{detail::entries[147], detail::infos[147], detail::scales[147]}; // 0x2D93
inline constexpr od::descriptor cavity_press_max_fau{detail::entries[148], detail::infos[148], detail::scales[148]}; // 0x2D94
inline constexpr od::descriptor press_fb_2_max_fau{detail::entries[149], detail::infos[149], detail::scales[149]}; // 0x2D95
inline constexpr od::descriptor cyl_pos_fb_max_fau{detail::entries[150], detail::infos[150], detail::scales[150]}; // 0x2D96
inline constexpr od::descriptor vel_cmd_max_fau{detail::entries[151], detail::infos[151], detail::scales[151]}; // 0x2D97
inline constexpr od::descriptor press_cmd_max_uni{detail::entries[152], detail::infos[152], detail::scales[152]}; // 0x2D9D
inline constexpr od::descriptor press_fb_1_max_uni{detail::entries[153], detail::infos[153], detail::scales[153]}; // 0x2D9E
inline constexpr od::descriptor cavity_press_max_uni{detail::entries[154], detail::infos[154], detail::scales[154]}; // 0x2D9F
inline constexpr od::descriptor press_fb_2_max_uni{detail::entries[155], detail::infos[155], detail::scales[155]}; // 0x2DA0
inline constexpr od::descriptor cyl_pos_cmd_max_uni{detail::entries[156], detail::infos[156], detail::scales[156]}; // 0x2DA1
inline constexpr od::descriptor ssi_nb_of_bits{detail::entries[157], detail::infos[157], detail::scales[157]}; // 0x2DC1
inline constexpr od::descriptor ssi_resolution{detail::entries[158], detail::infos[158], detail::scales[158]}; // 0x2DC4
inline constexpr od::descriptor ssi_offset{detail::entries[159], detail::infos[159], detail::scales[159]}; // 0x2DC5
inline constexpr od::descriptor incr_home_offset{detail::entries[160], detail::infos[160], detail::scales[160]}; // 0x2DCB
inline constexpr od::descriptor incr_resolution{detail::entries[161], detail::infos[161], detail::scales[161]}; // 0x2DCC
inline constexpr od::descriptor injection_scale{detail::entries[162], detail::infos[162], detail::scales[162]}; // 0x2E21
inline constexpr od::descriptor injection_limit_plus{detail::entries[163], detail::infos[163], detail::scales[163]}; // 0x2E2A
inline constexpr od::descriptor injection_limit_minus{detail::entries[164], detail::infos[164], detail::scales[164]}; // 0x2E2D
inline constexpr od::descriptor out2_inject_limit_minus{detail::entries[165], detail::infos[165], detail::scales[165]}; // 0x2E2E
inline constexpr od::descriptor velocity_cmd_ai6{detail::entries[166], detail::infos[166], detail::scales[166]}; // 0x2F03
inline constexpr od::descriptor vel_loop_cmd{detail::entries[167], detail::infos[167], detail::scales[167]}; // 0x2F04
inline constexpr od::descriptor position_fb{detail::entries[168], detail::infos[168], detail::scales[168]}; // 0x2F07
inline constexpr od::descriptor position_error{detail::entries[169], detail::infos[169], detail::scales[169]}; // 0x2F09
inline constexpr od::descriptor pressure_cmd_ai1{detail::entries[170], detail::infos[170], detail::scales[170]}; // 0x2F0B
inline constexpr od::descriptor press_loop_cmd{detail::entries[171], detail::infos[171], detail::scales[171]}; // 0x2F0E
inline constexpr od::descriptor pressure_fb_1_ai2{detail::entries[172], detail::infos[172], detail::scales[172]}; // 0x2F0F
inline constexpr od::descriptor pressure_fb_2_ai4{detail::entries[173], detail::infos[173], detail::scales[173]}; // 0x2F10
inline constexpr od::descriptor pressure_fb{detail::entries[174], detail::infos[174], detail::scales[174]}; // 0x2F11
inline constexpr od::descriptor pressure_error{detail::entries[175], detail::infos[175], detail::scales[175]}; // 0x2F13
inline constexpr od::descriptor cavity_pressure_ai3{detail::entries[176], detail::infos[176], detail::scales[176]}; // 0x2F19
inline constexpr od::descriptor position_ai5{detail::entries[177], detail::infos[177], detail::scales[177]}; // 0x2F1A
inline constexpr od::descriptor valve_output_1{detail::entries[178], detail::infos[178], detail::scales[178]}; // 0x2F1F
inline constexpr od::descriptor valve_output_2{detail::entries[179], detail::infos[179], detail::scales[179]}; // 0x2F20
inline constexpr od::descriptor valve_output_3{detail::entries[180], detail::infos[180], detail::scales[180]}; // 0x2F21
inline constexpr od::descriptor program_block{detail::entries[181], detail::infos[181], detail::scales[181]}; // 0x2F25
inline constexpr od::descriptor discrete_outputs{detail::entries[182], detail::infos[182], detail::scales[182]}; // 0x2F26
inline constexpr od::descriptor discrete_inputs{detail::entries[183], detail::infos[183], detail::scales[183]}; // 0x2F27
inline constexpr od::descriptor output_mode{detail::entries[184], detail::infos[184], detail::scales[184]}; // 0x2F28
inline constexpr od::descriptor program_status{detail::entries[185], detail::infos[185], detail::scales[185]}; // 0x2F34
inline constexpr od::descriptor injection_offset{detail::entries[186], detail::infos[186], detail::scales[186]}; // 0x2F6D
inline constexpr od::descriptor pos_max_length{detail::entries[187], detail::infos[187], detail::scales[187]}; // 0x2F72
inline constexpr od::descriptor pres_max_inject{detail::entries[188], detail::infos[188], detail::scales[188]}; // 0x2F78
inline constexpr od::descriptor jog_mode_offset{detail::entries[189], detail::infos[189], detail::scales[189]}; // 0x2F7F
inline constexpr od::descriptor jog_mode_scale{detail::entries[190], detail::infos[190], detail::scales[190]}; // 0x2F80
inline constexpr od::descriptor jog_mode_limit_minus{detail::entries[191], detail::infos[191], detail::scales[191]}; // 0x2F81
inline constexpr od::descriptor jog_mode_limit_plus{detail::entries[192], detail::infos[192], detail::scales[192]}; // 0x2F82
inline constexpr od::descriptor out2_jog_limit_minus{detail::entries[193], detail::infos[193], detail::scales[193]}; // 0x2F87
inline constexpr od::descriptor pah_backpres_offset{detail::entries[194], detail::infos[194], detail::scales[194]}; // 0x2F91
inline constexpr od::descriptor pah_backpres_scale{detail::entries[195], detail::infos[195], detail::scales[195]}; // 0x2F92
inline constexpr od::descriptor pah_backpres_limit_minus{detail::entries[196], detail::infos[196], detail::scales[196]}; // 0x2F93
inline constexpr od::descriptor pah_backpres_limit_plus{detail::entries[197], detail::infos[197], detail::scales[197]}; // 0x2F94
inline constexpr od::descriptor out2_backpress_lim_minus{detail::entries[198], detail::infos[198], detail::scales[198]}; // 0x2F99
inline constexpr od::descriptor decompres_offset{detail::entries[199], detail::infos[199], detail::scales[199]}; // 0x2FA3
inline constexpr od::descriptor decompres_scale{detail::entries[200], detail::infos[200], detail::scales[200]}; // 0x2FA4
inline constexpr od::descriptor decompres_limit_minus{detail::entries[201], detail::infos[201], detail::scales[201]}; // 0x2FA5
inline constexpr od::descriptor decompres_limit_plus{detail::entries[202], detail::infos[202], detail::scales[202]}; // 0x2FA6
inline constexpr od::descriptor out2_decomp_limit_minus{detail::entries[203], detail::infos[203], detail::scales[203]}; // 0x2FAB
inline constexpr od::descriptor cyl_area_ratio{detail::entries[204], detail::infos[204], detail::scales[204]}; // 0x3116
inline constexpr od::descriptor hist_time_1{detail::entries[205], detail::infos[205], detail::scales[205]}; // 0x3501
inline constexpr od::descriptor hist_time_3{detail::entries[206], detail::infos[206], detail::scales[206]}; // 0x3503
inline constexpr od::descriptor hist_time_4{detail::entries[207], detail::infos[207], detail::scales[207]}; // 0x3504
inline constexpr od::descriptor hist_time_5{detail::entries[208], detail::infos[208], detail::scales[208]}; // 0x3505
inline constexpr od::descriptor hist_time_6{detail::entries[209], detail::infos[209], detail::scales[209]}; // 0x3506
inline constexpr od::descriptor hist_time_13{detail::entries[210], detail::infos[210], detail::scales[210]}; // 0x350E
inline constexpr od::descriptor hist_time_14{detail::entries[211], detail::infos[211], detail::scales[211]}; // 0x350F
inline constexpr od::descriptor hist_time_15{detail::entries[212], detail::infos[212], detail::scales[212]}; // 0x3510
inline constexpr od::descriptor hist_time_16{detail::entries[213], detail::infos[213], detail::scales[213]}; // 0x3511
inline constexpr od::descriptor hist_time_17{detail::entries[214], detail::infos[214], detail::scales[214]}; // 0x3512
inline constexpr od::descriptor hist_time_23{detail::entries[215], detail::infos[215], detail::scales[215]}; // 0x3518
inline constexpr od::descriptor hist_time_26{detail::entries[216], detail::infos[216], detail::scales[216]}; // 0x351B
inline constexpr od::descriptor hist_time_27{detail::entries[217], detail::infos[217], detail::scales[217]}; // 0x351C
inline constexpr od::descriptor hist_time_28{detail::entries[218], detail::infos[218], detail::scales[218]}; // 0x351D
inline constexpr od::descriptor hist_time_29{detail::entries[219], detail::infos[219], detail::scales[219]}; // 0x351E
inline constexpr od::descriptor hist_time_30{detail::entries[220], detail::infos[220], detail::scales[220]}; // 0x351F
inline constexpr od::descriptor hist_pres_cmd_13{detail::entries[221], detail::infos[221], detail::scales[221]}; // 0x3571
inline constexpr od::descriptor hist_pos_fb_1{detail::entries[222], detail::infos[222], detail::scales[222]}; // 0x3601
inline constexpr od::descriptor hist_pos_fb_2{detail::entries[223], detail::infos[223], detail::scales[223]}; // 0x3602
inline constexpr od::descriptor hist_pos_fb_3{detail::entries[224], detail::infos[224], detail::scales[224]}; // 0x3603
inline constexpr od::descriptor hist_pos_fb_4{detail::entries[225], detail::infos[225], detail::scales[225]}; // 0x3604
inline constexpr od::descriptor hist_pos_fb_5{detail::entries[226], detail::infos[226], detail::scales[226]}; // 0x3605
inline constexpr od::descriptor hist_pos_fb_6{detail::entries[227], detail::infos[227], detail::scales[227]}; // 0x3606
inline constexpr od::descriptor hist_pos_fb_13{detail::entries[228], detail::infos[228], detail::scales[228]}; // 0x360D
inline constexpr od::descriptor hist_pos_fb_14{detail::entries[229], detail::infos[229], detail::scales[229]}; // 0x360E
inline constexpr od::descriptor hist_pos_fb_15{detail::entries[230], detail::infos[230], detail::scales[230]}; // 0x360F
inline constexpr od::descriptor hist_pos_fb_16{detail::entries[231], detail::infos[231], detail::scales[231]}; // 0x3610
inline constexpr od::descriptor hist_pos_fb_17{detail::entries[232], detail::infos[232], detail::scales[232]}; // 0x3611
inline constexpr od::descriptor hist_pos_fb_18{detail::entries[233], detail::infos[233], detail::scales[233]}; // 0x3617
inline constexpr od::descriptor hist_pos_fb_26{detail::entries[234], detail::infos[234], detail::scales[234]}; // 0x361A
inline constexpr od::descriptor hist_pos_fb_27{detail::entries[235], detail::infos[235], detail::scales[235]}; // 0x361B
inline constexpr od::descriptor hist_pos_fb_28{detail::entries[236], detail::infos[236], detail::scales[236]}; // 0x361C
inline constexpr od::descriptor hist_pos_fb_29{detail::entries[237], detail::infos[237], detail::scales[237]}; // 0x361D
inline constexpr od::descriptor hist_pos_fb_30{detail::entries[238], detail::infos[238], detail::scales[238]}; // 0x361E
inline constexpr od::descriptor hist_pres_fb_13{detail::entries[239], detail::infos[239], detail::scales[239]}; // 0x362E

// ARRAY and RECORD objects: views into the tables.
inline constexpr od::object error_history{0x1003, od::object_code::array, "Error History"sv, dictionary.entries().subspan(1, 5), dictionary.infos().subspan(1, 5), dictionary.scales().subspan(1, 5)};
inline constexpr od::descriptor error_history_sub0{detail::entries[1], detail::infos[1], detail::scales[1]}; // 0x1003 sub 0
inline constexpr od::descriptor error_code_1{detail::entries[2], detail::infos[2], detail::scales[2]}; // 0x1003 sub 1
inline constexpr od::descriptor error_code_2{detail::entries[3], detail::infos[3], detail::scales[3]}; // 0x1003 sub 2
inline constexpr od::descriptor error_code_3{detail::entries[4], detail::infos[4], detail::scales[4]}; // 0x1003 sub 3
inline constexpr od::descriptor error_code_4{detail::entries[5], detail::infos[5], detail::scales[5]}; // 0x1003 sub 4
inline constexpr od::object consumer_heartbeat_time{0x1016, od::object_code::array, "Consumer Heartbeat Time"sv, dictionary.entries().subspan(8, 2), dictionary.infos().subspan(8, 2), dictionary.scales().subspan(8, 2)};
inline constexpr od::descriptor consumer_heartbeat_time_sub0{detail::entries[8], detail::infos[8], detail::scales[8]}; // 0x1016 sub 0
inline constexpr od::descriptor consumer_heartbeat_time_interval{detail::entries[9], detail::infos[9], detail::scales[9]}; // 0x1016 sub 1
inline constexpr od::object tx_pdo1{0x1800, od::object_code::record, "Tx-PDO1 Communication Parameter"sv, dictionary.entries().subspan(11, 2), dictionary.infos().subspan(11, 2), dictionary.scales().subspan(11, 2)};
inline constexpr od::descriptor tx_pdo1_sub0{detail::entries[11], detail::infos[11], detail::scales[11]}; // 0x1800 sub 0
inline constexpr od::descriptor tx_pdo1_event_timer{detail::entries[12], detail::infos[12], detail::scales[12]}; // 0x1800 sub 5
inline constexpr od::object tx_pdo2{0x1801, od::object_code::record, "Tx-PDO2 Communication Parameter"sv, dictionary.entries().subspan(13, 2), dictionary.infos().subspan(13, 2), dictionary.scales().subspan(13, 2)};
inline constexpr od::descriptor tx_pdo2_sub0{detail::entries[13], detail::infos[13], detail::scales[13]}; // 0x1801 sub 0
inline constexpr od::descriptor tx_pdo2_event_timer{detail::entries[14], detail::infos[14], detail::scales[14]}; // 0x1801 sub 5
inline constexpr od::object tx_pdo3{0x1802, od::object_code::record, "Tx-PDO3 Communication Parameter"sv, dictionary.entries().subspan(15, 2), dictionary.infos().subspan(15, 2), dictionary.scales().subspan(15, 2)};
inline constexpr od::descriptor tx_pdo3_sub0{detail::entries[15], detail::infos[15], detail::scales[15]}; // 0x1802 sub 0
inline constexpr od::descriptor tx_pdo3_event_timer{detail::entries[16], detail::infos[16], detail::scales[16]}; // 0x1802 sub 5
inline constexpr od::object tx_pdo4{0x1803, od::object_code::record, "Tx-PDO4 Communication Parameter"sv, dictionary.entries().subspan(17, 2), dictionary.infos().subspan(17, 2), dictionary.scales().subspan(17, 2)};
inline constexpr od::descriptor tx_pdo4_sub0{detail::entries[17], detail::infos[17], detail::scales[17]}; // 0x1803 sub 0
inline constexpr od::descriptor tx_pdo4_event_timer{detail::entries[18], detail::infos[18], detail::scales[18]}; // 0x1803 sub 5

} // namespace fieldcodec::dictionaries::dpq_parameters
// clang-format on
