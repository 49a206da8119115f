#pragma once
// What both ends do with a function's signature: read its arguments from a message, call it,
// and write back what it returned and every argument it was free to change (a non-const
// lvalue reference parameter: the particles an update kills, the positions a step moves).
#include <cstdint>
#include <functional>
#include <tuple>
#include <type_traits>
#include <utility>

#include "wire.hpp"

namespace kit::remote {

/// True for a parameter the callee may change, whose value therefore travels back.
template <class P>
inline constexpr bool is_out = std::is_lvalue_reference_v<P> && !std::is_const_v<std::remove_reference_t<P>>;

template <class P>
using Value = std::remove_cv_t<std::remove_reference_t<P>>;

/// Writes back, in order, every argument whose parameter is an out-parameter.
template <class... P, class Tuple, std::size_t... I>
void put_outs(Writer& w, const Tuple& values, std::index_sequence<I...>) {
  (
      [&] {
        if constexpr (is_out<P>) put(w, std::get<I>(values));
      }(),
      ...);
}

/// Reads arguments of types P..., calls `f` on them, writes the result and the out-arguments.
template <class R, class... P, class F>
void invoke_from(Reader& r, Writer& w, F&& f) {
  std::tuple<Value<P>...> values;
  std::apply([&](auto&... v) { (get(r, v), ...); }, values);
  if (r.left() != 0) throw ProtocolError("a call with more arguments than its signature");
  if constexpr (std::is_void_v<R>) {
    std::apply([&](auto&... v) { f(v...); }, values);
  } else {
    const R result = std::apply([&](auto&... v) -> R { return f(v...); }, values);
    put(w, result);
  }
  put_outs<P...>(w, values, std::index_sequence_for<P...>{});
}

/// The parameter list of a lambda or function object with one, non-template, call operator.
template <class T>
struct CallTraits : CallTraits<decltype(&T::operator())> {};
template <class C, class R, class... P>
struct CallTraits<R (C::*)(P...) const> {
  using Result = R;
  template <class F>
  static void invoke(Reader& r, Writer& w, F&& f) {
    invoke_from<R, P...>(r, w, std::forward<F>(f));
  }
  /// Calls Use::add<R, P...>(args…): a template that needs the signature spelled out.
  template <class Use, class... A>
  static void with_parameters(A&&... args) {
    Use::template add<R, P...>(std::forward<A>(args)...);
  }
};

}  // namespace kit::remote
