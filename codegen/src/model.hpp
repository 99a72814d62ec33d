// fieldcodec-gen — the generator's in-memory dictionary model (host tool, std library only).
#pragma once

#include <fieldcodec/compax/columns.hpp>
#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/dpq/columns.hpp>
#include <fieldcodec/od/command.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/entry_spec.hpp>
#include <fieldcodec/od/number.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fieldcodec::gen {

/// Keys of a section as written (name, value), in file order.
using key_list = std::vector<std::pair<std::string, std::string>>;

/// A text that is empty for nearly every entry (the columns only CSV tables have): 8 bytes, the
/// string allocated when a text is set, where a std::string takes 32 bytes in every entry (an
/// entry's pages are a measurable part of reading a big EDS; docs/performance.md). Reads like a
/// `const std::string &` (an empty one when no text is set).
class rare_text {
public:
  rare_text() = default;
  rare_text(const rare_text &o) : p_(o.p_ ? std::make_unique<std::string>(*o.p_) : nullptr) {}
  rare_text(rare_text &&) noexcept = default;
  rare_text &operator=(const rare_text &o) {
    if (this != &o) p_ = o.p_ ? std::make_unique<std::string>(*o.p_) : nullptr;
    return *this;
  }
  rare_text &operator=(rare_text &&) noexcept = default;
  ~rare_text() = default;
  /// Sets the text (an empty one frees the string).
  rare_text &operator=(std::string_view s) {
    if (s.empty()) {
      p_.reset();
    } else if (p_) {
      p_->assign(s);
    } else {
      p_ = std::make_unique<std::string>(s);
    }
    return *this;
  }
  [[nodiscard]] const std::string &str() const noexcept {
    static const std::string none;
    return p_ ? *p_ : none;
  }
  operator const std::string &() const noexcept { return str(); }
  operator std::string_view() const noexcept { return str(); }
  [[nodiscard]] bool empty() const noexcept { return !p_ || p_->empty(); }
  [[nodiscard]] std::size_t size() const noexcept { return p_ ? p_->size() : 0U; }
  [[nodiscard]] const char *data() const noexcept { return str().data(); }
  void clear() noexcept { p_.reset(); }
  friend bool operator==(const rare_text &a, const rare_text &b) noexcept {
    return a.str() == b.str();
  }
  friend bool operator==(const rare_text &a, std::string_view b) noexcept { return a.str() == b; }

private:
  std::unique_ptr<std::string> p_;
};

/// Where an EDS lists an object: [MandatoryObjects], [OptionalObjects], [ManufacturerObjects].
enum class object_list : std::uint8_t { mandatory, optional, manufacturer };

/// One sub-object as read from an EDS/DCF or a CSV object table.
struct entry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  /// Sub-indices this entry stands for: sub .. sub + count - 1. 1 for every entry except a run of
  /// CompactSubObj sub-objects kept compact (--keep-compact): those are alike in everything but
  /// their names, sub-index i is named `name` followed by i in decimal ("TPDO 1 mapping5").
  std::uint16_t count = 1;
  od::object_code object = od::object_code::var;
  std::uint16_t type_code = 0;                ///< data type as written (may be > 0x1B)
  od::data_type type = od::data_type::domain; ///< type_code if a basic type, DOMAIN otherwise
  od::access access = od::access::ro;
  od::pdo_mapping pdo = od::pdo_mapping::no;
  std::uint8_t flags = 0;
  /// Capacity in bytes of a VISIBLE_STRING / OCTET_STRING / UNICODE_STRING / DOMAIN value (0: no
  /// capacity known; docs/generator.md "String and DOMAIN capacity"); 0 for every other type.
  std::uint32_t size = 0;
  bool size_declared = false; ///< `size` is given by the file (CSV `bytes`, EDS `Size=`)
  std::string name;
  rare_text symbol; ///< requested C++ identifier (CSV `symbol`), empty: derive from name
  od::number low, high, default_value, parameter_value;
  bool low_nodeid = false;       ///< low is "$NODEID + low"
  bool high_nodeid = false;      ///< high is "$NODEID + high"
  bool default_nodeid = false;   ///< default_value is "$NODEID + default_value"
  bool parameter_nodeid = false; ///< parameter_value (DCF ParameterValue) is "$NODEID + ..."
  /// Default / DCF ParameterValue of a byte-string entry: the value's bytes as a store holds them
  /// (an EDS OCTET_STRING / DOMAIN written as hex digits is decoded, a UNICODE_STRING is UTF-16LE).
  rare_text default_text, parameter_text;
  std::string denotation;
  bool scaled = false;
  decimal scale{1, 0}, offset{0, 0};
  rare_text unit, alt_name, section, remark; ///< CSV columns
  /// The data type's name in an ESI (`BYTE`, `BIT2`, `STRING(10)`, `UINT32`): written back by the
  /// ESI writer where it differs from the name of `type_code`; empty for other sources.
  rare_text type_name;
  // Columns of one manufacturer's table (CSV), emitted as that manufacturer's table beside the
  // dictionary (emit_header.cpp "vendor columns"), not as od::entry_info.
  dpq::acceptance acceptance = dpq::acceptance::unknown; ///< DPQ "Value acceptance"
  dpq::bus_manager bus = dpq::bus_manager::unspecified;  ///< DPQ "Busmanager"
  std::optional<std::uint8_t> pointer;                   ///< COMPAX index pointer
  std::uint32_t obj_flags = 0;
  bool has_obj_flags = false;
  /// Keys of the EDS section the reader does not interpret (UploadFile, SRDOMapping, a vendor's
  /// Unit, ...): not in the header, written back unchanged by the EDS writer.
  key_list other_keys;
  int line = 0; ///< source line (diagnostics)
};

