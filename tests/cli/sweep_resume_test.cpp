// Resuming a sweep is safe: a folder holds the rows of one study (sweep_identity.txt); a resume or a
// merge with an edited study is refused naming what changed (serially and under mpirun), --restart
// replaces the rows, and a point stored twice with other numbers is computed again.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/cli_runner.hpp"

namespace {

using namespace hpcontact::testing;

const std::string& kMpi = kMpiEnvironment;

// A sweep of the §7 square over the levels `n` (a second's work).
std::filesystem::path write_sweep(const std::filesystem::path& dir, const std::string& name, const std::string& n) {
  std::filesystem::copy_file(HPCONTACT_SOURCE_DIR "/studies/stability/square.toml", dir / "square.toml",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / name) << "[sweep]\nscene = \"square.toml\"\np = \"1..2\"\npC = \"0..1\"\n"
                            << "levels = { \"domain.n_x\" = " << n << ", \"domain.n_y\" = " << n << " }\n"
                            << "ratio = [1, \"1/2\"]\nnorm = [\"interp\"]\n";
  return dir / name;
}

std::string text_of(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(SweepResume, EditedStudyIsRefusedNamingWhatChanged) {
  const auto dir = scratch("sweep_resume_edited");
  const auto study = write_sweep(dir, "study.toml", "[4, 8, 16]");
  const auto edited = write_sweep(dir, "edited.toml", "[8, 16, 32]");
  const auto out = (dir / "out").string();
  ASSERT_EQ(run("sweep " + study.string() + " --out " + out).exit_code, 0);
  const std::string rows = text_of(dir / "out" / "alpha.csv");
  for (const std::string& launcher : {std::string(), kMpi + "mpirun -n 2 --oversubscribe "}) {
    const auto refused = run_command(launcher + HPCONTACT_CLI " sweep " + edited.string() + " --out " + out);
    EXPECT_EQ(refused.exit_code, 2) << launcher << refused.output;
    EXPECT_NE(refused.output.find("holds the rows of another study"), std::string::npos) << refused.output;
    EXPECT_NE(refused.output.find("level 1: domain.n_x: 4 in the folder, 8 in the study"), std::string::npos)
        << refused.output;
    EXPECT_NE(refused.output.find("--restart"), std::string::npos) << refused.output;
    EXPECT_EQ(text_of(dir / "out" / "alpha.csv"), rows) << "the refused run changed the stored rows";
  }
  // The same study resumes (nothing to do); --restart replaces the rows with the edited study's.
  ASSERT_EQ(run("sweep " + study.string() + " --out " + out).exit_code, 0);
  EXPECT_EQ(text_of(dir / "out" / "alpha.csv"), rows);
  ASSERT_EQ(run("sweep " + edited.string() + " --out " + (dir / "fresh").string()).exit_code, 0);
  const auto restarted = run("sweep " + edited.string() + " --out " + out + " --restart");
  ASSERT_EQ(restarted.exit_code, 0) << restarted.output;
  EXPECT_EQ(without_seconds(dir / "out" / "alpha.csv"), without_seconds(dir / "fresh" / "alpha.csv"));
  // A slice of the other study is refused by --merge.
  const auto merged = run("sweep " + study.string() + " --merge " + out + " --out " + (dir / "merged").string());
  EXPECT_EQ(merged.exit_code, 2) << merged.output;
  EXPECT_NE(merged.output.find("merge only the folders of this study's slices"), std::string::npos) << merged.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "merged" / "alpha.csv"));
}

