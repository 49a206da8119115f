#include "rigid_flags.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <CLI/CLI.hpp>

#include <kit/base/usage.hpp>

namespace kit {
namespace {

constexpr double max_spin = 1e4;  // [rad/s]: about 1600 turns a second, beyond any animated body

Vec3 parse_omega(const std::string& text) {
  const auto refuse = [&](const std::string& why) {
    return UsageError(fmt::format("--omega0 '{}': {}; expected three finite numbers x,y,z [rad/s], each in "
                                  "[-{:g}, {:g}], not all zero, e.g. --omega0 10,0,0.1",
                                  text, why, max_spin, max_spin));
  };
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    // std::from_chars reads plain decimal numbers only (no hex, no locale), and tells a number
    // too large for a double from text that is no number.
    const auto first = item.find_first_not_of(" \t"), last = item.find_last_not_of(" \t");
    const char* begin = item.data() + (first == std::string::npos ? item.size() : first);
    const char* end = item.data() + (last == std::string::npos ? 0 : last + 1);
    double value = 0;
    const auto [stop, error] = std::from_chars(begin, std::max(begin, end), value);
    if (error == std::errc::result_out_of_range) throw refuse(fmt::format("{} is out of range", item));
    if (error != std::errc() || stop != std::max(begin, end))
      throw refuse(fmt::format("'{}' is not a number", item));
    if (!std::isfinite(value) || std::abs(value) > max_spin)
      throw refuse(fmt::format("{} is out of range", item));
    values.push_back(value);
  }
  if (values.size() != 3 || text.empty() || text.back() == ',') throw refuse("not three numbers");
  const Vec3 omega(values[0], values[1], values[2]);
  if (omega.isZero(0)) throw refuse("a body at rest never turns");
  return omega;
}

}  // namespace

void add_rigid_flags(ChapterApp& app, RigidFlags& f) {
  app.add_choice("--body", f.body, "the free body: t-handle, box or cylinder (the drops use the box)",
                 shape_names());
  const auto names = rotation_integrator_names.flags();
  app.add_choice("--integrator", f.integrator,
                 fmt::format("the scene runs' rotation integrator: {}", fmt::join(names, ", ")), names);
  app.add_real("--dt", f.dt, "time step h [s] of the runs at one step", positive(0.1));
  app.add_real("--t-end", f.t_end, "duration of the free body's runs [s]", positive(1e5));
  app.cli()
      .add_option("--omega0", f.omega0, "initial angular velocity in the body frame [rad/s], as x,y,z")
      ->type_name("X,Y,Z")
      ->capture_default_str();
  app.add_real("--restitution", f.restitution, "the ground's coefficient of restitution e", between(0, 1));
  app.add_real("--friction", f.friction, "the ground's Coulomb friction coefficient μ", between(0, 10));
  app.add_count("--frames", f.frames, "pictures and meshes of each scene run (0: none)", 0, 20'000);
  app.add_count("--trade-steps", f.trade_steps,
                "the most steps of an integrator in the cost-of-accuracy runs", 100,
                10'000'000);  // 1e7: about 30 s of the six integrators
  app.add_divergence_flag();
  app.add_viewer_flag();
}

RigidSetup rigid_setup(const RigidFlags& flags) {
  RigidSetup setup;
  setup.shape = shape_named(flags.body);
  // add_choice let only the table's names through.
  setup.integrator = rotation_integrator_names.parse(flags.integrator).value_or(setup.integrator);
  setup.omega0 = parse_omega(flags.omega0);
  setup.contact.restitution = flags.restitution;
  setup.contact.friction = flags.friction;
  setup.dt = flags.dt;
  setup.t_end = flags.t_end;
  setup.frames = flags.frames;
  for (long n = 100; n <= flags.trade_steps; n *= 10) {  // 1 and 3 per decade
    setup.trade_steps.push_back(n);
    if (3 * n <= flags.trade_steps) setup.trade_steps.push_back(3 * n);
  }
  if (flags.dt > flags.t_end)
    throw UsageError(fmt::format("--dt {} s is longer than --t-end {} s: --dt must be at most --t-end",
                                 flags.dt, flags.t_end));
  return setup;
}

std::string describe_rigid_run(const RigidFlags& flags) {
  return fmt::format("--body {}, --integrator {}, --dt {} s, --t-end {} s, --trade-steps {}", flags.body,
                     flags.integrator, flags.dt, flags.t_end, flags.trade_steps);
}

}  // namespace kit