/// Object-level information (one per index).
struct object_info {
  std::uint16_t index = 0;
  od::object_code code = od::object_code::var;
  std::string name;
  std::string symbol;
  std::uint8_t sub_number = 0;  ///< EDS SubNumber (0 for VAR)
  std::uint8_t compact_sub = 0; ///< EDS CompactSubObj (0: not compact)
  std::uint32_t obj_flags = 0;
  bool has_obj_flags = false;
  object_list list = object_list::mandatory;
  std::vector<std::uint16_t> object_links; ///< DCF/EDS [xxxxObjectLinks], in file order
  key_list other_keys; ///< keys of a container's object section the reader does not interpret
  int line = 0;
};

/// A section of an EDS the reader keeps but does not interpret ([Tools], [M1ModuleInfo], a
/// vendor's own section, ...): written back unchanged by the EDS writer.
struct other_section {
  std::string name;
  key_list keys;
};

/// The list an object not listed anywhere belongs in: the CiA 306 mandatory objects 1000h, 1001h
/// and 1018h, manufacturer-specific 2000h..5FFFh, optional otherwise.
[[nodiscard]] constexpr object_list default_list(std::uint16_t index) noexcept {
  if (index == 0x1000U || index == 0x1001U || index == 0x1018U) return object_list::mandatory;
  return index >= 0x2000U && index < 0x6000U ? object_list::manufacturer : object_list::optional;
}

/// The bus an XML device description is for: an XDD/XDC names CANopen (CiA 311) or POWERLINK
/// (EPSG DS 311), an ESI is EtherCAT (ETG.2000). `unspecified` for EDS, DCF and CSV input.
enum class bus_profile : std::uint8_t { unspecified, canopen, powerlink, ethercat };

/// One entry of an EtherCAT PDO (ESI RxPdo/TxPdo Entry): index 0 is a gap of `bits` bits.
struct esi_pdo_entry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint8_t bits = 0;
  std::string name;
  std::string data_type; ///< as the ESI writes it (USINT, BOOL, BIT2, ...); empty for a gap
  int line = 0;
};

/// An EtherCAT PDO as an ESI describes it (ETG.2000 RxPdo/TxPdo).
struct esi_pdo {
  bool tx = false; ///< TxPdo (inputs, device to master) or RxPdo (outputs)
  std::uint16_t index = 0;
  std::string name;
  bool fixed = false;                  ///< the mapping cannot be changed
  bool mandatory = false;              ///< always assigned
  int sm = -1;                         ///< the sync manager it is assigned to by default, -1: none
  std::vector<std::uint16_t> excludes; ///< PDOs that cannot be assigned with it
  key_list other_attributes;           ///< attributes kept as written (Virtual, Su, OSFac, ...)
  std::vector<esi_pdo_entry> entries;
  int line = 0;
};

/// A sync manager of an ESI device (ETG.2000 Sm).
struct esi_sync_manager {
  std::string type; ///< MBoxOut, MBoxIn, Outputs, Inputs
  std::uint16_t start = 0;
  std::uint16_t default_size = 0;
  bool has_default_size = false;
  std::uint8_t control = 0;
  bool enable = true;
  int line = 0;
};

