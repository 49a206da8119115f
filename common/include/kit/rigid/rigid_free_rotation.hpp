#pragma once
// The torque-free rigid body in closed form (Landau & Lifshitz, Mechanics, §37). With principal
// moments I1 < I2 < I3, the energy E and |L|² = M² are conserved, and the angular velocity in the
// body frame is periodic, made of Jacobi's elliptic functions sn, cn, dn of
//   τ = λ t,  λ = sqrt((I3 − I2)(M² − 2E I1) / (I1 I2 I3)),
//   k² = (I2 − I1)(2E I3 − M²) / ((I3 − I2)(M² − 2E I1))          when M² > 2E I2,
// and the same with I1 and I3 exchanged when M² < 2E I2. Its period is 4K(k)/λ (K: the complete
// elliptic integral of the first kind). The component along the intermediate axis is λ-scaled
// sn(τ): near that axis (k → 1) it stays close to ±its amplitude for a long time and then
// reverses quickly: the flips of the Dzhanibekov effect, every half period.
#include <kit/rigid/rigid_body.hpp>

namespace kit {

/// The conserved quantities of one torque-free motion and what they imply.
struct FreeRotation {
  Vec3 moments = Vec3::Ones();  ///< I1 ≤ I2 ≤ I3 [kg·m²]
  double energy = 0;            ///< E = ½ Σ I_i ω_i² [J]
  double momentum = 0;          ///< |L| [kg·m²/s]

  /// 4K(k)/λ [s]: the time after which ω in the body frame repeats; +∞ on the separatrix
  /// M² = 2E I2 (a spin exactly about the intermediate axis, which flips never or once).
  double period() const;
  /// The elliptic modulus k of the motion (0: a steady spin about the largest or smallest axis).
  double modulus() const;
  /// True when the body turns mostly about its largest axis (M² > 2E I2), false about its
  /// smallest; either way the polhode circles that axis.
  bool about_largest_axis() const;
};

/// The motion of a body with principal moments `moments` (ascending, kg·m²) started at ω_body =
/// `omega` [rad/s] in those principal axes.
FreeRotation free_rotation(const Vec3& moments, const Vec3& omega);

}  // namespace kit
