// Generated from io_node.eds by fieldcodec-gen — do not edit.
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

namespace fieldcodec::dictionaries::io_node {

using namespace std::string_view_literals;

inline constexpr const char *source_file = "io_node.eds";

inline constexpr std::array<od::entry, 164> entries{{
    {.index = 0x1000, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(983441U)},
    {.index = 0x1001, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1003, .object = od::object_code::array, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1003, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1003, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1003, .sub = 3, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1003, .sub = 4, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1005, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(128U)},
    {.index = 0x1007, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1008, .type = od::data_type::visible_string, .access_type = od::access::constant, .size = 13, .default_text = {"fieldcodec IO", 13}},
    {.index = 0x100C, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x100D, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1014, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(128U)},
    {.index = 0x1015, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1016, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(1U)},
    {.index = 0x1016, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1017, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1018, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(4U)},
    {.index = 0x1018, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1018, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1018, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1018, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1019, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1200, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(2U)},
    {.index = 0x1200, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(1536U)},
    {.index = 0x1200, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(1408U)},
    {.index = 0x1400, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1400, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(512U)},
    {.index = 0x1400, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1400, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1400, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1400, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1401, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1401, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(768U)},
    {.index = 0x1401, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1401, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1401, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1401, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1402, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1402, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1402, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1402, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1402, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1402, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1403, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1403, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1403, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1403, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1403, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1403, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1600, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1600, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1644167432U)},
    {.index = 0x1600, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1644167688U)},
    {.index = 0x1600, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1600, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1600, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1600, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1600, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1600, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1601, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1601, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1678835984U)},
    {.index = 0x1601, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1678836240U)},
    {.index = 0x1601, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1601, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1601, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1601, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1601, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1601, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1602, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1602, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1602, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1602, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1602, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1602, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1602, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1602, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1602, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1603, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1603, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1603, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1603, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1603, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1603, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1603, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1603, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1603, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1800, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(6U)},
    {.index = 0x1800, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(384U)},
    {.index = 0x1800, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1800, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1800, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1800, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1800, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1801, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(6U)},
    {.index = 0x1801, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(640U)},
    {.index = 0x1801, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1801, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1801, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1801, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1801, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1802, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(6U)},
    {.index = 0x1802, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1802, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1802, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1802, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1802, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1802, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1803, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(6U)},
    {.index = 0x1803, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1803, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1803, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1803, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1803, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1803, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A00, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1A00, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1610613000U)},
    {.index = 0x1A00, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1610613256U)},
    {.index = 0x1A00, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A00, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A00, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A00, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A00, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A00, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A01, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(4U)},
    {.index = 0x1A01, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1677787408U)},
    {.index = 0x1A01, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1677787664U)},
    {.index = 0x1A01, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1677787920U)},
    {.index = 0x1A01, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1677788176U)},
    {.index = 0x1A01, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A01, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A01, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A01, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A02, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A02, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A02, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A02, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A02, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A02, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A02, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A02, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A02, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A03, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A03, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A03, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A03, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A03, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A03, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A03, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A03, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A03, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(0U)},
    {.index = 0x6000, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(2U)},
    {.index = 0x6000, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .default_value = od::unsigned_number(0U)},
    {.index = 0x6000, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .default_value = od::unsigned_number(0U)},
    {.index = 0x6200, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(2U)},
    {.index = 0x6200, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned8, .pdo = od::pdo_mapping::yes, .default_value = od::unsigned_number(0U)},
    {.index = 0x6200, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned8, .pdo = od::pdo_mapping::yes, .default_value = od::unsigned_number(0U)},
    {.index = 0x6401, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(4U)},
    {.index = 0x6401, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .default_value = od::signed_number(0)},
    {.index = 0x6401, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .default_value = od::signed_number(0)},
    {.index = 0x6401, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .default_value = od::signed_number(0)},
    {.index = 0x6401, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .default_value = od::signed_number(0)},
    {.index = 0x6411, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(2U)},
    {.index = 0x6411, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer16, .pdo = od::pdo_mapping::yes, .default_value = od::signed_number(0)},
    {.index = 0x6411, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer16, .pdo = od::pdo_mapping::yes, .default_value = od::signed_number(0)},
}};

