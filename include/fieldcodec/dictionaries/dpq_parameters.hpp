// Generated from dpq_parameters.csv by fieldcodec-gen — do not edit.
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

#include <array>
#include <cstdint>
#include <string_view>

namespace fieldcodec::dictionaries::dpq_parameters {

using namespace std::string_view_literals;

inline constexpr const char *source_file = "dpq_parameters.csv";

inline constexpr std::array<od::entry, 240> entries{{
    {.index = 0x1001, .type = od::data_type::unsigned8, .access_type = od::access::ro},
    {.index = 0x1003, .object = od::object_code::array, .type = od::data_type::unsigned8, .low = od::unsigned_number(0U), .high = od::unsigned_number(4U), .default_value = od::unsigned_number(0U)},
    {.index = 0x1003, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro},
    {.index = 0x1003, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro},
    {.index = 0x1003, .sub = 3, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro},
    {.index = 0x1003, .sub = 4, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro},
    {.index = 0x100C, .type = od::data_type::unsigned16, .low = od::unsigned_number(0U), .high = od::unsigned_number(65535U), .default_value = od::unsigned_number(0U)},
    {.index = 0x100D, .type = od::data_type::unsigned8, .low = od::unsigned_number(0U), .high = od::unsigned_number(255U), .default_value = od::unsigned_number(0U)},
    {.index = 0x1016, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(1U), .high = od::unsigned_number(127U)},
    {.index = 0x1016, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .low = od::unsigned_number(0U), .high = od::unsigned_number(16777215U), .default_value = od::unsigned_number(0U)},
    {.index = 0x1017, .type = od::data_type::unsigned16, .low = od::unsigned_number(0U), .high = od::unsigned_number(65535U), .default_value = od::unsigned_number(0U)},
    {.index = 0x1800, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(5U), .high = od::unsigned_number(6U)},
    {.index = 0x1800, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .low = od::unsigned_number(0U), .high = od::unsigned_number(65535U), .default_value = od::unsigned_number(0U)},
    {.index = 0x1801, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(5U), .high = od::unsigned_number(6U)},
    {.index = 0x1801, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .low = od::unsigned_number(0U), .high = od::unsigned_number(65535U), .default_value = od::unsigned_number(0U)},
    {.index = 0x1802, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(5U), .high = od::unsigned_number(6U)},
    {.index = 0x1802, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .low = od::unsigned_number(0U), .high = od::unsigned_number(65535U), .default_value = od::unsigned_number(0U)},
    {.index = 0x1803, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(5U), .high = od::unsigned_number(6U)},
    {.index = 0x1803, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .low = od::unsigned_number(0U), .high = od::unsigned_number(65535U), .default_value = od::unsigned_number(0U)},
    {.index = 0x200D, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(100)},
    {.index = 0x200E, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x200F, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2010, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2011, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2012, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2013, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2014, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2015, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2017, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2018, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x201F, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2023, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2025, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2026, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2027, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2028, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x202F, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2030, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2031, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2032, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2033, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2036, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2037, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2039, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x203A, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x203C, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x203D, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x203E, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x203F, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2040, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2041, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2114, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2130, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2131, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2132, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2133, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2136, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2137, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x213A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2167, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2169, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x216A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x216B, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x216C, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2180, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2181, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2182, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2183, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2184, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2195, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2196, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2197, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2198, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2199, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x219C, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x219D, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x21A0, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2201, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(65)},
    {.index = 0x2301, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(9999, 2)},
    {.index = 0x2323, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(9999, 2)},
    {.index = 0x2336, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(9999, 2)},
    {.index = 0x2337, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(9999, 2)},
    {.index = 0x233A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(9999, 2)},
    {.index = 0x2423, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(30000)},
    {.index = 0x2436, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(30000)},
    {.index = 0x2437, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(30000)},
    {.index = 0x243A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(30000)},
    {.index = 0x2701, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(640)},
    {.index = 0x2723, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(640)},
    {.index = 0x2736, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(640)},
    {.index = 0x2737, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(640)},
    {.index = 0x273A, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(640)},
    {.index = 0x2923, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(1)},
    {.index = 0x2936, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(1)},
    {.index = 0x2937, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(1)},
    {.index = 0x293A, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(1)},
    {.index = 0x2A01, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(5000)},
    {.index = 0x2A03, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(5000)},
    {.index = 0x2A04, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(5000)},
    {.index = 0x2A05, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(5000)},
    {.index = 0x2A06, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(5000)},
    {.index = 0x2A14, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2A15, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2A17, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2A1A, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(5000)},
    {.index = 0x2A1B, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(5000)},
    {.index = 0x2A1C, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(5000)},
    {.index = 0x2A1D, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(5000)},
    {.index = 0x2A64, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::index_anomaly | od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2B2F, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(99999, 2)},
    {.index = 0x2B30, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(99999, 2)},
    {.index = 0x2B31, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(99999, 2)},
    {.index = 0x2B32, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(99999, 2)},
    {.index = 0x2B33, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(99999, 2)},
    {.index = 0x2C67, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2C68, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2C69, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2C78, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D02, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(640)},
    {.index = 0x2D04, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(2559, 1)},
    {.index = 0x2D05, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::decimal_number(9999, 2)},
    {.index = 0x2D0E, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2D0F, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2D17, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(60)},
    {.index = 0x2D3B, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2D3C, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2D3D, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2D3E, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2D71, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D72, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D73, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D74, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D75, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D76, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D7C, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D7D, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D7E, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D7F, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D80, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D81, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2D87, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D88, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D89, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D8A, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D8B, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D8C, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D92, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D93, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D94, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D95, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D96, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D97, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::signed_number(-150), .high = od::signed_number(150)},
    {.index = 0x2D9D, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2D9E, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2D9F, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2DA0, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2DA1, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2DC1, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(1), .high = od::signed_number(25)},
    {.index = 0x2DC4, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(32767)},
    {.index = 0x2DC5, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2DCB, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2DCC, .type = od::data_type::unsigned16, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(32767)},
    {.index = 0x2E21, .type = od::data_type::integer16, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::decimal_number(-999, 1), .high = od::decimal_number(999, 1)},
    {.index = 0x2E2A, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2E2D, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2E2E, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(0)},
    {.index = 0x2F03, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F04, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(1000)},
    {.index = 0x2F07, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(1000)},
    {.index = 0x2F09, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-1000), .high = od::signed_number(1000)},
    {.index = 0x2F0B, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(200)},
    {.index = 0x2F0E, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(200)},
    {.index = 0x2F0F, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(200)},
    {.index = 0x2F10, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(200)},
    {.index = 0x2F11, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(200)},
    {.index = 0x2F13, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-200), .high = od::signed_number(200)},
    {.index = 0x2F19, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(2000)},
    {.index = 0x2F1A, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(1000)},
    {.index = 0x2F1F, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F20, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F21, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F25, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(32)},
    {.index = 0x2F26, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F27, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F28, .type = od::data_type::unsigned16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(32)},
    {.index = 0x2F34, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::tx, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F6D, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F72, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2F78, .type = od::data_type::unsigned32, .flags = od::flag::signedness_guess | od::flag::scaled, .low = od::signed_number(0), .high = od::signed_number(5000)},
    {.index = 0x2F7F, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F80, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::decimal_number(-999, 1), .high = od::decimal_number(999, 1)},
    {.index = 0x2F81, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F82, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F87, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(0)},
    {.index = 0x2F91, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F92, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::decimal_number(-999, 1), .high = od::decimal_number(999, 1)},
    {.index = 0x2F93, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F94, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2F99, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(0)},
    {.index = 0x2FA3, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2FA4, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::decimal_number(-999, 1), .high = od::decimal_number(999, 1)},
    {.index = 0x2FA5, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2FA6, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x2FAB, .type = od::data_type::integer16, .flags = od::flag::range_exceeds_field | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(0)},
    {.index = 0x3116, .type = od::data_type::integer16, .flags = od::flag::scaled, .low = od::decimal_number(-319, 1), .high = od::decimal_number(319, 1)},
    {.index = 0x3501, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3503, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3504, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3505, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3506, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x350E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x350F, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3510, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3511, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3512, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3518, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x351B, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x351C, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x351D, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x351E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x351F, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3571, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3601, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3602, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3603, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3604, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3605, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3606, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x360D, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x360E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x360F, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3610, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3611, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x3617, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::index_anomaly | od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x361A, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x361B, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x361C, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x361D, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x361E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
    {.index = 0x362E, .type = od::data_type::integer32, .access_type = od::access::ro, .flags = od::flag::scaled, .low = od::signed_number(-100), .high = od::signed_number(100)},
}};

