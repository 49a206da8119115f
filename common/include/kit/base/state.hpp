#pragma once
// State vectors, work counters and trajectories shared by every chapter.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace kit {

/// Storage options for fixed-size states. Small fixed-size vectors are left unaligned, and
/// kit::common sets EIGEN_UNALIGNED_VECTORIZE=0, so Eigen keeps them in scalar registers:
/// packing (v, g) into an SSE register every step stalls store-to-load forwarding and made
/// an explicit Euler step on free fall 5.6× slower (6.5 ns against 1.2 ns). Dynamic-size
/// vectors (cloth) stay aligned and vectorised.
template <int N>
inline constexpr int small_state_options =
    (N == Eigen::Dynamic ? Eigen::AutoAlign : Eigen::DontAlign) | Eigen::ColMajor;

/// A state u of N components (N = Eigen::Dynamic for run-time sizes). For a particle,
/// u = (x, v): positions in m, velocities in m/s.
template <int N, class Scalar = double>
using Vec = Eigen::Matrix<Scalar, N, 1, small_state_options<N>>;

/// An N×N matrix, e.g. the A of u' = A u + b.
template <int N, class Scalar = double>
using Mat = Eigen::Matrix<Scalar, N, N, small_state_options<N>>;

using Vec2 = Vec<2>;
using Mat2 = Mat<2>;

/// What an integration cost. Tests compare these counts; timings live in benchmarks only.
struct Stats {
  long rhs_evals = 0;  ///< evaluations of the right-hand side f(t, u)
  long steps = 0;      ///< accepted steps
  long rejected = 0;   ///< rejected steps (adaptive methods only)
};

/// Wraps a right-hand side f(t, u) so that every call is counted in `count`.
template <class Rhs>
struct CountingRhs {
  const Rhs& f;
  long& count;
  template <class T, class State>
  auto operator()(T t, const State& u) const {
    ++count;
    return f(t, u);
  }
};

/// Where a run blew up: the first step whose state was not finite or exceeded the limit.
struct Divergence {
  long step = 0;         ///< k of the first bad state
  double t = 0;          ///< its time [s]
  double magnitude = 0;  ///< |u_k| (may be inf or NaN)
  /// "diverged at step k (t = … s), |u| = …", the words every chapter prints.
  std::string describe() const;
};

/// Samples (t_k, u_k) of one run, in time order. t in s. When the run diverged, it stops at
/// the last good state and `divergence` says where.
template <class State>
struct Trajectory {
  std::vector<double> t;
  std::vector<State> u;
  std::optional<Divergence> divergence;
  void push(double time, const State& state) {
    t.push_back(time);
    u.push_back(state);
  }
  std::size_t size() const { return t.size(); }
  /// Component i of every sample, e.g. component(0) = the positions x_k.
  std::vector<double> component(int i) const {
    std::vector<double> values;
    values.reserve(u.size());
    for (const auto& state : u) values.push_back(static_cast<double>(state[i]));
    return values;
  }
};

}  // namespace kit
