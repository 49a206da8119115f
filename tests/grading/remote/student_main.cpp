// The student's program's loop (student.hpp): one call at a time, until the judge closes the pipe.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "student.hpp"

namespace kit::remote {
/// Descriptors 3 and 4, or the two KIT_JUDGE_FDS names ("in,out"), which the grader sets.
Link& student_link() {
  static Link link = [] {
    int in = 3, out = 4;
    if (const char* fds = std::getenv("KIT_JUDGE_FDS")) std::sscanf(fds, "%d,%d", &in, &out);
    return Link(in, out);
  }();
  return link;
}
}  // namespace kit::remote

int main() {
  using namespace kit::remote;
  Entries entries;
  register_entries(entries);
  Link& link = student_link();
  for (;;) {
    Message m;
    try {
      m = link.receive();
    } catch (const PeerGone&) {
      return 0;  // the judge is done
    }
    if (m.kind != Kind::call) return 3;
    try {
      Reader r = m.reader();
      const auto name = get<std::string>(r);
      const auto* entry = entries.find(name);
      if (!entry) throw std::logic_error("this program has no entry point " + name);
      Writer w;
      (*entry)(r, w);
      link.send(Kind::result, w.bytes());
    } catch (const PeerGone&) {
      return 0;
    } catch (...) {
      try {
        link.send(Kind::error, describe_current_exception());
      } catch (const PeerGone&) {
        return 0;
      }
    }
  }
}
