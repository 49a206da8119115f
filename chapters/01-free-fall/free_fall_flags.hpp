#pragma once
// Chapter 1's command-line flags for free fall, and the limits they must meet together.
#include <kit/app/chapter_app.hpp>
#include <kit/problems/free_fall.hpp>

namespace kit {

/// Adds --x0 [m] --v0 [m/s] --g [m/s²] (y axis up) --dt [s] --t-end [s] --dt-min [s], with SI
/// units and ranges, writing into `fall` and the steps (whose current values are the defaults).
/// dt_min is the smallest step asked of the round-off sweep; the sweep may raise it.
void add_free_fall_flags(ChapterApp& app, FreeFall& fall, double& dt, double& t_end, double& dt_min);

/// Throws UsageError naming the flag, its value and the allowed range when |g| < 1e-3 m/s² (the
/// errors the chapter measures, ∝ |g|, would vanish in round-off) or dt_min > t_end/10 (the
/// round-off sweep would not span a decade of Δt).
void require_measurable(const FreeFall& fall, double t_end, double dt_min);

}  // namespace kit
