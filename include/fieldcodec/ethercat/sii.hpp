// fieldcodec — the EtherCAT Slave Information Interface (SII): the contents of a slave's EEPROM
// (ETG.1000.6 5.4, ETG.2010). Pure constexpr codecs over the image's bytes: the fixed area of
// words 0x00..0x3F (the ESC configuration area with its CRC-8, the identity, the mailboxes) and
// the categories that follow (strings, general, FMMU, sync managers, TxPDO, RxPDO, distributed
// clocks). All values are little-endian; offsets here are in bytes (the specification counts
// 16-bit words: word w is byte 2w).
#pragma once

#include <fieldcodec/core/bytes.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/core/result.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace fieldcodec::ethercat::sii {

/// The fixed area: words 0x00..0x3F. Categories start at word 0x40.
inline constexpr std::size_t fixed_area_bytes = 128;
/// The checksum value that tells the ESC not to check the configuration area (for debugging,
/// never in a product). Source: Beckhoff EtherCAT Slave Controller datasheet, section I
/// (Technology), 11.1 "SII EEPROM Content", Table 37 "ESC Configuration Area", word 7, note.
inline constexpr std::uint16_t checksum_disabled = 0x88A4;

/// Words 0..7: what the ESC loads into its registers at power-on.
struct config_area {
  std::uint16_t pdi_control = 0;        ///< word 0 → register 0x0140
  std::uint16_t pdi_configuration = 0;  ///< word 1 → 0x0150
  std::uint16_t sync_impulse = 0;       ///< word 2: SYNC pulse length in 10 ns → 0x0982
  std::uint16_t pdi_configuration2 = 0; ///< word 3 → 0x0152
  std::uint16_t station_alias = 0;      ///< word 4 → 0x0012
  std::uint16_t reserved5 = 0;          ///< word 5, 0
  std::uint16_t reserved6 = 0;          ///< word 6, 0
  std::uint16_t checksum = 0;           ///< word 7: CRC-8 of bytes 0..13 in the low byte
  friend constexpr bool operator==(const config_area &, const config_area &) = default;
};

struct mailbox {
  std::uint16_t offset = 0; ///< ESC address of the mailbox's sync manager buffer
  std::uint16_t size = 0;   ///< bytes
  friend constexpr bool operator==(const mailbox &, const mailbox &) = default;
};

/// Mailbox protocols (word 0x1C).
namespace protocol {
inline constexpr std::uint16_t aoe = 0x0001;
inline constexpr std::uint16_t eoe = 0x0002;
inline constexpr std::uint16_t coe = 0x0004;
inline constexpr std::uint16_t foe = 0x0008;
inline constexpr std::uint16_t soe = 0x0010;
inline constexpr std::uint16_t voe = 0x0020;
} // namespace protocol

/// Words 0x00..0x3F.
struct fixed_area {
  config_area config;
  std::uint32_t vendor_id = 0;    ///< word 0x08
  std::uint32_t product_code = 0; ///< word 0x0A
  std::uint32_t revision = 0;     ///< word 0x0C
  std::uint32_t serial = 0;       ///< word 0x0E
  std::uint16_t execution_delay = 0;
  std::uint16_t port0_delay = 0;
  std::uint16_t port1_delay = 0;
  mailbox bootstrap_receive;   ///< word 0x14: master → slave in BOOT
  mailbox bootstrap_send;      ///< word 0x16
  mailbox standard_receive;    ///< word 0x18: master → slave
  mailbox standard_send;       ///< word 0x1A
  std::uint16_t protocols = 0; ///< word 0x1C: protocol::… bits
  std::uint16_t size = 0;      ///< word 0x3E: EEPROM size in kbit - 1
  std::uint16_t version = 0;   ///< word 0x3F: 1
  friend constexpr bool operator==(const fixed_area &, const fixed_area &) = default;

  /// The EEPROM's size in bytes as word 0x3E says ((size + 1) kbit).
  [[nodiscard]] constexpr std::uint32_t eeprom_bytes() const noexcept {
    return (std::uint32_t{size} + 1U) * 128U;
  }
};

/// The checksum of a configuration area: CRC-8 of bytes 0..13, in the low byte of word 7.
/// Errors: truncated (fewer than 14 bytes).
[[nodiscard]] constexpr result<std::uint16_t>
checksum_of(std::span<const std::uint8_t> image) noexcept {
  if (image.size() < 14U) return errc::truncated;
  return std::uint16_t{crc::crc8(image.first(14))};
}

