#pragma once
// The values that cross between a graded test (the judge) and a student's program, as bytes.
//
// Both ends are built by the same compiler on the same machine, so numbers travel in their own
// representation (no text, no rounding: a double arrives bit for bit). There are no type tags:
// each end reads what the entry point's signature says it must find. What the judge reads came
// from a student's process, so every read is checked: a length is compared with the bytes left
// before anything is allocated, an Eigen matrix's shape with its type's, a sparse entry's
// indices with its matrix's size. A message that breaks any of these is a ProtocolError, and
// the graded case that made the call fails.
//
// What travels: arithmetic types, enums, bools, std::complex, std::string, std::vector (any
// allocator), std::array, std::optional, Eigen dense matrices, Eigen sparse matrices,
// quaternions, and any struct for which `fields(T&)`, found by argument-dependent lookup,
// returns a std::tie of its members (kit_fields.hpp).
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include <array>
#include <complex>
#include <cstdint>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace kit::remote {

/// A message that is not what the signature says: the student's side answered out of turn.
struct ProtocolError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Bytes being written, one value after another.
class Writer {
 public:
  void raw(const void* data, std::size_t size) {
    // resize and copy, not insert: GCC 12 warns (-Wstringop-overflow) on a range insert it
    // cannot size, and CI builds with -Werror.
    const std::size_t at = buffer_.size();
    buffer_.resize(at + size);
    if (size > 0) std::memcpy(buffer_.data() + at, data, size);
  }
  template <class T>
  void scalar(T value) {
    static_assert(std::is_trivially_copyable_v<T>);
    raw(&value, sizeof value);
  }
  std::vector<unsigned char>& bytes() { return buffer_; }

 private:
  std::vector<unsigned char> buffer_;
};

/// Bytes being read back, each read checked against what is left.
class Reader {
 public:
  Reader(const unsigned char* data, std::size_t size) : data_(data), left_(size) {}
  void raw(void* out, std::size_t size) {
    need(size);
    if (size == 0) return;  // an empty vector's data() may be null, and memcpy must not see it
    std::memcpy(out, data_, size);
    data_ += size;
    left_ -= size;
  }
  template <class T>
  T scalar() {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    raw(&value, sizeof value);
    return value;
  }
  /// A count of `element_size`-byte items that must all still fit in the message.
  std::size_t count(std::size_t element_size) {
    const auto n = scalar<std::uint64_t>();
    if (element_size > 0 && n > left_ / element_size) throw ProtocolError("a length longer than its message");
    return std::size_t(n);
  }
  std::size_t left() const { return left_; }

 private:
  void need(std::size_t size) const {
    if (size > left_) throw ProtocolError("a message shorter than its values");
  }
  const unsigned char* data_;
  std::size_t left_;
};

// --- the encoding, type by type ----------------------------------------------------------------
template <class T>
struct Codec;  // specialised below; `put`/`get` dispatch to it

template <class T>
void put(Writer& w, const T& value) {
  Codec<std::remove_cv_t<T>>::put(w, value);
}
template <class T>
void get(Reader& r, T& value) {
  Codec<std::remove_cv_t<T>>::get(r, value);
}
template <class T>
T get(Reader& r) {
  T value{};
  get(r, value);
  return value;
}

template <class T, class = void>
struct has_fields : std::false_type {};
template <class T>
struct has_fields<T, std::void_t<decltype(fields(std::declval<T&>()))>> : std::true_type {};

template <class T>
struct Codec {
  static void put(Writer& w, const T& value) {
    if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) {
      w.scalar(value);
    } else {
      static_assert(has_fields<T>::value, "no fields(T&) for this type: add one to kit_fields.hpp");
      std::apply([&](const auto&... member) { (remote::put(w, member), ...); },
                 fields(const_cast<T&>(value)));
    }
  }
  static void get(Reader& r, T& value) {
    if constexpr (std::is_same_v<T, bool>) {
      const auto byte = r.scalar<unsigned char>();
      if (byte > 1) throw ProtocolError("a bool that is neither 0 nor 1");
      value = byte == 1;
    } else if constexpr (std::is_arithmetic_v<T>) {
      value = r.scalar<T>();
    } else if constexpr (std::is_enum_v<T>) {
      value = r.scalar<T>();  // every enum the kit sends is checked where it is used (a switch's default)
    } else {
      std::apply([&](auto&... member) { (remote::get(r, member), ...); }, fields(value));
    }
  }
};

