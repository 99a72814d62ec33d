// fieldcodec-gen — the SII EEPROM image of an ESI device (--sii) and the report of an image
// (INPUT .bin), on the codecs of <fieldcodec/ethercat/sii.hpp> (docs/generator.md, "SII").
#include "esi_tables.hpp"
#include "readers.hpp"
#include "text.hpp"

#include <fieldcodec/ethercat/sii.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fieldcodec::gen {

namespace {

namespace sii = ethercat::sii;

// Hex digit pairs (Eeprom/ConfigData, BootStrap) as bytes: the dictionaries' reader of them.
bool hex_bytes(std::string_view t, std::vector<std::uint8_t> &out) {
  const auto bytes = byte_string_value(od::data_type::octet_string, t);
  if (!bytes) return false;
  out.assign(bytes->begin(), bytes->end());
  return true;
}

std::uint16_t le16(const std::vector<std::uint8_t> &b, std::size_t at) {
  return load<std::uint16_t>(std::span<const std::uint8_t>(b).subspan(at, 2), byte_order::little)
      .value();
}

class sii_writer {
public:
  // level: what is left out to fit Eeprom/ByteSize (0 nothing; 1 the PDOs not assigned by
  // default; 2 also the names of PDO entries; 3 the PDO categories).
  sii_writer(const dictionary &d, const std::string &file, diagnostics &diag, int level)
      : d_(d), file_(file), diag_(diag), level_(level) {}

  /// Whether the image did not fit Eeprom/ByteSize (an error reported).
  [[nodiscard]] bool too_big() const noexcept { return too_big_; }
  /// The image's size before padding (also when too big).
  [[nodiscard]] std::size_t image_bytes() const noexcept { return image_bytes_; }
  /// How many PDOs were written, and left out at level 1 and above.
  [[nodiscard]] std::size_t pdos_written() const noexcept { return pdos_written_; }
  [[nodiscard]] std::size_t pdos_left_out() const noexcept { return pdos_left_out_; }

  std::optional<std::vector<std::uint8_t>> write() {
    if (!d_.ethercat) {
      diag_.error(file_, 0, 0,
                  "an SII image is written from an ESI device (.xml input); this dictionary has no "
                  "EtherCAT device description");
      return std::nullopt;
    }
    const esi_device &dev = *d_.ethercat;
    std::vector<std::uint8_t> image(sii::fixed_area_bytes, 0);
    sii::fixed_area a;
    config(dev, a);
    a.vendor_id = dev.vendor_id;
    a.product_code = dev.product_code;
    a.revision = dev.revision;
    mailboxes(dev, a);
    a.version = 1;
    // categories
    const std::uint8_t group = string(dev.group);
    const std::uint8_t order = string(dev.type);
    const std::uint8_t name = string(dev.name);
    std::vector<std::uint8_t> general(sii::general_bytes, 0);
    general_category(dev, group, order, name, general);
    std::vector<std::uint8_t> fmmu = fmmus(dev);
    std::vector<std::uint8_t> sms = sync_managers(dev);
    std::vector<std::uint8_t> tx;
    std::vector<std::uint8_t> rx;
    if (level_ < 3) {
      tx = pdos(dev, true);
      rx = pdos(dev, false);
    }
    append(image, sii::category_type::strings, strings_category());
    append(image, sii::category_type::general, general);
    if (!fmmu.empty()) append(image, sii::category_type::fmmu, fmmu);
    if (!sms.empty()) append(image, sii::category_type::sync_manager, sms);
    if (!tx.empty()) append(image, sii::category_type::txpdo, tx);
    if (!rx.empty()) append(image, sii::category_type::rxpdo, rx);
    image.push_back(0xFF);
    image.push_back(0xFF);
    image_bytes_ = image.size();
    // the EEPROM's size: Eeprom/ByteSize, else the smallest power of two of 1 kbit or more
    std::uint32_t bytes = dev.eeprom_bytes;
    if (bytes == 0U) {
      bytes = 128;
      while (bytes < image.size()) bytes *= 2U;
      diag_.warning(file_, dev_line(), 0,
                    "the ESI has no Eeprom/ByteSize: word 0x3E says " + std::to_string(bytes) +
                        " bytes, the smallest EEPROM that holds the " +
                        std::to_string(image.size()) + "-byte image");
    } else if (bytes % 128U != 0U || bytes > 128U * 65536U) {
      diag_.error(file_, eeprom_line(), 0,
                  "Eeprom/ByteSize " + std::to_string(bytes) +
                      " is no whole number of kbit (128 bytes): word 0x3E cannot say it");
      return std::nullopt;
    } else if (image.size() > bytes) {
      too_big_ = true;
      diag_.error(file_, eeprom_line(), 0,
                  "the SII image of " + std::to_string(image.size()) +
                      " bytes does not fit the EEPROM of " + std::to_string(bytes) +
                      " bytes (Eeprom/ByteSize)");
      return std::nullopt;
    }
    a.size = static_cast<std::uint16_t>(bytes / 128U - 1U);
    (void)sii::encode_fixed_area(a, std::span<std::uint8_t>(image).first(sii::fixed_area_bytes));
    image.resize(bytes, 0xFF); // the rest of the EEPROM erased, as a programmer leaves it
    if (!bootstrap_ok_ || !config_ok_) return std::nullopt;
    return image;
  }

private:
  int dev_line() const { return d_.ethercat->line; }
  int eeprom_line() const {
    return d_.ethercat->eeprom_line != 0 ? d_.ethercat->eeprom_line : d_.ethercat->line;
  }

