// od::text: the text columns of od::entry / od::entry_info read like std::string_view.
#include <fieldcodec/od/entry.hpp>
#include <fieldcodec/od/text.hpp>

#include <doctest/doctest.h>

#include <string>
#include <string_view>
#include <type_traits>

namespace od = fieldcodec::od;
using namespace std::string_view_literals;

namespace {

// the reason it exists: an omitted column is zero-initialised, no constructor is evaluated
static_assert(std::is_trivially_default_constructible_v<od::text>);
static_assert(std::is_trivially_copyable_v<od::text>);

constexpr od::entry_info named{.name = "Device type", .unit = {"bar", 3}, .remark = "a\0b"sv};
static_assert(named.name == "Device type");
static_assert("Device type" == named.name);
static_assert(named.name != "Device typ");
static_assert(named.name.size() == 11U && named.name.length() == 11U);
static_assert(named.unit == "bar" && named.unit.view() == "bar"sv);
static_assert(named.remark.size() == 3U && named.remark == "a\0b"sv && named.remark[1] == '\0');
static_assert(named.alt_name.empty() && named.alt_name.size() == 0U && named.alt_name == "");
static_assert(od::no_info.name.empty() && od::no_info.parameter_text.empty());
static_assert(od::entry{}.default_text().empty());
static_assert(od::text{"x"} == od::text{"x"} && !(od::text{"x"} == od::text{"y"}));
static_assert(od::text{} == od::text{nullptr} && od::text{nullptr}.empty());
static_assert(std::string_view{named.name} == "Device type"sv);

} // namespace

TEST_CASE("od text: reads like a string_view") {
  const std::string s = "Device type";
  CHECK(named.name == s);
  CHECK(s == named.name);
  CHECK(std::string(named.name) == s);
  CHECK(std::string(named.name.begin(), named.name.end()) == s);
  CHECK(named.name.data() == named.name.view().data());
  const od::text t(s); // from a std::string (through std::string_view): views s
  CHECK(t.data() == s.data());
  CHECK(t.size() == s.size());
  const std::string_view v = t;
  CHECK(v == "Device type");
  od::text empty{};
  CHECK(empty.empty());
  CHECK(empty.begin() == empty.end());
  CHECK(empty == ""sv);
}
