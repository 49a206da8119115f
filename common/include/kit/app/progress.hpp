#pragma once
// A progress line on the terminal for runs that take more than a moment:
//   round-off  [#########...........]  45%  about 3 s left
// drawn on stderr only, only when stderr is a terminal, only once a task has run for
// `delay` seconds, at most `1/interval` times a second, and erased when the task ends. stdout
// is never touched, so --json output stays one JSON object. KIT_PROGRESS=always draws on any
// stderr (tests), KIT_PROGRESS=never never draws (CI logs).
//
// Work is counted in units proportional to time (steps of a method, not loop iterations of
// wildly different cost). A chapter names the task (ChapterApp::section opens one per section)
// and its total (kit/app/run_estimate.hpp's announce sets it from the estimate); the loops that do
// the work report it with progress_add(steps): kit::advance does it every 2^16 steps.
#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace kit {

/// Where KIT_PROGRESS puts the progress line.
enum class ProgressMode {
  automatic,  ///< on stderr when stderr is a terminal (unset or any other value)
  always,     ///< "always" or "1": on stderr whatever it is
  never,      ///< "never" or "0": nowhere
};
/// The mode that the value of KIT_PROGRESS (nullptr: unset) asks for.
ProgressMode progress_mode(const char* value);

/// The drawing logic of one progress line, its clock and its output given: tests drive it with
/// a fake clock and a string stream; the process-wide line (ProgressTask) uses the steady clock
/// and stderr.
class ProgressBar {
 public:
  struct Settings {
    double delay = 1.5;     ///< seconds a task runs before the line first appears
    double interval = 0.1;  ///< least seconds between two draws: at most 10 a second
    int bar_cells = 20;     ///< width of the bar, in characters
    int max_width = 78;     ///< the line is cut to this many characters
  };
  /// Draws on `out` (nullptr: draws nothing, but still counts), reading the time in seconds
  /// from `clock`.
  ProgressBar(std::ostream* out, std::function<double()> clock, Settings settings);
  ProgressBar(std::ostream* out, std::function<double()> clock)
      : ProgressBar(out, std::move(clock), Settings{}) {}
  ~ProgressBar() { finish(); }
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  /// A new task: what runs (a section's name), and its total work (0: not known yet). The time
  /// starts now; the line drawn for a previous task is erased.
  void start(std::string what, double total);
  /// Sets the total work of the current task (an estimate made once it started).
  void set_total(double total);
  /// Records `work` more units done, and redraws when it is time to.
  void add(double work);
  /// Records `work` more units done without drawing (a task that an inner task interrupted).
  void count(double work) { done_ += work; }
  /// Erases the line if one is drawn. The task's counts stay readable.
  void finish();

  double done() const { return done_; }
  double total() const { return total_; }
  /// done/total in [0, 1]; 0 while the total is not known.
  double fraction() const;
  /// Seconds left at `elapsed` seconds into the task: elapsed·(1 − f)/f; negative when unknown.
  double seconds_left(double elapsed) const;
  /// The line as drawn `elapsed` seconds into the task, without control characters.
  std::string line(double elapsed) const;
  /// How many times the line was drawn, and whether one is on the terminal now.
  long draws() const { return draws_; }
  bool shown() const { return shown_; }

 private:
  void draw(double now);
  std::ostream* out_;
  std::function<double()> clock_;
  Settings settings_;
  std::string what_;
  double total_ = 0, done_ = 0, started_ = 0, last_draw_ = 0;
  std::size_t drawn_width_ = 0;
  long draws_ = 0;
  bool shown_ = false;
};

/// "3 s", "2.5 min", "1.2 h", "3.4 days": a duration for a person to read.
std::string describe_seconds(double seconds);
/// "about 3 s", "about 2.5 min", or "under a second".
std::string about_seconds(double seconds);

/// Where the work of the innermost running ProgressTask goes: set while one runs, null
/// otherwise. A header-only hook, so that code that counts work (kit::advance) costs one load
/// and a branch when no task runs, and needs no library.
inline void (*progress_hook)(double work) = nullptr;
/// Steps between two reports of work by a stepping loop: tens of microseconds of the cheapest
/// steps, so that reporting costs nothing measurable.
inline constexpr long progress_chunk = 1L << 16;

/// What one unit of reported work counts for, ProgressWeight's while one lives; 1 otherwise.
inline double progress_weight = 1.0;
/// Records `work` units done by the innermost running task, if any.
inline void progress_add(double work) {
  if (progress_hook) progress_hook(work * progress_weight);
}

/// While it lives, work reported counts `weight` times: for a loop whose steps cost `weight`
/// times the unit of the task's total (an implicit step among explicit ones, say), so that the
/// fraction stays proportional to time.
class ProgressWeight {
 public:
  explicit ProgressWeight(double weight) : outer_(progress_weight) { progress_weight = outer_ * weight; }
  ~ProgressWeight() { progress_weight = outer_; }
  ProgressWeight(const ProgressWeight&) = delete;
  ProgressWeight& operator=(const ProgressWeight&) = delete;

 private:
  double outer_;
};

/// Counts work one unit at a time and reports it to the progress line a chunk at a time: for
/// loops whose steps are too cheap to report one by one. Reports what is left when destroyed.
class ProgressCounter {
 public:
  ProgressCounter() = default;
  ProgressCounter(const ProgressCounter&) = delete;
  ProgressCounter& operator=(const ProgressCounter&) = delete;
  ~ProgressCounter() { progress_add(static_cast<double>(pending_)); }
  void add(long work) {
    if ((pending_ += work) >= 4096) progress_add(static_cast<double>(pending_)), pending_ = 0;
  }

 private:
  long pending_ = 0;
};

/// One task of the process-wide progress line on stderr (mode from KIT_PROGRESS). Tasks nest:
/// the innermost one draws, every running task counts the work, and the one an inner task
/// interrupted resumes its line when that ends.
class ProgressTask {
 public:
  explicit ProgressTask(std::string what, double total = 0);
  ~ProgressTask();
  ProgressTask(const ProgressTask&) = delete;
  ProgressTask& operator=(const ProgressTask&) = delete;
  /// Sets the total work of the innermost running task (nothing when none runs).
  static void set_total(double total);
  /// Erases the line while something else is written to the same terminal (ChapterApp's text
  /// does it before every write); the next progress_add draws it again.
  static void clear_line();

 private:
  ProgressTask* outer_;
  std::unique_ptr<ProgressBar> bar_;
};

}  // namespace kit
