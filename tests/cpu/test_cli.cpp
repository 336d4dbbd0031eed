// The tools' number checks (tools/common/cli.h): CLI11's own Range lets "nan" through (every comparison
// with NaN is false) and calls "abc" "not in range"; these must refuse both, naming which it is.
#include "tools/common/cli.h"

#include <catch2/catch.hpp>

#include <string>

namespace {

// What the check says about `text` (empty: accepted).
std::string verdict(const CLI::Validator& check, std::string text) { return check(text); }

}  // namespace

TEST_CASE("finite_range refuses text, NaN, infinities and values out of range, saying which", "[cli]") {
  const CLI::Validator fps = tools::finite_range(0.001, 10000.0);
  CHECK(verdict(fps, "30") == "");
  CHECK(verdict(fps, "0.5") == "");
  CHECK(verdict(fps, "1e3") == "");
  CHECK(verdict(fps, "+24") == "");
  CHECK(verdict(fps, "nan") == "must be a finite number, got 'nan'");
  CHECK(verdict(fps, "-inf") == "must be a finite number, got '-inf'");
  CHECK(verdict(fps, "infinity") == "must be a finite number, got 'infinity'");
  CHECK(verdict(fps, "1e400") == "must be a finite number, got '1e400'");
  CHECK(verdict(fps, "abc") == "must be a number, got 'abc'");
  CHECK(verdict(fps, "30fps") == "must be a number, got '30fps'");
  CHECK(verdict(fps, "") == "must be a number, got ''");
  CHECK(verdict(fps, "0") == "must be in [0.001, 10000], got 0");
  CHECK(verdict(fps, "20000") == "must be in [0.001, 10000], got 20000");
}

TEST_CASE("integer_range refuses text, fractions and values out of range, saying which", "[cli]") {
  const CLI::Validator frames = tools::integer_range(1, 1000000);
  CHECK(verdict(frames, "60") == "");
  CHECK(verdict(frames, "+7") == "");
  CHECK(verdict(frames, "abc") == "must be an integer, got 'abc'");
  CHECK(verdict(frames, "nan") == "must be an integer, got 'nan'");
  CHECK(verdict(frames, "2.5") == "must be an integer, got '2.5'");
  CHECK(verdict(frames, "1e3") == "must be an integer, got '1e3'");
  CHECK(verdict(frames, "0") == "must be in [1, 1000000], got 0");
  CHECK(verdict(frames, "-3") == "must be in [1, 1000000], got -3");
  CHECK(verdict(frames, "99999999999999999999") == "must be in [1, 1000000], got 99999999999999999999");
}

TEST_CASE("a refused value comes back from parsing as one line naming the flag", "[cli]") {
  CLI::App app{"test"};
  double fps = 0.0;
  app.add_option("--fps", fps)->check(tools::finite_range(0.001, 10000.0));
  const char* argv[] = {"tool", "--fps", "nan"};
  REQUIRE_THROWS_WITH(app.parse(3, const_cast<char**>(argv)), "--fps: must be a finite number, got 'nan'");
  CHECK(fps == 0.0);
}
