// fieldcodec-gen — readers (EDS/DCF, CSV) and writers (EDS, C++ header).
#pragma once

#include "diag.hpp"
#include "model.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fieldcodec::gen {

/// Read a CiA 306 EDS or DCF from `text` (the file's bytes); `file` names it in diagnostics.
/// Returns nothing when an error was reported.
[[nodiscard]] std::optional<dictionary> read_eds(std::string_view text, const std::string &file,
                                                 diagnostics &diag);

/// Read an XDD, XDC or XPD (ISO 15745 profile container: CiA 311 CANopen or EPSG DS 311
/// POWERLINK; docs/generator.md "XDD and XDC").
[[nodiscard]] std::optional<dictionary> read_xdd(std::string_view text, const std::string &file,
                                                 diagnostics &diag);

/// Read an ESI (EtherCAT Slave Information, ETG.2000): the object dictionary of one device and
/// its PDOs, sync managers and mailbox (dictionary::ethercat). `device` chooses the device of a
/// file that describes several: its Type text or Name, "<product code>" or
/// "<product code>:<revision>" (decimal, 0x… or #x…); empty: the only one (a file with several
/// is an error that lists them). An XDD given as .xml is read as an XDD.
[[nodiscard]] std::optional<dictionary> read_esi(std::string_view text, const std::string &file,
                                                 diagnostics &diag, const std::string &device = {});

/// Read a CSV object or command table (docs/dictionary-formats.md).
[[nodiscard]] std::optional<dictionary> read_csv(std::string_view text, const std::string &file,
                                                 diagnostics &diag);

/// Warns about a PDO communication parameter (1400h..15FFh, 1800h..19FFh) without its mapping
/// parameter (1600h..17FFh, 1A00h..1BFFh), and the reverse. Both readers call it.
void check_pdo_pairs(const dictionary &d, const std::string &file, diagnostics &diag);

/// Adds CiA 301's mandatory objects 1000h (device type), 1001h (error register) and 1018h
/// (identity, vendor-ID) with neutral values where the dictionary lacks them — CSV tables have
/// no communication objects, and CANopen tools refuse an EDS without them.
void add_mandatory_objects(dictionary &d);

/// A number of entry `e` as the writers write it (and the readers read it back unchanged):
/// signed values in decimal, values of unsigned types as `0x…` hex, reals in their shortest
/// round-trip form, decimals as written, node-ID relative values as `$NODEID+…`.
[[nodiscard]] std::string entry_number(const entry &e, const od::number &n, bool nodeid);

/// A limit of entry `e` as the writers write it: entry_number(), except that the limits of a
/// scaled CSV row (engineering units) are written as raw values, cut to the field's range.
[[nodiscard]] std::string limit_number(const entry &e, const od::number &n, bool nodeid);

/// Write a dictionary (object table) as a CiA 306 EDS (or DCF when it has DCF values).
[[nodiscard]] std::string write_eds(const dictionary &d);

/// Write a dictionary as an XDD (an XDC when it has DCF values) for `profile`: CiA 311 CANopen
/// or EPSG DS 311 POWERLINK. What the XDD cannot hold (CiA 306 keys without an XDD attribute,
/// object links, CSV columns, ...) is reported to `diag` as warnings naming it; `file` names the
/// source in them.
[[nodiscard]] std::string write_xdd(const dictionary &d, bus_profile profile,
                                    const std::string &file, diagnostics &diag);

/// Write a dictionary as an ESI (ETG.2000 EtherCATInfo) describing one device: its dictionary
/// (DataTypes, Objects), its PDOs (those of the ESI read, else from the mapping objects and the
/// sync manager assignments 1C10h+n) and, when the dictionary was read from an ESI, its sync
/// managers, FMMUs, mailbox and EEPROM data. What an ESI cannot hold is reported to `diag`.
[[nodiscard]] std::string write_esi(const dictionary &d, const std::string &file,
                                    diagnostics &diag);

