#include <kit/app/progress.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iostream>

#include <unistd.h>

#include <fmt/format.h>

namespace kit {

ProgressMode progress_mode(const char* value) {
  if (!value) return ProgressMode::automatic;
  if (!std::strcmp(value, "always") || !std::strcmp(value, "1")) return ProgressMode::always;
  if (!std::strcmp(value, "never") || !std::strcmp(value, "0")) return ProgressMode::never;
  return ProgressMode::automatic;
}

ProgressBar::ProgressBar(std::ostream* out, std::function<double()> clock, Settings settings)
    : out_(out), clock_(std::move(clock)), settings_(settings) {}

void ProgressBar::start(std::string what, double total) {
  finish();
  what_ = std::move(what);
  total_ = std::max(0.0, total);
  done_ = 0;
  draws_ = 0;
  started_ = last_draw_ = clock_();
}

void ProgressBar::set_total(double total) { total_ = std::max(0.0, total); }

void ProgressBar::add(double work) {
  done_ += work;
  if (!out_) return;  // disabled: counting only, not even a look at the clock
  const double now = clock_();
  if (now - started_ < settings_.delay) return;
  if (shown_ && now - last_draw_ < settings_.interval) return;
  draw(now);
}

double ProgressBar::fraction() const {
  if (!(total_ > 0)) return 0;
  return std::clamp(done_ / total_, 0.0, 1.0);
}

double ProgressBar::seconds_left(double elapsed) const {
  const double f = fraction();
  if (!(f > 0)) return -1;
  return elapsed * (1 - f) / f;
}

std::string describe_seconds(double seconds) {
  if (!(seconds >= 0) || !std::isfinite(seconds)) return "an unknown time";
  if (seconds < 1) return "under a second";
  if (seconds < 90) return fmt::format("{:.0f} s", seconds);
  if (seconds < 90 * 60) return fmt::format("{:.2g} min", seconds / 60);
  if (seconds < 48 * 3600) return fmt::format("{:.2g} h", seconds / 3600);
  if (seconds < 730 * 86400) return fmt::format("{:.3g} days", seconds / 86400);
  return fmt::format("{:.2g} years", seconds / (365.25 * 86400));
}

std::string about_seconds(double seconds) {
  return seconds < 1 ? "under a second" : "about " + describe_seconds(seconds);
}

std::string ProgressBar::line(double elapsed) const {
  std::string text = what_;
  if (total_ > 0) {
    const double f = fraction();
    const auto full = static_cast<int>(std::floor(f * settings_.bar_cells));
    text += fmt::format("  [{}{}] {:3.0f}%", std::string(static_cast<std::size_t>(full), '#'),
                        std::string(static_cast<std::size_t>(settings_.bar_cells - full), '.'), 100 * f);
    const double left = seconds_left(elapsed);
    text += left >= 0 ? "  " + about_seconds(left) + " left" : "  estimating the time left";
  } else {
    text += fmt::format("  running for {}", describe_seconds(elapsed));
  }
  // Cut to the width, counting characters (a section's name may hold UTF-8), not bytes.
  std::size_t chars = 0, cut = 0;
  for (; cut < text.size(); ++cut) {
    if ((static_cast<unsigned char>(text[cut]) & 0xC0) != 0x80 && ++chars > std::size_t(settings_.max_width))
      break;
  }
  return text.substr(0, cut);
}

void ProgressBar::draw(double now) {
  const std::string text = line(now - started_);
  // \r to the start of the line, the text, then erase what a longer previous line left.
  *out_ << '\r' << text << "\033[K" << std::flush;
  drawn_width_ = text.size();
  last_draw_ = now;
  shown_ = true;
  ++draws_;
}

void ProgressBar::finish() {
  if (!shown_ || !out_) return;
  *out_ << "\r\033[K" << std::flush;
  shown_ = false;
}

namespace {

ProgressTask* innermost = nullptr;

double steady_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

std::ostream* progress_stream() {
  switch (progress_mode(std::getenv("KIT_PROGRESS"))) {
    case ProgressMode::always:
      return &std::cerr;
    case ProgressMode::never:
      return nullptr;
    case ProgressMode::automatic:
      break;
  }
  return ::isatty(STDERR_FILENO) ? &std::cerr : nullptr;
}

}  // namespace

ProgressTask::ProgressTask(std::string what, double total)
    : outer_(innermost), bar_(std::make_unique<ProgressBar>(progress_stream(), steady_seconds)) {
  if (outer_) outer_->bar_->finish();  // one line at a time: the inner task's
  bar_->start(std::move(what), total);
  innermost = this;
  progress_hook = [](double work) {
    innermost->bar_->add(work);
    for (ProgressTask* task = innermost->outer_; task; task = task->outer_) task->bar_->count(work);
  };
}

ProgressTask::~ProgressTask() {
  bar_->finish();
  innermost = outer_;
  if (!innermost) progress_hook = nullptr;
}

void ProgressTask::set_total(double total) {
  if (innermost) innermost->bar_->set_total(total);
}

void ProgressTask::clear_line() {
  if (innermost) innermost->bar_->finish();
}

}  // namespace kit
