#pragma once
// The spring's command-line flags, shared by the chapters that simulate it.
#include <kit/app/chapter_app.hpp>
#include <kit/problems/spring.hpp>

namespace kit {

/// Adds --mass --stiffness --damping --rest-length --x0 --v0, with SI units and ranges, writing
/// into `spring` and `u0` (whose current values are the defaults). `max_stiffness` [N/m] bounds K.
void add_spring_flags(ChapterApp& app, Spring& spring, Vec2& u0, double max_stiffness);

/// Throws UsageError when u0 is the equilibrium (x0 = L0, v0 = 0): nothing would move.
void require_motion(const Spring& spring, const Vec2& u0);

}  // namespace kit
