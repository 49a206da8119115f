#pragma once
// The judge's end: a graded test calls the student's function through `call`, in a program
// built from the kit's sources alone. The student's code runs in a process of its own
// (student.hpp) and only returns values; every check is made here, on those values.
//
// The stubs in tests/grading/stubs/ give each exercise's functions their usual names and
// signatures, so a graded test reads as it always did: `kit::rk4_step(f, t, u, dt)` sends
// (f, t, u, dt) and returns what the student's rk4_step returned. A function argument such as
// f crosses as a callback: the student's program asks for f(t, u) and the judge computes it
// here, so what f counts and records is counted by the judge.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "link.hpp"
#include "signature.hpp"

namespace kit::remote {

/// The link to the student's program: the descriptors in KIT_STUDENT_FDS ("in,out", set by the
/// grader, which starts the program in its sandbox), or else a program KIT_STUDENT_PROGRAM
/// names, started here (ctest, with the kit's own solutions).
Link& judge_link();

/// An argument the student's function may change: its new value is copied back after the call.
template <class T>
struct Inout {
  T* value;
};
template <class T>
Inout<T> inout(T& value) {
  return {&value};
}

/// An argument sent as `sent` whose new value is read into `received` (another object), for a
/// stub that must compare the two.
template <class T>
struct Replaced {
  const T* sent;
  T* received;
};
template <class T>
Replaced<T> replaced(const T& sent, T& received) {
  return {&sent, &received};
}

/// A function handed to the student's code, with the signature the student's side calls it by.
template <class Sig, class F>
struct CallbackArg {
  const F* f;
};
template <class Sig, class F>
CallbackArg<Sig, F> callback(const F& f) {
  return {&f};
}

using Handler = std::function<void(Reader&, Writer&)>;

namespace detail {
template <class Sig>
struct CallbackSignature;
template <class R, class... P>
struct CallbackSignature<R(P...)> {
  template <class F>
  static Handler handler(const F& f) {
    return [&f](Reader& r, Writer& w) { invoke_from<R, P...>(r, w, f); };
  }
};

template <class T>
void put_arg(Writer& w, std::vector<Handler>&, const T& value) {
  put(w, value);
}
template <class T>
void put_arg(Writer& w, std::vector<Handler>&, const Inout<T>& value) {
  put(w, *value.value);
}
template <class T>
void put_arg(Writer& w, std::vector<Handler>&, const Replaced<T>& value) {
  put(w, *value.sent);
}
template <class Sig, class F>
void put_arg(Writer& w, std::vector<Handler>& handlers, const CallbackArg<Sig, F>& callback) {
  put(w, std::uint32_t(handlers.size()));
  handlers.push_back(CallbackSignature<Sig>::handler(*callback.f));
}

template <class T>
void get_back(Reader&, const T&) {}
template <class T>
void get_back(Reader& r, const Inout<T>& value) {
  get(r, *value.value);
}

template <class T>
void get_back(Reader& r, const Replaced<T>& value) {
  get(r, *value.received);
}

/// Sends the call and serves callbacks until the result or an error arrives.
Message exchange(const std::string& name, Writer& arguments, const std::vector<Handler>& handlers);
}  // namespace detail

/// Calls the student's entry point `name` with `args` and returns its result of type R.
template <class R, class... A>
R call(const std::string& name, const A&... args) {
  Writer w;
  put(w, name);
  std::vector<Handler> handlers;
  (detail::put_arg(w, handlers, args), ...);
  const Message answer = detail::exchange(name, w, handlers);
  Reader r = answer.reader();
  if constexpr (std::is_void_v<R>) {
    (detail::get_back(r, args), ...);
    if (r.left() != 0) throw ProtocolError(name + ": an answer longer than its signature");
  } else {
    R result = get<R>(r);
    (detail::get_back(r, args), ...);
    if (r.left() != 0) throw ProtocolError(name + ": an answer longer than its signature");
    return result;
  }
}

/// The judge's handle on an object the student's program keeps (a stepper built once, stepped
/// many times): made by the entry NAME/new, stepped by NAME/step (student.hpp: add_stepper).
template <class State>
class RemoteStepper {
 public:
  template <class... Args>
  explicit RemoteStepper(std::string name, const Args&... args)
      : name_(std::move(name)), id_(call<long>(name_ + "/new", args...)) {}
  State step(const State& u) const { return call<State>(name_ + "/step", id_, u); }

 private:
  std::string name_;
  long id_;
};

/// A one-step method's call, step(f, t, u, dt) → u_{k+1} (explicit Euler, midpoint, RK4): f, the
/// right-hand side f(t, u), crosses as a callback. The entry is "METHOD/" + key<State>().
template <class State, class Rhs>
State call_one_step(const std::string& method, const Rhs& f, typename State::Scalar t, const State& u,
                    typename State::Scalar dt) {
  using S = typename State::Scalar;
  return call<State>(method + "/" + key<State>(), callback<State(S, const State&)>(f), t, u, dt);
}

/// n steps x ← name(x, rest…) from x0, run in the student's program (harness: add_iterable):
/// every state x_1 … x_n, or only the last (x0 when n = 0). A million calls across the pipe
/// take about ten seconds; one call, milliseconds.
template <class R, class... A>
std::vector<R> iterate(const std::string& name, long n, const R& x0, const A&... rest) {
  return call<std::vector<R>>(name + "/states", n, x0, rest...);
}
template <class R, class... A>
R iterated(const std::string& name, long n, const R& x0, const A&... rest) {
  return call<R>(name + "/last", n, x0, rest...);
}

}  // namespace kit::remote
