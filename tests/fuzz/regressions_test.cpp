// Fuzz regressions: every scene in tests/fuzz/corpus (the fuzzer's seeds) and
// tests/fuzz/regressions (inputs that once crashed the parser or escaped as a non-InputError)
// must parse to a Scene or give an InputError that names the file, nothing else.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "io/toml_reader.hpp"
#include "scene/scene_mesh.hpp"
#include "scene/scene_reader.hpp"

using namespace hpcontact;

namespace {

int replay(const std::filesystem::path& folder) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file() || entry.path().filename() == "README.md") continue;
    ++files;
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    const std::string name = entry.path().filename().string();
    try {
      scene::parse_scene(text.str(), name);
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << name << ": " << error.what();
    } catch (const std::exception& error) {
      ADD_FAILURE() << name << ": escaped as " << typeid(error).name() << ": " << error.what();
    }
  }
  return files;
}

}  // namespace

TEST(FuzzRegressions, SeedCorpusParsesOrIsAnInputError) {
  EXPECT_GE(replay(std::filesystem::path(HPCONTACT_FUZZ_DIR) / "corpus"), 4);
}

TEST(FuzzRegressions, CrashersStayFixed) {
  // A replay of nothing would pass silently: the folder holds the crashers found so far.
  EXPECT_GE(replay(std::filesystem::path(HPCONTACT_FUZZ_DIR) / "regressions"), 2);
}

// Found by reading the fuzzer's neighbourhood: an integer range is checked against its bounds
// before it is expanded, so a huge range is an error at once instead of a hang.
TEST(FuzzRegressions, HugeIntegerRangeIsAnErrorNotAHang) {
  const auto table =
      io::parse_toml_string("p = \"1..99999999999\"\nq = \"1..99999999999999999999999\"\n", "study.toml");
  EXPECT_THROW(table.integer_list("p", 1, 20), InputError);
  EXPECT_THROW(table.integer_list("q", 1, 20), InputError);
}
