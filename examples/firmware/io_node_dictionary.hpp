// Generated from io_node.eds by fieldcodec-gen — do not edit.
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

namespace fieldcodec::dictionaries::io_node {

inline constexpr const char *source_file = "io_node.eds";

inline constexpr std::array<od::entry, 164> entries{{
    {.index = 0x1000, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Device type", .default_value = od::num::u(983441U)},
    {.index = 0x1001, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Error register", .default_value = od::num::u(0U)},
    {.index = 0x1003, .object = od::object_code::array, .type = od::data_type::unsigned8, .name = "Number of errors", .default_value = od::num::u(0U)},
    {.index = 0x1003, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Standard error field 1", .default_value = od::num::u(0U)},
    {.index = 0x1003, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Standard error field 2", .default_value = od::num::u(0U)},
    {.index = 0x1003, .sub = 3, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Standard error field 3", .default_value = od::num::u(0U)},
    {.index = 0x1003, .sub = 4, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Standard error field 4", .default_value = od::num::u(0U)},
    {.index = 0x1005, .type = od::data_type::unsigned32, .name = "COB-ID SYNC", .default_value = od::num::u(128U)},
    {.index = 0x1007, .type = od::data_type::unsigned32, .name = "Synchronous window length", .default_value = od::num::u(0U)},
    {.index = 0x1008, .type = od::data_type::visible_string, .access_type = od::access::constant, .size = 13, .name = "Manufacturer device name", .default_text = "fieldcodec IO"},
    {.index = 0x100C, .type = od::data_type::unsigned16, .name = "Guard time", .default_value = od::num::u(0U)},
    {.index = 0x100D, .type = od::data_type::unsigned8, .name = "Life time factor", .default_value = od::num::u(0U)},
    {.index = 0x1014, .type = od::data_type::unsigned32, .name = "COB-ID EMCY", .default_value = od::num::u(128U), .default_nodeid = true},
    {.index = 0x1015, .type = od::data_type::unsigned16, .name = "Inhibit time EMCY", .default_value = od::num::u(0U)},
    {.index = 0x1016, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Number of entries", .default_value = od::num::u(1U)},
    {.index = 0x1016, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .name = "Consumer heartbeat time 1", .default_value = od::num::u(0U)},
    {.index = 0x1017, .type = od::data_type::unsigned16, .name = "Producer heartbeat time", .default_value = od::num::u(0U)},
    {.index = 0x1018, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Number of entries", .default_value = od::num::u(4U)},
    {.index = 0x1018, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Vendor-ID", .default_value = od::num::u(0U)},
    {.index = 0x1018, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Product code", .default_value = od::num::u(0U)},
    {.index = 0x1018, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Revision number", .default_value = od::num::u(0U)},
    {.index = 0x1018, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "Serial number", .default_value = od::num::u(0U)},
    {.index = 0x1019, .type = od::data_type::unsigned8, .name = "Synchronous counter overflow value", .default_value = od::num::u(0U)},
    {.index = 0x1200, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest sub-index supported", .default_value = od::num::u(2U)},
    {.index = 0x1200, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "COB-ID client to server", .default_value = od::num::u(1536U), .default_nodeid = true},
    {.index = 0x1200, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .name = "COB-ID server to client", .default_value = od::num::u(1408U), .default_nodeid = true},
    {.index = 0x1400, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest sub-index supported", .default_value = od::num::u(5U)},
    {.index = 0x1400, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID used by RPDO", .default_value = od::num::u(512U), .default_nodeid = true},
    {.index = 0x1400, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission type", .default_value = od::num::u(255U)},
    {.index = 0x1400, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit time", .default_value = od::num::u(0U)},
    {.index = 0x1400, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility entry", .default_value = od::num::u(0U)},
    {.index = 0x1400, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event timer", .default_value = od::num::u(0U)},
    {.index = 0x1401, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest sub-index supported", .default_value = od::num::u(5U)},
    {.index = 0x1401, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID used by RPDO", .default_value = od::num::u(768U), .default_nodeid = true},
    {.index = 0x1401, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission type", .default_value = od::num::u(255U)},
    {.index = 0x1401, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit time", .default_value = od::num::u(0U)},
    {.index = 0x1401, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility entry", .default_value = od::num::u(0U)},
    {.index = 0x1401, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event timer", .default_value = od::num::u(0U)},
    {.index = 0x1402, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest sub-index supported", .default_value = od::num::u(5U)},
    {.index = 0x1402, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID used by RPDO", .default_value = od::num::u(2147483648U)},
    {.index = 0x1402, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission type", .default_value = od::num::u(255U)},
    {.index = 0x1402, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit time", .default_value = od::num::u(0U)},
    {.index = 0x1402, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility entry", .default_value = od::num::u(0U)},
    {.index = 0x1402, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event timer", .default_value = od::num::u(0U)},
    {.index = 0x1403, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest sub-index supported", .default_value = od::num::u(5U)},
    {.index = 0x1403, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID used by RPDO", .default_value = od::num::u(2147483648U)},
    {.index = 0x1403, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission type", .default_value = od::num::u(255U)},
    {.index = 0x1403, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit time", .default_value = od::num::u(0U)},
    {.index = 0x1403, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Compatibility entry", .default_value = od::num::u(0U)},
    {.index = 0x1403, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event timer", .default_value = od::num::u(0U)},
    {.index = 0x1600, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Number of mapped objects", .default_value = od::num::u(2U)},
    {.index = 0x1600, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 1", .default_value = od::num::u(1644167432U)},
    {.index = 0x1600, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 2", .default_value = od::num::u(1644167688U)},
    {.index = 0x1600, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 3", .default_value = od::num::u(0U)},
    {.index = 0x1600, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 4", .default_value = od::num::u(0U)},
    {.index = 0x1600, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 5", .default_value = od::num::u(0U)},
    {.index = 0x1600, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 6", .default_value = od::num::u(0U)},
    {.index = 0x1600, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 7", .default_value = od::num::u(0U)},
    {.index = 0x1600, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 8", .default_value = od::num::u(0U)},
    {.index = 0x1601, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Number of mapped objects", .default_value = od::num::u(2U)},
    {.index = 0x1601, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 1", .default_value = od::num::u(1678835984U)},
    {.index = 0x1601, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 2", .default_value = od::num::u(1678836240U)},
    {.index = 0x1601, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 3", .default_value = od::num::u(0U)},
    {.index = 0x1601, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 4", .default_value = od::num::u(0U)},
    {.index = 0x1601, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 5", .default_value = od::num::u(0U)},
    {.index = 0x1601, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 6", .default_value = od::num::u(0U)},
    {.index = 0x1601, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 7", .default_value = od::num::u(0U)},
    {.index = 0x1601, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 8", .default_value = od::num::u(0U)},
    {.index = 0x1602, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Number of mapped objects", .default_value = od::num::u(0U)},
    {.index = 0x1602, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 1", .default_value = od::num::u(0U)},
    {.index = 0x1602, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 2", .default_value = od::num::u(0U)},
    {.index = 0x1602, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 3", .default_value = od::num::u(0U)},
    {.index = 0x1602, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 4", .default_value = od::num::u(0U)},
    {.index = 0x1602, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 5", .default_value = od::num::u(0U)},
    {.index = 0x1602, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 6", .default_value = od::num::u(0U)},
    {.index = 0x1602, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 7", .default_value = od::num::u(0U)},
    {.index = 0x1602, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 8", .default_value = od::num::u(0U)},
    {.index = 0x1603, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Number of mapped objects", .default_value = od::num::u(0U)},
    {.index = 0x1603, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 1", .default_value = od::num::u(0U)},
    {.index = 0x1603, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 2", .default_value = od::num::u(0U)},
    {.index = 0x1603, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 3", .default_value = od::num::u(0U)},
    {.index = 0x1603, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 4", .default_value = od::num::u(0U)},
    {.index = 0x1603, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 5", .default_value = od::num::u(0U)},
    {.index = 0x1603, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 6", .default_value = od::num::u(0U)},
    {.index = 0x1603, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 7", .default_value = od::num::u(0U)},
    {.index = 0x1603, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 8", .default_value = od::num::u(0U)},
    {.index = 0x1800, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest sub-index supported", .default_value = od::num::u(6U)},
    {.index = 0x1800, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID used by TPDO", .default_value = od::num::u(384U), .default_nodeid = true},
    {.index = 0x1800, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission type", .default_value = od::num::u(255U)},
    {.index = 0x1800, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit time", .default_value = od::num::u(0U)},
    {.index = 0x1800, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Reserved", .default_value = od::num::u(0U)},
    {.index = 0x1800, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event timer", .default_value = od::num::u(0U)},
    {.index = 0x1800, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "SYNC start value", .default_value = od::num::u(0U)},
    {.index = 0x1801, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest sub-index supported", .default_value = od::num::u(6U)},
    {.index = 0x1801, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID used by TPDO", .default_value = od::num::u(640U), .default_nodeid = true},
    {.index = 0x1801, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission type", .default_value = od::num::u(255U)},
    {.index = 0x1801, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit time", .default_value = od::num::u(0U)},
    {.index = 0x1801, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Reserved", .default_value = od::num::u(0U)},
    {.index = 0x1801, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event timer", .default_value = od::num::u(0U)},
    {.index = 0x1801, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "SYNC start value", .default_value = od::num::u(0U)},
    {.index = 0x1802, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest sub-index supported", .default_value = od::num::u(6U)},
    {.index = 0x1802, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID used by TPDO", .default_value = od::num::u(2147483648U)},
    {.index = 0x1802, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission type", .default_value = od::num::u(255U)},
    {.index = 0x1802, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit time", .default_value = od::num::u(0U)},
    {.index = 0x1802, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Reserved", .default_value = od::num::u(0U)},
    {.index = 0x1802, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event timer", .default_value = od::num::u(0U)},
    {.index = 0x1802, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "SYNC start value", .default_value = od::num::u(0U)},
    {.index = 0x1803, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Highest sub-index supported", .default_value = od::num::u(6U)},
    {.index = 0x1803, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "COB-ID used by TPDO", .default_value = od::num::u(2147483648U)},
    {.index = 0x1803, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Transmission type", .default_value = od::num::u(255U)},
    {.index = 0x1803, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Inhibit time", .default_value = od::num::u(0U)},
    {.index = 0x1803, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Reserved", .default_value = od::num::u(0U)},
    {.index = 0x1803, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .name = "Event timer", .default_value = od::num::u(0U)},
    {.index = 0x1803, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "SYNC start value", .default_value = od::num::u(0U)},
    {.index = 0x1A00, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Number of mapped objects", .default_value = od::num::u(2U)},
    {.index = 0x1A00, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 1", .default_value = od::num::u(1610613000U)},
    {.index = 0x1A00, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 2", .default_value = od::num::u(1610613256U)},
    {.index = 0x1A00, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 3", .default_value = od::num::u(0U)},
    {.index = 0x1A00, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 4", .default_value = od::num::u(0U)},
    {.index = 0x1A00, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 5", .default_value = od::num::u(0U)},
    {.index = 0x1A00, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 6", .default_value = od::num::u(0U)},
    {.index = 0x1A00, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 7", .default_value = od::num::u(0U)},
    {.index = 0x1A00, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 8", .default_value = od::num::u(0U)},
    {.index = 0x1A01, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Number of mapped objects", .default_value = od::num::u(4U)},
    {.index = 0x1A01, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 1", .default_value = od::num::u(1677787408U)},
    {.index = 0x1A01, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 2", .default_value = od::num::u(1677787664U)},
    {.index = 0x1A01, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 3", .default_value = od::num::u(1677787920U)},
    {.index = 0x1A01, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 4", .default_value = od::num::u(1677788176U)},
    {.index = 0x1A01, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 5", .default_value = od::num::u(0U)},
    {.index = 0x1A01, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 6", .default_value = od::num::u(0U)},
    {.index = 0x1A01, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 7", .default_value = od::num::u(0U)},
    {.index = 0x1A01, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 8", .default_value = od::num::u(0U)},
    {.index = 0x1A02, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Number of mapped objects", .default_value = od::num::u(0U)},
    {.index = 0x1A02, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 1", .default_value = od::num::u(0U)},
    {.index = 0x1A02, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 2", .default_value = od::num::u(0U)},
    {.index = 0x1A02, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 3", .default_value = od::num::u(0U)},
    {.index = 0x1A02, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 4", .default_value = od::num::u(0U)},
    {.index = 0x1A02, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 5", .default_value = od::num::u(0U)},
    {.index = 0x1A02, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 6", .default_value = od::num::u(0U)},
    {.index = 0x1A02, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 7", .default_value = od::num::u(0U)},
    {.index = 0x1A02, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 8", .default_value = od::num::u(0U)},
    {.index = 0x1A03, .object = od::object_code::record, .type = od::data_type::unsigned8, .name = "Number of mapped objects", .default_value = od::num::u(0U)},
    {.index = 0x1A03, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 1", .default_value = od::num::u(0U)},
    {.index = 0x1A03, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 2", .default_value = od::num::u(0U)},
    {.index = 0x1A03, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 3", .default_value = od::num::u(0U)},
    {.index = 0x1A03, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 4", .default_value = od::num::u(0U)},
    {.index = 0x1A03, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 5", .default_value = od::num::u(0U)},
    {.index = 0x1A03, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 6", .default_value = od::num::u(0U)},
    {.index = 0x1A03, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 7", .default_value = od::num::u(0U)},
    {.index = 0x1A03, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .name = "Mapped object 8", .default_value = od::num::u(0U)},
    {.index = 0x6000, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Number of input 8-bit", .default_value = od::num::u(2U)},
    {.index = 0x6000, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Read input 1h to 8h", .default_value = od::num::u(0U)},
    {.index = 0x6000, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Read input 9h to 10h", .default_value = od::num::u(0U)},
    {.index = 0x6200, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Number of output 8-bit", .default_value = od::num::u(2U)},
    {.index = 0x6200, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned8, .pdo = od::pdo_mapping::yes, .name = "Write output 1h to 8h", .default_value = od::num::u(0U)},
    {.index = 0x6200, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned8, .pdo = od::pdo_mapping::yes, .name = "Write output 9h to 10h", .default_value = od::num::u(0U)},
    {.index = 0x6401, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Number of analog input 16-bit", .default_value = od::num::u(4U)},
    {.index = 0x6401, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Analog input 1", .default_value = od::num::i(0)},
    {.index = 0x6401, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Analog input 2", .default_value = od::num::i(0)},
    {.index = 0x6401, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Analog input 3", .default_value = od::num::i(0)},
    {.index = 0x6401, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .name = "Analog input 4", .default_value = od::num::i(0)},
    {.index = 0x6411, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .name = "Number of analog output 16-bit", .default_value = od::num::u(2U)},
    {.index = 0x6411, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer16, .pdo = od::pdo_mapping::yes, .name = "Analog output 1", .default_value = od::num::i(0)},
    {.index = 0x6411, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer16, .pdo = od::pdo_mapping::yes, .name = "Analog output 2", .default_value = od::num::i(0)},
}};

inline constexpr od::dictionary dictionary{entries};
static_assert(dictionary.is_valid());

inline constexpr const od::entry &device_type = entries[0]; // 0x1000
inline constexpr const od::entry &error_register = entries[1]; // 0x1001
inline constexpr od::object pre_defined_error_field{0x1003, od::object_code::array, "Pre-defined error field", {entries.data() + 2, 5}};
inline constexpr const od::entry &cob_id_sync = entries[7]; // 0x1005
inline constexpr const od::entry &synchronous_window_length = entries[8]; // 0x1007
inline constexpr const od::entry &manufacturer_device_name = entries[9]; // 0x1008
inline constexpr const od::entry &guard_time = entries[10]; // 0x100C
inline constexpr const od::entry &life_time_factor = entries[11]; // 0x100D
inline constexpr const od::entry &cob_id_emcy = entries[12]; // 0x1014
inline constexpr const od::entry &inhibit_time_emcy = entries[13]; // 0x1015
inline constexpr od::object consumer_heartbeat_time{0x1016, od::object_code::array, "Consumer heartbeat time", {entries.data() + 14, 2}};
inline constexpr const od::entry &producer_heartbeat_time = entries[16]; // 0x1017
inline constexpr od::object identity_object{0x1018, od::object_code::record, "Identity object", {entries.data() + 17, 5}};
inline constexpr const od::entry &identity_object_number_of_entries = entries[17];
inline constexpr const od::entry &identity_object_vendor_id = entries[18];
inline constexpr const od::entry &identity_object_product_code = entries[19];
inline constexpr const od::entry &identity_object_revision_number = entries[20];
inline constexpr const od::entry &identity_object_serial_number = entries[21];
inline constexpr const od::entry &synchronous_counter_overflow_value = entries[22]; // 0x1019
inline constexpr od::object sdo_server_parameter{0x1200, od::object_code::record, "SDO server parameter", {entries.data() + 23, 3}};
inline constexpr const od::entry &sdo_server_parameter_highest_sub_index_supported = entries[23];
inline constexpr const od::entry &sdo_server_parameter_cob_id_client_to_server = entries[24];
inline constexpr const od::entry &sdo_server_parameter_cob_id_server_to_client = entries[25];
inline constexpr od::object rpdo_communication_parameter_1{0x1400, od::object_code::record, "RPDO communication parameter 1", {entries.data() + 26, 6}};
inline constexpr const od::entry &rpdo_communication_parameter_1_highest_sub_index_supported = entries[26];
inline constexpr const od::entry &rpdo_communication_parameter_1_cob_id_used_by_rpdo = entries[27];
inline constexpr const od::entry &rpdo_communication_parameter_1_transmission_type = entries[28];
inline constexpr const od::entry &rpdo_communication_parameter_1_inhibit_time = entries[29];
inline constexpr const od::entry &rpdo_communication_parameter_1_compatibility_entry = entries[30];
inline constexpr const od::entry &rpdo_communication_parameter_1_event_timer = entries[31];
inline constexpr od::object rpdo_communication_parameter_2{0x1401, od::object_code::record, "RPDO communication parameter 2", {entries.data() + 32, 6}};
inline constexpr const od::entry &rpdo_communication_parameter_2_highest_sub_index_supported = entries[32];
inline constexpr const od::entry &rpdo_communication_parameter_2_cob_id_used_by_rpdo = entries[33];
inline constexpr const od::entry &rpdo_communication_parameter_2_transmission_type = entries[34];
inline constexpr const od::entry &rpdo_communication_parameter_2_inhibit_time = entries[35];
inline constexpr const od::entry &rpdo_communication_parameter_2_compatibility_entry = entries[36];
inline constexpr const od::entry &rpdo_communication_parameter_2_event_timer = entries[37];
inline constexpr od::object rpdo_communication_parameter_3{0x1402, od::object_code::record, "RPDO communication parameter 3", {entries.data() + 38, 6}};
inline constexpr const od::entry &rpdo_communication_parameter_3_highest_sub_index_supported = entries[38];
inline constexpr const od::entry &rpdo_communication_parameter_3_cob_id_used_by_rpdo = entries[39];
inline constexpr const od::entry &rpdo_communication_parameter_3_transmission_type = entries[40];
inline constexpr const od::entry &rpdo_communication_parameter_3_inhibit_time = entries[41];
inline constexpr const od::entry &rpdo_communication_parameter_3_compatibility_entry = entries[42];
inline constexpr const od::entry &rpdo_communication_parameter_3_event_timer = entries[43];
inline constexpr od::object rpdo_communication_parameter_4{0x1403, od::object_code::record, "RPDO communication parameter 4", {entries.data() + 44, 6}};
inline constexpr const od::entry &rpdo_communication_parameter_4_highest_sub_index_supported = entries[44];
inline constexpr const od::entry &rpdo_communication_parameter_4_cob_id_used_by_rpdo = entries[45];
inline constexpr const od::entry &rpdo_communication_parameter_4_transmission_type = entries[46];
inline constexpr const od::entry &rpdo_communication_parameter_4_inhibit_time = entries[47];
inline constexpr const od::entry &rpdo_communication_parameter_4_compatibility_entry = entries[48];
inline constexpr const od::entry &rpdo_communication_parameter_4_event_timer = entries[49];
inline constexpr od::object rpdo_mapping_parameter_1{0x1600, od::object_code::record, "RPDO mapping parameter 1", {entries.data() + 50, 9}};
inline constexpr const od::entry &rpdo_mapping_parameter_1_number_of_mapped_objects = entries[50];
inline constexpr const od::entry &rpdo_mapping_parameter_1_mapped_object_1 = entries[51];
inline constexpr const od::entry &rpdo_mapping_parameter_1_mapped_object_2 = entries[52];
inline constexpr const od::entry &rpdo_mapping_parameter_1_mapped_object_3 = entries[53];
inline constexpr const od::entry &rpdo_mapping_parameter_1_mapped_object_4 = entries[54];
inline constexpr const od::entry &rpdo_mapping_parameter_1_mapped_object_5 = entries[55];
inline constexpr const od::entry &rpdo_mapping_parameter_1_mapped_object_6 = entries[56];
inline constexpr const od::entry &rpdo_mapping_parameter_1_mapped_object_7 = entries[57];
inline constexpr const od::entry &rpdo_mapping_parameter_1_mapped_object_8 = entries[58];
inline constexpr od::object rpdo_mapping_parameter_2{0x1601, od::object_code::record, "RPDO mapping parameter 2", {entries.data() + 59, 9}};
inline constexpr const od::entry &rpdo_mapping_parameter_2_number_of_mapped_objects = entries[59];
inline constexpr const od::entry &rpdo_mapping_parameter_2_mapped_object_1 = entries[60];
inline constexpr const od::entry &rpdo_mapping_parameter_2_mapped_object_2 = entries[61];
inline constexpr const od::entry &rpdo_mapping_parameter_2_mapped_object_3 = entries[62];
inline constexpr const od::entry &rpdo_mapping_parameter_2_mapped_object_4 = entries[63];
inline constexpr const od::entry &rpdo_mapping_parameter_2_mapped_object_5 = entries[64];
inline constexpr const od::entry &rpdo_mapping_parameter_2_mapped_object_6 = entries[65];
inline constexpr const od::entry &rpdo_mapping_parameter_2_mapped_object_7 = entries[66];
inline constexpr const od::entry &rpdo_mapping_parameter_2_mapped_object_8 = entries[67];
inline constexpr od::object rpdo_mapping_parameter_3{0x1602, od::object_code::record, "RPDO mapping parameter 3", {entries.data() + 68, 9}};
inline constexpr const od::entry &rpdo_mapping_parameter_3_number_of_mapped_objects = entries[68];
inline constexpr const od::entry &rpdo_mapping_parameter_3_mapped_object_1 = entries[69];
inline constexpr const od::entry &rpdo_mapping_parameter_3_mapped_object_2 = entries[70];
inline constexpr const od::entry &rpdo_mapping_parameter_3_mapped_object_3 = entries[71];
inline constexpr const od::entry &rpdo_mapping_parameter_3_mapped_object_4 = entries[72];
inline constexpr const od::entry &rpdo_mapping_parameter_3_mapped_object_5 = entries[73];
inline constexpr const od::entry &rpdo_mapping_parameter_3_mapped_object_6 = entries[74];
inline constexpr const od::entry &rpdo_mapping_parameter_3_mapped_object_7 = entries[75];
inline constexpr const od::entry &rpdo_mapping_parameter_3_mapped_object_8 = entries[76];
inline constexpr od::object rpdo_mapping_parameter_4{0x1603, od::object_code::record, "RPDO mapping parameter 4", {entries.data() + 77, 9}};
inline constexpr const od::entry &rpdo_mapping_parameter_4_number_of_mapped_objects = entries[77];
inline constexpr const od::entry &rpdo_mapping_parameter_4_mapped_object_1 = entries[78];
inline constexpr const od::entry &rpdo_mapping_parameter_4_mapped_object_2 = entries[79];
inline constexpr const od::entry &rpdo_mapping_parameter_4_mapped_object_3 = entries[80];
inline constexpr const od::entry &rpdo_mapping_parameter_4_mapped_object_4 = entries[81];
inline constexpr const od::entry &rpdo_mapping_parameter_4_mapped_object_5 = entries[82];
inline constexpr const od::entry &rpdo_mapping_parameter_4_mapped_object_6 = entries[83];
inline constexpr const od::entry &rpdo_mapping_parameter_4_mapped_object_7 = entries[84];
inline constexpr const od::entry &rpdo_mapping_parameter_4_mapped_object_8 = entries[85];
inline constexpr od::object tpdo_communication_parameter_1{0x1800, od::object_code::record, "TPDO communication parameter 1", {entries.data() + 86, 7}};
inline constexpr const od::entry &tpdo_communication_parameter_1_highest_sub_index_supported = entries[86];
inline constexpr const od::entry &tpdo_communication_parameter_1_cob_id_used_by_tpdo = entries[87];
inline constexpr const od::entry &tpdo_communication_parameter_1_transmission_type = entries[88];
inline constexpr const od::entry &tpdo_communication_parameter_1_inhibit_time = entries[89];
inline constexpr const od::entry &tpdo_communication_parameter_1_reserved = entries[90];
inline constexpr const od::entry &tpdo_communication_parameter_1_event_timer = entries[91];
inline constexpr const od::entry &tpdo_communication_parameter_1_sync_start_value = entries[92];
inline constexpr od::object tpdo_communication_parameter_2{0x1801, od::object_code::record, "TPDO communication parameter 2", {entries.data() + 93, 7}};
inline constexpr const od::entry &tpdo_communication_parameter_2_highest_sub_index_supported = entries[93];
inline constexpr const od::entry &tpdo_communication_parameter_2_cob_id_used_by_tpdo = entries[94];
inline constexpr const od::entry &tpdo_communication_parameter_2_transmission_type = entries[95];
inline constexpr const od::entry &tpdo_communication_parameter_2_inhibit_time = entries[96];
inline constexpr const od::entry &tpdo_communication_parameter_2_reserved = entries[97];
inline constexpr const od::entry &tpdo_communication_parameter_2_event_timer = entries[98];
inline constexpr const od::entry &tpdo_communication_parameter_2_sync_start_value = entries[99];
inline constexpr od::object tpdo_communication_parameter_3{0x1802, od::object_code::record, "TPDO communication parameter 3", {entries.data() + 100, 7}};
inline constexpr const od::entry &tpdo_communication_parameter_3_highest_sub_index_supported = entries[100];
inline constexpr const od::entry &tpdo_communication_parameter_3_cob_id_used_by_tpdo = entries[101];
inline constexpr const od::entry &tpdo_communication_parameter_3_transmission_type = entries[102];
inline constexpr const od::entry &tpdo_communication_parameter_3_inhibit_time = entries[103];
inline constexpr const od::entry &tpdo_communication_parameter_3_reserved = entries[104];
inline constexpr const od::entry &tpdo_communication_parameter_3_event_timer = entries[105];
inline constexpr const od::entry &tpdo_communication_parameter_3_sync_start_value = entries[106];
inline constexpr od::object tpdo_communication_parameter_4{0x1803, od::object_code::record, "TPDO communication parameter 4", {entries.data() + 107, 7}};
inline constexpr const od::entry &tpdo_communication_parameter_4_highest_sub_index_supported = entries[107];
inline constexpr const od::entry &tpdo_communication_parameter_4_cob_id_used_by_tpdo = entries[108];
inline constexpr const od::entry &tpdo_communication_parameter_4_transmission_type = entries[109];
inline constexpr const od::entry &tpdo_communication_parameter_4_inhibit_time = entries[110];
inline constexpr const od::entry &tpdo_communication_parameter_4_reserved = entries[111];
inline constexpr const od::entry &tpdo_communication_parameter_4_event_timer = entries[112];
inline constexpr const od::entry &tpdo_communication_parameter_4_sync_start_value = entries[113];
inline constexpr od::object tpdo_mapping_parameter_1{0x1A00, od::object_code::record, "TPDO mapping parameter 1", {entries.data() + 114, 9}};
inline constexpr const od::entry &tpdo_mapping_parameter_1_number_of_mapped_objects = entries[114];
inline constexpr const od::entry &tpdo_mapping_parameter_1_mapped_object_1 = entries[115];
inline constexpr const od::entry &tpdo_mapping_parameter_1_mapped_object_2 = entries[116];
inline constexpr const od::entry &tpdo_mapping_parameter_1_mapped_object_3 = entries[117];
inline constexpr const od::entry &tpdo_mapping_parameter_1_mapped_object_4 = entries[118];
inline constexpr const od::entry &tpdo_mapping_parameter_1_mapped_object_5 = entries[119];
inline constexpr const od::entry &tpdo_mapping_parameter_1_mapped_object_6 = entries[120];
inline constexpr const od::entry &tpdo_mapping_parameter_1_mapped_object_7 = entries[121];
inline constexpr const od::entry &tpdo_mapping_parameter_1_mapped_object_8 = entries[122];
inline constexpr od::object tpdo_mapping_parameter_2{0x1A01, od::object_code::record, "TPDO mapping parameter 2", {entries.data() + 123, 9}};
inline constexpr const od::entry &tpdo_mapping_parameter_2_number_of_mapped_objects = entries[123];
inline constexpr const od::entry &tpdo_mapping_parameter_2_mapped_object_1 = entries[124];
inline constexpr const od::entry &tpdo_mapping_parameter_2_mapped_object_2 = entries[125];
inline constexpr const od::entry &tpdo_mapping_parameter_2_mapped_object_3 = entries[126];
inline constexpr const od::entry &tpdo_mapping_parameter_2_mapped_object_4 = entries[127];
inline constexpr const od::entry &tpdo_mapping_parameter_2_mapped_object_5 = entries[128];
inline constexpr const od::entry &tpdo_mapping_parameter_2_mapped_object_6 = entries[129];
inline constexpr const od::entry &tpdo_mapping_parameter_2_mapped_object_7 = entries[130];
inline constexpr const od::entry &tpdo_mapping_parameter_2_mapped_object_8 = entries[131];
inline constexpr od::object tpdo_mapping_parameter_3{0x1A02, od::object_code::record, "TPDO mapping parameter 3", {entries.data() + 132, 9}};
inline constexpr const od::entry &tpdo_mapping_parameter_3_number_of_mapped_objects = entries[132];
inline constexpr const od::entry &tpdo_mapping_parameter_3_mapped_object_1 = entries[133];
inline constexpr const od::entry &tpdo_mapping_parameter_3_mapped_object_2 = entries[134];
inline constexpr const od::entry &tpdo_mapping_parameter_3_mapped_object_3 = entries[135];
inline constexpr const od::entry &tpdo_mapping_parameter_3_mapped_object_4 = entries[136];
inline constexpr const od::entry &tpdo_mapping_parameter_3_mapped_object_5 = entries[137];
inline constexpr const od::entry &tpdo_mapping_parameter_3_mapped_object_6 = entries[138];
inline constexpr const od::entry &tpdo_mapping_parameter_3_mapped_object_7 = entries[139];
inline constexpr const od::entry &tpdo_mapping_parameter_3_mapped_object_8 = entries[140];
inline constexpr od::object tpdo_mapping_parameter_4{0x1A03, od::object_code::record, "TPDO mapping parameter 4", {entries.data() + 141, 9}};
inline constexpr const od::entry &tpdo_mapping_parameter_4_number_of_mapped_objects = entries[141];
inline constexpr const od::entry &tpdo_mapping_parameter_4_mapped_object_1 = entries[142];
inline constexpr const od::entry &tpdo_mapping_parameter_4_mapped_object_2 = entries[143];
inline constexpr const od::entry &tpdo_mapping_parameter_4_mapped_object_3 = entries[144];
inline constexpr const od::entry &tpdo_mapping_parameter_4_mapped_object_4 = entries[145];
inline constexpr const od::entry &tpdo_mapping_parameter_4_mapped_object_5 = entries[146];
inline constexpr const od::entry &tpdo_mapping_parameter_4_mapped_object_6 = entries[147];
inline constexpr const od::entry &tpdo_mapping_parameter_4_mapped_object_7 = entries[148];
inline constexpr const od::entry &tpdo_mapping_parameter_4_mapped_object_8 = entries[149];
inline constexpr od::object read_input_8_bit{0x6000, od::object_code::array, "Read input 8-bit", {entries.data() + 150, 3}};
inline constexpr od::object write_output_8_bit{0x6200, od::object_code::array, "Write output 8-bit", {entries.data() + 153, 3}};
inline constexpr od::object read_analog_input_16_bit{0x6401, od::object_code::array, "Read analog input 16-bit", {entries.data() + 156, 5}};
inline constexpr od::object write_analog_output_16_bit{0x6411, od::object_code::array, "Write analog output 16-bit", {entries.data() + 161, 3}};

} // namespace fieldcodec::dictionaries::io_node
// clang-format on