  void config(const esi_device &dev, sii::fixed_area &a) {
    std::vector<std::uint8_t> c;
    if (dev.config_data.empty()) {
      diag_.warning(file_, eeprom_line(), 0,
                    "the ESI has no Eeprom/ConfigData: the configuration area (PDI, SYNC) is "
                    "written as zeros");
    } else if (!hex_bytes(dev.config_data, c) || c.size() > 14U) {
      diag_.error(file_, eeprom_line(), 0,
                  "Eeprom/ConfigData \"" + dev.config_data +
                      "\" is not up to 14 bytes of hex digit pairs (words 0..6)");
      config_ok_ = false;
      c.clear();
    }
    c.resize(14, 0);
    a.config = {le16(c, 0), le16(c, 2),  le16(c, 4),  le16(c, 6),
                le16(c, 8), le16(c, 10), le16(c, 12), 0};
  }

  void mailboxes(const esi_device &dev, sii::fixed_area &a) {
    const esi_sync_manager *out = nullptr;
    const esi_sync_manager *in = nullptr;
    for (const auto &sm : dev.sync_managers) {
      if (sm.type == "MBoxOut" && out == nullptr) out = &sm;
      if (sm.type == "MBoxIn" && in == nullptr) in = &sm;
    }
    if (out != nullptr) a.standard_receive = {out->start, out->default_size};
    if (in != nullptr) a.standard_send = {in->start, in->default_size};
    if (dev.mailbox && (out == nullptr || in == nullptr)) {
      diag_.warning(file_, dev_line(), 0,
                    "the ESI has a mailbox but no MBoxOut/MBoxIn sync manager: the "
                    "standard mailbox (words 0x18..0x1B) is written as zeros");
    }
    a.bootstrap_receive = a.standard_receive;
    a.bootstrap_send = a.standard_send;
    if (!dev.bootstrap.empty()) {
      std::vector<std::uint8_t> b;
      if (!hex_bytes(dev.bootstrap, b) || b.size() != 8U) {
        diag_.error(file_, eeprom_line(), 0,
                    "Eeprom/BootStrap \"" + dev.bootstrap +
                        "\" is not 8 bytes of hex digit pairs (offset and size of the two "
                        "bootstrap mailboxes)");
        bootstrap_ok_ = false;
      } else {
        a.bootstrap_receive = {le16(b, 0), le16(b, 2)};
        a.bootstrap_send = {le16(b, 4), le16(b, 6)};
      }
    }
    for (const auto &p : dev.protocols) {
      if (p == "AoE") a.protocols |= sii::protocol::aoe;
      if (p == "EoE") a.protocols |= sii::protocol::eoe;
      if (p == "CoE") a.protocols |= sii::protocol::coe;
      if (p == "FoE") a.protocols |= sii::protocol::foe;
      if (p == "SoE") a.protocols |= sii::protocol::soe;
      if (p == "VoE") a.protocols |= sii::protocol::voe;
    }
  }

