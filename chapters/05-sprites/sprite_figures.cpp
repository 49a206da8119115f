#include "sprite_figures.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include <kit/app/look.hpp>

namespace kit {
namespace {
std::string style(Integrator i) {
  switch (i) {
    case Integrator::explicit_euler:
      return look::explicit_euler;
    case Integrator::symplectic_euler:
      return look::symplectic_euler;
    case Integrator::midpoint:
      return look::midpoint;
    case Integrator::exact:
      return look::exact;
  }
  return look::highlight;
}
}  // namespace

double pixels_between(const Pinhole& camera, const Vec3& a, const Vec3& b) {
  const auto pa = camera.project(a[0], a[1], a[2]), pb = camera.project(b[0], b[1], b[2]);
  if (!pa || !pb) return std::numeric_limits<double>::quiet_NaN();
  return std::hypot(pa->px - pb->px, pa->py - pb->py);
}

Figure trade_figure(const TradeCurves& curves, const Pinhole& camera, double fps, const std::string& scene) {
  Figure fig("trade",
             fmt::format("Speed against accuracy: the mean particle of '{}' at the end of its life", scene));
  fig.height_in = 6.5;
  auto& metres =
      fig.panel("steps per second of animation, 1/Δt [1/s] (the cost: all four cost the same per step)",
                "position error |x_n − x(t)| [m]", "error against the closed form");
  auto& pixels = fig.panel("steps per second of animation, 1/Δt [1/s]",
                           fmt::format("error on screen [px], {}×{}", camera.width(), camera.height()),
                           "what the error means on screen (default camera)");
  double lo = INFINITY, hi = 0;
  for (Panel* p : {&metres, &pixels}) {
    p->logx = p->logy = true;
    p->commands.push_back("set ytics 1e-16, 1e4");  // a tic every 4 decades: the panels span up to 20
  }
  for (const auto& [integrator, runs] : curves) {
    std::vector<double> rate, error, px;
    for (const TradeRun& run : runs) {
      // The exact step leaves only round-off, below any log axis: it is drawn at 1e-16 m.
      rate.push_back(1.0 / run.dt), error.push_back(std::max(run.error, 1e-16));
      px.push_back(std::max(pixels_between(camera, run.position, run.exact), 1e-14));
      lo = std::min(lo, rate.back()), hi = std::max(hi, rate.back());
    }
    const std::string title = fmt::format("{} (order {})", display_name(integrator), order(integrator));
    metres.add({title, rate, error, "linespoints", style(integrator) + " pt 7 ps 0.6"});
    pixels.add({title, rate, px, "linespoints", style(integrator) + " pt 7 ps 0.6"});
  }
  pixels.line("one pixel", {lo, hi}, {1.0, 1.0}, look::guide);
  for (Panel* p : {&metres, &pixels}) {
    p->commands.push_back(
        fmt::format("set arrow from {0},graph 0 to {0},graph 1 nohead {1}", fps, look::guide));
    p->commands.push_back(
        fmt::format("set label '--fps {}' at {},graph 0.92 offset 0.5,0 {}", fps, fps, look::guide_label));
  }
  return fig;
}

Figure counts_figure(const SpriteRecording& rec, double fps, const std::string& scene) {
  Figure fig("counts", fmt::format("Particles of '{}': alive = emitted − dead, every frame", scene));
  auto& p = fig.panel(fmt::format("frame (Δt = 1/{} s)", fps), "particles", "");
  p.key = "top left";
  std::vector<double> frame, emitted, dead, alive;
  long e = 0, d = 0;
  for (const FrameCounts& c : rec.frames) {
    e += c.emitted, d += c.died;
    frame.push_back(double(c.frame)), emitted.push_back(double(e)), dead.push_back(double(d));
    alive.push_back(double(c.alive));
  }
  p.line("emitted so far", frame, emitted, "lw 2 lc rgb '#1f77b4'");
  p.line("dead so far", frame, dead, "lw 2 lc rgb '#d62728'");
  p.line("alive", frame, alive, "lw 3 lc rgb '#2ca02c'");
  if (rec.warmup_frames > 0) {  // the frames before this line are simulated, not rendered
    p.commands.push_back(
        fmt::format("set arrow from {0},graph 0 to {0},graph 1 nohead {1}", rec.warmup_frames, look::guide));
    p.commands.push_back(fmt::format("set label 'first rendered frame' at {},graph 0.5 offset 0.5,0 {}",
                                     rec.warmup_frames, look::guide_label));
  }
  return fig;
}

Figure paths_figure(const SpriteRecording& rec, const std::string& scene) {
  Figure fig("paths", fmt::format("Paths of {} particles of '{}' seen from the side, coloured by age",
                                  rec.paths.size(), scene));
  auto& p = fig.panel("x [m]", "height y [m] (up)");
  p.commands.push_back("set size ratio -1");  // metres the same both ways
  double max_age = 0;
  for (const ParticlePath& path : rec.paths)
    if (!path.age.empty()) max_age = std::max(max_age, path.age.back());
  // Ages cut into bins, each one colour from yellow (young) to dark red (old). A path is drawn
  // as one series per bin it passes through (from the point before it enters, so the pieces
  // join), and only the first series of a bin has a legend entry: the legend reads as a scale.
  const char* colours[] = {"#f0e442", "#e69f00", "#d55e00", "#cc3311", "#882255", "#44001f"};
  const int bins = 6;
  for (int b = 0; b < bins; ++b) {
    const double from = max_age * b / bins, to = max_age * (b + 1) / bins;
    std::string title = fmt::format("age {:.2g}–{:.2g} s", from, to);
    for (const ParticlePath& path : rec.paths) {
      Series s{title, {}, {}, "lines", fmt::format("lw 2 lc rgb '{}'", colours[b])};
      for (std::size_t k = 0; k < path.x.size(); ++k) {
        const bool in_bin = path.age[k] >= from && (path.age[k] < to || b + 1 == bins);
        if (!in_bin) continue;
        if (s.x.empty() && k > 0) s.x.push_back(path.x[k - 1]), s.y.push_back(path.y[k - 1]);
        s.x.push_back(path.x[k]), s.y.push_back(path.y[k]);
      }
      if (s.x.size() < 2) continue;
      p.add(std::move(s));
      title.clear();
    }
  }
  return fig;
}

}  // namespace kit
