#pragma once
// Gravity plus linear drag, the motion every sprite follows (chapter 5):
//   dx/dt = v,   dv/dt = g − k (v − w)   (per axis; g gravity [m/s²], k drag rate [1/s], w wind [m/s]).
// It is linear with constant coefficients, so one step of any length h has a closed form:
//   v(h) = E v + F (g + k w),   x(h) = x + F v + (h − F) w + G g,
// with E = e^{−kh}, F = (1 − e^{−kh})/k and G = (h − F)/k; at k = 0 these are 1, h and h²/2
// (free fall). The particles' "exact" integrator applies it; the others are measured against it.
#include <cmath>

namespace kit {

/// The per-step constants of the closed form above, shared by every particle of a step.
struct DragStep {
  double e = 1;  ///< e^{−kh}, dimensionless
  double f = 0;  ///< (1 − e^{−kh})/k [s]
  double g = 0;  ///< (h − f)/k [s²]

  DragStep(double k, double h) {
    const double kh = k * h;
    e = std::exp(-kh);
    f = k == 0 ? h : -std::expm1(-kh) / k;
    // (kh − 1 + e^{−kh})/k² loses every digit to cancellation as kh → 0: use its series there.
    g = std::abs(kh) < 1e-3 ? h * h * (0.5 - kh / 6.0 + kh * kh / 24.0) : (h - f) / k;
  }
};

/// One axis of the motion: position [m] and velocity [m/s] after time h [s], exactly.
struct AxisState {
  double x = 0, v = 0;
};
inline AxisState drag_motion(AxisState s, double gravity, double k, double wind, double h) {
  const DragStep c(k, h);
  return {s.x + c.f * s.v + (h - c.f) * wind + c.g * gravity, c.e * s.v + c.f * (gravity + k * wind)};
}

}  // namespace kit