/// What an ESI (EtherCAT Slave Information, ETG.2000) says about a device beyond its object
/// dictionary: identity, sync managers, PDOs, mailbox protocols, EEPROM.
struct esi_device {
  std::uint32_t vendor_id = 0;
  std::string vendor_name;
  std::uint32_t product_code = 0;
  std::uint32_t revision = 0;
  std::string type;  ///< the Type element's text (the order name)
  std::string name;  ///< the device name (language 1033 where there are several)
  std::string group; ///< GroupType
  std::string group_name;
  std::string physics;
  std::uint32_t profile_no = 0; ///< Profile/ProfileNo (402: CiA 402), 0 when none
  std::string add_info;         ///< Profile/AddInfo as written
  std::vector<std::string> fmmu;
  std::vector<esi_sync_manager> sync_managers;
  std::vector<esi_pdo> pdos;
  bool mailbox = false;               ///< a Mailbox element
  bool data_link_layer = false;       ///< Mailbox DataLinkLayer="true"
  std::vector<std::string> protocols; ///< CoE, FoE, EoE, SoE, VoE, AoE as present
  key_list coe;                       ///< the CoE element's attributes as written
  std::uint32_t eeprom_bytes = 0;     ///< Eeprom/ByteSize, 0 when none
  std::string config_data;            ///< Eeprom/ConfigData (hex) as written
  std::string bootstrap;              ///< Eeprom/BootStrap (hex) as written
  int line = 0;                       ///< the Device element's line
  int eeprom_line = 0;                ///< the Eeprom element's line, 0 when none
};

/// One row of a command table.
struct command {
  std::uint16_t code = 0;
  std::string name, symbol, section, title, parameter, date, reply, modes, remark;
  od::number parameter_min, parameter_max, date_min, date_max;
  od::packing parameter_packing = od::packing::whole;
  od::packing date_packing = od::packing::whole;
  od::command_value date_type = od::command_value::none;
  od::command_value reply_type = od::command_value::none;
  int line = 0;
};

/// A whole dictionary or command table.
struct dictionary {
  std::string source_name; ///< file name (no directories) for the "generated from" line
  std::string stem;        ///< namespace name
  bool is_command_table = false;
  /// The header names each named sub-object of an ARRAY/RECORD with a standalone descriptor
  /// (the default); false (--no-sub-descriptors): only the object's view, `view[sub]`.
  bool sub_descriptors = true;
  std::vector<entry> entries; ///< sorted by (index, sub-index)
  std::map<std::uint16_t, object_info> objects;
  std::vector<command> commands; ///< sorted by code
  // EDS header sections, kept for writing EDS (key, value in file order)
  key_list file_info, device_info, dummy_usage;
  key_list commissioning; ///< [DeviceComissioning] as read (NodeID, NodeName, Baudrate, ...)
  std::vector<std::string> comments;
  std::vector<other_section> other_sections; ///< in file order
  bool is_dcf = false;
  int node_id = -1; ///< [DeviceComissioning] NodeID, -1 when absent
  std::string node_name;
  /// The bus of the XML description read (the XDD writer's default profile).
  bus_profile profile = bus_profile::unspecified;
  /// EtherCAT: what the ESI read says beyond the objects (nothing for other sources).
  std::optional<esi_device> ethercat;
};

/// The entry as od::pack takes it (every column a plain member; the text views `e`'s strings;
/// the first sub-index of an entry that stands for `count` of them).
[[nodiscard]] inline od::entry_spec spec_of(const entry &e) {
  od::entry_spec s;
  s.index = e.index;
  s.sub = e.sub;
  s.object = e.object;
  s.type = e.type;
  s.access_type = e.access;
  s.pdo = e.pdo;
  std::uint16_t f = e.flags;
  if (e.scaled) f |= od::flag::scaled;
  if (e.default_nodeid) f |= od::flag::default_nodeid;
  if (e.low_nodeid) f |= od::flag::low_nodeid;
  if (e.high_nodeid) f |= od::flag::high_nodeid;
  if (e.parameter_nodeid) f |= od::flag::parameter_nodeid;
  s.flags = f;
  s.size = e.size;
  s.low = e.low;
  s.high = e.high;
  s.default_value = e.default_value;
  s.default_text = od::text(e.default_text.data(), e.default_text.size());
  return s;
}

} // namespace fieldcodec::gen
