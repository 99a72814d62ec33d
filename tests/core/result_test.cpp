#include <fieldcodec/core/decimal.hpp>
#include <fieldcodec/core/result.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__unix__)
#include <csignal>
#include <sys/wait.h>
#include <unistd.h>
#endif

using fieldcodec::errc;
using fieldcodec::result;
using fieldcodec::status;

namespace {
constexpr result<int> half(int v) {
  if (v % 2 != 0) return errc::bad_digit;
  return v / 2;
}

/// An error with context, as an SDO transfer reports it.
struct transfer_error {
  errc code;
  std::uint32_t abort = 0;
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  friend constexpr bool operator==(const transfer_error &, const transfer_error &) = default;
};

/// An error type that does not carry an errc.
struct text_error {
  const char *text;
};

/// An error with context that converts from a plain errc (so an errc propagates into it).
struct node_error {
  errc code;
  std::uint8_t node = 0;
  constexpr node_error(errc c) noexcept : code(c) {} // NOLINT: implicit on purpose
  constexpr node_error(errc c, std::uint8_t n) noexcept : code(c), node(n) {}
  friend constexpr bool operator==(const node_error &, const node_error &) = default;
};

/// Trivially copyable, but not default constructible: the union layout.
struct no_default {
  constexpr explicit no_default(int x) noexcept : v(x) {}
  int v;
  friend constexpr bool operator==(const no_default &, const no_default &) = default;
};
} // namespace

// ---- the basics, at compile time ---------------------------------------------------------------
static_assert(half(8).value() == 4);
static_assert(*half(8) == 4);
static_assert(!half(7).has_value());
static_assert(!static_cast<bool>(half(7)));
static_assert(half(7).error() == errc::bad_digit);
static_assert(half(7).value_or(-1) == -1);
static_assert(half(8).value_or(-1) == 4);
static_assert(half(7) == errc::bad_digit);
static_assert(half(7) != errc::overflow);
static_assert(half(8) != errc::bad_digit);
static_assert(half(8) == result<int>(4));
static_assert(half(8) == 4);
static_assert(half(8) != 5);
static_assert(half(7) != 3);
static_assert(half(7) == result<int>(errc::bad_digit));
static_assert(half(7) != result<int>(errc::truncated));
static_assert(half(8).is(errc::bad_digit) == false);
static_assert(half(7).is(errc::bad_digit));
static_assert(half(8).and_then(half).value() == 2);
static_assert(half(6).and_then(half).error() == errc::bad_digit);
static_assert(half(7).and_then(half).error() == errc::bad_digit);
static_assert(half(8).transform([](int v) { return v * 10; }).value() == 40);
static_assert(half(7).transform([](int v) { return v * 10; }).error() == errc::bad_digit);
static_assert(status{}.has_value());
static_assert(status{errc::overflow}.is(errc::overflow));
static_assert(status{errc::overflow} == errc::overflow);
static_assert(status{} == status{});
static_assert(status{} != status{errc::overflow});
static_assert(status{errc::timeout} != status{errc::overflow});
static_assert(std::is_same_v<result<int>::error_type, errc>);
static_assert(std::is_same_v<result<int>::value_type, int>);
static_assert(std::is_same_v<result<int>::rebind<long>, result<long>>);
static_assert(std::is_same_v<status, result<void, errc>>);

// or_else and transform_error
static_assert(half(7).or_else([](errc) { return result<int>(0); }).value() == 0);
static_assert(half(8).or_else([](errc) { return result<int>(0); }).value() == 4);
static_assert(half(7)
                  .or_else([](errc e) {
                    return result<int>(e == errc::bad_digit ? errc::overflow : e);
                  })
                  .error() == errc::overflow);
