// fieldcodec CLI — the CANopen traffic decoder behind `decode` and `monitor`: one readable
// line per frame (NMT, SYNC, TIME, EMCY, PDO, heartbeat, node guarding), SDO transfers
// reassembled into one line each (expedited, segmented, block), PDOs unpacked by the mapping
// the dictionaries or the log's own SDO writes define.
#pragma once

#include "dictionary.hpp"
#include "util.hpp"
#include "values.hpp"

#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/host/candump.hpp>
#include <fieldcodec/host/frame_record.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace fieldcodec::cli {

/// Where a node is: the interface of its frames and its node-ID. The same node-ID on two
/// interfaces (a `candump -l any` log) is two devices, each with its own transfers and PDOs.
struct node_key {
  std::string iface; ///< empty: no interface known (also: the dictionaries' defaults)
  std::uint8_t node = 0;
  friend auto operator<=>(const node_key &, const node_key &) = default;
};

/// One output line.
struct decoded_line {
  host::timestamp time{};
  host::interface_name iface{};
  std::string id;       ///< "605", "12345678", "" (not a frame)
  std::string function; ///< "SDO", "NMT", "TPDO1", "EMCY", "HEARTBEAT", ...
  int node = -1;        ///< -1: no node
  std::string text;     ///< the description
  json_object json;     ///< the fields of the description
  bool problem = false; ///< malformed input, an abort, a protocol error
  std::size_t line_no = 0;
};

/// "1700000000.123456 can0 585 SDO        node 5: …" (time and interface only when known).
[[nodiscard]] std::string render_text(const decoded_line &l);
/// One JSON object per line.
[[nodiscard]] std::string render_json(const decoded_line &l);

class can_decoder {
public:
  struct options {
    bool sdo_frames = false; ///< also one line per SDO frame (not only per transfer)
  };

  /// Dictionaries by node (index 1..127; a default for nodes without their own at 0).
  can_decoder(std::map<std::uint8_t, node_dictionary> dicts,
              std::map<std::uint8_t, device_family> families, options o);

  /// Decode one frame; appends 0..n lines (an SDO segment adds none until its transfer ends).
  void feed(const host::frame_record &r, std::size_t line_no, std::vector<decoded_line> &out);
  /// A line of the input that is not a frame: its number, what is wrong and where, the line
  /// (at most 120 characters of it, escaped).
  void malformed(std::string_view text, const host::candump::line_error &e, std::size_t line_no,
                 std::vector<decoded_line> &out);
  /// A line of candump's own that tells something (DROPCOUNT: frames the kernel dropped).
  void note(std::string_view text, std::size_t line_no, std::vector<decoded_line> &out);
  /// The input ended: transfers still running are reported as incomplete.
  void finish(std::vector<decoded_line> &out);

private:
  /// An SDO transfer seen on the bus, from its initiate to its last frame.
  struct sdo_track {
    enum class kind : std::uint8_t { none, download, upload, block_download, block_upload };
    kind k = kind::none;
    od::address a{};
    bool expedited = false;
    bool size_indicated = false;
    std::uint32_t size = 0;
    std::vector<std::uint8_t> data;
    bool toggle = false;    ///< the toggle the next segment must carry
    bool last_sent = false; ///< the last segment was seen
    std::size_t segments = 0;
    std::string problem; ///< protocol errors seen during the transfer
    // block transfer
    bool crc = false;
    bool in_burst = false;
    std::uint8_t expected_seq = 1;
    std::vector<std::array<std::uint8_t, 7>> burst;
    int burst_last = -1; ///< index in `burst` of the segment marked last, -1: none yet
    bool final_committed = false;
    std::uint8_t unused = 0;
    std::uint16_t checksum = 0;
    bool end_seen = false;
    host::timestamp last_time{}; ///< of the last frame of the transfer
    host::interface_name iface{};
    canopen::sdo::abort_code abort{}; ///< the abort that ended it
    std::string aborted_by;           ///< "client" or "server"
  };
  struct pdo_config {
    std::uint32_t cob_id = 0x80000000U; ///< bit 31: not valid
    std::uint8_t count = 0;
    std::array<std::uint32_t, 64> map{};
    bool mapping_known = false;
  };
  struct node_state {
    const node_dictionary *dict = nullptr;
    device_family family = device_family::generic;
    value_context values{};
    std::array<pdo_config, 512> rpdo{}, tpdo{};
    std::uint8_t last_toggle = 2; ///< node guarding: toggle of the last response (2: none)
    bool guarded = false;         ///< a guarding request was seen: 0x700 answers are guarding
  };
  node_state &node(const node_key &k);
  const object_desc *desc(const node_key &k, od::address a);
  void on_sdo(const host::frame_record &r, const node_key &k, bool to_server, decoded_line base,
              std::vector<decoded_line> &out);
  bool on_pdo(const host::frame_record &r, decoded_line base, std::vector<decoded_line> &out);
  void on_lss(const host::frame_record &r, decoded_line base, std::vector<decoded_line> &out);
  void sdo_done(sdo_track &t, const node_key &k, decoded_line &l, bool aborted);
  static std::string trim_unindicated(sdo_track &t, const object_desc *d);
  void apply_write(const node_key &k, od::address a, std::span<const std::uint8_t> bytes);

  std::map<std::uint8_t, node_dictionary> dicts_; ///< as loaded: by node, 0 for every node
  std::map<std::uint8_t, node_dictionary> built_; ///< for each node seen: resolved, units applied
  std::map<std::uint8_t, device_family> families_;
  options options_;
  std::map<node_key, node_state> nodes_;
  /// Valid PDO COB-IDs on an interface → node, direction (0 TPDO, 1 RPDO), number; rebuilt
  /// when a node appears or a PDO parameter is written. Interface "": a node only a dictionary
  /// has told of so far (its PDOs are known on every interface until it shows up on one).
  struct pdo_ref {
    node_key node;
    int dir;
    std::size_t k;
  };
  std::map<std::pair<std::string, std::uint32_t>, pdo_ref> pdo_index_;
  bool pdo_dirty_ = true;
  std::map<node_key, sdo_track> sdo_;
};

} // namespace fieldcodec::cli
