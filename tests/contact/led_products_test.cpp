// Products led by the first rank (contact/led_products.hpp), under mpirun on 3 ranks: every rank
// makes exactly the first rank's products and gets its result, and a failure of the method or of a
// product ends every rank with the message instead of leaving the others waiting.
#include <gtest/gtest.h>

#include <regex>
#include <string>

#include "support/cli_runner.hpp"

namespace hpcontact::testing {
namespace {

Run check(const std::string& mode) {
  return run_command(kMpiEnvironment + "timeout 60 mpirun -n 3 --oversubscribe " HPCONTACT_LED_CHECK " " + mode);
}

TEST(LedProducts, EveryRankMakesTheFirstRanksProductsAndGetsItsResult) {
  const auto run = check("ok");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::regex line("rank (\\d) products (\\d+) result (\\S+)");
  int lines = 0;
  for (std::sregex_iterator it(run.output.begin(), run.output.end(), line), end; it != end; ++it, ++lines) {
    EXPECT_EQ((*it)[2], "5") << run.output;  // the first rank's 5 steps, not 5 + r
    EXPECT_EQ((*it)[3], "4") << run.output;  // Σ x of Ones(4), each step scaled back to x
  }
  EXPECT_EQ(lines, 3) << run.output;
}

TEST(LedProducts, AFailureOfTheMethodOrOfAProductEndsEveryRank) {
  for (const char* mode : {"method_fails", "product_fails"}) {
    const auto run = check(mode);
    EXPECT_EQ(run.exit_code, 3) << mode << "\n" << run.output;  // (timeout would give 124)
    const std::string message = std::string(mode) == "method_fails" ? "the method failed" : "the third product failed";
    int failed = 0;
    for (auto at = run.output.find(message); at != std::string::npos; at = run.output.find(message, at + 1)) ++failed;
    EXPECT_EQ(failed, 3) << mode << "\n" << run.output;
  }
}

}  // namespace
}  // namespace hpcontact::testing