inline constexpr std::array<od::entry_info, 164> infos{{
    {.name = {"Device type", 11}},
    {.name = {"Error register", 14}},
    {.name = {"Number of errors", 16}},
    {.name = {"Standard error field 1", 22}},
    {.name = {"Standard error field 2", 22}},
    {.name = {"Standard error field 3", 22}},
    {.name = {"Standard error field 4", 22}},
    {.name = {"COB-ID SYNC", 11}},
    {.name = {"Synchronous window length", 25}},
    {.name = {"Manufacturer device name", 24}},
    {.name = {"Guard time", 10}},
    {.name = {"Life time factor", 16}},
    {.name = {"COB-ID EMCY", 11}},
    {.name = {"Inhibit time EMCY", 17}},
    {.name = {"Number of entries", 17}},
    {.name = {"Consumer heartbeat time 1", 25}},
    {.name = {"Producer heartbeat time", 23}},
    {.name = {"Number of entries", 17}},
    {.name = {"Vendor-ID", 9}},
    {.name = {"Product code", 12}},
    {.name = {"Revision number", 15}},
    {.name = {"Serial number", 13}},
    {.name = {"Synchronous counter overflow value", 34}},
    {.name = {"Highest sub-index supported", 27}},
    {.name = {"COB-ID client to server", 23}},
    {.name = {"COB-ID server to client", 23}},
    {.name = {"Highest sub-index supported", 27}},
    {.name = {"COB-ID used by RPDO", 19}},
    {.name = {"Transmission type", 17}},
    {.name = {"Inhibit time", 12}},
    {.name = {"Compatibility entry", 19}},
    {.name = {"Event timer", 11}},
    {.name = {"Highest sub-index supported", 27}},
    {.name = {"COB-ID used by RPDO", 19}},
    {.name = {"Transmission type", 17}},
    {.name = {"Inhibit time", 12}},
    {.name = {"Compatibility entry", 19}},
    {.name = {"Event timer", 11}},
    {.name = {"Highest sub-index supported", 27}},
    {.name = {"COB-ID used by RPDO", 19}},
    {.name = {"Transmission type", 17}},
    {.name = {"Inhibit time", 12}},
    {.name = {"Compatibility entry", 19}},
    {.name = {"Event timer", 11}},
    {.name = {"Highest sub-index supported", 27}},
    {.name = {"COB-ID used by RPDO", 19}},
    {.name = {"Transmission type", 17}},
    {.name = {"Inhibit time", 12}},
    {.name = {"Compatibility entry", 19}},
    {.name = {"Event timer", 11}},
    {.name = {"Number of mapped objects", 24}},
    {.name = {"Mapped object 1", 15}},
    {.name = {"Mapped object 2", 15}},
    {.name = {"Mapped object 3", 15}},
    {.name = {"Mapped object 4", 15}},
    {.name = {"Mapped object 5", 15}},
    {.name = {"Mapped object 6", 15}},
    {.name = {"Mapped object 7", 15}},
    {.name = {"Mapped object 8", 15}},
    {.name = {"Number of mapped objects", 24}},
    {.name = {"Mapped object 1", 15}},
    {.name = {"Mapped object 2", 15}},
    {.name = {"Mapped object 3", 15}},
    {.name = {"Mapped object 4", 15}},
    {.name = {"Mapped object 5", 15}},
    {.name = {"Mapped object 6", 15}},
    {.name = {"Mapped object 7", 15}},
    {.name = {"Mapped object 8", 15}},
    {.name = {"Number of mapped objects", 24}},
    {.name = {"Mapped object 1", 15}},
    {.name = {"Mapped object 2", 15}},
    {.name = {"Mapped object 3", 15}},
    {.name = {"Mapped object 4", 15}},
    {.name = {"Mapped object 5", 15}},
    {.name = {"Mapped object 6", 15}},
    {.name = {"Mapped object 7", 15}},
    {.name = {"Mapped object 8", 15}},
    {.name = {"Number of mapped objects", 24}},
    {.name = {"Mapped object 1", 15}},
    {.name = {"Mapped object 2", 15}},
    {.name = {"Mapped object 3", 15}},
    {.name = {"Mapped object 4", 15}},
    {.name = {"Mapped object 5", 15}},
    {.name = {"Mapped object 6", 15}},
    {.name = {"Mapped object 7", 15}},
    {.name = {"Mapped object 8", 15}},
    {.name = {"Highest sub-index supported", 27}},
    {.name = {"COB-ID used by TPDO", 19}},
    {.name = {"Transmission type", 17}},
    {.name = {"Inhibit time", 12}},
    {.name = {"Reserved", 8}},
    {.name = {"Event timer", 11}},
    {.name = {"SYNC start value", 16}},
    {.name = {"Highest sub-index supported", 27}},
    {.name = {"COB-ID used by TPDO", 19}},
    {.name = {"Transmission type", 17}},
    {.name = {"Inhibit time", 12}},
    {.name = {"Reserved", 8}},
    {.name = {"Event timer", 11}},
    {.name = {"SYNC start value", 16}},
    {.name = {"Highest sub-index supported", 27}},
    {.name = {"COB-ID used by TPDO", 19}},
    {.name = {"Transmission type", 17}},
    {.name = {"Inhibit time", 12}},
    {.name = {"Reserved", 8}},
    {.name = {"Event timer", 11}},
    {.name = {"SYNC start value", 16}},
    {.name = {"Highest sub-index supported", 27}},
    {.name = {"COB-ID used by TPDO", 19}},
    {.name = {"Transmission type", 17}},
    {.name = {"Inhibit time", 12}},
    {.name = {"Reserved", 8}},
    {.name = {"Event timer", 11}},
    {.name = {"SYNC start value", 16}},
    {.name = {"Number of mapped objects", 24}},
    {.name = {"Mapped object 1", 15}},
    {.name = {"Mapped object 2", 15}},
    {.name = {"Mapped object 3", 15}},
    {.name = {"Mapped object 4", 15}},
    {.name = {"Mapped object 5", 15}},
    {.name = {"Mapped object 6", 15}},
    {.name = {"Mapped object 7", 15}},
    {.name = {"Mapped object 8", 15}},
    {.name = {"Number of mapped objects", 24}},
    {.name = {"Mapped object 1", 15}},
    {.name = {"Mapped object 2", 15}},
    {.name = {"Mapped object 3", 15}},
    {.name = {"Mapped object 4", 15}},
    {.name = {"Mapped object 5", 15}},
    {.name = {"Mapped object 6", 15}},
    {.name = {"Mapped object 7", 15}},
    {.name = {"Mapped object 8", 15}},
    {.name = {"Number of mapped objects", 24}},
    {.name = {"Mapped object 1", 15}},
    {.name = {"Mapped object 2", 15}},
    {.name = {"Mapped object 3", 15}},
    {.name = {"Mapped object 4", 15}},
    {.name = {"Mapped object 5", 15}},
    {.name = {"Mapped object 6", 15}},
    {.name = {"Mapped object 7", 15}},
    {.name = {"Mapped object 8", 15}},
    {.name = {"Number of mapped objects", 24}},
    {.name = {"Mapped object 1", 15}},
    {.name = {"Mapped object 2", 15}},
    {.name = {"Mapped object 3", 15}},
    {.name = {"Mapped object 4", 15}},
    {.name = {"Mapped object 5", 15}},
    {.name = {"Mapped object 6", 15}},
    {.name = {"Mapped object 7", 15}},
    {.name = {"Mapped object 8", 15}},
    {.name = {"Number of input 8-bit", 21}},
    {.name = {"Read input 1h to 8h", 19}},
    {.name = {"Read input 9h to 10h", 20}},
    {.name = {"Number of output 8-bit", 22}},
    {.name = {"Write output 1h to 8h", 21}},
    {.name = {"Write output 9h to 10h", 22}},
    {.name = {"Number of analog input 16-bit", 29}},
    {.name = {"Analog input 1", 14}},
    {.name = {"Analog input 2", 14}},
    {.name = {"Analog input 3", 14}},
    {.name = {"Analog input 4", 14}},
    {.name = {"Number of analog output 16-bit", 30}},
    {.name = {"Analog output 1", 15}},
    {.name = {"Analog output 2", 15}},
}};

