#include "harness.h"

#include <chrono>
#include <cstdio>
#include <cstring>

namespace th {
namespace {
int g_failures_in_test = 0;
const char* g_current = "";
}  // namespace

std::vector<Test>& registry() {
  static std::vector<Test> tests;
  return tests;
}

void fail(const char* file, int line, const std::string& message) {
  if (g_failures_in_test < 10) {
    std::printf("FAIL %s\n  %s:%d: %s\n", g_current, file, line, message.c_str());
  }
  ++g_failures_in_test;
}

}  // namespace th

int main(int argc, char** argv) {
  const char* filter = argc > 1 ? argv[1] : nullptr;
  int passed = 0;
  int failed = 0;
  const auto start = std::chrono::steady_clock::now();
  for (const th::Test& test : th::registry()) {
    if (filter && !std::strstr(test.name, filter)) continue;
    th::g_current = test.name;
    th::g_failures_in_test = 0;
    test.fn();
    if (th::g_failures_in_test == 0) {
      ++passed;
    } else {
      ++failed;
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("(%.2f s)\n%d passed, %d failed\n", seconds, passed, failed);
  return failed == 0 && passed > 0 ? 0 : 1;
}