/// Decodes words 0x00..0x3F. Reserved words are not checked (real images have vendor data in
/// some). Errors: truncated (fewer than 128 bytes). The checksum is not checked here: see
/// check_config_area.
[[nodiscard]] constexpr result<fixed_area>
decode_fixed_area(std::span<const std::uint8_t> image) noexcept {
  if (image.size() < fixed_area_bytes) return errc::truncated;
  const auto u16 = [&](std::size_t word) {
    return load<std::uint16_t>(image.subspan(2U * word, 2), byte_order::little).value();
  };
  const auto u32 = [&](std::size_t word) {
    return load<std::uint32_t>(image.subspan(2U * word, 4), byte_order::little).value();
  };
  fixed_area a;
  a.config = {u16(0), u16(1), u16(2), u16(3), u16(4), u16(5), u16(6), u16(7)};
  a.vendor_id = u32(0x08);
  a.product_code = u32(0x0A);
  a.revision = u32(0x0C);
  a.serial = u32(0x0E);
  a.execution_delay = u16(0x10);
  a.port0_delay = u16(0x11);
  a.port1_delay = u16(0x12);
  a.bootstrap_receive = {u16(0x14), u16(0x15)};
  a.bootstrap_send = {u16(0x16), u16(0x17)};
  a.standard_receive = {u16(0x18), u16(0x19)};
  a.standard_send = {u16(0x1A), u16(0x1B)};
  a.protocols = u16(0x1C);
  a.size = u16(0x3E);
  a.version = u16(0x3F);
  return a;
}

/// Whether word 7 holds the CRC-8 of bytes 0..13 (high byte 0), or the value that disables the
/// check. Errors: truncated (fewer than 16 bytes), bad_checksum.
[[nodiscard]] constexpr status check_config_area(std::span<const std::uint8_t> image) noexcept {
  if (image.size() < 16U) return errc::truncated;
  const auto stored = load<std::uint16_t>(image.subspan(14, 2), byte_order::little).value();
  if (stored == checksum_disabled) return {};
  return stored == crc::crc8(image.first(14)) ? status{} : status{errc::bad_checksum};
}

/// Writes words 0x00..0x3F into image[0..128) (reserved words 0); the checksum in word 7 is
/// computed (the one in `a.config` is ignored). Errors: buffer_too_small.
[[nodiscard]] constexpr status encode_fixed_area(const fixed_area &a,
                                                 std::span<std::uint8_t> image) noexcept {
  if (image.size() < fixed_area_bytes) return errc::buffer_too_small;
  for (std::size_t i = 0; i < fixed_area_bytes; ++i) image[i] = 0;
  const auto u16 = [&](std::size_t word, std::uint16_t v) {
    (void)store<std::uint16_t>(image.subspan(2U * word, 2), v, byte_order::little);
  };
  const auto u32 = [&](std::size_t word, std::uint32_t v) {
    (void)store<std::uint32_t>(image.subspan(2U * word, 4), v, byte_order::little);
  };
  u16(0, a.config.pdi_control);
  u16(1, a.config.pdi_configuration);
  u16(2, a.config.sync_impulse);
  u16(3, a.config.pdi_configuration2);
  u16(4, a.config.station_alias);
  u16(5, a.config.reserved5);
  u16(6, a.config.reserved6);
  u16(7, crc::crc8(std::span<const std::uint8_t>(image.first(14))));
  u32(0x08, a.vendor_id);
  u32(0x0A, a.product_code);
  u32(0x0C, a.revision);
  u32(0x0E, a.serial);
  u16(0x10, a.execution_delay);
  u16(0x11, a.port0_delay);
  u16(0x12, a.port1_delay);
  u16(0x14, a.bootstrap_receive.offset);
  u16(0x15, a.bootstrap_receive.size);
  u16(0x16, a.bootstrap_send.offset);
  u16(0x17, a.bootstrap_send.size);
  u16(0x18, a.standard_receive.offset);
  u16(0x19, a.standard_receive.size);
  u16(0x1A, a.standard_send.offset);
  u16(0x1B, a.standard_send.size);
  u16(0x1C, a.protocols);
  u16(0x3E, a.size);
  u16(0x3F, a.version);
  return {};
}

// ---- categories ---------------------------------------------------------------------------------

