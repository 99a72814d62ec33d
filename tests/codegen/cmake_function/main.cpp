#include <fieldcodec/dictionaries/my_drive.hpp>
#include <fieldcodec/dictionaries/my_drive_empty.hpp>
#include <fieldcodec/dictionaries/my_drive_views.hpp>
#include <fieldcodec/dictionaries/my_ecat_pdos.hpp>

namespace drive = fieldcodec::dictionaries::my_drive;
namespace views = fieldcodec::dictionaries::my_drive_views;

static_assert(drive::device_type.index == 0x1000);
static_assert(drive::identity_object.find(4) != nullptr);
// the tables are spans with a constant size
static_assert(drive::entries.size() == drive::dictionary.size() &&
              drive::infos.size() == drive::entries.size());

// --no-sub-descriptors: the view names the sub-object; the descriptor is the same constant
inline constexpr fieldcodec::od::descriptor vendor_id = views::identity_object[1];
static_assert(vendor_id.index == drive::identity_object_vendor_id.index &&
              vendor_id.sub == drive::identity_object_vendor_id.sub &&
              vendor_id.info.name == drive::identity_object_vendor_id.info.name);
static_assert(views::device_type.index == 0x1000); // VAR objects keep their descriptors

// no entries: empty spans and an empty, valid dictionary
static_assert(fieldcodec::dictionaries::my_drive_empty::entries.size() == 0 &&
              fieldcodec::dictionaries::my_drive_empty::dictionary.empty());

// the ESI's RxPDO 0x1600: controlword and target position, checked against the dictionary
static_assert(fieldcodec::dictionaries::my_ecat::pdos::rxpdo_1600.bytes() == 6);

int main() {
  return drive::dictionary.find(0x1014, 0)->default_for(3).value().bits == 0x83U ? 0 : 1;
}