/// The PDO layouts header (--pdo-header): namespace fieldcodec::dictionaries::<stem>::pdos with
/// one `canopen::pdo::static_mapping` per PDO (an ESI's RxPdo/TxPdo descriptions, else the
/// default values of the mapping objects 1600h-17FFh and 1A00h-1BFFh with 32-bit entries), made
/// by make_static_mapping with the dictionary (checked by the compiler) where the library's
/// checks pass for it, else for lengths only, with a warning to `diag` naming the entry and the
/// problem. The header includes <fieldcodec/dictionaries/<stem>.hpp>.
[[nodiscard]] std::string emit_pdo_layouts(const dictionary &d, const std::string &file,
                                           diagnostics &diag);

/// The SII EEPROM image (ETG.2010) of the ESI device of `d` (dictionary::ethercat; an error for
/// a dictionary not read from an ESI): configuration area from Eeprom/ConfigData with its CRC-8,
/// identity, mailboxes (Sm MBoxOut/MBoxIn, Eeprom/BootStrap), protocols, and the categories
/// STRINGS, GENERAL, FMMU, SYNCM, TXPDO, RXPDO, padded with 0xFF to Eeprom/ByteSize. Nothing
/// after an error.
[[nodiscard]] std::optional<std::vector<std::uint8_t>>
write_sii(const dictionary &d, const std::string &file, diagnostics &diag);

/// A readable report of an SII image: every field of words 0x00..0x3F, the checksum checked,
/// every category decoded (strings resolved). Problems go to `diag`: a wrong checksum, a
/// category that runs past the image or an image shorter than 128 bytes are errors; a missing
/// end category, unknown categories and string indices that name no string warnings.
[[nodiscard]] std::string sii_report(std::span<const std::uint8_t> image, const std::string &file,
                                     diagnostics &diag);

/// Emit the C++ header.
[[nodiscard]] std::string emit_header(const dictionary &d);
/// Receives the header in pieces (consecutive, each non-empty).
using header_sink = std::function<void(std::string_view piece)>;
/// Emit the C++ header in pieces of up to 64 kB (a text longer than that makes its piece
/// longer): together the bytes emit_header(d) returns, without holding them whole
/// (fieldcodec-gen compares them with the existing output file).
void emit_header(const dictionary &d, const header_sink &sink);

/// The namespace name for a file stem ("XENAX-CANopen" → "xenax_canopen").
[[nodiscard]] std::string stem_identifier(std::string_view stem);

/// The whole file at `path` into `out`, read in blocks into one buffer. Returns nullptr on
/// success, else what failed: "cannot open file" or "cannot read file" (a directory, an I/O
/// error).
[[nodiscard]] const char *read_bytes(const std::string &path, std::string &out);

/// The bytes of a file: a regular file is mapped into memory where the system has mmap (no copy;
/// the kernel maps the pages it has cached), anything else is read with read_bytes().
class file_bytes {
public:
  file_bytes() = default;
  file_bytes(const file_bytes &) = delete;
  file_bytes &operator=(const file_bytes &) = delete;
  ~file_bytes();
  /// Returns nullptr on success, else what failed (as read_bytes()).
  [[nodiscard]] const char *load(const std::string &path);
  [[nodiscard]] std::string_view view() const noexcept { return view_; }

private:
  std::string buffer_;
  void *map_ = nullptr;
  std::size_t map_size_ = 0;
  std::string_view view_;
};

/// What read_file passes on to a reader.
struct read_options {
  std::string device; ///< the ESI device to read (read_esi)
};

/// Read `path` (EDS/DCF by extension .eds/.dcf, CSV by .csv, XDD/XDC by .xdd/.xdc/.xpd, ESI by
/// .xml). Reports unreadable files.
[[nodiscard]] std::optional<dictionary> read_file(const std::string &path, diagnostics &diag,
                                                  const read_options &options = {});

} // namespace fieldcodec::gen
