// io: the CSV writer, TOML checking, atomic files (split from the core tests).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/csv_writer.hpp"
#include "io/toml_reader.hpp"
#include "support/input_error_message.hpp"
#include "support/scratch.hpp"

using namespace hpcontact;

using hpcontact::testing::message_of;

TEST(Csv, FullPrecisionRoundTrip) {
  const double value = 0.1 + 0.2;
  EXPECT_EQ(std::stod(io::format_full_precision(value)), value);
  io::CsvTable table({"a", "b", "c"});
  table.add_row({1LL, 0.5, std::string("x")});
  EXPECT_EQ(table.to_string(), "a,b,c\n1,0.5,x\n");
}

TEST(Toml, MalformedFileReportsLine) {
  const auto message = message_of([] { io::parse_toml_string("a = 1\nb = [1, 2\n", "bad.toml"); });
  EXPECT_NE(message.find("bad.toml:"), std::string::npos) << message;
  EXPECT_NE(message.find("malformed TOML"), std::string::npos) << message;
}

TEST(Toml, UnknownKeySuggestsNearest) {
  const auto root = io::parse_toml_string("[mesh]\nperturbb = 0.1\n", "s.toml");
  const auto mesh = root.table("mesh");
  mesh.number("perturb", 0.0);
  mesh.integer("seed", 0, 10, 1);
  const auto message = message_of([&] { mesh.reject_unknown_keys(); });
  EXPECT_NE(message.find("unknown key 'mesh.perturbb'"), std::string::npos) << message;
  EXPECT_NE(message.find("did you mean 'perturb'"), std::string::npos) << message;
}

TEST(Toml, OutOfRangeNamesFileKeyValueAndRange) {
  const auto root = io::parse_toml_string("p = [1, 0, 3]\nn = \"2..5\"\nq = 2.5\n", "s.toml");
  const auto message = message_of([&] { root.integer_list("p", 1, 16); });
  EXPECT_NE(message.find("s.toml: key 'p' = 0: each in [1, 16]"), std::string::npos) << message;
  EXPECT_EQ(root.integer_list("n", 1, 10), (std::vector<long long>{2, 3, 4, 5}));
  EXPECT_THROW(root.integer("q", 0, 5), InputError);
  EXPECT_THROW(root.number("missing"), InputError);
}

TEST(AtomicFile, NothingIsLeftWhenNotCommitted) {
  const auto dir = hpcontact::testing::scratch("atomic") / "made";
  io::ensure_writable_directory(dir);
  {
    io::AtomicFile file(dir / "half.csv");
    file.stream() << "partial";
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  io::write_file_atomically(dir / "whole.csv", "done\n");
  std::ifstream in(dir / "whole.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "done");
}

TEST(AtomicFile, UnwritableFolderIsAnInputError) {
  EXPECT_THROW(io::ensure_writable_directory("/proc/hpcontact_cannot_exist"), InputError);
}