TEST(SweepResume, RowsWithoutIdentityAreRefused) {
  const auto dir = scratch("sweep_resume_anonymous");
  const auto study = write_sweep(dir, "study.toml", "[4, 8, 16]");
  ASSERT_EQ(run("sweep " + study.string() + " --out " + (dir / "out").string()).exit_code, 0);
  std::filesystem::remove(dir / "out" / "sweep_identity.txt");
  const auto refused = run("sweep " + study.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_NE(refused.output.find("without sweep_identity.txt"), std::string::npos) << refused.output;
}

// A folder with the identity of another study but no rows yet (a run stopped before its first
// group) takes the new study.
TEST(SweepResume, FolderWithoutRowsTakesTheNewStudy) {
  const auto dir = scratch("sweep_resume_no_rows");
  const auto study = write_sweep(dir, "study.toml", "[4, 8, 16]");
  const auto edited = write_sweep(dir, "edited.toml", "[8, 16, 32]");
  ASSERT_EQ(run("sweep " + study.string() + " --out " + (dir / "first").string()).exit_code, 0);
  std::filesystem::create_directories(dir / "out");
  std::filesystem::copy_file(dir / "first" / "sweep_identity.txt", dir / "out" / "sweep_identity.txt");
  const auto result = run("sweep " + edited.string() + " --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 0) << result.output;
}

// The identity names a mesh file by its key, not its path: the same study run from another
// folder resumes; the file's contents edited, it is refused.
TEST(SweepResume, MeshFileIsKnownByItsContents) {
  const auto dir = scratch("sweep_resume_mesh");
  const std::string geo =
      "Point(1) = {0, 0, 0, 1};\nPoint(2) = {2, 0, 0, 1};\nPoint(3) = {2, 1, 0, 1};\n"
      "Point(4) = {0, 1, 0, 1};\nLine(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\n"
      "Line(4) = {4, 1};\nCurve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n"
      "Physical Curve(\"contact\") = {1};\nPhysical Curve(\"top\") = {3};\n"
      "Physical Surface(\"body\") = {1};\n";
  std::ofstream(dir / "block.geo") << geo;
  std::ofstream(dir / "block.toml") << "[domain]\nmesh = \"block.geo\"\n[boundary]\ncontact_groups = [\"contact\"]\n"
                                       "dirichlet_groups = [\"top\"]\n[contact_mesh]\nratio = 1\n"
                                       "[discretization]\np = 2\npC = 1\n";
  std::ofstream(dir / "study.toml") << "[sweep]\nscene = \"block.toml\"\np = [2]\npC = [1]\nnorm = [\"interp\"]\n"
                                       "levels = { \"domain.mesh_size\" = [0.5, 0.25] }\nfit_levels = 2\n";
  ASSERT_EQ(run("sweep " + (dir / "study.toml").string() + " --out " + (dir / "out").string()).exit_code, 0);
  const auto elsewhere = run_command("cd " + dir.string() + " && " HPCONTACT_CLI " sweep study.toml --out out");
  EXPECT_EQ(elsewhere.exit_code, 0) << elsewhere.output;
  std::ofstream(dir / "block.geo") << geo << "Mesh.MeshSizeFactor = 0.9;\n";
  const auto edited = run("sweep " + (dir / "study.toml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(edited.exit_code, 2) << edited.output;
  EXPECT_NE(edited.output.find("contents of domain.mesh"), std::string::npos) << edited.output;
}

// Two rows of one point with other numbers: which one is right cannot be told, so the point is
// computed again (with a warning naming it) and the file equals a fresh run's.
TEST(SweepResume, PointStoredTwiceWithOtherNumbersIsComputedAgain) {
  const auto dir = scratch("sweep_resume_duplicate");
  const auto study = write_sweep(dir, "study.toml", "[4, 8, 16]");
  const auto out = dir / "out";
  ASSERT_EQ(run("sweep " + study.string() + " --out " + out.string()).exit_code, 0);
  std::string text = text_of(out / "alpha.csv");
  const auto second_line = text.find('\n') + 1;
  std::string row = text.substr(second_line, text.find('\n', second_line) + 1 - second_line);
  const auto h_column = row.find(",0.");  // the first number in (0, 1): h, given another value
  ASSERT_NE(h_column, std::string::npos) << row;
  row.insert(h_column + 3, "9");
  std::ofstream(out / "alpha.csv", std::ios::app) << row;
  const auto resumed = run("sweep " + study.string() + " --out " + out.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("1 point stored twice with other numbers"), std::string::npos) << resumed.output;
  ASSERT_EQ(run("sweep " + study.string() + " --out " + (dir / "fresh").string()).exit_code, 0);
  EXPECT_EQ(without_seconds(out / "alpha.csv"), without_seconds(dir / "fresh" / "alpha.csv"));
}

}  // namespace
