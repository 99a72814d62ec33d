// fieldcodec — the units of XENAX objects that its EDS cannot carry (CiA 306 has no unit or
// scale key; docs/xenax.md, decision 15), as data for od::with_unit: the current limits 6073h
// and 5003h subs 0Ch (IS) / 13h (IR) in 10 mA steps, 2005h and 6078h in mA, 2009h/200Ah in mN,
// 2007h in µs, 6068h in ms, positions in encoder increments, speeds in inc/s, accelerations
// in inc/s². Applied to a descriptor, a value in these units goes through od's one value path
// (od/engineering.hpp, od/value_text.hpp): 6073h "1500 mA" is raw 150, and raw 150 reads "1500 mA".
#pragma once

#include <fieldcodec/od/engineering.hpp>

#include <array>

namespace fieldcodec::xenax {

namespace detail {
/// raw = EU × 0.1: one raw step is 10 mA.
inline constexpr scaling::linear per_10_ma{{1, 1}, {0, 0}};
} // namespace detail

/// The XENAX units for od::with_unit, for the objects of its three dictionaries (CANopen,
/// EtherCAT, POWERLINK) that have one.
inline constexpr std::array<od::unit_rule, 23> canopen_units{{
    {0x6073, -1, "mA", detail::per_10_ma},
    {0x5003, 0x0C, "mA", detail::per_10_ma},
    {0x5003, 0x13, "mA", detail::per_10_ma},
    {0x2005, -1, "mA", {}},
    {0x6078, -1, "mA", {}},
    {0x2009, -1, "mN", {}},
    {0x200A, -1, "mN", {}},
    {0x2007, -1, "µs", {}},
    {0x6068, -1, "ms", {}},
    {0x6064, -1, "inc", {}},
    {0x6065, -1, "inc", {}},
    {0x6067, -1, "inc", {}},
    {0x607A, -1, "inc", {}},
    {0x607D, -1, "inc", {}},
    {0x60F4, -1, "inc", {}},
    {0x606C, -1, "inc/s", {}},
    {0x6081, -1, "inc/s", {}},
    {0x60FF, -1, "inc/s", {}},
    {0x60B1, -1, "inc/s", {}},
    {0x6099, -1, "inc/s", {}},
    {0x6083, -1, "inc/s²", {}},
    {0x6084, -1, "inc/s²", {}},
    {0x6085, -1, "inc/s²", {}},
}};

} // namespace fieldcodec::xenax