/// Category types (ETG.1000.6 Table 19, ETG.2010).
namespace category_type {
inline constexpr std::uint16_t nop = 0;
inline constexpr std::uint16_t strings = 10;
inline constexpr std::uint16_t data_types = 20;
inline constexpr std::uint16_t general = 30;
inline constexpr std::uint16_t fmmu = 40;
inline constexpr std::uint16_t sync_manager = 41;
inline constexpr std::uint16_t fmmu_extended = 42;
inline constexpr std::uint16_t sync_unit = 43;
inline constexpr std::uint16_t txpdo = 50;
inline constexpr std::uint16_t rxpdo = 51;
inline constexpr std::uint16_t dc = 60;
inline constexpr std::uint16_t end = 0xFFFF;
} // namespace category_type

/// A category: its header word (bit 15: vendor specific) and its data.
struct category {
  std::uint16_t type = 0; ///< without the vendor-specific bit
  bool vendor_specific = false;
  std::size_t offset = 0; ///< byte offset of the header in the image
  std::span<const std::uint8_t> data;
};

/// The categories after the fixed area, one by one: next() gives each, then nothing at the end
/// category (0xFFFF) or at the end of the image. Errors: truncated (a header or a category's
/// data runs past the image; reading stops).
class category_reader {
public:
  constexpr explicit category_reader(std::span<const std::uint8_t> image) noexcept
      : image_(image), at_(fixed_area_bytes) {}

  [[nodiscard]] constexpr result<std::optional<category>> next() noexcept {
    if (done_ || at_ >= image_.size()) return std::optional<category>{};
    if (at_ + 2U > image_.size()) {
      done_ = true;
      return errc::truncated;
    }
    const auto header = load<std::uint16_t>(image_.subspan(at_, 2), byte_order::little).value();
    if (header == category_type::end) {
      done_ = true;
      end_found_ = true;
      return std::optional<category>{};
    }
    if (at_ + 4U > image_.size()) {
      done_ = true;
      return errc::truncated;
    }
    const std::size_t words =
        load<std::uint16_t>(image_.subspan(at_ + 2U, 2), byte_order::little).value();
    if (at_ + 4U + 2U * words > image_.size()) {
      done_ = true;
      return errc::truncated;
    }
    category c;
    c.type = static_cast<std::uint16_t>(header & 0x7FFFU);
    c.vendor_specific = (header & 0x8000U) != 0U;
    c.offset = at_;
    c.data = image_.subspan(at_ + 4U, 2U * words);
    at_ += 4U + 2U * words;
    return std::optional<category>{c};
  }
  /// Whether the end category (0xFFFF) was met.
  [[nodiscard]] constexpr bool end_found() const noexcept { return end_found_; }
  /// Byte offset of the next category: after the last one read, the end marker's once found.
  [[nodiscard]] constexpr std::size_t offset() const noexcept { return at_; }

private:
  std::span<const std::uint8_t> image_;
  std::size_t at_;
  bool done_ = false;
  bool end_found_ = false;
};

/// Strings category: a count byte, then each string as a length byte and its characters. String
/// indices count from 1; 0 means "no string". Errors: out_of_range (index 0 or beyond the
/// count), truncated.
[[nodiscard]] constexpr result<std::uint8_t>
string_count(std::span<const std::uint8_t> data) noexcept {
  if (data.empty()) return errc::truncated;
  return data[0];
}
[[nodiscard]] constexpr result<std::string_view> string_at(std::span<const std::uint8_t> data,
                                                           std::uint8_t index) noexcept {
  if (data.empty()) return errc::truncated;
  if (index == 0U || index > data[0]) return errc::out_of_range;
  std::size_t at = 1;
  for (unsigned i = 1;; ++i) {
    if (at >= data.size()) return errc::truncated;
    const std::size_t len = data[at];
    if (at + 1U + len > data.size()) return errc::truncated;
    if (i == index) {
      return std::string_view(reinterpret_cast<const char *>(data.data() + at + 1U), len);
    }
    at += 1U + len;
  }
}

/// CoE details of the general category.
namespace coe_details {
inline constexpr std::uint8_t sdo = 0x01;
inline constexpr std::uint8_t sdo_info = 0x02;
inline constexpr std::uint8_t pdo_assign = 0x04;
inline constexpr std::uint8_t pdo_config = 0x08;
inline constexpr std::uint8_t upload_at_startup = 0x10;
inline constexpr std::uint8_t complete_access = 0x20;
} // namespace coe_details