template <class T>
struct Codec<std::complex<T>> {
  static void put(Writer& w, const std::complex<T>& z) { w.scalar(z.real()), w.scalar(z.imag()); }
  static void get(Reader& r, std::complex<T>& z) {
    const T re = r.scalar<T>();
    z = {re, r.scalar<T>()};
  }
};

template <>
struct Codec<std::string> {
  static void put(Writer& w, const std::string& s) {
    w.scalar(std::uint64_t(s.size()));
    w.raw(s.data(), s.size());
  }
  static void get(Reader& r, std::string& s) {
    s.resize(r.count(1));
    r.raw(s.data(), s.size());
  }
};

template <class T, class Allocator>
struct Codec<std::vector<T, Allocator>> {
  static void put(Writer& w, const std::vector<T, Allocator>& v) {
    w.scalar(std::uint64_t(v.size()));
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
      w.raw(v.data(), v.size() * sizeof(T));
    } else {
      for (const auto& item : v) remote::put(w, static_cast<const T&>(item));
    }
  }
  static void get(Reader& r, std::vector<T, Allocator>& v) {
    // Every item takes at least one byte of the message; other items are read one by one, so that
    // what is allocated grows with what was actually read, never with what a count claims.
    const std::size_t n = r.count(std::is_arithmetic_v<T> ? sizeof(T) : 1);
    if constexpr (std::is_arithmetic_v<T> && !std::is_same_v<T, bool>) {
      v.assign(n, T{});
      r.raw(v.data(), n * sizeof(T));
    } else {
      v.clear();
      for (std::size_t i = 0; i < n; ++i) {
        T item{};
        remote::get(r, item);
        v.push_back(std::move(item));
      }
    }
  }
};

template <class T, std::size_t N>
struct Codec<std::array<T, N>> {
  static void put(Writer& w, const std::array<T, N>& a) {
    for (const auto& item : a) remote::put(w, item);
  }
  static void get(Reader& r, std::array<T, N>& a) {
    for (auto& item : a) remote::get(r, item);
  }
};

template <class T>
struct Codec<std::optional<T>> {
  static void put(Writer& w, const std::optional<T>& o) {
    remote::put(w, o.has_value());
    if (o) remote::put(w, *o);
  }
  static void get(Reader& r, std::optional<T>& o) {
    if (remote::get<bool>(r)) {
      o.emplace();
      remote::get(r, *o);
    } else {
      o.reset();
    }
  }
};

template <class A, class B>
struct Codec<std::pair<A, B>> {
  static void put(Writer& w, const std::pair<A, B>& p) { remote::put(w, p.first), remote::put(w, p.second); }
  static void get(Reader& r, std::pair<A, B>& p) { remote::get(r, p.first), remote::get(r, p.second); }
};

/// Dense matrices: rows, columns, then the coefficients in column order. A fixed dimension must
/// arrive as it is.
template <class S, int R, int C, int O, int MR, int MC>
struct Codec<Eigen::Matrix<S, R, C, O, MR, MC>> {
  using M = Eigen::Matrix<S, R, C, O, MR, MC>;
  static void put(Writer& w, const M& m) {
    w.scalar(std::int64_t(m.rows())), w.scalar(std::int64_t(m.cols()));
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      for (Eigen::Index i = 0; i < m.rows(); ++i) w.scalar(m(i, j));
  }
  static void get(Reader& r, M& m) {
    const auto rows = r.scalar<std::int64_t>(), cols = r.scalar<std::int64_t>();
    if (rows < 0 || cols < 0 || (R != Eigen::Dynamic && rows != R) || (C != Eigen::Dynamic && cols != C))
      throw ProtocolError("a matrix of the wrong shape");
    if (cols > 0 && std::uint64_t(rows) > r.left() / sizeof(S) / std::uint64_t(cols))
      throw ProtocolError("a matrix larger than its message");
    if (rows > (std::int64_t(1) << 31) || cols > (std::int64_t(1) << 31))
      throw ProtocolError("a matrix of an impossible size");  // 0 × 2^60 holds no number but loops
    m.resize(rows, cols);
    if (rows == 0) return;
    for (Eigen::Index j = 0; j < cols; ++j)
      for (Eigen::Index i = 0; i < rows; ++i) m(i, j) = r.scalar<S>();
  }
};

