#pragma once
// The pipe pair between the judge and a student's program, and its messages.
//
// A message is a header (its kind, its length in bytes) and then that many bytes (wire.hpp).
// The judge sends `call` (an entry point's name and its arguments); the student's program
// answers `result` (the returned value, then every argument it may change) or `error` (an
// exception's kind and text). While a call runs, the student's program may send `callback` (a
// function the judge handed over, and its arguments), which the judge evaluates in its own
// process and answers with `callback_result`: a right-hand side or a force field is computed
// and counted where the student cannot reach it.
//
// No message may exceed kMaxMessage: a student's program cannot make the judge allocate more.
#include <cstdint>
#include <string>
#include <vector>

#include "wire.hpp"

namespace kit::remote {

enum class Kind : std::uint32_t {
  call = 1,
  result = 2,
  error = 3,
  callback = 4,
  callback_result = 5,
  callback_error = 6
};

/// Bytes in one message, at most: the largest a graded test sends is under 8 MiB.
inline constexpr std::uint32_t kMaxMessage = 64u << 20;

/// The kinds of exception that cross, so that a test expecting std::invalid_argument sees one.
enum class Failure : std::uint8_t {
  other,
  invalid_argument,
  domain_error,
  out_of_range,
  logic_error,
  runtime_error
};

/// The other end went away (exited, crashed, was killed): every later call fails at once.
struct PeerGone : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Message {
  Kind kind{};
  std::vector<unsigned char> body;
  Reader reader() const { return Reader(body.data(), body.size()); }
};

/// One end of the link: reads from one descriptor, writes to another.
class Link {
 public:
  Link(int in, int out) : in_(in), out_(out) {}
  void send(Kind kind, const std::vector<unsigned char>& body);
  Message receive();
  bool open() const { return !gone_; }

 private:
  int in_, out_;
  bool gone_ = false;
};

/// Throws the exception a `error` message describes.
[[noreturn]] void rethrow(Reader& r);
/// The `error` body for the exception in flight.
std::vector<unsigned char> describe_current_exception();

}  // namespace kit::remote
