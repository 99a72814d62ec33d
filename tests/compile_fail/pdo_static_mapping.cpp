// Compile-time PDO mappings: a correct one compiles (control), each mistake (selected with
// -DCASE=n) must stop the build with a compile_error::pdo_mapping_<problem> diagnostic.
// Run by tests/compile_fail/run.cmake.
#include <fieldcodec/canopen/pdo.hpp>
#include <fieldcodec/dictionaries/xenax_canopen.hpp>

namespace pdo = fieldcodec::canopen::pdo;
namespace xcan = fieldcodec::dictionaries::xenax_canopen;
using pdo::mapping_entry;

#ifndef CASE
#define CASE 0
#endif

#if CASE == 0 // controlword + target position: fine
constexpr mapping_entry entries[] = {{0x6040, 0, 16}, {0x607A, 0, 32}};
constexpr auto direction = pdo::direction::rpdo;
#elif CASE == 1 // INTEGER32 target position mapped as 16 bits
constexpr mapping_entry entries[] = {{0x607A, 0, 16}};
constexpr auto direction = pdo::direction::rpdo;
#elif CASE == 2 // 80 bits do not fit a CAN frame
constexpr mapping_entry entries[] = {{0x6064, 0, 32}, {0x6064, 0, 32}, {0x6041, 0, 16}};
constexpr auto direction = pdo::direction::tpdo;
#elif CASE == 3 // no such object
constexpr mapping_entry entries[] = {{0x6ABC, 0, 16}};
constexpr auto direction = pdo::direction::rpdo;
#elif CASE == 4 // statusword is read-only: not into a receive PDO
constexpr mapping_entry entries[] = {{0x6041, 0, 16}};
constexpr auto direction = pdo::direction::rpdo;
#endif

constexpr auto mapping = pdo::make_static_mapping(xcan::dictionary, direction, entries);
static_assert(mapping.total_bits > 0);

int main() { return 0; }
