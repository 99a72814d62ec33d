// fieldcodec — od::text, a text column of a dictionary (a name, a unit, a default string): a
// pointer and a length that reads like a std::string_view.
//
// Why not std::string_view itself: a generated dictionary has thousands of rows with up to nine
// text columns, most of them empty, and std::string_view's default constructor is user-provided,
// so the compiler evaluates it for every empty column of every row. od::text's default
// constructor is trivial (an omitted `{}` member is zero-initialised, nothing is evaluated):
// the `infos` table of a 4574-entry dictionary compiles ~0.25 s faster with g++ 12
// (docs/performance.md, "Compile time of generated headers").
//
//   od::text t = "Device type";         // from a string literal / const char * (NUL-terminated)
//   od::text u = some_string_view;      // from a std::string_view (embedded NULs kept)
//   od::text v{"a\0b", 3};              // pointer and length (what generated headers write)
//   t == "Device type"; t.size(); t.empty(); std::string_view{t}; t.view()
//
// `od::text t;` (default-initialised, like an int) holds no value; write `od::text t{};` for the
// empty text. Every member of od::entry / od::entry_info is written `{}` and so is empty.
#pragma once

#include <concepts>
#include <cstddef>
#include <string_view>

namespace fieldcodec::od {

class text {
public:
  /// Trivial (see above): `text{}` is the empty text.
  constexpr text() noexcept = default;
  constexpr text(const char *chars, std::size_t size) noexcept : chars_(chars), size_(size) {}
  /// A NUL-terminated string.
  constexpr text(const char *s) noexcept // NOLINT(google-explicit-constructor): reads as a view
      : chars_(s), size_(s == nullptr ? 0U : std::char_traits<char>::length(s)) {}
  constexpr text(std::string_view s) noexcept // NOLINT(google-explicit-constructor)
      : chars_(s.data()), size_(s.size()) {}

  [[nodiscard]] constexpr std::string_view view() const noexcept { return {chars_, size_}; }
  constexpr operator std::string_view() const noexcept { // NOLINT(google-explicit-constructor)
    return view();
  }

  [[nodiscard]] constexpr const char *data() const noexcept { return chars_; }
  [[nodiscard]] constexpr std::size_t size() const noexcept { return size_; }
  [[nodiscard]] constexpr std::size_t length() const noexcept { return size_; }
  [[nodiscard]] constexpr bool empty() const noexcept { return size_ == 0U; }
  [[nodiscard]] constexpr const char *begin() const noexcept { return chars_; }
  [[nodiscard]] constexpr const char *end() const noexcept { return chars_ + size_; }
  /// The byte at `i` (i < size()).
  [[nodiscard]] constexpr char operator[](std::size_t i) const noexcept { return chars_[i]; }

  /// By content, with anything a std::string_view is made from ("…", std::string, …).
  [[nodiscard]] friend constexpr bool operator==(const text &a, std::string_view b) noexcept {
    return a.view() == b;
  }
  /// By content (a template, so that `text == "…"` has one candidate, not two conversions).
  template <class T>
  requires std::same_as<T, text>
  [[nodiscard]] friend constexpr bool operator==(const text &a, const T &b) noexcept {
    return a.view() == b.view();
  }

private:
  const char *chars_;
  std::size_t size_;
};

} // namespace fieldcodec::od