  // The strings category: each text once, in the order first used; index 0 for none.
  std::uint8_t string(const std::string &s) {
    if (s.empty()) return 0;
    for (std::size_t i = 0; i < strings_.size(); ++i) {
      if (strings_[i] == s) return static_cast<std::uint8_t>(i + 1U);
    }
    if (s.size() > 255U) {
      diag_.warning(file_, dev_line(), 0,
                    "text \"" + s.substr(0, 40) +
                        "…\" is longer than 255 bytes, the most an SII "
                        "string holds: not written (index 0)");
      return 0;
    }
    if (strings_.size() == 255U) {
      if (!strings_full_) {
        diag_.warning(file_, dev_line(), 0,
                      "more than 255 different texts: the SII strings category "
                      "holds 255; later names are not written (index 0)");
      }
      strings_full_ = true;
      return 0;
    }
    strings_.push_back(s);
    return static_cast<std::uint8_t>(strings_.size());
  }
  std::vector<std::uint8_t> strings_category() const {
    std::vector<std::uint8_t> out{static_cast<std::uint8_t>(strings_.size())};
    for (const auto &s : strings_) {
      out.push_back(static_cast<std::uint8_t>(s.size()));
      out.insert(out.end(), s.begin(), s.end());
    }
    return out;
  }

  static bool flag(const key_list &coe, std::string_view k) {
    for (const auto &[name, v] : coe) {
      if (name == k) return v == "true" || v == "1";
    }
    return false;
  }

  void general_category(const esi_device &dev, std::uint8_t group, std::uint8_t order,
                        std::uint8_t name, std::vector<std::uint8_t> &out) {
    sii::general g;
    g.group_index = group;
    g.order_index = order;
    g.name_index = name;
    g.group_index_compat = group;
    const bool coe =
        std::find(dev.protocols.begin(), dev.protocols.end(), "CoE") != dev.protocols.end();
    if (coe) {
      g.coe = sii::coe_details::sdo;
      if (flag(dev.coe, "SdoInfo")) g.coe |= sii::coe_details::sdo_info;
      if (flag(dev.coe, "PdoAssign")) g.coe |= sii::coe_details::pdo_assign;
      if (flag(dev.coe, "PdoConfig")) g.coe |= sii::coe_details::pdo_config;
      if (flag(dev.coe, "PdoUpload")) g.coe |= sii::coe_details::upload_at_startup;
      if (flag(dev.coe, "CompleteAccess")) g.coe |= sii::coe_details::complete_access;
    }
    if (std::find(dev.protocols.begin(), dev.protocols.end(), "FoE") != dev.protocols.end())
      g.foe = 1;
    if (std::find(dev.protocols.begin(), dev.protocols.end(), "EoE") != dev.protocols.end())
      g.eoe = 1;
    if (dev.data_link_layer) g.flags |= sii::general_flags::mailbox_data_link_layer;
    // Physics: a letter a port (Y: MII, K: EBUS, H: fast hot connect)
    for (std::size_t i = 0; i < dev.physics.size() && i < 4U; ++i) {
      unsigned v = 0;
      switch (dev.physics[i]) {
      case 'Y': v = 1; break;
      case 'K': v = 3; break;
      case 'H': v = 4; break;
      case ' ': v = 0; break;
      default:
        diag_.warning(file_, dev_line(), 0,
                      std::string("Physics letter '") + dev.physics[i] + "' of port " +
                          std::to_string(i) + " unknown: written as unused");
      }
      g.physical_ports = static_cast<std::uint16_t>(g.physical_ports | (v << (4U * i)));
    }
    (void)sii::encode_general(g, out);
  }

  std::vector<std::uint8_t> fmmus(const esi_device &dev) {
    std::vector<std::uint8_t> out;
    for (const auto &f : dev.fmmu) {
      if (f == "Outputs") {
        out.push_back(sii::fmmu_usage::outputs);
      } else if (f == "Inputs") {
        out.push_back(sii::fmmu_usage::inputs);
      } else if (f == "MBoxState") {
        out.push_back(sii::fmmu_usage::mailbox_state);
      } else {
        if (!f.empty()) {
          diag_.warning(file_, dev_line(), 0,
                        "FMMU use \"" + f + "\" unknown: written as unused (0)");
        }
        out.push_back(sii::fmmu_usage::unused);
      }
    }
    return out;
  }

