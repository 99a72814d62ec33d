// dpq_descriptor: what naming one generated descriptor costs, and nothing else. The descriptor's
// address goes to a volatile register, so the whole constant (entry, info, scale and the strings
// they view) must be in flash; no codec is used.
#include "io.hpp"

#include <fieldcodec/dictionaries/dpq_parameters.hpp>

namespace p = fieldcodec::dictionaries::dpq_parameters;

inline const void *volatile descriptor_register;

int main() {
  auto in = fw::receive<8>();
  fw::transmit(in);
  descriptor_register = &p::inj_p_limit_1;
  return 0;
}
