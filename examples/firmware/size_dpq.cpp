// dpq: engineering units ↔ card raw values of one parameter (exact decimal scaling).
#include "io.hpp"

#include <fieldcodec/dictionaries/dpq_parameters.hpp>
#include <fieldcodec/dpq/parameter.hpp>

namespace p = fieldcodec::dictionaries::dpq_parameters;

// Generated descriptors are standalone constants: naming one keeps only that one in flash, not
// the dictionary's tables.
using p::inj_p_limit_1;

int main() {
  const fieldcodec::decimal bar{static_cast<std::int64_t>(fw::rx_register[0]), 1};
  if (auto b = fieldcodec::dpq::to_bytes(inj_p_limit_1, bar)) fw::transmit(b.value().span());
  if (auto eu = fieldcodec::dpq::from_bytes(inj_p_limit_1, fw::receive<4>())) {
    fw::tx_register[0] = static_cast<std::uint8_t>(eu.value().mantissa);
  }
  return 0;
}
