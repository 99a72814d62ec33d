// Store and restore parameters (CiA 301, 1010h/1011h): the commands alone and in the device
// (signatures, the application's hook, capability bits on read, defaults after a reset).
#include "node_test_util.hpp"

#include <fieldcodec/canopen/node/parameter_storage.hpp>

#include <map>
#include <utility>

using namespace test_node;

namespace {

constexpr std::uint32_t save = 0x6576'6173U; // "save"
constexpr std::uint32_t load = 0x6461'6F6CU; // "load"

/// The application's storage in the test: what the hook was asked, and whether it works.
struct flash {
  std::vector<std::pair<char, std::uint8_t>> calls;
  bool works = true;
  static bool save(void *c, std::uint8_t group) noexcept {
    auto &f = *static_cast<flash *>(c);
    f.calls.emplace_back('s', group);
    return f.works;
  }
  static bool restore(void *c, std::uint8_t group) noexcept {
    auto &f = *static_cast<flash *>(c);
    f.calls.emplace_back('r', group);
    return f.works;
  }
  node::storage_hook hook() { return {this, &flash::save, &flash::restore}; }
};

/// SDO expedited upload through the node (what an SDO client reads, not the store's value).
std::uint32_t sdo_read_u(rig<> &r, std::uint16_t index, std::uint8_t sub) {
  const auto ch = sdo::channel::default_for(5).value();
  const auto out = r.feed(ch.request(sdo::initiate_upload({index, sub})));
  const auto resp = on(out, ch.response_id);
  REQUIRE(resp.size() == 1U);
  const auto m = sdo::decode(resp[0].data, sdo::direction::to_client).value();
  REQUIRE(m.type == sdo::message_type::initiate_upload_response);
  REQUIRE(m.expedited);
  return m.value;
}

} // namespace

