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
#include <fieldcodec/od/value_kinds.hpp>

#include <cstdint>
#include <span>
#include <string_view>

namespace fieldcodec::dictionaries::io_node {

using namespace std::string_view_literals;

inline constexpr const char *source_file = "io_node.eds";

namespace detail {
inline constexpr od::entry entries[164]{
    {.index = 0x1000, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\221\001\017\000"},
    {.index = 0x1001, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1003, .object = od::object_code::array, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1003, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1003, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1003, .sub = 3, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1003, .sub = 4, .object = od::object_code::array, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1005, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\200\000\000\000"},
    {.index = 0x1007, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1008, .type = od::data_type::visible_string, .access_type = od::access::constant, .flags = od::flag::has_size | od::flag::has_text, .extra = "\015\000\000\000\015\000\000\000fieldcodec IO"},
    {.index = 0x100C, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x100D, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1014, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid | od::flag::has_default, .extra = "\200\000\000\000"},
    {.index = 0x1015, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1016, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\001"},
    {.index = 0x1016, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1017, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1018, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\004"},
    {.index = 0x1018, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1018, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1018, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1018, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1019, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1200, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\002"},
    {.index = 0x1200, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::default_nodeid | od::flag::has_default, .extra = "\000\006\000\000"},
    {.index = 0x1200, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .access_type = od::access::ro, .flags = od::flag::default_nodeid | od::flag::has_default, .extra = "\200\005\000\000"},
    {.index = 0x1400, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\005"},
    {.index = 0x1400, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid | od::flag::has_default, .extra = "\000\002\000\000"},
    {.index = 0x1400, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\377"},
    {.index = 0x1400, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1400, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1400, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1401, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\005"},
    {.index = 0x1401, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid | od::flag::has_default, .extra = "\000\003\000\000"},
    {.index = 0x1401, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\377"},
    {.index = 0x1401, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1401, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1401, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1402, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\005"},
    {.index = 0x1402, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\200"},
    {.index = 0x1402, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\377"},
    {.index = 0x1402, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1402, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1402, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1403, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\005"},
    {.index = 0x1403, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\200"},
    {.index = 0x1403, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\377"},
    {.index = 0x1403, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1403, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1403, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1600, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\002"},
    {.index = 0x1600, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\010\001\000b"},
    {.index = 0x1600, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\010\002\000b"},
    {.index = 0x1600, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1600, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1600, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1600, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1600, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1600, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1601, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\002"},
    {.index = 0x1601, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\020\001\021d"},
    {.index = 0x1601, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\020\002\021d"},
    {.index = 0x1601, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1601, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1601, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1601, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1601, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1601, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1602, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1602, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1602, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1602, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1602, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1602, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1602, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1602, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1602, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1603, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1603, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1603, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1603, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1603, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1603, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1603, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1603, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1603, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1800, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\006"},
    {.index = 0x1800, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid | od::flag::has_default, .extra = "\200\001\000\000"},
    {.index = 0x1800, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\377"},
    {.index = 0x1800, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1800, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1800, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1800, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1801, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\006"},
    {.index = 0x1801, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::default_nodeid | od::flag::has_default, .extra = "\200\002\000\000"},
    {.index = 0x1801, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\377"},
    {.index = 0x1801, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1801, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1801, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1801, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1802, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\006"},
    {.index = 0x1802, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\200"},
    {.index = 0x1802, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\377"},
    {.index = 0x1802, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1802, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1802, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1802, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1803, .object = od::object_code::record, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\006"},
    {.index = 0x1803, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\200"},
    {.index = 0x1803, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\377"},
    {.index = 0x1803, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1803, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1803, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned16, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x1803, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1A00, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\002"},
    {.index = 0x1A00, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\010\001\000`"},
    {.index = 0x1A00, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\010\002\000`"},
    {.index = 0x1A00, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A00, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A00, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A00, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A00, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A00, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A01, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\004"},
    {.index = 0x1A01, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\020\001\001d"},
    {.index = 0x1A01, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\020\002\001d"},
    {.index = 0x1A01, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\020\003\001d"},
    {.index = 0x1A01, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\020\004\001d"},
    {.index = 0x1A01, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A01, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A01, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A01, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A02, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1A02, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A02, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A02, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A02, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A02, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A02, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A02, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A02, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A03, .object = od::object_code::record, .type = od::data_type::unsigned8, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x1A03, .sub = 1, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A03, .sub = 2, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A03, .sub = 3, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A03, .sub = 4, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A03, .sub = 5, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A03, .sub = 6, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A03, .sub = 7, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x1A03, .sub = 8, .object = od::object_code::record, .type = od::data_type::unsigned32, .flags = od::flag::has_default, .extra = "\000\000\000\000"},
    {.index = 0x6000, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\002"},
    {.index = 0x6000, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x6000, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x6200, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\002"},
    {.index = 0x6200, .sub = 1, .object = od::object_code::array, .type = od::data_type::unsigned8, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x6200, .sub = 2, .object = od::object_code::array, .type = od::data_type::unsigned8, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000"},
    {.index = 0x6401, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\004"},
    {.index = 0x6401, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x6401, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x6401, .sub = 3, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x6401, .sub = 4, .object = od::object_code::array, .type = od::data_type::integer16, .access_type = od::access::ro, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x6411, .object = od::object_code::array, .type = od::data_type::unsigned8, .access_type = od::access::ro, .flags = od::flag::has_default, .extra = "\002"},
    {.index = 0x6411, .sub = 1, .object = od::object_code::array, .type = od::data_type::integer16, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000\000"},
    {.index = 0x6411, .sub = 2, .object = od::object_code::array, .type = od::data_type::integer16, .pdo = od::pdo_mapping::yes, .flags = od::flag::has_default, .extra = "\000\000"},
};

inline constexpr od::entry_info infos[164]{
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
};
} // namespace detail

inline constexpr std::span<const od::entry, 164> entries{detail::entries};
inline constexpr std::span<const od::entry_info, 164> infos{detail::infos};

inline constexpr od::dictionary dictionary{entries, infos};
static_assert(dictionary.is_valid());

// The kinds of values in the entries (od/value_kinds.hpp).
inline constexpr od::value_kinds kinds{.strings = true, .real = false, .time = false, .wide = false, .limits = false, .node_limits = false, .scaled = false, .numbers = false};

// VAR objects: standalone descriptors (firmware that names one keeps only that one).
inline constexpr od::descriptor device_type{detail::entries[0], detail::infos[0]}; // 0x1000
inline constexpr od::descriptor error_register{detail::entries[1], detail::infos[1]}; // 0x1001
inline constexpr od::descriptor cob_id_sync{detail::entries[7], detail::infos[7]}; // 0x1005
inline constexpr od::descriptor synchronous_window_length{detail::entries[8], detail::infos[8]}; // 0x1007
inline constexpr od::descriptor manufacturer_device_name{detail::entries[9], detail::infos[9]}; // 0x1008
inline constexpr od::descriptor guard_time{detail::entries[10], detail::infos[10]}; // 0x100C
inline constexpr od::descriptor life_time_factor{detail::entries[11], detail::infos[11]}; // 0x100D
inline constexpr od::descriptor cob_id_emcy{detail::entries[12], detail::infos[12]}; // 0x1014
inline constexpr od::descriptor inhibit_time_emcy{detail::entries[13], detail::infos[13]}; // 0x1015
inline constexpr od::descriptor producer_heartbeat_time{detail::entries[16], detail::infos[16]}; // 0x1017
inline constexpr od::descriptor synchronous_counter_overflow_value{detail::entries[22], detail::infos[22]}; // 0x1019

// ARRAY and RECORD objects: views into the tables.
inline constexpr od::object pre_defined_error_field{0x1003, od::object_code::array, "Pre-defined error field"sv, dictionary.entries().subspan(2, 5), dictionary.infos().subspan(2, 5)};
inline constexpr od::object consumer_heartbeat_time{0x1016, od::object_code::array, "Consumer heartbeat time"sv, dictionary.entries().subspan(14, 2), dictionary.infos().subspan(14, 2)};
inline constexpr od::object identity_object{0x1018, od::object_code::record, "Identity object"sv, dictionary.entries().subspan(17, 5), dictionary.infos().subspan(17, 5)};
inline constexpr od::descriptor identity_object_number_of_entries{detail::entries[17], detail::infos[17]}; // 0x1018 sub 0
inline constexpr od::descriptor identity_object_vendor_id{detail::entries[18], detail::infos[18]}; // 0x1018 sub 1
inline constexpr od::descriptor identity_object_product_code{detail::entries[19], detail::infos[19]}; // 0x1018 sub 2
inline constexpr od::descriptor identity_object_revision_number{detail::entries[20], detail::infos[20]}; // 0x1018 sub 3
inline constexpr od::descriptor identity_object_serial_number{detail::entries[21], detail::infos[21]}; // 0x1018 sub 4
inline constexpr od::object sdo_server_parameter{0x1200, od::object_code::record, "SDO server parameter"sv, dictionary.entries().subspan(23, 3), dictionary.infos().subspan(23, 3)};
inline constexpr od::descriptor sdo_server_parameter_highest_sub_index_supported{detail::entries[23], detail::infos[23]}; // 0x1200 sub 0
inline constexpr od::descriptor sdo_server_parameter_cob_id_client_to_server{detail::entries[24], detail::infos[24]}; // 0x1200 sub 1
inline constexpr od::descriptor sdo_server_parameter_cob_id_server_to_client{detail::entries[25], detail::infos[25]}; // 0x1200 sub 2
inline constexpr od::object rpdo_communication_parameter_1{0x1400, od::object_code::record, "RPDO communication parameter 1"sv, dictionary.entries().subspan(26, 6), dictionary.infos().subspan(26, 6)};
inline constexpr od::descriptor rpdo_communication_parameter_1_highest_sub_index_supported{detail::entries[26], detail::infos[26]}; // 0x1400 sub 0
inline constexpr od::descriptor rpdo_communication_parameter_1_cob_id_used_by_rpdo{detail::entries[27], detail::infos[27]}; // 0x1400 sub 1
inline constexpr od::descriptor rpdo_communication_parameter_1_transmission_type{detail::entries[28], detail::infos[28]}; // 0x1400 sub 2
inline constexpr od::descriptor rpdo_communication_parameter_1_inhibit_time{detail::entries[29], detail::infos[29]}; // 0x1400 sub 3
inline constexpr od::descriptor rpdo_communication_parameter_1_compatibility_entry{detail::entries[30], detail::infos[30]}; // 0x1400 sub 4
inline constexpr od::descriptor rpdo_communication_parameter_1_event_timer{detail::entries[31], detail::infos[31]}; // 0x1400 sub 5
inline constexpr od::object rpdo_communication_parameter_2{0x1401, od::object_code::record, "RPDO communication parameter 2"sv, dictionary.entries().subspan(32, 6), dictionary.infos().subspan(32, 6)};
inline constexpr od::descriptor rpdo_communication_parameter_2_highest_sub_index_supported{detail::entries[32], detail::infos[32]}; // 0x1401 sub 0
inline constexpr od::descriptor rpdo_communication_parameter_2_cob_id_used_by_rpdo{detail::entries[33], detail::infos[33]}; // 0x1401 sub 1
inline constexpr od::descriptor rpdo_communication_parameter_2_transmission_type{detail::entries[34], detail::infos[34]}; // 0x1401 sub 2
inline constexpr od::descriptor rpdo_communication_parameter_2_inhibit_time{detail::entries[35], detail::infos[35]}; // 0x1401 sub 3
inline constexpr od::descriptor rpdo_communication_parameter_2_compatibility_entry{detail::entries[36], detail::infos[36]}; // 0x1401 sub 4
inline constexpr od::descriptor rpdo_communication_parameter_2_event_timer{detail::entries[37], detail::infos[37]}; // 0x1401 sub 5
inline constexpr od::object rpdo_communication_parameter_3{0x1402, od::object_code::record, "RPDO communication parameter 3"sv, dictionary.entries().subspan(38, 6), dictionary.infos().subspan(38, 6)};
inline constexpr od::descriptor rpdo_communication_parameter_3_highest_sub_index_supported{detail::entries[38], detail::infos[38]}; // 0x1402 sub 0
inline constexpr od::descriptor rpdo_communication_parameter_3_cob_id_used_by_rpdo{detail::entries[39], detail::infos[39]}; // 0x1402 sub 1
inline constexpr od::descriptor rpdo_communication_parameter_3_transmission_type{detail::entries[40], detail::infos[40]}; // 0x1402 sub 2
inline constexpr od::descriptor rpdo_communication_parameter_3_inhibit_time{detail::entries[41], detail::infos[41]}; // 0x1402 sub 3
inline constexpr od::descriptor rpdo_communication_parameter_3_compatibility_entry{detail::entries[42], detail::infos[42]}; // 0x1402 sub 4
inline constexpr od::descriptor rpdo_communication_parameter_3_event_timer{detail::entries[43], detail::infos[43]}; // 0x1402 sub 5
inline constexpr od::object rpdo_communication_parameter_4{0x1403, od::object_code::record, "RPDO communication parameter 4"sv, dictionary.entries().subspan(44, 6), dictionary.infos().subspan(44, 6)};
inline constexpr od::descriptor rpdo_communication_parameter_4_highest_sub_index_supported{detail::entries[44], detail::infos[44]}; // 0x1403 sub 0
inline constexpr od::descriptor rpdo_communication_parameter_4_cob_id_used_by_rpdo{detail::entries[45], detail::infos[45]}; // 0x1403 sub 1
inline constexpr od::descriptor rpdo_communication_parameter_4_transmission_type{detail::entries[46], detail::infos[46]}; // 0x1403 sub 2
inline constexpr od::descriptor rpdo_communication_parameter_4_inhibit_time{detail::entries[47], detail::infos[47]}; // 0x1403 sub 3
inline constexpr od::descriptor rpdo_communication_parameter_4_compatibility_entry{detail::entries[48], detail::infos[48]}; // 0x1403 sub 4
inline constexpr od::descriptor rpdo_communication_parameter_4_event_timer{detail::entries[49], detail::infos[49]}; // 0x1403 sub 5
inline constexpr od::object rpdo_mapping_parameter_1{0x1600, od::object_code::record, "RPDO mapping parameter 1"sv, dictionary.entries().subspan(50, 9), dictionary.infos().subspan(50, 9)};
inline constexpr od::descriptor rpdo_mapping_parameter_1_number_of_mapped_objects{detail::entries[50], detail::infos[50]}; // 0x1600 sub 0
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_1{detail::entries[51], detail::infos[51]}; // 0x1600 sub 1
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_2{detail::entries[52], detail::infos[52]}; // 0x1600 sub 2
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_3{detail::entries[53], detail::infos[53]}; // 0x1600 sub 3
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_4{detail::entries[54], detail::infos[54]}; // 0x1600 sub 4
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_5{detail::entries[55], detail::infos[55]}; // 0x1600 sub 5
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_6{detail::entries[56], detail::infos[56]}; // 0x1600 sub 6
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_7{detail::entries[57], detail::infos[57]}; // 0x1600 sub 7
inline constexpr od::descriptor rpdo_mapping_parameter_1_mapped_object_8{detail::entries[58], detail::infos[58]}; // 0x1600 sub 8
inline constexpr od::object rpdo_mapping_parameter_2{0x1601, od::object_code::record, "RPDO mapping parameter 2"sv, dictionary.entries().subspan(59, 9), dictionary.infos().subspan(59, 9)};
inline constexpr od::descriptor rpdo_mapping_parameter_2_number_of_mapped_objects{detail::entries[59], detail::infos[59]}; // 0x1601 sub 0
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_1{detail::entries[60], detail::infos[60]}; // 0x1601 sub 1
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_2{detail::entries[61], detail::infos[61]}; // 0x1601 sub 2
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_3{detail::entries[62], detail::infos[62]}; // 0x1601 sub 3
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_4{detail::entries[63], detail::infos[63]}; // 0x1601 sub 4
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_5{detail::entries[64], detail::infos[64]}; // 0x1601 sub 5
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_6{detail::entries[65], detail::infos[65]}; // 0x1601 sub 6
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_7{detail::entries[66], detail::infos[66]}; // 0x1601 sub 7
inline constexpr od::descriptor rpdo_mapping_parameter_2_mapped_object_8{detail::entries[67], detail::infos[67]}; // 0x1601 sub 8
inline constexpr od::object rpdo_mapping_parameter_3{0x1602, od::object_code::record, "RPDO mapping parameter 3"sv, dictionary.entries().subspan(68, 9), dictionary.infos().subspan(68, 9)};
inline constexpr od::descriptor rpdo_mapping_parameter_3_number_of_mapped_objects{detail::entries[68], detail::infos[68]}; // 0x1602 sub 0
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_1{detail::entries[69], detail::infos[69]}; // 0x1602 sub 1
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_2{detail::entries[70], detail::infos[70]}; // 0x1602 sub 2
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_3{detail::entries[71], detail::infos[71]}; // 0x1602 sub 3
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_4{detail::entries[72], detail::infos[72]}; // 0x1602 sub 4
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_5{detail::entries[73], detail::infos[73]}; // 0x1602 sub 5
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_6{detail::entries[74], detail::infos[74]}; // 0x1602 sub 6
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_7{detail::entries[75], detail::infos[75]}; // 0x1602 sub 7
inline constexpr od::descriptor rpdo_mapping_parameter_3_mapped_object_8{detail::entries[76], detail::infos[76]}; // 0x1602 sub 8
inline constexpr od::object rpdo_mapping_parameter_4{0x1603, od::object_code::record, "RPDO mapping parameter 4"sv, dictionary.entries().subspan(77, 9), dictionary.infos().subspan(77, 9)};
inline constexpr od::descriptor rpdo_mapping_parameter_4_number_of_mapped_objects{detail::entries[77], detail::infos[77]}; // 0x1603 sub 0
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_1{detail::entries[78], detail::infos[78]}; // 0x1603 sub 1
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_2{detail::entries[79], detail::infos[79]}; // 0x1603 sub 2
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_3{detail::entries[80], detail::infos[80]}; // 0x1603 sub 3
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_4{detail::entries[81], detail::infos[81]}; // 0x1603 sub 4
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_5{detail::entries[82], detail::infos[82]}; // 0x1603 sub 5
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_6{detail::entries[83], detail::infos[83]}; // 0x1603 sub 6
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_7{detail::entries[84], detail::infos[84]}; // 0x1603 sub 7
inline constexpr od::descriptor rpdo_mapping_parameter_4_mapped_object_8{detail::entries[85], detail::infos[85]}; // 0x1603 sub 8
inline constexpr od::object tpdo_communication_parameter_1{0x1800, od::object_code::record, "TPDO communication parameter 1"sv, dictionary.entries().subspan(86, 7), dictionary.infos().subspan(86, 7)};
inline constexpr od::descriptor tpdo_communication_parameter_1_highest_sub_index_supported{detail::entries[86], detail::infos[86]}; // 0x1800 sub 0
inline constexpr od::descriptor tpdo_communication_parameter_1_cob_id_used_by_tpdo{detail::entries[87], detail::infos[87]}; // 0x1800 sub 1
inline constexpr od::descriptor tpdo_communication_parameter_1_transmission_type{detail::entries[88], detail::infos[88]}; // 0x1800 sub 2
inline constexpr od::descriptor tpdo_communication_parameter_1_inhibit_time{detail::entries[89], detail::infos[89]}; // 0x1800 sub 3
inline constexpr od::descriptor tpdo_communication_parameter_1_reserved{detail::entries[90], detail::infos[90]}; // 0x1800 sub 4
inline constexpr od::descriptor tpdo_communication_parameter_1_event_timer{detail::entries[91], detail::infos[91]}; // 0x1800 sub 5
inline constexpr od::descriptor tpdo_communication_parameter_1_sync_start_value{detail::entries[92], detail::infos[92]}; // 0x1800 sub 6
inline constexpr od::object tpdo_communication_parameter_2{0x1801, od::object_code::record, "TPDO communication parameter 2"sv, dictionary.entries().subspan(93, 7), dictionary.infos().subspan(93, 7)};
inline constexpr od::descriptor tpdo_communication_parameter_2_highest_sub_index_supported{detail::entries[93], detail::infos[93]}; // 0x1801 sub 0
inline constexpr od::descriptor tpdo_communication_parameter_2_cob_id_used_by_tpdo{detail::entries[94], detail::infos[94]}; // 0x1801 sub 1
inline constexpr od::descriptor tpdo_communication_parameter_2_transmission_type{detail::entries[95], detail::infos[95]}; // 0x1801 sub 2
inline constexpr od::descriptor tpdo_communication_parameter_2_inhibit_time{detail::entries[96], detail::infos[96]}; // 0x1801 sub 3
inline constexpr od::descriptor tpdo_communication_parameter_2_reserved{detail::entries[97], detail::infos[97]}; // 0x1801 sub 4
inline constexpr od::descriptor tpdo_communication_parameter_2_event_timer{detail::entries[98], detail::infos[98]}; // 0x1801 sub 5
inline constexpr od::descriptor tpdo_communication_parameter_2_sync_start_value{detail::entries[99], detail::infos[99]}; // 0x1801 sub 6
inline constexpr od::object tpdo_communication_parameter_3{0x1802, od::object_code::record, "TPDO communication parameter 3"sv, dictionary.entries().subspan(100, 7), dictionary.infos().subspan(100, 7)};
inline constexpr od::descriptor tpdo_communication_parameter_3_highest_sub_index_supported{detail::entries[100], detail::infos[100]}; // 0x1802 sub 0
inline constexpr od::descriptor tpdo_communication_parameter_3_cob_id_used_by_tpdo{detail::entries[101], detail::infos[101]}; // 0x1802 sub 1
inline constexpr od::descriptor tpdo_communication_parameter_3_transmission_type{detail::entries[102], detail::infos[102]}; // 0x1802 sub 2
inline constexpr od::descriptor tpdo_communication_parameter_3_inhibit_time{detail::entries[103], detail::infos[103]}; // 0x1802 sub 3
inline constexpr od::descriptor tpdo_communication_parameter_3_reserved{detail::entries[104], detail::infos[104]}; // 0x1802 sub 4
inline constexpr od::descriptor tpdo_communication_parameter_3_event_timer{detail::entries[105], detail::infos[105]}; // 0x1802 sub 5
inline constexpr od::descriptor tpdo_communication_parameter_3_sync_start_value{detail::entries[106], detail::infos[106]}; // 0x1802 sub 6
inline constexpr od::object tpdo_communication_parameter_4{0x1803, od::object_code::record, "TPDO communication parameter 4"sv, dictionary.entries().subspan(107, 7), dictionary.infos().subspan(107, 7)};
inline constexpr od::descriptor tpdo_communication_parameter_4_highest_sub_index_supported{detail::entries[107], detail::infos[107]}; // 0x1803 sub 0
inline constexpr od::descriptor tpdo_communication_parameter_4_cob_id_used_by_tpdo{detail::entries[108], detail::infos[108]}; // 0x1803 sub 1
inline constexpr od::descriptor tpdo_communication_parameter_4_transmission_type{detail::entries[109], detail::infos[109]}; // 0x1803 sub 2
inline constexpr od::descriptor tpdo_communication_parameter_4_inhibit_time{detail::entries[110], detail::infos[110]}; // 0x1803 sub 3
inline constexpr od::descriptor tpdo_communication_parameter_4_reserved{detail::entries[111], detail::infos[111]}; // 0x1803 sub 4
inline constexpr od::descriptor tpdo_communication_parameter_4_event_timer{detail::entries[112], detail::infos[112]}; // 0x1803 sub 5
inline constexpr od::descriptor tpdo_communication_parameter_4_sync_start_value{detail::entries[113], detail::infos[113]}; // 0x1803 sub 6
inline constexpr od::object tpdo_mapping_parameter_1{0x1A00, od::object_code::record, "TPDO mapping parameter 1"sv, dictionary.entries().subspan(114, 9), dictionary.infos().subspan(114, 9)};
inline constexpr od::descriptor tpdo_mapping_parameter_1_number_of_mapped_objects{detail::entries[114], detail::infos[114]}; // 0x1A00 sub 0
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_1{detail::entries[115], detail::infos[115]}; // 0x1A00 sub 1
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_2{detail::entries[116], detail::infos[116]}; // 0x1A00 sub 2
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_3{detail::entries[117], detail::infos[117]}; // 0x1A00 sub 3
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_4{detail::entries[118], detail::infos[118]}; // 0x1A00 sub 4
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_5{detail::entries[119], detail::infos[119]}; // 0x1A00 sub 5
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_6{detail::entries[120], detail::infos[120]}; // 0x1A00 sub 6
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_7{detail::entries[121], detail::infos[121]}; // 0x1A00 sub 7
inline constexpr od::descriptor tpdo_mapping_parameter_1_mapped_object_8{detail::entries[122], detail::infos[122]}; // 0x1A00 sub 8
inline constexpr od::object tpdo_mapping_parameter_2{0x1A01, od::object_code::record, "TPDO mapping parameter 2"sv, dictionary.entries().subspan(123, 9), dictionary.infos().subspan(123, 9)};
inline constexpr od::descriptor tpdo_mapping_parameter_2_number_of_mapped_objects{detail::entries[123], detail::infos[123]}; // 0x1A01 sub 0
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_1{detail::entries[124], detail::infos[124]}; // 0x1A01 sub 1
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_2{detail::entries[125], detail::infos[125]}; // 0x1A01 sub 2
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_3{detail::entries[126], detail::infos[126]}; // 0x1A01 sub 3
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_4{detail::entries[127], detail::infos[127]}; // 0x1A01 sub 4
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_5{detail::entries[128], detail::infos[128]}; // 0x1A01 sub 5
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_6{detail::entries[129], detail::infos[129]}; // 0x1A01 sub 6
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_7{detail::entries[130], detail::infos[130]}; // 0x1A01 sub 7
inline constexpr od::descriptor tpdo_mapping_parameter_2_mapped_object_8{detail::entries[131], detail::infos[131]}; // 0x1A01 sub 8
inline constexpr od::object tpdo_mapping_parameter_3{0x1A02, od::object_code::record, "TPDO mapping parameter 3"sv, dictionary.entries().subspan(132, 9), dictionary.infos().subspan(132, 9)};
inline constexpr od::descriptor tpdo_mapping_parameter_3_number_of_mapped_objects{detail::entries[132], detail::infos[132]}; // 0x1A02 sub 0
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_1{detail::entries[133], detail::infos[133]}; // 0x1A02 sub 1
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_2{detail::entries[134], detail::infos[134]}; // 0x1A02 sub 2
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_3{detail::entries[135], detail::infos[135]}; // 0x1A02 sub 3
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_4{detail::entries[136], detail::infos[136]}; // 0x1A02 sub 4
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_5{detail::entries[137], detail::infos[137]}; // 0x1A02 sub 5
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_6{detail::entries[138], detail::infos[138]}; // 0x1A02 sub 6
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_7{detail::entries[139], detail::infos[139]}; // 0x1A02 sub 7
inline constexpr od::descriptor tpdo_mapping_parameter_3_mapped_object_8{detail::entries[140], detail::infos[140]}; // 0x1A02 sub 8
inline constexpr od::object tpdo_mapping_parameter_4{0x1A03, od::object_code::record, "TPDO mapping parameter 4"sv, dictionary.entries().subspan(141, 9), dictionary.infos().subspan(141, 9)};
inline constexpr od::descriptor tpdo_mapping_parameter_4_number_of_mapped_objects{detail::entries[141], detail::infos[141]}; // 0x1A03 sub 0
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_1{detail::entries[142], detail::infos[142]}; // 0x1A03 sub 1
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_2{detail::entries[143], detail::infos[143]}; // 0x1A03 sub 2
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_3{detail::entries[144], detail::infos[144]}; // 0x1A03 sub 3
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_4{detail::entries[145], detail::infos[145]}; // 0x1A03 sub 4
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_5{detail::entries[146], detail::infos[146]}; // 0x1A03 sub 5
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_6{detail::entries[147], detail::infos[147]}; // 0x1A03 sub 6
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_7{detail::entries[148], detail::infos[148]}; // 0x1A03 sub 7
inline constexpr od::descriptor tpdo_mapping_parameter_4_mapped_object_8{detail::entries[149], detail::infos[149]}; // 0x1A03 sub 8
inline constexpr od::object read_input_8_bit{0x6000, od::object_code::array, "Read input 8-bit"sv, dictionary.entries().subspan(150, 3), dictionary.infos().subspan(150, 3)};
inline constexpr od::object write_output_8_bit{0x6200, od::object_code::array, "Write output 8-bit"sv, dictionary.entries().subspan(153, 3), dictionary.infos().subspan(153, 3)};
inline constexpr od::object read_analog_input_16_bit{0x6401, od::object_code::array, "Read analog input 16-bit"sv, dictionary.entries().subspan(156, 5), dictionary.infos().subspan(156, 5)};
inline constexpr od::object write_analog_output_16_bit{0x6411, od::object_code::array, "Write analog output 16-bit"sv, dictionary.entries().subspan(161, 3), dictionary.infos().subspan(161, 3)};

} // namespace fieldcodec::dictionaries::io_node
// clang-format on
