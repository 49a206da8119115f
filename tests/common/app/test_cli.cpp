#include <cmath>
#include <iostream>
#include <sstream>

#include <kit_catch.hpp>

#include <kit/app/chapter_app.hpp>

#include "process.hpp"

namespace {
// Runs a small chapter app with the given flags; returns its exit code and stderr text.
struct Outcome {
  int code;
  std::string err;
  bool body_ran;
  double dt;
  std::string shape;
  nlohmann::json summary;
};
Outcome run_app(std::vector<std::string> args, const std::string& out_dir = "unused-out") {
  double dt = 0.1;
  long count = 5;
  std::string shape = "circle";
  kit::ChapterApp app("toy", out_dir, "a toy chapter");
  app.add_real("--dt", dt, "time step [s]", kit::positive(10));
  app.add_count("--count", count, "how many", 1, 100);
  app.add_choice("--shape", shape, "the toy's shape", {"circle", "square"});
  args.insert(args.begin(), "toy");
  std::vector<const char*> argv;
  for (auto& a : args) argv.push_back(a.c_str());
  std::ostringstream captured;
  auto* old = std::cerr.rdbuf(captured.rdbuf());
  bool ran = false;
  const int code = app.run(int(argv.size()), argv.data(), [&] { ran = true; });
  std::cerr.rdbuf(old);
  return {code, captured.str(), ran, dt, shape, app.summary()};
}
}  // namespace

TEST_CASE("ranges reject NaN and infinities and describe themselves") {
  CHECK_FALSE(kit::positive().contains(NAN));
  CHECK_FALSE(kit::any_finite().contains(INFINITY));
  CHECK_FALSE(kit::positive(10).contains(0.0));
  CHECK(kit::positive(10).contains(10.0));
  CHECK_FALSE(kit::nonzero_finite().contains(0.0));
  CHECK(kit::positive(10).describe() == "a finite number in (0, 10]");
  CHECK(kit::between(-1, 1).describe() == "a finite number in [-1, 1]");
  CHECK(kit::positive().describe() == "a finite number > 0");
}

TEST_CASE("a bad value is a usage error naming the flag, the value and the range; exit 2") {
  for (const char* bad : {"-1", "nan", "inf", "0", "abc", "1e999"}) {
    const auto outcome = run_app({"--dt", bad, "--json"});
    INFO("--dt " << bad << " -> " << outcome.err);
    CHECK(outcome.code == 2);
    CHECK_FALSE(outcome.body_ran);
    CHECK_THAT(outcome.err,
               ContainsSubstring("--dt") && ContainsSubstring(bad) && ContainsSubstring("(0, 10]"));
  }
}

TEST_CASE("whole-number flags are checked the same way") {
  const auto outcome = run_app({"--count", "0"});
  CHECK(outcome.code == 2);
  CHECK_THAT(outcome.err, ContainsSubstring("--count") && ContainsSubstring("[1, 100]"));
}

TEST_CASE("a whole number may be written as a number (1e2), never as a fraction, in hexadecimal or octal") {
  const auto written_as_number = run_app({"--count", "1e2", "--quiet", "--no-plot"});
  CHECK(written_as_number.code == 0);
  CHECK(written_as_number.summary["parameters"]["count"].get<long>() == 100);
  CHECK(run_app({"--count", "2.5e1", "--quiet", "--no-plot"}).summary["parameters"]["count"].get<long>() ==
        25);
  for (const std::string refused : {"2.5", "1e3", "0x10", "010", "1e", "inf", "nan", "12abc",
                                    "2.0000000000000001", "1e-400", " 5", "99999999999999999999"}) {
    const auto outcome = run_app({"--count", refused});
    INFO(refused << ": " << outcome.err);
    CHECK(outcome.code == 2);
    CHECK_FALSE(outcome.body_ran);
    CHECK_THAT(outcome.err, ContainsSubstring("--count") && ContainsSubstring("value " + refused) &&
                                ContainsSubstring("[1, 100]"));
  }
}

TEST_CASE("a named choice takes one of its names; any other is a usage error naming the flag and the names") {
  CHECK(run_app({"--quiet", "--no-plot"}).shape == "circle");
  const auto chosen = run_app({"--shape", "square", "--quiet", "--no-plot"});
  CHECK(chosen.code == 0);
  CHECK(chosen.shape == "square");
  for (const std::string refused : {"triangle", "", "Square", "circle,square"}) {
    const auto outcome = run_app({"--shape", refused});
    INFO(refused << ": " << outcome.err);
    CHECK(outcome.code == 2);
    CHECK_FALSE(outcome.body_ran);
    CHECK_THAT(outcome.err, ContainsSubstring("--shape") && ContainsSubstring("{circle,square}"));
  }
}

TEST_CASE("an unknown flag or format is a usage error") {
  CHECK(run_app({"--bogus"}).code == 2);
  CHECK_THAT(run_app({"--bogus"}).err, ContainsSubstring("--bogus"));
  const auto format = run_app({"--format", "pdf,gif"});
  CHECK(format.code == 2);
  CHECK_THAT(format.err, ContainsSubstring("gif"));
}

TEST_CASE("good flags reach the body and the summary's parameters") {
  const auto outcome = run_app({"--dt", "0.25", "--count", "7", "--quiet", "--no-plot"});
  CHECK(outcome.code == 0);
  CHECK(outcome.body_ran);
  CHECK(outcome.dt == 0.25);
  CHECK(outcome.summary["chapter"] == "toy");
  CHECK(outcome.summary["parameters"]["dt"].get<double>() == 0.25);  // as given on the command line
  CHECK(outcome.summary["parameters"]["count"].get<long>() == 7);
  // A flag left at its default is reported with its default value.
  CHECK(run_app({"--quiet"}).summary["parameters"]["count"].get<long>() == 5);
}

TEST_CASE("a UsageError thrown by the body exits 2, any other failure exits 1") {
  kit::ChapterApp app("toy", "unused", "toy");
  const char* argv[] = {"toy", "--quiet"};
  std::ostringstream captured;
  auto* old = std::cerr.rdbuf(captured.rdbuf());
  const int usage =
      app.run(2, argv, [] { throw kit::UsageError("--t-end must be a whole number of steps"); });
  kit::ChapterApp app2("toy", "unused", "toy");
  const int failure = app2.run(2, argv, [] { throw std::runtime_error("solver failed"); });
  std::cerr.rdbuf(old);
  CHECK(usage == 2);
  CHECK(failure == 1);
  CHECK_THAT(captured.str(),
             ContainsSubstring("whole number of steps") && ContainsSubstring("solver failed"));
}

TEST_CASE("a bad --out is refused with exit 2 before the body runs: empty, a file, below a file") {
  kit::test::TempDir dir("cli-out");
  std::ofstream(dir.path() / "a-file") << "x";
  for (const std::string& bad :
       {std::string(""), (dir.path() / "a-file").string(), (dir.path() / "a-file" / "sub").string()}) {
    const auto outcome = run_app({"--out", bad, "--quiet"});
    INFO("--out '" << bad << "' -> " << outcome.err);
    CHECK(outcome.code == 2);
    CHECK_FALSE(outcome.body_ran);
    CHECK_THAT(outcome.err, ContainsSubstring("--out"));
  }
  CHECK(run_app({"--out", "", "--no-plot", "--quiet"}).code == 0);  // no figure, no folder needed
  const auto fine = run_app({"--out", (dir.path() / "new" / "folder").string(), "--quiet"});
  CHECK(fine.code == 0);
  CHECK(kit::test::files_under(dir.path()).size() == 1);  // a-file: the check itself creates nothing
}
