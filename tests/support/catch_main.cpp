// The one Catch2 main every test executable links (compiled once), with the evidence channel
// the grader reads: when KIT_EVIDENCE_FD names an open file descriptor, every test case that
// ends writes one line to it, "case<TAB>name<TAB>assertions passed<TAB>failed", and the run's
// end writes "end<TAB>passed<TAB>failed". The grader counts a verdict only when it sees every
// expected case end with the expected number of assertions, then the end of the run: a process
// that exits early, skips cases or silences its checks leaves that record incomplete.
// The lines are written with write(2), unbuffered, so a crash keeps what came before it.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace {

int evidence_fd() {
  const char* text = std::getenv("KIT_EVIDENCE_FD");
  if (!text) return -1;
  char* end = nullptr;
  const long fd = std::strtol(text, &end, 10);
  return (end != text && *end == '\0' && fd > 2 && fd < 1024) ? int(fd) : -1;
}

void emit(const std::string& line) {
  static const int fd = evidence_fd();
  if (fd < 0) return;
  std::size_t done = 0;
  while (done < line.size()) {
    const ssize_t n = ::write(fd, line.data() + done, line.size() - done);
    if (n <= 0) return;
    done += std::size_t(n);
  }
}

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\t' || c == '\n' || c == '\r') c = ' ';
  return s;
}

struct EvidenceListener : Catch::TestEventListenerBase {
  using TestEventListenerBase::TestEventListenerBase;
  void testCaseEnded(const Catch::TestCaseStats& stats) override {
    emit("case\t" + one_line(stats.testInfo.name) + "\t" + std::to_string(stats.totals.assertions.passed) + "\t" +
         std::to_string(stats.totals.assertions.failed) + "\n");
  }
  void testRunEnded(const Catch::TestRunStats& stats) override {
    emit("end\t" + std::to_string(stats.totals.assertions.passed) + "\t" +
         std::to_string(stats.totals.assertions.failed) + "\n");
  }
};

}  // namespace

CATCH_REGISTER_LISTENER(EvidenceListener)
