// fieldcodec-gen — the generator's in-memory dictionary model (host tool, std library only).
#pragma once

#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/od/command.hpp>
#include <fieldcodec/od/data_type.hpp>
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/number.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fieldcodec::gen {

/// One sub-object as read from an EDS/DCF or a CSV object table.
struct entry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  od::object_code object = od::object_code::var;
  std::uint16_t type_code = 0;                ///< data type as written (may be > 0x1B)
  od::data_type type = od::data_type::domain; ///< type_code if a basic type, DOMAIN otherwise
  od::access access = od::access::ro;
  od::pdo_mapping pdo = od::pdo_mapping::no;
  std::uint8_t flags = 0;
  std::uint32_t size = 0;
  std::string name;
  std::string symbol; ///< requested C++ identifier (CSV `symbol`), empty: derive from name
  od::number low, high, def, param;
  bool def_nodeid = false, param_nodeid = false;
  std::string def_text, param_text, denotation;
  bool scaled = false;
  decimal scale{1, 0}, offset{0, 0};
  std::string unit, alt_name, acceptance, section, remark;
  std::uint8_t pointer = od::no_pointer;
  od::bus_manager bus = od::bus_manager::unspecified;
  std::uint32_t obj_flags = 0;
  bool has_obj_flags = false;
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
  int list = 0; ///< 0 mandatory, 1 optional, 2 manufacturer
  int line = 0;
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
  std::vector<entry> entries; ///< sorted by (index, sub-index)
  std::map<std::uint16_t, object_info> objects;
  std::vector<command> commands; ///< sorted by code
  // EDS header sections, kept for writing EDS (key, value in file order)
  std::vector<std::pair<std::string, std::string>> file_info, device_info, dummy_usage;
  std::vector<std::string> comments;
  bool is_dcf = false;
  int node_id = -1; ///< [DeviceComissioning] NodeID, -1 when absent
  std::string node_name;
};

} // namespace fieldcodec::gen
