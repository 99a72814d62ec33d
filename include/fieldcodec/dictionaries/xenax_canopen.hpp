// Generated from xenax_canopen.eds by fieldcodec-gen — do not edit.
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

#include <array>
#include <cstdint>

namespace fieldcodec::dictionaries::xenax_canopen {

inline constexpr const char *source_file = "xenax_canopen.eds";

inline constexpr std::array<od::entry, 448> entries{{
    {.index = 0x1000, .type = od::data_type::unsigned32, .access_type = od::access::ro, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(131474U)},
    {.index = 0x1001, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(0U), .high = od::unsigned_number(255U), .default_value = od::unsigned_number(0U)},
    {.index = 0x1005, .type = od::data_type::unsigned32, .low = od::unsigned_number(1U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(2147483776U)},
    {.index = 0x1008, .type = od::data_type::visible_string, .access_type = od::access::ro, .default_text = "Servocontroller XENAX Xvi xxVx"},
    {.index = 0x1009, .type = od::data_type::visible_string, .access_type = od::access::ro, .default_text = "BUS Module HW Vxxx.xxx"},
    {.index = 0x100A, .type = od::data_type::visible_string, .access_type = od::access::ro, .default_text = "BUS Protocol SW Vxxx.xxx"},
    {.index = 0x1014, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(128U)},
    {.index = 0x1017, .type = od::data_type::unsigned32, .access_type = od::access::ro, .default_value = od::unsigned_number(0U)},
    {.index = 0x1018, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(1U), .high = od::unsigned_number(4U), .default_value = od::unsigned_number(4U)},
    {.index = 0x1018, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U)},
    {.index = 0x1018, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U)},
    {.index = 0x1018, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(65536U)},
    {.index = 0x1018, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(1U)},
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
    {.index = 0x1410, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1410, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1410, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1410, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1410, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1410, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1411, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1411, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1411, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1411, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1411, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1411, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1412, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1412, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1412, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1412, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1412, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1412, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1413, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1413, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1413, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1413, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1413, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1413, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1414, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1414, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1414, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1414, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1414, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1414, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1415, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1415, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1415, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1415, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1415, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1415, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1416, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1416, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1416, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1416, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1416, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1416, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1417, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1417, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1417, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1417, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1417, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1417, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1600, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(1U)},
    {.index = 0x1600, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1614807056U)},
    {.index = 0x1601, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1601, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1614807056U)},
    {.index = 0x1601, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1618608160U)},
    {.index = 0x1610, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(1U)},
    {.index = 0x1610, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1627259168U)},
    {.index = 0x1611, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1611, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1619197984U)},
    {.index = 0x1611, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(536870944U)},
    {.index = 0x1612, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(1U)},
    {.index = 0x1612, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1619066912U)},
    {.index = 0x1613, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1613, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1617231904U)},
    {.index = 0x1613, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1617362976U)},
    {.index = 0x1614, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(1U)},
    {.index = 0x1614, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1618149392U)},
    {.index = 0x1617, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1617, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1614807056U)},
    {.index = 0x1617, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(537002016U)},
    {.index = 0x1800, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1800, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(384U)},
    {.index = 0x1800, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1800, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1800, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1800, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1801, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1801, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid, .default_value = od::unsigned_number(640U)},
    {.index = 0x1801, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(255U)},
    {.index = 0x1801, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1801, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1801, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1810, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1810, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1810, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1810, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1810, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1810, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1811, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1811, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1811, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1811, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1811, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1811, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1812, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1812, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1812, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1812, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1812, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1812, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1813, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1813, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1813, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1813, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1813, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1813, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1814, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1814, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1814, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1814, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1814, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1814, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1815, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1815, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1815, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1815, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1815, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1815, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1816, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1816, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1816, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1816, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1816, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1816, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1817, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(5U)},
    {.index = 0x1817, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(2147483648U)},
    {.index = 0x1817, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(254U)},
    {.index = 0x1817, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1817, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(0U)},
    {.index = 0x1817, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .default_value = od::unsigned_number(0U)},
    {.index = 0x1A00, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(1U)},
    {.index = 0x1A00, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1614872592U)},
    {.index = 0x1A01, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1A01, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1614872592U)},
    {.index = 0x1A01, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1617166368U)},
    {.index = 0x1A10, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(1U)},
    {.index = 0x1A10, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1627193376U)},
    {.index = 0x1A13, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1A13, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1626603552U)},
    {.index = 0x1A13, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(537264160U)},
    {.index = 0x1A14, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(1U)},
    {.index = 0x1A14, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1618477072U)},
    {.index = 0x1A16, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1A16, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(537198624U)},
    {.index = 0x1A16, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(537264160U)},
    {.index = 0x1A17, .object = od::object_code::record, .type = od::data_type::unsigned8, .default_value = od::unsigned_number(2U)},
    {.index = 0x1A17, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(1614872592U)},
    {.index = 0x1A17, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .default_value = od::unsigned_number(537198624U)},
    {.index = 0x2000, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(1U), .high = od::unsigned_number(100U), .default_value = od::unsigned_number(20U)},
    {.index = 0x2001, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(0U)},
    {.index = 0x2002, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(0U)},
    {.index = 0x2003, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(0U)},
    {.index = 0x2004, .type = od::data_type::integer8, .access_type = od::access::ro, .low = od::signed_number(0), .high = od::signed_number(127), .default_value = od::signed_number(0)},
    {.index = 0x2005, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x2006, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x2007, .type = od::data_type::unsigned16, .low = od::unsigned_number(100U), .high = od::unsigned_number(10000U), .default_value = od::unsigned_number(1000U)},
    {.index = 0x2008, .type = od::data_type::visible_string, .access_type = od::access::ro},
    {.index = 0x2009, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x200A, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5000, .type = od::data_type::unsigned32, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(0U)},
    {.index = 0x5001, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(45U)},
    {.index = 0x5001, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 15, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 16, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 17, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 18, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 19, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 20, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 21, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 22, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 23, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 24, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 25, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 26, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 27, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 28, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 29, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 30, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 31, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 32, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 33, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 34, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 35, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 36, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 37, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 38, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 39, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 40, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 41, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 42, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 43, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 44, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5001, .sub = 45, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5002, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(16U)},
    {.index = 0x5002, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(1), .high = od::signed_number(8)},
    {.index = 0x5002, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5002, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647)},
    {.index = 0x5002, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(1), .high = od::signed_number(50)},
    {.index = 0x5002, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(1), .high = od::signed_number(63)},
    {.index = 0x5002, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(1), .high = od::signed_number(8)},
    {.index = 0x5002, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(0), .high = od::signed_number(255)},
    {.index = 0x5002, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(-2000000000), .high = od::signed_number(2000000000)},
    {.index = 0x5002, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(-2000000000), .high = od::signed_number(2000000000)},
    {.index = 0x5002, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(0), .high = od::signed_number(12)},
    {.index = 0x5002, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(0), .high = od::signed_number(12)},
    {.index = 0x5002, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(1), .high = od::signed_number(5)},
    {.index = 0x5002, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(0), .high = od::signed_number(2147483647)},
    {.index = 0x5002, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(1), .high = od::signed_number(10)},
    {.index = 0x5002, .sub = 15, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(0), .high = od::signed_number(2000)},
    {.index = 0x5002, .sub = 16, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .low = od::signed_number(1), .high = od::signed_number(16)},
    {.index = 0x5003, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(106U)},
    {.index = 0x5003, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(2000), .high = od::signed_number(1000000000), .default_value = od::signed_number(1000000)},
    {.index = 0x5003, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(100), .default_value = od::signed_number(20)},
    {.index = 0x5003, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(10), .high = od::signed_number(100000000), .default_value = od::signed_number(100000)},
    {.index = 0x5003, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2000000000), .high = od::signed_number(2000000000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2000000000), .high = od::signed_number(2000000000), .default_value = od::signed_number(20000)},
    {.index = 0x5003, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(1000000), .default_value = od::signed_number(2000)},
    {.index = 0x5003, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(5), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(10000), .default_value = od::signed_number(100)},
    {.index = 0x5003, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(10000), .high = od::signed_number(1000000000), .default_value = od::signed_number(10000000)},
    {.index = 0x5003, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(4095), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(10), .high = od::signed_number(2000)},
    {.index = 0x5003, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 15, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(13), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 16, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(100000000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 17, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(5), .high = od::signed_number(5000), .default_value = od::signed_number(1500)},
    {.index = 0x5003, .sub = 18, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(5000), .default_value = od::signed_number(50)},
    {.index = 0x5003, .sub = 19, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(10), .high = od::signed_number(2000), .default_value = od::signed_number(1200)},
    {.index = 0x5003, .sub = 20, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(50)},
    {.index = 0x5003, .sub = 21, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(2), .high = od::signed_number(1000000), .default_value = od::signed_number(1000)},
    {.index = 0x5003, .sub = 22, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(10), .high = od::signed_number(100000000), .default_value = od::signed_number(100000)},
    {.index = 0x5003, .sub = 23, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2000000000), .high = od::signed_number(2000000000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 24, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(255), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 25, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(4), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 26, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(500), .high = od::signed_number(100000), .default_value = od::signed_number(5000)},
    {.index = 0x5003, .sub = 27, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 28, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(50), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 29, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(8), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 30, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(100), .default_value = od::signed_number(100)},
    {.index = 0x5003, .sub = 31, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 32, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(255), .default_value = od::signed_number(255)},
    {.index = 0x5003, .sub = 33, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(65535), .default_value = od::signed_number(21845)},
    {.index = 0x5003, .sub = 34, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-1000), .high = od::signed_number(1000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 35, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(10000), .high = od::signed_number(1000000), .default_value = od::signed_number(500000)},
    {.index = 0x5003, .sub = 36, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(0), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 37, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 38, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 39, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2000000000), .high = od::signed_number(2000000000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 40, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2000000000), .high = od::signed_number(2000000000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 41, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2312), .high = od::signed_number(2000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 42, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2312), .high = od::signed_number(2000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 43, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 44, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 45, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2000000000), .high = od::signed_number(2000000000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 46, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(1000), .default_value = od::signed_number(100)},
    {.index = 0x5003, .sub = 47, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 48, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 49, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(2), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 50, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(10), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 51, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(65535), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 52, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(10), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 53, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(2), .high = od::signed_number(1000000), .default_value = od::signed_number(1000)},
    {.index = 0x5003, .sub = 54, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(10), .high = od::signed_number(100000000), .default_value = od::signed_number(100000)},
    {.index = 0x5003, .sub = 55, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(2000), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 56, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 57, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1023), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 58, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 59, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 60, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 61, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(0), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 62, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(2), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 63, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(3), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 64, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(500), .high = od::signed_number(100000), .default_value = od::signed_number(5000)},
    {.index = 0x5003, .sub = 65, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 66, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 67, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 68, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(2), .high = od::signed_number(1000000), .default_value = od::signed_number(1000)},
    {.index = 0x5003, .sub = 69, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(10), .high = od::signed_number(100000000), .default_value = od::signed_number(100000)},
    {.index = 0x5003, .sub = 70, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2000000000), .high = od::signed_number(2000000000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 71, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(2), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 72, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-50), .high = od::signed_number(50), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 73, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(7), .default_value = od::signed_number(3)},
    {.index = 0x5003, .sub = 74, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 75, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 76, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(50), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 77, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 78, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 79, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2000), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 80, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(50), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 81, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(8), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 82, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(13), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 83, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(8), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 84, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(22), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 85, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 86, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 87, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 88, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 89, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 90, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 91, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 92, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 93, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(100), .high = od::signed_number(5000), .default_value = od::signed_number(500)},
    {.index = 0x5003, .sub = 94, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 95, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 96, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 97, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 98, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 99, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 100, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(63), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 101, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(65535), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 102, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 103, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 104, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5003, .sub = 105, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(1)},
    {.index = 0x5003, .sub = 106, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5004, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(11U)},
    {.index = 0x5004, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(100), .default_value = od::signed_number(0)},
    {.index = 0x5004, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(10), .high = od::signed_number(10000000), .default_value = od::signed_number(24000)},
    {.index = 0x5004, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5004, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(359), .default_value = od::signed_number(0)},
    {.index = 0x5004, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(10000000)},
    {.index = 0x5004, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(100000000)},
    {.index = 0x5004, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(100000)},
    {.index = 0x5004, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(100000)},
    {.index = 0x5004, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(10000)},
    {.index = 0x5004, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(10000)},
    {.index = 0x5004, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(13U)},
    {.index = 0x5005, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5005, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5006, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(10U)},
    {.index = 0x5006, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(-1062731263)},
    {.index = 0x5006, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(-1062731164)},
    {.index = 0x5006, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(-1024)},
    {.index = 0x5006, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5006, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5006, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(65535), .default_value = od::signed_number(10001)},
    {.index = 0x5006, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5006, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(9600), .high = od::signed_number(345600), .default_value = od::signed_number(115200)},
    {.index = 0x5006, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5006, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5010, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .default_value = od::unsigned_number(14U)},
    {.index = 0x5010, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(100), .high = od::signed_number(5000), .default_value = od::signed_number(500)},
    {.index = 0x5010, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(200000), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(200000), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(25000000), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(2), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(9000000), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(0), .high = od::signed_number(1), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .low = od::signed_number(0), .high = od::signed_number(7), .default_value = od::signed_number(0)},
    {.index = 0x5010, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(1000), .default_value = od::signed_number(50)},
    {.index = 0x5010, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(1), .high = od::signed_number(10000000), .default_value = od::signed_number(1000)},
    {.index = 0x5011, .type = od::data_type::visible_string},
    {.index = 0x5012, .type = od::data_type::visible_string},
    {.index = 0x5020, .type = od::data_type::visible_string, .access_type = od::access::ro, .default_text = "no error"},
    {.index = 0x5021, .type = od::data_type::visible_string},
    {.index = 0x603F, .type = od::data_type::unsigned16, .access_type = od::access::ro, .low = od::unsigned_number(0U), .high = od::unsigned_number(65535U), .default_value = od::unsigned_number(0U)},
    {.index = 0x6040, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(0U), .high = od::unsigned_number(65535U), .default_value = od::unsigned_number(0U)},
    {.index = 0x6041, .type = od::data_type::unsigned16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(0U), .high = od::unsigned_number(65535U), .default_value = od::unsigned_number(0U)},
    {.index = 0x6060, .type = od::data_type::integer8, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2), .high = od::signed_number(10), .default_value = od::signed_number(0)},
    {.index = 0x6061, .type = od::data_type::integer8, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2), .high = od::signed_number(10), .default_value = od::signed_number(0)},
    {.index = 0x6064, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x6065, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(1U), .high = od::unsigned_number(1000000U), .default_value = od::unsigned_number(2000U)},
    {.index = 0x6067, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(1U), .high = od::unsigned_number(10000U), .default_value = od::unsigned_number(100U)},
    {.index = 0x6068, .type = od::data_type::unsigned16, .low = od::unsigned_number(0U), .high = od::unsigned_number(1000U), .default_value = od::unsigned_number(0U)},
    {.index = 0x606C, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x6073, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(0U), .high = od::unsigned_number(2000U), .default_value = od::unsigned_number(0U)},
    {.index = 0x6078, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-20000), .high = od::signed_number(20000)},
    {.index = 0x607A, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x607D, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(2U), .high = od::unsigned_number(2U), .default_value = od::unsigned_number(2U)},
    {.index = 0x607D, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x607D, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647), .default_value = od::signed_number(0)},
    {.index = 0x6081, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(10U), .high = od::unsigned_number(100000000U), .default_value = od::unsigned_number(100000U)},
    {.index = 0x6083, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(2000U), .high = od::unsigned_number(1000000000U), .default_value = od::unsigned_number(1000000U)},
    {.index = 0x6085, .type = od::data_type::unsigned32, .low = od::unsigned_number(10000U), .high = od::unsigned_number(1000000000U), .default_value = od::unsigned_number(10000000U)},
    {.index = 0x6098, .type = od::data_type::integer8, .low = od::signed_number(1), .high = od::signed_number(15), .default_value = od::signed_number(1)},
    {.index = 0x6099, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(2U), .high = od::unsigned_number(2U), .default_value = od::unsigned_number(2U)},
    {.index = 0x6099, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .low = od::unsigned_number(0U), .high = od::unsigned_number(250000U), .default_value = od::unsigned_number(1000U)},
    {.index = 0x6099, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .low = od::unsigned_number(0U), .high = od::unsigned_number(100000U), .default_value = od::unsigned_number(500U)},
    {.index = 0x60B1, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-9000000), .high = od::signed_number(9000000), .default_value = od::signed_number(0)},
    {.index = 0x60B2, .type = od::data_type::integer16, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-32768), .high = od::signed_number(32767), .default_value = od::signed_number(0)},
    {.index = 0x60C2, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(2U), .high = od::unsigned_number(2U), .default_value = od::unsigned_number(2U)},
    {.index = 0x60C2, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned8, .low = od::unsigned_number(0U), .high = od::unsigned_number(255U), .default_value = od::unsigned_number(1U)},
    {.index = 0x60C2, .sub = 2, .object = od::object_code::record, .type = od::data_type::integer8, .low = od::signed_number(-128), .high = od::signed_number(63), .default_value = od::signed_number(-3)},
    {.index = 0x60F4, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-2147483648), .high = od::signed_number(2147483647)},
    {.index = 0x60FD, .type = od::data_type::unsigned32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(0U)},
    {.index = 0x60FE, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .low = od::unsigned_number(1U), .high = od::unsigned_number(2U), .default_value = od::unsigned_number(2U)},
    {.index = 0x60FE, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(0U)},
    {.index = 0x60FE, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .low = od::unsigned_number(0U), .high = od::unsigned_number(4294967295U), .default_value = od::unsigned_number(0U)},
    {.index = 0x60FF, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .low = od::signed_number(-9000000), .high = od::signed_number(9000000), .default_value = od::signed_number(0)},
    {.index = 0x6502, .type = od::data_type::unsigned32, .access_type = od::access::ro, .low = od::unsigned_number(65697U), .high = od::unsigned_number(65697U), .default_value = od::unsigned_number(65697U)},
    {.index = 0x6505, .type = od::data_type::visible_string, .access_type = od::access::ro, .default_text = "http://www.jennyscience.ch"},
}};

