// fieldcodec — the SDO channels of a node (CiA 301 7.5.2.33/34): the default server channel,
// additional servers from the SDO server parameters 1201h–127Fh and clients from the SDO
// client parameters 1280h–12FFh, each with its COB-IDs taken from the store and kept up to
// date by the writes to them.
//
//   node::sdo_channels<Store, 2, 1, 64> sdo(store, 5);
//   sdo.reload(dictionary);                     // 1200h.. and 1280h.. from the store
//   if (auto s = sdo.on_frame(frame, now)) ...  // taken by a server or client: its step
//   sdo.on_server_frames(sdo.server_of(f), run, now);  // a run of frames for one server
//   sdo.poll(now);                              // timeouts of every channel
//   auto t = sdo.client(0).upload({0x1008, 0}, buffer, now);   // a transfer of client 0
//
// Server 0 is the default channel: 1200h when the dictionary has it (its values, usually
// 0x600 + node / 0x580 + node), the predefined connection of the node otherwise. Servers 1..
// take 1201h, 1202h, … in the order the dictionary has them, clients 1280h, 1281h, …. A
// parameter object whose sub 1 or sub 2 has bit 31 set is a channel that does not exist: no
// frames are routed to it. Writes to sub 1 / sub 2 follow the COB-ID rule of CiA 301 (bits
// 11..29 refused, no change of a valid COB-ID while it stays valid: 0x06090030); a new value
// moves the channel at once (a transfer running on it ends silently).
#pragma once

#include <fieldcodec/canopen/can_frame.hpp>
#include <fieldcodec/canopen/node/cob_id_rules.hpp>
#include <fieldcodec/canopen/node/deadlines.hpp>
#include <fieldcodec/canopen/node/lists.hpp>
#include <fieldcodec/canopen/node/values.hpp>
#include <fieldcodec/canopen/object_store.hpp>
#include <fieldcodec/canopen/sdo.hpp>
#include <fieldcodec/canopen/sdo_client.hpp>
#include <fieldcodec/canopen/sdo_server.hpp>
#include <fieldcodec/canopen/step.hpp>
#include <fieldcodec/core/crc.hpp>
#include <fieldcodec/core/result.hpp>
#include <fieldcodec/od/address.hpp>
#include <fieldcodec/od/dictionary.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <utility>

namespace fieldcodec::canopen::node {

namespace sdo_index {
inline constexpr std::uint16_t server = 0x1200U; ///< 1200h–127Fh
inline constexpr std::uint16_t client = 0x1280U; ///< 1280h–12FFh
inline constexpr std::uint16_t count = 0x80U;
} // namespace sdo_index

/// `Crc`: how the servers compute the CRC of block transfers (core/crc.hpp; the clients always
/// compute it without a table, so that they stay `sdo::client`).
/// The state in an sdo_channels' steps: whether a transfer runs on any of its channels.
/// (0 and 1, the bool it replaced: converted without code.)
enum class channels_state : std::uint8_t { idle = 0, transferring = 1 };

[[nodiscard]] constexpr std::string_view to_string(channels_state s) noexcept {
  return s == channels_state::transferring ? "SDO transfer running" : "no SDO transfer";
}

template <canopen::object_store Store, std::size_t Servers, std::size_t Clients, std::size_t Buffer,
          class Crc = crc::ccitt16_no_table>
class sdo_channels {
  static_assert(Servers >= 1U, "a node has at least its default SDO server");
  static_assert(Buffer >= 8U, "an SDO server buffer holds at least one segment and a u32");

public:
  /// State in the steps: is any transfer running?
  using step = canopen::step<channels_state>;

  /// Channels of node `node` over `store` (borrowed). Until reload() only server 0 exists, on
  /// the predefined connection.
  constexpr sdo_channels(Store &store, std::uint8_t node, std::uint32_t timeout_ms = 1000,
                         sdo::server_options o = {}) noexcept
      : sdo_channels(store, node, sdo::channel::default_for(node), timeout_ms, o) {}

