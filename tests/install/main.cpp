// A consumer of the installed package: uses the library and checks one manual vector.
#include <fieldcodec/core/bcd.hpp>

int main() {
  constexpr auto pos = fieldcodec::bcd::encode_signed<6>(7'350'150);
  static_assert(pos.value()[3] == 0x35);
  return pos.value()[5] == 0x50 ? 0 : 1;
}
