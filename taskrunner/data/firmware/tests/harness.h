// A tiny test harness: TEST(name) { CHECK(...); CHECK_EQ(a, b); REQUIRE(...); }.
// The runner (harness.cpp) runs every test (or those whose name contains argv[1]) and
// ends with "N passed, M failed"; the exit status is 0 only when nothing failed.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace th {

struct Test {
  const char* name;
  void (*fn)();
};

std::vector<Test>& registry();
void fail(const char* file, int line, const std::string& message);

struct Registrar {
  Registrar(const char* name, void (*fn)()) { registry().push_back({name, fn}); }
};

}  // namespace th

#define TH_CAT2(a, b) a##b
#define TH_CAT(a, b) TH_CAT2(a, b)

#define TEST(name)                                               \
  static void name();                                            \
  static const th::Registrar TH_CAT(registrar_, name)(#name, name); \
  static void name()

#define CHECK(cond)                                                  \
  do {                                                               \
    if (!(cond)) th::fail(__FILE__, __LINE__, "CHECK(" #cond ")");   \
  } while (0)

#define CHECK_EQ(a, b)                                                       \
  do {                                                                       \
    const auto& th_a = (a);                                                  \
    const auto& th_b = (b);                                                  \
    if (!(th_a == th_b)) {                                                   \
      std::ostringstream th_out;                                             \
      th_out << "CHECK_EQ(" #a ", " #b ")\n      left:  " << th_a            \
             << "\n      right: " << th_b;                                   \
      th::fail(__FILE__, __LINE__, th_out.str());                            \
    }                                                                        \
  } while (0)

// Stops the test at the first failure (for preconditions later checks rely on).
#define REQUIRE(cond)                                                    \
  do {                                                                   \
    if (!(cond)) {                                                       \
      th::fail(__FILE__, __LINE__, "REQUIRE(" #cond ")");                \
      return;                                                            \
    }                                                                    \
  } while (0)