inline constexpr std::array<od::entry_info, 448> infos{{
    {.name = "Device Type"},
    {.name = "Error Register"},
    {.name = "COB-ID SYNC"},
    {.name = "Manufacturer Device Name"},
    {.name = "Manufacturer Hardware Version"},
    {.name = "Manufacturer Software Version"},
    {.name = "COB-ID EMCY"},
    {.name = "Producer Heartbeat Time"},
    {.name = "Nbr of Entries"},
    {.name = "Vendor Id"},
    {.name = "Product Code"},
    {.name = "Revision Number"},
    {.name = "Serial Number"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID Client -> Server"},
    {.name = "COB-ID Server -> Client"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "Controlword"},
    {.name = "Nbr of Entries"},
    {.name = "Controlword"},
    {.name = "Target Position"},
    {.name = "Nbr of Entries"},
    {.name = "Digital Outputs"},
    {.name = "Nbr of Entries"},
    {.name = "Acceleration"},
    {.name = "S-Curve"},
    {.name = "Nbr of Entries"},
    {.name = "Speed"},
    {.name = "Nbr of Entries"},
    {.name = "Following Position Error Window"},
    {.name = "Target Position Error Window"},
    {.name = "Nbr of Entries"},
    {.name = "I Force Max"},
    {.name = "Nbr of Entries"},
    {.name = "Controlword"},
    {.name = "Reserved for future"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "COB-ID"},
    {.name = "Transmission Type"},
    {.name = "Inhibit Time"},
    {.name = "Compatibility Entry"},
    {.name = "Event Timer"},
    {.name = "Nbr of Entries"},
    {.name = "Statusword"},
    {.name = "Nbr of Entries"},
    {.name = "Statusword"},
    {.name = "Actual Position"},
    {.name = "Nbr of Entries"},
    {.name = "Digital Inputs"},
    {.name = "Nbr of Entries"},
    {.name = "Actual Following Position Error"},
    {.name = "Process Status Register"},
    {.name = "Nbr of Entries"},
    {.name = "Actual Current"},
    {.name = "Nbr of Entries"},
    {.name = "I Force Actual"},
    {.name = "Process Status Register"},
    {.name = "Nbr of Entries"},
    {.name = "Statusword"},
    {.name = "I Force Actual"},
    {.name = "S-Curve Profile"},
    {.name = "Reserved 2001"},
    {.name = "Reserved 2002"},
    {.name = "Reserved 2003"},
    {.name = "XENAX Error Number"},
    {.name = "I_Force Actual"},
    {.name = "Process Status Register"},
    {.name = "PDO Cycle Time"},
    {.name = "Motor Type"},
    {.name = "Limit Force"},
    {.name = "Force Actual Value"},
    {.name = "Direct Commands"},
    {.name = "NumOfEntries"},
    {.name = "TS Tell Status"},
    {.name = "TE Tell Error Number"},
    {.name = "TP Tell Position"},
    {.name = "TT Tell Temperature"},
    {.name = "TOX Tell Output Hex"},
    {.name = "TIX Tell Input Hex"},
    {.name = "TMC Tell Motor Current"},
    {.name = "TMT Tell Motion Time"},
    {.name = "TCP Tell Captured Position 1"},
    {.name = "TCP Tell Captured Position 2"},
    {.name = "TCP Tell Captured Position 3"},
    {.name = "TCP Tell Captured Position 4"},
    {.name = "TCP Tell Captured Position 5"},
    {.name = "TCP Tell Captured Position 6"},
    {.name = "TCP Tell Captured Position 7"},
    {.name = "TCP Tell Captured Position 8"},
    {.name = "TH Tell Reference State"},
    {.name = "VER Version of Firmware"},
    {.name = "ACV Acceleration Variation (Jerk, scaled to 1000)"},
    {.name = "I2TM Limit Value (scaled to 10)"},
    {.name = "I2T Calculated Value (scaled to 10)"},
    {.name = "IFPK I_Force Peak (FTM = 0) FPK Force Peak (FTM = 1,2)"},
    {.name = "TESM Tell SMU Error"},
    {.name = "DGMSO Detected Gantry Master Slave Offset"},
    {.name = "SIFF Sector I_Force Curve Failed (FTM = 0) SFF Sector Force Curve Failed (FTM = 1,2) (binary notation, LSB = sector 1)"},
    {.name = "IFPKn I_Force Peak Sector (FTM = 0) FPKn Force Peak Sector (FTM = 1,2) (select sector over Object 0x5003/050)"},
    {.name = "FCV Force Calibration Valid"},
    {.name = "TV Tell Velocity"},
    {.name = "TPT Tell Process Time"},
    {.name = "VERL Version of Bootloader"},
    {.name = "TCPB Tell Capture Pos. Buffer 1"},
    {.name = "TCPB Tell Capture Pos. Buffer 2"},
    {.name = "TCPB Tell Capture Pos. Buffer 3"},
    {.name = "TCPB Tell Capture Pos. Buffer 4"},
    {.name = "TCPB Tell Capture Pos. Buffer 5"},
    {.name = "TCPB Tell Capture Pos. Buffer 6"},
    {.name = "TCPB Tell Capture Pos. Buffer 7"},
    {.name = "TCPB Tell Capture Pos. Buffer 8"},
    {.name = "TESMH Tell SMU Error History"},
    {.name = "GR Gear Ratio"},
    {.name = "TTPS Tell Temperature Power Stage (Xvi75V8S only)"},
    {.name = "TVPSM Tell voltage power supply motor in [mV]"},
    {.name = "LARES linear axis resolution in [inc/m]"},
    {.name = "LAST linear axis stroke in [inc]"},
    {.name = "TTGS Tell trajectory state"},
    {.name = "NumOfEntries"},
    {.name = "CO Clear Output Number"},
    {.name = "EVT Event Activation"},
    {.name = "G Go Immediately"},
    {.name = "IX Start Index Number"},
    {.name = "PG Start Program Number"},
    {.name = "SO Set Output Number"},
    {.name = "SOX Set Output Hex Mask"},
    {.name = "TGD Set Trigger Position Downward"},
    {.name = "TGU Set Trigger Position Upward"},
    {.name = "ETI Enable Track Input"},
    {.name = "DTI Disable Track Input"},
    {.name = "PRF Start Profile Number"},
    {.name = "CRDA Cogging Reference Drive Automatic"},
    {.name = "DIF Drive I_Force"},
    {.name = "CLIF Change Limit I_Force"},
    {.name = "DF Drive Force (Xvi75V8S only)"},
    {.name = "NumOfEntries"},
    {.name = "AC Acceleration"},
    {.name = "S-Curve Profile (in percent)"},
    {.name = "SP Speed"},
    {.name = "PO Position (absolute)"},
    {.name = "WA Way (relative)"},
    {.name = "DP Deviation Position"},
    {.name = "DRHR Direction Reference"},
    {.name = "DTP Deviation Target Position"},
    {.name = "ED Emergency Deceleration"},
    {.name = "ILAS Input Low Active Selective"},
    {.name = "ILA Input Low Active"},
    {.name = "IS Stop Current (Linear) Nominal Current (Rotative) scaled to 10mA"},
    {.name = "SLPP Software Limit Position Positive"},
    {.name = "SLPN Software Limit Position Negative"},
    {.name = "MD Mode"},
    {.name = "ML Mass Load (WebMotion: Payload / Inertia)"},
    {.name = "BWC Bandwidth Current Controller (WebMotion: GAIN CUR)"},
    {.name = "BWP Bandwidth Position Controller (WebMotion: GAIN POS)"},
    {.name = "IR Run Current (Linear) Torque Current (Rotative) scaled to 10mA"},
    {.name = "NIX Preselected Index Number"},
    {.name = "AIX Acceleration of selected Index"},
    {.name = "SIX Speed of selected Index"},
    {.name = "DIX Distance of selected Index (depends on absolute or relative index definition)"},
    {.name = "CI Card Identifier"},
    {.name = "GSID Gantry Slave Identifier"},
    {.name = "FQC Filter Quality Current"},
    {.name = "FFC Filter Frequency Current"},
    {.name = "ICP Increments per Puls"},
    {.name = "INH Input Home Sensor"},
    {.name = "OVRD Speed Override"},
    {.name = "PWRT Phasing Rotative w/o HALL"},
    {.name = "SOA Set Output Activity"},
    {.name = "SOT Set Output Type"},
    {.name = "SR Synchronous Ratio"},
    {.name = "CAB CAN Baud Rate"},
    {.name = "ROID Rotative Motor Identifier"},
    {.name = "Reserved"},
    {.name = "Reserved"},
    {.name = "SIFS Sector I_Force Start (FTM = 0) SFS Sector Force Start (FTM = 1,2)"},
    {.name = "SIFE Sector I_Force End (FTM = 0) SFE Sector Force End (FTM = 1,2)"},
    {.name = "IFL I_Force Low"},
    {.name = "IFH I_Force High"},
    {.name = "MLPN Mechanical Limit Position Negative"},
    {.name = "MLPP Mechanical Limit Position Positive"},
    {.name = "PGMSO Preset Gantry Master Slave Offset"},
    {.name = "BRKD Brake delay"},
    {.name = "Reserved"},
    {.name = "LIF Limit I_Force"},
    {.name = "TYIX Type of Index"},
    {.name = "NSEC Preselected Sector Number"},
    {.name = "STCX Sector Transition Configuration (Hex Mask)"},
    {.name = "NDIF Preselected Drive I_Force Number (FTM = 0) NDF Preselected Drive Force Number (FTM = 1,2)"},
    {.name = "ADIF Acceleration of selected Drive I_Force (FTM = 0) ADF Acceleration of selected Drive Force (FTM = 1,2)"},
    {.name = "SDIF Speed of selected Drive I_Force (FTM = 0) SDF Speed of selected Drive Force (FTM = 1,2)"},
    {.name = "IDIF I_Force Limit of selected Drive I_Force"},
    {.name = "DDIF Direction of selected Drive I_Force (FTM = 0) DDF Direction of selected Drive Force (FTM = 1,2)"},
    {.name = "SSEC Select Sectors (binary notation, LSB = sector 1)"},
    {.name = "SSO Set Sector Offset"},
    {.name = "ENCPD Encoder Plausibility Checking Disable"},
    {.name = "SPAD Set Point ACK disable"},
    {.name = "RXZP ROTAX Z-Position"},
    {.name = "DRH Dir Home"},
    {.name = "DRZ Z-Mark"},
    {.name = "FQS Filter Quality Speed"},
    {.name = "FFS Filter Frequency Speed"},
    {.name = "EBMD Enhanced Bandwidth Mode Disabled"},
    {.name = "Reserved"},
    {.name = "AIXD Acceleration of dynamically selected Index"},
    {.name = "SIXD Speed of dynamically selected Index"},
    {.name = "DIXD Distance of dynamically selected Index (depends on absolute or relative index definition)"},
    {.name = "TYIXD Type of dynamically selected Index"},
    {.name = "PPSD Pole Placement Stability Dynamics"},
    {.name = "IFDCS I_Force Drift Compensation Setting"},
    {.name = "Reserved"},
    {.name = "SORF Swing Out Reduction Frequency"},
    {.name = "SORD Swing Out Reduction Damping"},
    {.name = "Reserved"},
    {.name = "Reserved"},
    {.name = "AVF Filter Frequency for Current Shaper"},
    {.name = "AVD Damping Ratio for Current Shaper"},
    {.name = "NOF Preselected Output Function"},
    {.name = "TYOF Type of Output Function"},
    {.name = "NIF Preselected Input Function"},
    {.name = "TYIF Type of Input Function"},
    {.name = "PAIF Parameter A of Input Function"},
    {.name = "PBIF Parameter B of Input Function"},
    {.name = "PCIF Parameter C of Input Function"},
    {.name = "CLF Change Limit Force (Xvi75V8S only)"},
    {.name = "FD Force of selected Drive Force (Xvi75V8S only)"},
    {.name = "FH Force High (Xvi75V8S only)"},
    {.name = "FL Force Low (Xvi75V8S only)"},
    {.name = "FTM Forceteq Mode (Xvi75V8S only)"},
    {.name = "SQBW Signateq Bandwidth (Xvi75V8S only)"},
    {.name = "MM Motor Manufacturer (Xvi75V8S only)"},
    {.name = "AREF Automatic Reference"},
    {.name = "EGMSO Enable user defined gantry Master/Slave offset"},
    {.name = "VMTAE Virtual multiturn for rotative motors with absolute encoder"},
    {.name = "ENAR Enable absolute reference"},
    {.name = "CTAB Correction Table State"},
    {.name = "APSN number of program to auto start"},
    {.name = "APSD Automatic program start delay[ms]"},
    {.name = "PMHSD Profinet MC_Home support disable"},
    {.name = "FCSM Force Calibration Storage mode"},
    {.name = "SOD P402 Switch on at transition 3 disable"},
    {.name = "GCME Gantry Coupled Mode Enable"},
    {.name = "FBCM Force buffered CSP mode"},
    {.name = "NumOfEntries"},
    {.name = "POL Pole Pairs"},
    {.name = "ENC Encoder Increments (Rotative, 1 turn of motor shaft)"},
    {.name = "PHD Phase Direction"},
    {.name = "PHO Phase Offset"},
    {.name = "MAMO Slider Mass (LINAX / ELAX) Rotor Inertia (Rotative)"},
    {.name = "FCM Force Constant of Motor"},
    {.name = "LPH Inductance Phase-Phase"},
    {.name = "RPH Resistance Phase-Phase"},
    {.name = "FFDY Frictional Force Dynamic"},
    {.name = "FFST Frictional Force Static"},
    {.name = "DMLPP Detected Mechanical Limit Position Positive"},
    {.name = "NumOfEntries"},
    {.name = "VERS Version SMU"},
    {.name = "SLS Timeout"},
    {.name = "Speed Limit"},
    {.name = "Stop Timeout"},
    {.name = "Position Window"},
    {.name = "SFTRD Input Configuration SMU"},
    {.name = "TESM Tell SMU Error"},
    {.name = "SMU Master Error Bitfeld"},
    {.name = "SMU Slave Error Bitfeld"},
    {.name = "SMU Master Info Bitfeld"},
    {.name = "SMU Slave Info Bitfeld"},
    {.name = "SPC Safety Parameter CRC"},
    {.name = "SPCMAC Safety Parameter and MAC Adress CRC (Xvi75V8S only)"},
    {.name = "NumOfEntries"},
    {.name = "EGW Set Gateway Address"},
    {.name = "EIP Set IP Address"},
    {.name = "ENM Set Net Mask"},
    {.name = "EMAC Read MAC Address 3 high Bytes"},
    {.name = "EMAC Read MAC Address 3 low Bytes"},
    {.name = "EPRT Set Port Number"},
    {.name = "LICR Show Installed Licences"},
    {.name = "SERB Set Baud Rate on Serial Interface"},
    {.name = "WebMotion Version"},
    {.name = "WebMotion Boot Version"},
    {.name = "NumOfEntries"},
    {.name = "SQVER Signateq Firmware Version"},
    {.name = "SQBW Signateq Bandwidth"},
    {.name = "SQSNF Signateq Sensor Nominal Force"},
    {.name = "SQMRP Signateq Measurement Range"},
    {.name = "Reserved"},
    {.name = "SQSS Signateq Sensor Sensitivity"},
    {.name = "SQSFT Signateq Sensor Force Type"},
    {.name = "SQCM Signateq Calibration Mode"},
    {.name = "SQFD Signateq Force Direction"},
    {.name = "LFRMS Limit Force Reached Maximum Speed"},
    {.name = "CLFO Clear force offset"},
    {.name = "SQAC Signateq available calibrations"},
    {.name = "BWFP Bandwidth for forceteq pro controller"},
    {.name = "FTPES Forceteq Pro Elastic Spring Constant"},
    {.name = "Signateq Sensor Model Type (SQSMT)"},
    {.name = "Signateq Sensor Serial Number (SQSSN)"},
    {.name = "Tell Error String (TES)"},
    {.name = "Servo identification string (SID)"},
    {.name = "Error Code"},
    {.name = "Controlword"},
    {.name = "Statusword"},
    {.name = "Modes of Operation Requested"},
    {.name = "Modes of Operation Display"},
    {.name = "Position Actual Value"},
    {.name = "Following Position Error Window"},
    {.name = "Target Position Window"},
    {.name = "Position Window Time"},
    {.name = "Velocity Actual Value"},
    {.name = "Limit I_Force"},
    {.name = "Motor Current Actual Value"},
    {.name = "Target Position"},
    {.name = "Highest Sub-index Value"},
    {.name = "Software Position Limit Left"},
    {.name = "Software Position Limit Right"},
    {.name = "Speed"},
    {.name = "Acceleration"},
    {.name = "Quick Stop Deceleration"},
    {.name = "Reference Methods"},
    {.name = "Highest Sub-index Value"},
    {.name = "Reference-Speed searching external Reference sensor"},
    {.name = "Z-Speed searching internal encoder Z-mark"},
    {.name = "Velocity Offset"},
    {.name = "Torque Offset"},
    {.name = "Highest Sub-index Value"},
    {.name = "Base value"},
    {.name = "10^EXPONENT"},
    {.name = "Actual Position Following Error"},
    {.name = "Digital Inputs"},
    {.name = "Highest Sub-index Value"},
    {.name = "Output Bit"},
    {.name = "Output Mask (not supported)"},
    {.name = "Target Velocity"},
    {.name = "Supported Modes of Operation"},
    {.name = "Product Website Address"},
}};

inline constexpr od::dictionary dictionary{entries, infos};
static_assert(dictionary.is_valid());

// VAR objects: standalone descriptors (copies, not references into the tables: firmware that
// names one keeps only that one).
inline constexpr od::descriptor device_type{entries[0], infos[0]}; // 0x1000
inline constexpr od::descriptor error_register{entries[1], infos[1]}; // 0x1001
inline constexpr od::descriptor cob_id_sync{entries[2], infos[2]}; // 0x1005
inline constexpr od::descriptor manufacturer_device_name{entries[3], infos[3]}; // 0x1008
inline constexpr od::descriptor manufacturer_hardware_version{entries[4], infos[4]}; // 0x1009
inline constexpr od::descriptor manufacturer_software_version{entries[5], infos[5]}; // 0x100A
inline constexpr od::descriptor cob_id_emcy{entries[6], infos[6]}; // 0x1014
inline constexpr od::descriptor producer_heartbeat_time{entries[7], infos[7]}; // 0x1017
inline constexpr od::descriptor s_curve_profile{entries[174], infos[174]}; // 0x2000
inline constexpr od::descriptor reserved_2001{entries[175], infos[175]}; // 0x2001
inline constexpr od::descriptor reserved_2002{entries[176], infos[176]}; // 0x2002
inline constexpr od::descriptor reserved_2003{entries[177], infos[177]}; // 0x2003
inline constexpr od::descriptor xenax_error_number{entries[178], infos[178]}; // 0x2004
inline constexpr od::descriptor i_force_actual{entries[179], infos[179]}; // 0x2005
inline constexpr od::descriptor process_status_register{entries[180], infos[180]}; // 0x2006
inline constexpr od::descriptor pdo_cycle_time{entries[181], infos[181]}; // 0x2007
inline constexpr od::descriptor motor_type{entries[182], infos[182]}; // 0x2008
inline constexpr od::descriptor limit_force{entries[183], infos[183]}; // 0x2009
inline constexpr od::descriptor force_actual_value{entries[184], infos[184]}; // 0x200A
inline constexpr od::descriptor direct_commands{entries[185], infos[185]}; // 0x5000
inline constexpr od::descriptor signateq_sensor_model_type_sqsmt{entries[408], infos[408]}; // 0x5011
inline constexpr od::descriptor signateq_sensor_serial_number_sqssn{entries[409], infos[409]}; // 0x5012
inline constexpr od::descriptor tell_error_string_tes{entries[410], infos[410]}; // 0x5020
inline constexpr od::descriptor servo_identification_string_sid{entries[411], infos[411]}; // 0x5021
inline constexpr od::descriptor error_code{entries[412], infos[412]}; // 0x603F
inline constexpr od::descriptor controlword{entries[413], infos[413]}; // 0x6040
inline constexpr od::descriptor statusword{entries[414], infos[414]}; // 0x6041
inline constexpr od::descriptor modes_of_operation_requested{entries[415], infos[415]}; // 0x6060
inline constexpr od::descriptor modes_of_operation_display{entries[416], infos[416]}; // 0x6061
inline constexpr od::descriptor position_actual_value{entries[417], infos[417]}; // 0x6064
inline constexpr od::descriptor following_position_error_window{entries[418], infos[418]}; // 0x6065
inline constexpr od::descriptor target_position_window{entries[419], infos[419]}; // 0x6067
inline constexpr od::descriptor position_window_time{entries[420], infos[420]}; // 0x6068
inline constexpr od::descriptor velocity_actual_value{entries[421], infos[421]}; // 0x606C
inline constexpr od::descriptor limit_i_force{entries[422], infos[422]}; // 0x6073
inline constexpr od::descriptor motor_current_actual_value{entries[423], infos[423]}; // 0x6078
inline constexpr od::descriptor target_position{entries[424], infos[424]}; // 0x607A
inline constexpr od::descriptor speed{entries[428], infos[428]}; // 0x6081
inline constexpr od::descriptor acceleration{entries[429], infos[429]}; // 0x6083
inline constexpr od::descriptor quick_stop_deceleration{entries[430], infos[430]}; // 0x6085
inline constexpr od::descriptor reference_methods{entries[431], infos[431]}; // 0x6098
inline constexpr od::descriptor velocity_offset{entries[435], infos[435]}; // 0x60B1
inline constexpr od::descriptor torque_offset{entries[436], infos[436]}; // 0x60B2
inline constexpr od::descriptor actual_position_following_error{entries[440], infos[440]}; // 0x60F4
inline constexpr od::descriptor digital_inputs{entries[441], infos[441]}; // 0x60FD
inline constexpr od::descriptor target_velocity{entries[445], infos[445]}; // 0x60FF
inline constexpr od::descriptor supported_modes_of_operation{entries[446], infos[446]}; // 0x6502
inline constexpr od::descriptor product_website_address{entries[447], infos[447]}; // 0x6505

// ARRAY and RECORD objects: views into the tables.
inline constexpr od::object identity_object{0x1018, od::object_code::record, "Identity Object", {entries.data() + 8, 5}, {infos.data() + 8, 5}};
inline constexpr const od::entry &identity_object_nbr_of_entries = entries[8];
inline constexpr const od::entry &identity_object_vendor_id = entries[9];
inline constexpr const od::entry &identity_object_product_code = entries[10];
inline constexpr const od::entry &identity_object_revision_number = entries[11];
inline constexpr const od::entry &identity_object_serial_number = entries[12];
inline constexpr od::object server_sdo_parameter_1{0x1200, od::object_code::record, "Server SDO Parameter 1", {entries.data() + 13, 3}, {infos.data() + 13, 3}};
inline constexpr const od::entry &server_sdo_parameter_1_nbr_of_entries = entries[13];
inline constexpr const od::entry &server_sdo_parameter_1_cob_id_client_server = entries[14];
inline constexpr const od::entry &server_sdo_parameter_1_cob_id_server_client = entries[15];
inline constexpr od::object receive_pdo_comm_param_1{0x1400, od::object_code::record, "Receive PDO Comm Param 1", {entries.data() + 16, 6}, {infos.data() + 16, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_1_nbr_of_entries = entries[16];
inline constexpr const od::entry &receive_pdo_comm_param_1_cob_id = entries[17];
inline constexpr const od::entry &receive_pdo_comm_param_1_transmission_type = entries[18];
inline constexpr const od::entry &receive_pdo_comm_param_1_inhibit_time = entries[19];
inline constexpr const od::entry &receive_pdo_comm_param_1_compatibility_entry = entries[20];
inline constexpr const od::entry &receive_pdo_comm_param_1_event_timer = entries[21];
inline constexpr od::object receive_pdo_comm_param_2{0x1401, od::object_code::record, "Receive PDO Comm Param 2", {entries.data() + 22, 6}, {infos.data() + 22, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_2_nbr_of_entries = entries[22];
inline constexpr const od::entry &receive_pdo_comm_param_2_cob_id = entries[23];
inline constexpr const od::entry &receive_pdo_comm_param_2_transmission_type = entries[24];
inline constexpr const od::entry &receive_pdo_comm_param_2_inhibit_time = entries[25];
inline constexpr const od::entry &receive_pdo_comm_param_2_compatibility_entry = entries[26];
inline constexpr const od::entry &receive_pdo_comm_param_2_event_timer = entries[27];
inline constexpr od::object receive_pdo_comm_param_17{0x1410, od::object_code::record, "Receive PDO Comm Param 17", {entries.data() + 28, 6}, {infos.data() + 28, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_17_nbr_of_entries = entries[28];
inline constexpr const od::entry &receive_pdo_comm_param_17_cob_id = entries[29];
inline constexpr const od::entry &receive_pdo_comm_param_17_transmission_type = entries[30];
inline constexpr const od::entry &receive_pdo_comm_param_17_inhibit_time = entries[31];
inline constexpr const od::entry &receive_pdo_comm_param_17_compatibility_entry = entries[32];
inline constexpr const od::entry &receive_pdo_comm_param_17_event_timer = entries[33];
inline constexpr od::object receive_pdo_comm_param_18{0x1411, od::object_code::record, "Receive PDO Comm Param 18", {entries.data() + 34, 6}, {infos.data() + 34, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_18_nbr_of_entries = entries[34];
inline constexpr const od::entry &receive_pdo_comm_param_18_cob_id = entries[35];
inline constexpr const od::entry &receive_pdo_comm_param_18_transmission_type = entries[36];
inline constexpr const od::entry &receive_pdo_comm_param_18_inhibit_time = entries[37];
inline constexpr const od::entry &receive_pdo_comm_param_18_compatibility_entry = entries[38];
inline constexpr const od::entry &receive_pdo_comm_param_18_event_timer = entries[39];
inline constexpr od::object receive_pdo_comm_param_19{0x1412, od::object_code::record, "Receive PDO Comm Param 19", {entries.data() + 40, 6}, {infos.data() + 40, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_19_nbr_of_entries = entries[40];
inline constexpr const od::entry &receive_pdo_comm_param_19_cob_id = entries[41];
inline constexpr const od::entry &receive_pdo_comm_param_19_transmission_type = entries[42];
inline constexpr const od::entry &receive_pdo_comm_param_19_inhibit_time = entries[43];
inline constexpr const od::entry &receive_pdo_comm_param_19_compatibility_entry = entries[44];
inline constexpr const od::entry &receive_pdo_comm_param_19_event_timer = entries[45];
inline constexpr od::object receive_pdo_comm_param_20{0x1413, od::object_code::record, "Receive PDO Comm Param 20", {entries.data() + 46, 6}, {infos.data() + 46, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_20_nbr_of_entries = entries[46];
inline constexpr const od::entry &receive_pdo_comm_param_20_cob_id = entries[47];
inline constexpr const od::entry &receive_pdo_comm_param_20_transmission_type = entries[48];
inline constexpr const od::entry &receive_pdo_comm_param_20_inhibit_time = entries[49];
inline constexpr const od::entry &receive_pdo_comm_param_20_compatibility_entry = entries[50];
inline constexpr const od::entry &receive_pdo_comm_param_20_event_timer = entries[51];
inline constexpr od::object receive_pdo_comm_param_21{0x1414, od::object_code::record, "Receive PDO Comm Param 21", {entries.data() + 52, 6}, {infos.data() + 52, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_21_nbr_of_entries = entries[52];
inline constexpr const od::entry &receive_pdo_comm_param_21_cob_id = entries[53];
inline constexpr const od::entry &receive_pdo_comm_param_21_transmission_type = entries[54];
inline constexpr const od::entry &receive_pdo_comm_param_21_inhibit_time = entries[55];
inline constexpr const od::entry &receive_pdo_comm_param_21_compatibility_entry = entries[56];
inline constexpr const od::entry &receive_pdo_comm_param_21_event_timer = entries[57];
inline constexpr od::object receive_pdo_comm_param_22{0x1415, od::object_code::record, "Receive PDO Comm Param 22", {entries.data() + 58, 6}, {infos.data() + 58, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_22_nbr_of_entries = entries[58];
inline constexpr const od::entry &receive_pdo_comm_param_22_cob_id = entries[59];
inline constexpr const od::entry &receive_pdo_comm_param_22_transmission_type = entries[60];
inline constexpr const od::entry &receive_pdo_comm_param_22_inhibit_time = entries[61];
inline constexpr const od::entry &receive_pdo_comm_param_22_compatibility_entry = entries[62];
inline constexpr const od::entry &receive_pdo_comm_param_22_event_timer = entries[63];
inline constexpr od::object receive_pdo_comm_param_23{0x1416, od::object_code::record, "Receive PDO Comm Param 23", {entries.data() + 64, 6}, {infos.data() + 64, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_23_nbr_of_entries = entries[64];
inline constexpr const od::entry &receive_pdo_comm_param_23_cob_id = entries[65];
inline constexpr const od::entry &receive_pdo_comm_param_23_transmission_type = entries[66];
inline constexpr const od::entry &receive_pdo_comm_param_23_inhibit_time = entries[67];
inline constexpr const od::entry &receive_pdo_comm_param_23_compatibility_entry = entries[68];
inline constexpr const od::entry &receive_pdo_comm_param_23_event_timer = entries[69];
inline constexpr od::object receive_pdo_comm_param_24{0x1417, od::object_code::record, "Receive PDO Comm Param 24", {entries.data() + 70, 6}, {infos.data() + 70, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_24_nbr_of_entries = entries[70];
inline constexpr const od::entry &receive_pdo_comm_param_24_cob_id = entries[71];
inline constexpr const od::entry &receive_pdo_comm_param_24_transmission_type = entries[72];
inline constexpr const od::entry &receive_pdo_comm_param_24_inhibit_time = entries[73];
inline constexpr const od::entry &receive_pdo_comm_param_24_compatibility_entry = entries[74];
inline constexpr const od::entry &receive_pdo_comm_param_24_event_timer = entries[75];
inline constexpr od::object receive_pdo_mapping_param_1{0x1600, od::object_code::record, "Receive PDO Mapping Param 1", {entries.data() + 76, 2}, {infos.data() + 76, 2}};
inline constexpr const od::entry &receive_pdo_mapping_param_1_nbr_of_entries = entries[76];
inline constexpr const od::entry &receive_pdo_mapping_param_1_controlword = entries[77];
inline constexpr od::object receive_pdo_mapping_param_2{0x1601, od::object_code::record, "Receive PDO Mapping Param 2", {entries.data() + 78, 3}, {infos.data() + 78, 3}};
inline constexpr const od::entry &receive_pdo_mapping_param_2_nbr_of_entries = entries[78];
inline constexpr const od::entry &receive_pdo_mapping_param_2_controlword = entries[79];
inline constexpr const od::entry &receive_pdo_mapping_param_2_target_position = entries[80];
inline constexpr od::object receive_pdo_mapping_param_17{0x1610, od::object_code::record, "Receive PDO Mapping Param 17", {entries.data() + 81, 2}, {infos.data() + 81, 2}};
inline constexpr const od::entry &receive_pdo_mapping_param_17_nbr_of_entries = entries[81];
inline constexpr const od::entry &receive_pdo_mapping_param_17_digital_outputs = entries[82];
inline constexpr od::object receive_pdo_mapping_param_18{0x1611, od::object_code::record, "Receive PDO Mapping Param 18", {entries.data() + 83, 3}, {infos.data() + 83, 3}};
inline constexpr const od::entry &receive_pdo_mapping_param_18_nbr_of_entries = entries[83];
inline constexpr const od::entry &receive_pdo_mapping_param_18_acceleration = entries[84];
inline constexpr const od::entry &receive_pdo_mapping_param_18_s_curve = entries[85];
inline constexpr od::object receive_pdo_mapping_param_19{0x1612, od::object_code::record, "Receive PDO Mapping Param 19", {entries.data() + 86, 2}, {infos.data() + 86, 2}};
inline constexpr const od::entry &receive_pdo_mapping_param_19_nbr_of_entries = entries[86];
inline constexpr const od::entry &receive_pdo_mapping_param_19_speed = entries[87];
inline constexpr od::object receive_pdo_mapping_param_20{0x1613, od::object_code::record, "Receive PDO Mapping Param 20", {entries.data() + 88, 3}, {infos.data() + 88, 3}};
inline constexpr const od::entry &receive_pdo_mapping_param_20_nbr_of_entries = entries[88];
inline constexpr const od::entry &receive_pdo_mapping_param_20_following_position_error_window = entries[89];
inline constexpr const od::entry &receive_pdo_mapping_param_20_target_position_error_window = entries[90];
inline constexpr od::object receive_pdo_mapping_param_21{0x1614, od::object_code::record, "Receive PDO Mapping Param 21", {entries.data() + 91, 2}, {infos.data() + 91, 2}};
inline constexpr const od::entry &receive_pdo_mapping_param_21_nbr_of_entries = entries[91];
inline constexpr const od::entry &receive_pdo_mapping_param_21_i_force_max = entries[92];
inline constexpr od::object receive_pdo_mapping_param_24{0x1617, od::object_code::record, "Receive PDO Mapping Param 24", {entries.data() + 93, 3}, {infos.data() + 93, 3}};
inline constexpr const od::entry &receive_pdo_mapping_param_24_nbr_of_entries = entries[93];
inline constexpr const od::entry &receive_pdo_mapping_param_24_controlword = entries[94];
inline constexpr const od::entry &receive_pdo_mapping_param_24_reserved_for_future = entries[95];
inline constexpr od::object transmit_pdo_comm_param_1{0x1800, od::object_code::record, "Transmit PDO Comm Param 1", {entries.data() + 96, 6}, {infos.data() + 96, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_1_nbr_of_entries = entries[96];
inline constexpr const od::entry &transmit_pdo_comm_param_1_cob_id = entries[97];
inline constexpr const od::entry &transmit_pdo_comm_param_1_transmission_type = entries[98];
inline constexpr const od::entry &transmit_pdo_comm_param_1_inhibit_time = entries[99];
inline constexpr const od::entry &transmit_pdo_comm_param_1_compatibility_entry = entries[100];
inline constexpr const od::entry &transmit_pdo_comm_param_1_event_timer = entries[101];
inline constexpr od::object transmit_pdo_comm_param_2{0x1801, od::object_code::record, "Transmit PDO Comm Param 2", {entries.data() + 102, 6}, {infos.data() + 102, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_2_nbr_of_entries = entries[102];
inline constexpr const od::entry &transmit_pdo_comm_param_2_cob_id = entries[103];
inline constexpr const od::entry &transmit_pdo_comm_param_2_transmission_type = entries[104];
inline constexpr const od::entry &transmit_pdo_comm_param_2_inhibit_time = entries[105];
inline constexpr const od::entry &transmit_pdo_comm_param_2_compatibility_entry = entries[106];
inline constexpr const od::entry &transmit_pdo_comm_param_2_event_timer = entries[107];
inline constexpr od::object transmit_pdo_comm_param_17{0x1810, od::object_code::record, "Transmit PDO Comm Param 17", {entries.data() + 108, 6}, {infos.data() + 108, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_17_nbr_of_entries = entries[108];
inline constexpr const od::entry &transmit_pdo_comm_param_17_cob_id = entries[109];
inline constexpr const od::entry &transmit_pdo_comm_param_17_transmission_type = entries[110];
inline constexpr const od::entry &transmit_pdo_comm_param_17_inhibit_time = entries[111];
inline constexpr const od::entry &transmit_pdo_comm_param_17_compatibility_entry = entries[112];
inline constexpr const od::entry &transmit_pdo_comm_param_17_event_timer = entries[113];
inline constexpr od::object transmit_pdo_comm_param_18{0x1811, od::object_code::record, "Transmit PDO Comm Param 18", {entries.data() + 114, 6}, {infos.data() + 114, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_18_nbr_of_entries = entries[114];
inline constexpr const od::entry &transmit_pdo_comm_param_18_cob_id = entries[115];
inline constexpr const od::entry &transmit_pdo_comm_param_18_transmission_type = entries[116];
inline constexpr const od::entry &transmit_pdo_comm_param_18_inhibit_time = entries[117];
inline constexpr const od::entry &transmit_pdo_comm_param_18_compatibility_entry = entries[118];
inline constexpr const od::entry &transmit_pdo_comm_param_18_event_timer = entries[119];
inline constexpr od::object transmit_pdo_comm_param_19{0x1812, od::object_code::record, "Transmit PDO Comm Param 19", {entries.data() + 120, 6}, {infos.data() + 120, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_19_nbr_of_entries = entries[120];
inline constexpr const od::entry &transmit_pdo_comm_param_19_cob_id = entries[121];
inline constexpr const od::entry &transmit_pdo_comm_param_19_transmission_type = entries[122];
inline constexpr const od::entry &transmit_pdo_comm_param_19_inhibit_time = entries[123];
inline constexpr const od::entry &transmit_pdo_comm_param_19_compatibility_entry = entries[124];
inline constexpr const od::entry &transmit_pdo_comm_param_19_event_timer = entries[125];
inline constexpr od::object transmit_pdo_comm_param_20{0x1813, od::object_code::record, "Transmit PDO Comm Param 20", {entries.data() + 126, 6}, {infos.data() + 126, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_20_nbr_of_entries = entries[126];
inline constexpr const od::entry &transmit_pdo_comm_param_20_cob_id = entries[127];
inline constexpr const od::entry &transmit_pdo_comm_param_20_transmission_type = entries[128];
inline constexpr const od::entry &transmit_pdo_comm_param_20_inhibit_time = entries[129];
inline constexpr const od::entry &transmit_pdo_comm_param_20_compatibility_entry = entries[130];
inline constexpr const od::entry &transmit_pdo_comm_param_20_event_timer = entries[131];
inline constexpr od::object transmit_pdo_comm_param_21{0x1814, od::object_code::record, "Transmit PDO Comm Param 21", {entries.data() + 132, 6}, {infos.data() + 132, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_21_nbr_of_entries = entries[132];
inline constexpr const od::entry &transmit_pdo_comm_param_21_cob_id = entries[133];
inline constexpr const od::entry &transmit_pdo_comm_param_21_transmission_type = entries[134];
inline constexpr const od::entry &transmit_pdo_comm_param_21_inhibit_time = entries[135];
inline constexpr const od::entry &transmit_pdo_comm_param_21_compatibility_entry = entries[136];
inline constexpr const od::entry &transmit_pdo_comm_param_21_event_timer = entries[137];
inline constexpr od::object transmit_pdo_comm_param_22{0x1815, od::object_code::record, "Transmit PDO Comm Param 22", {entries.data() + 138, 6}, {infos.data() + 138, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_22_nbr_of_entries = entries[138];
inline constexpr const od::entry &transmit_pdo_comm_param_22_cob_id = entries[139];
inline constexpr const od::entry &transmit_pdo_comm_param_22_transmission_type = entries[140];
inline constexpr const od::entry &transmit_pdo_comm_param_22_inhibit_time = entries[141];
inline constexpr const od::entry &transmit_pdo_comm_param_22_compatibility_entry = entries[142];
inline constexpr const od::entry &transmit_pdo_comm_param_22_event_timer = entries[143];
inline constexpr od::object transmit_pdo_comm_param_23{0x1816, od::object_code::record, "Transmit PDO Comm Param 23", {entries.data() + 144, 6}, {infos.data() + 144, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_23_nbr_of_entries = entries[144];
inline constexpr const od::entry &transmit_pdo_comm_param_23_cob_id = entries[145];
inline constexpr const od::entry &transmit_pdo_comm_param_23_transmission_type = entries[146];
inline constexpr const od::entry &transmit_pdo_comm_param_23_inhibit_time = entries[147];
inline constexpr const od::entry &transmit_pdo_comm_param_23_compatibility_entry = entries[148];
inline constexpr const od::entry &transmit_pdo_comm_param_23_event_timer = entries[149];
inline constexpr od::object transmit_pdo_comm_param_24{0x1817, od::object_code::record, "Transmit PDO Comm Param 24", {entries.data() + 150, 6}, {infos.data() + 150, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_24_nbr_of_entries = entries[150];
inline constexpr const od::entry &transmit_pdo_comm_param_24_cob_id = entries[151];
inline constexpr const od::entry &transmit_pdo_comm_param_24_transmission_type = entries[152];
inline constexpr const od::entry &transmit_pdo_comm_param_24_inhibit_time = entries[153];
inline constexpr const od::entry &transmit_pdo_comm_param_24_compatibility_entry = entries[154];
inline constexpr const od::entry &transmit_pdo_comm_param_24_event_timer = entries[155];
inline constexpr od::object transmit_pdo_mapping_param_1{0x1A00, od::object_code::record, "Transmit PDO Mapping Param 1", {entries.data() + 156, 2}, {infos.data() + 156, 2}};
inline constexpr const od::entry &transmit_pdo_mapping_param_1_nbr_of_entries = entries[156];
inline constexpr const od::entry &transmit_pdo_mapping_param_1_statusword = entries[157];
inline constexpr od::object transmit_pdo_mapping_param_2{0x1A01, od::object_code::record, "Transmit PDO Mapping Param 2", {entries.data() + 158, 3}, {infos.data() + 158, 3}};
inline constexpr const od::entry &transmit_pdo_mapping_param_2_nbr_of_entries = entries[158];
inline constexpr const od::entry &transmit_pdo_mapping_param_2_statusword = entries[159];
inline constexpr const od::entry &transmit_pdo_mapping_param_2_actual_position = entries[160];
inline constexpr od::object transmit_pdo_mapping_param_17{0x1A10, od::object_code::record, "Transmit PDO Mapping Param 17", {entries.data() + 161, 2}, {infos.data() + 161, 2}};
inline constexpr const od::entry &transmit_pdo_mapping_param_17_nbr_of_entries = entries[161];
inline constexpr const od::entry &transmit_pdo_mapping_param_17_digital_inputs = entries[162];
inline constexpr od::object transmit_pdo_mapping_param_20{0x1A13, od::object_code::record, "Transmit PDO Mapping Param 20", {entries.data() + 163, 3}, {infos.data() + 163, 3}};
inline constexpr const od::entry &transmit_pdo_mapping_param_20_nbr_of_entries = entries[163];
inline constexpr const od::entry &transmit_pdo_mapping_param_20_actual_following_position_error = entries[164];
inline constexpr const od::entry &transmit_pdo_mapping_param_20_process_status_register = entries[165];
inline constexpr od::object transmit_pdo_mapping_param_21{0x1A14, od::object_code::record, "Transmit PDO Mapping Param 21", {entries.data() + 166, 2}, {infos.data() + 166, 2}};
inline constexpr const od::entry &transmit_pdo_mapping_param_21_nbr_of_entries = entries[166];
inline constexpr const od::entry &transmit_pdo_mapping_param_21_actual_current = entries[167];
inline constexpr od::object transmit_pdo_mapping_param_23{0x1A16, od::object_code::record, "Transmit PDO Mapping Param 23", {entries.data() + 168, 3}, {infos.data() + 168, 3}};
inline constexpr const od::entry &transmit_pdo_mapping_param_23_nbr_of_entries = entries[168];
inline constexpr const od::entry &transmit_pdo_mapping_param_23_i_force_actual = entries[169];
inline constexpr const od::entry &transmit_pdo_mapping_param_23_process_status_register = entries[170];
inline constexpr od::object transmit_pdo_mapping_param_24{0x1A17, od::object_code::record, "Transmit PDO Mapping Param 24", {entries.data() + 171, 3}, {infos.data() + 171, 3}};
inline constexpr const od::entry &transmit_pdo_mapping_param_24_nbr_of_entries = entries[171];
inline constexpr const od::entry &transmit_pdo_mapping_param_24_statusword = entries[172];
inline constexpr const od::entry &transmit_pdo_mapping_param_24_i_force_actual = entries[173];
inline constexpr od::object read_parameter{0x5001, od::object_code::array, "Read Parameter", {entries.data() + 186, 46}, {infos.data() + 186, 46}};
inline constexpr od::object write_parameter{0x5002, od::object_code::array, "Write Parameter", {entries.data() + 232, 17}, {infos.data() + 232, 17}};
inline constexpr od::object read_write_parameter{0x5003, od::object_code::array, "Read Write Parameter", {entries.data() + 249, 107}, {infos.data() + 249, 107}};
inline constexpr od::object motor_parameter{0x5004, od::object_code::array, "Motor Parameter", {entries.data() + 356, 12}, {infos.data() + 356, 12}};
inline constexpr od::object smu_parameter{0x5005, od::object_code::array, "SMU Parameter", {entries.data() + 368, 14}, {infos.data() + 368, 14}};
inline constexpr od::object xvi75v8s_and_xvi48v8_parameter{0x5006, od::object_code::array, "Xvi75V8S and Xvi48V8 Parameter", {entries.data() + 382, 11}, {infos.data() + 382, 11}};
inline constexpr od::object forceteq_pro_parameter{0x5010, od::object_code::array, "Forceteq pro Parameter", {entries.data() + 393, 15}, {infos.data() + 393, 15}};
inline constexpr od::object soft_limit_positions{0x607D, od::object_code::array, "Soft-Limit Positions", {entries.data() + 425, 3}, {infos.data() + 425, 3}};
inline constexpr od::object reference_speeds{0x6099, od::object_code::array, "Reference Speeds", {entries.data() + 432, 3}, {infos.data() + 432, 3}};
inline constexpr od::object synchronous_cycle_time{0x60C2, od::object_code::record, "Synchronous Cycle Time", {entries.data() + 437, 3}, {infos.data() + 437, 3}};
inline constexpr const od::entry &synchronous_cycle_time_highest_sub_index_value = entries[437];
inline constexpr const od::entry &synchronous_cycle_time_base_value = entries[438];
inline constexpr const od::entry &synchronous_cycle_time_n_10_exponent = entries[439];
inline constexpr od::object digital_outputs{0x60FE, od::object_code::array, "Digital Outputs", {entries.data() + 442, 3}, {infos.data() + 442, 3}};

} // namespace fieldcodec::dictionaries::xenax_canopen
// clang-format on