  sdo_channels(const sdo_channels &) = delete;
  sdo_channels &operator=(const sdo_channels &) = delete;

  /// Read the SDO parameter objects of `dict` from the store. Errors: too_long (the dictionary
  /// has more servers / clients than Servers / Clients: the first ones are served).
  [[nodiscard]] constexpr status reload(od::dictionary dict) noexcept {
    status st{};
    server_count_ = 1;
    client_count_ = 0;
    server_index_[0] = dict.contains(sdo_index::server, 1) ? sdo_index::server : 0U;
    for (const od::entry &e : dict) {
      if (e.sub != 1U) continue;
      if (e.index > sdo_index::server && e.index < sdo_index::client) {
        if (server_count_ == Servers) {
          st = errc::too_long;
          continue;
        }
        server_index_[server_count_++] = e.index;
      } else if (e.index >= sdo_index::client && e.index < sdo_index::client + sdo_index::count) {
        if (client_count_ == Clients) {
          st = errc::too_long;
          continue;
        }
        client_index_[client_count_++] = e.index;
      }
    }
    for (std::size_t i = 0; i < Servers; ++i) connect_server(i);
    for (std::size_t i = 0; i < used_clients(); ++i) connect_client(i);
    return st;
  }

  /// A new node-ID (LSS, at an NMT reset): the default server's predefined connection
  /// follows it (reload() then reads the parameter objects).
  constexpr void set_node(std::uint8_t node) noexcept {
    node_ = node;
    connect_server(0);
  }

  // ----- parameter writes ------------------------------------------------------------------

  /// Would `value` be accepted at `a` (sub 1 / sub 2 of a served SDO parameter object)?
  [[nodiscard]] constexpr abort_code
  check_write(od::address a, std::span<const std::uint8_t> value) const noexcept {
    const auto v = u32_of(value);
    return v ? check_write(a, *v) : abort_code::none;
  }
  /// The same for a value of 1..4 bytes as a number (node::device decodes it once).
  [[nodiscard]] constexpr abort_code check_write(od::address a, std::uint32_t v) const noexcept {
    if (a.sub != 1U && a.sub != 2U) return abort_code::none;
    if (!serves(a.index)) return abort_code::none;
    return check_cob_id(v, read_u32(*store_, a), false);
  }
  /// `a` was written: move the channel.
  constexpr void written(od::address a) noexcept {
    if (a.sub != 1U && a.sub != 2U) return;
    for (std::size_t i = 0; i < server_count_; ++i) {
      if (server_index_[i] == a.index && a.index != 0U) connect_server(i);
    }
    for (std::size_t i = 0; i < used_clients(); ++i) {
      if (client_index_[i] == a.index) connect_client(i);
    }
  }
  constexpr void written(od::address a, std::uint32_t, std::uint32_t) noexcept { written(a); }
  /// reload() from `store`'s dictionary with every server transfer ended, as node::device
  /// starts its services.
  template <class S>
  constexpr status load(const S &store, std::uint32_t) noexcept {
    const status st = reload(store.dictionary());
    stop_servers();
    return st;
  }

  // ----- traffic ---------------------------------------------------------------------------

  /// A frame for a server (its request COB-ID) or a client (its response COB-ID): that
  /// machine's step; nullopt when no channel takes the frame.
  [[nodiscard]] constexpr std::optional<sdo::step> on_frame(const can_frame &f,
                                                            std::uint32_t now) noexcept {
    for (std::size_t i = 0; i < Servers; ++i) {
      if (server_ok_[i] && servers_[i].connection().is_request(f)) {
        return servers_[i].on_frame(f, now);
      }
    }
    for (std::size_t i = 0; i < used_clients(); ++i) {
      if (client_ok_[i] && clients_[i].connection().is_response(f)) {
        return clients_[i].on_frame(f, now);
      }
    }
    return std::nullopt;
  }

