// genmesh/detail/branchless.h — conditions combined without a branch.
//
// all_true(a, b, ...) and any_true(a, b, ...) evaluate every condition and
// combine them with `&` / `|`: for hot tests whose outcome goes either way,
// where `&&` / `||` would compile to a branch per condition (and mispredict).
// Written as functions, not `&` between the comparisons themselves: Clang's
// -Wbitwise-instead-of-logical (in -Wall) takes that for a mistaken `&&`
// when an operand calls a function, as Eigen's accessors do.
#pragma once

namespace genmesh::detail {

template <class... B>
[[gnu::always_inline]] constexpr bool all_true(B... b) noexcept {
  return (... & static_cast<bool>(b));
}

template <class... B>
[[gnu::always_inline]] constexpr bool any_true(B... b) noexcept {
  return (... | static_cast<bool>(b));
}

} // namespace genmesh::detail