  std::vector<std::uint8_t> sync_managers(const esi_device &dev) {
    std::vector<std::uint8_t> out;
    for (const auto &s : dev.sync_managers) {
      sii::sync_manager m;
      m.start = s.start;
      m.length = s.default_size;
      m.control = s.control;
      m.enable = s.enable ? 1U : 0U;
      if (s.type == "MBoxOut") {
        m.type = sii::sync_manager_type::mailbox_out;
      } else if (s.type == "MBoxIn") {
        m.type = sii::sync_manager_type::mailbox_in;
      } else if (s.type == "Outputs") {
        m.type = sii::sync_manager_type::outputs;
      } else if (s.type == "Inputs") {
        m.type = sii::sync_manager_type::inputs;
      } else {
        diag_.warning(file_, s.line, 0,
                      "sync manager type \"" + s.type + "\" unknown: written as unused");
      }
      const std::size_t at = out.size();
      out.resize(at + sii::sync_manager_bytes);
      (void)sii::encode_sync_manager(m, std::span<std::uint8_t>(out).subspan(at));
    }
    return out;
  }

  // The ETG.1000.6 code of a PDO entry's data type (0 for a gap or an unknown name, warned).
  std::uint8_t etg_code(const esi_pdo_entry &e) {
    if (e.index == 0U && e.data_type.empty()) return 0;
    const std::string &n = e.data_type;
    if (const esi::base_type *b = esi::find_base_type(n)) {
      return static_cast<std::uint8_t>(b->etg_code != 0U ? b->etg_code : b->code);
    }
    if (n.size() == 4 && n.starts_with("BIT") && n[3] >= '2' && n[3] <= '8') {
      return static_cast<std::uint8_t>(esi::bit_field_code(static_cast<unsigned>(n[3] - '0')));
    }
    if (n.starts_with("STRING(")) return 0x09;
    if (n.starts_with("ARRAY [0..") && n.ends_with("] OF BYTE")) return 0x0A;
    if (unknown_types_.insert(n).second) {
      diag_.warning(file_, e.line, 0,
                    "PDO entry data type \"" + n + "\" has no ETG.1000.6 code: written as 0");
    }
    return 0;
  }

  std::vector<std::uint8_t> pdos(const esi_device &dev, bool tx) {
    std::vector<std::uint8_t> out;
    for (const esi_pdo &p : dev.pdos) {
      if (p.tx != tx) continue;
      if (level_ >= 1 && p.sm < 0) {
        ++pdos_left_out_;
        continue;
      }
      if (p.entries.size() > 255U) {
        diag_.warning(file_, p.line, 0,
                      "PDO 0x" + hex(p.index, 4) +
                          " has more than 255 entries: not written to the SII");
        continue;
      }
      sii::pdo_header h;
      h.index = p.index;
      h.entries = static_cast<std::uint8_t>(p.entries.size());
      h.sync_manager = p.sm >= 0 && p.sm < 0xFF ? static_cast<std::uint8_t>(p.sm) : 0xFF;
      h.name_index = string(p.name);
      if (p.mandatory) h.flags |= sii::pdo_flags::mandatory;
      if (p.sm >= 0) h.flags |= sii::pdo_flags::default_;
      if (p.fixed) h.flags |= sii::pdo_flags::fixed_content;
      std::size_t at = out.size();
      out.resize(at + sii::pdo_header_bytes);
      (void)sii::encode_pdo_header(h, std::span<std::uint8_t>(out).subspan(at));
      for (const auto &e : p.entries) {
        sii::pdo_entry se;
        se.index = e.index;
        se.sub = e.sub;
        se.name_index = level_ >= 2 ? std::uint8_t{0} : string(e.name);
        se.data_type = etg_code(e);
        se.bits = e.bits;
        at = out.size();
        out.resize(at + sii::pdo_entry_bytes);
        (void)sii::encode_pdo_entry(se, std::span<std::uint8_t>(out).subspan(at));
      }
      ++pdos_written_;
    }
    return out;
  }

  void append(std::vector<std::uint8_t> &image, std::uint16_t type,
              std::vector<std::uint8_t> data) {
    if (data.size() % 2U != 0U) data.push_back(0); // categories are whole words
    if (data.size() > 2U * 0xFFFFU) {
      diag_.error(file_, dev_line(), 0,
                  "SII category " + std::to_string(type) + " of " + std::to_string(data.size()) +
                      " bytes: a category holds at most 65535 words");
      config_ok_ = false;
      return;
    }
    const auto words = static_cast<std::uint16_t>(data.size() / 2U);
    const auto t = to_bytes(type, byte_order::little);
    const auto w = to_bytes(words, byte_order::little);
    image.insert(image.end(), t.begin(), t.end());
    image.insert(image.end(), w.begin(), w.end());
    image.insert(image.end(), data.begin(), data.end());
  }

