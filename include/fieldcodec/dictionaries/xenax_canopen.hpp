// Generated from xenax_canopen.eds by fieldcodec-gen — do not edit.
// Regenerate with codegen/regenerate.sh (or the fieldcodec_generate_dictionary CMake function).
// clang-format off
#pragma once

#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/number.hpp>
#include <fieldcodec/od/object.hpp>

#include <array>
#include <cstdint>

namespace fieldcodec::dictionaries::xenax_canopen {

inline constexpr const char *source_file = "xenax_canopen.eds";

inline constexpr std::array<od::entry, 448> entries{{
    {.index = 0x1000, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Device Type", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(131474U)},
    {.index = 0x1001, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Error Register", .low = od::num::u(0U), .high = od::num::u(255U), .default_value = od::num::u(0U)},
    {.index = 0x1005, .type = od::data_type::unsigned32, .name = "COB-ID SYNC", .low = od::num::u(1U), .high = od::num::u(4294967295U), .default_value = od::num::u(2147483776U)},
    {.index = 0x1008, .type = od::data_type::visible_string, .access_type = od::access::ro, .size = 30, .name = "Manufacturer Device Name", .default_text = "Servocontroller XENAX Xvi xxVx"},
    {.index = 0x1009, .type = od::data_type::visible_string, .access_type = od::access::ro, .size = 22, .name = "Manufacturer Hardware Version", .default_text = "BUS Module HW Vxxx.xxx"},
    {.index = 0x100A, .type = od::data_type::visible_string, .access_type = od::access::ro, .size = 24, .name = "Manufacturer Software Version", .default_text = "BUS Protocol SW Vxxx.xxx"},
    {.index = 0x1014, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "COB-ID EMCY", .default_value = od::num::u(128U), .default_nodeid = true},
    {.index = 0x1017, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Producer Heartbeat Time", .default_value = od::num::u(0U)},
    {.index = 0x1018, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .low = od::num::u(1U), .high = od::num::u(4U), .default_value = od::num::u(4U)},
    {.index = 0x1018, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Vendor Id", .low = od::num::u(0U), .high = od::num::u(4294967295U)},
    {.index = 0x1018, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Product Code", .low = od::num::u(0U), .high = od::num::u(4294967295U)},
    {.index = 0x1018, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Revision Number", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(65536U)},
    {.index = 0x1018, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Serial Number", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1U)},
    {.index = 0x1200, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(2U)},
    {.index = 0x1200, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "COB-ID Client -> Server", .default_value = od::num::u(1536U), .default_nodeid = true},
    {.index = 0x1200, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "COB-ID Server -> Client", .default_value = od::num::u(1408U), .default_nodeid = true},
    {.index = 0x1400, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1400, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(512U), .default_nodeid = true},
    {.index = 0x1400, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(255U)},
    {.index = 0x1400, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1400, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1400, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1401, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1401, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(768U), .default_nodeid = true},
    {.index = 0x1401, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(255U)},
    {.index = 0x1401, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1401, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1401, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1410, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1410, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1410, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1410, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1410, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1410, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1411, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1411, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1411, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1411, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1411, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1411, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1412, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1412, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1412, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1412, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1412, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1412, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1413, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1413, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1413, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1413, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1413, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1413, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1414, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1414, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1414, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1414, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1414, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1414, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1415, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1415, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1415, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1415, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1415, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1415, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1416, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1416, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1416, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1416, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1416, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1416, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1417, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1417, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1417, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1417, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1417, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1417, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1600, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(1U)},
    {.index = 0x1600, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .default_value = od::num::u(1614807056U)},
    {.index = 0x1601, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(2U)},
    {.index = 0x1601, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .default_value = od::num::u(1614807056U)},
    {.index = 0x1601, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Target Position", .default_value = od::num::u(1618608160U)},
    {.index = 0x1610, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(1U)},
    {.index = 0x1610, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Digital Outputs", .default_value = od::num::u(1627259168U)},
    {.index = 0x1611, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(2U)},
    {.index = 0x1611, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Acceleration", .default_value = od::num::u(1619197984U)},
    {.index = 0x1611, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "S-Curve", .default_value = od::num::u(536870944U)},
    {.index = 0x1612, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(1U)},
    {.index = 0x1612, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Speed", .default_value = od::num::u(1619066912U)},
    {.index = 0x1613, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(2U)},
    {.index = 0x1613, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Following Position Error Window", .default_value = od::num::u(1617231904U)},
    {.index = 0x1613, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Target Position Error Window", .default_value = od::num::u(1617362976U)},
    {.index = 0x1614, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(1U)},
    {.index = 0x1614, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "I Force Max", .default_value = od::num::u(1618149392U)},
    {.index = 0x1617, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(2U)},
    {.index = 0x1617, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .default_value = od::num::u(1614807056U)},
    {.index = 0x1617, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Reserved for future", .default_value = od::num::u(537002016U)},
    {.index = 0x1800, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1800, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(384U), .default_nodeid = true},
    {.index = 0x1800, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(255U)},
    {.index = 0x1800, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1800, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1800, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1801, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1801, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(640U), .default_nodeid = true},
    {.index = 0x1801, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(255U)},
    {.index = 0x1801, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1801, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1801, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1810, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1810, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1810, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1810, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1810, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1810, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1811, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1811, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1811, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1811, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1811, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1811, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1812, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1812, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1812, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1812, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1812, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1812, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1813, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1813, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1813, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1813, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1813, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1813, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1814, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1814, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1814, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1814, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1814, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1814, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1815, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1815, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1815, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1815, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1815, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1815, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1816, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1816, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1816, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1816, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1816, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1816, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1817, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .default_value = od::num::u(5U)},
    {.index = 0x1817, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID", .default_value = od::num::u(2147483648U)},
    {.index = 0x1817, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission Type", .default_value = od::num::u(254U)},
    {.index = 0x1817, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit Time", .default_value = od::num::u(0U)},
    {.index = 0x1817, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility Entry", .default_value = od::num::u(0U)},
    {.index = 0x1817, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event Timer", .default_value = od::num::u(0U)},
    {.index = 0x1A00, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(1U)},
    {.index = 0x1A00, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Statusword", .default_value = od::num::u(1614872592U)},
    {.index = 0x1A01, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(2U)},
    {.index = 0x1A01, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Statusword", .default_value = od::num::u(1614872592U)},
    {.index = 0x1A01, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Position", .default_value = od::num::u(1617166368U)},
    {.index = 0x1A10, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(1U)},
    {.index = 0x1A10, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Digital Inputs", .default_value = od::num::u(1627193376U)},
    {.index = 0x1A13, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(2U)},
    {.index = 0x1A13, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Following Position Error", .default_value = od::num::u(1626603552U)},
    {.index = 0x1A13, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Process Status Register", .default_value = od::num::u(537264160U)},
    {.index = 0x1A14, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(1U)},
    {.index = 0x1A14, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Current", .default_value = od::num::u(1618477072U)},
    {.index = 0x1A16, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(2U)},
    {.index = 0x1A16, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "I Force Actual", .default_value = od::num::u(537198624U)},
    {.index = 0x1A16, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Process Status Register", .default_value = od::num::u(537264160U)},
    {.index = 0x1A17, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .default_value = od::num::u(2U)},
    {.index = 0x1A17, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Statusword", .default_value = od::num::u(1614872592U)},
    {.index = 0x1A17, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "I Force Actual", .default_value = od::num::u(537198624U)},
    {.index = 0x2000, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "S-Curve Profile", .low = od::num::u(1U), .high = od::num::u(100U), .default_value = od::num::u(20U)},
    {.index = 0x2001, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "Reserved 2001", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(0U)},
    {.index = 0x2002, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "Reserved 2002", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(0U)},
    {.index = 0x2003, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "Reserved 2003", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(0U)},
    {.index = 0x2004, .type = od::data_type::integer8, .access_type = od::access::ro, .name = "XENAX Error Number", .low = od::num::i(0), .high = od::num::i(127), .default_value = od::num::i(0)},
    {.index = 0x2005, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "I_Force Actual", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x2006, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Process Status Register", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x2007, .type = od::data_type::unsigned16, .name = "PDO Cycle Time", .low = od::num::u(100U), .high = od::num::u(10000U), .default_value = od::num::u(1000U)},
    {.index = 0x2008, .type = od::data_type::visible_string, .access_type = od::access::ro, .name = "Motor Type"},
    {.index = 0x2009, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .name = "Limit Force", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x200A, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Force Actual Value", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5000, .type = od::data_type::unsigned32, .name = "Direct Commands", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(0U)},
    {.index = 0x5001, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "NumOfEntries", .default_value = od::num::u(45U)},
    {.index = 0x5001, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TS Tell Status", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TE Tell Error Number", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TP Tell Position", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TT Tell Temperature", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TOX Tell Output Hex", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TIX Tell Input Hex", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TMC Tell Motor Current", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TMT Tell Motion Time", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCP Tell Captured Position 1", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCP Tell Captured Position 2", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCP Tell Captured Position 3", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCP Tell Captured Position 4", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCP Tell Captured Position 5", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCP Tell Captured Position 6", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 15, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCP Tell Captured Position 7", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 16, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCP Tell Captured Position 8", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 17, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TH Tell Reference State", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 18, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "VER Version of Firmware", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 19, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "ACV Acceleration Variation (Jerk, scaled to 1000)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 20, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "I2TM Limit Value (scaled to 10)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 21, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "I2T Calculated Value (scaled to 10)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 22, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "IFPK I_Force Peak (FTM = 0) FPK Force Peak (FTM = 1,2)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 23, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TESM Tell SMU Error", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 24, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "DGMSO Detected Gantry Master Slave Offset", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 25, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SIFF Sector I_Force Curve Failed (FTM = 0) SFF Sector Force Curve Failed (FTM = 1,2) (binary notation, LSB = sector 1)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 26, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "IFPKn I_Force Peak Sector (FTM = 0) FPKn Force Peak Sector (FTM = 1,2) (select sector over Object 0x5003/050)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 27, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "FCV Force Calibration Valid", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 28, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TV Tell Velocity", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 29, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TPT Tell Process Time", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 30, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "VERL Version of Bootloader", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 31, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCPB Tell Capture Pos. Buffer 1", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 32, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCPB Tell Capture Pos. Buffer 2", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 33, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCPB Tell Capture Pos. Buffer 3", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 34, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCPB Tell Capture Pos. Buffer 4", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 35, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCPB Tell Capture Pos. Buffer 5", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 36, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCPB Tell Capture Pos. Buffer 6", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 37, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCPB Tell Capture Pos. Buffer 7", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 38, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TCPB Tell Capture Pos. Buffer 8", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 39, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TESMH Tell SMU Error History", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 40, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "GR Gear Ratio", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 41, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TTPS Tell Temperature Power Stage (Xvi75V8S only)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 42, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TVPSM Tell voltage power supply motor in [mV]", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 43, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "LARES linear axis resolution in [inc/m]", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 44, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "LAST linear axis stroke in [inc]", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5001, .sub = 45, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TTGS Tell trajectory state", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5002, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "NumOfEntries", .default_value = od::num::u(16U)},
    {.index = 0x5002, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "CO Clear Output Number", .low = od::num::i(1), .high = od::num::i(8)},
    {.index = 0x5002, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "EVT Event Activation", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5002, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "G Go Immediately", .low = od::num::i(-2147483648), .high = od::num::i(2147483647)},
    {.index = 0x5002, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "IX Start Index Number", .low = od::num::i(1), .high = od::num::i(50)},
    {.index = 0x5002, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "PG Start Program Number", .low = od::num::i(1), .high = od::num::i(63)},
    {.index = 0x5002, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "SO Set Output Number", .low = od::num::i(1), .high = od::num::i(8)},
    {.index = 0x5002, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "SOX Set Output Hex Mask", .low = od::num::i(0), .high = od::num::i(255)},
    {.index = 0x5002, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "TGD Set Trigger Position Downward", .low = od::num::i(-2000000000), .high = od::num::i(2000000000)},
    {.index = 0x5002, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "TGU Set Trigger Position Upward", .low = od::num::i(-2000000000), .high = od::num::i(2000000000)},
    {.index = 0x5002, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "ETI Enable Track Input", .low = od::num::i(0), .high = od::num::i(12)},
    {.index = 0x5002, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "DTI Disable Track Input", .low = od::num::i(0), .high = od::num::i(12)},
    {.index = 0x5002, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "PRF Start Profile Number", .low = od::num::i(1), .high = od::num::i(5)},
    {.index = 0x5002, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "CRDA Cogging Reference Drive Automatic", .low = od::num::i(0), .high = od::num::i(2147483647)},
    {.index = 0x5002, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "DIF Drive I_Force", .low = od::num::i(1), .high = od::num::i(10)},
    {.index = 0x5002, .sub = 15, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "CLIF Change Limit I_Force", .low = od::num::i(0), .high = od::num::i(2000)},
    {.index = 0x5002, .sub = 16, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::wo, .name = "DF Drive Force (Xvi75V8S only)", .low = od::num::i(1), .high = od::num::i(16)},
    {.index = 0x5003, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "NumOfEntries", .default_value = od::num::u(106U)},
    {.index = 0x5003, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .name = "AC Acceleration", .low = od::num::i(2000), .high = od::num::i(1000000000), .default_value = od::num::i(1000000)},
    {.index = 0x5003, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .name = "S-Curve Profile (in percent)", .low = od::num::i(1), .high = od::num::i(100), .default_value = od::num::i(20)},
    {.index = 0x5003, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SP Speed", .low = od::num::i(10), .high = od::num::i(100000000), .default_value = od::num::i(100000)},
    {.index = 0x5003, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PO Position (absolute)", .low = od::num::i(-2000000000), .high = od::num::i(2000000000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .name = "WA Way (relative)", .low = od::num::i(-2000000000), .high = od::num::i(2000000000), .default_value = od::num::i(20000)},
    {.index = 0x5003, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .name = "DP Deviation Position", .low = od::num::i(1), .high = od::num::i(1000000), .default_value = od::num::i(2000)},
    {.index = 0x5003, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .name = "DRHR Direction Reference", .low = od::num::i(0), .high = od::num::i(5), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .name = "DTP Deviation Target Position", .low = od::num::i(1), .high = od::num::i(10000), .default_value = od::num::i(100)},
    {.index = 0x5003, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ED Emergency Deceleration", .low = od::num::i(10000), .high = od::num::i(1000000000), .default_value = od::num::i(10000000)},
    {.index = 0x5003, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ILAS Input Low Active Selective", .low = od::num::i(0), .high = od::num::i(4095), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ILA Input Low Active", .low = od::num::i(0), .high = od::num::i(2), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .name = "IS Stop Current (Linear) Nominal Current (Rotative) scaled to 10mA", .low = od::num::i(10), .high = od::num::i(2000)},
    {.index = 0x5003, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SLPP Software Limit Position Positive", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SLPN Software Limit Position Negative", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 15, .object = od::object_code::array, .type = od::data_type::integer32, .name = "MD Mode", .low = od::num::i(0), .high = od::num::i(13), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 16, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ML Mass Load (WebMotion: Payload / Inertia)", .low = od::num::i(0), .high = od::num::i(100000000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 17, .object = od::object_code::array, .type = od::data_type::integer32, .name = "BWC Bandwidth Current Controller (WebMotion: GAIN CUR)", .low = od::num::i(5), .high = od::num::i(5000), .default_value = od::num::i(1500)},
    {.index = 0x5003, .sub = 18, .object = od::object_code::array, .type = od::data_type::integer32, .name = "BWP Bandwidth Position Controller (WebMotion: GAIN POS)", .low = od::num::i(1), .high = od::num::i(5000), .default_value = od::num::i(50)},
    {.index = 0x5003, .sub = 19, .object = od::object_code::array, .type = od::data_type::integer32, .name = "IR Run Current (Linear) Torque Current (Rotative) scaled to 10mA", .low = od::num::i(10), .high = od::num::i(2000), .default_value = od::num::i(1200)},
    {.index = 0x5003, .sub = 20, .object = od::object_code::array, .type = od::data_type::integer32, .name = "NIX Preselected Index Number", .low = od::num::i(1), .high = od::num::i(50)},
    {.index = 0x5003, .sub = 21, .object = od::object_code::array, .type = od::data_type::integer32, .name = "AIX Acceleration of selected Index", .low = od::num::i(2), .high = od::num::i(1000000), .default_value = od::num::i(1000)},
    {.index = 0x5003, .sub = 22, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SIX Speed of selected Index", .low = od::num::i(10), .high = od::num::i(100000000), .default_value = od::num::i(100000)},
    {.index = 0x5003, .sub = 23, .object = od::object_code::array, .type = od::data_type::integer32, .name = "DIX Distance of selected Index (depends on absolute or relative index definition)", .low = od::num::i(-2000000000), .high = od::num::i(2000000000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 24, .object = od::object_code::array, .type = od::data_type::integer32, .name = "CI Card Identifier", .low = od::num::i(0), .high = od::num::i(255), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 25, .object = od::object_code::array, .type = od::data_type::integer32, .name = "GSID Gantry Slave Identifier", .low = od::num::i(0), .high = od::num::i(4), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 26, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FQC Filter Quality Current", .low = od::num::i(500), .high = od::num::i(100000), .default_value = od::num::i(5000)},
    {.index = 0x5003, .sub = 27, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FFC Filter Frequency Current", .low = od::num::i(0), .high = od::num::i(2000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 28, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ICP Increments per Puls", .low = od::num::i(0), .high = od::num::i(50), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 29, .object = od::object_code::array, .type = od::data_type::integer32, .name = "INH Input Home Sensor", .low = od::num::i(1), .high = od::num::i(8), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 30, .object = od::object_code::array, .type = od::data_type::integer32, .name = "OVRD Speed Override", .low = od::num::i(0), .high = od::num::i(100), .default_value = od::num::i(100)},
    {.index = 0x5003, .sub = 31, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PWRT Phasing Rotative w/o HALL", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 32, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SOA Set Output Activity", .low = od::num::i(0), .high = od::num::i(255), .default_value = od::num::i(255)},
    {.index = 0x5003, .sub = 33, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SOT Set Output Type", .low = od::num::i(0), .high = od::num::i(65535), .default_value = od::num::i(21845)},
    {.index = 0x5003, .sub = 34, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SR Synchronous Ratio", .low = od::num::i(-1000), .high = od::num::i(1000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 35, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "CAB CAN Baud Rate", .low = od::num::i(10000), .high = od::num::i(1000000), .default_value = od::num::i(500000)},
    {.index = 0x5003, .sub = 36, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "ROID Rotative Motor Identifier", .low = od::num::i(0), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 37, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Reserved", .low = od::num::i(0), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 38, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Reserved", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 39, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SIFS Sector I_Force Start (FTM = 0) SFS Sector Force Start (FTM = 1,2)", .low = od::num::i(-2000000000), .high = od::num::i(2000000000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 40, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SIFE Sector I_Force End (FTM = 0) SFE Sector Force End (FTM = 1,2)", .low = od::num::i(-2000000000), .high = od::num::i(2000000000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 41, .object = od::object_code::array, .type = od::data_type::integer32, .name = "IFL I_Force Low", .low = od::num::i(-2312), .high = od::num::i(2000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 42, .object = od::object_code::array, .type = od::data_type::integer32, .name = "IFH I_Force High", .low = od::num::i(-2312), .high = od::num::i(2000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 43, .object = od::object_code::array, .type = od::data_type::integer32, .name = "MLPN Mechanical Limit Position Negative", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 44, .object = od::object_code::array, .type = od::data_type::integer32, .name = "MLPP Mechanical Limit Position Positive", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 45, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PGMSO Preset Gantry Master Slave Offset", .low = od::num::i(-2000000000), .high = od::num::i(2000000000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 46, .object = od::object_code::array, .type = od::data_type::integer32, .name = "BRKD Brake delay", .low = od::num::i(1), .high = od::num::i(1000), .default_value = od::num::i(100)},
    {.index = 0x5003, .sub = 47, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Reserved", .low = od::num::i(0), .high = od::num::i(2), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 48, .object = od::object_code::array, .type = od::data_type::integer32, .name = "LIF Limit I_Force", .low = od::num::i(0), .high = od::num::i(2000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 49, .object = od::object_code::array, .type = od::data_type::integer32, .name = "TYIX Type of Index", .low = od::num::i(1), .high = od::num::i(2), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 50, .object = od::object_code::array, .type = od::data_type::integer32, .name = "NSEC Preselected Sector Number", .low = od::num::i(1), .high = od::num::i(10), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 51, .object = od::object_code::array, .type = od::data_type::integer32, .name = "STCX Sector Transition Configuration (Hex Mask)", .low = od::num::i(0), .high = od::num::i(65535), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 52, .object = od::object_code::array, .type = od::data_type::integer32, .name = "NDIF Preselected Drive I_Force Number (FTM = 0) NDF Preselected Drive Force Number (FTM = 1,2)", .low = od::num::i(1), .high = od::num::i(10), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 53, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ADIF Acceleration of selected Drive I_Force (FTM = 0) ADF Acceleration of selected Drive Force (FTM = 1,2)", .low = od::num::i(2), .high = od::num::i(1000000), .default_value = od::num::i(1000)},
    {.index = 0x5003, .sub = 54, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SDIF Speed of selected Drive I_Force (FTM = 0) SDF Speed of selected Drive Force (FTM = 1,2)", .low = od::num::i(10), .high = od::num::i(100000000), .default_value = od::num::i(100000)},
    {.index = 0x5003, .sub = 55, .object = od::object_code::array, .type = od::data_type::integer32, .name = "IDIF I_Force Limit of selected Drive I_Force", .low = od::num::i(1), .high = od::num::i(2000), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 56, .object = od::object_code::array, .type = od::data_type::integer32, .name = "DDIF Direction of selected Drive I_Force (FTM = 0) DDF Direction of selected Drive Force (FTM = 1,2)", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 57, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SSEC Select Sectors (binary notation, LSB = sector 1)", .low = od::num::i(0), .high = od::num::i(1023), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 58, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SSO Set Sector Offset", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 59, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ENCPD Encoder Plausibility Checking Disable", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 60, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SPAD Set Point ACK disable", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 61, .object = od::object_code::array, .type = od::data_type::integer32, .name = "RXZP ROTAX Z-Position", .low = od::num::i(0), .high = od::num::i(0), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 62, .object = od::object_code::array, .type = od::data_type::integer32, .name = "DRH Dir Home", .low = od::num::i(1), .high = od::num::i(2), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 63, .object = od::object_code::array, .type = od::data_type::integer32, .name = "DRZ Z-Mark", .low = od::num::i(1), .high = od::num::i(3), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 64, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FQS Filter Quality Speed", .low = od::num::i(500), .high = od::num::i(100000), .default_value = od::num::i(5000)},
    {.index = 0x5003, .sub = 65, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FFS Filter Frequency Speed", .low = od::num::i(0), .high = od::num::i(2000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 66, .object = od::object_code::array, .type = od::data_type::integer32, .name = "EBMD Enhanced Bandwidth Mode Disabled", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 67, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Reserved", .low = od::num::i(0), .high = od::num::i(1000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 68, .object = od::object_code::array, .type = od::data_type::integer32, .name = "AIXD Acceleration of dynamically selected Index", .low = od::num::i(2), .high = od::num::i(1000000), .default_value = od::num::i(1000)},
    {.index = 0x5003, .sub = 69, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SIXD Speed of dynamically selected Index", .low = od::num::i(10), .high = od::num::i(100000000), .default_value = od::num::i(100000)},
    {.index = 0x5003, .sub = 70, .object = od::object_code::array, .type = od::data_type::integer32, .name = "DIXD Distance of dynamically selected Index (depends on absolute or relative index definition)", .low = od::num::i(-2000000000), .high = od::num::i(2000000000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 71, .object = od::object_code::array, .type = od::data_type::integer32, .name = "TYIXD Type of dynamically selected Index", .low = od::num::i(1), .high = od::num::i(2), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 72, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PPSD Pole Placement Stability Dynamics", .low = od::num::i(-50), .high = od::num::i(50), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 73, .object = od::object_code::array, .type = od::data_type::integer32, .name = "IFDCS I_Force Drift Compensation Setting", .low = od::num::i(0), .high = od::num::i(7), .default_value = od::num::i(3)},
    {.index = 0x5003, .sub = 74, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Reserved", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 75, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SORF Swing Out Reduction Frequency", .low = od::num::i(0), .high = od::num::i(1000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 76, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SORD Swing Out Reduction Damping", .low = od::num::i(0), .high = od::num::i(50), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 77, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Reserved", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 78, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Reserved", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 79, .object = od::object_code::array, .type = od::data_type::integer32, .name = "AVF Filter Frequency for Current Shaper", .low = od::num::i(0), .high = od::num::i(2000), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 80, .object = od::object_code::array, .type = od::data_type::integer32, .name = "AVD Damping Ratio for Current Shaper", .low = od::num::i(1), .high = od::num::i(50), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 81, .object = od::object_code::array, .type = od::data_type::integer32, .name = "NOF Preselected Output Function", .low = od::num::i(1), .high = od::num::i(8), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 82, .object = od::object_code::array, .type = od::data_type::integer32, .name = "TYOF Type of Output Function", .low = od::num::i(0), .high = od::num::i(13), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 83, .object = od::object_code::array, .type = od::data_type::integer32, .name = "NIF Preselected Input Function", .low = od::num::i(1), .high = od::num::i(8), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 84, .object = od::object_code::array, .type = od::data_type::integer32, .name = "TYIF Type of Input Function", .low = od::num::i(0), .high = od::num::i(22), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 85, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PAIF Parameter A of Input Function", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 86, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PBIF Parameter B of Input Function", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 87, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PCIF Parameter C of Input Function", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 88, .object = od::object_code::array, .type = od::data_type::integer32, .name = "CLF Change Limit Force (Xvi75V8S only)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 89, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FD Force of selected Drive Force (Xvi75V8S only)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 90, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FH Force High (Xvi75V8S only)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 91, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FL Force Low (Xvi75V8S only)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 92, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FTM Forceteq Mode (Xvi75V8S only)", .low = od::num::i(0), .high = od::num::i(2), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 93, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SQBW Signateq Bandwidth (Xvi75V8S only)", .low = od::num::i(100), .high = od::num::i(5000), .default_value = od::num::i(500)},
    {.index = 0x5003, .sub = 94, .object = od::object_code::array, .type = od::data_type::integer32, .name = "MM Motor Manufacturer (Xvi75V8S only)", .low = od::num::i(0), .high = od::num::i(2), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 95, .object = od::object_code::array, .type = od::data_type::integer32, .name = "AREF Automatic Reference", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 96, .object = od::object_code::array, .type = od::data_type::integer32, .name = "EGMSO Enable user defined gantry Master/Slave offset", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 97, .object = od::object_code::array, .type = od::data_type::integer32, .name = "VMTAE Virtual multiturn for rotative motors with absolute encoder", .low = od::num::i(0), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 98, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ENAR Enable absolute reference", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 99, .object = od::object_code::array, .type = od::data_type::integer32, .name = "CTAB Correction Table State", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 100, .object = od::object_code::array, .type = od::data_type::integer32, .name = "APSN number of program to auto start", .low = od::num::i(0), .high = od::num::i(63), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 101, .object = od::object_code::array, .type = od::data_type::integer32, .name = "APSD Automatic program start delay[ms]", .low = od::num::i(0), .high = od::num::i(65535), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 102, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PMHSD Profinet MC_Home support disable", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 103, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FCSM Force Calibration Storage mode", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 104, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SOD P402 Switch on at transition 3 disable", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5003, .sub = 105, .object = od::object_code::array, .type = od::data_type::integer32, .name = "GCME Gantry Coupled Mode Enable", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(1)},
    {.index = 0x5003, .sub = 106, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FBCM Force buffered CSP mode", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5004, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "NumOfEntries", .default_value = od::num::u(11U)},
    {.index = 0x5004, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .name = "POL Pole Pairs", .low = od::num::i(0), .high = od::num::i(100), .default_value = od::num::i(0)},
    {.index = 0x5004, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ENC Encoder Increments (Rotative, 1 turn of motor shaft)", .low = od::num::i(10), .high = od::num::i(10000000), .default_value = od::num::i(24000)},
    {.index = 0x5004, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PHD Phase Direction", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5004, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .name = "PHO Phase Offset", .low = od::num::i(0), .high = od::num::i(359), .default_value = od::num::i(0)},
    {.index = 0x5004, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .name = "MAMO Slider Mass (LINAX / ELAX) Rotor Inertia (Rotative)", .low = od::num::i(0), .high = od::num::i(10000000)},
    {.index = 0x5004, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FCM Force Constant of Motor", .low = od::num::i(0), .high = od::num::i(100000000)},
    {.index = 0x5004, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .name = "LPH Inductance Phase-Phase", .low = od::num::i(0), .high = od::num::i(100000)},
    {.index = 0x5004, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .name = "RPH Resistance Phase-Phase", .low = od::num::i(0), .high = od::num::i(100000)},
    {.index = 0x5004, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FFDY Frictional Force Dynamic", .low = od::num::i(0), .high = od::num::i(10000)},
    {.index = 0x5004, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FFST Frictional Force Static", .low = od::num::i(0), .high = od::num::i(10000)},
    {.index = 0x5004, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .name = "DMLPP Detected Mechanical Limit Position Positive", .low = od::num::i(0), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "NumOfEntries", .default_value = od::num::u(13U)},
    {.index = 0x5005, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "VERS Version SMU", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SLS Timeout", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "Speed Limit", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "Stop Timeout", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "Position Window", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SFTRD Input Configuration SMU", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "TESM Tell SMU Error", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SMU Master Error Bitfeld", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SMU Slave Error Bitfeld", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SMU Master Info Bitfeld", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SMU Slave Info Bitfeld", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SPC Safety Parameter CRC", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5005, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SPCMAC Safety Parameter and MAC Adress CRC (Xvi75V8S only)", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5006, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "NumOfEntries", .default_value = od::num::u(10U)},
    {.index = 0x5006, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .name = "EGW Set Gateway Address", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(-1062731263)},
    {.index = 0x5006, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .name = "EIP Set IP Address", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(-1062731164)},
    {.index = 0x5006, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .name = "ENM Set Net Mask", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(-1024)},
    {.index = 0x5006, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "EMAC Read MAC Address 3 high Bytes", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5006, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "EMAC Read MAC Address 3 low Bytes", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5006, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .name = "EPRT Set Port Number", .low = od::num::i(1), .high = od::num::i(65535), .default_value = od::num::i(10001)},
    {.index = 0x5006, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "LICR Show Installed Licences", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5006, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SERB Set Baud Rate on Serial Interface", .low = od::num::i(9600), .high = od::num::i(345600), .default_value = od::num::i(115200)},
    {.index = 0x5006, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "WebMotion Version", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5006, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "WebMotion Boot Version", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5010, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "NumOfEntries", .default_value = od::num::u(14U)},
    {.index = 0x5010, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SQVER Signateq Firmware Version", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SQBW Signateq Bandwidth", .low = od::num::i(100), .high = od::num::i(5000), .default_value = od::num::i(500)},
    {.index = 0x5010, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SQSNF Signateq Sensor Nominal Force", .low = od::num::i(0), .high = od::num::i(200000), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SQMRP Signateq Measurement Range", .low = od::num::i(0), .high = od::num::i(200000), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 5, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Reserved", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 6, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SQSS Signateq Sensor Sensitivity", .low = od::num::i(0), .high = od::num::i(25000000), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 7, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SQSFT Signateq Sensor Force Type", .low = od::num::i(0), .high = od::num::i(2), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 8, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SQCM Signateq Calibration Mode", .low = od::num::i(0), .high = od::num::i(2), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 9, .object = od::object_code::array, .type = od::data_type::integer32, .name = "SQFD Signateq Force Direction", .low = od::num::i(0), .high = od::num::i(2), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 10, .object = od::object_code::array, .type = od::data_type::integer32, .name = "LFRMS Limit Force Reached Maximum Speed", .low = od::num::i(0), .high = od::num::i(9000000), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 11, .object = od::object_code::array, .type = od::data_type::integer32, .name = "CLFO Clear force offset", .low = od::num::i(0), .high = od::num::i(1), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 12, .object = od::object_code::array, .type = od::data_type::integer32, .access_type = od::access::ro, .name = "SQAC Signateq available calibrations", .low = od::num::i(0), .high = od::num::i(7), .default_value = od::num::i(0)},
    {.index = 0x5010, .sub = 13, .object = od::object_code::array, .type = od::data_type::integer32, .name = "BWFP Bandwidth for forceteq pro controller", .low = od::num::i(1), .high = od::num::i(1000), .default_value = od::num::i(50)},
    {.index = 0x5010, .sub = 14, .object = od::object_code::array, .type = od::data_type::integer32, .name = "FTPES Forceteq Pro Elastic Spring Constant", .low = od::num::i(1), .high = od::num::i(10000000), .default_value = od::num::i(1000)},
    {.index = 0x5011, .type = od::data_type::visible_string, .name = "Signateq Sensor Model Type (SQSMT)"},
    {.index = 0x5012, .type = od::data_type::visible_string, .name = "Signateq Sensor Serial Number (SQSSN)"},
    {.index = 0x5020, .type = od::data_type::visible_string, .access_type = od::access::ro, .size = 8, .name = "Tell Error String (TES)", .default_text = "no error"},
    {.index = 0x5021, .type = od::data_type::visible_string, .name = "Servo identification string (SID)"},
    {.index = 0x603F, .type = od::data_type::unsigned16, .access_type = od::access::ro, .name = "Error Code", .low = od::num::u(0U), .high = od::num::u(65535U), .default_value = od::num::u(0U)},
    {.index = 0x6040, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .name = "Controlword", .low = od::num::u(0U), .high = od::num::u(65535U), .default_value = od::num::u(0U)},
    {.index = 0x6041, .type = od::data_type::unsigned16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Statusword", .low = od::num::u(0U), .high = od::num::u(65535U), .default_value = od::num::u(0U)},
    {.index = 0x6060, .type = od::data_type::integer8, .pdo = od::pdo_mapping::yes, .name = "Modes of Operation Requested", .low = od::num::i(-2), .high = od::num::i(10), .default_value = od::num::i(0)},
    {.index = 0x6061, .type = od::data_type::integer8, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Modes of Operation Display", .low = od::num::i(-2), .high = od::num::i(10), .default_value = od::num::i(0)},
    {.index = 0x6064, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Position Actual Value", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x6065, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "Following Position Error Window", .low = od::num::u(1U), .high = od::num::u(1000000U), .default_value = od::num::u(2000U)},
    {.index = 0x6067, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "Target Position Window", .low = od::num::u(1U), .high = od::num::u(10000U), .default_value = od::num::u(100U)},
    {.index = 0x6068, .type = od::data_type::unsigned16, .name = "Position Window Time", .low = od::num::u(0U), .high = od::num::u(1000U), .default_value = od::num::u(0U)},
    {.index = 0x606C, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Velocity Actual Value", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x6073, .type = od::data_type::unsigned16, .pdo = od::pdo_mapping::yes, .name = "Limit I_Force", .low = od::num::u(0U), .high = od::num::u(2000U), .default_value = od::num::u(0U)},
    {.index = 0x6078, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Motor Current Actual Value", .low = od::num::i(-20000), .high = od::num::i(20000)},
    {.index = 0x607A, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .name = "Target Position", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x607D, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest Sub-index Value", .low = od::num::u(2U), .high = od::num::u(2U), .default_value = od::num::u(2U)},
    {.index = 0x607D, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Software Position Limit Left", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x607D, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer32, .name = "Software Position Limit Right", .low = od::num::i(-2147483648), .high = od::num::i(2147483647), .default_value = od::num::i(0)},
    {.index = 0x6081, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "Speed", .low = od::num::u(10U), .high = od::num::u(100000000U), .default_value = od::num::u(100000U)},
    {.index = 0x6083, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "Acceleration", .low = od::num::u(2000U), .high = od::num::u(1000000000U), .default_value = od::num::u(1000000U)},
    {.index = 0x6085, .type = od::data_type::unsigned32, .name = "Quick Stop Deceleration", .low = od::num::u(10000U), .high = od::num::u(1000000000U), .default_value = od::num::u(10000000U)},
    {.index = 0x6098, .type = od::data_type::integer8, .name = "Reference Methods", .low = od::num::i(1), .high = od::num::i(15), .default_value = od::num::i(1)},
    {.index = 0x6099, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest Sub-index Value", .low = od::num::u(2U), .high = od::num::u(2U), .default_value = od::num::u(2U)},
    {.index = 0x6099, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .name = "Reference-Speed searching external Reference sensor", .low = od::num::u(0U), .high = od::num::u(250000U), .default_value = od::num::u(1000U)},
    {.index = 0x6099, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .name = "Z-Speed searching internal encoder Z-mark", .low = od::num::u(0U), .high = od::num::u(100000U), .default_value = od::num::u(500U)},
    {.index = 0x60B1, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .name = "Velocity Offset", .low = od::num::i(-9000000), .high = od::num::i(9000000), .default_value = od::num::i(0)},
    {.index = 0x60B2, .type = od::data_type::integer16, .pdo = od::pdo_mapping::yes, .name = "Torque Offset", .low = od::num::i(-32768), .high = od::num::i(32767), .default_value = od::num::i(0)},
    {.index = 0x60C2, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest Sub-index Value", .low = od::num::u(2U), .high = od::num::u(2U), .default_value = od::num::u(2U)},
    {.index = 0x60C2, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Base value", .low = od::num::u(0U), .high = od::num::u(255U), .default_value = od::num::u(1U)},
    {.index = 0x60C2, .sub = 2, .object = od::object_code::record, .type = od::data_type::integer8, .name = "10^EXPONENT", .low = od::num::i(-128), .high = od::num::i(63), .default_value = od::num::i(-3)},
    {.index = 0x60F4, .type = od::data_type::integer32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Actual Position Following Error", .low = od::num::i(-2147483648), .high = od::num::i(2147483647)},
    {.index = 0x60FD, .type = od::data_type::unsigned32, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Digital Inputs", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(0U)},
    {.index = 0x60FE, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest Sub-index Value", .low = od::num::u(1U), .high = od::num::u(2U), .default_value = od::num::u(2U)},
    {.index = 0x60FE, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "Output Bit", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(0U)},
    {.index = 0x60FE, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .name = "Output Mask (not supported)", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(0U)},
    {.index = 0x60FF, .type = od::data_type::integer32, .pdo = od::pdo_mapping::yes, .name = "Target Velocity", .low = od::num::i(-9000000), .high = od::num::i(9000000), .default_value = od::num::i(0)},
    {.index = 0x6502, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Supported Modes of Operation", .low = od::num::u(65697U), .high = od::num::u(65697U), .default_value = od::num::u(65697U)},
    {.index = 0x6505, .type = od::data_type::visible_string, .access_type = od::access::ro, .size = 26, .name = "Product Website Address", .default_text = "http://www.jennyscience.ch"},
}};

inline constexpr od::dictionary dictionary{entries};
static_assert(dictionary.is_valid());

inline constexpr const od::entry &device_type = entries[0]; // 0x1000
inline constexpr const od::entry &error_register = entries[1]; // 0x1001
inline constexpr const od::entry &cob_id_sync = entries[2]; // 0x1005
inline constexpr const od::entry &manufacturer_device_name = entries[3]; // 0x1008
inline constexpr const od::entry &manufacturer_hardware_version = entries[4]; // 0x1009
inline constexpr const od::entry &manufacturer_software_version = entries[5]; // 0x100A
inline constexpr const od::entry &cob_id_emcy = entries[6]; // 0x1014
inline constexpr const od::entry &producer_heartbeat_time = entries[7]; // 0x1017
inline constexpr od::object identity_object{0x1018, od::object_code::record, "Identity Object", {entries.data() + 8, 5}};
inline constexpr const od::entry &identity_object_nbr_of_entries = entries[8];
inline constexpr const od::entry &identity_object_vendor_id = entries[9];
inline constexpr const od::entry &identity_object_product_code = entries[10];
inline constexpr const od::entry &identity_object_revision_number = entries[11];
inline constexpr const od::entry &identity_object_serial_number = entries[12];
inline constexpr od::object server_sdo_parameter_1{0x1200, od::object_code::record, "Server SDO Parameter 1", {entries.data() + 13, 3}};
inline constexpr const od::entry &server_sdo_parameter_1_nbr_of_entries = entries[13];
inline constexpr const od::entry &server_sdo_parameter_1_cob_id_client_server = entries[14];
inline constexpr const od::entry &server_sdo_parameter_1_cob_id_server_client = entries[15];
inline constexpr od::object receive_pdo_comm_param_1{0x1400, od::object_code::record, "Receive PDO Comm Param 1", {entries.data() + 16, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_1_nbr_of_entries = entries[16];
inline constexpr const od::entry &receive_pdo_comm_param_1_cob_id = entries[17];
inline constexpr const od::entry &receive_pdo_comm_param_1_transmission_type = entries[18];
inline constexpr const od::entry &receive_pdo_comm_param_1_inhibit_time = entries[19];
inline constexpr const od::entry &receive_pdo_comm_param_1_compatibility_entry = entries[20];
inline constexpr const od::entry &receive_pdo_comm_param_1_event_timer = entries[21];
inline constexpr od::object receive_pdo_comm_param_2{0x1401, od::object_code::record, "Receive PDO Comm Param 2", {entries.data() + 22, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_2_nbr_of_entries = entries[22];
inline constexpr const od::entry &receive_pdo_comm_param_2_cob_id = entries[23];
inline constexpr const od::entry &receive_pdo_comm_param_2_transmission_type = entries[24];
inline constexpr const od::entry &receive_pdo_comm_param_2_inhibit_time = entries[25];
inline constexpr const od::entry &receive_pdo_comm_param_2_compatibility_entry = entries[26];
inline constexpr const od::entry &receive_pdo_comm_param_2_event_timer = entries[27];
inline constexpr od::object receive_pdo_comm_param_17{0x1410, od::object_code::record, "Receive PDO Comm Param 17", {entries.data() + 28, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_17_nbr_of_entries = entries[28];
inline constexpr const od::entry &receive_pdo_comm_param_17_cob_id = entries[29];
inline constexpr const od::entry &receive_pdo_comm_param_17_transmission_type = entries[30];
inline constexpr const od::entry &receive_pdo_comm_param_17_inhibit_time = entries[31];
inline constexpr const od::entry &receive_pdo_comm_param_17_compatibility_entry = entries[32];
inline constexpr const od::entry &receive_pdo_comm_param_17_event_timer = entries[33];
inline constexpr od::object receive_pdo_comm_param_18{0x1411, od::object_code::record, "Receive PDO Comm Param 18", {entries.data() + 34, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_18_nbr_of_entries = entries[34];
inline constexpr const od::entry &receive_pdo_comm_param_18_cob_id = entries[35];
inline constexpr const od::entry &receive_pdo_comm_param_18_transmission_type = entries[36];
inline constexpr const od::entry &receive_pdo_comm_param_18_inhibit_time = entries[37];
inline constexpr const od::entry &receive_pdo_comm_param_18_compatibility_entry = entries[38];
inline constexpr const od::entry &receive_pdo_comm_param_18_event_timer = entries[39];
inline constexpr od::object receive_pdo_comm_param_19{0x1412, od::object_code::record, "Receive PDO Comm Param 19", {entries.data() + 40, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_19_nbr_of_entries = entries[40];
inline constexpr const od::entry &receive_pdo_comm_param_19_cob_id = entries[41];
inline constexpr const od::entry &receive_pdo_comm_param_19_transmission_type = entries[42];
inline constexpr const od::entry &receive_pdo_comm_param_19_inhibit_time = entries[43];
inline constexpr const od::entry &receive_pdo_comm_param_19_compatibility_entry = entries[44];
inline constexpr const od::entry &receive_pdo_comm_param_19_event_timer = entries[45];
inline constexpr od::object receive_pdo_comm_param_20{0x1413, od::object_code::record, "Receive PDO Comm Param 20", {entries.data() + 46, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_20_nbr_of_entries = entries[46];
inline constexpr const od::entry &receive_pdo_comm_param_20_cob_id = entries[47];
inline constexpr const od::entry &receive_pdo_comm_param_20_transmission_type = entries[48];
inline constexpr const od::entry &receive_pdo_comm_param_20_inhibit_time = entries[49];
inline constexpr const od::entry &receive_pdo_comm_param_20_compatibility_entry = entries[50];
inline constexpr const od::entry &receive_pdo_comm_param_20_event_timer = entries[51];
inline constexpr od::object receive_pdo_comm_param_21{0x1414, od::object_code::record, "Receive PDO Comm Param 21", {entries.data() + 52, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_21_nbr_of_entries = entries[52];
inline constexpr const od::entry &receive_pdo_comm_param_21_cob_id = entries[53];
inline constexpr const od::entry &receive_pdo_comm_param_21_transmission_type = entries[54];
inline constexpr const od::entry &receive_pdo_comm_param_21_inhibit_time = entries[55];
inline constexpr const od::entry &receive_pdo_comm_param_21_compatibility_entry = entries[56];
inline constexpr const od::entry &receive_pdo_comm_param_21_event_timer = entries[57];
inline constexpr od::object receive_pdo_comm_param_22{0x1415, od::object_code::record, "Receive PDO Comm Param 22", {entries.data() + 58, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_22_nbr_of_entries = entries[58];
inline constexpr const od::entry &receive_pdo_comm_param_22_cob_id = entries[59];
inline constexpr const od::entry &receive_pdo_comm_param_22_transmission_type = entries[60];
inline constexpr const od::entry &receive_pdo_comm_param_22_inhibit_time = entries[61];
inline constexpr const od::entry &receive_pdo_comm_param_22_compatibility_entry = entries[62];
inline constexpr const od::entry &receive_pdo_comm_param_22_event_timer = entries[63];
inline constexpr od::object receive_pdo_comm_param_23{0x1416, od::object_code::record, "Receive PDO Comm Param 23", {entries.data() + 64, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_23_nbr_of_entries = entries[64];
inline constexpr const od::entry &receive_pdo_comm_param_23_cob_id = entries[65];
inline constexpr const od::entry &receive_pdo_comm_param_23_transmission_type = entries[66];
inline constexpr const od::entry &receive_pdo_comm_param_23_inhibit_time = entries[67];
inline constexpr const od::entry &receive_pdo_comm_param_23_compatibility_entry = entries[68];
inline constexpr const od::entry &receive_pdo_comm_param_23_event_timer = entries[69];
inline constexpr od::object receive_pdo_comm_param_24{0x1417, od::object_code::record, "Receive PDO Comm Param 24", {entries.data() + 70, 6}};
inline constexpr const od::entry &receive_pdo_comm_param_24_nbr_of_entries = entries[70];
inline constexpr const od::entry &receive_pdo_comm_param_24_cob_id = entries[71];
inline constexpr const od::entry &receive_pdo_comm_param_24_transmission_type = entries[72];
inline constexpr const od::entry &receive_pdo_comm_param_24_inhibit_time = entries[73];
inline constexpr const od::entry &receive_pdo_comm_param_24_compatibility_entry = entries[74];
inline constexpr const od::entry &receive_pdo_comm_param_24_event_timer = entries[75];
inline constexpr od::object receive_pdo_mapping_param_1{0x1600, od::object_code::record, "Receive PDO Mapping Param 1", {entries.data() + 76, 2}};
inline constexpr const od::entry &receive_pdo_mapping_param_1_nbr_of_entries = entries[76];
inline constexpr const od::entry &receive_pdo_mapping_param_1_controlword = entries[77];
inline constexpr od::object receive_pdo_mapping_param_2{0x1601, od::object_code::record, "Receive PDO Mapping Param 2", {entries.data() + 78, 3}};
inline constexpr const od::entry &receive_pdo_mapping_param_2_nbr_of_entries = entries[78];
inline constexpr const od::entry &receive_pdo_mapping_param_2_controlword = entries[79];
inline constexpr const od::entry &receive_pdo_mapping_param_2_target_position = entries[80];
inline constexpr od::object receive_pdo_mapping_param_17{0x1610, od::object_code::record, "Receive PDO Mapping Param 17", {entries.data() + 81, 2}};
inline constexpr const od::entry &receive_pdo_mapping_param_17_nbr_of_entries = entries[81];
inline constexpr const od::entry &receive_pdo_mapping_param_17_digital_outputs = entries[82];
inline constexpr od::object receive_pdo_mapping_param_18{0x1611, od::object_code::record, "Receive PDO Mapping Param 18", {entries.data() + 83, 3}};
inline constexpr const od::entry &receive_pdo_mapping_param_18_nbr_of_entries = entries[83];
inline constexpr const od::entry &receive_pdo_mapping_param_18_acceleration = entries[84];
inline constexpr const od::entry &receive_pdo_mapping_param_18_s_curve = entries[85];
inline constexpr od::object receive_pdo_mapping_param_19{0x1612, od::object_code::record, "Receive PDO Mapping Param 19", {entries.data() + 86, 2}};
inline constexpr const od::entry &receive_pdo_mapping_param_19_nbr_of_entries = entries[86];
inline constexpr const od::entry &receive_pdo_mapping_param_19_speed = entries[87];
inline constexpr od::object receive_pdo_mapping_param_20{0x1613, od::object_code::record, "Receive PDO Mapping Param 20", {entries.data() + 88, 3}};
inline constexpr const od::entry &receive_pdo_mapping_param_20_nbr_of_entries = entries[88];
inline constexpr const od::entry &receive_pdo_mapping_param_20_following_position_error_window = entries[89];
inline constexpr const od::entry &receive_pdo_mapping_param_20_target_position_error_window = entries[90];
inline constexpr od::object receive_pdo_mapping_param_21{0x1614, od::object_code::record, "Receive PDO Mapping Param 21", {entries.data() + 91, 2}};
inline constexpr const od::entry &receive_pdo_mapping_param_21_nbr_of_entries = entries[91];
inline constexpr const od::entry &receive_pdo_mapping_param_21_i_force_max = entries[92];
inline constexpr od::object receive_pdo_mapping_param_24{0x1617, od::object_code::record, "Receive PDO Mapping Param 24", {entries.data() + 93, 3}};
inline constexpr const od::entry &receive_pdo_mapping_param_24_nbr_of_entries = entries[93];
inline constexpr const od::entry &receive_pdo_mapping_param_24_controlword = entries[94];
inline constexpr const od::entry &receive_pdo_mapping_param_24_reserved_for_future = entries[95];
inline constexpr od::object transmit_pdo_comm_param_1{0x1800, od::object_code::record, "Transmit PDO Comm Param 1", {entries.data() + 96, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_1_nbr_of_entries = entries[96];
inline constexpr const od::entry &transmit_pdo_comm_param_1_cob_id = entries[97];
inline constexpr const od::entry &transmit_pdo_comm_param_1_transmission_type = entries[98];
inline constexpr const od::entry &transmit_pdo_comm_param_1_inhibit_time = entries[99];
inline constexpr const od::entry &transmit_pdo_comm_param_1_compatibility_entry = entries[100];
inline constexpr const od::entry &transmit_pdo_comm_param_1_event_timer = entries[101];
inline constexpr od::object transmit_pdo_comm_param_2{0x1801, od::object_code::record, "Transmit PDO Comm Param 2", {entries.data() + 102, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_2_nbr_of_entries = entries[102];
inline constexpr const od::entry &transmit_pdo_comm_param_2_cob_id = entries[103];
inline constexpr const od::entry &transmit_pdo_comm_param_2_transmission_type = entries[104];
inline constexpr const od::entry &transmit_pdo_comm_param_2_inhibit_time = entries[105];
inline constexpr const od::entry &transmit_pdo_comm_param_2_compatibility_entry = entries[106];
inline constexpr const od::entry &transmit_pdo_comm_param_2_event_timer = entries[107];
inline constexpr od::object transmit_pdo_comm_param_17{0x1810, od::object_code::record, "Transmit PDO Comm Param 17", {entries.data() + 108, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_17_nbr_of_entries = entries[108];
inline constexpr const od::entry &transmit_pdo_comm_param_17_cob_id = entries[109];
inline constexpr const od::entry &transmit_pdo_comm_param_17_transmission_type = entries[110];
inline constexpr const od::entry &transmit_pdo_comm_param_17_inhibit_time = entries[111];
inline constexpr const od::entry &transmit_pdo_comm_param_17_compatibility_entry = entries[112];
inline constexpr const od::entry &transmit_pdo_comm_param_17_event_timer = entries[113];
inline constexpr od::object transmit_pdo_comm_param_18{0x1811, od::object_code::record, "Transmit PDO Comm Param 18", {entries.data() + 114, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_18_nbr_of_entries = entries[114];
inline constexpr const od::entry &transmit_pdo_comm_param_18_cob_id = entries[115];
inline constexpr const od::entry &transmit_pdo_comm_param_18_transmission_type = entries[116];
inline constexpr const od::entry &transmit_pdo_comm_param_18_inhibit_time = entries[117];
inline constexpr const od::entry &transmit_pdo_comm_param_18_compatibility_entry = entries[118];
inline constexpr const od::entry &transmit_pdo_comm_param_18_event_timer = entries[119];
inline constexpr od::object transmit_pdo_comm_param_19{0x1812, od::object_code::record, "Transmit PDO Comm Param 19", {entries.data() + 120, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_19_nbr_of_entries = entries[120];
inline constexpr const od::entry &transmit_pdo_comm_param_19_cob_id = entries[121];
inline constexpr const od::entry &transmit_pdo_comm_param_19_transmission_type = entries[122];
inline constexpr const od::entry &transmit_pdo_comm_param_19_inhibit_time = entries[123];
inline constexpr const od::entry &transmit_pdo_comm_param_19_compatibility_entry = entries[124];
inline constexpr const od::entry &transmit_pdo_comm_param_19_event_timer = entries[125];
inline constexpr od::object transmit_pdo_comm_param_20{0x1813, od::object_code::record, "Transmit PDO Comm Param 20", {entries.data() + 126, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_20_nbr_of_entries = entries[126];
inline constexpr const od::entry &transmit_pdo_comm_param_20_cob_id = entries[127];
inline constexpr const od::entry &transmit_pdo_comm_param_20_transmission_type = entries[128];
inline constexpr const od::entry &transmit_pdo_comm_param_20_inhibit_time = entries[129];
inline constexpr const od::entry &transmit_pdo_comm_param_20_compatibility_entry = entries[130];
inline constexpr const od::entry &transmit_pdo_comm_param_20_event_timer = entries[131];
inline constexpr od::object transmit_pdo_comm_param_21{0x1814, od::object_code::record, "Transmit PDO Comm Param 21", {entries.data() + 132, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_21_nbr_of_entries = entries[132];
inline constexpr const od::entry &transmit_pdo_comm_param_21_cob_id = entries[133];
inline constexpr const od::entry &transmit_pdo_comm_param_21_transmission_type = entries[134];
inline constexpr const od::entry &transmit_pdo_comm_param_21_inhibit_time = entries[135];
inline constexpr const od::entry &transmit_pdo_comm_param_21_compatibility_entry = entries[136];
inline constexpr const od::entry &transmit_pdo_comm_param_21_event_timer = entries[137];
inline constexpr od::object transmit_pdo_comm_param_22{0x1815, od::object_code::record, "Transmit PDO Comm Param 22", {entries.data() + 138, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_22_nbr_of_entries = entries[138];
inline constexpr const od::entry &transmit_pdo_comm_param_22_cob_id = entries[139];
inline constexpr const od::entry &transmit_pdo_comm_param_22_transmission_type = entries[140];
inline constexpr const od::entry &transmit_pdo_comm_param_22_inhibit_time = entries[141];
inline constexpr const od::entry &transmit_pdo_comm_param_22_compatibility_entry = entries[142];
inline constexpr const od::entry &transmit_pdo_comm_param_22_event_timer = entries[143];
inline constexpr od::object transmit_pdo_comm_param_23{0x1816, od::object_code::record, "Transmit PDO Comm Param 23", {entries.data() + 144, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_23_nbr_of_entries = entries[144];
inline constexpr const od::entry &transmit_pdo_comm_param_23_cob_id = entries[145];
inline constexpr const od::entry &transmit_pdo_comm_param_23_transmission_type = entries[146];
inline constexpr const od::entry &transmit_pdo_comm_param_23_inhibit_time = entries[147];
inline constexpr const od::entry &transmit_pdo_comm_param_23_compatibility_entry = entries[148];
inline constexpr const od::entry &transmit_pdo_comm_param_23_event_timer = entries[149];
inline constexpr od::object transmit_pdo_comm_param_24{0x1817, od::object_code::record, "Transmit PDO Comm Param 24", {entries.data() + 150, 6}};
inline constexpr const od::entry &transmit_pdo_comm_param_24_nbr_of_entries = entries[150];
inline constexpr const od::entry &transmit_pdo_comm_param_24_cob_id = entries[151];
inline constexpr const od::entry &transmit_pdo_comm_param_24_transmission_type = entries[152];
inline constexpr const od::entry &transmit_pdo_comm_param_24_inhibit_time = entries[153];
inline constexpr const od::entry &transmit_pdo_comm_param_24_compatibility_entry = entries[154];
inline constexpr const od::entry &transmit_pdo_comm_param_24_event_timer = entries[155];
inline constexpr od::object transmit_pdo_mapping_param_1{0x1A00, od::object_code::record, "Transmit PDO Mapping Param 1", {entries.data() + 156, 2}};
inline constexpr const od::entry &transmit_pdo_mapping_param_1_nbr_of_entries = entries[156];
inline constexpr const od::entry &transmit_pdo_mapping_param_1_statusword = entries[157];
inline constexpr od::object transmit_pdo_mapping_param_2{0x1A01, od::object_code::record, "Transmit PDO Mapping Param 2", {entries.data() + 158, 3}};
inline constexpr const od::entry &transmit_pdo_mapping_param_2_nbr_of_entries = entries[158];
inline constexpr const od::entry &transmit_pdo_mapping_param_2_statusword = entries[159];
inline constexpr const od::entry &transmit_pdo_mapping_param_2_actual_position = entries[160];
inline constexpr od::object transmit_pdo_mapping_param_17{0x1A10, od::object_code::record, "Transmit PDO Mapping Param 17", {entries.data() + 161, 2}};
inline constexpr const od::entry &transmit_pdo_mapping_param_17_nbr_of_entries = entries[161];
inline constexpr const od::entry &transmit_pdo_mapping_param_17_digital_inputs = entries[162];
inline constexpr od::object transmit_pdo_mapping_param_20{0x1A13, od::object_code::record, "Transmit PDO Mapping Param 20", {entries.data() + 163, 3}};
inline constexpr const od::entry &transmit_pdo_mapping_param_20_nbr_of_entries = entries[163];
inline constexpr const od::entry &transmit_pdo_mapping_param_20_actual_following_position_error = entries[164];
inline constexpr const od::entry &transmit_pdo_mapping_param_20_process_status_register = entries[165];
inline constexpr od::object transmit_pdo_mapping_param_21{0x1A14, od::object_code::record, "Transmit PDO Mapping Param 21", {entries.data() + 166, 2}};
inline constexpr const od::entry &transmit_pdo_mapping_param_21_nbr_of_entries = entries[166];
inline constexpr const od::entry &transmit_pdo_mapping_param_21_actual_current = entries[167];
inline constexpr od::object transmit_pdo_mapping_param_23{0x1A16, od::object_code::record, "Transmit PDO Mapping Param 23", {entries.data() + 168, 3}};
inline constexpr const od::entry &transmit_pdo_mapping_param_23_nbr_of_entries = entries[168];
inline constexpr const od::entry &transmit_pdo_mapping_param_23_i_force_actual = entries[169];
inline constexpr const od::entry &transmit_pdo_mapping_param_23_process_status_register = entries[170];
inline constexpr od::object transmit_pdo_mapping_param_24{0x1A17, od::object_code::record, "Transmit PDO Mapping Param 24", {entries.data() + 171, 3}};
inline constexpr const od::entry &transmit_pdo_mapping_param_24_nbr_of_entries = entries[171];
inline constexpr const od::entry &transmit_pdo_mapping_param_24_statusword = entries[172];
inline constexpr const od::entry &transmit_pdo_mapping_param_24_i_force_actual = entries[173];
inline constexpr const od::entry &s_curve_profile = entries[174]; // 0x2000
inline constexpr const od::entry &reserved_2001 = entries[175]; // 0x2001
inline constexpr const od::entry &reserved_2002 = entries[176]; // 0x2002
inline constexpr const od::entry &reserved_2003 = entries[177]; // 0x2003
inline constexpr const od::entry &xenax_error_number = entries[178]; // 0x2004
inline constexpr const od::entry &i_force_actual = entries[179]; // 0x2005
inline constexpr const od::entry &process_status_register = entries[180]; // 0x2006
inline constexpr const od::entry &pdo_cycle_time = entries[181]; // 0x2007
inline constexpr const od::entry &motor_type = entries[182]; // 0x2008
inline constexpr const od::entry &limit_force = entries[183]; // 0x2009
inline constexpr const od::entry &force_actual_value = entries[184]; // 0x200A
inline constexpr const od::entry &direct_commands = entries[185]; // 0x5000
inline constexpr od::object read_parameter{0x5001, od::object_code::array, "Read Parameter", {entries.data() + 186, 46}};
inline constexpr od::object write_parameter{0x5002, od::object_code::array, "Write Parameter", {entries.data() + 232, 17}};
inline constexpr od::object read_write_parameter{0x5003, od::object_code::array, "Read Write Parameter", {entries.data() + 249, 107}};
inline constexpr od::object motor_parameter{0x5004, od::object_code::array, "Motor Parameter", {entries.data() + 356, 12}};
inline constexpr od::object smu_parameter{0x5005, od::object_code::array, "SMU Parameter", {entries.data() + 368, 14}};
inline constexpr od::object xvi75v8s_and_xvi48v8_parameter{0x5006, od::object_code::array, "Xvi75V8S and Xvi48V8 Parameter", {entries.data() + 382, 11}};
inline constexpr od::object forceteq_pro_parameter{0x5010, od::object_code::array, "Forceteq pro Parameter", {entries.data() + 393, 15}};
inline constexpr const od::entry &signateq_sensor_model_type_sqsmt = entries[408]; // 0x5011
inline constexpr const od::entry &signateq_sensor_serial_number_sqssn = entries[409]; // 0x5012
inline constexpr const od::entry &tell_error_string_tes = entries[410]; // 0x5020
inline constexpr const od::entry &servo_identification_string_sid = entries[411]; // 0x5021
inline constexpr const od::entry &error_code = entries[412]; // 0x603F
inline constexpr const od::entry &controlword = entries[413]; // 0x6040
inline constexpr const od::entry &statusword = entries[414]; // 0x6041
inline constexpr const od::entry &modes_of_operation_requested = entries[415]; // 0x6060
inline constexpr const od::entry &modes_of_operation_display = entries[416]; // 0x6061
inline constexpr const od::entry &position_actual_value = entries[417]; // 0x6064
inline constexpr const od::entry &following_position_error_window = entries[418]; // 0x6065
inline constexpr const od::entry &target_position_window = entries[419]; // 0x6067
inline constexpr const od::entry &position_window_time = entries[420]; // 0x6068
inline constexpr const od::entry &velocity_actual_value = entries[421]; // 0x606C
inline constexpr const od::entry &limit_i_force = entries[422]; // 0x6073
inline constexpr const od::entry &motor_current_actual_value = entries[423]; // 0x6078
inline constexpr const od::entry &target_position = entries[424]; // 0x607A
inline constexpr od::object soft_limit_positions{0x607D, od::object_code::array, "Soft-Limit Positions", {entries.data() + 425, 3}};
inline constexpr const od::entry &speed = entries[428]; // 0x6081
inline constexpr const od::entry &acceleration = entries[429]; // 0x6083
inline constexpr const od::entry &quick_stop_deceleration = entries[430]; // 0x6085
inline constexpr const od::entry &reference_methods = entries[431]; // 0x6098
inline constexpr od::object reference_speeds{0x6099, od::object_code::array, "Reference Speeds", {entries.data() + 432, 3}};
inline constexpr const od::entry &velocity_offset = entries[435]; // 0x60B1
inline constexpr const od::entry &torque_offset = entries[436]; // 0x60B2
inline constexpr od::object synchronous_cycle_time{0x60C2, od::object_code::record, "Synchronous Cycle Time", {entries.data() + 437, 3}};
inline constexpr const od::entry &synchronous_cycle_time_highest_sub_index_value = entries[437];
inline constexpr const od::entry &synchronous_cycle_time_base_value = entries[438];
inline constexpr const od::entry &synchronous_cycle_time_n_10_exponent = entries[439];
inline constexpr const od::entry &actual_position_following_error = entries[440]; // 0x60F4
inline constexpr const od::entry &digital_inputs = entries[441]; // 0x60FD
inline constexpr od::object digital_outputs{0x60FE, od::object_code::array, "Digital Outputs", {entries.data() + 442, 3}};
inline constexpr const od::entry &target_velocity = entries[445]; // 0x60FF
inline constexpr const od::entry &supported_modes_of_operation = entries[446]; // 0x6502
inline constexpr const od::entry &product_website_address = entries[447]; // 0x6505

} // namespace fieldcodec::dictionaries::xenax_canopen
// clang-format on
