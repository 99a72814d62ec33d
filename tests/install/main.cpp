// A consumer of the installed package: uses the library, checks one manual vector and, in the
// find_package() consumer, a dictionary generated at build time from its own CSV file.
#include <fieldcodec/core/bcd.hpp>
#ifdef FIELDCODEC_CONSUMER_HAS_DICTIONARY
#include <fieldcodec/dictionaries/my_device.hpp>
#endif

int main() {
  constexpr auto pos = fieldcodec::bcd::encode_signed<6>(7'350'150);
  static_assert(pos.value()[3] == 0x35);
#ifdef FIELDCODEC_CONSUMER_HAS_DICTIONARY
  namespace dev = fieldcodec::dictionaries::my_device;
  static_assert(dev::pressure_limit.to_raw(4.0).value() == 1311);
  if (dev::dictionary.find(0x2000, 0) == nullptr) return 1;
#endif
  return pos.value()[5] == 0x50 ? 0 : 1;
}
