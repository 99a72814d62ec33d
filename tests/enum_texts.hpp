// For the tests of an enum's to_string: every value from 0 to `last` has a text that is not
// empty and not the fallback "?", a value no enumerator has gives "?", and the function returns
// how many different texts there are (the caller compares it with the number of values).
// to_string is found by argument-dependent lookup, as an application writes it.
#pragma once

#include <doctest/doctest.h>

#include <cstddef>
#include <set>
#include <string_view>

namespace test_texts {

template <class E>
std::size_t distinct_texts(E last) {
  std::set<std::string_view> texts;
  for (int v = 0; v <= static_cast<int>(last); ++v) {
    const std::string_view t = to_string(static_cast<E>(v));
    CHECK(t != "?");
    CHECK_FALSE(t.empty());
    texts.insert(t);
  }
  CHECK(to_string(static_cast<E>(200)) == "?");
  return texts.size();
}

} // namespace test_texts
