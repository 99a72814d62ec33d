// dpq_dictionary: the whole DPQ dictionary; a parameter looked up at run time by the index that
// arrives, EU → bytes and bytes → EU with exact decimal scaling (as size_dpq.cpp for one name).
#include "io.hpp"

#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/parameter.hpp>

namespace p = fieldcodec::dictionaries::dpq_parameters;

int main() {
  auto d = p::dictionary.at({fw::receive_u16(), 0});
  if (!d) return 1;
  const fieldcodec::decimal bar{static_cast<std::int64_t>(fw::rx_register[2]), 1};
  if (auto b = fieldcodec::dpq::to_bytes(*d, bar)) fw::transmit(b.value().span());
  if (auto eu = fieldcodec::dpq::from_bytes(*d, fw::receive<4>(4))) {
    fw::tx_register[0] = static_cast<std::uint8_t>(eu.value().mantissa);
  }
  return 0;
}