inline constexpr od::dictionary dictionary{entries, infos};
static_assert(dictionary.is_valid());

// VAR objects: standalone descriptors (firmware that names one keeps only that one).
inline constexpr od::descriptor device_type{entries[0], infos[0]}; // 0x1000
inline constexpr od::descriptor error_register{entries[1], infos[1]}; // 0x1001
inline constexpr od::descriptor cob_id_sync{entries[7], infos[7]}; // 0x1005
inline constexpr od::descriptor synchronous_window_length{entries[8], infos[8]}; // 0x1007
inline constexpr od::descriptor manufacturer_device_name{entries[9], infos[9]}; // 0x1008
inline constexpr od::descriptor guard_time{entries[10], infos[10]}; // 0x100C
inline constexpr od::descriptor life_time_factor{entries[11], infos[11]}; // 0x100D
inline constexpr od::descriptor cob_id_emcy{entries[12], infos[12]}; // 0x1014
inline constexpr od::descriptor inhibit_time_emcy{entries[13], infos[13]}; // 0x1015
inline constexpr od::descriptor producer_heartbeat_time{entries[16], infos[16]}; // 0x1017
inline constexpr od::descriptor synchronous_counter_overflow_value{entries[22], infos[22]}; // 0x1019

// ARRAY and RECORD objects: views into the tables.
inline constexpr od::object pre_defined_error_field{0x1003, od::object_code::array, "Pre-defined error field"sv, dictionary.entries().subspan(2, 5), dictionary.infos().subspan(2, 5)};
inline constexpr od::object consumer_heartbeat_time{0x1016, od::object_code::array, "Consumer heartbeat time"sv, dictionary.entries().subspan(14, 2), dictionary.infos().subspan(14, 2)};
inline constexpr od::object identity_object{0x1018, od::object_code::record, "Identity object"sv, dictionary.entries().subspan(17, 5), dictionary.infos().subspan(17, 5)};
inline constexpr od::descriptor identity_object_number_of_entries{entries[17], infos[17]}; // 0x1018 sub 0
inline constexpr od::descriptor identity_object_vendor_id{entries[18], infos[18]}; // 0x1018 sub 1
inline constexpr od::descriptor identity_object_product_code{entries[19], infos[19]}; // 0x1018 sub 2
inline constexpr od::descriptor identity_object_revision_number{entries[20], infos[20]}; // 0x1018 sub 3
inline constexpr od::descriptor identity_object_serial_number{entries[21], infos[21]}; // 0x1018 sub 4
inline constexpr od::object sdo_server_parameter{0x1200, od::object_code::record, "SDO server parameter"sv, dictionary.entries().subspan(23, 3), dictionary.infos().subspan(23, 3)};
inline constexpr od::descriptor sdo_server_parameter_highest_sub_index_supported{entries[23], infos[23]}; // 0x1200 sub 0
inline constexpr od::descriptor sdo_server_parameter_cob_id_client_to_server{entries[24], infos[24]}; // 0x1200 sub 1
inline constexpr od::descriptor sdo_server_parameter_cob_id_server_to_client{entries[25], infos[25]}; // 0x1200 sub 2
inline constexpr od::object rpdo_communication_parameter_1{0x1400, od::object_code::record, "RPDO communication parameter 1"sv, dictionary.entries().subspan(26, 6), dictionary.infos().subspan(26, 6)};
inline constexpr od::descriptor rpdo_communication_parameter_1_highest_sub_index_supported{entries[26], infos[26]}; // 0x1400 sub 0
inline constexpr od::descriptor rpdo_communication_parameter_1_cob_id_used_by_rpdo{entries[27], infos[27]}; // 0x1400 sub 1
inline constexpr od::descriptor rpdo_communication_parameter_1_transmission_type{entries[28], infos[28]}; // 0x1400 sub 2
inline constexpr od::descriptor rpdo_communication_parameter_1_inhibit_time{entries[29], infos[29]}; // 0x1400 sub 3
inline constexpr od::descriptor rpdo_communication_parameter_1_compatibility_entry{entries[30], infos[30]}; // 0x1400 sub 4
inline constexpr od::descriptor rpdo_communication_parameter_1_event_timer{entries[31], infos[31]}; // 0x1400 sub 5
inline constexpr od::object rpdo_communication_parameter_2{0x1401, od::object_code::record, "RPDO communication parameter 2"sv, dictionary.entries().subspan(32, 6), dictionary.infos().subspan(32, 6)};
inline constexpr od::descriptor rpdo_communication_parameter_2_highest_sub_index_supported{entries[32], infos[32]}; // 0x1401 sub 0
inline constexpr od::descriptor rpdo_communication_parameter_2_cob_id_used_by_rpdo{entries[33], infos[33]}; // 0x1401 sub 1
inline constexpr od::descriptor rpdo_communication_parameter_2_transmission_type{entries[34], infos[34]}; // 0x1401 sub 2
inline constexpr od::descriptor rpdo_communication_parameter_2_inhibit_time{entries[35], infos[35]}; // 0x1401 sub 3
inline constexpr od::descriptor rpdo_communication_parameter_2_compatibility_entry{entries[36], infos[36]}; // 0x1401 sub 4
inline constexpr od::descriptor rpdo_communication_parameter_2_event_timer{entries[37], infos[37]}; // 0x1401 sub 5
inline constexpr od::object rpdo_communication_parameter_3{0x1402, od::object_code::record, "RPDO communication parameter 3"sv, dictionary.entries().subspan(38, 6), dictionary.infos().subspan(38, 6)};
inline constexpr od::descriptor rpdo_communication_parameter_3_highest_sub_index_supported{entries[38], infos[38]}; // 0x1402 sub 0
inline constexpr od::descriptor rpdo_communication_parameter_3_cob_id_used_by_rpdo{entries[39], infos[39]}; // 0x1402 sub 1
inline constexpr od::descriptor rpdo_communication_parameter_3_transmission_type{entries[40], infos[40]}; // 0x1402 sub 2
inline constexpr od::descriptor rpdo_communication_parameter_3_inhibit_time{entries[41], infos[41]}; // 0x1402 sub 3
inline constexpr od::descriptor rpdo_communication_parameter_3_compatibility_entry{entries[42], infos[42]}; // 0x1402 sub 4
inline constexpr od::descriptor rpdo_communication_parameter_3_event_timer{entries[43], infos[43]}; // 0x1402 sub 5
inline constexpr od::object rpdo_communication_parameter_4{0x1403, od::object_code::record, "RPDO communication parameter 4"sv, dictionary.entries().subspan(44, 6), dictionary.infos().subspan(44, 6)};
inline constexpr od::descriptor rpdo_communication_parameter_4_highest_sub_index_supported{entries[44], infos[44]}; // 0x1403 sub 0
inline constexpr od::descriptor rpdo_communication_parameter_4_cob_id_used_by_rpdo{entries[45], infos[45]}; // 0x1403 sub 1
inline constexpr od::descriptor rpdo_communication_parameter_4_transmission_type{entries[46], infos[46]}; // 0x1403 sub 2
inline constexpr od::descriptor rpdo_communication_parameter_4_inhibit_time{entries[47], infos[47]}; // 0x1403 sub 3
inline constexpr od::descriptor rpdo_communication_parameter_4_compatibility_entry{entries[48], infos[48]}; // 0x1403 sub 4
inline constexpr od::descriptor rpdo_communication_parameter_4_event_timer{entries[49], infos[49]}; // 0x1403 sub 5
inline constexpr od::object rpdo_mapping_parameter_1{0x1600, od::object_code::record, "RPDO mapping parameter 1"sv, dictionary.entries().subspan(50, 9), dictionary.infos().subspan(50, 9)};
inline constexpr od::descriptor rpdo_mapping_parameter_1_number_of_mapped_objects{entries[50], infos[50]}; // 0x1600 sub 0
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_1{entries[51], infos[51]}; // 0x1600 sub 1
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_2{entries[52], infos[52]}; // 0x1600 sub 2
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_3{entries[53], infos[53]}; // 0x1600 sub 3
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_4{entries[54], infos[54]}; // 0x1600 sub 4
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_5{entries[55], infos[55]}; // 0x1600 sub 5
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_6{entries[56], infos[56]}; // 0x1600 sub 6
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_7{entries[57], infos[57]}; // 0x1600 sub 7
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_8{entries[58], infos[58]}; // 0x1600 sub 8
inline constexpr od::object rpdo_mapping_parameter_2{0x1601, od::object_code::record, "RPDO mapping parameter 2"sv, dictionary.entries().subspan(59, 9), dictionary.infos().subspan(59, 9)};
inline constexpr od::descriptor rpdo_mapping_parameter_2_number_of_mapped_objects{entries[59], infos[59]}; // 0x1601 sub 0
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_1{entries[60], infos[60]}; // 0x1601 sub 1
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_2{entries[61], infos[61]}; // 0x1601 sub 2
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_3{entries[62], infos[62]}; // 0x1601 sub 3
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_4{entries[63], infos[63]}; // 0x1601 sub 4
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_5{entries[64], infos[64]}; // 0x1601 sub 5
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_6{entries[65], infos[65]}; // 0x1601 sub 6
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_7{entries[66], infos[66]}; // 0x1601 sub 7
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_8{entries[67], infos[67]}; // 0x1601 sub 8
inline constexpr od::object rpdo_mapping_parameter_3{0x1602, od::object_code::record, "RPDO mapping parameter 3"sv, dictionary.entries().subspan(68, 9), dictionary.infos().subspan(68, 9)};
inline constexpr od::descriptor rpdo_mapping_parameter_3_number_of_mapped_objects{entries[68], infos[68]}; // 0x1602 sub 0
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_1{entries[69], infos[69]}; // 0x1602 sub 1
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_2{entries[70], infos[70]}; // 0x1602 sub 2
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_3{entries[71], infos[71]}; // 0x1602 sub 3
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_4{entries[72], infos[72]}; // 0x1602 sub 4
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_5{entries[73], infos[73]}; // 0x1602 sub 5
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_6{entries[74], infos[74]}; // 0x1602 sub 6
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_7{entries[75], infos[75]}; // 0x1602 sub 7
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_8{entries[76], infos[76]}; // 0x1602 sub 8
inline constexpr od::object rpdo_mapping_parameter_4{0x1603, od::object_code::record, "RPDO mapping parameter 4"sv, dictionary.entries().subspan(77, 9), dictionary.infos().subspan(77, 9)};
inline constexpr od::descriptor rpdo_mapping_parameter_4_number_of_mapped_objects{entries[77], infos[77]}; // 0x1603 sub 0
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_1{entries[78], infos[78]}; // 0x1603 sub 1
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_2{entries[79], infos[79]}; // 0x1603 sub 2
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_3{entries[80], infos[80]}; // 0x1603 sub 3
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_4{entries[81], infos[81]}; // 0x1603 sub 4
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_5{entries[82], infos[82]}; // 0x1603 sub 5
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_6{entries[83], infos[83]}; // 0x1603 sub 6
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_7{entries[84], infos[84]}; // 0x1603 sub 7
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_8{entries[85], infos[85]}; // 0x1603 sub 8
inline constexpr od::object tpdo_communication_parameter_1{0x1800, od::object_code::record, "TPDO communication parameter 1"sv, dictionary.entries().subspan(86, 7), dictionary.infos().subspan(86, 7)};
inline constexpr od::descriptor tpdo_communication_parameter_1_highest_sub_index_supported{entries[86], infos[86]}; // 0x1800 sub 0
inline constexpr od::descriptor tpdo_communication_parameter_1_cob_id_used_by_tpdo{entries[87], infos[87]}; // 0x1800 sub 1
inline constexpr od::descriptor tpdo_communication_parameter_1_transmission_type{entries[88], infos[88]}; // 0x1800 sub 2
inline constexpr od::descriptor tpdo_communication_parameter_1_inhibit_time{entries[89], infos[89]}; // 0x1800 sub 3
inline constexpr od::descriptor tpdo_communication_parameter_1_reserved{entries[90], infos[90]}; // 0x1800 sub 4
inline constexpr od::descriptor tpdo_communication_parameter_1_event_timer{entries[91], infos[91]}; // 0x1800 sub 5
inline constexpr od::descriptor tpdo_communication_parameter_1_sync_start_value{entries[92], infos[92]}; // 0x1800 sub 6
inline constexpr od::object tpdo_communication_parameter_2{0x1801, od::object_code::record, "TPDO communication parameter 2"sv, dictionary.entries().subspan(93, 7), dictionary.infos().subspan(93, 7)};
inline constexpr od::descriptor tpdo_communication_parameter_2_highest_sub_index_supported{entries[93], infos[93]}; // 0x1801 sub 0
inline constexpr od::descriptor tpdo_communication_parameter_2_cob_id_used_by_tpdo{entries[94], infos[94]}; // 0x1801 sub 1
inline constexpr od::descriptor tpdo_communication_parameter_2_transmission_type{entries[95], infos[95]}; // 0x1801 sub 2
inline constexpr od::descriptor tpdo_communication_parameter_2_inhibit_time{entries[96], infos[96]}; // 0x1801 sub 3
inline constexpr od::descriptor tpdo_communication_parameter_2_reserved{entries[97], infos[97]}; // 0x1801 sub 4
inline constexpr od::descriptor tpdo_communication_parameter_2_event_timer{entries[98], infos[98]}; // 0x1801 sub 5
inline constexpr od::descriptor tpdo_communication_parameter_2_sync_start_value{entries[99], infos[99]}; // 0x1801 sub 6
inline constexpr od::object tpdo_communication_parameter_3{0x1802, od::object_code::record, "TPDO communication parameter 3"sv, dictionary.entries().subspan(100, 7), dictionary.infos().subspan(100, 7)};
inline constexpr od::descriptor tpdo_communication_parameter_3_highest_sub_index_supported{entries[100], infos[100]}; // 0x1802 sub 0
inline constexpr od::descriptor tpdo_communication_parameter_3_cob_id_used_by_tpdo{entries[101], infos[101]}; // 0x1802 sub 1
inline constexpr od::descriptor tpdo_communication_parameter_3_transmission_type{entries[102], infos[102]}; // 0x1802 sub 2
inline constexpr od::descriptor tpdo_communication_parameter_3_inhibit_time{entries[103], infos[103]}; // 0x1802 sub 3
inline constexpr od::descriptor tpdo_communication_parameter_3_reserved{entries[104], infos[104]}; // 0x1802 sub 4
inline constexpr od::descriptor tpdo_communication_parameter_3_event_timer{entries[105], infos[105]}; // 0x1802 sub 5
inline constexpr od::descriptor tpdo_communication_parameter_3_sync_start_value{entries[106], infos[106]}; // 0x1802 sub 6
inline constexpr od::object tpdo_communication_parameter_4{0x1803, od::object_code::record, "TPDO communication parameter 4"sv, dictionary.entries().subspan(107, 7), dictionary.infos().subspan(107, 7)};
inline constexpr od::descriptor tpdo_communication_parameter_4_highest_sub_index_supported{entries[107], infos[107]}; // 0x1803 sub 0
inline constexpr od::descriptor tpdo_communication_parameter_4_cob_id_used_by_tpdo{entries[108], infos[108]}; // 0x1803 sub 1
inline constexpr od::descriptor tpdo_communication_parameter_4_transmission_type{entries[109], infos[109]}; // 0x1803 sub 2
inline constexpr od::descriptor tpdo_communication_parameter_4_inhibit_time{entries[110], infos[110]}; // 0x1803 sub 3
inline constexpr od::descriptor tpdo_communication_parameter_4_reserved{entries[111], infos[111]}; // 0x1803 sub 4
inline constexpr od::descriptor tpdo_communication_parameter_4_event_timer{entries[112], infos[112]}; // 0x1803 sub 5
inline constexpr od::descriptor tpdo_communication_parameter_4_sync_start_value{entries[113], infos[113]}; // 0x1803 sub 6
inline constexpr od::object tpdo_mapping_parameter_1{0x1A00, od::object_code::record, "TPDO mapping parameter 1"sv, dictionary.entries().subspan(114, 9), dictionary.infos().subspan(114, 9)};
inline constexpr od::descriptor tpdo_mapping_parameter_1_number_of_mapped_objects{entries[114], infos[114]}; // 0x1A00 sub 0
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_1{entries[115], infos[115]}; // 0x1A00 sub 1
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_2{entries[116], infos[116]}; // 0x1A00 sub 2
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_3{entries[117], infos[117]}; // 0x1A00 sub 3
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_4{entries[118], infos[118]}; // 0x1A00 sub 4
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_5{entries[119], infos[119]}; // 0x1A00 sub 5
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_6{entries[120], infos[120]}; // 0x1A00 sub 6
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_7{entries[121], infos[121]}; // 0x1A00 sub 7
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_8{entries[122], infos[122]}; // 0x1A00 sub 8
inline constexpr od::object tpdo_mapping_parameter_2{0x1A01, od::object_code::record, "TPDO mapping parameter 2"sv, dictionary.entries().subspan(123, 9), dictionary.infos().subspan(123, 9)};
inline constexpr od::descriptor tpdo_mapping_parameter_2_number_of_mapped_objects{entries[123], infos[123]}; // 0x1A01 sub 0
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_1{entries[124], infos[124]}; // 0x1A01 sub 1
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_2{entries[125], infos[125]}; // 0x1A01 sub 2
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_3{entries[126], infos[126]}; // 0x1A01 sub 3
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_4{entries[127], infos[127]}; // 0x1A01 sub 4
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_5{entries[128], infos[128]}; // 0x1A01 sub 5
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_6{entries[129], infos[129]}; // 0x1A01 sub 6
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_7{entries[130], infos[130]}; // 0x1A01 sub 7
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_8{entries[131], infos[131]}; // 0x1A01 sub 8
inline constexpr od::object tpdo_mapping_parameter_3{0x1A02, od::object_code::record, "TPDO mapping parameter 3"sv, dictionary.entries().subspan(132, 9), dictionary.infos().subspan(132, 9)};
inline constexpr od::descriptor tpdo_mapping_parameter_3_number_of_mapped_objects{entries[132], infos[132]}; // 0x1A02 sub 0
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_1{entries[133], infos[133]}; // 0x1A02 sub 1
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_2{entries[134], infos[134]}; // 0x1A02 sub 2
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_3{entries[135], infos[135]}; // 0x1A02 sub 3
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_4{entries[136], infos[136]}; // 0x1A02 sub 4
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_5{entries[137], infos[137]}; // 0x1A02 sub 5
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_6{entries[138], infos[138]}; // 0x1A02 sub 6
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_7{entries[139], infos[139]}; // 0x1A02 sub 7
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_8{entries[140], infos[140]}; // 0x1A02 sub 8
inline constexpr od::object tpdo_mapping_parameter_4{0x1A03, od::object_code::record, "TPDO mapping parameter 4"sv, dictionary.entries().subspan(141, 9), dictionary.infos().subspan(141, 9)};
inline constexpr od::descriptor tpdo_mapping_parameter_4_number_of_mapped_objects{entries[141], infos[141]}; // 0x1A03 sub 0
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_1{entries[142], infos[142]}; // 0x1A03 sub 1
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_2{entries[143], infos[143]}; // 0x1A03 sub 2
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_3{entries[144], infos[144]}; // 0x1A03 sub 3
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_4{entries[145], infos[145]}; // 0x1A03 sub 4
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_5{entries[146], infos[146]}; // 0x1A03 sub 5
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_6{entries[147], infos[147]}; // 0x1A03 sub 6
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_7{entries[148], infos[148]}; // 0x1A03 sub 7
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_8{entries[149], infos[149]}; // 0x1A03 sub 8
inline constexpr od::object read_input_8_bit{0x6000, od::object_code::array, "Read input 8-bit"sv, dictionary.entries().subspan(150, 3), dictionary.infos().subspan(150, 3)};
inline constexpr od::object write_output_8_bit{0x6200, od::object_code::array, "Write output 8-bit"sv, dictionary.entries().subspan(153, 3), dictionary.infos().subspan(153, 3)};
inline constexpr od::object read_analog_input_16_bit{0x6401, od::object_code::array, "Read analog input 16-bit"sv, dictionary.entries().subspan(156, 5), dictionary.infos().subspan(156, 5)};
inline constexpr od::object write_analog_output_16_bit{0x6411, od::object_code::array, "Write analog output 16-bit"sv, dictionary.entries().subspan(161, 3), dictionary.infos().subspan(161, 3)};

} // namespace fieldcodec::dictionaries::io_node
// clang-format on