TEST_CASE("parameter storage alone: signatures, hook, capability") {
  node::parameter_storage p;
  CHECK(node::storage_signature::save == save);
  CHECK(node::storage_signature::load == load);
  // "save" and "load" are the ASCII bytes, least significant first
  CHECK(node::encode_le(save, 4).bytes == std::array<std::uint8_t, 4>{'s', 'a', 'v', 'e'});
  CHECK(node::encode_le(load, 4).bytes == std::array<std::uint8_t, 4>{'l', 'o', 'a', 'd'});
  CHECK(node::parameter_storage::owns({0x1010, 1}));
  CHECK(node::parameter_storage::owns({0x1011, 4}));
  CHECK_FALSE(node::parameter_storage::owns({0x1010, 0}));
  CHECK_FALSE(node::parameter_storage::owns({0x1012, 1}));
  // no hook: refused, capability 0
  CHECK(p.check_write({0x1010, 1}, save) == abort_code::cannot_store);
  CHECK(p.check_write({0x1011, 1}, load) == abort_code::cannot_store);
  CHECK(p.capability({0x1010, 1}) == 0U);
  flash f;
  p.set_hook(f.hook());
  CHECK(p.capability({0x1010, 1}) == 1U);
  CHECK(p.capability({0x1011, 3}) == 1U);
  CHECK(p.check_write({0x1010, 2}, save) == abort_code::none);
  CHECK(p.check_write({0x1011, 2}, load) == abort_code::none);
  // a wrong signature, the other object's, reversed bytes
  CHECK(p.check_write({0x1010, 1}, load) == abort_code::cannot_store);
  CHECK(p.check_write({0x1011, 1}, save) == abort_code::cannot_store);
  CHECK(p.check_write({0x1010, 1}, 0x7361'7665U) == abort_code::cannot_store);
  CHECK(p.check_write({0x1010, 1}, 0) == abort_code::cannot_store);
  CHECK(p.check_write({0x1005, 0}, 0) == abort_code::none); // not its object
  // the hook's answer
  CHECK(p.command({0x1010, 3}) == abort_code::none);
  f.works = false;
  CHECK(p.command({0x1011, 4}) == abort_code::hardware_error);
  CHECK(f.calls == std::vector<std::pair<char, std::uint8_t>>{{'s', 3}, {'r', 4}});
  // only a restore hook
  p.set_hook({&f, nullptr, &flash::restore});
  CHECK(p.capability({0x1010, 1}) == 0U);
  CHECK(p.capability({0x1011, 1}) == 1U);
  CHECK(p.check_write({0x1010, 1}, save) == abort_code::cannot_store);
}

TEST_CASE("device: 1010h/1011h over SDO") {
  rig<> r;
  static_assert(caps.storage);
  (void)r.start();
  flash f;
  // without a hook: capability 0, commands refused
  CHECK(sdo_read_u(r, 0x1010, 1) == 0U);
  CHECK(r.sdo_write(0x1010, 1, save, 4) == abort_code::cannot_store);
  r.dev.set_storage(f.hook());
  for (std::uint8_t sub = 1; sub <= 4; ++sub) {
    CHECK(sdo_read_u(r, 0x1010, sub) == 1U); // saves on command, not autonomously
    CHECK(sdo_read_u(r, 0x1011, sub) == 1U);
  }
  CHECK(sdo_read_u(r, 0x1010, 0) == 4U); // sub 0 is the store's: highest sub-index
  // "save" to every group: the hook is asked, nothing is stored
  for (std::uint8_t sub = 1; sub <= 4; ++sub) {
    CHECK(r.sdo_write(0x1010, sub, save, 4) == abort_code::none);
  }
  CHECK(f.calls ==
        std::vector<std::pair<char, std::uint8_t>>{{'s', 1}, {'s', 2}, {'s', 3}, {'s', 4}});
  CHECK(r.read_u(0x1010, 1) != save);
  // wrong signatures, sub 0, a failing hook
  CHECK(r.sdo_write(0x1010, 1, load, 4) == abort_code::cannot_store);
  CHECK(r.sdo_write(0x1010, 1, 0x6576'6174U, 4) == abort_code::cannot_store);
  CHECK(r.sdo_write(0x1011, 1, save, 4) == abort_code::cannot_store);
  CHECK(r.sdo_write(0x1010, 1, 0x6173, 2) == abort_code::length_too_low);
  CHECK(r.sdo_write(0x1010, 0, 4, 1) == abort_code::write_read_only);
  CHECK(f.calls.size() == 4U);
  f.works = false;
  CHECK(r.sdo_write(0x1010, 2, save, 4) == abort_code::hardware_error);
  CHECK(r.sdo_write(0x1011, 2, load, 4) == abort_code::hardware_error);
  f.works = true;
  // the application's set() takes the same path
  CHECK(r.set_u(0x1010, 3, save, 4) == abort_code::none);
  CHECK(r.set_u(0x1011, 3, save, 4) == abort_code::cannot_store);
  CHECK(f.calls.back() == std::pair<char, std::uint8_t>{'s', 3});
}

TEST_CASE("device: \"load\" restores the defaults at the next reset, not before") {
  rig<> r;
  (void)r.start();
  // the application's storage: the saved value of 1017h per group, put back after a reset
  static std::uint16_t heartbeat = 0;
  static std::map<std::uint8_t, std::uint16_t> saved;
  saved.clear();
  node::storage_hook hook{nullptr,
                          [](void *, std::uint8_t group) noexcept {
                            saved[group] = heartbeat;
                            return true;
                          },
                          [](void *, std::uint8_t group) noexcept {
                            saved.erase(group);
                            if (group == 1U) saved.clear();
                            return true;
                          }};
  r.dev.set_storage(hook);
  CHECK(r.sdo_write(0x1017, 0, 100, 2) == abort_code::none);
  heartbeat = static_cast<std::uint16_t>(r.read_u(0x1017, 0));
  CHECK(r.sdo_write(0x1010, 2, save, 4) == abort_code::none);
  REQUIRE(saved.count(2) == 1U);
  CHECK(saved[2] == 100U);
  // reset communication: the node restores the defaults; the application puts its saved
  // communication parameters back on the reset event
  const auto reapply = [&] {
    for (const auto &e : r.dev.events()) {
      if (e.what == node::event::kind::reset_communication ||
          e.what == node::event::kind::reset_application) {
        if (saved.count(2) != 0U) CHECK(r.set_u(0x1017, 0, saved[2], 2) == abort_code::none);
      }
    }
  };
  (void)r.feed(F(0, {0x82, 5}));
  reapply();
  CHECK(r.read_u(0x1017, 0) == 100U);
  // "load": the current value stays until the next reset, then the default (0) is back
  CHECK(r.sdo_write(0x1011, 1, load, 4) == abort_code::none);
  CHECK(saved.empty());
  CHECK(r.read_u(0x1017, 0) == 100U);
  CHECK(r.dev.producer().period() == 100U);
  (void)r.feed(F(0, {0x82, 5}));
  reapply();
  CHECK(r.read_u(0x1017, 0) == 0U);
  CHECK(r.dev.producer().period() == 0U);
}