  const dictionary &d_;
  const std::string &file_;
  diagnostics &diag_;
  int level_ = 0;
  bool too_big_ = false;
  std::size_t image_bytes_ = 0;
  std::size_t pdos_written_ = 0;
  std::size_t pdos_left_out_ = 0;
  std::vector<std::string> strings_;
  bool strings_full_ = false;
  bool bootstrap_ok_ = true;
  bool config_ok_ = true;
  std::set<std::string> unknown_types_;
};

// ---- the report ---------------------------------------------------------------------------------

std::string hex16(std::uint32_t v) { return "0x" + hex(v, 4); }
std::string hex32(std::uint32_t v) { return "0x" + hex(v, 8); }

std::string padded(std::string s, std::size_t n) {
  if (s.size() < n) s.append(n - s.size(), ' ');
  return s;
}

class sii_reporter {
public:
  sii_reporter(std::span<const std::uint8_t> image, const std::string &file, diagnostics &diag)
      : image_(image), file_(file), diag_(diag) {}

  std::string report() {
    const auto fixed = sii::decode_fixed_area(image_);
    if (!fixed) {
      diag_.error(file_, 0, 0,
                  "an SII image has at least 128 bytes (words 0x00..0x3F); this file has " +
                      std::to_string(image_.size()));
      return {};
    }
    const sii::fixed_area &a = fixed.value();
    line("SII EEPROM image, " + std::to_string(image_.size()) +
         " bytes; word 0x3E: " + std::to_string(a.eeprom_bytes()) + "-byte EEPROM (" +
         std::to_string(a.size + 1U) + " kbit); version " + std::to_string(a.version));
    if (a.version != 1U) problem(false, "version " + std::to_string(a.version) + " (ETG.2010: 1)");
    if (a.eeprom_bytes() < image_.size()) {
      problem(false, "the image (" + std::to_string(image_.size()) +
                         " bytes) is larger than the EEPROM word 0x3E gives");
    }
    line("");
    line("configuration area (words 0x00-0x07, loaded by the ESC):");
    field("PDI control", hex16(a.config.pdi_control));
    field("PDI configuration", hex16(a.config.pdi_configuration));
    field("SYNC pulse length", std::to_string(a.config.sync_impulse) + " x 10 ns");
    field("PDI configuration 2", hex16(a.config.pdi_configuration2));
    field("station alias", hex16(a.config.station_alias));
    const std::uint16_t computed = sii::checksum_of(image_).value();
    std::string check =
        hex16(a.config.checksum) + ", CRC-8 of bytes 0..13 " + "0x" + hex(computed, 2);
    if (a.config.checksum == sii::checksum_disabled) {
      check += ": check disabled (0x88A4, for debugging only)";
      problem(false, "the configuration area's checksum is 0x88A4: the ESC does not check it "
                     "(debugging only, never in a product)");
    } else if (sii::check_config_area(image_)) {
      check += ": ok";
    } else {
      check += ": WRONG";
      problem(true, "checksum " + hex16(a.config.checksum) +
                        " of the configuration area is not "
                        "its CRC-8 0x" +
                        hex(computed, 2) + ": the ESC refuses the configuration");
    }
    field("checksum", check);
    line("");
    line("identity (words 0x08-0x0F):");
    field("vendor ID", hex32(a.vendor_id));
    field("product code", hex32(a.product_code));
    field("revision", hex32(a.revision));
    field("serial number", hex32(a.serial));
    line("");
    line("mailboxes (words 0x14-0x1C):");
    const auto mbx = [](const sii::mailbox &m) {
      return hex16(m.offset) + ", " + std::to_string(m.size) + " bytes";
    };
    field("bootstrap receive", mbx(a.bootstrap_receive));
    field("bootstrap send", mbx(a.bootstrap_send));
    field("standard receive", mbx(a.standard_receive));
    field("standard send", mbx(a.standard_send));
    std::string protos;
    const std::pair<std::uint16_t, const char *> names[] = {
        {sii::protocol::aoe, "AoE"}, {sii::protocol::eoe, "EoE"}, {sii::protocol::coe, "CoE"},
        {sii::protocol::foe, "FoE"}, {sii::protocol::soe, "SoE"}, {sii::protocol::voe, "VoE"}};
    for (const auto &[bit, n] : names) {
      if ((a.protocols & bit) != 0U) protos += std::string(protos.empty() ? "" : ", ") + n;
    }
    field("protocols",
          (protos.empty() ? std::string("none") : protos) + " (" + hex16(a.protocols) + ")");
    line("");
    categories();
    return out_;
  }

private:
  void line(const std::string &s) { out_ += s + "\n"; }
  void field(const std::string &k, const std::string &v) { line("  " + padded(k, 22) + v); }
  void problem(bool error, const std::string &msg) {
    if (error) {
      diag_.error(file_, 0, 0, msg);
    } else {
      diag_.warning(file_, 0, 0, msg);
    }
  }
  std::string text(std::uint8_t index) {
    if (index == 0U) return "-";
    const auto s = sii::string_at(strings_, index);
    if (!s) {
      problem(false, "string index " + std::to_string(index) +
                         " names no string of the STRINGS "
                         "category");
      return "#" + std::to_string(index) + " (missing)";
    }
    return "\"" + std::string(s.value()) + "\"";
  }