/// Flags of the general category.
namespace general_flags {
inline constexpr std::uint8_t enable_safe_op = 0x01;
inline constexpr std::uint8_t enable_not_lrw = 0x02;
inline constexpr std::uint8_t mailbox_data_link_layer = 0x04;
inline constexpr std::uint8_t ident_al_status = 0x08;
inline constexpr std::uint8_t ident_physical_memory = 0x10;
} // namespace general_flags

/// General category (32 bytes; ETG.2010).
struct general {
  std::uint8_t group_index = 0; ///< strings
  std::uint8_t image_index = 0;
  std::uint8_t order_index = 0;
  std::uint8_t name_index = 0;
  std::uint8_t coe = 0; ///< coe_details bits
  std::uint8_t foe = 0; ///< bit 0: FoE
  std::uint8_t eoe = 0; ///< bit 0: EoE
  std::uint8_t soe_channels = 0;
  std::uint8_t ds402_channels = 0;
  std::uint8_t sysman_class = 0;
  std::uint8_t flags = 0;              ///< general_flags bits
  std::int16_t ebus_current = 0;       ///< mA; negative: the device feeds the E-Bus
  std::uint8_t group_index_compat = 0; ///< byte 14: the group index again, for old masters
  std::uint16_t physical_ports = 0; ///< 4 bits a port: 0 unused, 1 MII, 3 EBUS, 4 fast hot connect
  std::uint16_t physical_memory_address = 0;
  friend constexpr bool operator==(const general &, const general &) = default;
};
inline constexpr std::size_t general_bytes = 32;

/// Errors: bad_length (fewer than 16 bytes; a shorter category than 32 bytes leaves the ports
/// and the memory address 0).
[[nodiscard]] constexpr result<general> decode_general(std::span<const std::uint8_t> d) noexcept {
  if (d.size() < 16U) return errc::bad_length;
  general g;
  g.group_index = d[0];
  g.image_index = d[1];
  g.order_index = d[2];
  g.name_index = d[3];
  g.coe = d[5];
  g.foe = d[6];
  g.eoe = d[7];
  g.soe_channels = d[8];
  g.ds402_channels = d[9];
  g.sysman_class = d[10];
  g.flags = d[11];
  g.ebus_current = load<std::int16_t>(d.subspan(12, 2), byte_order::little).value();
  g.group_index_compat = d[14];
  if (d.size() >= 18U)
    g.physical_ports = load<std::uint16_t>(d.subspan(16, 2), byte_order::little).value();
  if (d.size() >= 20U) {
    g.physical_memory_address = load<std::uint16_t>(d.subspan(18, 2), byte_order::little).value();
  }
  return g;
}
/// Errors: buffer_too_small (fewer than 32 bytes).
[[nodiscard]] constexpr status encode_general(const general &g,
                                              std::span<std::uint8_t> d) noexcept {
  if (d.size() < general_bytes) return errc::buffer_too_small;
  for (std::size_t i = 0; i < general_bytes; ++i) d[i] = 0;
  d[0] = g.group_index;
  d[1] = g.image_index;
  d[2] = g.order_index;
  d[3] = g.name_index;
  d[5] = g.coe;
  d[6] = g.foe;
  d[7] = g.eoe;
  d[8] = g.soe_channels;
  d[9] = g.ds402_channels;
  d[10] = g.sysman_class;
  d[11] = g.flags;
  (void)store<std::int16_t>(d.subspan(12, 2), g.ebus_current, byte_order::little);
  d[14] = g.group_index_compat;
  (void)store<std::uint16_t>(d.subspan(16, 2), g.physical_ports, byte_order::little);
  (void)store<std::uint16_t>(d.subspan(18, 2), g.physical_memory_address, byte_order::little);
  return {};
}

/// FMMU category: one byte a FMMU.
namespace fmmu_usage {
inline constexpr std::uint8_t unused = 0x00;
inline constexpr std::uint8_t outputs = 0x01;
inline constexpr std::uint8_t inputs = 0x02;
inline constexpr std::uint8_t mailbox_state = 0x03; ///< sync manager status
inline constexpr std::uint8_t unused_ff = 0xFF;
} // namespace fmmu_usage

