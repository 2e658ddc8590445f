// Stage 7, command line: --help lists the subcommands, bad input exits with code 2 and leaves
// no output, and the convergence subcommand writes its CSV.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>

namespace {

struct Run {
  int exit_code;
  std::string output;
};

Run run(const std::string& arguments) {
  const std::string command = std::string(HPCONTACT_CLI) + " " + arguments + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string output;
  std::array<char, 4096> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe.get())) output += buffer.data();
  const int status = pclose(pipe.release());
  return {WEXITSTATUS(status), output};
}

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("hpcontact_cli_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

const char* kStudy = R"toml([solution]
u  = "sin(1-x)*sin(1-y)"
ux = "-cos(1-x)*sin(1-y)"
uy = "-sin(1-x)*cos(1-y)"
f  = "2*sin(1-x)*sin(1-y)"
[[runs]]
p = [1, 2]
n = [2, 4]
)toml";

}  // namespace

TEST(Cli, HelpListsSubcommands) {
  const auto result = run("--help");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.output.find("convergence"), std::string::npos) << result.output;
}

TEST(Cli, ConvergenceWritesCsvWithDocumentedColumns) {
  const auto dir = scratch("ok");
  std::ofstream(dir / "study.toml") << kStudy;
  const auto result = run("convergence " + (dir / "study.toml").string() + " --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::ifstream csv(dir / "out" / "convergence.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header, "p,n,ndofs,h,error_h1,error_l2,seconds");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 4);
}

TEST(Cli, BadInputExitsWithTwoAndWritesNothing) {
  const auto dir = scratch("bad");
  std::string study = kStudy;
  study.replace(study.find("p = [1, 2]"), 10, "p = [0, 2]");
  std::ofstream(dir / "study.toml") << study;
  const auto result = run("convergence " + (dir / "study.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 2) << result.output;
  EXPECT_NE(result.output.find("runs[0].p"), std::string::npos) << result.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));

  std::string wrong_f = kStudy;
  wrong_f.replace(wrong_f.find("f  = \"2*"), 8, "f  = \"3*");
  std::ofstream(dir / "wrong_f.toml") << wrong_f;
  const auto inconsistent = run("convergence " + (dir / "wrong_f.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(inconsistent.exit_code, 2);
  EXPECT_NE(inconsistent.output.find("solution.f"), std::string::npos) << inconsistent.output;
}

TEST(Cli, UnknownSubcommandOrMissingFileIsAnError) {
  EXPECT_NE(run("no-such-command").exit_code, 0);
  EXPECT_EQ(run("convergence /nonexistent/study.toml").exit_code, 2);
}
