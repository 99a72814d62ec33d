// The consumer of the README's recipes (installed package, subproject, plain include path):
// uses the library and checks one manual vector at compile time and at run time.
#include <fieldcodec/core/bcd.hpp>

int main() {
  // COMPAX POSA 7350.150 mm → 00 00 07 35 01 50 (manual 000, "Position values")
  constexpr auto pos = fieldcodec::bcd::encode_signed<6>(7'350'150);
  static_assert(pos.value()[3] == 0x35);
  return pos.value()[5] == 0x50 ? 0 : 1;
}
