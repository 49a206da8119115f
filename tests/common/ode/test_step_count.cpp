// The steps of the run a user asks for (step_count.hpp).
#include <kit_catch.hpp>

#include <kit/base/usage.hpp>
#include <kit/ode/step_count.hpp>

TEST_CASE("a whole number of steps within the limit is the run's length") {
  CHECK(kit::require_whole_steps(1.0, 0.1, 1'000'000) == 10);
  CHECK(kit::require_whole_steps(6.721, 0.013, 1'000'000) == 517);
  CHECK(kit::require_whole_steps(1.0, 1e-6, 1'000'000) == 1'000'000);
}

TEST_CASE("T/dt not whole, under one step or over the limit: a usage error naming both flags and the range") {
  for (auto [t_end, dt] : {std::pair{1.0, 0.3}, {1e-4, 1.0}, {1e4, 1e-3}}) {
    INFO("T = " << t_end << ", dt = " << dt);
    try {
      kit::require_whole_steps(t_end, dt, 1'000'000);
      FAIL("no usage error");
    } catch (const kit::UsageError& e) {
      CHECK_THAT(e.what(), ContainsSubstring("--t-end") && ContainsSubstring("--dt") &&
                               ContainsSubstring("from 1 to 1000000 steps"));
    }
  }
}

TEST_CASE("a run past the limit is refused with the memory it would take") {
  try {
    kit::require_whole_steps(1e4, 1e-6, 1'000'000, 100.0);  // 1e10 steps of 100 B
    FAIL("no usage error");
  } catch (const kit::UsageError& e) {
    CHECK_THAT(e.what(), ContainsSubstring("--t-end 10000 s with --dt 1e-06 s is 1e+10 steps") &&
                             ContainsSubstring("recording them would take 1 TB") &&
                             ContainsSubstring("at most 1000000 steps, 100 MB, are recorded"));
  }
  try {  // not whole, but within the limit: no estimate
    kit::require_whole_steps(1.0, 0.3, 1'000'000);
    FAIL("no usage error");
  } catch (const kit::UsageError& e) {
    CHECK_THAT(e.what(), !ContainsSubstring("recording"));
  }
}
