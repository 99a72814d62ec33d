// Generated from xenax_ethercat.eds by fieldcodec-gen — do not edit.
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

namespace fieldcodec::dictionaries::xenax_ethercat {

inline constexpr const char *source_file = "xenax_ethercat.eds";

inline constexpr std::array<od::entry, 358> entries{{
    {.index = 0x1000, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Device Type", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(4325778U)},
    {.index = 0x1001, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Error Register", .low = od::num::u(0U), .high = od::num::u(255U), .default_value = od::num::u(0U)},
    {.index = 0x1008, .type = od::data_type::visible_string, .access_type = od::access::ro, .size = 30, .name = "Manufacturer Device Name", .default_text = "Servocontroller XENAX Xvi xxVx"},
    {.index = 0x1009, .type = od::data_type::visible_string, .access_type = od::access::ro, .size = 22, .name = "Manufacturer Hardware Version", .default_text = "BUS Module HW Vxxx.xxx"},
    {.index = 0x100A, .type = od::data_type::visible_string, .access_type = od::access::ro, .size = 24, .name = "Manufacturer Software Version", .default_text = "BUS Protocol SW Vxxx.xxx"},
    {.index = 0x1018, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .low = od::num::u(1U), .high = od::num::u(4U), .default_value = od::num::u(4U)},
    {.index = 0x1018, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Vendor Id", .low = od::num::u(0U), .high = od::num::u(4294967295U)},
    {.index = 0x1018, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Product Code", .low = od::num::u(0U), .high = od::num::u(4294967295U)},
    {.index = 0x1018, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Revision Number", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(65536U)},
    {.index = 0x1018, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Serial Number", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1U)},
    {.index = 0x1600, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(1U)},
    {.index = 0x1600, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614807056U)},
    {.index = 0x1601, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(2U)},
    {.index = 0x1601, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614807056U)},
    {.index = 0x1601, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Target Position", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1618608160U)},
    {.index = 0x1611, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(3U)},
    {.index = 0x1611, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614807056U)},
    {.index = 0x1611, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Target Position", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1618608160U)},
    {.index = 0x1611, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Digital Outputs", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1627259168U)},
    {.index = 0x1612, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(9U), .default_value = od::num::u(9U)},
    {.index = 0x1612, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614807056U)},
    {.index = 0x1612, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Target Position", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1618608160U)},
    {.index = 0x1612, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Speed", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1619066912U)},
    {.index = 0x1612, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Acceleration", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1619197984U)},
    {.index = 0x1612, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Deceleration (reserved for future)", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1619263520U)},
    {.index = 0x1612, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "S-Curve", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(536870944U)},
    {.index = 0x1612, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Following Position Error Window", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1617231904U)},
    {.index = 0x1612, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Target Position Error Window", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1617362976U)},
    {.index = 0x1612, .sub = 9, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Digital Outputs", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1627259168U)},
    {.index = 0x1613, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(5U)},
    {.index = 0x1613, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614807056U)},
    {.index = 0x1613, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Speed", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1619066912U)},
    {.index = 0x1613, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Reserved for future 2001", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(536936480U)},
    {.index = 0x1613, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Reserved for future 2003", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(537067552U)},
    {.index = 0x1613, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Digital Outputs", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1627259168U)},
    {.index = 0x1614, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(3U)},
    {.index = 0x1614, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614807056U)},
    {.index = 0x1614, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Reserved for future 2002", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(537002016U)},
    {.index = 0x1614, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Digital Outputs", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1627259168U)},
    {.index = 0x1615, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(5U)},
    {.index = 0x1615, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Controlword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614807056U)},
    {.index = 0x1615, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Target Position", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1618608160U)},
    {.index = 0x1615, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Following position error window", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1617231904U)},
    {.index = 0x1615, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Target position error window", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1617362976U)},
    {.index = 0x1615, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "I Force Max", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1618149392U)},
    {.index = 0x1A00, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(1U)},
    {.index = 0x1A00, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Statusword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614872592U)},
    {.index = 0x1A01, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(2U)},
    {.index = 0x1A01, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Statusword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614872592U)},
    {.index = 0x1A01, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Position", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1617166368U)},
    {.index = 0x1A10, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(3U)},
    {.index = 0x1A10, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Statusword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614872592U)},
    {.index = 0x1A10, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Position", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1617166368U)},
    {.index = 0x1A10, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Digital Inputs", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1627193376U)},
    {.index = 0x1A11, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(5U)},
    {.index = 0x1A11, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Statusword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614872592U)},
    {.index = 0x1A11, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Position", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1617166368U)},
    {.index = 0x1A11, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Following position error", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1626603552U)},
    {.index = 0x1A11, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Current", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1618477072U)},
    {.index = 0x1A11, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Digital Inputs", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1627193376U)},
    {.index = 0x1A12, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(4U)},
    {.index = 0x1A12, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Statusword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614872592U)},
    {.index = 0x1A12, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Position", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1617166368U)},
    {.index = 0x1A12, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "I Force Actual", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(537198624U)},
    {.index = 0x1A12, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Digital Inputs", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1627193376U)},
    {.index = 0x1A13, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(8U), .default_value = od::num::u(5U)},
    {.index = 0x1A13, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Statusword", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1614872592U)},
    {.index = 0x1A13, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Position", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1617166368U)},
    {.index = 0x1A13, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Following position error", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1626603552U)},
    {.index = 0x1A13, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Actual Current", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(1618477072U)},
    {.index = 0x1A13, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Process Status Register", .low = od::num::u(0U), .high = od::num::u(4294967295U), .default_value = od::num::u(537264160U)},
    {.index = 0x1C00, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "No of Used Sync Manager Channels", .low = od::num::u(0U), .high = od::num::u(32U), .default_value = od::num::u(5U)},
    {.index = 0x1C00, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Com Type Sync Manager 1", .low = od::num::u(0U), .high = od::num::u(4U), .default_value = od::num::u(1U)},
    {.index = 0x1C00, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Com Type Sync Manager 2", .low = od::num::u(0U), .high = od::num::u(4U), .default_value = od::num::u(2U)},
    {.index = 0x1C00, .sub = 3, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Com Type Sync Manager 3", .low = od::num::u(0U), .high = od::num::u(4U), .default_value = od::num::u(3U)},
    {.index = 0x1C00, .sub = 4, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Com Type Sync Manager 4", .low = od::num::u(0U), .high = od::num::u(4U), .default_value = od::num::u(4U)},
    {.index = 0x1C00, .sub = 5, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Com Type Sync Manager 5", .low = od::num::u(0U), .high = od::num::u(4U), .default_value = od::num::u(0U)},
    {.index = 0x1C10, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(0U), .default_value = od::num::u(0U)},
    {.index = 0x1C11, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Nbr of Entries", .low = od::num::u(0U), .high = od::num::u(0U), .default_value = od::num::u(0U)},
    {.index = 0x1C12, .object = od::object_code::array, .type = od::data_type::unsigned8, .name = "Nbr of Assigned RxPDO", .low = od::num::u(0U), .high = od::num::u(6U), .default_value = od::num::u(1U)},
    {.index = 0x1C12, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned16, .name = "PDO Mapping Index of Assigned RxPDOs", .low = od::num::u(5632U), .high = od::num::u(6143U), .default_value = od::num::u(5633U)},
    {.index = 0x1C13, .object = od::object_code::array, .type = od::data_type::unsigned8, .name = "Nbr of Assigned TxPDO", .low = od::num::u(0U), .high = od::num::u(5U), .default_value = od::num::u(1U)},
    {.index = 0x1C13, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned16, .name = "PDO Mapping Index of Assigned TxPDOs", .low = od::num::u(6656U), .high = od::num::u(7167U), .default_value = od::num::u(6675U)},
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
    {.index = 0x6084, .type = od::data_type::unsigned32, .pdo = od::pdo_mapping::yes, .name = "Deceleration (reserved for future)"},
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
inline constexpr const od::entry &manufacturer_device_name = entries[2]; // 0x1008
inline constexpr const od::entry &manufacturer_hardware_version = entries[3]; // 0x1009
inline constexpr const od::entry &manufacturer_software_version = entries[4]; // 0x100A
inline constexpr od::object identity_object{0x1018, od::object_code::record, "Identity Object", {entries.data() + 5, 5}};
inline constexpr const od::entry &identity_object_nbr_of_entries = entries[5];
inline constexpr const od::entry &identity_object_vendor_id = entries[6];
inline constexpr const od::entry &identity_object_product_code = entries[7];
inline constexpr const od::entry &identity_object_revision_number = entries[8];
inline constexpr const od::entry &identity_object_serial_number = entries[9];
inline constexpr od::object receive_pdo_1{0x1600, od::object_code::record, "Receive PDO 1", {entries.data() + 10, 2}};
inline constexpr const od::entry &receive_pdo_1_nbr_of_entries = entries[10];
inline constexpr const od::entry &receive_pdo_1_controlword = entries[11];
inline constexpr od::object receive_pdo_2{0x1601, od::object_code::record, "Receive PDO 2", {entries.data() + 12, 3}};
inline constexpr const od::entry &receive_pdo_2_nbr_of_entries = entries[12];
inline constexpr const od::entry &receive_pdo_2_controlword = entries[13];
inline constexpr const od::entry &receive_pdo_2_target_position = entries[14];
inline constexpr od::object receive_pdo_17{0x1611, od::object_code::record, "Receive PDO 17", {entries.data() + 15, 4}};
inline constexpr const od::entry &receive_pdo_17_nbr_of_entries = entries[15];
inline constexpr const od::entry &receive_pdo_17_controlword = entries[16];
inline constexpr const od::entry &receive_pdo_17_target_position = entries[17];
inline constexpr const od::entry &receive_pdo_17_digital_outputs = entries[18];
inline constexpr od::object receive_pdo_18{0x1612, od::object_code::record, "Receive PDO 18", {entries.data() + 19, 10}};
inline constexpr const od::entry &receive_pdo_18_nbr_of_entries = entries[19];
inline constexpr const od::entry &receive_pdo_18_controlword = entries[20];
inline constexpr const od::entry &receive_pdo_18_target_position = entries[21];
inline constexpr const od::entry &receive_pdo_18_speed = entries[22];
inline constexpr const od::entry &receive_pdo_18_acceleration = entries[23];
inline constexpr const od::entry &receive_pdo_18_deceleration_reserved_for_future = entries[24];
inline constexpr const od::entry &receive_pdo_18_s_curve = entries[25];
inline constexpr const od::entry &receive_pdo_18_following_position_error_window = entries[26];
inline constexpr const od::entry &receive_pdo_18_target_position_error_window = entries[27];
inline constexpr const od::entry &receive_pdo_18_digital_outputs = entries[28];
inline constexpr od::object receive_pdo_19_reserved_for_future{0x1613, od::object_code::record, "Receive PDO 19 (reserved for future)", {entries.data() + 29, 6}};
inline constexpr const od::entry &receive_pdo_19_reserved_for_future_nbr_of_entries = entries[29];
inline constexpr const od::entry &receive_pdo_19_reserved_for_future_controlword = entries[30];
inline constexpr const od::entry &receive_pdo_19_reserved_for_future_speed = entries[31];
inline constexpr const od::entry &receive_pdo_19_reserved_for_future_reserved_for_future_2001 = entries[32];
inline constexpr const od::entry &receive_pdo_19_reserved_for_future_reserved_for_future_2003 = entries[33];
inline constexpr const od::entry &receive_pdo_19_reserved_for_future_digital_outputs = entries[34];
inline constexpr od::object receive_pdo_20_reserved_for_future{0x1614, od::object_code::record, "Receive PDO 20 (reserved for future)", {entries.data() + 35, 4}};
inline constexpr const od::entry &receive_pdo_20_reserved_for_future_nbr_of_entries = entries[35];
inline constexpr const od::entry &receive_pdo_20_reserved_for_future_controlword = entries[36];
inline constexpr const od::entry &receive_pdo_20_reserved_for_future_reserved_for_future_2002 = entries[37];
inline constexpr const od::entry &receive_pdo_20_reserved_for_future_digital_outputs = entries[38];
inline constexpr od::object receive_pdo_21{0x1615, od::object_code::record, "Receive PDO 21", {entries.data() + 39, 6}};
inline constexpr const od::entry &receive_pdo_21_nbr_of_entries = entries[39];
inline constexpr const od::entry &receive_pdo_21_controlword = entries[40];
inline constexpr const od::entry &receive_pdo_21_target_position = entries[41];
inline constexpr const od::entry &receive_pdo_21_following_position_error_window = entries[42];
inline constexpr const od::entry &receive_pdo_21_target_position_error_window = entries[43];
inline constexpr const od::entry &receive_pdo_21_i_force_max = entries[44];
inline constexpr od::object transmit_pdo_1{0x1A00, od::object_code::record, "Transmit PDO 1", {entries.data() + 45, 2}};
inline constexpr const od::entry &transmit_pdo_1_nbr_of_entries = entries[45];
inline constexpr const od::entry &transmit_pdo_1_statusword = entries[46];
inline constexpr od::object transmit_pdo_2{0x1A01, od::object_code::record, "Transmit PDO 2", {entries.data() + 47, 3}};
inline constexpr const od::entry &transmit_pdo_2_nbr_of_entries = entries[47];
inline constexpr const od::entry &transmit_pdo_2_statusword = entries[48];
inline constexpr const od::entry &transmit_pdo_2_actual_position = entries[49];
inline constexpr od::object transmit_pdo_17{0x1A10, od::object_code::record, "Transmit PDO 17", {entries.data() + 50, 4}};
inline constexpr const od::entry &transmit_pdo_17_nbr_of_entries = entries[50];
inline constexpr const od::entry &transmit_pdo_17_statusword = entries[51];
inline constexpr const od::entry &transmit_pdo_17_actual_position = entries[52];
inline constexpr const od::entry &transmit_pdo_17_digital_inputs = entries[53];
inline constexpr od::object transmit_pdo_18{0x1A11, od::object_code::record, "Transmit PDO 18", {entries.data() + 54, 6}};
inline constexpr const od::entry &transmit_pdo_18_nbr_of_entries = entries[54];
inline constexpr const od::entry &transmit_pdo_18_statusword = entries[55];
inline constexpr const od::entry &transmit_pdo_18_actual_position = entries[56];
inline constexpr const od::entry &transmit_pdo_18_actual_following_position_error = entries[57];
inline constexpr const od::entry &transmit_pdo_18_actual_current = entries[58];
inline constexpr const od::entry &transmit_pdo_18_digital_inputs = entries[59];
inline constexpr od::object transmit_pdo_19_reserved_for_future{0x1A12, od::object_code::record, "Transmit PDO 19 (reserved for future)", {entries.data() + 60, 5}};
inline constexpr const od::entry &transmit_pdo_19_reserved_for_future_nbr_of_entries = entries[60];
inline constexpr const od::entry &transmit_pdo_19_reserved_for_future_statusword = entries[61];
inline constexpr const od::entry &transmit_pdo_19_reserved_for_future_actual_position = entries[62];
inline constexpr const od::entry &transmit_pdo_19_reserved_for_future_i_force_actual = entries[63];
inline constexpr const od::entry &transmit_pdo_19_reserved_for_future_digital_inputs = entries[64];
inline constexpr od::object transmit_pdo_21{0x1A13, od::object_code::record, "Transmit PDO 21", {entries.data() + 65, 6}};
inline constexpr const od::entry &transmit_pdo_21_nbr_of_entries = entries[65];
inline constexpr const od::entry &transmit_pdo_21_statusword = entries[66];
inline constexpr const od::entry &transmit_pdo_21_actual_position = entries[67];
inline constexpr const od::entry &transmit_pdo_21_actual_following_position_error = entries[68];
inline constexpr const od::entry &transmit_pdo_21_actual_current = entries[69];
inline constexpr const od::entry &transmit_pdo_21_process_status_register = entries[70];
inline constexpr od::object sync_manager_communication_type{0x1C00, od::object_code::array, "Sync Manager Communication Type", {entries.data() + 71, 6}};
inline constexpr od::object sync_manager_pdo_assignment_0{0x1C10, od::object_code::array, "Sync Manager PDO Assignment 0", {entries.data() + 77, 1}};
inline constexpr od::object sync_manager_pdo_assignment_1{0x1C11, od::object_code::array, "Sync Manager PDO Assignment 1", {entries.data() + 78, 1}};
inline constexpr od::object sync_manager_pdo_assignment_2{0x1C12, od::object_code::array, "Sync Manager PDO Assignment 2", {entries.data() + 79, 2}};
inline constexpr od::object sync_manager_pdo_assignment_3{0x1C13, od::object_code::array, "Sync Manager PDO Assignment 3", {entries.data() + 81, 2}};
inline constexpr const od::entry &s_curve_profile = entries[83]; // 0x2000
inline constexpr const od::entry &reserved_2001 = entries[84]; // 0x2001
inline constexpr const od::entry &reserved_2002 = entries[85]; // 0x2002
inline constexpr const od::entry &reserved_2003 = entries[86]; // 0x2003
inline constexpr const od::entry &xenax_error_number = entries[87]; // 0x2004
inline constexpr const od::entry &i_force_actual = entries[88]; // 0x2005
inline constexpr const od::entry &process_status_register = entries[89]; // 0x2006
inline constexpr const od::entry &pdo_cycle_time = entries[90]; // 0x2007
inline constexpr const od::entry &motor_type = entries[91]; // 0x2008
inline constexpr const od::entry &limit_force = entries[92]; // 0x2009
inline constexpr const od::entry &force_actual_value = entries[93]; // 0x200A
inline constexpr const od::entry &direct_commands = entries[94]; // 0x5000
inline constexpr od::object read_parameter{0x5001, od::object_code::array, "Read Parameter", {entries.data() + 95, 46}};
inline constexpr od::object write_parameter{0x5002, od::object_code::array, "Write Parameter", {entries.data() + 141, 17}};
inline constexpr od::object read_write_parameter{0x5003, od::object_code::array, "Read Write Parameter", {entries.data() + 158, 107}};
inline constexpr od::object motor_parameter{0x5004, od::object_code::array, "Motor Parameter", {entries.data() + 265, 12}};
inline constexpr od::object smu_parameter{0x5005, od::object_code::array, "SMU Parameter", {entries.data() + 277, 14}};
inline constexpr od::object xvi75v8s_and_xvi48v8_parameter{0x5006, od::object_code::array, "Xvi75V8S and Xvi48V8 Parameter", {entries.data() + 291, 11}};
inline constexpr od::object forceteq_pro_parameter{0x5010, od::object_code::array, "Forceteq pro Parameter", {entries.data() + 302, 15}};
inline constexpr const od::entry &signateq_sensor_model_type_sqsmt = entries[317]; // 0x5011
inline constexpr const od::entry &signateq_sensor_serial_number_sqssn = entries[318]; // 0x5012
inline constexpr const od::entry &tell_error_string_tes = entries[319]; // 0x5020
inline constexpr const od::entry &servo_identification_string_sid = entries[320]; // 0x5021
inline constexpr const od::entry &error_code = entries[321]; // 0x603F
inline constexpr const od::entry &controlword = entries[322]; // 0x6040
inline constexpr const od::entry &statusword = entries[323]; // 0x6041
inline constexpr const od::entry &modes_of_operation_requested = entries[324]; // 0x6060
inline constexpr const od::entry &modes_of_operation_display = entries[325]; // 0x6061
inline constexpr const od::entry &position_actual_value = entries[326]; // 0x6064
inline constexpr const od::entry &following_position_error_window = entries[327]; // 0x6065
inline constexpr const od::entry &target_position_window = entries[328]; // 0x6067
inline constexpr const od::entry &position_window_time = entries[329]; // 0x6068
inline constexpr const od::entry &velocity_actual_value = entries[330]; // 0x606C
inline constexpr const od::entry &limit_i_force = entries[331]; // 0x6073
inline constexpr const od::entry &motor_current_actual_value = entries[332]; // 0x6078
inline constexpr const od::entry &target_position = entries[333]; // 0x607A
inline constexpr od::object soft_limit_positions{0x607D, od::object_code::array, "Soft-Limit Positions", {entries.data() + 334, 3}};
inline constexpr const od::entry &speed = entries[337]; // 0x6081
inline constexpr const od::entry &acceleration = entries[338]; // 0x6083
inline constexpr const od::entry &deceleration_reserved_for_future = entries[339]; // 0x6084
inline constexpr const od::entry &quick_stop_deceleration = entries[340]; // 0x6085
inline constexpr const od::entry &reference_methods = entries[341]; // 0x6098
inline constexpr od::object reference_speeds{0x6099, od::object_code::array, "Reference Speeds", {entries.data() + 342, 3}};
inline constexpr const od::entry &velocity_offset = entries[345]; // 0x60B1
inline constexpr const od::entry &torque_offset = entries[346]; // 0x60B2
inline constexpr od::object synchronous_cycle_time{0x60C2, od::object_code::record, "Synchronous Cycle Time", {entries.data() + 347, 3}};
inline constexpr const od::entry &synchronous_cycle_time_highest_sub_index_value = entries[347];
inline constexpr const od::entry &synchronous_cycle_time_base_value = entries[348];
inline constexpr const od::entry &synchronous_cycle_time_n_10_exponent = entries[349];
inline constexpr const od::entry &actual_position_following_error = entries[350]; // 0x60F4
inline constexpr const od::entry &digital_inputs = entries[351]; // 0x60FD
inline constexpr od::object digital_outputs{0x60FE, od::object_code::array, "Digital Outputs", {entries.data() + 352, 3}};
inline constexpr const od::entry &target_velocity = entries[355]; // 0x60FF
inline constexpr const od::entry &supported_modes_of_operation = entries[356]; // 0x6502
inline constexpr const od::entry &product_website_address = entries[357]; // 0x6505

} // namespace fieldcodec::dictionaries::xenax_ethercat
// clang-format on