  static const char *category_name(std::uint16_t t) {
    switch (t) {
    case sii::category_type::nop: return "NOP";
    case sii::category_type::strings: return "STRINGS";
    case sii::category_type::data_types: return "DATATYPES";
    case sii::category_type::general: return "GENERAL";
    case sii::category_type::fmmu: return "FMMU";
    case sii::category_type::sync_manager: return "SYNCM";
    case sii::category_type::fmmu_extended: return "FMMU_EX";
    case sii::category_type::sync_unit: return "SYNCUNIT";
    case sii::category_type::txpdo: return "TXPDO";
    case sii::category_type::rxpdo: return "RXPDO";
    case sii::category_type::dc: return "DC";
    default: return "unknown";
    }
  }

  void categories() {
    // the strings first: other categories refer to them
    {
      sii::category_reader r(image_);
      for (;;) {
        const auto c = r.next();
        if (!c || !c.value()) break;
        if (c.value()->type == sii::category_type::strings) {
          strings_ = c.value()->data;
          break;
        }
      }
    }
    line("categories (from word 0x40):");
    sii::category_reader r(image_);
    for (;;) {
      const auto c = r.next();
      if (!c) {
        problem(true, "category at word 0x" + hex(r.offset() / 2U, 4) +
                          " runs past the end of the image");
        return;
      }
      if (!c.value()) break;
      const sii::category &cat = *c.value();
      cat_word_ = cat.offset / 2U;
      line("  " + std::string(category_name(cat.type)) + " (" + std::to_string(cat.type) +
           (cat.vendor_specific ? ", vendor specific" : "") + ") at word 0x" +
           hex(cat.offset / 2U, 4) + ", " + std::to_string(cat.data.size() / 2U) + " words");
      switch (cat.type) {
      case sii::category_type::strings: strings(cat.data); break;
      case sii::category_type::general: general(cat.data); break;
      case sii::category_type::fmmu: fmmu(cat.data); break;
      case sii::category_type::sync_manager: sync_managers(cat.data); break;
      case sii::category_type::txpdo:
      case sii::category_type::rxpdo: pdos(cat.data); break;
      case sii::category_type::dc: dc(cat.data); break;
      default:
        if (cat.type != sii::category_type::nop && !cat.vendor_specific &&
            (cat.type < 1U || cat.type > 9U)) {
          problem(false, "unknown category " + std::to_string(cat.type) + " at word 0x" +
                             hex(cat.offset / 2U, 4) + " (not decoded)");
        }
        break;
      }
    }
    if (!r.end_found()) {
      problem(false, "no end category (0xFFFF) before the end of the image");
    } else {
      line("  END at word 0x" + hex(r.offset() / 2U, 4));
    }
  }

  void strings(std::span<const std::uint8_t> d) {
    const auto n = sii::string_count(d);
    if (!n) {
      problem(true, "empty STRINGS category at word 0x" + hex(cat_word_, 4));
      return;
    }
    for (unsigned i = 1; i <= n.value(); ++i) {
      const auto s = sii::string_at(d, static_cast<std::uint8_t>(i));
      if (!s) {
        problem(true, "STRINGS category at word 0x" + hex(cat_word_, 4) + ": string " +
                          std::to_string(i) + " of " + std::to_string(n.value()) +
                          " runs past the category");
        return;
      }
      line("    " + padded(std::to_string(i), 4) + "\"" + std::string(s.value()) + "\"");
    }
  }