template <class S, int O>
struct Codec<Eigen::Quaternion<S, O>> {
  static void put(Writer& w, const Eigen::Quaternion<S, O>& q) {
    remote::put(w, Eigen::Matrix<S, 4, 1>(q.coeffs()));
  }
  static void get(Reader& r, Eigen::Quaternion<S, O>& q) {
    q.coeffs() = remote::get<Eigen::Matrix<S, 4, 1>>(r);
  }
};

/// Sparse matrices: the size, then every stored entry as (row, column, value); an entry outside
/// the matrix, or the same one twice, is refused.
template <class S, int O, class I>
struct Codec<Eigen::SparseMatrix<S, O, I>> {
  using M = Eigen::SparseMatrix<S, O, I>;
  static void put(Writer& w, const M& m) {
    w.scalar(std::int64_t(m.rows())), w.scalar(std::int64_t(m.cols())), w.scalar(std::uint64_t(m.nonZeros()));
    for (Eigen::Index k = 0; k < m.outerSize(); ++k)
      for (typename M::InnerIterator it(m, k); it; ++it)
        w.scalar(std::int64_t(it.row())), w.scalar(std::int64_t(it.col())), w.scalar(it.value());
  }
  static void get(Reader& r, M& m) {
    const auto rows = r.scalar<std::int64_t>(), cols = r.scalar<std::int64_t>();
    // Its index arrays take 4 bytes a row or column, entries or not: 2^24 keeps them under 64 MiB
    // (the largest the kit sends has 3·81² = 19 683 rows).
    if (rows < 0 || cols < 0 || rows > (std::int64_t(1) << 24) || cols > (std::int64_t(1) << 24))
      throw ProtocolError("a sparse matrix of an impossible size");
    const std::size_t n = r.count(2 * sizeof(std::int64_t) + sizeof(S));
    std::vector<Eigen::Triplet<S, I>> entries;
    entries.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
      const auto i = r.scalar<std::int64_t>(), j = r.scalar<std::int64_t>();
      const S value = r.scalar<S>();
      if (i < 0 || j < 0 || i >= rows || j >= cols) throw ProtocolError("a sparse entry outside its matrix");
      entries.emplace_back(I(i), I(j), value);
    }
    m.resize(Eigen::Index(rows), Eigen::Index(cols));
    m.setFromTriplets(entries.begin(), entries.end(),
                      [](const S&, const S&) -> S { throw ProtocolError("a sparse entry stored twice"); });
    m.makeCompressed();
  }
};

}  // namespace kit::remote

namespace kit::remote {

/// The part of an entry point's name that tells one instantiation of a template from another,
/// the same on both sides: "2x1d" for a 2-vector of double, "3x1f" for one of float.
template <class T>
struct TypeKey;
template <class S, int R, int C, int O, int MR, int MC>
struct TypeKey<Eigen::Matrix<S, R, C, O, MR, MC>> {
  static std::string text() {
    const char* scalar = std::is_same_v<S, float> ? "f" : std::is_same_v<S, double> ? "d" : "e";
    return (R == Eigen::Dynamic ? std::string("X") : std::to_string(R)) + "x" +
           (C == Eigen::Dynamic ? std::string("X") : std::to_string(C)) + scalar;
  }
};
template <class T>
std::string key() {
  return TypeKey<std::remove_cv_t<std::remove_reference_t<T>>>::text();
}

}  // namespace kit::remote
