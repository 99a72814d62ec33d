// The consumer of docs/generator.md's recipes: a header generated at build time from
// devices/drive.eds (tests/install/drive.eds) by fieldcodec_generate_dictionary().
#include <fieldcodec/dictionaries/drive.hpp>

namespace drive = fieldcodec::dictionaries::drive;

int main() {
  static_assert(drive::dictionary.is_valid());
  const auto *type = drive::dictionary.find(0x1000, 0);
  const auto *limit = drive::dictionary.find(0x2000, 0);
  if (type == nullptr || limit == nullptr) return 1;
  auto v = limit->default_value().to_int64();
  return v && v.value() == 1311 ? 0 : 2;
}
