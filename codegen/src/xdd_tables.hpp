// fieldcodec-gen — what the XDD reader and writer map between an XDD (CiA 311 / EPSG DS 311)
// and the model, which holds CiA 306 keys: one table per mapping, read in both directions.
#pragma once

#include <cstdint>
#include <string_view>

namespace fieldcodec::gen::xdd {

/// An XDD attribute or element with a CiA 306 key; `flag`: xs:boolean in the XDD, 0/1 in CiA 306.
struct mapped_key {
  std::string_view eds_key;
  std::string_view xdd_name;
  bool flag = false;
};

/// ProfileBody attributes ↔ [FileInfo] (dates converted between xs:date and mm-dd-yyyy).
inline constexpr mapped_key file_keys[] = {
    {"FileName", "fileName"},
    {"FileVersion", "fileVersion"},
    {"CreatedBy", "fileCreator"},
    {"CreationDate", "fileCreationDate"},
    {"CreationTime", "fileCreationTime"},
    {"ModifiedBy", "fileModifiedBy"},
    {"ModificationDate", "fileModificationDate"},
    {"ModificationTime", "fileModificationTime"},
};

/// DeviceIdentity children ↔ [DeviceInfo].
inline constexpr mapped_key identity_keys[] = {{"VendorName", "vendorName"},
                                               {"VendorNumber", "vendorID"},
                                               {"ProductName", "productName"},
                                               {"ProductNumber", "productID"},
                                               {"OrderCode", "orderNumber"}};

/// CANopenGeneralFeatures attributes ↔ [DeviceInfo].
inline constexpr mapped_key general_feature_keys[] = {
    {"GroupMessaging", "groupMessaging", true},
    {"DynamicChannelsSupported", "dynamicChannels"},
    {"Granularity", "granularity"},
    {"NrOfRXPDO", "nrOfRxPDO"},
    {"NrOfTXPDO", "nrOfTxPDO"},
    {"SimpleBootUpSlave", "bootUpSlave", true},
    {"LSS_Supported", "layerSettingServiceSlave", true},
};

/// CANopenMasterFeatures attributes ↔ [DeviceInfo].
inline constexpr mapped_key master_feature_keys[] = {{"SimpleBootUpMaster", "bootUpMaster", true}};

/// CiA 301 bit rates (kbit/s): supportedBaudRate "<n> Kbps" ↔ [DeviceInfo] BaudRate_<n>.
inline constexpr std::uint32_t bit_rates[] = {10, 20, 50, 125, 250, 500, 800, 1000};

/// IEC 61131-3 type names of ApplicationProcess parameters (CiA 311) → CiA 301 codes. BITSTRING
/// stands for OCTET_STRING and DOMAIN alike (read as OCTET_STRING); the writer writes the first
/// name of a code.
struct iec_type {
  std::string_view name;
  std::uint16_t code;
};
inline constexpr iec_type iec_types[] = {
    {"BOOL", 0x0001},   {"SINT", 0x0002},      {"INT", 0x0003},     {"DINT", 0x0004},
    {"USINT", 0x0005},  {"UINT", 0x0006},      {"UDINT", 0x0007},   {"REAL", 0x0008},
    {"STRING", 0x0009}, {"BITSTRING", 0x000A}, {"WSTRING", 0x000B}, {"LREAL", 0x0011},
    {"LINT", 0x0015},   {"ULINT", 0x001B},     {"BYTE", 0x0005},    {"WORD", 0x0006},
    {"DWORD", 0x0007},  {"LWORD", 0x001B},     {"CHAR", 0x0005},
};

/// The IEC name the writer writes for a code (BITSTRING for every other byte string).
[[nodiscard]] constexpr std::string_view iec_name(std::uint16_t code) noexcept {
  for (const auto &t : iec_types) {
    if (t.code == code) return t.name;
  }
  return "BITSTRING";
}

/// Data types of the POWERLINK DataTypeList (EPSG DS 301): the CiA 301 basic types under their
/// XDD names and the POWERLINK types kept as DOMAIN with their size.
struct type_name {
  std::uint16_t code;
  std::string_view name;
  std::uint32_t bytes = 0; ///< POWERLINK types: their size
};
inline constexpr type_name powerlink_types[] = {
    {0x0001, "Boolean"},      {0x0002, "Integer8"},       {0x0003, "Integer16"},
    {0x0004, "Integer32"},    {0x0005, "Unsigned8"},      {0x0006, "Unsigned16"},
    {0x0007, "Unsigned32"},   {0x0008, "Real32"},         {0x0009, "Visible_String"},
    {0x000A, "Octet_String"}, {0x000B, "Unicode_String"}, {0x000C, "Time_of_Day"},
    {0x000D, "Time_Diff"},    {0x000F, "Domain"},         {0x0010, "Integer24"},
    {0x0011, "Real64"},       {0x0012, "Integer40"},      {0x0013, "Integer48"},
    {0x0014, "Integer56"},    {0x0015, "Integer64"},      {0x0016, "Unsigned24"},
    {0x0018, "Unsigned40"},   {0x0019, "Unsigned48"},     {0x001A, "Unsigned56"},
    {0x001B, "Unsigned64"},   {0x0401, "MAC_ADDRESS", 6}, {0x0402, "IP_ADDRESS", 4},
    {0x0403, "NETTIME", 8}};

/// MAC_ADDRESS and IP_ADDRESS values are written as addresses ("00:60:65:0A:0B:FF",
/// "192.168.100.1"), held as their bytes.
inline constexpr std::uint16_t mac_address = 0x0401;
inline constexpr std::uint16_t ip_address = 0x0402;

} // namespace fieldcodec::gen::xdd