/// Sync manager category: 8 bytes a sync manager.
namespace sync_manager_type {
inline constexpr std::uint8_t unused = 0;
inline constexpr std::uint8_t mailbox_out = 1; ///< master → slave
inline constexpr std::uint8_t mailbox_in = 2;
inline constexpr std::uint8_t outputs = 3;
inline constexpr std::uint8_t inputs = 4;
} // namespace sync_manager_type
struct sync_manager {
  std::uint16_t start = 0;
  std::uint16_t length = 0;
  std::uint8_t control = 0;
  std::uint8_t status = 0; ///< not used (0)
  std::uint8_t enable = 0; ///< bit 0 enable, 1 fixed content, 2 virtual, 3 enable in OP only
  std::uint8_t type = 0;   ///< sync_manager_type
  friend constexpr bool operator==(const sync_manager &, const sync_manager &) = default;
};
inline constexpr std::size_t sync_manager_bytes = 8;
/// The i-th sync manager of the category. Errors: out_of_range (no i-th).
[[nodiscard]] constexpr result<sync_manager> decode_sync_manager(std::span<const std::uint8_t> d,
                                                                 std::size_t i) noexcept {
  if (d.size() / sync_manager_bytes <= i) return errc::out_of_range;
  const auto s = d.subspan(i * sync_manager_bytes, sync_manager_bytes);
  return sync_manager{load<std::uint16_t>(s.first(2), byte_order::little).value(),
                      load<std::uint16_t>(s.subspan(2, 2), byte_order::little).value(),
                      s[4],
                      s[5],
                      s[6],
                      s[7]};
}
[[nodiscard]] constexpr status encode_sync_manager(const sync_manager &m,
                                                   std::span<std::uint8_t> d) noexcept {
  if (d.size() < sync_manager_bytes) return errc::buffer_too_small;
  (void)store<std::uint16_t>(d.first(2), m.start, byte_order::little);
  (void)store<std::uint16_t>(d.subspan(2, 2), m.length, byte_order::little);
  d[4] = m.control;
  d[5] = m.status;
  d[6] = m.enable;
  d[7] = m.type;
  return {};
}

/// TxPDO / RxPDO categories: per PDO an 8-byte header, then 8 bytes per entry.
namespace pdo_flags {
inline constexpr std::uint16_t mandatory = 0x0001;
inline constexpr std::uint16_t default_ = 0x0002; ///< assigned by default
inline constexpr std::uint16_t oversample = 0x0004;
inline constexpr std::uint16_t fixed_content = 0x0010;
inline constexpr std::uint16_t virtual_content = 0x0020;
} // namespace pdo_flags
struct pdo_header {
  std::uint16_t index = 0;
  std::uint8_t entries = 0;
  std::uint8_t sync_manager = 0; ///< 0xFF: none
  std::uint8_t dc_sync = 0;
  std::uint8_t name_index = 0;
  std::uint16_t flags = 0; ///< pdo_flags
  friend constexpr bool operator==(const pdo_header &, const pdo_header &) = default;
};
struct pdo_entry {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::uint8_t name_index = 0;
  std::uint8_t data_type = 0; ///< ETG.1000.6 code (0x07 UDINT, 0x30 BIT1, ...)
  std::uint8_t bits = 0;
  std::uint16_t flags = 0;
  friend constexpr bool operator==(const pdo_entry &, const pdo_entry &) = default;
};
inline constexpr std::size_t pdo_header_bytes = 8;
inline constexpr std::size_t pdo_entry_bytes = 8;