inline constexpr std::array<od::entry_info, 240> infos{{
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
    {.name = {"Holding: Vel.Limit 1", 20}, .section = {"4.92", 4}, .remark = {"signed although the printed range is not negative: Holding: Vel.Limit 2..5 are -100..100 (docs/dpq.md)", 102}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Vel.Limit 2", 20}, .section = {"4.93", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Vel.Limit 3", 20}, .section = {"4.94", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Vel.Limit 4", 20}, .section = {"4.95", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Vel.Limit 5", 20}, .section = {"4.96", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"JogMode:Vel.Forward", 19}, .unit = {"%", 1}, .section = {"4.141", 5}, .remark = {"name follows the Name line; the table of contents prints \"Jog Mode: Vel. Forward\"", 81}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"JogMode:Vel.Backward", 20}, .unit = {"%", 1}, .section = {"4.140", 5}, .remark = {"name follows the Name line; the table of contents prints \"Jog Mode: Vel. Backward\"", 82}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Screw Speed 2", 13}, .section = {"4.199", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Screw Speed 3", 13}, .section = {"4.200", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Pre.Decomp: Velocity", 20}, .section = {"4.172", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Screw Speed 4", 13}, .section = {"4.201", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Post.Decomp: Velocit", 20}, .section = {"4.170", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 1", 14}, .section = {"4.100", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 2", 14}, .section = {"4.102", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 3", 14}, .section = {"4.103", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 4", 14}, .section = {"4.104", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 5", 14}, .section = {"4.105", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Pressure 1", 19}, .section = {"4.82", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Pressure 2", 19}, .section = {"4.83", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Pressure 3", 19}, .section = {"4.84", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Pressure 4", 19}, .section = {"4.85", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Pressure 5", 19}, .section = {"4.86", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackPress: Press 2", 18}, .section = {"4.20", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackPress: Press 3", 18}, .section = {"4.21", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Press: PreDecompress", 20}, .unit = {"bar", 3}, .section = {"4.191", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"BackPress: Press 4", 18}, .section = {"4.22", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 6", 14}, .section = {"4.106", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 7", 14}, .section = {"4.107", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 8", 14}, .section = {"4.108", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 9", 14}, .section = {"4.109", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. P Limit 10", 15}, .section = {"4.101", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Press: PostDecompres", 20}, .unit = {"bar", 3}, .section = {"4.190", 5}, .remark = {"name follows the Name line; the table of contents prints \"Press: PostDecompress\"", 80}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"BackP: Vel. Ramp 2", 18}, .unit = {"%/sec", 5}, .section = {"4.17", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Press Rate 2", 17}, .section = {"4.158", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Press Rate 3", 17}, .section = {"4.159", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Press Rate 4", 17}, .section = {"4.160", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Press Rate 5", 17}, .unit = {"bar/sec", 7}, .section = {"4.161", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press Rate 2", 19}, .section = {"4.14", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press Rate 3", 19}, .section = {"4.15", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press Rate 4", 19}, .unit = {"bar/sec", 7}, .section = {"4.16", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 1", 15}, .section = {"4.119", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 2", 15}, .section = {"4.121", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 3", 15}, .section = {"4.122", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 4", 15}, .section = {"4.123", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 5", 15}, .section = {"4.124", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 6", 15}, .section = {"4.125", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 7", 15}, .section = {"4.126", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 8", 15}, .section = {"4.127", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 9", 15}, .section = {"4.128", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Velocity 10", 16}, .section = {"4.120", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Decomp Rate 1", 18}, .section = {"4.153", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Decomp Rate 2", 18}, .section = {"4.154", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Decomp Rate 3", 18}, .section = {"4.155", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Decomp Rate 4", 18}, .section = {"4.156", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Decomp Rate 5", 18}, .unit = {"bar/sec", 7}, .section = {"4.157", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Decomp Rate 2", 20}, .section = {"4.2", 3}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Decomp Rate 3", 20}, .section = {"4.3", 3}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Decomp Rate 4", 20}, .unit = {"bar/sec", 7}, .section = {"4.4", 3}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Accel.Ramp", 15}, .unit = {"[s]", 3}, .section = {"4.99", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj.: Velocity P", 16}, .section = {"4.131", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Pressure P", 15}, .section = {"4.164", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press P 2", 16}, .section = {"4.11", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press P 3", 16}, .section = {"4.12", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press P 4", 16}, .section = {"4.13", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Pressure I", 15}, .unit = {"ms", 2}, .section = {"4.163", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press I 2", 16}, .section = {"4.8", 3}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press I 3", 16}, .section = {"4.9", 3}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press I 4", 16}, .unit = {"ms", 2}, .section = {"4.10", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj.: Velocity D", 16}, .unit = {"Hz", 2}, .section = {"4.130", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: Pressure D", 15}, .unit = {"Hz", 2}, .section = {"4.162", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press D 2", 16}, .section = {"4.5", 3}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press D 3", 16}, .section = {"4.6", 3}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackP: Press D 4", 16}, .unit = {"Hz", 2}, .section = {"4.7", 3}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"FWD: Inject", 11}, .section = {"4.46", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"FWD: BackPress 1", 16}, .section = {"4.43", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"FWD: BackPress 2", 16}, .section = {"4.44", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"FWD: BackPress 3", 16}, .section = {"4.45", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Inj. Position 2", 15}, .section = {"4.111", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Position 3", 15}, .section = {"4.112", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Position 4", 15}, .section = {"4.113", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Position 5", 15}, .section = {"4.114", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Position 6", 15}, .section = {"4.115", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackPress: Position3", 20}, .section = {"4.18", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"BackPress: Position4", 20}, .section = {"4.19", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Pre.Decomp: Position", 20}, .section = {"4.171", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Position 7", 15}, .section = {"4.116", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Position 8", 15}, .section = {"4.117", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Position 9", 15}, .section = {"4.118", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj. Position 10", 16}, .section = {"4.110", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Post.Decomp: Positio", 20}, .section = {"4.169", 5}, .remark = {"index_anomaly: Pre/Post pairs differ by 8 (0x2017/0x201F, 0x2039/0x2041) and Pre.Decomp: Position is 0x2A17, so 0x2A1F would be expected; as printed, see docs/errata.md", 168}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Time 1", 15}, .section = {"4.87", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Time 2", 15}, .section = {"4.88", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Time 3", 15}, .section = {"4.89", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Time 4", 15}, .section = {"4.90", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Holding: Time 5", 15}, .section = {"4.91", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Trigger", 7}, .section = {"4.212", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Status", 6}, .section = {"4.207", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Analog Vel Max", 14}, .unit = {"mm/s", 4}, .section = {"4.1", 3}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Set SSI/INCR to zero", 20}, .section = {"4.202", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"PaH: act.Damp. Freq.", 20}, .unit = {"Hz", 2}, .section = {"4.151", 5}, .remark = {"name follows the Name line; the table of contents prints \"PaH: act.Damp. Freq\"", 78}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Inj.: Vel.ActiveDamp", 20}, .section = {"4.129", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"PaH: act.Damp. Gain", 19}, .section = {"4.152", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Shot Size Position", 18}, .section = {"4.203", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"DO7: At Press Level", 19}, .unit = {"bar", 3}, .section = {"4.42", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"DO7: At Press Delay", 19}, .unit = {"sec", 3}, .section = {"4.41", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Transfer Position", 17}, .unit = {"mm", 2}, .section = {"4.211", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Transfer Cavity Pres", 20}, .unit = {"bar", 3}, .section = {"4.208", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Transfer Hydr.Press", 19}, .unit = {"bar", 3}, .section = {"4.210", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Transfer Hydr.Pos.", 18}, .unit = {"mm", 2}, .section = {"4.209", 5}, .remark = {"name follows the Name line; the table of contents prints \"Transfer Hydr.Pos\" (a trailing dot cannot be told apart from the dot leader)", 134}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::available},
    {.name = {"Press CMD Min", 13}, .section = {"4.177", 5}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #1 Min", 15}, .section = {"4.182", 5}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cavity Press Min", 16}, .section = {"4.26", 4}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #2 Min", 15}, .section = {"4.187", 5}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cyl Pos FB Min", 14}, .section = {"4.32", 4}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Vel. CMD Min", 12}, .section = {"4.219", 5}, .remark = {"printed range gives raw -1638350..1638350, outside INTEGER16; the encoder refuses such values with errc::overflow", 113}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press CMD Max", 13}, .section = {"4.174", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #1 Max", 15}, .section = {"4.179", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cavity Press Max", 16}, .section = {"4.23", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #2 Max", 15}, .section = {"4.184", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cyl Pos FB Max", 14}, .section = {"4.30", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Vel. CMD Max", 12}, .section = {"4.217", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press CMD Min Fau", 17}, .unit = {"bar", 3}, .section = {"4.178", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #1 Min Fau", 19}, .unit = {"bar", 3}, .section = {"4.183", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cavity Press Min Fau", 20}, .unit = {"bar", 3}, .section = {"4.27", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #2 Min Fau", 19}, .unit = {"bar", 3}, .section = {"4.188", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cyl Pos FB Min Fau", 18}, .unit = {"mm", 2}, .section = {"4.33", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Vel. CMD Min Fau", 16}, .unit = {"mm/s", 4}, .section = {"4.220", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press CMD Max Fau", 17}, .unit = {"bar", 3}, .section = {"4.175", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #1 Max Fau", 19}, .unit = {"bar", 3}, .section = {"4.180", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cavity Press Max Fau", 20}, .unit = {"bar", 3}, .section = {"4.24", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #2 Max Fau", 19}, .unit = {"bar", 3}, .section = {"4.185", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cyl Pos FB Max Fau", 18}, .unit = {"mm", 2}, .section = {"4.31", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Vel. CMD Max Fau", 16}, .unit = {"mm/s", 4}, .section = {"4.218", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press CMD Max Uni", 17}, .unit = {"bar", 3}, .section = {"4.176", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #1 Max Uni", 19}, .unit = {"bar", 3}, .section = {"4.181", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cavity Press Max Uni", 20}, .unit = {"bar", 3}, .section = {"4.25", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Press FB #2 Max Uni", 19}, .unit = {"bar", 3}, .section = {"4.186", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cyl Pos CMD Max Uni", 19}, .unit = {"mm", 2}, .section = {"4.29", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"SSI: Nb. of bits", 16}, .section = {"4.204", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"SSI: Resolution", 15}, .unit = {"count/mm", 8}, .section = {"4.206", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"SSI: Offset", 11}, .unit = {"mm", 2}, .section = {"4.205", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"INCR: Home Offset", 17}, .unit = {"mm", 2}, .section = {"4.97", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"INCR: Resolution", 16}, .unit = {"count/mm", 8}, .section = {"4.98", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Injection: Scale", 16}, .section = {"4.135", 5}, .remark = {"index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 273}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Injection: Limit+", 17}, .unit = {"%", 1}, .section = {"4.133", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow; index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 384}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Injection: Limit-", 17}, .unit = {"%", 1}, .section = {"4.132", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow; index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 384}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"OUT2: Inject Limit-", 19}, .unit = {"%", 1}, .section = {"4.144", 5}, .remark = {"printed range gives raw -32770..0, outside INTEGER16; the encoder refuses such values with errc::overflow; index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 380}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Velocity CMD AI6:", 17}, .unit = {"[mm/s]", 6}, .section = {"4.221", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Vel Loop CMD :", 14}, .unit = {"[mm]", 4}, .section = {"4.216", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md); unit printed [mm] although this is a velocity command", 142}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Position FB :", 13}, .unit = {"[mm]", 4}, .section = {"4.168", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Position Error :", 16}, .unit = {"[mm]", 4}, .section = {"4.167", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Pressure CMD AI1:", 17}, .unit = {"[bar]", 5}, .section = {"4.192", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Press Loop CMD :", 16}, .unit = {"[bar]", 5}, .section = {"4.189", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Pressure FB#1 AI2:", 18}, .unit = {"[bar]", 5}, .section = {"4.195", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Pressure FB#2 AI4:", 18}, .unit = {"[bar]", 5}, .section = {"4.196", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Pressure FB :", 13}, .unit = {"[bar]", 5}, .section = {"4.194", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Pressure Error :", 16}, .unit = {"[bar]", 5}, .section = {"4.193", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Cavity Pressure AI3:", 20}, .unit = {"[bar]", 5}, .section = {"4.28", 4}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Position AI5:", 13}, .unit = {"[mm]", 4}, .section = {"4.166", 5}, .remark = {"signed although the printed range is not negative: read-only actual value (docs/dpq.md)", 87}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Valve Output 1 :", 16}, .unit = {"[%]", 3}, .section = {"4.213", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Valve Output 2 :", 16}, .unit = {"[%]", 3}, .section = {"4.214", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Valve Output 3 :", 16}, .unit = {"[%]", 3}, .section = {"4.215", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Program Block", 13}, .section = {"4.197", 5}, .remark = {"offset 1: printed minimum 0 is raw -1", 37}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Discrete Outputs", 16}, .section = {"4.40", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Discrete Inputs", 15}, .section = {"4.39", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Output Mode", 11}, .section = {"4.146", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Program Status", 14}, .section = {"4.198", 5}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::available},
    {.name = {"Injection: Offset", 17}, .unit = {"%", 1}, .section = {"4.134", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow; index_anomaly: the Injection: block is split (Offset 0x2F6D; Scale, Limit+, Limit-, OUT2: Inject Limit- at 0x2E21/0x2E2A/0x2E2D/0x2E2E) while the Jog Mode, PaH/BackPres and Decompres. blocks sit together at 0x2F7F/0x2F91/0x2FA3 (stride 0x12); as printed, see docs/errata.md", 384}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Pos Max Length", 14}, .unit = {"mm", 2}, .section = {"4.165", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Pres Max Inject", 15}, .unit = {"bar", 3}, .section = {"4.173", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Jog Mode: Offset", 16}, .unit = {"%", 1}, .section = {"4.138", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Jog Mode: Scale", 15}, .section = {"4.139", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Jog Mode: Limit-", 16}, .unit = {"%", 1}, .section = {"4.136", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Jog Mode: Limit+", 16}, .unit = {"%", 1}, .section = {"4.137", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"OUT2: Jog Limit-", 16}, .unit = {"%", 1}, .section = {"4.145", 5}, .remark = {"printed range gives raw -32770..0, outside INTEGER16; the encoder refuses such values with errc::overflow", 105}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"PaH/BackPres: Offset", 20}, .unit = {"%", 1}, .section = {"4.149", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"PaH/BackPres: Scale", 19}, .section = {"4.150", 5}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"PaH/BackPres: Limit-", 20}, .unit = {"%", 1}, .section = {"4.147", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"PaH/BackPres: Limit+", 20}, .unit = {"%", 1}, .section = {"4.148", 5}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"OUT2: BackPress Lim-", 20}, .unit = {"%", 1}, .section = {"4.142", 5}, .remark = {"printed range gives raw -32770..0, outside INTEGER16; the encoder refuses such values with errc::overflow", 105}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Decompres.: Offset", 18}, .unit = {"%", 1}, .section = {"4.37", 4}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Decompres.: Scale", 17}, .section = {"4.38", 4}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Decompres.: Limit-", 18}, .unit = {"%", 1}, .section = {"4.35", 4}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Decompres.: Limit+", 18}, .unit = {"%", 1}, .section = {"4.36", 4}, .remark = {"printed range gives raw -32770..32770, outside INTEGER16; the encoder refuses such values with errc::overflow", 109}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"OUT2: Decomp Limit-", 19}, .unit = {"%", 1}, .section = {"4.143", 5}, .remark = {"printed range gives raw -32770..0, outside INTEGER16; the encoder refuses such values with errc::overflow", 105}, .acceptance = {"also with active enabling", 25}, .bus = od::bus_manager::not_available},
    {.name = {"Cyl. Area Ratio", 15}, .section = {"4.34", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 1", 12}, .section = {"4.66", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 3", 12}, .section = {"4.77", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 4", 12}, .section = {"4.79", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 5", 12}, .section = {"4.80", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 6", 12}, .section = {"4.81", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 13", 13}, .section = {"4.67", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 14", 13}, .section = {"4.68", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 15", 13}, .section = {"4.69", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 16", 13}, .section = {"4.70", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 17", 13}, .section = {"4.71", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 23", 13}, .section = {"4.72", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 26", 13}, .section = {"4.73", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 27", 13}, .section = {"4.74", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 28", 13}, .section = {"4.75", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 29", 13}, .section = {"4.76", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Time 30", 13}, .section = {"4.78", 4}, .remark = {"index_anomaly: Hist. Time 13..30 are at 0x3501+n, Hist. Time 1..6 and Hist. Pos.FB at base+n; shift consistent over all 11, may be genuine; as printed, see docs/errata.md", 170}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pres CMD 13", 17}, .section = {"4.64", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 1", 14}, .section = {"4.48", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 2", 14}, .section = {"4.54", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 3", 14}, .section = {"4.59", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 4", 14}, .section = {"4.61", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 5", 14}, .section = {"4.62", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 6", 14}, .section = {"4.63", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos. FB 13", 16}, .section = {"4.47", 4}, .remark = {"spelled \"Pos. FB\" with a space, unlike the other Hist. Pos.FB entries (same in TOC, heading and Name line)", 106}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 14", 15}, .section = {"4.49", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 15", 15}, .section = {"4.50", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 16", 15}, .section = {"4.51", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 17", 15}, .section = {"4.52", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 18", 15}, .section = {"4.53", 4}, .remark = {"index_anomaly: every other Hist. Pos.FB n is at 0x3600+n, so 18 would be 0x3612; as printed, see docs/errata.md", 111}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 26", 15}, .section = {"4.55", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 27", 15}, .section = {"4.56", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 28", 15}, .section = {"4.57", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 29", 15}, .section = {"4.58", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pos.FB 30", 15}, .section = {"4.60", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
    {.name = {"Hist. Pres.FB 13", 16}, .section = {"4.65", 4}, .acceptance = {"only with deactivated enabling", 30}, .bus = od::bus_manager::not_available},
}};