  /// The server that on_frame hands `f` to (the first whose request COB-ID it is), or
  /// server_capacity() when it hands it to none (a client's frame, or no channel's).
  [[nodiscard]] constexpr std::size_t server_of(const can_frame &f) const noexcept {
    for (std::size_t i = 0; i < Servers; ++i) {
      if (server_ok_[i] && servers_[i].connection().is_request(f)) return i;
    }
    return Servers;
  }
  /// Frames that server_of gives to server `i` (< server_capacity()), in order: that server's
  /// on_frames (sdo::server::on_frames; what on_frame does for each of them).
  [[nodiscard]] constexpr sdo::batch_step
  on_server_frames(std::size_t i, std::span<const can_frame> fs, std::uint32_t now) noexcept {
    return servers_[i].on_frames(fs, now);
  }

  /// Timeouts of every channel (each sends at most one abort).
  [[nodiscard]] constexpr step poll(std::uint32_t now) noexcept {
    out_.clear();
    // a timeout sends one abort frame, nothing else does
    for (std::size_t i = 0; i < Servers; ++i) {
      if (const auto s = servers_[i].poll(now); !s.send.empty()) out_.push(s.send[0]);
    }
    for (std::size_t i = 0; i < used_clients(); ++i) {
      if (const auto s = clients_[i].poll(now); !s.send.empty()) out_.push(s.send[0]);
    }
    return {out_.view(), static_cast<channels_state>(busy()), deadline(now)};
  }

  /// End every server transfer silently (NMT stopped or a reset; a client's transfer belongs to
  /// the application and runs on until it completes or times out).
  constexpr void stop_servers() noexcept {
    for (std::size_t i = 0; i < Servers; ++i) servers_[i].set_connection(servers_[i].connection());
  }

  // ----- access ----------------------------------------------------------------------------

  [[nodiscard]] constexpr sdo::client &client(std::size_t i) noexcept { return clients_[i]; }
  [[nodiscard]] constexpr const sdo::client &client(std::size_t i) const noexcept {
    return clients_[i];
  }
  [[nodiscard]] constexpr const sdo::server<Store, Crc> &server(std::size_t i) const noexcept {
    return servers_[i];
  }
  /// Does server / client i exist (valid COB-IDs)?
  [[nodiscard]] constexpr bool server_valid(std::size_t i) const noexcept {
    return i < Servers && server_ok_[i];
  }
  [[nodiscard]] constexpr bool client_valid(std::size_t i) const noexcept {
    return i < Clients && client_ok_[i];
  }
  /// The node-ID of the server client i talks to (1280h + i sub 3; 0 when not given).
  [[nodiscard]] constexpr std::uint8_t client_server_node(std::size_t i) const noexcept {
    if (i >= used_clients()) return 0;
    return static_cast<std::uint8_t>(read_u32(*store_, {client_index_[i], 3}).value_or(0U));
  }
  [[nodiscard]] constexpr bool busy() const noexcept {
    for (std::size_t i = 0; i < Servers; ++i) {
      if (servers_[i].busy()) return true;
    }
    for (std::size_t i = 0; i < used_clients(); ++i) {
      if (clients_[i].busy()) return true;
    }
    return false;
  }
  [[nodiscard]] constexpr std::optional<std::uint32_t> deadline(std::uint32_t now) const noexcept {
    std::optional<std::uint32_t> d;
    for (std::size_t i = 0; i < Servers; ++i) d = earliest(d, servers_[i].deadline(), now);
    for (std::size_t i = 0; i < used_clients(); ++i) d = earliest(d, clients_[i].deadline(), now);
    return d;
  }
  static constexpr std::size_t server_capacity() noexcept { return Servers; }
  static constexpr std::size_t client_capacity() noexcept { return Clients; }

private:
  /// `predefined`: the predefined connection of `node`, when it has one.
  constexpr sdo_channels(Store &store, std::uint8_t node, result<sdo::channel> predefined,
                         std::uint32_t timeout_ms, sdo::server_options o) noexcept
      : store_(&store), node_(node),
        servers_(make_servers(store, predefined.value_or(sdo::channel{}), timeout_ms, o, buffers_,
                              std::make_index_sequence<Servers>{})),
        clients_(make_clients(timeout_ms, std::make_index_sequence<Clients>{})) {
    server_ok_[0] = predefined.has_value();
  }

