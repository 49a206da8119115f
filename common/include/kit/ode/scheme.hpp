#pragma once
// The one-step schemes chapters 2–3 compare, with what the lecture and the errata say of them.
#include <array>

namespace kit {

enum class Scheme { explicit_euler, implicit_euler, symplectic_euler, midpoint, rk4 };

inline constexpr std::array<Scheme, 5> all_schemes{Scheme::explicit_euler, Scheme::implicit_euler,
                                                   Scheme::symplectic_euler, Scheme::midpoint, Scheme::rk4};

/// Display name, e.g. "explicit Euler".
const char* name(Scheme scheme);
/// Short key for JSON and file names, e.g. "explicit_euler".
const char* key(Scheme scheme);
/// Global order of accuracy: 1, 1, 1, 2, 4.
int order(Scheme scheme);
/// Right-hand-side evaluations per step (implicit Euler: one linear solve, counted as one).
int evaluations_per_step(Scheme scheme);
/// gnuplot colour, the same in every figure ("lc rgb '#d62728'").
const char* style(Scheme scheme);
/// gnuplot point type and size for the scheme's marks ("pt 7 ps 0.7").
const char* marker(Scheme scheme);

}  // namespace kit