static_assert(half(7)
                  .transform_error([](errc e) {
                    return transfer_error{e, 0x0604'0041U};
                  })
                  .error()
                  .abort == 0x0604'0041U);
static_assert(half(8).transform_error([](errc e) { return transfer_error{e}; }).value() == 4);
static_assert(
    std::is_same_v<decltype(half(8).transform_error([](errc e) { return transfer_error{e}; })),
                   result<int, transfer_error>>);
// transform to void
static_assert(std::is_same_v<decltype(half(8).transform([](int) {})), status>);
static_assert(half(8).transform([](int) {}).has_value());
static_assert(half(7).transform([](int) {}) == errc::bad_digit);

// ---- the layout firmware depends on ------------------------------------------------------------
template <class R>
constexpr bool plain_v =
    std::conjunction_v<std::is_trivially_copyable<R>, std::is_trivially_destructible<R>>;
static_assert(plain_v<result<int>>);
static_assert(plain_v<result<bool>>);
static_assert(plain_v<result<std::int64_t>>);
static_assert(plain_v<result<std::array<std::uint8_t, 4>>>);
static_assert(plain_v<result<fieldcodec::decimal>>);
static_assert(plain_v<result<const int *>>);
static_assert(plain_v<result<std::string_view>>);
static_assert(plain_v<result<no_default>>);
static_assert(plain_v<status>);
static_assert(plain_v<result<int, transfer_error>>);
static_assert(plain_v<result<void, transfer_error>>);
static_assert(plain_v<result<no_default, transfer_error>>);
// Value and error side by side, then the flag (the layout of the first result<T>: GCC keeps
// the code of every encoder and decoder as it was, see result.hpp).
static_assert(sizeof(status) == 2);
static_assert(sizeof(result<std::uint8_t>) == 3);
static_assert(sizeof(result<std::array<std::uint8_t, 4>>) == 6);
static_assert(sizeof(result<std::int64_t>) == 24);
static_assert(sizeof(result<no_default>) == 8); // union of int and errc, plus the flag
static_assert(result<no_default>(no_default{3}) == result<no_default>(no_default{3}));
static_assert(result<no_default>(no_default{3}).value().v == 3);
static_assert(result<no_default>(errc::timeout).is(errc::timeout));

// Owning types: not trivial, but copyable and movable as their value is.
static_assert(!std::is_trivially_destructible_v<result<std::vector<std::uint8_t>>>);
static_assert(std::is_copy_constructible_v<result<std::vector<std::uint8_t>>>);
static_assert(std::is_copy_assignable_v<result<std::string>>);
static_assert(std::is_nothrow_move_constructible_v<result<std::string>>);
static_assert(std::is_nothrow_move_assignable_v<result<std::vector<std::uint8_t>>>);
static_assert(!std::is_copy_constructible_v<result<std::unique_ptr<int>>>);
static_assert(!std::is_copy_assignable_v<result<std::unique_ptr<int>>>);
static_assert(std::is_move_constructible_v<result<std::unique_ptr<int>>>);
static_assert(std::is_move_assignable_v<result<std::unique_ptr<int>>>);
static_assert(!std::is_copy_constructible_v<result<int, std::unique_ptr<int>>>);
static_assert(std::is_move_constructible_v<result<void, std::unique_ptr<int>>>);
static_assert(!std::is_copy_constructible_v<result<void, std::unique_ptr<int>>>);

// Construction: values and errors are told apart by type, never by guessing.
static_assert(std::is_convertible_v<errc, result<int>>);
static_assert(std::is_convertible_v<int, result<int>>);
static_assert(std::is_convertible_v<const char *, result<std::string>>);
static_assert(!std::is_convertible_v<std::string_view, result<std::string>>); // explicit in T
static_assert(std::is_constructible_v<result<std::string>, std::string_view>);
static_assert(std::is_convertible_v<errc, result<int, node_error>>); // via node_error(errc)
static_assert(!std::is_convertible_v<errc, result<int, transfer_error>>);
static_assert(std::is_convertible_v<transfer_error, result<int, transfer_error>>);
static_assert(std::is_convertible_v<errc, result<void, node_error>>);

// is() and == errc exist where the error carries an errc, and only there.
static_assert(fieldcodec::carries_errc<errc>);
static_assert(fieldcodec::carries_errc<transfer_error>);
static_assert(fieldcodec::carries_errc<node_error>);
static_assert(!fieldcodec::carries_errc<text_error>);
static_assert(!fieldcodec::carries_errc<int>);
template <class R>
concept has_is = requires(const R &r) {
  r.is(errc::timeout);
};
static_assert(has_is<result<int>>);
static_assert(has_is<result<int, transfer_error>>);
static_assert(has_is<result<void, transfer_error>>);
static_assert(!has_is<result<int, text_error>>);
static_assert(!has_is<result<void, text_error>>);
static_assert(fieldcodec::errc_of(transfer_error{errc::aborted, 1}) == errc::aborted);
static_assert(fieldcodec::errc_of(errc::timeout) == errc::timeout);

namespace {
constexpr result<int, transfer_error> read_object(std::uint16_t index) {
  if (index == 0x1018) return 0x1234;
  return transfer_error{errc::aborted, 0x0602'0000U, index, 0};
}
} // namespace
static_assert(read_object(0x1018) == 0x1234);
static_assert(read_object(0x2000).is(errc::aborted));
static_assert(read_object(0x2000) == errc::aborted);
static_assert(read_object(0x2000) != errc::timeout);
static_assert(read_object(0x2000).error().abort == 0x0602'0000U);
static_assert(read_object(0x2000).error().index == 0x2000);
static_assert(read_object(0x2000) ==
              result<int, transfer_error>(transfer_error{errc::aborted, 0x0602'0000U, 0x2000, 0}));
static_assert(read_object(0x2000) !=
              result<int, transfer_error>(transfer_error{errc::aborted, 0x0602'0001U, 0x2000, 0}));

// ---- comparison never converts into a result ----------------------------------------------------
namespace {
/// Holds the left side of a comparison, as a test framework's expression decomposer does
/// (doctest's Expression_lhs): the result becomes an associated class of the wrapper.
template <class R>
struct lhs_wrapper {
  const R &lhs;
  template <class X>
  constexpr bool operator==(const X &x) const {
    return lhs == x;
  }
};
template <class A, class B>
concept equality_with = requires(const A &a, const B &b) {
  a == b;
};
} // namespace
static_assert(lhs_wrapper<result<long>>{result<long>(5)} == result<long>(5));
static_assert(lhs_wrapper<result<long>>{result<long>(5)} == 5L);
static_assert(lhs_wrapper<result<long>>{result<long>(errc::timeout)} == errc::timeout);
/// Only names a result as a template argument (so result's friends are found by lookup).
template <class R>
struct tag_of {};
// A plain long is never turned into a result<long> to be compared (through such a conversion,
// a long compared with the wrapper above recursed forever under clang).
static_assert(!equality_with<long, tag_of<result<long>>>);
static_assert(!equality_with<tag_of<result<long>>, long>);
static_assert(!equality_with<long, errc>);
static_assert(5 == half(10)); // reversed value comparison
static_assert(equality_with<result<int>, int>);
static_assert(!equality_with<result<int>, result<long>>); // different results do not compare
static_assert(!equality_with<result<int, text_error>, errc>);

// ---- reading the wrong side does not compile in a constant expression ---------------------------
template <int N>
struct probe {};
template <int V>
constexpr bool value_is_constant() {
  return requires { typename probe<half(V).value()>; };
}
template <int V>
constexpr bool error_is_constant() {
  return requires { typename probe<static_cast<int>(half(V).error())>; };
}
static_assert(value_is_constant<8>());
static_assert(!value_is_constant<7>());
static_assert(error_is_constant<7>());
static_assert(!error_is_constant<8>());
template <int V>
constexpr bool status_value_is_constant() {
  return requires { typename probe<((V == 0 ? status{} : status{errc::timeout}).value(), 1)>; };
}
static_assert(status_value_is_constant<0>());
static_assert(!status_value_is_constant<1>());

// ---- owning types in constant expressions ------------------------------------------------------
namespace {
/// A non-trivial type that counts its live copies in a counter it points to.
class tracked {
public:
  constexpr tracked(int *live, int v) : live_(live), v_(v) { ++*live_; }
  constexpr tracked(const tracked &o) : live_(o.live_), v_(o.v_) { ++*live_; }
  constexpr tracked(tracked &&o) noexcept : live_(o.live_), v_(o.v_) { ++*live_; }
  constexpr tracked &operator=(const tracked &o) {
    v_ = o.v_;
    return *this;
  }
  constexpr tracked &operator=(tracked &&o) noexcept {
    v_ = o.v_;
    return *this;
  }
  constexpr ~tracked() { --*live_; }
  [[nodiscard]] constexpr int get() const { return v_; }

private:
  int *live_;
  int v_;
};

constexpr bool owning_lifetimes() {
  int live = 0;
  {
    result<tracked> a(std::in_place, &live, 7);
    result<tracked> b = a;             // copy of a value
    result<tracked> c = std::move(a);  // move of a value
    result<tracked> d = errc::timeout; // an error holds no tracked
    result<tracked> e = d;             // copy of an error
    if (live != 3) return false;       // a, b, c
    b = c;                             // value to value
    d = e;                             // error to error
    if (live != 3 || b.value().get() != 7 || !d.is(errc::timeout)) return false;
    const int moved = std::move(c).value().get(); // moved out of a temporary
    if (moved != 7) return false;
    auto t = b.transform([](const tracked &x) { return x.get() + 1; });
    if (t.value() != 8 || !e.transform([](const tracked &x) { return x.get(); }).is(errc::timeout))
      return false;
    result<int, tracked> err(fieldcodec::unexpect, &live, 3); // an owning error
    if (live != 4 || err.error().get() != 3) return false;
  }
  return live == 0; // everything constructed was destroyed
}
} // namespace
static_assert(owning_lifetimes());

// ---- run time ----------------------------------------------------------------------------------
TEST_CASE("result holds a value or an error") {
  auto ok = half(10);
  REQUIRE(ok);
  CHECK(*ok == 5);
  CHECK(ok.value() == 5);
  CHECK_FALSE(ok.is(errc::bad_digit));
  *ok = 6; // a mutable value
  CHECK(ok.value() == 6);

  auto bad = half(3);
  REQUIRE_FALSE(bad);
  CHECK(bad.error() == errc::bad_digit);
  CHECK(bad.value_or(99) == 99);
  CHECK(bad != result<int>(errc::truncated));
  bad = 4; // assign a value over an error
  CHECK(bad == 4);
  bad = errc::overflow;
  CHECK(bad.is(errc::overflow));
}

TEST_CASE("every errc has a distinct, stable text") {
  std::set<std::string_view> texts;
  for (int v = 1; v <= static_cast<int>(errc::bad_character); ++v) {
    const auto e = static_cast<errc>(v);
    const auto t = fieldcodec::to_string(e);
    CHECK(t != "unknown error");
    CHECK(texts.insert(t).second);
  }
  // The texts are part of the interface: spot-check that they do not change.
  CHECK(fieldcodec::to_string(errc::truncated) == "truncated input");
  CHECK(fieldcodec::to_string(errc::bad_checksum) == "bad checksum");
  CHECK(fieldcodec::to_string(errc::overflow) == "value does not fit the field");
  CHECK(fieldcodec::to_string(errc{}) == "unknown error"); // 0 is not an error
  // The numeric values are stable too.
  CHECK(static_cast<int>(errc::truncated) == 1);
  CHECK(static_cast<int>(errc::bad_checksum) == 5);
  CHECK(static_cast<int>(errc::bad_character) == 22);
}

TEST_CASE("an error with context travels whole and answers is(errc)") {
  const auto r = read_object(0x6041);
  REQUIRE_FALSE(r);
  CHECK(r.is(errc::aborted));
  CHECK(r == errc::aborted);
  CHECK(r.error() == transfer_error{errc::aborted, 0x0602'0000U, 0x6041, 0});
  CHECK(fieldcodec::errc_of(r.error()) == errc::aborted);
  // map the context away where a caller only wants the errc
  const result<int> plain = r.transform_error([](const transfer_error &e) { return e.code; });
  CHECK(plain.is(errc::aborted));
  // or add context to a plain error
  const result<int, transfer_error> ctx = half(3).transform_error([](errc e) {
    return transfer_error{e, 0, 0x2000, 1};
  });
  CHECK(ctx.error().index == 0x2000);
  CHECK(ctx.error().sub == 1);

  result<void, transfer_error> done{};
  CHECK(done.has_value());
  done = transfer_error{errc::timeout, 0x0504'0000U};
  CHECK(done.is(errc::timeout));
  CHECK(done.error().abort == 0x0504'0000U);
}

TEST_CASE("an error without an errc still works") {
  result<int, text_error> r = text_error{"no"};
  REQUIRE_FALSE(r);
  CHECK(std::string_view(r.error().text) == "no");
  r = 5;
  CHECK(r.value() == 5);
}

TEST_CASE("owning value types: vector, string, unique_ptr") {
  result<std::vector<std::uint8_t>> bytes = std::vector<std::uint8_t>{1, 2, 3};
  REQUIRE(bytes);
  CHECK(bytes->size() == 3);
  bytes->push_back(4); // operator-> on a mutable result
  CHECK(bytes.value() == std::vector<std::uint8_t>{1, 2, 3, 4});
  auto copy = bytes;
  CHECK(copy == bytes);
  auto moved = std::move(bytes);
  CHECK(moved.value().size() == 4);
  copy = errc::truncated; // value → error: the vector is destroyed (ASan/valgrind would see)
  CHECK(copy.is(errc::truncated));
  copy = moved; // error → value
  CHECK(copy.value().size() == 4);
  const std::vector<std::uint8_t> out = std::move(copy).value();
  CHECK(out.size() == 4);

  result<std::string> text = "hello";
  CHECK(text.value() == "hello");
  CHECK(text == std::string("hello"));
  CHECK(text.transform([](const std::string &s) { return s.size(); }).value() == 5U);
  result<std::string> none = errc::bad_syntax;
  CHECK(none.value_or("fallback") == "fallback");
  CHECK(std::move(none).value_or("x") == "x");
  const result<std::string> from_view(std::in_place, std::string_view("abc"));
  CHECK(*from_view == "abc");

  struct base {
    virtual ~base() = default;
    [[nodiscard]] virtual int id() const { return 1; }
  };
  struct derived : base {
    [[nodiscard]] int id() const override { return 2; }
  };
  result<std::unique_ptr<base>> p = std::make_unique<derived>();
  REQUIRE(p);
  CHECK(p.value()->id() == 2);
  auto q = std::move(p);
  CHECK(q.value()->id() == 2);
  result<std::unique_ptr<base>> r = errc::unknown_object;
  r = std::move(q); // error → value, move only
  CHECK(r.value()->id() == 2);
  std::unique_ptr<base> taken = std::move(r).value_or(nullptr);
  CHECK(taken->id() == 2);
  result<std::unique_ptr<base>> e = errc::timeout;
  CHECK(std::move(e).value_or(nullptr) == nullptr);

  const result<std::vector<int>, std::string> both_owning(fieldcodec::unexpect, "why");
  CHECK(both_owning.error() == "why");
}

namespace {
int g_live = 0;
/// Counts live objects; its copy throws when asked to (the copy that switches a result).
struct fragile {
  static inline bool throw_on_copy = false;
  int v = 0;
  explicit fragile(int x) : v(x) { ++g_live; }
  fragile(const fragile &o) : v(o.v) {
    if (throw_on_copy) throw std::runtime_error("copy");
    ++g_live;
  }
  fragile(fragile &&o) noexcept : v(o.v) { ++g_live; }
  fragile &operator=(const fragile &) = default;
  fragile &operator=(fragile &&) noexcept = default;
  ~fragile() { --g_live; }
};
} // namespace

TEST_CASE("owning results construct and destroy exactly once, also when a copy throws") {
  g_live = 0;
  {
    result<fragile> a(std::in_place, 1);
    result<fragile> b = errc::timeout;
    CHECK(g_live == 1);
    b = a; // error → value: one more
    CHECK(g_live == 2);
    a = errc::bad_state; // value → error: one less
    CHECK(g_live == 1);
    auto &same = b;
    b = same; // self-assignment keeps the value
    CHECK(b.value().v == 1);
    CHECK(g_live == 1);
    result<fragile> c(std::in_place, 3);
    fragile::throw_on_copy = true;
    CHECK_THROWS_AS(a = c, std::runtime_error); // error → value, the copy throws
    fragile::throw_on_copy = false;
    CHECK(a.is(errc::bad_state)); // unchanged
    CHECK(g_live == 2);
  }
  CHECK(g_live == 0);
}

namespace {
constexpr result<int> quarter(int v) {
  FIELDCODEC_TRY(const int h, half(v));
  FIELDCODEC_TRY(int q, half(h));
  return q;
}
fieldcodec::status forward(bool fail) {
  FIELDCODEC_TRY_STATUS(fail ? status{errc::timeout} : status{});
  return {};
}
result<std::size_t, node_error> length_of(result<std::string> s) {
  FIELDCODEC_TRY(const std::string text, std::move(s)); // errc → node_error on the way out
  return text.size();
}
result<std::unique_ptr<int>> boxed(int v) {
  if (v < 0) return errc::out_of_range;
  return std::make_unique<int>(v);
}
result<int> unbox(int v) {
  FIELDCODEC_TRY(auto p, boxed(v)); // move-only values move out
  return *p;
}
} // namespace
static_assert(quarter(8) == 2);
static_assert(quarter(6) == errc::bad_digit);
static_assert(quarter(7) == errc::bad_digit);

TEST_CASE("FIELDCODEC_TRY and FIELDCODEC_TRY_STATUS propagate the error") {
  CHECK(forward(false).has_value());
  CHECK(forward(true).is(errc::timeout));
  CHECK(quarter(12) == 3);
  CHECK(quarter(10).is(errc::bad_digit));
  CHECK(length_of(std::string("abcd")) == std::size_t{4});
  const auto failed = length_of(errc::bad_syntax);
  REQUIRE_FALSE(failed);
  CHECK(failed.error() == node_error{errc::bad_syntax});
  CHECK(unbox(5) == 5);
  CHECK(unbox(-1).is(errc::out_of_range));
}

TEST_CASE("monadic operations on status and on results with context") {
  int calls = 0;
  const status ok{};
  const status bad{errc::timeout};
  CHECK(ok.and_then([&] {
            ++calls;
            return status{errc::bad_state};
          }).is(errc::bad_state));
  CHECK(bad.and_then([&] {
             ++calls;
             return status{};
           })
            .is(errc::timeout));
  CHECK(calls == 1); // not called on an error
  CHECK(ok.transform([] { return 5; }) == 5);
  CHECK(bad.transform([] { return 5; }).is(errc::timeout));
  CHECK(bad.or_else([](errc) { return status{}; }).has_value());
  CHECK(ok.or_else([](errc e) { return status{e}; }).has_value());
  const auto with_node = bad.transform_error([](errc e) { return node_error{e, 5}; });
  CHECK(with_node.error().node == 5);
  CHECK(with_node.is(errc::timeout));
  CHECK(ok.transform_error([](errc e) { return node_error{e, 5}; }).has_value());
  ok.value(); // success: nothing happens
  *ok;
}

#if defined(__unix__)
namespace {
/// Runs `f` in a child process; true when the child was killed by a signal (the trap).
template <class F>
bool dies(F f) {
  const pid_t pid = fork();
  if (pid == 0) {
    // the test runner catches crashes: give the trap its default effect in the child
    (void)std::signal(SIGILL, SIG_DFL);
    (void)std::signal(SIGTRAP, SIG_DFL);
    f();
    _exit(0);
  }
  int st = 0;
  waitpid(pid, &st, 0);
  return WIFSIGNALED(st);
}
} // namespace

TEST_CASE("reading the value of an error or the error of a value traps at run time") {
  CHECK(dies([] { (void)half(3).value(); }));
  CHECK(dies([] { (void)half(4).error(); }));
  CHECK(dies([] { status{errc::timeout}.value(); }));
  CHECK(dies([] { (void)status{}.error(); }));
  CHECK(dies([] { (void)result<std::string>(errc::timeout).value(); }));
  CHECK(dies([] { (void)*read_object(1); }));
  CHECK_FALSE(dies([] { (void)half(4).value(); })); // the harness itself does not kill
}
#endif
