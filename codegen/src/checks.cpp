// fieldcodec-gen — checks of a whole dictionary, whatever format it was read from.
#include "readers.hpp"
#include "text.hpp"

namespace fieldcodec::gen {

// CiA 301 7.5.2.35..38: a PDO has a communication parameter (RPDO 1400h..15FFh, TPDO
// 1800h..19FFh) and a mapping parameter 200h above it (1600h..17FFh, 1A00h..1BFFh). A device that
// supports the PDO has both; masters configure one through the other (python canopen's
// RemoteNode fails with a KeyError on a communication object without its mapping object).
//
// EtherCAT (CoE) has no PDO communication parameters: a sync manager's PDO assignment (1C12h
// RxPDO, 1C13h TxPDO) says which mapping objects are used. In a dictionary with either, mapping
// parameters without communication parameters are what CoE expects.
void check_pdo_pairs(const dictionary &d, const std::string &file, diagnostics &diag) {
  const bool coe = d.objects.count(0x1C12) != 0U || d.objects.count(0x1C13) != 0U;
  struct block {
    std::uint16_t first;
    const char *pdo;
    const char *role;
    std::int32_t partner; // offset to the other parameter of the same PDO
    const char *partner_role;
  };
  constexpr block blocks[] = {
      {0x1400, "RPDO", "communication", 0x200, "mapping"},
      {0x1600, "RPDO", "mapping", -0x200, "communication"},
      {0x1800, "TPDO", "communication", 0x200, "mapping"},
      {0x1A00, "TPDO", "mapping", -0x200, "communication"},
  };
  for (const auto &[index, info] : d.objects) {
    for (const auto &b : blocks) {
      if (index < b.first || index > b.first + 0x1FFU) continue;
      const auto other = static_cast<std::uint16_t>(index + b.partner);
      if (d.objects.count(other) != 0U || (coe && b.partner < 0)) break;
      diag.warning(file, info.line, 0,
                   std::string(b.pdo) + " " + std::to_string(index - b.first + 1U) + " has a " +
                       b.role + " parameter 0x" + hex(index, 4) + " but no " + b.partner_role +
                       " parameter 0x" + hex(other, 4) +
                       " (CiA 301: a PDO has both; masters that configure the PDO fail on it)");
      break;
    }
  }
}

} // namespace fieldcodec::gen
