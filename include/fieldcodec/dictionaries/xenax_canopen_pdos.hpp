// Generated from xenax_canopen.eds by fieldcodec-gen --pdo-header — do not edit.
// The PDO layouts of the dictionary fieldcodec::dictionaries::xenax_canopen, each made by
// canopen::pdo::make_static_mapping: with the dictionary, checked by the compiler against
// it (objects, PDO mapping, access, lengths) and read with each object's signedness; a
// layout that fails those checks is checked for lengths only (the comment says why).
// clang-format off
#pragma once

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>

namespace fieldcodec::dictionaries::xenax_canopen::pdos {

// RxPDO 0x1600 "Receive PDO Mapping Param 1": 1 entry, 16 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1600_entries[]{{0x6040, 0, 16}};
inline constexpr auto rxpdo_1600 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1600_entries, 64);

// RxPDO 0x1601 "Receive PDO Mapping Param 2": 2 entries, 48 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1601_entries[]{{0x6040, 0, 16}, {0x607A, 0, 32}};
inline constexpr auto rxpdo_1601 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1601_entries, 64);

// RxPDO 0x1610 "Receive PDO Mapping Param 17": 1 entry, 32 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1610_entries[]{{0x60FE, 1, 32}};
inline constexpr auto rxpdo_1610 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1610_entries, 64);

// RxPDO 0x1611 "Receive PDO Mapping Param 18": 2 entries, 64 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1611_entries[]{{0x6083, 0, 32}, {0x2000, 0, 32}};
inline constexpr auto rxpdo_1611 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1611_entries, 64);

// RxPDO 0x1612 "Receive PDO Mapping Param 19": 1 entry, 32 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1612_entries[]{{0x6081, 0, 32}};
inline constexpr auto rxpdo_1612 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1612_entries, 64);

// RxPDO 0x1613 "Receive PDO Mapping Param 20": 2 entries, 64 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1613_entries[]{{0x6065, 0, 32}, {0x6067, 0, 32}};
inline constexpr auto rxpdo_1613 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1613_entries, 64);

// RxPDO 0x1614 "Receive PDO Mapping Param 21": 1 entry, 16 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1614_entries[]{{0x6073, 0, 16}};
inline constexpr auto rxpdo_1614 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1614_entries, 64);

// RxPDO 0x1615 "Receive PDO Mapping Param 22": 0 entries, 0 bits
// (maps nothing: no layout)

// RxPDO 0x1616 "Receive PDO Mapping Param 23": 0 entries, 0 bits
// (maps nothing: no layout)

// RxPDO 0x1617 "Receive PDO Mapping Param 24": 2 entries, 48 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1617_entries[]{{0x6040, 0, 16}, {0x2002, 0, 32}};
inline constexpr auto rxpdo_1617 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1617_entries, 64);

// TxPDO 0x1A00 "Transmit PDO Mapping Param 1": 1 entry, 16 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a00_entries[]{{0x6041, 0, 16}};
inline constexpr auto txpdo_1a00 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a00_entries, 64);

// TxPDO 0x1A01 "Transmit PDO Mapping Param 2": 2 entries, 48 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a01_entries[]{{0x6041, 0, 16}, {0x6064, 0, 32}};
inline constexpr auto txpdo_1a01 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a01_entries, 64);

// TxPDO 0x1A10 "Transmit PDO Mapping Param 17": 1 entry, 32 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a10_entries[]{{0x60FD, 0, 32}};
inline constexpr auto txpdo_1a10 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a10_entries, 64);

// TxPDO 0x1A11 "Transmit PDO Mapping Param 18": 0 entries, 0 bits
// (maps nothing: no layout)

// TxPDO 0x1A12 "Transmit PDO Mapping Param 19": 0 entries, 0 bits
// (maps nothing: no layout)

// TxPDO 0x1A13 "Transmit PDO Mapping Param 20": 2 entries, 64 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a13_entries[]{{0x60F4, 0, 32}, {0x2006, 0, 32}};
inline constexpr auto txpdo_1a13 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a13_entries, 64);

// TxPDO 0x1A14 "Transmit PDO Mapping Param 21": 1 entry, 16 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a14_entries[]{{0x6078, 0, 16}};
inline constexpr auto txpdo_1a14 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a14_entries, 64);

// TxPDO 0x1A15 "Transmit PDO Mapping Param 22": 0 entries, 0 bits
// (maps nothing: no layout)

// TxPDO 0x1A16 "Transmit PDO Mapping Param 23": 2 entries, 64 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a16_entries[]{{0x2005, 0, 32}, {0x2006, 0, 32}};
inline constexpr auto txpdo_1a16 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a16_entries, 64);

// TxPDO 0x1A17 "Transmit PDO Mapping Param 24": 2 entries, 48 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a17_entries[]{{0x6041, 0, 16}, {0x2005, 0, 32}};
inline constexpr auto txpdo_1a17 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a17_entries, 64);

} // namespace fieldcodec::dictionaries::xenax_canopen::pdos
// clang-format on
