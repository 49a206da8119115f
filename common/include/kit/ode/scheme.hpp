#pragma once
// The one-step schemes chapters 2–3 compare, with what the lecture and the errata say of them.
#include <array>

#include <kit/base/enum_names.hpp>

namespace kit {

enum class Scheme { explicit_euler, implicit_euler, symplectic_euler, midpoint, rk4 };

/// Each scheme's key in JSON and file names, and its name in figures and tables.
inline constexpr auto scheme_names = enum_names<Scheme>({
    {Scheme::explicit_euler, "explicit_euler", "explicit Euler"},
    {Scheme::implicit_euler, "implicit_euler", "implicit Euler"},
    {Scheme::symplectic_euler, "symplectic_euler", "symplectic Euler"},
    {Scheme::midpoint, "midpoint", "midpoint RK2"},
    {Scheme::rk4, "rk4", "RK4"},
});
static_assert(scheme_names.in_order());
inline constexpr auto all_schemes = scheme_names.all();

/// Display name, e.g. "explicit Euler".
inline const char* name(Scheme scheme) { return scheme_names.display(scheme); }
/// Short key for JSON and file names, e.g. "explicit_euler".
inline const char* key(Scheme scheme) { return scheme_names.flag(scheme); }
/// Global order of accuracy: 1, 1, 1, 2, 4.
int order(Scheme scheme);
/// Right-hand-side evaluations per step (implicit Euler: one linear solve, counted as one).
int evaluations_per_step(Scheme scheme);
/// gnuplot colour, the same in every figure ("lc rgb '#d62728'").
const char* style(Scheme scheme);
/// gnuplot point type and size for the scheme's marks ("pt 7 ps 0.7").
const char* marker(Scheme scheme);

}  // namespace kit
