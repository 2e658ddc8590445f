// Core: expressions, the PETSc option split, and the modules' include order (the CSV writer,
// TOML checking and atomic files: io/text_files_test.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/expression.hpp"
#include "core/petsc_session.hpp"
#include "support/input_error_message.hpp"

using namespace hpcontact;

using hpcontact::testing::message_of;

TEST(Expression, EvaluatesWithVariablesAndConstants) {
  const Expression g("-x^2 + 2*y + pi", "test");
  EXPECT_NEAR(g(3.0, 0.5), -9.0 + 1.0 + M_PI, 1e-14);
}

TEST(Expression, SyntaxErrorNamesOriginAndText) {
  const auto message = message_of([] { Expression("x +* 2", "scene.toml: key 'f'"); });
  EXPECT_NE(message.find("scene.toml: key 'f'"), std::string::npos) << message;
  EXPECT_NE(message.find("x +* 2"), std::string::npos) << message;
}

TEST(Expression, UnknownVariableIsAnError) { EXPECT_THROW(Expression("z + 1", "test"), InputError); }

TEST(Expression, NonFiniteValueIsAnError) {
  const Expression g("1/x", "scene.toml: key 'g'");
  const auto message = message_of([&] { g(0.0, 1.0); });
  EXPECT_NE(message.find("must be finite"), std::string::npos) << message;
}

TEST(PetscOptions, SplitKeepsOwnArgumentsAndPassesSolverOptions) {
  const char* argv[] = {"hpcontact", "infsup", "--p", "3",         "-eps_type", "arpack", "-st_shift",
                        "-1",        "--n",    "8",   "-eps_view", "--pc",      "2"};
  const auto split = split_petsc_options(13, argv);
  EXPECT_EQ(split.own, (std::vector<std::string>{"hpcontact", "infsup", "--p", "3", "--n", "8", "--pc", "2"}));
  EXPECT_EQ(split.petsc,
            (std::vector<std::string>{"hpcontact", "-eps_type", "arpack", "-st_shift", "-1", "-eps_view"}));
}

// The modules of lib/ form a pipeline: no file includes a module above its own, so the data of a
// run flows from the command line down to the eigen solve without returning to a higher layer.
TEST(Architecture, NoModuleIncludesOneAboveIt) {
  const std::vector<std::string> order{"core",      "basis", "mesh",    "space",  "linalg", "assembly",
                                       "operators", "norms", "contact", "infsup", "io",     "postprocess",
                                       "adapt",     "scene", "driver",  "studies"};
  const std::filesystem::path lib = std::filesystem::path(HPCONTACT_TEST_DATA) / ".." / ".." / "lib";
  const std::regex include_line(R"(#include "(\w+)/)");
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(lib)) {
    const auto extension = entry.path().extension();
    if (!entry.is_regular_file() || (extension != ".cpp" && extension != ".hpp")) continue;
    const std::string module = entry.path().parent_path().filename().string();
    const auto own = std::find(order.begin(), order.end(), module);
    ASSERT_NE(own, order.end()) << "module " << module << " is not in the pipeline order";
    ++files;
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);) {
      std::smatch match;
      if (!std::regex_search(line, match, include_line)) continue;
      const auto included = std::find(order.begin(), order.end(), match[1].str());
      if (included != order.end()) {
        EXPECT_LE(included - order.begin(), own - order.begin()) << entry.path() << " includes " << match[1];
      }
    }
  }
  EXPECT_GT(files, 100);
}
