#pragma once
// What a chapter binary's exit code means, and the error that makes it 2.
#include <stdexcept>

namespace kit {

namespace exit_code {
inline constexpr int ok = 0;
inline constexpr int failure = 1;   ///< a solver or I/O failure: a defect, never valid input
inline constexpr int usage = 2;     ///< bad flag, value or scene
inline constexpr int diverged = 3;  ///< only with --fail-on-divergence
}  // namespace exit_code

/// Bad input found after parsing (a combination of flags, a scene key): exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace kit
