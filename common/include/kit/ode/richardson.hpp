#pragma once
// Richardson's extrapolation: from a quantity computed at three resolutions, each twice the
// last, the limit it converges to and the observed order, assuming error ∝ N^−p.
namespace kit {

struct Convergence {
  double limit = 0, order = 0, remaining = 0;
  bool converges = false;  ///< the successive differences shrink (ratio > 1)
};
/// From the values at N, 2N and 4N: the limit, the observed order p in error ∝ N^−p, and the
/// remaining relative error of the finest.
Convergence richardson(double coarse, double middle, double fine);

}  // namespace kit
