#include <fieldcodec/dictionaries/my_drive.hpp>

namespace drive = fieldcodec::dictionaries::my_drive;

static_assert(drive::device_type.index == 0x1000);
static_assert(drive::identity_object.find(4) != nullptr);

int main() {
  return drive::dictionary.find(0x1014, 0)->default_for(3).value().bits == 0x83U ? 0 : 1;
}
