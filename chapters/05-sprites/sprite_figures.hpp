#pragma once
// Chapter 5's figures: the speed/accuracy trade of the integrators (error against cost, in
// metres and in pixels on screen), the particle counts per frame, and particle paths coloured
// by age (lecture: "on peut afficher la trajectoire").
#include <map>
#include <vector>

#include <kit/app/figure.hpp>
#include <kit/render/camera.hpp>
#include <kit/sprites/sprite_run.hpp>

#include "sprite_trade.hpp"

namespace kit {

/// Distance on screen [px] between the projections of a and b [m]; NaN when either is behind
/// the camera.
double pixels_between(const Pinhole& camera, const Vec3& a, const Vec3& b);

using TradeCurves = std::map<Integrator, std::vector<TradeRun>>;
/// Error at the end of the mean particle's life against steps per second of animation (1/Δt):
/// top in metres, bottom in pixels at `camera`, with the frame rate `fps` and one pixel marked.
Figure trade_figure(const TradeCurves& curves, const Pinhole& camera, double fps, const std::string& scene);

/// Emitted and dead (cumulative) and alive per frame; alive = emitted − dead.
Figure counts_figure(const SpriteRecording& recording, double fps, const std::string& scene);

/// The recorded paths, side view (x, y), each cut into segments coloured by age.
Figure paths_figure(const SpriteRecording& recording, const std::string& scene);

}  // namespace kit