  void general(std::span<const std::uint8_t> d) {
    const auto g = sii::decode_general(d);
    if (!g) {
      problem(true, "GENERAL category at word 0x" + hex(cat_word_, 4) + " has " +
                        std::to_string(d.size()) + " bytes (at least 16)");
      return;
    }
    const sii::general &x = g.value();
    line("    group " + text(x.group_index) + ", image " + text(x.image_index) + ", order " +
         text(x.order_index) + ", name " + text(x.name_index));
    std::string coe;
    const std::pair<std::uint8_t, const char *> bits[] = {
        {sii::coe_details::sdo, "SDO"},
        {sii::coe_details::sdo_info, "SDO info"},
        {sii::coe_details::pdo_assign, "PDO assign"},
        {sii::coe_details::pdo_config, "PDO configuration"},
        {sii::coe_details::upload_at_startup, "upload at startup"},
        {sii::coe_details::complete_access, "complete access"}};
    for (const auto &[b, n] : bits) {
      if ((x.coe & b) != 0U) coe += std::string(coe.empty() ? "" : ", ") + n;
    }
    line("    CoE: " + (coe.empty() ? std::string("none") : coe) + "; FoE " +
         ((x.foe & 1U) != 0U ? "yes" : "no") + "; EoE " + ((x.eoe & 1U) != 0U ? "yes" : "no"));
    std::string flags;
    const std::pair<std::uint8_t, const char *> fb[] = {
        {sii::general_flags::enable_safe_op, "enable SafeOp"},
        {sii::general_flags::enable_not_lrw, "not LRW"},
        {sii::general_flags::mailbox_data_link_layer, "mailbox data link layer"},
        {sii::general_flags::ident_al_status, "identification in AL status"},
        {sii::general_flags::ident_physical_memory, "identification in physical memory"}};
    for (const auto &[b, n] : fb) {
      if ((x.flags & b) != 0U) flags += std::string(flags.empty() ? "" : ", ") + n;
    }
    line("    flags: " + (flags.empty() ? std::string("none") : flags) + "; E-Bus current " +
         std::to_string(x.ebus_current) + " mA");
    std::string ports;
    for (unsigned p = 0; p < 4U; ++p) {
      const unsigned v = (x.physical_ports >> (4U * p)) & 0xFU;
      const char *n = v == 0U   ? "unused"
                      : v == 1U ? "MII"
                      : v == 3U ? "EBUS"
                      : v == 4U ? "fast hot connect"
                                : "?";
      ports += std::string(p == 0U ? "" : ", ") + std::to_string(p) + " " + n;
    }
    line("    ports: " + ports);
  }

  void fmmu(std::span<const std::uint8_t> d) {
    for (std::size_t i = 0; i < d.size(); ++i) {
      const std::uint8_t u = d[i];
      const char *n = u == sii::fmmu_usage::outputs         ? "outputs"
                      : u == sii::fmmu_usage::inputs        ? "inputs"
                      : u == sii::fmmu_usage::mailbox_state ? "mailbox state"
                      : u == 0U || u == 0xFFU               ? "unused"
                                                            : "?";
      line("    FMMU " + std::to_string(i) + ": " + n);
    }
  }

  void sync_managers(std::span<const std::uint8_t> d) {
    if (d.size() % sii::sync_manager_bytes != 0U) {
      problem(false, "SYNCM category at word 0x" + hex(cat_word_, 4) + " has " +
                         std::to_string(d.size()) + " bytes: not whole 8-byte entries");
    }
    for (std::size_t i = 0;; ++i) {
      const auto m = sii::decode_sync_manager(d, i);
      if (!m) break;
      const sii::sync_manager &s = m.value();
      const char *types[] = {"unused", "mailbox out", "mailbox in", "outputs", "inputs"};
      line("    SM" + std::to_string(i) + ": " + hex16(s.start) + ", " + std::to_string(s.length) +
           " bytes, control 0x" + hex(s.control, 2) + ", enable 0x" + hex(s.enable, 2) + ", " +
           (s.type < 5U ? types[s.type] : "?"));
    }
  }