inline constexpr std::array<scaling::linear, 240> scales{{
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
}};

inline constexpr od::dictionary dictionary{entries, infos, scales};
static_assert(dictionary.is_valid());

// VAR objects: standalone descriptors (firmware that names one keeps only that one).
inline constexpr od::descriptor error_register{entries[0], infos[0], scales[0]}; // 0x1001
inline constexpr od::descriptor guard_time{entries[6], infos[6], scales[6]}; // 0x100C
inline constexpr od::descriptor life_time_factor{entries[7], infos[7], scales[7]}; // 0x100D
inline constexpr od::descriptor producer_heartbeat_time_interval{entries[10], infos[10], scales[10]}; // 0x1017
inline constexpr od::descriptor holding_vel_limit_1{entries[19], infos[19], scales[19]}; // 0x200D
inline constexpr od::descriptor holding_vel_limit_2{entries[20], infos[20], scales[20]}; // 0x200E
inline constexpr od::descriptor holding_vel_limit_3{entries[21], infos[21], scales[21]}; // 0x200F
inline constexpr od::descriptor holding_vel_limit_4{entries[22], infos[22], scales[22]}; // 0x2010
inline constexpr od::descriptor holding_vel_limit_5{entries[23], infos[23], scales[23]}; // 0x2011
inline constexpr od::descriptor jogmode_vel_forward{entries[24], infos[24], scales[24]}; // 0x2012
inline constexpr od::descriptor jogmode_vel_backward{entries[25], infos[25], scales[25]}; // 0x2013
inline constexpr od::descriptor screw_speed_2{entries[26], infos[26], scales[26]}; // 0x2014
inline constexpr od::descriptor screw_speed_3{entries[27], infos[27], scales[27]}; // 0x2015
inline constexpr od::descriptor pre_decomp_velocity{entries[28], infos[28], scales[28]}; // 0x2017
inline constexpr od::descriptor screw_speed_4{entries[29], infos[29], scales[29]}; // 0x2018
inline constexpr od::descriptor post_decomp_velocit{entries[30], infos[30], scales[30]}; // 0x201F
inline constexpr od::descriptor inj_p_limit_1{entries[31], infos[31], scales[31]}; // 0x2023
inline constexpr od::descriptor inj_p_limit_2{entries[32], infos[32], scales[32]}; // 0x2025
inline constexpr od::descriptor inj_p_limit_3{entries[33], infos[33], scales[33]}; // 0x2026
inline constexpr od::descriptor inj_p_limit_4{entries[34], infos[34], scales[34]}; // 0x2027
inline constexpr od::descriptor inj_p_limit_5{entries[35], infos[35], scales[35]}; // 0x2028
inline constexpr od::descriptor holding_pressure_1{entries[36], infos[36], scales[36]}; // 0x202F
inline constexpr od::descriptor holding_pressure_2{entries[37], infos[37], scales[37]}; // 0x2030
inline constexpr od::descriptor holding_pressure_3{entries[38], infos[38], scales[38]}; // 0x2031
inline constexpr od::descriptor holding_pressure_4{entries[39], infos[39], scales[39]}; // 0x2032
inline constexpr od::descriptor holding_pressure_5{entries[40], infos[40], scales[40]}; // 0x2033
inline constexpr od::descriptor backpress_press_2{entries[41], infos[41], scales[41]}; // 0x2036
inline constexpr od::descriptor backpress_press_3{entries[42], infos[42], scales[42]}; // 0x2037
inline constexpr od::descriptor press_predecompress{entries[43], infos[43], scales[43]}; // 0x2039
inline constexpr od::descriptor backpress_press_4{entries[44], infos[44], scales[44]}; // 0x203A
inline constexpr od::descriptor inj_p_limit_6{entries[45], infos[45], scales[45]}; // 0x203C
inline constexpr od::descriptor inj_p_limit_7{entries[46], infos[46], scales[46]}; // 0x203D
inline constexpr od::descriptor inj_p_limit_8{entries[47], infos[47], scales[47]}; // 0x203E
inline constexpr od::descriptor inj_p_limit_9{entries[48], infos[48], scales[48]}; // 0x203F
inline constexpr od::descriptor inj_p_limit_10{entries[49], infos[49], scales[49]}; // 0x2040
inline constexpr od::descriptor press_postdecompres{entries[50], infos[50], scales[50]}; // 0x2041
inline constexpr od::descriptor backp_vel_ramp_2{entries[51], infos[51], scales[51]}; // 0x2114
inline constexpr od::descriptor pah_press_rate_2{entries[52], infos[52], scales[52]}; // 0x2130
inline constexpr od::descriptor pah_press_rate_3{entries[53], infos[53], scales[53]}; // 0x2131
inline constexpr od::descriptor pah_press_rate_4{entries[54], infos[54], scales[54]}; // 0x2132
inline constexpr od::descriptor pah_press_rate_5{entries[55], infos[55], scales[55]}; // 0x2133
inline constexpr od::descriptor backp_press_rate_2{entries[56], infos[56], scales[56]}; // 0x2136
inline constexpr od::descriptor backp_press_rate_3{entries[57], infos[57], scales[57]}; // 0x2137
inline constexpr od::descriptor backp_press_rate_4{entries[58], infos[58], scales[58]}; // 0x213A
inline constexpr od::descriptor inj_velocity_1{entries[59], infos[59], scales[59]}; // 0x2167
inline constexpr od::descriptor inj_velocity_2{entries[60], infos[60], scales[60]}; // 0x2169
inline constexpr od::descriptor inj_velocity_3{entries[61], infos[61], scales[61]}; // 0x216A
inline constexpr od::descriptor inj_velocity_4{entries[62], infos[62], scales[62]}; // 0x216B
inline constexpr od::descriptor inj_velocity_5{entries[63], infos[63], scales[63]}; // 0x216C
inline constexpr od::descriptor inj_velocity_6{entries[64], infos[64], scales[64]}; // 0x2180
inline constexpr od::descriptor inj_velocity_7{entries[65], infos[65], scales[65]}; // 0x2181
inline constexpr od::descriptor inj_velocity_8{entries[66], infos[66], scales[66]}; // 0x2182
inline constexpr od::descriptor inj_velocity_9{entries[67], infos[67], scales[67]}; // 0x2183
inline constexpr od::descriptor inj_velocity_10{entries[68], infos[68], scales[68]}; // 0x2184
inline constexpr od::descriptor pah_decomp_rate_1{entries[69], infos[69], scales[69]}; // 0x2195
inline constexpr od::descriptor pah_decomp_rate_2{entries[70], infos[70], scales[70]}; // 0x2196
inline constexpr od::descriptor pah_decomp_rate_3{entries[71], infos[71], scales[71]}; // 0x2197
inline constexpr od::descriptor pah_decomp_rate_4{entries[72], infos[72], scales[72]}; // 0x2198
inline constexpr od::descriptor pah_decomp_rate_5{entries[73], infos[73], scales[73]}; // 0x2199
inline constexpr od::descriptor backp_decomp_rate_2{entries[74], infos[74], scales[74]}; // 0x219C
inline constexpr od::descriptor backp_decomp_rate_3{entries[75], infos[75], scales[75]}; // 0x219D
inline constexpr od::descriptor backp_decomp_rate_4{entries[76], infos[76], scales[76]}; // 0x21A0
inline constexpr od::descriptor inj_accel_ramp{entries[77], infos[77], scales[77]}; // 0x2201
inline constexpr od::descriptor inj_velocity_p{entries[78], infos[78], scales[78]}; // 0x2301
inline constexpr od::descriptor pah_pressure_p{entries[79], infos[79], scales[79]}; // 0x2323
inline constexpr od::descriptor backp_press_p_2{entries[80], infos[80], scales[80]}; // 0x2336
inline constexpr od::descriptor backp_press_p_3{entries[81], infos[81], scales[81]}; // 0x2337
inline constexpr od::descriptor backp_press_p_4{entries[82], infos[82], scales[82]}; // 0x233A
inline constexpr od::descriptor pah_pressure_i{entries[83], infos[83], scales[83]}; // 0x2423
inline constexpr od::descriptor backp_press_i_2{entries[84], infos[84], scales[84]}; // 0x2436
inline constexpr od::descriptor backp_press_i_3{entries[85], infos[85], scales[85]}; // 0x2437
inline constexpr od::descriptor backp_press_i_4{entries[86], infos[86], scales[86]}; // 0x243A
inline constexpr od::descriptor inj_velocity_d{entries[87], infos[87], scales[87]}; // 0x2701
inline constexpr od::descriptor pah_pressure_d{entries[88], infos[88], scales[88]}; // 0x2723
inline constexpr od::descriptor backp_press_d_2{entries[89], infos[89], scales[89]}; // 0x2736
inline constexpr od::descriptor backp_press_d_3{entries[90], infos[90], scales[90]}; // 0x2737
inline constexpr od::descriptor backp_press_d_4{entries[91], infos[91], scales[91]}; // 0x273A
inline constexpr od::descriptor fwd_inject{entries[92], infos[92], scales[92]}; // 0x2923
inline constexpr od::descriptor fwd_backpress_1{entries[93], infos[93], scales[93]}; // 0x2936
inline constexpr od::descriptor fwd_backpress_2{entries[94], infos[94], scales[94]}; // 0x2937
inline constexpr od::descriptor fwd_backpress_3{entries[95], infos[95], scales[95]}; // 0x293A
inline constexpr od::descriptor inj_position_2{entries[96], infos[96], scales[96]}; // 0x2A01
inline constexpr od::descriptor inj_position_3{entries[97], infos[97], scales[97]}; // 0x2A03
inline constexpr od::descriptor inj_position_4{entries[98], infos[98], scales[98]}; // 0x2A04
inline constexpr od::descriptor inj_position_5{entries[99], infos[99], scales[99]}; // 0x2A05
inline constexpr od::descriptor inj_position_6{entries[100], infos[100], scales[100]}; // 0x2A06
inline constexpr od::descriptor backpress_position3{entries[101], infos[101], scales[101]}; // 0x2A14
inline constexpr od::descriptor backpress_position4{entries[102], infos[102], scales[102]}; // 0x2A15
inline constexpr od::descriptor pre_decomp_position{entries[103], infos[103], scales[103]}; // 0x2A17
inline constexpr od::descriptor inj_position_7{entries[104], infos[104], scales[104]}; // 0x2A1A
inline constexpr od::descriptor inj_position_8{entries[105], infos[105], scales[105]}; // 0x2A1B
inline constexpr od::descriptor inj_position_9{entries[106], infos[106], scales[106]}; // 0x2A1C
inline constexpr od::descriptor inj_position_10{entries[107], infos[107], scales[107]}; // 0x2A1D
inline constexpr od::descriptor post_decomp_positio{entries[108], infos[108], scales[108]}; // 0x2A64
inline constexpr od::descriptor holding_time_1{entries[109], infos[109], scales[109]}; // 0x2B2F
inline constexpr od::descriptor holding_time_2{entries[110], infos[110], scales[110]}; // 0x2B30
inline constexpr od::descriptor holding_time_3{entries[111], infos[111], scales[111]}; // 0x2B31
inline constexpr od::descriptor holding_time_4{entries[112], infos[112], scales[112]}; // 0x2B32
inline constexpr od::descriptor holding_time_5{entries[113], infos[113], scales[113]}; // 0x2B33
inline constexpr od::descriptor trigger{entries[114], infos[114], scales[114]}; // 0x2C67
inline constexpr od::descriptor status{entries[115], infos[115], scales[115]}; // 0x2C68
inline constexpr od::descriptor analog_vel_max{entries[116], infos[116], scales[116]}; // 0x2C69
inline constexpr od::descriptor set_ssi_incr_to_zero{entries[117], infos[117], scales[117]}; // 0x2C78
inline constexpr od::descriptor pah_act_damp_freq{entries[118], infos[118], scales[118]}; // 0x2D02
inline constexpr od::descriptor inj_vel_activedamp{entries[119], infos[119], scales[119]}; // 0x2D04
inline constexpr od::descriptor pah_act_damp_gain{entries[120], infos[120], scales[120]}; // 0x2D05
inline constexpr od::descriptor shot_size_position{entries[121], infos[121], scales[121]}; // 0x2D0E
inline constexpr od::descriptor do7_at_press_level{entries[122], infos[122], scales[122]}; // 0x2D0F
inline constexpr od::descriptor do7_at_press_delay{entries[123], infos[123], scales[123]}; // 0x2D17
inline constexpr od::descriptor transfer_position{entries[124], infos[124], scales[124]}; // 0x2D3B
inline constexpr od::descriptor transfer_cavity_pres{entries[125], infos[125], scales[125]}; // 0x2D3C
inline constexpr od::descriptor transfer_hydr_press{entries[126], infos[126], scales[126]}; // 0x2D3D
inline constexpr od::descriptor transfer_hydr_pos{entries[127], infos[127], scales[127]}; // 0x2D3E
inline constexpr od::descriptor press_cmd_min{entries[128], infos[128], scales[128]}; // 0x2D71
inline constexpr od::descriptor press_fb_1_min{entries[129], infos[129], scales[129]}; // 0x2D72
inline constexpr od::descriptor cavity_press_min{entries[130], infos[130], scales[130]}; // 0x2D73
inline constexpr od::descriptor press_fb_2_min{entries[131], infos[131], scales[131]}; // 0x2D74
inline constexpr od::descriptor cyl_pos_fb_min{entries[132], infos[132], scales[132]}; // 0x2D75
inline constexpr od::descriptor vel_cmd_min{entries[133], infos[133], scales[133]}; // 0x2D76
inline constexpr od::descriptor press_cmd_max{entries[134], infos[134], scales[134]}; // 0x2D7C
inline constexpr od::descriptor press_fb_1_max{entries[135], infos[135], scales[135]}; // 0x2D7D
inline constexpr od::descriptor cavity_press_max{entries[136], infos[136], scales[136]}; // 0x2D7E
inline constexpr od::descriptor press_fb_2_max{entries[137], infos[137], scales[137]}; // 0x2D7F
inline constexpr od::descriptor cyl_pos_fb_max{entries[138], infos[138], scales[138]}; // 0x2D80
inline constexpr od::descriptor vel_cmd_max{entries[139], infos[139], scales[139]}; // 0x2D81
inline constexpr od::descriptor press_cmd_min_fau{entries[140], infos[140], scales[140]}; // 0x2D87
inline constexpr od::descriptor press_fb_1_min_fau{entries[141], infos[141], scales[141]}; // 0x2D88
inline constexpr od::descriptor cavity_press_min_fau{entries[142], infos[142], scales[142]}; // 0x2D89
inline constexpr od::descriptor press_fb_2_min_fau{entries[143], infos[143], scales[143]}; // 0x2D8A
inline constexpr od::descriptor cyl_pos_fb_min_fau{entries[144], infos[144], scales[144]}; // 0x2D8B
inline constexpr od::descriptor vel_cmd_min_fau{entries[145], infos[145], scales[145]}; // 0x2D8C
inline constexpr od::descriptor press_cmd_max_fau{entries[146], infos[146], scales[146]}; // 0x2D92
inline constexpr od::descriptor press_fb_1_max_fau{entries[147], infos[147], scales[147]}; // 0x2D93
inline constexpr od::descriptor cavity_press_max_fau{entries[148], infos[148], scales[148]}; // 0x2D94
inline constexpr od::descriptor press_fb_2_max_fau{entries[149], infos[149], scales[149]}; // 0x2D95
inline constexpr od::descriptor cyl_pos_fb_max_fau{entries[150], infos[150], scales[150]}; // 0x2D96
inline constexpr od::descriptor vel_cmd_max_fau{entries[151], infos[151], scales[151]}; // 0x2D97
inline constexpr od::descriptor press_cmd_max_uni{entries[152], infos[152], scales[152]}; // 0x2D9D
inline constexpr od::descriptor press_fb_1_max_uni{entries[153], infos[153], scales[153]}; // 0x2D9E
inline constexpr od::descriptor cavity_press_max_uni{entries[154], infos[154], scales[154]}; // 0x2D9F
inline constexpr od::descriptor press_fb_2_max_uni{entries[155], infos[155], scales[155]}; // 0x2DA0
inline constexpr od::descriptor cyl_pos_cmd_max_uni{entries[156], infos[156], scales[156]}; // 0x2DA1
inline constexpr od::descriptor ssi_nb_of_bits{entries[157], infos[157], scales[157]}; // 0x2DC1
inline constexpr od::descriptor ssi_resolution{entries[158], infos[158], scales[158]}; // 0x2DC4
inline constexpr od::descriptor ssi_offset{entries[159], infos[159], scales[159]}; // 0x2DC5
inline constexpr od::descriptor incr_home_offset{entries[160], infos[160], scales[160]}; // 0x2DCB
inline constexpr od::descriptor incr_resolution{entries[161], infos[161], scales[161]}; // 0x2DCC
inline constexpr od::descriptor injection_scale{entries[162], infos[162], scales[162]}; // 0x2E21
inline constexpr od::descriptor injection_limit_plus{entries[163], infos[163], scales[163]}; // 0x2E2A
inline constexpr od::descriptor injection_limit_minus{entries[164], infos[164], scales[164]}; // 0x2E2D
inline constexpr od::descriptor out2_inject_limit_minus{entries[165], infos[165], scales[165]}; // 0x2E2E
inline constexpr od::descriptor velocity_cmd_ai6{entries[166], infos[166], scales[166]}; // 0x2F03
inline constexpr od::descriptor vel_loop_cmd{entries[167], infos[167], scales[167]}; // 0x2F04
inline constexpr od::descriptor position_fb{entries[168], infos[168], scales[168]}; // 0x2F07
inline constexpr od::descriptor position_error{entries[169], infos[169], scales[169]}; // 0x2F09
inline constexpr od::descriptor pressure_cmd_ai1{entries[170], infos[170], scales[170]}; // 0x2F0B
inline constexpr od::descriptor press_loop_cmd{entries[171], infos[171], scales[171]}; // 0x2F0E
inline constexpr od::descriptor pressure_fb_1_ai2{entries[172], infos[172], scales[172]}; // 0x2F0F
inline constexpr od::descriptor pressure_fb_2_ai4{entries[173], infos[173], scales[173]}; // 0x2F10
inline constexpr od::descriptor pressure_fb{entries[174], infos[174], scales[174]}; // 0x2F11
inline constexpr od::descriptor pressure_error{entries[175], infos[175], scales[175]}; // 0x2F13
inline constexpr od::descriptor cavity_pressure_ai3{entries[176], infos[176], scales[176]}; // 0x2F19
inline constexpr od::descriptor position_ai5{entries[177], infos[177], scales[177]}; // 0x2F1A
inline constexpr od::descriptor valve_output_1{entries[178], infos[178], scales[178]}; // 0x2F1F
inline constexpr od::descriptor valve_output_2{entries[179], infos[179], scales[179]}; // 0x2F20
inline constexpr od::descriptor valve_output_3{entries[180], infos[180], scales[180]}; // 0x2F21
inline constexpr od::descriptor program_block{entries[181], infos[181], scales[181]}; // 0x2F25
inline constexpr od::descriptor discrete_outputs{entries[182], infos[182], scales[182]}; // 0x2F26
inline constexpr od::descriptor discrete_inputs{entries[183], infos[183], scales[183]}; // 0x2F27
inline constexpr od::descriptor output_mode{entries[184], infos[184], scales[184]}; // 0x2F28
inline constexpr od::descriptor program_status{entries[185], infos[185], scales[185]}; // 0x2F34
inline constexpr od::descriptor injection_offset{entries[186], infos[186], scales[186]}; // 0x2F6D
inline constexpr od::descriptor pos_max_length{entries[187], infos[187], scales[187]}; // 0x2F72
inline constexpr od::descriptor pres_max_inject{entries[188], infos[188], scales[188]}; // 0x2F78
inline constexpr od::descriptor jog_mode_offset{entries[189], infos[189], scales[189]}; // 0x2F7F
inline constexpr od::descriptor jog_mode_scale{entries[190], infos[190], scales[190]}; // 0x2F80
inline constexpr od::descriptor jog_mode_limit_minus{entries[191], infos[191], scales[191]}; // 0x2F81
inline constexpr od::descriptor jog_mode_limit_plus{entries[192], infos[192], scales[192]}; // 0x2F82
inline constexpr od::descriptor out2_jog_limit_minus{entries[193], infos[193], scales[193]}; // 0x2F87
inline constexpr od::descriptor pah_backpres_offset{entries[194], infos[194], scales[194]}; // 0x2F91
inline constexpr od::descriptor pah_backpres_scale{entries[195], infos[195], scales[195]}; // 0x2F92
inline constexpr od::descriptor pah_backpres_limit_minus{entries[196], infos[196], scales[196]}; // 0x2F93
inline constexpr od::descriptor pah_backpres_limit_plus{entries[197], infos[197], scales[197]}; // 0x2F94
inline constexpr od::descriptor out2_backpress_lim_minus{entries[198], infos[198], scales[198]}; // 0x2F99
inline constexpr od::descriptor decompres_offset{entries[199], infos[199], scales[199]}; // 0x2FA3
inline constexpr od::descriptor decompres_scale{entries[200], infos[200], scales[200]}; // 0x2FA4
inline constexpr od::descriptor decompres_limit_minus{entries[201], infos[201], scales[201]}; // 0x2FA5
inline constexpr od::descriptor decompres_limit_plus{entries[202], infos[202], scales[202]}; // 0x2FA6
inline constexpr od::descriptor out2_decomp_limit_minus{entries[203], infos[203], scales[203]}; // 0x2FAB
inline constexpr od::descriptor cyl_area_ratio{entries[204], infos[204], scales[204]}; // 0x3116
inline constexpr od::descriptor hist_time_1{entries[205], infos[205], scales[205]}; // 0x3501
inline constexpr od::descriptor hist_time_3{entries[206], infos[206], scales[206]}; // 0x3503
inline constexpr od::descriptor hist_time_4{entries[207], infos[207], scales[207]}; // 0x3504
inline constexpr od::descriptor hist_time_5{entries[208], infos[208], scales[208]}; // 0x3505
inline constexpr od::descriptor hist_time_6{entries[209], infos[209], scales[209]}; // 0x3506
inline constexpr od::descriptor hist_time_13{entries[210], infos[210], scales[210]}; // 0x350E
inline constexpr od::descriptor hist_time_14{entries[211], infos[211], scales[211]}; // 0x350F
inline constexpr od::descriptor hist_time_15{entries[212], infos[212], scales[212]}; // 0x3510
inline constexpr od::descriptor hist_time_16{entries[213], infos[213], scales[213]}; // 0x3511
inline constexpr od::descriptor hist_time_17{entries[214], infos[214], scales[214]}; // 0x3512
inline constexpr od::descriptor hist_time_23{entries[215], infos[215], scales[215]}; // 0x3518
inline constexpr od::descriptor hist_time_26{entries[216], infos[216], scales[216]}; // 0x351B
inline constexpr od::descriptor hist_time_27{entries[217], infos[217], scales[217]}; // 0x351C
inline constexpr od::descriptor hist_time_28{entries[218], infos[218], scales[218]}; // 0x351D
inline constexpr od::descriptor hist_time_29{entries[219], infos[219], scales[219]}; // 0x351E
inline constexpr od::descriptor hist_time_30{entries[220], infos[220], scales[220]}; // 0x351F
inline constexpr od::descriptor hist_pres_cmd_13{entries[221], infos[221], scales[221]}; // 0x3571
inline constexpr od::descriptor hist_pos_fb_1{entries[222], infos[222], scales[222]}; // 0x3601
inline constexpr od::descriptor hist_pos_fb_2{entries[223], infos[223], scales[223]}; // 0x3602
inline constexpr od::descriptor hist_pos_fb_3{entries[224], infos[224], scales[224]}; // 0x3603
inline constexpr od::descriptor hist_pos_fb_4{entries[225], infos[225], scales[225]}; // 0x3604
inline constexpr od::descriptor hist_pos_fb_5{entries[226], infos[226], scales[226]}; // 0x3605
inline constexpr od::descriptor hist_pos_fb_6{entries[227], infos[227], scales[227]}; // 0x3606
inline constexpr od::descriptor hist_pos_fb_13{entries[228], infos[228], scales[228]}; // 0x360D
inline constexpr od::descriptor hist_pos_fb_14{entries[229], infos[229], scales[229]}; // 0x360E
inline constexpr od::descriptor hist_pos_fb_15{entries[230], infos[230], scales[230]}; // 0x360F
inline constexpr od::descriptor hist_pos_fb_16{entries[231], infos[231], scales[231]}; // 0x3610
inline constexpr od::descriptor hist_pos_fb_17{entries[232], infos[232], scales[232]}; // 0x3611
inline constexpr od::descriptor hist_pos_fb_18{entries[233], infos[233], scales[233]}; // 0x3617
inline constexpr od::descriptor hist_pos_fb_26{entries[234], infos[234], scales[234]}; // 0x361A
inline constexpr od::descriptor hist_pos_fb_27{entries[235], infos[235], scales[235]}; // 0x361B
inline constexpr od::descriptor hist_pos_fb_28{entries[236], infos[236], scales[236]}; // 0x361C
inline constexpr od::descriptor hist_pos_fb_29{entries[237], infos[237], scales[237]}; // 0x361D
inline constexpr od::descriptor hist_pos_fb_30{entries[238], infos[238], scales[238]}; // 0x361E
inline constexpr od::descriptor hist_pres_fb_13{entries[239], infos[239], scales[239]}; // 0x362E