  template <std::size_t... S>
  [[nodiscard]] static constexpr std::array<sdo::server<Store, Crc>, Servers>
  make_servers(Store &store, sdo::channel predefined, std::uint32_t timeout_ms,
               sdo::server_options o,
               std::array<std::array<std::uint8_t, Buffer>, Servers> &buffers,
               std::index_sequence<S...>) noexcept {
    // server 0 starts on the predefined connection, the others without one (until reload)
    return {{sdo::server<Store, Crc>(S == 0U ? predefined : sdo::channel{}, store,
                                     std::span<std::uint8_t>(buffers[S]), timeout_ms, o)...}};
  }
  template <std::size_t... C>
  [[nodiscard]] static constexpr std::array<sdo::client, Clients>
  make_clients([[maybe_unused]] std::uint32_t timeout_ms, std::index_sequence<C...>) noexcept {
    return {{(static_cast<void>(C), sdo::client(sdo::channel{}, timeout_ms))...}};
  }

  [[nodiscard]] constexpr bool serves(std::uint16_t index) const noexcept {
    for (std::size_t i = 0; i < server_count_; ++i) {
      if (server_index_[i] == index && index != 0U) return true;
    }
    for (std::size_t i = 0; i < used_clients(); ++i) {
      if (client_index_[i] == index) return true;
    }
    return false;
  }
  /// The channel of parameter object `index`, or nullopt when a COB-ID is not valid / missing.
  [[nodiscard]] constexpr std::optional<sdo::channel>
  channel_of(std::uint16_t index) const noexcept {
    const auto rx = read_u32(*store_, {index, 1});
    const auto tx = read_u32(*store_, {index, 2});
    if (!rx || !tx) return std::nullopt;
    auto ch = sdo::channel::from_cob_ids(*rx, *tx);
    if (!ch) return std::nullopt;
    return ch.value();
  }
  constexpr void connect_server(std::size_t i) noexcept {
    std::optional<sdo::channel> ch;
    if (i == 0U && server_index_[0] == 0U) {
      const auto d = sdo::channel::default_for(node_);
      if (d) ch = d.value();
    } else if (i < server_count_) {
      ch = channel_of(server_index_[i]);
    }
    server_ok_[i] = ch.has_value();
    servers_[i].set_connection(ch.value_or(sdo::channel{}));
  }
  constexpr void connect_client(std::size_t i) noexcept {
    std::optional<sdo::channel> ch;
    if (i < used_clients()) ch = channel_of(client_index_[i]);
    client_ok_[i] = ch.has_value();
    if (clients_[i].busy()) (void)clients_[i].cancel(); // the channel it ran on is gone
    (void)clients_[i].set_connection(ch.value_or(sdo::channel{}));
  }

  static constexpr std::size_t client_slots = Clients == 0U ? 1U : Clients;
  /// The clients in use: 0, known at compile time, for a node without clients (whose image
  /// then holds no client code, and whose loops over the clients do not index an empty array
  /// behind a run-time bound, which g++ 12 -O2 reports with -Warray-bounds in users' builds).
  [[nodiscard]] constexpr std::size_t used_clients() const noexcept {
    return Clients == 0U ? 0U : client_count_;
  }

  Store *store_;
  std::uint8_t node_;
  std::array<std::array<std::uint8_t, Buffer>, Servers> buffers_{};
  std::array<sdo::server<Store, Crc>, Servers> servers_;
  std::array<sdo::client, Clients> clients_;
  std::array<std::uint16_t, Servers> server_index_{};
  std::array<std::uint16_t, client_slots> client_index_{};
  std::array<bool, Servers> server_ok_{};
  std::array<bool, client_slots> client_ok_{};
  std::size_t server_count_ = 1;
  std::size_t client_count_ = 0;
  frame_list<Servers + Clients> out_{};
};

} // namespace fieldcodec::canopen::node
