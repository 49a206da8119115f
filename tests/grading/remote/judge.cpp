// The judge's end of the link (judge.hpp): finding or starting the student's program, and the
// exchange of one call.
#include "judge.hpp"

#include <sched.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

extern char** environ;

namespace kit::remote {
namespace {

/// "in,out" → two descriptors above 2, or nothing.
bool parse_fds(const char* text, int& in, int& out) {
  char* end = nullptr;
  in = int(std::strtol(text, &end, 10));
  if (end == text || *end != ',') return false;
  const char* second = end + 1;
  out = int(std::strtol(second, &end, 10));
  return end != second && *end == '\0' && in > 2 && out > 2;
}

/// Keeps the judge, and the program it starts, on the processor it runs on: a call and its answer
/// then pass between two processes on one core, about ten times faster than between two.
void stay_on_this_processor() {
  const int cpu = sched_getcpu();
  if (cpu < 0) return;
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  sched_setaffinity(0, sizeof set, &set);
}

/// Starts `program` with its requests on descriptor 3 and its answers on 4 (student.hpp).
std::unique_ptr<Link> start(const char* program) {
  int requests[2], answers[2];
  if (::pipe(requests) != 0 || ::pipe(answers) != 0)
    throw std::runtime_error("judge: no pipe for the student program");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, requests[0], 3);
  posix_spawn_file_actions_adddup2(&actions, answers[1], 4);
  for (int fd : {requests[0], requests[1], answers[0], answers[1]})
    if (fd > 4) posix_spawn_file_actions_addclose(&actions, fd);
  stay_on_this_processor();
  pid_t pid = 0;
  char* argv[] = {const_cast<char*>(program), nullptr};
  const int failed = posix_spawn(&pid, program, &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(requests[0]);
  ::close(answers[1]);
  if (failed) throw std::runtime_error(std::string("judge: cannot start the student program ") + program);
  return std::make_unique<Link>(answers[0], requests[1]);
}

}  // namespace

Link& judge_link() {
  static const std::unique_ptr<Link> link = [] {
    std::signal(SIGPIPE, SIG_IGN);  // a student's program that died is a failed call, not a dead judge
    int in = -1, out = -1;
    if (const char* fds = std::getenv("KIT_STUDENT_FDS"); fds && parse_fds(fds, in, out))
      return std::make_unique<Link>(in, out);
    if (const char* program = std::getenv("KIT_STUDENT_PROGRAM"); program && *program) return start(program);
    throw std::runtime_error("judge: no student program (KIT_STUDENT_FDS or KIT_STUDENT_PROGRAM)");
  }();
  return *link;
}

namespace detail {

Message exchange(const std::string& name, Writer& arguments, const std::vector<Handler>& handlers) {
  Link& link = judge_link();
  link.send(Kind::call, arguments.bytes());
  for (;;) {
    Message m = link.receive();
    Reader r = m.reader();
    switch (m.kind) {
      case Kind::result:
        return m;
      case Kind::error:
        rethrow(r);
      case Kind::callback: {
        const auto id = get<std::uint32_t>(r);
        if (id >= handlers.size()) throw ProtocolError(name + ": a callback that was never handed over");
        Writer answer;
        try {
          handlers[id](r, answer);
        } catch (const ProtocolError&) {
          throw;
        } catch (...) {
          link.send(Kind::callback_error, describe_current_exception());
          continue;
        }
        link.send(Kind::callback_result, answer.bytes());
        continue;
      }
      default:
        throw ProtocolError(name + ": a message out of turn");
    }
  }
}

}  // namespace detail
}  // namespace kit::remote