/// The PDO whose header is at byte `offset` of a PDO category, and the offset of the next one.
/// Errors: truncated (the header or its entries run past the category).
struct pdo_at {
  pdo_header header;
  std::size_t entries_offset = 0;
  std::size_t next = 0;
};
[[nodiscard]] constexpr result<pdo_at> decode_pdo(std::span<const std::uint8_t> d,
                                                  std::size_t offset) noexcept {
  if (offset > d.size() || d.size() - offset < pdo_header_bytes) return errc::truncated;
  const auto h = d.subspan(offset, pdo_header_bytes);
  pdo_at p;
  p.header = {
      load<std::uint16_t>(h.first(2), byte_order::little).value(),     h[2], h[3], h[4], h[5],
      load<std::uint16_t>(h.subspan(6, 2), byte_order::little).value()};
  p.entries_offset = offset + pdo_header_bytes;
  const std::size_t end = p.entries_offset + std::size_t{p.header.entries} * pdo_entry_bytes;
  if (end > d.size()) return errc::truncated;
  p.next = end;
  return p;
}
/// Entry `i` of the PDO `p` of category `d`. Errors: out_of_range.
[[nodiscard]] constexpr result<pdo_entry>
decode_pdo_entry(std::span<const std::uint8_t> d, const pdo_at &p, std::size_t i) noexcept {
  if (i >= p.header.entries) return errc::out_of_range;
  const auto e = d.subspan(p.entries_offset + i * pdo_entry_bytes, pdo_entry_bytes);
  return pdo_entry{
      load<std::uint16_t>(e.first(2), byte_order::little).value(),     e[2], e[3], e[4], e[5],
      load<std::uint16_t>(e.subspan(6, 2), byte_order::little).value()};
}
[[nodiscard]] constexpr status encode_pdo_header(const pdo_header &h,
                                                 std::span<std::uint8_t> d) noexcept {
  if (d.size() < pdo_header_bytes) return errc::buffer_too_small;
  (void)store<std::uint16_t>(d.first(2), h.index, byte_order::little);
  d[2] = h.entries;
  d[3] = h.sync_manager;
  d[4] = h.dc_sync;
  d[5] = h.name_index;
  (void)store<std::uint16_t>(d.subspan(6, 2), h.flags, byte_order::little);
  return {};
}
[[nodiscard]] constexpr status encode_pdo_entry(const pdo_entry &e,
                                                std::span<std::uint8_t> d) noexcept {
  if (d.size() < pdo_entry_bytes) return errc::buffer_too_small;
  (void)store<std::uint16_t>(d.first(2), e.index, byte_order::little);
  d[2] = e.sub;
  d[3] = e.name_index;
  d[4] = e.data_type;
  d[5] = e.bits;
  (void)store<std::uint16_t>(d.subspan(6, 2), e.flags, byte_order::little);
  return {};
}

/// Distributed clocks category: 24 bytes an operation mode.
struct dc_mode {
  std::uint32_t cycle_time_sync0 = 0; ///< ns
  std::uint32_t shift_time_sync0 = 0; ///< ns
  std::uint32_t shift_time_sync1 = 0; ///< ns
  std::int16_t sync1_cycle_factor = 0;
  std::uint16_t assign_activate = 0;
  std::int16_t sync0_cycle_factor = 0;
  std::uint8_t name_index = 0;
  std::uint8_t description_index = 0;
  friend constexpr bool operator==(const dc_mode &, const dc_mode &) = default;
};
inline constexpr std::size_t dc_mode_bytes = 24;
/// The i-th mode of the category. Errors: out_of_range.
[[nodiscard]] constexpr result<dc_mode> decode_dc_mode(std::span<const std::uint8_t> d,
                                                       std::size_t i) noexcept {
  if (d.size() / dc_mode_bytes <= i) return errc::out_of_range;
  const auto m = d.subspan(i * dc_mode_bytes, dc_mode_bytes);
  return dc_mode{load<std::uint32_t>(m.first(4), byte_order::little).value(),
                 load<std::uint32_t>(m.subspan(4, 4), byte_order::little).value(),
                 load<std::uint32_t>(m.subspan(8, 4), byte_order::little).value(),
                 load<std::int16_t>(m.subspan(12, 2), byte_order::little).value(),
                 load<std::uint16_t>(m.subspan(14, 2), byte_order::little).value(),
                 load<std::int16_t>(m.subspan(16, 2), byte_order::little).value(),
                 m[18],
                 m[19]};
}
[[nodiscard]] constexpr status encode_dc_mode(const dc_mode &m,
                                              std::span<std::uint8_t> d) noexcept {
  if (d.size() < dc_mode_bytes) return errc::buffer_too_small;
  for (std::size_t i = 0; i < dc_mode_bytes; ++i) d[i] = 0;
  (void)store<std::uint32_t>(d.first(4), m.cycle_time_sync0, byte_order::little);
  (void)store<std::uint32_t>(d.subspan(4, 4), m.shift_time_sync0, byte_order::little);
  (void)store<std::uint32_t>(d.subspan(8, 4), m.shift_time_sync1, byte_order::little);
  (void)store<std::int16_t>(d.subspan(12, 2), m.sync1_cycle_factor, byte_order::little);
  (void)store<std::uint16_t>(d.subspan(14, 2), m.assign_activate, byte_order::little);
  (void)store<std::int16_t>(d.subspan(16, 2), m.sync0_cycle_factor, byte_order::little);
  d[18] = m.name_index;
  d[19] = m.description_index;
  return {};
}

} // namespace fieldcodec::ethercat::sii
