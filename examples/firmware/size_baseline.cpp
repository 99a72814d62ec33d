// Size baseline: the same scaffolding as every size_<module>.cpp, without any codec.
#include "io.hpp"

int main() {
  auto in = fw::receive<8>();
  fw::transmit(in);
  return 0;
}
