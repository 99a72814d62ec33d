// The object dictionary of the SDO transfer tests: one object of every fixed-size type, byte
// strings of several capacities (a domain longer than any CoE mailbox among them), limits,
// access rights, a record. Shared by tests/canopen/sdo_transfer_test.cpp (SDO over CAN) and
// tests/coe/ (the same transfers over CoE mailboxes).
#pragma once

#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/dictionary.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/number.hpp>

namespace sdo_test {

namespace od = fieldcodec::od;
using od::data_type;

inline constexpr od::entry_spec specs[] = {
    {.index = 0x1000,
     .type = data_type::unsigned32,
     .access_type = od::access::ro,
     .default_value = od::unsigned_number(0x00020192)},
    {.index = 0x1008,
     .type = data_type::visible_string,
     .access_type = od::access::constant,
     .size = 16,
     .default_text = "XENAX Xvi 75V8S"},
    {.index = 0x2001, .type = data_type::boolean},
    {.index = 0x2002, .type = data_type::integer8},
    {.index = 0x2003, .type = data_type::integer16},
    {.index = 0x2004, .type = data_type::integer32},
    {.index = 0x2005, .type = data_type::unsigned8},
    {.index = 0x2006, .type = data_type::unsigned16},
    {.index = 0x2007, .type = data_type::unsigned32},
    {.index = 0x2008, .type = data_type::real32},
    {.index = 0x2009, .type = data_type::visible_string, .size = 400},
    {.index = 0x200A, .type = data_type::octet_string, .size = 600},
    {.index = 0x200B, .type = data_type::unicode_string, .size = 64},
    {.index = 0x200C, .type = data_type::time_of_day},
    {.index = 0x200D, .type = data_type::time_difference},
    {.index = 0x200F, .type = data_type::domain, .size = 1000},
    {.index = 0x2010, .type = data_type::integer24},
    {.index = 0x2011, .type = data_type::real64},
    {.index = 0x2012, .type = data_type::integer40},
    {.index = 0x2013, .type = data_type::integer48},
    {.index = 0x2014, .type = data_type::integer56},
    {.index = 0x2015, .type = data_type::integer64},
    {.index = 0x2016, .type = data_type::unsigned24},
    {.index = 0x2018, .type = data_type::unsigned40},
    {.index = 0x2019, .type = data_type::unsigned48},
    {.index = 0x201A, .type = data_type::unsigned56},
    {.index = 0x201B, .type = data_type::unsigned64},
    {.index = 0x2020, .type = data_type::domain, .size = 5000}, // longer than any mailbox
    {.index = 0x3000,
     .sub = 0,
     .object = od::object_code::record,
     .type = data_type::unsigned8,
     .access_type = od::access::ro,
     .default_value = od::unsigned_number(2)},
    {.index = 0x3000,
     .sub = 1,
     .object = od::object_code::record,
     .type = data_type::unsigned16,
     .access_type = od::access::wo},
    {.index = 0x3000,
     .sub = 2,
     .object = od::object_code::record,
     .type = data_type::integer16,
     .low = od::signed_number(-20),
     .high = od::signed_number(20)},
    {.index = 0x3001, .type = data_type::domain}, // no size: not storable
};
/// The entries, packed once (a std::span<const od::entry, N>).
inline constexpr auto entries = od::entries_of<specs>;
inline constexpr od::dictionary dict{entries};
static_assert(dict.is_valid());

} // namespace sdo_test
