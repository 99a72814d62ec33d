// Generated from xenax_ethercat.eds by fieldcodec-gen --pdo-header — do not edit.
// The PDO layouts of the dictionary fieldcodec::dictionaries::xenax_ethercat, each made by
// canopen::pdo::make_static_mapping: with the dictionary, checked by the compiler against
// it (objects, PDO mapping, access, lengths) and read with each object's signedness; a
// layout that fails those checks is checked for lengths only (the comment says why).
// clang-format off
#pragma once

#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/dictionaries/xenax_ethercat.hpp>

namespace fieldcodec::dictionaries::xenax_ethercat::pdos {

// RxPDO 0x1600 "Receive PDO 1": 1 entry, 16 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1600_entries[]{{0x6040, 0, 16}};
inline constexpr auto rxpdo_1600 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1600_entries, 8192);

// RxPDO 0x1601 "Receive PDO 2": 2 entries, 48 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1601_entries[]{{0x6040, 0, 16}, {0x607A, 0, 32}};
inline constexpr auto rxpdo_1601 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1601_entries, 8192);

// RxPDO 0x1611 "Receive PDO 17": 3 entries, 80 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1611_entries[]{{0x6040, 0, 16}, {0x607A, 0, 32}, {0x60FE, 1, 32}};
inline constexpr auto rxpdo_1611 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1611_entries, 8192);

// RxPDO 0x1612 "Receive PDO 18": 9 entries, 272 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1612_entries[]{{0x6040, 0, 16}, {0x607A, 0, 32}, {0x6081, 0, 32}, {0x6083, 0, 32}, {0x6084, 0, 32}, {0x2000, 0, 32}, {0x6065, 0, 32}, {0x6067, 0, 32}, {0x60FE, 1, 32}};
inline constexpr auto rxpdo_1612 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1612_entries, 8192);

// RxPDO 0x1613 "Receive PDO 19 (reserved for future)": 5 entries, 144 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1613_entries[]{{0x6040, 0, 16}, {0x6081, 0, 32}, {0x2001, 0, 32}, {0x2003, 0, 32}, {0x60FE, 1, 32}};
inline constexpr auto rxpdo_1613 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1613_entries, 8192);

// RxPDO 0x1614 "Receive PDO 20 (reserved for future)": 3 entries, 80 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1614_entries[]{{0x6040, 0, 16}, {0x2002, 0, 32}, {0x60FE, 1, 32}};
inline constexpr auto rxpdo_1614 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1614_entries, 8192);

// RxPDO 0x1615 "Receive PDO 21": 5 entries, 128 bits
inline constexpr canopen::pdo::mapping_entry rxpdo_1615_entries[]{{0x6040, 0, 16}, {0x607A, 0, 32}, {0x6065, 0, 32}, {0x6067, 0, 32}, {0x6073, 0, 16}};
inline constexpr auto rxpdo_1615 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::rpdo, rxpdo_1615_entries, 8192);

// TxPDO 0x1A00 "Transmit PDO 1": 1 entry, 16 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a00_entries[]{{0x6041, 0, 16}};
inline constexpr auto txpdo_1a00 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a00_entries, 8192);

// TxPDO 0x1A01 "Transmit PDO 2": 2 entries, 48 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a01_entries[]{{0x6041, 0, 16}, {0x6064, 0, 32}};
inline constexpr auto txpdo_1a01 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a01_entries, 8192);

// TxPDO 0x1A10 "Transmit PDO 17": 3 entries, 80 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a10_entries[]{{0x6041, 0, 16}, {0x6064, 0, 32}, {0x60FD, 0, 32}};
inline constexpr auto txpdo_1a10 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a10_entries, 8192);

// TxPDO 0x1A11 "Transmit PDO 18": 5 entries, 128 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a11_entries[]{{0x6041, 0, 16}, {0x6064, 0, 32}, {0x60F4, 0, 32}, {0x6078, 0, 16}, {0x60FD, 0, 32}};
inline constexpr auto txpdo_1a11 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a11_entries, 8192);

// TxPDO 0x1A12 "Transmit PDO 19 (reserved for future)": 4 entries, 112 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a12_entries[]{{0x6041, 0, 16}, {0x6064, 0, 32}, {0x2005, 0, 32}, {0x60FD, 0, 32}};
inline constexpr auto txpdo_1a12 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a12_entries, 8192);

// TxPDO 0x1A13 "Transmit PDO 21": 5 entries, 128 bits
inline constexpr canopen::pdo::mapping_entry txpdo_1a13_entries[]{{0x6041, 0, 16}, {0x6064, 0, 32}, {0x60F4, 0, 32}, {0x6078, 0, 16}, {0x2006, 0, 32}};
inline constexpr auto txpdo_1a13 = canopen::pdo::make_static_mapping(
    dictionary, canopen::pdo::direction::tpdo, txpdo_1a13_entries, 8192);

} // namespace fieldcodec::dictionaries::xenax_ethercat::pdos
// clang-format on
