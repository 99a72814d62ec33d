// core/calendar.hpp (days ↔ dates, CiA 301's 1984 epoch) and core/utf8.hpp (strict UTF-8).
#include <fieldcodec/core/calendar.hpp>
#include <fieldcodec/core/utf8.hpp>

#include <doctest/doctest.h>

#include <string_view>

namespace cal = fieldcodec::calendar;
namespace utf8 = fieldcodec::utf8;
using fieldcodec::errc;

static_assert(cal::to_days({1970, 1, 1}).value() == 0);
static_assert(cal::to_days({1984, 1, 1}).value() == cal::cia301_epoch);
static_assert(cal::from_days(cal::cia301_epoch + 14610) == cal::date{2024, 1, 1});
static_assert(cal::from_days(-1) == cal::date{1969, 12, 31});
static_assert(cal::from_days(cal::to_days({2000, 2, 29}).value()) == cal::date{2000, 2, 29});
static_assert(cal::to_days({2023, 2, 29}).error() == errc::out_of_range);
static_assert(cal::to_days({2024, 13, 1}).error() == errc::out_of_range);
static_assert(cal::to_days({2024, 4, 31}).error() == errc::out_of_range);
static_assert(!cal::is_leap(1900) && cal::is_leap(2000) && cal::is_leap(2024));

static_assert(utf8::valid("plain ASCII"));
static_assert(utf8::valid("\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80")); // é € 😀
static_assert(!utf8::valid("\xC0\xAF"));                            // overlong '/'
static_assert(!utf8::valid("\xED\xA0\x80"));                        // a surrogate
static_assert(!utf8::valid("\xF4\x90\x80\x80"));                    // beyond U+10FFFF
static_assert(!utf8::valid("\xE2\x82"));                            // cut off
static_assert(!utf8::valid("\xFF"));
static_assert(utf8::sequence_length("\xE2\x82\xAC!", 0) == 3);
static_assert(utf8::sequence_length("\x80", 0) == 0);

TEST_CASE("calendar: every day from 1900 to 2200 goes to a date and back") {
  const std::int64_t first = cal::to_days({1900, 1, 1}).value();
  const std::int64_t last = cal::to_days({2200, 12, 31}).value();
  cal::date previous = cal::from_days(first - 1);
  for (std::int64_t d = first; d <= last; ++d) {
    const cal::date x = cal::from_days(d);
    CHECK(cal::to_days(x).value() == d);
    const bool next_day = x.day == previous.day + 1U && x.month == previous.month;
    const bool next_month = x.day == 1U && (x.month == previous.month + 1U ||
                                            (x.month == 1U && x.year == previous.year + 1));
    CHECK((next_day || next_month));
    previous = x;
  }
}

TEST_CASE("utf8::next gives code points and refuses what is no UTF-8") {
  std::size_t i = 0;
  const std::string_view s = "A\xC3\xA9\xF0\x9F\x98\x80";
  CHECK(utf8::next(s, i).value() == 0x41U);
  CHECK(utf8::next(s, i).value() == 0xE9U);
  CHECK(utf8::next(s, i).value() == 0x1F600U);
  CHECK(i == s.size());
  CHECK(utf8::next(s, i).error() == errc::bad_character);
  std::size_t j = 0;
  CHECK(utf8::next("\xC3", j).error() == errc::bad_character);
  CHECK(j == 0U);
}
