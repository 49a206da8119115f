// The progress line (progress.hpp): when it draws, what it says, and that it stays silent.
#include <kit_catch.hpp>

#include <cstdlib>
#include <iostream>
#include <sstream>

#include <kit/app/progress.hpp>

namespace {
/// A clock the test moves by hand [s].
struct FakeClock {
  double now = 100;
  std::function<double()> read() {
    return [this] { return now; };
  }
};

/// Redirects std::cerr into a string while it lives.
struct CaptureCerr {
  std::ostringstream text;
  std::streambuf* saved = std::cerr.rdbuf(text.rdbuf());
  ~CaptureCerr() { std::cerr.rdbuf(saved); }
};

/// Sets KIT_PROGRESS while it lives.
struct ProgressEnv {
  explicit ProgressEnv(const char* value) { ::setenv("KIT_PROGRESS", value, 1); }
  ~ProgressEnv() { ::unsetenv("KIT_PROGRESS"); }
};
}  // namespace

TEST_CASE("KIT_PROGRESS forces the line on or off; anything else leaves it to the terminal") {
  CHECK(kit::progress_mode(nullptr) == kit::ProgressMode::automatic);
  CHECK(kit::progress_mode("always") == kit::ProgressMode::always);
  CHECK(kit::progress_mode("1") == kit::ProgressMode::always);
  CHECK(kit::progress_mode("never") == kit::ProgressMode::never);
  CHECK(kit::progress_mode("0") == kit::ProgressMode::never);
  CHECK(kit::progress_mode("") == kit::ProgressMode::automatic);
  CHECK(kit::progress_mode("yes please") == kit::ProgressMode::automatic);
}

TEST_CASE("the line appears only after the delay, at most once an interval, and is erased at the end") {
  FakeClock clock;
  std::ostringstream out;
  kit::ProgressBar bar(&out, clock.read());  // delay 1.5 s, interval 0.1 s
  bar.start("round-off", 1000);
  for (int i = 0; i < 10; ++i) {  // 1 s of work: nothing drawn yet
    clock.now += 0.1;
    bar.add(10);
  }
  CHECK(out.str().empty());
  CHECK(bar.draws() == 0);
  clock.now += 0.6;  // 1.6 s in
  bar.add(10);
  CHECK(bar.draws() == 1);
  CHECK(bar.shown());
  for (int i = 0; i < 50; ++i) {  // 50 reports within 0.05 s: no redraw
    clock.now += 0.001;
    bar.add(1);
  }
  CHECK(bar.draws() == 1);
  clock.now += 0.06;  // past the interval
  bar.add(1);
  CHECK(bar.draws() == 2);
  // At most 10 draws a second, however many reports.
  for (int i = 0; i < 10'000; ++i) {
    clock.now += 1e-4;
    bar.add(0.01);
  }
  CHECK(bar.draws() <= 2 + 11);
  CHECK(bar.draws() >= 2 + 9);
  const std::string drawn = out.str();
  CHECK(drawn.front() == '\r');
  CHECK(drawn.find('\n') == std::string::npos);  // one line, redrawn in place
  bar.finish();
  CHECK_FALSE(bar.shown());
  CHECK(out.str().substr(drawn.size()) == "\r\033[K");
  bar.finish();  // twice: nothing more
  CHECK(out.str().size() == drawn.size() + 4);
}

TEST_CASE("the line says what runs, how far it is and the time left") {
  FakeClock clock;
  kit::ProgressBar bar(nullptr, clock.read());
  bar.start("work-precision", 400);
  CHECK(bar.fraction() == 0);
  CHECK(bar.seconds_left(1) < 0);
  bar.add(100);
  CHECK(bar.fraction() == 0.25);
  CHECK(bar.seconds_left(3) == Approx(9));  // a quarter in 3 s: three quarters in 9 s
  CHECK(bar.line(3) == "work-precision  [#####...............]  25%  about 9 s left");
  bar.add(1000);  // more than the estimate: the fraction stops at 1
  CHECK(bar.fraction() == 1);
  CHECK(bar.line(4) == "work-precision  [####################] 100%  under a second left");
  bar.start("step doubling", 0);  // no total known: what runs and for how long
  bar.add(5);
  CHECK(bar.fraction() == 0);
  CHECK(bar.line(75) == "step doubling  running for 75 s");
  bar.set_total(10);
  CHECK(bar.fraction() == 0.5);
  // A long name is cut to the width, in characters, not bytes.
  kit::ProgressBar narrow(nullptr, clock.read(), {1.5, 0.1, 20, 10});
  narrow.start("ωωωωωωωωωωωωωωω", 0);
  CHECK(narrow.line(1) == "ωωωωωωωωωω");
}

TEST_CASE("durations for a person to read") {
  CHECK(kit::describe_seconds(0.5) == "under a second");
  CHECK(kit::describe_seconds(6.2) == "6 s");
  CHECK(kit::describe_seconds(150) == "2.5 min");
  CHECK(kit::describe_seconds(3 * 3600) == "3 h");
  CHECK(kit::describe_seconds(10 * 86400) == "10 days");
  CHECK(kit::about_seconds(6.2) == "about 6 s");
  CHECK(kit::about_seconds(0.2) == "under a second");
}

TEST_CASE("a disabled line writes nothing, however long the task, but still counts") {
  FakeClock clock;
  kit::ProgressBar bar(nullptr, clock.read());
  bar.start("round-off", 10);
  for (int i = 0; i < 100; ++i) {
    clock.now += 1;
    bar.add(0.1);
  }
  CHECK(bar.draws() == 0);
  CHECK(bar.done() == Approx(10));

  const ProgressEnv never("never");
  const CaptureCerr err;
  {
    const kit::ProgressTask task("round-off", 1e6);
    for (int i = 0; i < 1000; ++i) kit::progress_add(1e3);
  }
  CHECK(err.text.str().empty());
}

TEST_CASE("work goes to the running task, weighted, and nowhere once it ends") {
  CHECK(kit::progress_hook == nullptr);
  kit::progress_add(5);  // no task: nothing happens
  const ProgressEnv never("never");
  {
    const kit::ProgressTask outer("outer");
    CHECK(kit::progress_hook != nullptr);
    {
      const kit::ProgressTask inner("inner");
      const kit::ProgressWeight heavier(3);
      CHECK(kit::progress_weight == 3);
      {
        const kit::ProgressWeight nested(2);
        CHECK(kit::progress_weight == 6);
      }
      CHECK(kit::progress_weight == 3);
    }
    CHECK(kit::progress_weight == 1);
    CHECK(kit::progress_hook != nullptr);  // the outer task again
  }
  CHECK(kit::progress_hook == nullptr);
}

TEST_CASE("KIT_PROGRESS=always draws on stderr whatever it is, and erases the line at the end") {
  const ProgressEnv always("always");
  const CaptureCerr err;
  {
    const kit::ProgressTask task("demo", 100);
    // The real clock: nothing is drawn before 1.5 s, so this task stays silent...
    kit::progress_add(50);
  }
  CHECK(err.text.str().empty());
  // ... and its bar is the ProgressBar above, drawn on std::cerr.
  kit::ProgressBar bar(&std::cerr, [] { return 0.0; }, {0.0, 0.1, 20, 78});
  bar.start("demo", 100);
  bar.add(50);
  bar.finish();
  CHECK(err.text.str() == "\rdemo  [##########..........]  50%  under a second left\033[K\r\033[K");
}