  void pdos(std::span<const std::uint8_t> d) {
    std::size_t at = 0;
    while (at < d.size()) {
      const auto p = sii::decode_pdo(d, at);
      if (!p) {
        problem(true, "PDO at word 0x" + hex(cat_word_ + 2U + at / 2U, 4) +
                          " runs past its category (at word 0x" + hex(cat_word_, 4) + ")");
        return;
      }
      const sii::pdo_header &h = p.value().header;
      std::string flags;
      if ((h.flags & sii::pdo_flags::mandatory) != 0U) flags += "mandatory";
      if ((h.flags & sii::pdo_flags::default_) != 0U)
        flags += std::string(flags.empty() ? "" : ", ") + "default";
      if ((h.flags & sii::pdo_flags::fixed_content) != 0U)
        flags += std::string(flags.empty() ? "" : ", ") + "fixed";
      line("    PDO " + hex16(h.index) + " " + text(h.name_index) + ", " +
           std::to_string(h.entries) + " entries, SM " +
           (h.sync_manager == 0xFFU ? std::string("none") : std::to_string(h.sync_manager)) +
           (flags.empty() ? "" : ", " + flags) + " (flags " + hex16(h.flags) + ")");
      for (std::size_t i = 0; i < h.entries; ++i) {
        const sii::pdo_entry e = sii::decode_pdo_entry(d, p.value(), i).value();
        line("      " + hex16(e.index) + ":" + hex(e.sub, 2) + " " +
             padded(text(e.name_index), 24) + " type 0x" + hex(e.data_type, 2) + ", " +
             std::to_string(e.bits) + " bits");
      }
      at = p.value().next;
    }
  }

  void dc(std::span<const std::uint8_t> d) {
    for (std::size_t i = 0;; ++i) {
      const auto m = sii::decode_dc_mode(d, i);
      if (!m) break;
      const sii::dc_mode &x = m.value();
      line("    mode " + std::to_string(i) + " " + text(x.name_index) + ": AssignActivate " +
           hex16(x.assign_activate) + ", SYNC0 cycle " + std::to_string(x.cycle_time_sync0) +
           " ns (factor " + std::to_string(x.sync0_cycle_factor) + "), shift " +
           std::to_string(x.shift_time_sync0) + " ns; SYNC1 factor " +
           std::to_string(x.sync1_cycle_factor) + ", shift " + std::to_string(x.shift_time_sync1) +
           " ns");
    }
  }

  std::span<const std::uint8_t> image_;
  const std::string &file_;
  diagnostics &diag_;
  std::span<const std::uint8_t> strings_;
  std::size_t cat_word_ = 0;
  std::string out_;
};

} // namespace

std::optional<std::vector<std::uint8_t>> write_sii(const dictionary &d, const std::string &file,
                                                   diagnostics &diag) {
  // Everything when it fits Eeprom/ByteSize; else less, step by step (a master reads what is
  // left out over CoE), with a warning that says what; an error when even the least does not.
  std::size_t full = 0;
  for (int level = 0;; ++level) {
    diagnostics attempt;
    attempt.strict = diag.strict;
    attempt.max_errors = diag.max_errors;
    sii_writer w(d, file, attempt, level);
    auto image = w.write();
    if (level == 0) full = w.image_bytes();
    if (w.too_big() && level < 3) continue;
    for (const auto &x : attempt.all()) {
      if (x.sev == severity::error) {
        diag.error(x.file, x.line, x.column, x.message);
      } else {
        diag.warning(x.file, x.line, x.column, x.message);
      }
    }
    if (level > 0 && image) {
      const esi_device &dev = *d.ethercat;
      std::string what = level == 3 ? "without the PDO categories"
                                    : "with the " + std::to_string(w.pdos_written()) +
                                          (w.pdos_written() == 1U ? " PDO" : " PDOs") +
                                          " assigned by default only (" +
                                          std::to_string(w.pdos_left_out()) + " left out)";
      if (level == 2) what += " and without the names of their entries";
      diag.warning(file, dev.eeprom_line != 0 ? dev.eeprom_line : dev.line, 0,
                   "the SII image with every PDO (" + std::to_string(full) +
                       " bytes) does not fit the EEPROM of " + std::to_string(dev.eeprom_bytes) +
                       " bytes (Eeprom/ByteSize): written " + what +
                       "; a master reads the PDOs over CoE");
    }
    return image;
  }
}

std::string sii_report(std::span<const std::uint8_t> image, const std::string &file,
                       diagnostics &diag) {
  sii_reporter r(image, file, diag);
  return r.report();
}

} // namespace fieldcodec::gen