// ARRAY and RECORD objects: views into the tables.
inline constexpr od::object error_history{0x1003, od::object_code::array, "Error History"sv, dictionary.entries().subspan(1, 5), dictionary.infos().subspan(1, 5), dictionary.scales().subspan(1, 5)};
inline constexpr od::descriptor error_history_sub0{entries[1], infos[1], scales[1]}; // 0x1003 sub 0
inline constexpr od::descriptor error_code_1{entries[2], infos[2], scales[2]}; // 0x1003 sub 1
inline constexpr od::descriptor error_code_2{entries[3], infos[3], scales[3]}; // 0x1003 sub 2
inline constexpr od::descriptor error_code_3{entries[4], infos[4], scales[4]}; // 0x1003 sub 3
inline constexpr od::descriptor error_code_4{entries[5], infos[5], scales[5]}; // 0x1003 sub 4
inline constexpr od::object consumer_heartbeat_time{0x1016, od::object_code::array, "Consumer Heartbeat Time"sv, dictionary.entries().subspan(8, 2), dictionary.infos().subspan(8, 2), dictionary.scales().subspan(8, 2)};
inline constexpr od::descriptor consumer_heartbeat_time_sub0{entries[8], infos[8], scales[8]}; // 0x1016 sub 0
inline constexpr od::descriptor consumer_heartbeat_time_interval{entries[9], infos[9], scales[9]}; // 0x1016 sub 1
inline constexpr od::object tx_pdo1{0x1800, od::object_code::record, "Tx-PDO1 Communication Parameter"sv, dictionary.entries().subspan(11, 2), dictionary.infos().subspan(11, 2), dictionary.scales().subspan(11, 2)};
inline constexpr od::descriptor tx_pdo1_sub0{entries[11], infos[11], scales[11]}; // 0x1800 sub 0
inline constexpr od::descriptor tx_pdo1_event_timer{entries[12], infos[12], scales[12]}; // 0x1800 sub 5
inline constexpr od::object tx_pdo2{0x1801, od::object_code::record, "Tx-PDO2 Communication Parameter"sv, dictionary.entries().subspan(13, 2), dictionary.infos().subspan(13, 2), dictionary.scales().subspan(13, 2)};
inline constexpr od::descriptor tx_pdo2_sub0{entries[13], infos[13], scales[13]}; // 0x1801 sub 0
inline constexpr od::descriptor tx_pdo2_event_timer{entries[14], infos[14], scales[14]}; // 0x1801 sub 5
inline constexpr od::object tx_pdo3{0x1802, od::object_code::record, "Tx-PDO3 Communication Parameter"sv, dictionary.entries().subspan(15, 2), dictionary.infos().subspan(15, 2), dictionary.scales().subspan(15, 2)};
inline constexpr od::descriptor tx_pdo3_sub0{entries[15], infos[15], scales[15]}; // 0x1802 sub 0
inline constexpr od::descriptor tx_pdo3_event_timer{entries[16], infos[16], scales[16]}; // 0x1802 sub 5
inline constexpr od::object tx_pdo4{0x1803, od::object_code::record, "Tx-PDO4 Communication Parameter"sv, dictionary.entries().subspan(17, 2), dictionary.infos().subspan(17, 2), dictionary.scales().subspan(17, 2)};
inline constexpr od::descriptor tx_pdo4_sub0{entries[17], infos[17], scales[17]}; // 0x1803 sub 0
inline constexpr od::descriptor tx_pdo4_event_timer{entries[18], infos[18], scales[18]}; // 0x1803 sub 5

} // namespace fieldcodec::dictionaries::dpq_parameters
// clang-format on
