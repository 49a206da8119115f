#pragma once
// The student's end: a small program made of the student's exercise file, the kit headers that
// exercise may use, one harness (tests/grading/harness/) and student_main.cpp. It reads calls on
// descriptor 3 (or the first that KIT_JUDGE_FDS names, as the grader sets it), runs the student's
// function, and writes what it returned on descriptor 4 (or the second). It judges nothing:
// whatever it writes is only a value for the judge to check.
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "link.hpp"
#include "signature.hpp"

namespace kit::remote {

/// The link to the judge (descriptors 3 and 4).
Link& student_link();

/// A function the judge handed over: calling it asks the judge to compute it.
template <class Sig>
class Callback;
template <class R, class... P>
class Callback<R(P...)> {
 public:
  R operator()(P... args) const {
    Writer w;
    put(w, id_);
    (put(w, static_cast<const Value<P>&>(args)), ...);
    Link& link = student_link();
    link.send(Kind::callback, w.bytes());
    const Message m = link.receive();
    Reader r = m.reader();
    if (m.kind == Kind::callback_error) rethrow(r);
    if (m.kind != Kind::callback_result) throw ProtocolError("the judge answered a callback out of turn");
    if constexpr (std::is_void_v<R>) {
      (take_back<P>(r, args), ...);
    } else {
      R result = get<R>(r);
      (take_back<P>(r, args), ...);
      return result;
    }
  }
  std::uint32_t id_ = 0;

 private:
  template <class Q, class A>
  static void take_back(Reader& r, A& arg) {
    if constexpr (is_out<Q>) get(r, arg);
  }
};

template <class Sig>
struct Codec<Callback<Sig>> {
  static void put(Writer& w, const Callback<Sig>& c) { w.scalar(c.id_); }
  static void get(Reader& r, Callback<Sig>& c) { c.id_ = r.scalar<std::uint32_t>(); }
};

/// The NAME/states and NAME/last entries of Entries::add_iterable.
struct Iterate {
  template <class R, class First, class... Rest, class E, class F>
  static void add(E& entries, const std::string& name, F f) {
    static_assert(std::is_same_v<Value<First>, R>,
                  "an iterable step takes its state first and returns the next");
    const auto steps = [](long n) {
      if (n < 0 || n > 10'000'000) throw std::invalid_argument("steps out of range [0, 1e7]");
      return n;
    };
    entries.add(name + "/states", [f, steps](long n, const R& x0, const Value<Rest>&... rest) {
      std::vector<R> states;
      states.reserve(std::size_t(steps(n)));
      R x = x0;
      for (long k = 0; k < n; ++k) states.push_back(x = f(x, rest...));
      return states;
    });
    entries.add(name + "/last", [f, steps](long n, const R& x0, const Value<Rest>&... rest) {
      R x = x0;
      for (long k = steps(n); k > 0; --k) x = f(x, rest...);
      return x;
    });
  }
};

/// The entry points a harness offers, by name.
class Entries {
 public:
  template <class F>
  void add(const std::string& name, F f) {
    table_[name] = [f](Reader& r, Writer& w) { CallTraits<F>::invoke(r, w, f); };
  }
  /// For a step x ← f(x, rest…): also NAME/states (n steps, every state) and NAME/last (n steps,
  /// the last state), so that a long run is one call across the pipe, not n.
  template <class F>
  void add_iterable(const std::string& name, F f) {
    add(name, f);
    CallTraits<F>::template with_parameters<Iterate>(*this, name, f);
  }
  const std::function<void(Reader&, Writer&)>* find(const std::string& name) const {
    const auto it = table_.find(name);
    return it == table_.end() ? nullptr : &it->second;
  }

 private:
  std::map<std::string, std::function<void(Reader&, Writer&)>> table_;
};

/// Objects the judge made through a constructor entry point and names by number afterwards.
template <class T>
class Objects {
 public:
  long keep(std::unique_ptr<T> object) {
    objects_.push_back(std::move(object));
    return long(objects_.size()) - 1;
  }
  T& at(long id) {
    if (id < 0 || id >= long(objects_.size())) throw std::out_of_range("no such object");
    return *objects_[std::size_t(id)];
  }

 private:
  std::vector<std::unique_ptr<T>> objects_;
};

/// The student's side of judge.hpp's RemoteStepper: a class T built by T(args…), stepped by
/// T::step(u), kept here and named by number.
template <class T, class State, class... Args>
void add_stepper(Entries& entries, const std::string& name) {
  static Objects<T> objects;
  entries.add(name + "/new", [](const Args&... args) { return objects.keep(std::make_unique<T>(args...)); });
  entries.add(name + "/step", [](long id, const State& u) -> State { return objects.at(id).step(u); });
}

/// The student's side of judge.hpp's call_one_step: `method` for each of the state types,
/// calling step(f, t, u, dt) with f a Callback.
template <class... States, class Step>
void add_one_step(Entries& entries, const std::string& method, Step step) {
  (entries.add(method + "/" + key<States>(),
               [step](Callback<States(typename States::Scalar, const States&)> f, typename States::Scalar t,
                      const States& u, typename States::Scalar dt) -> States { return step(f, t, u, dt); }),
   ...);
}

}  // namespace kit::remote

/// Each harness defines this: the entry points of its exercise file.
void register_entries(kit::remote::Entries& entries);
