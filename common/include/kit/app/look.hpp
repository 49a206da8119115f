#pragma once
// One style per method, the same in every figure of every chapter: a gnuplot colour (and, for
// peers, a dash pattern) that callers extend with marks and widths ("pt 7 ps 0.8", "lw 3").
// Kit methods are solid; peers (GSL, Boost.Odeint) are dashed; references are black or green.
#include <string>

namespace kit::look {

// The closed form, and a reference solver's points.
inline const std::string exact = "lc rgb '#000000' lw 2";
inline const std::string reference = "lc rgb '#2ca02c'";
// Predictions from theory (dashed grey), single precision, highlighted points.
inline const std::string prediction = "lc rgb '#555555' dt 2";
inline const std::string single_precision = "lc rgb '#9467bd'";
inline const std::string highlight = "lc rgb '#000000'";

// The fixed-step schemes of chapters 1–3 (kit::style(Scheme) returns these).
inline const std::string explicit_euler = "lc rgb '#d62728'";
inline const std::string implicit_euler = "lc rgb '#1f77b4'";
inline const std::string symplectic_euler = "lc rgb '#ff7f0e'";
inline const std::string midpoint = "lc rgb '#9467bd'";
inline const std::string rk4 = "lc rgb '#8c564b'";

// The adaptive methods of chapter 4: the kit's, then its peers (dashed).
inline const std::string dopri5 = "lc rgb '#d62728'";
inline const std::string cash_karp = "lc rgb '#ff7f0e'";
inline const std::string bogacki_shampine = "lc rgb '#bcbd22'";
inline const std::string step_doubling_euler = "lc rgb '#e377c2' dt 4";
inline const std::string step_doubling_rk2 = "lc rgb '#7f7f7f' dt 4";
inline const std::string gsl_rkck = "lc rgb '#1f77b4' dt 2";
inline const std::string gsl_rkf45 = "lc rgb '#17becf' dt 2";
inline const std::string gsl_rk8pd = "lc rgb '#9467bd' dt 2";
inline const std::string boost_dopri5 = "lc rgb '#2ca02c' dt 2";
inline const std::string fixed_rk4 = "lc rgb '#8c564b' dt 3";

// Verdicts in stability maps.
inline const std::string stable = "lc rgb '#2ca02c'";
inline const std::string unstable = "lc rgb '#d62728'";
// Guides drawn with `set arrow`: thresholds, boundaries.
inline const std::string guide = "lc rgb '#888888' dt 3";
inline const std::string guide_label = "tc rgb '#777777' font ',8'";  // `set label` text next to a guide

}  // namespace kit::look
